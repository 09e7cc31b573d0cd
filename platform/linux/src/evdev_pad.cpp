#include "azt/linux/evdev_pad.hpp"

#include <fcntl.h>
#include <libevdev/libevdev.h>
#include <unistd.h>

#include <boost/asio/io_context.hpp>
#include <boost/asio/posix/stream_descriptor.hpp>
#include <cerrno>
#include <cstring>

#include "azt/linux/unique_fd.hpp"

namespace azt::linux_os {
namespace {

namespace asio = boost::asio;

struct EvdevDeleter {
  void operator()(libevdev* dev) const { libevdev_free(dev); }
};
using EvdevHandle = std::unique_ptr<libevdev, EvdevDeleter>;

/// Every absolute axis the device has, with its range and present value.
hands::PadState initial_state(const libevdev* dev) {
  hands::PadState s;
  for (unsigned code = 0; code <= ABS_MAX; ++code) {
    if (libevdev_has_event_code(dev, EV_ABS, code) == 0) continue;
    const input_absinfo* info = libevdev_get_abs_info(dev, code);
    if (info == nullptr) continue;
    s.ranges[code] = hands::PadAxisRange{info->minimum, info->maximum, info->flat};
    s.values[code] = info->value;
  }
  for (unsigned code = BTN_MISC; code <= KEY_MAX; ++code) {
    if (libevdev_has_event_code(dev, EV_KEY, code) != 0 &&
        libevdev_get_event_value(dev, EV_KEY, code) != 0) {
      s.pressed.insert(code);
    }
  }
  return s;
}

class LibevdevPad final : public EvdevPad {
 public:
  LibevdevPad(asio::io_context& io, UniqueFd fd, EvdevHandle dev,
              std::function<void(const std::string&)> on_lost)
      : fd_(std::move(fd)),
        dev_(std::move(dev)),
        name_(libevdev_get_name(dev_.get()) != nullptr ? libevdev_get_name(dev_.get()) : "?"),
        state_(initial_state(dev_.get())),
        on_lost_(std::move(on_lost)),
        events_(io, fd_.get()) {
    watch();
  }
  ~LibevdevPad() override {
    boost::system::error_code ignored;
    events_.cancel(ignored);
    (void)events_.release();  // the descriptor is fd_'s
  }
  LibevdevPad(const LibevdevPad&) = delete;
  LibevdevPad& operator=(const LibevdevPad&) = delete;
  LibevdevPad(LibevdevPad&&) = delete;
  LibevdevPad& operator=(LibevdevPad&&) = delete;

  [[nodiscard]] const hands::PadState& state() const override { return state_; }
  [[nodiscard]] const std::string& name() const override { return name_; }
  [[nodiscard]] bool present() const override { return present_; }

 private:
  void watch() {
    events_.async_wait(asio::posix::stream_descriptor::wait_read,
                       [this](boost::system::error_code ec) {
                         if (ec || !present_) return;
                         if (drain()) watch();
                       });
  }

  /// Reads every queued event; false when the device is gone.
  bool drain() {
    unsigned flag = LIBEVDEV_READ_FLAG_NORMAL;
    for (;;) {
      input_event ev{};
      const int rc = libevdev_next_event(dev_.get(), flag, &ev);
      if (rc == LIBEVDEV_READ_STATUS_SYNC) {
        // The kernel's buffer overflowed: what follows (read with SYNC) is the delta to now.
        flag = LIBEVDEV_READ_FLAG_SYNC;
        hands::apply_pad_event(state_, ev.type, ev.code, ev.value);
        continue;
      }
      if (rc == LIBEVDEV_READ_STATUS_SUCCESS) {
        hands::apply_pad_event(state_, ev.type, ev.code, ev.value);
        continue;
      }
      if (rc == -EAGAIN && flag == LIBEVDEV_READ_FLAG_SYNC) {
        flag = LIBEVDEV_READ_FLAG_NORMAL;
        continue;
      }
      if (rc == -EAGAIN) return true;
      lose(std::string("read: ") + std::strerror(-rc));
      return false;
    }
  }

  void lose(const std::string& why) {
    present_ = false;
    state_ = hands::PadState{};  // nothing held: the hands let go
    if (on_lost_) on_lost_(why);
  }

  UniqueFd fd_;
  EvdevHandle dev_;
  std::string name_;
  hands::PadState state_;
  std::function<void(const std::string&)> on_lost_;
  asio::posix::stream_descriptor events_;
  bool present_ = true;
};

}  // namespace

Result<std::unique_ptr<EvdevPad>> open_evdev_pad(asio::io_context& io, const std::string& path,
                                                 std::function<void(const std::string&)> on_lost) {
  UniqueFd fd(::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC));
  if (!fd.valid()) return fail(path + ": " + std::strerror(errno));
  libevdev* raw = nullptr;
  const int rc = libevdev_new_from_fd(fd.get(), &raw);
  if (rc < 0) return fail(path + ": not an input device (" + std::strerror(-rc) + ")");
  EvdevHandle dev(raw);
  if (libevdev_has_event_type(dev.get(), EV_ABS) == 0 &&
      libevdev_has_event_type(dev.get(), EV_KEY) == 0) {
    return fail(path + ": has neither axes nor buttons");
  }
  return std::unique_ptr<EvdevPad>(
      std::make_unique<LibevdevPad>(io, std::move(fd), std::move(dev), std::move(on_lost)));
}

}  // namespace azt::linux_os
