#include "azt/linux/libgpiod_lines.hpp"

#include <gpiod.h>

#include <boost/asio/io_context.hpp>
#include <boost/asio/posix/stream_descriptor.hpp>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <ctime>
#include <optional>
#include <vector>

namespace azt::linux_os {

namespace {

namespace asio = boost::asio;

/// One requested line and its chip; released (and the chip closed) on destruction.
class Request {
 public:
  static Result<Request> make(const GpioLineSpec& spec, const std::string& consumer, int type,
                              int flags, int initial) {
    gpiod_chip* chip = gpiod_chip_open_lookup(spec.chip.c_str());
    if (chip == nullptr) {
      return fail(describe(spec) + ": cannot open the GPIO chip: " + std::strerror(errno) +
                  " (is it /dev/gpiochipN, and may this user open it?)");
    }
    Request r(chip);
    if (spec.offset >= gpiod_chip_num_lines(chip)) {
      return fail(describe(spec) + ": the chip has only " +
                  std::to_string(gpiod_chip_num_lines(chip)) + " lines");
    }
    gpiod_line* line = gpiod_chip_get_line(chip, spec.offset);
    if (line == nullptr) return fail(describe(spec) + ": " + std::strerror(errno));
    const gpiod_line_request_config config{consumer.c_str(), type, flags};
    if (gpiod_line_request(line, &config, initial) != 0) {
      const int e = errno;
      return fail(describe(spec) + ": cannot request the line: " + std::strerror(e) +
                  (e == EBUSY ? " (another program holds it: see gpioinfo)" : ""));
    }
    r.line_ = line;
    return r;
  }

  Request(Request&& other) noexcept
      : chip_(std::exchange(other.chip_, nullptr)), line_(std::exchange(other.line_, nullptr)) {}
  Request& operator=(Request&&) = delete;
  Request(const Request&) = delete;
  Request& operator=(const Request&) = delete;
  ~Request() {
    if (line_ != nullptr) gpiod_line_release(line_);
    if (chip_ != nullptr) gpiod_chip_close(chip_);
  }

  [[nodiscard]] gpiod_line* line() const { return line_; }

 private:
  explicit Request(gpiod_chip* chip) : chip_(chip) {}
  gpiod_chip* chip_;
  gpiod_line* line_ = nullptr;
};

int active_low_flag(const GpioLineSpec& spec) {
  return spec.active_low ? GPIOD_LINE_REQUEST_FLAG_ACTIVE_LOW : 0;
}

class LibgpiodOutput final : public GpioOutput {
 public:
  LibgpiodOutput(GpioLineSpec spec, Request request, bool initial)
      : spec_(std::move(spec)), request_(std::move(request)), active_(initial) {}
  ~LibgpiodOutput() override { (void)set(false); }
  LibgpiodOutput(const LibgpiodOutput&) = delete;
  LibgpiodOutput& operator=(const LibgpiodOutput&) = delete;
  LibgpiodOutput(LibgpiodOutput&&) = delete;
  LibgpiodOutput& operator=(LibgpiodOutput&&) = delete;

  Result<bool> set(bool active) override {
    if (gpiod_line_set_value(request_.line(), active ? 1 : 0) != 0) {
      return fail(describe(spec_) + ": write failed: " + std::strerror(errno));
    }
    active_ = active;
    return true;
  }
  [[nodiscard]] bool active() const override { return active_; }
  [[nodiscard]] const GpioLineSpec& spec() const override { return spec_; }

 private:
  GpioLineSpec spec_;
  Request request_;
  bool active_;
};

/// A requested input line watched on the loop: each time the kernel has events queued, drain()
/// reads them. Its descriptor belongs to the line request; the level is read once at the start.
class WatchedLine : public GpioInput {
 public:
  WatchedLine(asio::io_context& io, GpioLineSpec spec, Request request)
      : spec_(std::move(spec)),
        request_(std::move(request)),
        events_(io, gpiod_line_event_get_fd(request_.line())) {
    active_ = gpiod_line_get_value(request_.line()) == 1;
    watch();
  }
  ~WatchedLine() override {
    boost::system::error_code ignored;
    events_.cancel(ignored);
    (void)events_.release();  // the descriptor belongs to the line request
  }
  WatchedLine(const WatchedLine&) = delete;
  WatchedLine& operator=(const WatchedLine&) = delete;
  WatchedLine(WatchedLine&&) = delete;
  WatchedLine& operator=(WatchedLine&&) = delete;

  [[nodiscard]] bool active() const override { return active_; }
  [[nodiscard]] const GpioLineSpec& spec() const override { return spec_; }

 protected:
  /// Reads the queued events (at least one is waiting).
  virtual void drain() = 0;
  [[nodiscard]] gpiod_line* line() const { return request_.line(); }
  /// The level now, read after a burst; nullopt when the read fails (the last level stands).
  std::optional<bool> read_level() {
    const int value = gpiod_line_get_value(request_.line());
    if (value < 0) return std::nullopt;
    active_ = value == 1;
    return active_;
  }

 private:
  void watch() {
    events_.async_wait(asio::posix::stream_descriptor::wait_read,
                       [this](boost::system::error_code ec) {
                         if (ec) return;
                         drain();
                         watch();
                       });
  }

