#include "radio/wsjtx_listener.hpp"

#include <cmath>
#include <variant>

#include "azt/astro/time_scales.hpp"
#include "azt/radio/wsjtx_message.hpp"
#include "azt/radio/wsjtx_tr_period.hpp"

namespace azt::app {
namespace {

/// A sender of garbage is logged at most once a minute; the counter counts every one.
constexpr double kMalformedLogEveryS = 60.0;

}  // namespace

WsjtxListener::WsjtxListener(WsjtxParts parts) : p_(std::move(parts)) {}

Result<bool> WsjtxListener::open(boost::asio::io_context& io) {
  if (!p_.config.listen) return false;
  // The decoder's limit is the buffer: a longer datagram is reported by its real length.
  auto socket = linux_os::UdpReceiver::open(
      io, p_.config.listen->host, p_.config.listen->port, radio::kMaxDatagramBytes,
      [this](std::string_view datagram, const std::string&) { on_datagram(datagram); },
      [this](std::size_t bytes, const std::string&) { on_oversized(bytes); });
  if (!socket) return fail("[wsjtx] listen: " + socket.error().message);
  socket_ = std::move(socket).value();
  p_.log("wsjtx: listening on " + p_.config.listen->text() +
         (socket_->multicast() ? " (multicast group joined)" : ""));
  return true;
}

void WsjtxListener::close() {
  if (socket_) socket_->close();
}

void WsjtxListener::heard(const std::string& id) {
  last_heard_mono_s_ = p_.monotonic_s();
  last_heard_unix_s_ = p_.unix_s();
  id_ = id;
}

void WsjtxListener::on_datagram(std::string_view datagram) {
  const auto message = radio::decode_wsjtx_datagram(datagram);
  if (!message) return malformed(message.error().message);
  if (const auto* status = std::get_if<radio::WsjtxStatus>(&message.value())) {
    return on_status(*status);
  }
  if (const auto* beat = std::get_if<radio::WsjtxHeartbeat>(&message.value())) {
    ++received_.heartbeat;
    return heard(beat->id);
  }
  if (const auto* close = std::get_if<radio::WsjtxClose>(&message.value())) {
    return on_close(*close);
  }
  ++received_.other;
}

void WsjtxListener::on_status(const radio::WsjtxStatus& status) {
  ++received_.status;
  heard(status.id);
  dx_call_ = status.dx_call;
  if (status.transmitting != transmitting_) {
    p_.log(std::string("wsjtx: ") + (status.transmitting ? "transmitting" : "receiving"));
    // The receipt of the Status that began it: the hold's latency is measured from here.
    transmitting_since_unix_s_ =
        status.transmitting ? std::optional<double>(p_.unix_s()) : std::nullopt;
  }
  transmitting_ = status.transmitting;
  // Each Status says the period now: given, or the mode's own (FT8's 15 s is never sent), or
  // unknown after a change to a mode whose period WSJT-X does not say.
  tr_period_s_ = radio::tr_period_s(status);
  const std::string grid = status.stations ? status.stations->dx_grid : "";
  if (grid != dx_grid_) {
    dx_grid_ = grid;
    if (p_.config.follow_dx_grid && !grid.empty() && p_.dx_grid) p_.dx_grid(grid);
  }
}

void WsjtxListener::on_close(const radio::WsjtxClose& close) {
  ++received_.close;
  heard(close.id);
  if (transmitting_) p_.log("wsjtx: closed while transmitting; hold released");
  transmitting_ = false;
  transmitting_since_unix_s_.reset();
}

void WsjtxListener::on_oversized(std::size_t bytes) {
  malformed("a datagram of " + std::to_string(bytes) + " bytes (over " +
            std::to_string(radio::kMaxDatagramBytes) + ")");
}

void WsjtxListener::malformed(const std::string& why) {
  ++malformed_;
  last_malformed_ = why;
  const double now = p_.monotonic_s();
  if (malformed_logged_at_s_ && now - *malformed_logged_at_s_ < kMalformedLogEveryS) return;
  malformed_logged_at_s_ = now;
  p_.log("wsjtx: malformed datagram dropped (" + std::to_string(malformed_) + " so far): " + why);
}

bool WsjtxListener::transmitting() const {
  return transmitting_ && last_heard_mono_s_ && p_.monotonic_s() - *last_heard_mono_s_ < kStaleS;
}

bool WsjtxListener::motion_hold() const {
  if (p_.config.hold_motion_while_transmitting && transmitting()) return true;
  if (p_.config.move_in_last_s <= 0.0 || !tr_period_s_ || !last_heard_mono_s_ ||
      p_.monotonic_s() - *last_heard_mono_s_ >= kStaleS) {
    return false;
  }
  const double into_period_s = std::fmod(p_.unix_s(), *tr_period_s_);
  return into_period_s < *tr_period_s_ - p_.config.move_in_last_s;
}

nlohmann::json WsjtxListener::to_json() const {
  using nlohmann::json;
  return {
      {"listening", socket_ != nullptr},
      {"address", p_.config.listen ? json(p_.config.listen->text()) : json(nullptr)},
      {"last_heard", last_heard_unix_s_ ? json(astro::format_iso8601_utc_unix(*last_heard_unix_s_))
                                        : json(nullptr)},
      {"id", id_},
      {"dx_call", dx_call_},
      {"dx_grid", dx_grid_},
      {"transmitting", transmitting()},
      {"transmitting_since_unix_s",
       transmitting() ? json(*transmitting_since_unix_s_) : json(nullptr)},
      {"hold", motion_hold()},
      {"tr_period_s", tr_period_s_ ? json(*tr_period_s_) : json(nullptr)},
      {"received",
       {{"heartbeat", received_.heartbeat},
        {"status", received_.status},
        {"close", received_.close},
        {"other", received_.other}}},
      {"malformed", malformed_},
      {"last_malformed", last_malformed_.empty() ? json(nullptr) : json(last_malformed_)}};
}

}  // namespace azt::app
