#include "radio/rig_doppler_cycle.hpp"

#include <cmath>
#include <utility>

#include "azt/astro/time_scales.hpp"
#include "azt/linux/hamlib_rig_model.hpp"

namespace azt::app {
namespace {

/// No WSJT-X period heard: JT65's and Q65-60's 60 s, the EME modes' usual period.
constexpr double kDefaultTrPeriodS = 60.0;

nlohmann::json hz_json(const std::optional<WrittenHz>& w) {
  return w ? nlohmann::json(w->hz) : nlohmann::json(nullptr);
}

nlohmann::json at_json(const std::optional<WrittenHz>& w) {
  return w ? nlohmann::json(astro::format_iso8601_utc_unix(w->at_unix_s)) : nlohmann::json(nullptr);
}

nlohmann::json correction_json(const std::optional<WrittenHz>& w) {
  return w ? nlohmann::json(w->correction_hz) : nlohmann::json(nullptr);
}

nlohmann::json address_json(const std::optional<HostPort>& where) {
  return where ? nlohmann::json(where->text()) : nlohmann::json(nullptr);
}

/// How a rig is reached, in words: rigctld's address, or the Hamlib model opened directly.
nlohmann::json rig_json(const std::optional<HostPort>& rigctld,
                        const std::optional<linux_os::HamlibRigConfig>& hamlib) {
  if (rigctld) return rigctld->text();
  if (hamlib) return linux_os::describe_hamlib_rig(*hamlib);
  return nullptr;
}

/// The satellite-frame frequencies the rig follows: {norad, downlink_mhz, uplink_mhz (null:
/// receive only), mode}.
nlohmann::json transmitter_json(const TransmitterConfig* t) {
  if (t == nullptr) return nullptr;
  const auto& f = t->transmitter;
  return {
      {"norad", t->norad},
      {"downlink_mhz", f.downlink_hz / 1e6},
      {"uplink_mhz", f.uplink_hz ? nlohmann::json(*f.uplink_hz / 1e6) : nlohmann::json(nullptr)},
      {"mode", std::string(transponder_mode_name(f.mode))}};
}

}  // namespace

RigDopplerCycle::RigDopplerCycle(const RadioConfig& config, radio::RigPort& main,
                                 radio::RigPort* uplink)
    : config_(config), main_(main), uplink_(uplink) {}

void RigDopplerCycle::run(const RadioInputs& in) {
  switch (config_.doppler) {
    case DopplerSource::Off:
      return;
    case DopplerSource::Satellite:
      return run_satellite(in);
    case DopplerSource::Eme:
      return run_eme(in);
  }
}

bool RigDopplerCycle::differs(const Leg& leg, double hz) {
  return !leg.queued || std::round(leg.queued->hz) != std::round(hz);
}

bool RigDopplerCycle::queue_rx(double hz, double at_unix_s, double correction_hz) {
  if (!main_.set_rx_hz(hz)) return false;
  rx_.queued = WrittenHz{std::round(hz), at_unix_s, correction_hz};
  return true;
}

bool RigDopplerCycle::queue_tx(double hz, double at_unix_s, double correction_hz) {
  const bool queued = uplink_ != nullptr ? uplink_->set_rx_hz(hz) : main_.set_tx_hz(hz);
  if (queued) tx_.queued = WrittenHz{std::round(hz), at_unix_s, correction_hz};
  return queued;
}

void RigDopplerCycle::run_satellite(const RadioInputs& in) {
  transmitter_ = in.satellite ? config_.transmitter_of(in.satellite->norad) : nullptr;
  if (!in.satellite) return set_problem("no satellite is tracked");
  const TransmitterConfig* t = transmitter_;
  if (t == nullptr) {
    return set_problem("no [[satellites.transmitter]] for NORAD " + in.satellite->norad);
  }
  set_problem("");
  if (!planner_ || planner_norad_ != t->norad) {
    planner_ = std::make_unique<radio::SatelliteDopplerPlanner>(
        t->transmitter, radio::DopplerUpdateRule{config_.step_hz, 1.0});
    planner_norad_ = t->norad;
    awaiting_dial_.reset();
  }
  if (!main_.up()) return;
  const SatelliteCycle now{in.now_s, in.unix_s, in.satellite->range_rate_km_s};
  if (t->transmitter.mode == radio::TransponderMode::Fm) return plan_satellite(now, std::nullopt);
  // Track the knob: read the dial first and decide on its answer (on_event), as Gpredict reads
  // before it writes (gtk-rig-ctrl.c:1690-1726). Deciding on the last cycle's read instead wrote
  // over a turn made since, whenever the Doppler made the RX due (every cycle near TCA).
  if (main_.read_rx()) awaiting_dial_ = now;
}

void RigDopplerCycle::plan_satellite(const SatelliteCycle& at, std::optional<double> dial_hz) {
  const auto plan = planner_->plan(at.now_s, at.range_rate_km_s, dial_hz);
  if (plan.write_rx) queue_rx(plan.rx_hz, at.unix_s, plan.rx_hz - plan.satellite_downlink_hz);
  if (plan.write_tx && plan.tx_hz && plan.satellite_uplink_hz) {
    queue_tx(*plan.tx_hz, at.unix_s, *plan.tx_hz - *plan.satellite_uplink_hz);
  }
}

void RigDopplerCycle::run_eme(const RadioInputs& in) {
  const auto echo = in.echo_at ? in.echo_at(in.unix_s) : std::nullopt;
  if (!echo) return set_problem("the Moon's Doppler is not known (outside the ephemeris)");
  const auto correction = radio::eme_correction(config_.eme_mode, *echo);
  if (!correction) return set_problem(correction.error().message);
  set_problem("");
  const double dial_hz = config_.dial_mhz * 1e6;
  const double rx_hz = dial_hz + correction.value().rx_hz;
  if (differs(rx_, rx_hz)) queue_rx(rx_hz, in.unix_s, correction.value().rx_hz);
  eme_tx(in, *echo);
}

void RigDopplerCycle::eme_tx(const RadioInputs& in, const radio::EchoDoppler& now_echo) {
  const double dial_hz = config_.dial_mhz * 1e6;
  if (!config_.no_tx_qsy) {
    const auto c = radio::eme_correction(config_.eme_mode, now_echo);
    if (c && differs(tx_, dial_hz + c.value().tx_hz)) {
      queue_tx(dial_hz + c.value().tx_hz, in.unix_s, c.value().tx_hz);
    }
    return;
  }
  // WSJT-X's rule for rigs that cannot retune while keyed (astro.cpp:242-299): once per period,
  // for the middle of the next one, never while transmitting.
  const double period_s = in.tr_period_s.value_or(kDefaultTrPeriodS);
  const auto due = tx_period_.due(in.unix_s, period_s, in.transmitting);
  if (!due) return;
  const auto echo = in.echo_at(due->doppler_at_unix_s);
  if (!echo) return;
  const auto c = radio::eme_correction(config_.eme_mode, *echo);
  if (!c) return;
  if (queue_tx(dial_hz + c.value().tx_hz, due->doppler_at_unix_s, c.value().tx_hz)) {
    tx_period_.written(*due);
  }
}

void RigDopplerCycle::on_connected(RigRole role) {
  if (role == RigRole::Main) {
    rx_ = Leg();
    awaiting_dial_.reset();  // the read went with the connection
  }
  // The uplink is the main rig's split VFO unless a second rig carries it.
  if (role == RigRole::Uplink || uplink_ == nullptr) {
    tx_ = Leg();
    tx_period_.forget();
  }
  if (planner_) planner_->forget_written();
}

void RigDopplerCycle::on_event(RigRole role, const radio::RigEvent& e, double now_s) {
  using radio::RigCommand;
  using radio::RigEventKind;
  // Which leg this answer is about: the uplink rig's main VFO is the TX leg.
  const bool tx_leg = role == RigRole::Uplink || e.command == RigCommand::SetSplitFreq ||
                      e.command == RigCommand::GetSplitFreq;
  Leg& leg = tx_leg ? tx_ : rx_;
  switch (e.kind) {
    case RigEventKind::Written:
      if (e.command == RigCommand::SetFreq || e.command == RigCommand::SetSplitFreq) {
        leg.written = leg.queued;
        leg.readback_due = true;
      }
      return;
    case RigEventKind::RxRead:
    case RigEventKind::TxRead:
      return on_read(leg, tx_leg, e.hz, now_s);
    case RigEventKind::Refused:
      // A refused write is not on the rig: try again at the next cycle.
      if (e.command == RigCommand::SetFreq || e.command == RigCommand::SetSplitFreq) {
        leg.queued.reset();
      }
      return;
    case RigEventKind::VfoMode:
    case RigEventKind::LinkFailed:
      return;
  }
}

void RigDopplerCycle::on_read(Leg& leg, bool tx_leg, double hz, double now_s) {
  if (leg.readback_due) {
    leg.readback_due = false;
    if (planner_) tx_leg ? planner_->tx_written(now_s, hz) : planner_->rx_written(now_s, hz);
  }
  // Any read of the main VFO is the dial now (a read-back too: the queue merges the two).
  if (!tx_leg && awaiting_dial_ && planner_) {
    plan_satellite(*std::exchange(awaiting_dial_, std::nullopt), hz);
  }
}

nlohmann::json RigDopplerCycle::to_json() const {
  const std::optional<WrittenHz>& when = rx_.written ? rx_.written : tx_.written;
  const bool eme = config_.doppler == DopplerSource::Eme;
  return {{"doppler", std::string(doppler_source_name(config_.doppler))},
          {"rigctld", address_json(config_.rigctld)},
          {"tx_rigctld", address_json(config_.tx_rigctld)},
          {"rig", rig_json(config_.rigctld, config_.hamlib)},
          {"tx_rig", rig_json(config_.tx_rigctld, config_.tx_hamlib)},
          {"eme_mode",
           eme ? nlohmann::json(radio::eme_mode_name(config_.eme_mode)) : nlohmann::json(nullptr)},
          {"transmitter", transmitter_json(transmitter_)},
          {"rx_hz", hz_json(rx_.written)},
          {"tx_hz", hz_json(tx_.written)},
          {"at", at_json(when)},
          {"at_unix_s", when ? nlohmann::json(when->at_unix_s) : nlohmann::json(nullptr)},
          {"tx_at", at_json(tx_.written)},
          {"tx_at_unix_s",
           tx_.written ? nlohmann::json(tx_.written->at_unix_s) : nlohmann::json(nullptr)},
          {"rx_correction_hz", correction_json(rx_.written)},
          {"tx_correction_hz", correction_json(tx_.written)},
          {"problem", problem_.empty() ? nlohmann::json(nullptr) : nlohmann::json(problem_)}};
}

}  // namespace azt::app
