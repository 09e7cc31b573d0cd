#pragma once
// A station's front door over an antenna standing still, with faults the test sets: for the
// StationCommands and StationService tests.

#include <array>
#include <string>
#include <vector>

#include "azt/astro/erfa_ephemeris.hpp"
#include "config/sky_config.hpp"
#include "station/station_commands.hpp"

namespace azt::app::testing {

/// An antenna standing at az 100°, el 20° (and a pol feed at `pol_deg`, if set), with faults the
/// test sets. Only a direction test moves it: the tested axis at `test_step_deg` per tick, the
/// other way when `reversed`.
class StandingAntenna final : public AntennaBackend {
 public:
  void tick(double /*now_s*/, const control::Demand& demand,
            const control::AzEl& /*rate*/) override {
    const double sign = reversed ? -1.0 : 1.0;
    if (pol_deg) *pol_deg += sign * pol_demand.test_direction * test_step_deg;
    if (!demand.test) return;
    (demand.test->azimuth ? az_deg : el_deg) += sign * demand.test->direction * test_step_deg;
  }
  void set_pol_demand(const control::PolDemand& demand) override { pol_demand = demand; }
  [[nodiscard]] std::optional<PolStatus> pol_status() const override {
    if (!pol_deg) return std::nullopt;
    return PolStatus{*pol_deg, std::nullopt, false, "", -95.0, 95.0};
  }
  [[nodiscard]] std::optional<proto::PositionReport> position(double /*now_s*/) const override {
    if (lost) return std::nullopt;
    proto::PositionReport r;
    r.az_deg = az_deg;
    r.el_deg = el_deg;
    r.az_mount_deg = az_deg;
    r.fault = !faults_.empty();
    return r;
  }
  void stop_now(double /*now_s*/) override {}
  [[nodiscard]] std::vector<std::string> faults() const override { return faults_; }
  void clear_faults() override { faults_.clear(); }
  void set_corrections(const control::PositionCorrections& /*corrections*/) override {}
  [[nodiscard]] std::optional<control::AzEl> encoder_reading() const override {
    return std::nullopt;
  }
  [[nodiscard]] std::string describe() const override { return "standing antenna"; }
  [[nodiscard]] std::vector<NamedAxisStatus> axes() const override { return axes_; }
  std::optional<std::string> home(double /*now_s*/, const std::string& axis) override {
    if (home_refusal) return home_refusal;
    homed.push_back(axis);
    return std::nullopt;
  }
  void stop_homing(double /*now_s*/, std::string_view reason) override {
    homing_stopped.emplace_back(reason);
  }

  std::vector<std::string> faults_;
  double az_deg = 100.0;
  double el_deg = 20.0;
  double test_step_deg = 0.0;  ///< how far a direction test's tick moves the tested axis
  bool reversed = false;
  bool lost = false;              ///< the position unknown
  std::optional<double> pol_deg;  ///< a pol axis ([mount.pol]) standing here; none by default
  control::PolDemand pol_demand;
  std::vector<NamedAxisStatus> axes_;       ///< what axes() reports
  std::optional<std::string> home_refusal;  ///< home()'s answer; none: homing starts
  std::vector<std::string> homed;           ///< each axis home() started
  std::vector<std::string> homing_stopped;  ///< each stop_homing()'s reason
};

/// The front door of a station with the Sun and the Moon as targets, on a 0–450° mount with
/// el 0–90°; what it accepts and refuses is recorded.
struct StationRig {
  std::array<control::ParkSlot, control::ModeController::kParkSlots> slots{{
      {"park", {180.0, 0.0}},
      {"stow", {180.0, 90.0}},
      {"north", {0.0, 0.0}},
      {"service", {90.0, 0.0}},
  }};
  control::ModeController modes{slots, control::OutOfRangePolicy::Hold, 0.0};
  StandingAntenna antenna;
  astro::ErfaEphemeris ephemeris;
  SkyConfig station{{}, "144", {astro::Target::sun(), astro::Target::moon()}};
  SkyFollower sky{ephemeris, station};
  double now_s = 0.0;
  std::vector<std::string> accepted;
  std::vector<std::string> refused;
  StationCommands commands{StationCommandParts{
      modes, antenna, sky, nullptr, proto::TargetLimits{-180.0, 450.0, 0.0, 90.0},
      control::ElevationRange{0.0, 90.0}, [this] { return now_s; }, [] { return 1.8e9; }, 0.0,
      [this](const CommandSource& s, const CommandRecord& r) {
        accepted.push_back(s.name + ": " + r.words);
      },
      [this](const CommandSource& s, const Refusal& r) {
        refused.push_back(s.name + ": " + r.reason);
      }}};
};

inline CommandSource console_source() {
  return CommandSource{CommandSource::Kind::Console, "console 127.0.0.1"};
}
inline CommandSource program_source() {
  return CommandSource{CommandSource::Kind::Program, "rotctld 127.0.0.1:50000"};
}

}  // namespace azt::app::testing
