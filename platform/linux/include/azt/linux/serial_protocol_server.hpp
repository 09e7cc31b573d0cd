#pragma once
// A serial-line protocol server (GS-232, EasyComm, SPID) on a real serial device or on a
// pseudo-terminal that azeltrack creates and links at a configured path, so a PC program (or
// Hamlib's rotctl) opens that path as if it were the controller's COM port.
//
// Device syntax: "pty:gs232b" (pseudo-terminal, symlink in the runtime directory, runtime_dir.hpp),
// "pty:/abs/path" (symlink there, in a directory owned by this program's user; either held by
// one daemon at a time, pty_link.hpp) or a device path
// ("/dev/ttyUSB0"; opened exclusively, raw 8N1 at the configured baud). On a pseudo-terminal a
// client's open and hang-up discard what is pending, so one client's unread replies never
// reach the next.

#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "azt/linux/asio.hpp"
#include "azt/linux/pty_link.hpp"
#include "azt/proto/rotator_service.hpp"
#include "azt/util/result.hpp"

namespace azt::linux_os {

class SerialProtocolServer {
 public:
  using Log = std::function<void(const std::string& event)>;
  /// Makes the session for one client's conversation: at start, and afresh when a client of a
  /// pseudo-terminal hangs up, so nothing the leaving client half-sent prefixes the next one's.
  using SessionFactory = std::function<std::unique_ptr<proto::ProtocolSession>()>;

  /// Opens the device (or creates the pseudo-terminal and its link). Errors name the device and
  /// the reason: missing, busy (another program has it open exclusively), not a tty, bad baud.
  static Result<std::unique_ptr<SerialProtocolServer>> open(boost::asio::io_context& io,
                                                            const std::string& device,
                                                            unsigned baud, SessionFactory factory,
                                                            Log log);
  ~SerialProtocolServer();
  SerialProtocolServer(const SerialProtocolServer&) = delete;
  SerialProtocolServer& operator=(const SerialProtocolServer&) = delete;

  /// The path clients open: the link of a pseudo-terminal, or the device itself.
  [[nodiscard]] const std::string& path() const { return path_; }
  void close();

 private:
  SerialProtocolServer(boost::asio::io_context& io, SessionFactory factory, Log log);
  void read();
  void write(const std::string& bytes);
  void watch_clients(const std::string& slave_name);
  void read_client_events();
  /// Acts on inotify events in order; true if a client hung up.
  bool apply_client_events(const char* data, std::size_t size);
  /// The inotify events already queued (read without waiting), to act on around input.
  std::string queued_client_events();
  [[nodiscard]] static bool hangs_up(const std::string& events);
  /// The session's answer to `bytes`; an exception drops them (logged), never the daemon.
  std::string feed(std::string_view bytes);
  void discard_pending(bool hang_up);

  boost::asio::posix::stream_descriptor stream_;
  boost::asio::posix::stream_descriptor clients_{stream_.get_executor()};  ///< inotify events
  std::array<char, 1024> events_{};
  int keep_slave_fd_ = -1;  ///< our own open slave end: reads never fail with EIO between clients
  std::string path_;
  std::optional<PtyLink> link_;  ///< the link we hold to our pseudo-terminal
  SessionFactory factory_;
  std::unique_ptr<proto::ProtocolSession> session_;
  Log log_;
  std::array<char, 1024> buffer_{};
  std::string pending_;
  bool writing_ = false;
  std::shared_ptr<bool> alive_ = std::make_shared<bool>(true);
};

}  // namespace azt::linux_os
