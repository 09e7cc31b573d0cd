#include "azt/linux/hub_serial_link.hpp"

#include <chrono>

#include "azt/linux/serial_port.hpp"

namespace azt::linux_os {

namespace asio = boost::asio;

HubSerialLink::HubSerialLink(asio::io_context& io, HubSerialConfig config, OnFrame on_frame,
                             OnEvent on_event)
    : stream_(io),
      retry_timer_(io),
      config_(std::move(config)),
      on_frame_(std::move(on_frame)),
      on_event_(std::move(on_event)),
      decoder_(config_.accept) {}

HubSerialLink::~HubSerialLink() { close(); }

Result<std::unique_ptr<HubSerialLink>> HubSerialLink::open(asio::io_context& io,
                                                           HubSerialConfig config, OnFrame on_frame,
                                                           OnEvent on_event) {
  std::unique_ptr<HubSerialLink> link(
      new HubSerialLink(io, std::move(config), std::move(on_frame), std::move(on_event)));
  if (auto r = link->attach(); !r) return r.error();
  return link;
}

Result<bool> HubSerialLink::attach() {
  auto fd = open_serial_device(config_.device, config_.baud);
  if (!fd) return fd.error();
  stream_.assign(*fd);
  // A frame cut by the unplug must not be glued to the first bytes after it.
  decoder_.resync();
  read();
  return true;
}

void HubSerialLink::close() {
  *alive_ = false;
  boost::system::error_code ignored;
  retry_timer_.cancel();
  stream_.close(ignored);
}

void HubSerialLink::read() {
  stream_.async_read_some(
      asio::buffer(buffer_), [this, alive = alive_](boost::system::error_code ec, std::size_t n) {
        if (!*alive || ec == asio::error::operation_aborted) return;
        if (ec) {
          lost(ec == asio::error::eof ? "end of file" : ec.message());
          return;
        }
        proto::HubFrame frame{};
        for (std::size_t i = 0; i < n; ++i) {
          if (decoder_.push(buffer_[i], frame) == proto::HubFrameStatus::Ok && on_frame_) {
            on_frame_(frame);
          }
        }
        read();
      });
}

void HubSerialLink::lost(const std::string& why) {
  boost::system::error_code ignored;
  stream_.close(ignored);
  if (on_event_) on_event_("lost " + config_.device + ": " + why);
  retry();
}

void HubSerialLink::retry() {
  retry_timer_.expires_after(std::chrono::duration_cast<asio::steady_timer::duration>(
      std::chrono::duration<double>(config_.retry_s)));
  retry_timer_.async_wait([this, alive = alive_](boost::system::error_code ec) {
    if (ec || !*alive) return;
    if (attach()) {
      if (on_event_) on_event_("connected " + config_.device);
    } else {
      retry();
    }
  });
}

}  // namespace azt::linux_os
