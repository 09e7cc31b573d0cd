#include "azt/linux/serial_protocol_server.hpp"

#include <fcntl.h>
#include <sys/ioctl.h>
#include <sys/stat.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

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

/// Links `link` to `target`, replacing only a stale symlink (never a regular file or device).
Result<bool> make_link(const std::string& link, const std::string& target) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path path(link);
  if (path.has_parent_path()) fs::create_directories(path.parent_path(), ec);
  if (ec) return fail("cannot create " + path.parent_path().string() + ": " + ec.message());
  const auto status = fs::symlink_status(path, ec);
  if (fs::exists(status)) {
    if (!fs::is_symlink(status)) return fail(link + " exists and is not a symbolic link");
    fs::remove(path, ec);
  }
  fs::create_symlink(target, path, ec);
  if (ec) return fail("cannot link " + link + ": " + ec.message());
  return true;
}

}  // namespace

SerialProtocolServer::SerialProtocolServer(asio::io_context& io,
                                           std::unique_ptr<proto::ProtocolSession> s, Log log)
    : stream_(io), session_(std::move(s)), log_(std::move(log)) {}

SerialProtocolServer::~SerialProtocolServer() { close(); }

Result<std::unique_ptr<SerialProtocolServer>> SerialProtocolServer::open(
    asio::io_context& io, const std::string& device, unsigned baud,
    std::unique_ptr<proto::ProtocolSession> session, Log log) {
  std::unique_ptr<SerialProtocolServer> server(
      new SerialProtocolServer(io, std::move(session), std::move(log)));
  constexpr std::string_view kPty = "pty:";
  if (device.rfind(kPty, 0) == 0) {
    const std::string link = device.substr(kPty.size());
    if (link.empty()) return fail(device + ": give a path after pty:");
    auto pty = open_pty();
    if (!pty) return fail(device + ": " + pty.error().message);
    // The slave is raw too: no echo of the client's bytes, no CR -> LF translation.
    if (auto raw = make_raw_serial(pty->slave, baud); !raw) {
      ::close(pty->master);
      ::close(pty->slave);
      return fail(device + ": " + raw.error().message);
    }
    if (auto linked = make_link(link, pty->slave_name); !linked) {
      ::close(pty->master);
      ::close(pty->slave);
      return fail(device + ": " + linked.error().message);
    }
    server->keep_slave_fd_ = pty->slave;
    server->link_ = link;
    server->path_ = link;
    server->stream_.assign(pty->master);
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
  if (keep_slave_fd_ >= 0) {
    ::close(keep_slave_fd_);
    keep_slave_fd_ = -1;
  }
  if (!link_.empty()) {
    std::error_code ec;
    std::filesystem::remove(link_, ec);
    link_.clear();
  }
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
                            std::string reply = session_->feed(std::string_view(buffer_.data(), n));
                            if (!reply.empty()) write(reply);
                            read();
                          });
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
