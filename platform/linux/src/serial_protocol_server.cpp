#include "azt/linux/serial_protocol_server.hpp"

#include <fcntl.h>
#include <sys/inotify.h>
#include <sys/ioctl.h>
#include <sys/stat.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "azt/linux/runtime_dir.hpp"
#include "azt/linux/serial_port.hpp"

namespace azt::linux_os {
namespace {

namespace asio = boost::asio;

std::string errno_text() { return std::strerror(errno); }

struct PtyPair {
  int master = -1;
  int slave = -1;
  std::string slave_name;
};

Result<PtyPair> open_pty() {
  PtyPair p;
  p.master = posix_openpt(O_RDWR | O_NOCTTY | O_CLOEXEC);
  if (p.master < 0) return fail("cannot create a pseudo-terminal: " + errno_text());
  std::array<char, 128> name{};
  if (grantpt(p.master) != 0 || unlockpt(p.master) != 0 ||
      ptsname_r(p.master, name.data(), name.size()) != 0) {
    const auto why = errno_text();
    ::close(p.master);
    return fail("cannot set up the pseudo-terminal: " + why);
  }
  p.slave_name = name.data();
  p.slave = ::open(p.slave_name.c_str(), O_RDWR | O_NOCTTY | O_CLOEXEC);
  if (p.slave < 0) {
    const auto why = errno_text();
    ::close(p.master);
    return fail("cannot open " + p.slave_name + ": " + why);
  }
  return p;
}

/// The link's path for "pty:NAME": NAME as given when absolute, else in the runtime directory.
std::string link_path(const std::string& spec) {
  if (!spec.empty() && spec.front() == '/') return spec;
  return runtime_dir() + "/" + spec;
}

}  // namespace

SerialProtocolServer::SerialProtocolServer(asio::io_context& io, SessionFactory factory, Log log)
    : stream_(io), factory_(std::move(factory)), session_(factory_()), log_(std::move(log)) {}

SerialProtocolServer::~SerialProtocolServer() { close(); }

Result<std::unique_ptr<SerialProtocolServer>> SerialProtocolServer::open(asio::io_context& io,
                                                                         const std::string& device,
                                                                         unsigned baud,
                                                                         SessionFactory factory,
                                                                         Log log) {
  std::unique_ptr<SerialProtocolServer> server(
      new SerialProtocolServer(io, std::move(factory), std::move(log)));
  constexpr std::string_view kPty = "pty:";
  if (device.rfind(kPty, 0) == 0) {
    if (device.size() == kPty.size()) return fail(device + ": give a path after pty:");
    const std::string link = link_path(device.substr(kPty.size()));
    auto pty = open_pty();
    if (!pty) return fail(device + ": " + pty.error().message);
    // The slave is raw too: no echo of the client's bytes, no CR -> LF translation.
    if (auto raw = make_raw_serial(pty->slave, baud); !raw) {
      ::close(pty->master);
      ::close(pty->slave);
      return fail(device + ": " + raw.error().message);
    }
    auto linked = PtyLink::claim(link, pty->slave_name);
    if (!linked) {
      ::close(pty->master);
      ::close(pty->slave);
      return fail(device + ": " + linked.error().message);
    }
    server->keep_slave_fd_ = pty->slave;
    server->link_.emplace(std::move(linked).value());
    server->path_ = link;
    server->stream_.assign(pty->master);
    server->watch_clients(pty->slave_name);
  } else {
    auto fd = open_serial_device(device, baud);
    if (!fd) return fd.error();
    server->path_ = device;
    server->stream_.assign(*fd);
  }
  server->read();
  return server;
}

void SerialProtocolServer::close() {
  *alive_ = false;
  boost::system::error_code ignored;
  stream_.close(ignored);
  clients_.close(ignored);
  if (keep_slave_fd_ >= 0) {
    ::close(keep_slave_fd_);
    keep_slave_fd_ = -1;
  }
  link_.reset();  // removes the link if it is still ours
}

void SerialProtocolServer::read() {
  stream_.async_read_some(asio::buffer(buffer_),
                          [this, alive = alive_](boost::system::error_code ec, std::size_t n) {
                            if (!*alive) return;
                            if (ec) {
                              // A real device that went away (USB unplugged): report once and stop
                              // reading; the daemon keeps running and the other servers are
                              // unaffected.
                              if (log_) log_("read failed, server stopped: " + ec.message());
                              return;
                            }
                            // Events queued before these bytes are looked at first. If the
                            // client hung up, the bytes are its last: its commands still act
                            // (rotctl sends a set and exits at once), its replies go nowhere.
                            const std::string events = queued_client_events();
                            const bool leaving = hangs_up(events);
                            if (leaving) {
                              (void)feed(std::string_view(buffer_.data(), n));
                            }
                            (void)apply_client_events(events.data(), events.size());
                            if (!leaving) {
                              const std::string reply = feed(std::string_view(buffer_.data(), n));
                              if (!reply.empty()) write(reply);
                            }
                            read();
                          });
}

void SerialProtocolServer::watch_clients(const std::string& slave_name) {
  // Our own slave end stays open, so the master never sees a client come or go; inotify on the
  // slave's device node does (IN_OPEN, IN_CLOSE_*), with no polling.
  const int fd = ::inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
  if (fd < 0) {
    if (log_) log_("cannot watch for clients (inotify): " + errno_text());
    return;
  }
  if (::inotify_add_watch(fd, slave_name.c_str(), IN_OPEN | IN_CLOSE) < 0) {
    if (log_) log_("cannot watch " + slave_name + " for clients: " + errno_text());
    ::close(fd);
    return;
  }
  clients_.assign(fd);
  read_client_events();
}

void SerialProtocolServer::read_client_events() {
  clients_.async_read_some(asio::buffer(events_),
                           [this, alive = alive_](boost::system::error_code ec, std::size_t n) {
                             if (!*alive || ec) return;
                             (void)apply_client_events(events_.data(), n);
                             read_client_events();
                           });
}

bool SerialProtocolServer::apply_client_events(const char* data, std::size_t size) {
  bool hung_up = false;
  for (std::size_t at = 0; at + sizeof(inotify_event) <= size;) {
    inotify_event event{};
    std::memcpy(&event, data + at, sizeof event);
    at += sizeof(inotify_event) + event.len;
    // In the order they happened: a client that left, then the next one that opened.
    if ((event.mask & IN_CLOSE) != 0U) {
      discard_pending(true);
      hung_up = true;
    }
    if ((event.mask & IN_OPEN) != 0U) discard_pending(false);
  }
  return hung_up;
}

std::string SerialProtocolServer::queued_client_events() {
  std::string out;
  if (!clients_.is_open()) return out;
  std::array<char, 1024> events{};
  for (;;) {
    const ssize_t n = ::read(clients_.native_handle(), events.data(), events.size());
    if (n <= 0) return out;  // EAGAIN: nothing more queued
    out.append(events.data(), static_cast<std::size_t>(n));
  }
}

bool SerialProtocolServer::hangs_up(const std::string& events) {
  for (std::size_t at = 0; at + sizeof(inotify_event) <= events.size();) {
    inotify_event event{};
    std::memcpy(&event, events.data() + at, sizeof event);
    if ((event.mask & IN_CLOSE) != 0U) return true;
    at += sizeof(inotify_event) + event.len;
  }
  return false;
}

std::string SerialProtocolServer::feed(std::string_view bytes) {
  try {
    return session_->feed(bytes);
  } catch (const std::exception& e) {
    // A fault in the session drops these bytes, never the daemon.
    if (log_) log_(std::string("internal error, input dropped: ") + e.what());
    return {};
  }
}

void SerialProtocolServer::discard_pending(bool hang_up) {
  // What a client that left did not read must not greet the next one. At a
  // hang-up the commands it sent that are not read yet still act (a set sent just before
  // closing is meant), but their replies are dropped; a half-sent line is forgotten with the
  // session. Then, and at an open, the replies queued towards the slave are flushed.
  if (hang_up) {
    std::array<char, 1024> bytes{};
    for (int i = 0; i < 64; ++i) {  // bounded: a pty holds a few KiB
      const ssize_t n = ::read(stream_.native_handle(), bytes.data(), bytes.size());
      if (n <= 0) break;
      (void)feed(std::string_view(bytes.data(), static_cast<std::size_t>(n)));
    }
    session_ = factory_();
  }
  pending_.clear();
  (void)::tcflush(keep_slave_fd_, TCIFLUSH);
  if (log_) log_(hang_up ? "client closed the port" : "client opened the port");
}

void SerialProtocolServer::write(const std::string& bytes) {
  // A serial peer that stops reading must not grow memory: keep at most 4 KiB unsent.
  if (pending_.size() + bytes.size() > 4096) pending_.clear();
  pending_ += bytes;
  if (writing_) return;
  writing_ = true;
  auto chunk = std::make_shared<std::string>(std::move(pending_));
  pending_.clear();
  asio::async_write(stream_, asio::buffer(*chunk),
                    [this, chunk, alive = alive_](boost::system::error_code ec, std::size_t) {
                      if (!*alive) return;
                      writing_ = false;
                      if (ec) {
                        if (log_) log_("write failed: " + ec.message());
                        return;
                      }
                      if (!pending_.empty()) write(std::string());
                    });
}

}  // namespace azt::linux_os
