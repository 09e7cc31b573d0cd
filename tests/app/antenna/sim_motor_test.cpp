// The `sim` backend with [sim.az] brake and motor_heating (docs/control.md "The simulated
// antenna"): the daemon's own station drives the plant's brake line and reads its winding's
// temperature through the simulated ports, in virtual time; `simulate` flies the same plants.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "antenna/antenna_backend.hpp"
#include "azt/sim/plant_rig.hpp"
#include "azt/sim/station_sim.hpp"
#include "config/config_file.hpp"
#include "config/daemon_config.hpp"

namespace azt::app {
namespace {

constexpr double kTickS = 0.05;

DaemonConfig config_of(const std::string& az_keys) {
  return daemon_config_from(ConfigFile::parse(
      "[station]\ngrid = \"FN06HE\"\n[target]\nname = \"stop\"\n[sim.az]\nstart_deg = 100.0\n" +
          az_keys,
      "sim.toml"));
}

/// A slow brake (1.2 s to lift) the controller is told takes 1.5 s.
const std::string kSlowBrake = R"(brake = true
brake_lift_s = 1.2
brake_hold_s = 0.3
brake_release_s = 1.5
brake_engage_s = 0.5
brake_idle_s = 1.0
)";

/// A motor still warm from a long move, whose winding settles 80 °C above the air at full duty.
const std::string kWarmMotor = R"(motor_heating = true
motor_start_c = 60.0
motor_rise_c = 80.0
motor_time_constant_s = 30.0
temperature_limit_c = 75.0
temperature_hysteresis_c = 5.0
)";

struct SimRig {
  explicit SimRig(const std::string& az_keys)
      : config(config_of(az_keys)), backend(make_sim_backend(config, &truth)) {}

  /// Ticks at 20 Hz for `seconds` towards `az_deg`; `each` sees every tick's time.
  template <typename Each>
  void run(double az_deg, double seconds, Each each) {
    const auto ticks = static_cast<int>(std::lround(seconds / kTickS));
    for (int i = 0; i < ticks; ++i) {
      control::Demand d;
      d.position = control::AzEl{az_deg, 10.0};
      backend->tick(t, d, control::AzEl{});
      each(t);
      t += kTickS;
    }
  }
  void run(double az_deg, double seconds) {
    run(az_deg, seconds, [](double) {});
  }
  [[nodiscard]] double az_deg() const { return truth->plants().az().shaft_deg(); }
  [[nodiscard]] bool has_fault(const std::string& text) const {
    const auto f = backend->faults();
    return std::any_of(f.begin(), f.end(),
                       [&](const std::string& s) { return s.find(text) != std::string::npos; });
  }
  [[nodiscard]] std::string faults() const {
    std::string out;
    for (const auto& f : backend->faults()) out += f + "; ";
    return out;
  }

  DaemonConfig config;
  std::shared_ptr<const sim::PlantRig> truth;
  std::unique_ptr<AntennaBackend> backend;
  double t = 0.0;
};

TEST(SimMotor, ASlowBrakeGetsNoDutyBeforeItsReleaseTimeAndIsNeverPulledAgainst) {
  SimRig rig(kSlowBrake);
  const sim::BrakePlant* brake = rig.truth->brake(0);
  ASSERT_NE(brake, nullptr);
  EXPECT_EQ(rig.truth->brake(1), nullptr) << "[sim.el] has no brake";
  EXPECT_NE(rig.backend->describe().find("; az: simulated brake"), std::string::npos)
      << rig.backend->describe();
  std::optional<double> line_on_s;  // the first tick whose step found the line energised
  std::optional<double> first_duty_s;
  rig.run(200.0, 90.0, [&](double t) {
    if (!line_on_s && brake->progress() > 0.0) line_on_s = t - kTickS;
    const double duty = rig.truth->duty(0);
    if (!first_duty_s && duty != 0.0) first_duty_s = t;
    if (duty != 0.0) {
      EXPECT_GE(brake->progress(), 1.0) << "a duty of " << duty << " at " << t;
    }
  });
  ASSERT_TRUE(line_on_s && first_duty_s) << rig.faults();
  // The controller's 1.5 s, not the brake's 1.2 s: the duty waits for the configured time.
  EXPECT_NEAR(*first_duty_s - *line_on_s, 1.5, kTickS + 1e-9);
  EXPECT_EQ(brake->pulled_against_steps(), 0U);
  EXPECT_NEAR(rig.az_deg(), 200.0, 0.3);
  EXPECT_EQ(brake->progress(), 0.0) << "applied again once the axis was at rest";
  EXPECT_TRUE(rig.backend->faults().empty()) << rig.faults();
  // What /api/state antenna.axes shows: the azimuth's brake, held again.
  const auto axes = rig.backend->axes();
  ASSERT_FALSE(axes.empty());
  EXPECT_EQ(axes[0].axis, "az");
  EXPECT_TRUE(axes[0].status.brake == control::BrakeState::Engaged);
}