  GpioLineSpec spec_;
  Request request_;
  asio::posix::stream_descriptor events_;
  bool active_ = false;
};

/// An input that reports its level after each burst of edges (a switch, a button).
class LibgpiodInput final : public WatchedLine {
 public:
  LibgpiodInput(asio::io_context& io, GpioLineSpec spec, Request request, GpioEdgeHandler on_edge)
      : WatchedLine(io, std::move(spec), std::move(request)), on_edge_(std::move(on_edge)) {}

 private:
  /// Reads every queued event, then the level: a bounce burst is one notification with the level
  /// it settled at, and the edge type (which active-low inverts differently across kernels) is
  /// never needed.
  void drain() override {
    const timespec no_wait{0, 0};
    gpiod_line_event event{};
    do {
      if (gpiod_line_event_read(line(), &event) != 0) break;
    } while (gpiod_line_event_wait(line(), &no_wait) == 1);
    if (const auto level = read_level()) on_edge_(*level);
  }

  GpioEdgeHandler on_edge_;
};

/// The kernel's event timestamp as a steady_clock time. Kernels before 5.7 stamp line events
/// with CLOCK_REALTIME rather than CLOCK_MONOTONIC: a stamp more than a minute from now is one of
/// those, and the time it is read stands in for it (late by the loop's latency, not by decades).
std::chrono::steady_clock::time_point event_time(const timespec& ts) {
  const auto now = std::chrono::steady_clock::now();
  const std::chrono::steady_clock::time_point at{std::chrono::seconds(ts.tv_sec) +
                                                 std::chrono::nanoseconds(ts.tv_nsec)};
  return std::chrono::abs(now - at) > std::chrono::minutes(1) ? now : at;
}

/// An input that hands on every queued edge, for pulse counting.
class LibgpiodEventInput final : public WatchedLine {
 public:
  LibgpiodEventInput(asio::io_context& io, GpioLineSpec spec, Request request,
                     GpioEventHandler on_event)
      : WatchedLine(io, std::move(spec), std::move(request)), on_event_(std::move(on_event)) {}

 private:
  /// Every queued event in order. The edge type is the physical one on some kernels and the
  /// logical one on others for an active-low line (LibgpiodInput's note): the level read after the
  /// burst says which, and the burst's types are turned round when its last edge disagrees.
  void drain() override {
    const timespec no_wait{0, 0};
    std::vector<GpioEdgeEvent> burst;
    gpiod_line_event event{};
    do {
      if (gpiod_line_event_read(line(), &event) != 0) break;
      burst.push_back({event.event_type == GPIOD_LINE_EVENT_RISING_EDGE, event_time(event.ts)});
    } while (gpiod_line_event_wait(line(), &no_wait) == 1);
    if (const auto level = read_level(); level && !burst.empty() && burst.back().active != *level) {
      for (auto& e : burst) e.active = !e.active;
    }
    for (const auto& e : burst) on_event_(e);
  }

  GpioEventHandler on_event_;
};

class LibgpiodProvider final : public GpioProvider {
 public:
  LibgpiodProvider(asio::io_context& io, std::string consumer)
      : io_(io), consumer_(std::move(consumer)) {}

  Result<std::unique_ptr<GpioOutput>> output(const GpioLineSpec& spec, bool initial) override {
    auto request = Request::make(spec, consumer_, GPIOD_LINE_REQUEST_DIRECTION_OUTPUT,
                                 active_low_flag(spec), initial ? 1 : 0);
    if (!request) return request.error();
    return std::unique_ptr<GpioOutput>(
        std::make_unique<LibgpiodOutput>(spec, std::move(request).value(), initial));
  }

  Result<std::unique_ptr<GpioInput>> input(const GpioLineSpec& spec, GpioBias bias,
                                           GpioEdgeHandler on_edge) override {
    auto request = input_request(spec, bias);
    if (!request) return request.error();
    return std::unique_ptr<GpioInput>(
        std::make_unique<LibgpiodInput>(io_, spec, std::move(request).value(), std::move(on_edge)));
  }

  Result<std::unique_ptr<GpioInput>> event_input(const GpioLineSpec& spec, GpioBias bias,
                                                 GpioEventHandler on_event) override {
    auto request = input_request(spec, bias);
    if (!request) return request.error();
    return std::unique_ptr<GpioInput>(std::make_unique<LibgpiodEventInput>(
        io_, spec, std::move(request).value(), std::move(on_event)));
  }

 private:
  /// An input line's request, every edge reported, with the bias asked for.
  Result<Request> input_request(const GpioLineSpec& spec, GpioBias bias) {
    int flags = active_low_flag(spec);
    if (bias == GpioBias::PullUp) flags |= GPIOD_LINE_REQUEST_FLAG_BIAS_PULL_UP;
    if (bias == GpioBias::PullDown) flags |= GPIOD_LINE_REQUEST_FLAG_BIAS_PULL_DOWN;
    return Request::make(spec, consumer_, GPIOD_LINE_REQUEST_EVENT_BOTH_EDGES, flags, 0);
  }

  asio::io_context& io_;
  std::string consumer_;
};

}  // namespace

std::unique_ptr<GpioProvider> make_libgpiod_provider(asio::io_context& io, std::string consumer) {
  return std::make_unique<LibgpiodProvider>(io, std::move(consumer));
}

}  // namespace azt::linux_os
