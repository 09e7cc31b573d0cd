#include "radio/station_radio.hpp"

#include "azt/astro/sky.hpp"
#include "common/sky_report.hpp"
#include "common/usage_error.hpp"
#include "radio/rig_links.hpp"

namespace azt::app {

std::string link_text(const linux_os::RigConnection* link) {
  if (link == nullptr) return "off";
  switch (link->state()) {
    case linux_os::RigLinkState::Connecting:
      return "connecting";
    case linux_os::RigLinkState::Up:
      return "up";
    case linux_os::RigLinkState::Down:
      return "down: " + link->down_reason();
  }
  return "off";
}

StationRadio::StationRadio(boost::asio::io_context& io, StationRadioParts parts)
    : p_(std::move(parts)),
      io_(io),
      timer_(io),
      wsjtx_(WsjtxParts{p_.wsjtx, p_.monotonic_s, p_.unix_s, p_.dx_grid, p_.log}) {
  main_ = make_link(RigRole::Main);
  uplink_ = make_link(RigRole::Uplink);
  cycle_ = std::make_unique<RigDopplerCycle>(p_.radio, main_ ? main_->port() : idle_session_,
                                             uplink_ ? &uplink_->port() : nullptr);
  if (auto opened = wsjtx_.open(io); !opened) throw UsageError(opened.error().message);
  if (main_) arm();
}

StationRadio::~StationRadio() { close(); }

void StationRadio::close() {
  closed_ = true;
  timer_.cancel();
  wsjtx_.close();
  main_.reset();
  uplink_.reset();
}

std::unique_ptr<linux_os::RigConnection> StationRadio::make_link(RigRole role) {
  const std::string name = rig_link_name(p_.radio, role);
  linux_os::RigLinkEvents events{
      [this, role, name](linux_os::RigLinkState state, const std::string& why) {
        on_link(role, state, why, name);
      },
      [this, role, name](const radio::RigEvent& e) {
        if (e.kind == radio::RigEventKind::Refused) p_.log(name + ": " + e.message);
        cycle_->on_event(role, e, p_.monotonic_s());
        // An answer may queue writes (the dial read plans the satellite cycle), on either
        // rig: the answering link sends its own, the other one is told here.
        if (main_) main_->flush();
        if (uplink_) uplink_->flush();
      }};
  return open_rig_link(io_, p_.radio, role, p_.monotonic_s, std::move(events));
}

void StationRadio::on_link(RigRole role, linux_os::RigLinkState state, const std::string& why,
                           const std::string& name) {
  // One line each way: the link keeps its own count of retries quiet.
  if (state == linux_os::RigLinkState::Up) {
    p_.log(name + ": link up");
    cycle_->on_connected(role);
  } else {
    p_.log(name + ": link down: " + why + " (retrying)");
  }
}

std::optional<radio::EchoDoppler> StationRadio::echo_at(double unix_s) const {
  const auto sky =
      sky_snapshot(p_.ephemeris, p_.sky.settings, astro::UtcInstant::from_unix_seconds(unix_s));
  if (!sky) return std::nullopt;
  const auto moon = sky->observe(astro::Target::moon());
  if (!moon || !moon->observation.place.range_rate_km_s) return std::nullopt;
  const double rate = *moon->observation.place.range_rate_km_s;
  radio::EchoDoppler echo;
  echo.self_echo_hz = astro::self_echo_doppler_hz(p_.radio.dial_mhz, rate);
  if (moon->dx_range_rate_km_s) {
    echo.dx_echo_hz = astro::dx_echo_doppler_hz(p_.radio.dial_mhz, rate, *moon->dx_range_rate_km_s);
  }
  return echo;
}

void StationRadio::cycle() {
  RadioInputs in;
  in.now_s = p_.monotonic_s();
  in.unix_s = p_.unix_s();
  if (p_.radio.doppler == DopplerSource::Satellite && p_.satellite) in.satellite = p_.satellite();
  in.echo_at = [this](double unix_s) { return echo_at(unix_s); };
  in.transmitting = wsjtx_.transmitting();
  in.tr_period_s = wsjtx_.tr_period_s();
  cycle_->run(in);
  if (main_) main_->flush();
  if (uplink_) uplink_->flush();
}

void StationRadio::arm() {
  timer_.expires_after(std::chrono::duration_cast<boost::asio::steady_timer::duration>(
      std::chrono::duration<double>(kCycleS)));
  timer_.async_wait([this](const boost::system::error_code& ec) {
    if (ec || closed_) return;
    cycle();
    arm();
  });
}

nlohmann::json StationRadio::radio_json() const {
  nlohmann::json j = cycle_->to_json();
  j["link"] = link_text(main_.get());
  if (uplink_) j["tx_link"] = link_text(uplink_.get());
  return j;
}

}  // namespace azt::app