TEST(SimMotor, ABrakeTheControllerReleasesTooSoonIsPulledAgainst) {
  // The operator tries a release time shorter than the brake's own lift: the rehearsal shows it.
  SimRig rig("brake = true\nbrake_lift_s = 1.2\nbrake_release_s = 0.5\n");
  rig.run(200.0, 5.0);
  EXPECT_GT(rig.truth->brake(0)->pulled_against_s(), 0.5);
}

TEST(SimMotor, AHotMotorTripsLatchesWhileHotAndClearsOnceCool) {
  SimRig rig(kWarmMotor);
  bool tripped = false;
  for (int i = 0; i < 1200 && !tripped; ++i) {  // up to 60 s of a long move at full duty
    rig.run(350.0, kTickS);
    tripped = rig.has_fault("motor_trip");
  }
  ASSERT_TRUE(tripped) << rig.faults();
  // 60 °C settling towards 100 °C with τ = 30 s: 75 °C after 14.1 s at full duty from the
  // start, and a little later after the soft start (ramp_s = 1 s) and the first readings.
  EXPECT_GT(rig.t, 14.1);
  EXPECT_LT(rig.t, 16.0);
  EXPECT_TRUE(rig.has_fault("az: motor_trip: motor temperature 75.")) << rig.faults();
  EXPECT_LT(rig.az_deg(), 140.0);
  EXPECT_EQ(rig.truth->duty(0), 0.0);
  const double stopped_at = rig.az_deg();
  rig.run(350.0, 2.0);
  rig.backend->clear_faults();
  EXPECT_TRUE(rig.has_fault("is not yet below 70 °C")) << rig.faults();
  rig.run(350.0, 20.0);
  EXPECT_NEAR(rig.az_deg(), stopped_at, 0.6) << "latched: no motion while it cools";
  rig.backend->clear_faults();
  EXPECT_TRUE(rig.backend->faults().empty()) << rig.faults();
  rig.run(350.0, 5.0);
  EXPECT_GT(rig.az_deg(), stopped_at + 1.0);
}

TEST(SimMotor, SimulateFliesTheSameBrakeAndWinding) {
  // `azeltrack simulate` builds its station from the same [sim.*] tables (sim_config_from):
  // the slew waits the brake's release time and the warm motor trips on the long move.
  const control::AzEl to{300.0, 10.0};
  const DaemonConfig plain = config_of("");
  const DaemonConfig braked = config_of(kSlowBrake);
  const sim::SimResult a = sim::simulate_slew(plain.simulated(), to, 600.0);
  const sim::SimResult b = sim::simulate_slew(braked.simulated(), to, 600.0);
  ASSERT_TRUE(a.slew_time_s && b.slew_time_s);
  EXPECT_NEAR(*b.slew_time_s - *a.slew_time_s, 1.5, 0.2);
  EXPECT_TRUE(b.faults.empty()) << b.faults.front();
  EXPECT_EQ(b.brake_pulled_against_s[0], 0.0);
  // Released 0.5 s after its line went on, the 1.2 s brake is pulled against for about 0.7 s.
  const sim::SimResult soon = sim::simulate_slew(
      config_of("brake = true\nbrake_lift_s = 1.2\nbrake_release_s = 0.5\n").simulated(), to,
      600.0);
  EXPECT_NEAR(soon.brake_pulled_against_s[0], 0.7, 0.06);
  const sim::SimResult hot = sim::simulate_slew(config_of(kWarmMotor).simulated(), to, 600.0);
  ASSERT_FALSE(hot.faults.empty());
  EXPECT_NE(hot.faults.front().find("motor temperature"), std::string::npos) << hot.faults.front();
}

}  // namespace
}  // namespace azt::app
