#include "azt/linux/rigctld_link.hpp"

#include <algorithm>
#include <istream>
#include <utility>

namespace azt::linux_os {
namespace {

namespace asio = boost::asio;

/// rigctld's longest answer to what the session asks is a frequency; a line this long is not
/// rigctld.
constexpr std::size_t kMaxLineBytes = 4096;

asio::steady_timer::duration seconds(double s) {
  return std::chrono::duration_cast<asio::steady_timer::duration>(std::chrono::duration<double>(s));
}

}  // namespace

RigctldLink::RigctldLink(asio::io_context& io, RigctldLinkConfig config,
                         std::function<double()> now_s, RigLinkEvents events)
    : resolver_(io),
      socket_(io),
      retry_timer_(io),
      poll_timer_(io),
      in_(kMaxLineBytes),
      config_(std::move(config)),
      now_s_(std::move(now_s)),
      events_(std::move(events)),
      session_(config_.session),
      retry_s_(config_.retry_s) {
  connect();
  poll();
}

RigctldLink::~RigctldLink() {
  *alive_ = false;
  boost::system::error_code ignored;
  socket_.close(ignored);
}

std::string RigctldLink::describe() const {
  return "rigctld at " + config_.host + ":" + config_.port;
}

void RigctldLink::connect() {
  // Asio resolves on its own thread: a slow DNS never waits on the loop.
  resolver_.async_resolve(
      config_.host, config_.port,
      [this, alive = alive_](const boost::system::error_code& ec,
                             const asio::ip::tcp::resolver::results_type& endpoints) {
        if (!*alive) return;
        if (ec) return lost("cannot resolve " + config_.host + ": " + ec.message());
        asio::async_connect(socket_, endpoints,
                            [this, alive](const boost::system::error_code& e,
                                          const asio::ip::tcp::endpoint& /*endpoint*/) {
                              if (!*alive) return;
                              if (e) return lost(e.message());
                              boost::system::error_code ignored;
                              socket_.set_option(asio::ip::tcp::no_delay(true), ignored);
                              session_.connected();
                              read();
                              flush();
                            });
      });
}

void RigctldLink::flush() {
  if (writing_ || !socket_.is_open()) return;
  auto line = session_.next_line(now_s_());
  if (!line) return;
  writing_ = true;
  out_ = std::move(*line);
  asio::async_write(socket_, asio::buffer(out_),
                    [this, alive = alive_](const boost::system::error_code& ec, std::size_t) {
                      if (!*alive) return;
                      writing_ = false;
                      if (ec == asio::error::operation_aborted) return;  // closed by lost()
                      if (ec) return lost(ec.message());
                      flush();
                    });
}

void RigctldLink::read() {
  asio::async_read_until(
      socket_, in_, '\n',
      [this, alive = alive_](const boost::system::error_code& ec, std::size_t n) {
        if (!*alive || ec == asio::error::operation_aborted) return;  // closed by lost()
        if (ec == asio::error::not_found) return lost("a line longer than rigctld ever sends");
        if (ec)
          return lost(ec == asio::error::eof ? "rigctld closed the connection" : ec.message());
        std::string line(n, '\0');
        std::istream(&in_).read(line.data(), static_cast<std::streamsize>(n));
        while (!line.empty() && (line.back() == '\n' || line.back() == '\r')) line.pop_back();
        on_line(line);
        if (socket_.is_open()) read();
      });
}

void RigctldLink::on_line(const std::string& line) {
  const auto event = session_.on_line(line);
  if (!event) return;
  if (event->kind == radio::RigEventKind::LinkFailed) return lost(event->message);
  if (event->kind == radio::RigEventKind::VfoMode && state_ != RigLinkState::Up) {
    state_ = RigLinkState::Up;
    down_reason_.clear();
    retry_s_ = config_.retry_s;
    if (events_.link) events_.link(RigLinkState::Up, "");
    down_reported_ = false;
  }
  if (events_.event) events_.event(*event);
  flush();
}

void RigctldLink::poll() {
  poll_timer_.expires_after(seconds(config_.poll_s));
  poll_timer_.async_wait([this, alive = alive_](const boost::system::error_code& ec) {
    if (ec || !*alive) return;
    if (auto failed = session_.on_tick(now_s_())) lost(failed->message);
    poll();
  });
}

void RigctldLink::lost(const std::string& why) {
  boost::system::error_code ignored;
  socket_.close(ignored);
  in_.consume(in_.size());
  writing_ = false;
  session_.disconnected();
  const bool was_up = std::exchange(state_, RigLinkState::Down) == RigLinkState::Up;
  down_reason_ = why;
  // Said once per loss: a rigctld that is not running is not news every retry.
  if (events_.link && (was_up || !down_reported_)) events_.link(RigLinkState::Down, why);
  down_reported_ = true;
  retry_timer_.expires_after(seconds(retry_s_));
  retry_s_ = std::min(retry_s_ * 2.0, config_.max_retry_s);
  retry_timer_.async_wait([this, alive = alive_](const boost::system::error_code& ec) {
    if (!ec && *alive) connect();
  });
}

}  // namespace azt::linux_os
