#pragma once
// The EncoderHub on RS-485 through a USB adapter (docs/hardware.md): a serial device read raw
// through Asio and fed byte by byte to the core's HubDecoder. When the adapter goes away (a read
// error or end of file: USB unplugged) the link says so, closes, and tries the path again every
// retry period until the device is back — the supervisor meanwhile sees stale readings and stops
// the drives. Nothing here blocks the loop.

#include <functional>
#include <memory>
#include <string>

#include "azt/linux/asio.hpp"
#include "azt/proto/hub_decoder.hpp"
#include "azt/util/result.hpp"

namespace azt::linux_os {

struct HubSerialConfig {
  std::string device;     ///< e.g. /dev/ttyUSB0, or a stable /dev/serial/by-id/… link
  unsigned baud = 38400;  ///< azeltrack's hub firmware without a baud jumper
  proto::HubAccept accept = proto::HubAccept::Crc8Only;
  double retry_s = 0.5;
};

class HubSerialLink {
 public:
  using OnFrame = std::function<void(const proto::HubFrame&)>;
  using OnEvent = std::function<void(const std::string&)>;  ///< "lost: …", "connected"

  /// Fails (naming the device) when it cannot be opened now: a missing adapter at start-up is a
  /// configuration error, not something to wait for silently.
  static Result<std::unique_ptr<HubSerialLink>> open(boost::asio::io_context& io,
                                                     HubSerialConfig config, OnFrame on_frame,
                                                     OnEvent on_event);
  ~HubSerialLink();
  HubSerialLink(const HubSerialLink&) = delete;
  HubSerialLink& operator=(const HubSerialLink&) = delete;

  [[nodiscard]] bool connected() const { return stream_.is_open(); }
  [[nodiscard]] const proto::HubCounters& counters() const { return decoder_.counters(); }
  void close();

 private:
  HubSerialLink(boost::asio::io_context& io, HubSerialConfig config, OnFrame on_frame,
                OnEvent on_event);
  Result<bool> attach();
  void read();
  void lost(const std::string& why);
  void retry();

  boost::asio::posix::stream_descriptor stream_;
  boost::asio::steady_timer retry_timer_;
  HubSerialConfig config_;
  OnFrame on_frame_;
  OnEvent on_event_;
  proto::HubDecoder decoder_;
  std::array<std::uint8_t, 256> buffer_{};
  std::shared_ptr<bool> alive_ = std::make_shared<bool>(true);
};

}  // namespace azt::linux_os
