// A station whose elevation is a pulse-counted actuator dish (pulse_dish_fixture.hpp) and whose
// azimuth has an ordinary sensor: PortedStation takes the elevation's edges from its
// ports::PulseInput, homes it at start, gives no sky position until it is homed while the azimuth
// keeps its readings, then drives the elevation to its target; a dropped pulse shows in faults().
// A pol axis counted by its own PulseInput homes, holds its feed angle until homed, then follows
// it by the count, read alone as its sensor would be.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "azt/control/ported_station.hpp"
#include "azt/sim/actuator_dish_plant.hpp"
#include "fake_station_ports.hpp"
#include "pulse_dish_fixture.hpp"

namespace azt::control {
namespace {

using pulse_dish::dish;
using pulse_dish::kTickS;
using pulse_dish::PlantPulses;
using pulse_dish::pulse_config;

/// The plant's drive: the duty the station applies, held for the next step.
class PlantDrive final : public ports::AxisDrive {
 public:
  explicit PlantDrive(double& duty) : duty_(duty) {}
  Result<bool> apply(double /*now_s*/, double duty, std::optional<double> /*setpoint*/) override {
    duty_ = duty;
    return true;
  }
  void off(double /*now_s*/) override { duty_ = 0.0; }
  [[nodiscard]] std::string describe() const override { return "plant drive"; }

 private:
  double& duty_;
};

struct PulsedStation {
  sim::ActuatorDishPlant plant = sim::ActuatorDishPlant::make(dish()).value();
  PlantPulses* input = nullptr;
  std::shared_ptr<FakeAxis> az = std::make_shared<FakeAxis>();
  double el_duty = 0.0;
  std::unique_ptr<PortedStation> station;

  PulsedStation() {
    StationControlConfig c;
    c.tick_s = kTickS;
    c.el_control.window_deg = 0.2;
    c.el_control.lsb_deg = PulseAxis::make(pulse_config()).value().scale().max_deg_per_count();
    c.el_control.max_rate_deg_s = 2.5;
    c.el_control.min_duty = 0.1;
    c.el_control.time_constant_s = 0.15;
    c.el_supervisor.max_rate_deg_s = 3.0;
    c.el_supervisor.stale_s = 0.5;
    c.az_supervisor.stale_s = 0.5;
    c.el_drive.pulses = pulse_config();
    ports::StationPorts p;
    p.drives[0] = std::make_unique<FakeDrive>(az);
    p.sensors[0] = std::make_unique<FakeSensor>(az);
    p.drives[1] = std::make_unique<PlantDrive>(el_duty);
    auto pulses = std::make_unique<PlantPulses>(plant);
    input = pulses.get();
    p.pulse_inputs[1] = std::move(pulses);
    station =
        std::make_unique<PortedStation>(c, AzEl{0.0, 20.0}, PositionCorrections{}, std::move(p));
  }

  void run(double el_deg, double seconds) {
    Demand d;
    d.position = AzEl{0.0, el_deg};
    const double end_s = plant.now_s() + seconds;
    while (plant.now_s() < end_s) {
      station->tick(plant.now_s(), d, AzEl{});
      input->queue(plant.step(el_duty, kTickS));
    }
  }
  [[nodiscard]] bool faults_contain(std::string_view text) const {
    const auto f = station->faults();
    return std::any_of(f.begin(), f.end(),
                       [&](const std::string& s) { return s.find(text) != std::string::npos; });
  }
};

TEST(PortedStationPulses, HomesAtStartThenDrivesTheCountedElevation) {
  PulsedStation s;
  s.run(40.0, 1.0);
  EXPECT_EQ(s.station->station().el().homing, HomingState::Seeking);
  EXPECT_LT(s.el_duty, 0.0);  // homing's seek, not the 40° target
  EXPECT_FALSE(s.station->station().sky_position(s.plant.now_s()).has_value());
  EXPECT_TRUE(s.station->faults().empty());
  s.run(40.0, 60.0);
  ASSERT_EQ(s.station->station().el().homing, HomingState::Homed) << s.station->station().el().held;
  s.run(40.0, 30.0);
  const auto sky = s.station->station().sky_position(s.plant.now_s());
  ASSERT_TRUE(sky.has_value());
  EXPECT_NEAR(s.plant.angle_deg(), 40.0, 0.2 + s.station->station().config().el_control.lsb_deg);
  EXPECT_NEAR(sky->el_deg, s.plant.angle_deg(), 0.31);  // within one count at 40°
  EXPECT_EQ(s.station->home(s.plant.now_s(), 0), "this axis has no pulse sensor to home");
}

TEST(PortedStationPulses, ADroppedPulseIsAFaultAndTheOperatorsHomeClearsIt) {
  PulsedStation s;
  s.run(40.0, 60.0);
  ASSERT_EQ(s.station->station().el().homing, HomingState::Homed);
  s.plant.drop_pulse_after(s.plant.now_s() + 2.0);
  s.run(40.0, 30.0);
  s.run(s.plant.geometry().angle_deg(521.0).value(), 80.0);  // down past the home switch
  EXPECT_TRUE(s.faults_contain("el: position_lost: position lost: 1 count lost"));
  EXPECT_EQ(s.station->home(s.plant.now_s(), 1), std::nullopt);
  s.run(40.0, 60.0);
  EXPECT_TRUE(s.station->faults().empty());
  EXPECT_EQ(s.station->station().el().homing, HomingState::Homed);
}

/// A feed rotator at 5°/s at full duty: its reed closes every half degree, its home switch is
/// closed below −90°; each step's edges are stamped at the step's end.
class FeedPulses final : public ports::PulseInput {
 public:
  static constexpr double kCountsPerDeg = 2.0;
  static constexpr double kHomeDeg = -90.0;
  void step(double duty, double dt_s, double now_s) {
    const double before = deg;
    deg += 5.0 * duty * dt_s;
    const double crossed =
        std::abs(std::floor(deg * kCountsPerDeg) - std::floor(before * kCountsPerDeg));
    for (int i = 0; i < static_cast<int>(crossed); ++i) {
      edges_.push_back({ports::PulseLine::Pulse, true, now_s});
    }
    if ((before < kHomeDeg) != (deg < kHomeDeg)) {
      edges_.push_back({ports::PulseLine::Home, deg < kHomeDeg, now_s});
    }
  }
  std::vector<ports::PulseEdge> take_edges() override { return std::exchange(edges_, {}); }
  [[nodiscard]] bool home_closed() const override { return deg < kHomeDeg; }
  [[nodiscard]] std::string describe() const override { return "feed reed"; }
  double deg = 30.0;

 private:
  std::vector<ports::PulseEdge> edges_;
};

struct CountedPol {
  std::shared_ptr<FakeAxis> az = std::make_shared<FakeAxis>();
  std::shared_ptr<FakeAxis> el = std::make_shared<FakeAxis>();
  std::shared_ptr<FakeAxis> pol = std::make_shared<FakeAxis>();
  FeedPulses* feed = nullptr;
  std::unique_ptr<PortedStation> station;
  double t = 0.0;

  explicit CountedPol(bool with_input = true) {
    StationControlConfig c;
    c.tick_s = kTickS;
    PolAxisConfig p;
    p.control.window_deg = 0.5;
    p.control.max_rate_deg_s = 5.0;
    p.supervisor.max_rate_deg_s = 6.0;
    p.supervisor.stale_s = 0.5;
    p.travel = PolTravel{-95.0, 95.0};
    PulseAxisConfig pulses;
    pulses.homing.seek_duty = -1.0;
    pulses.homing.stop_s = 0.2;
    pulses.homing.no_pulse_s = 2.0;
    pulses.scale = {PulseUnit::Degrees, FeedPulses::kCountsPerDeg, FeedPulses::kHomeDeg};
    p.drive.pulses = pulses;
    c.pol = p;
    ports::StationPorts ports;
    ports.drives[0] = std::make_unique<FakeDrive>(az);
    ports.sensors[0] = std::make_unique<FakeSensor>(az);
    ports.drives[1] = std::make_unique<FakeDrive>(el);
    ports.sensors[1] = std::make_unique<FakeSensor>(el);
    ports.pol_drive = std::make_unique<FakeDrive>(pol);
    if (with_input) {
      auto input = std::make_unique<FeedPulses>();
      feed = input.get();
      ports.pol_pulse_input = std::move(input);
    }
    station = std::make_unique<PortedStation>(c, AzEl{}, PositionCorrections{}, std::move(ports));
  }
  void run(std::optional<double> feed_deg, double seconds) {
    const int ticks = static_cast<int>(std::lround(seconds / kTickS));
    for (int i = 0; i < ticks; ++i) {
      station->tick(t, Demand{}, AzEl{}, PolDemand{feed_deg, 0.0});
      t += kTickS;
      feed->step(pol->duty, kTickS, t);
    }
  }
  [[nodiscard]] AxisStatus status() const { return station->pol()->axis().status(); }
};

TEST(PortedStationPulses, ACountedPolAxisHomesHoldsItsFeedThenFollowsIt) {
  CountedPol s;
  ASSERT_NE(s.station->pol(), nullptr);
  s.run(40.0, 1.0);
  EXPECT_EQ(s.status().homing, HomingState::Seeking);
  EXPECT_LT(s.pol->duty, 0.0);  // the seek towards the switch, not the 40° feed
  EXPECT_FALSE(s.station->pol()->target_mount_deg().has_value()) << "held: sent nowhere";
  EXPECT_NE(s.status().held.find("not homed"), std::string::npos) << s.status().held;
  EXPECT_TRUE(s.station->faults().empty()) << s.station->faults().front();
  s.run(40.0, 60.0);
  ASSERT_EQ(s.status().homing, HomingState::Homed) << s.status().held;
  s.run(40.0, 60.0);
  EXPECT_NEAR(s.feed->deg, 40.0, 0.5 + 1.0 / FeedPulses::kCountsPerDeg);
  EXPECT_NEAR(s.status().mount_deg, s.feed->deg, 1.0 / FeedPulses::kCountsPerDeg + 0.01);
  EXPECT_TRUE(s.status().held.empty()) << s.status().held;
  EXPECT_EQ(s.station->pol()->target_mount_deg(), 40.0);
  EXPECT_TRUE(s.station->faults().empty()) << s.station->faults().front();
  // The operator's command homes it again; a STOP ends that homing, unreferenced.
  EXPECT_EQ(s.station->home(s.t, 2), std::nullopt);
  s.run(40.0, 0.5);
  EXPECT_EQ(s.status().homing, HomingState::Seeking);
  s.station->stop_homing(s.t, "stopped by test");
  s.run(40.0, 0.5);
  EXPECT_EQ(s.status().homing, HomingState::NotHomed);
  EXPECT_NE(s.status().held.find("stopped by test"), std::string::npos) << s.status().held;
  EXPECT_EQ(s.pol->duty, 0.0);
  EXPECT_EQ(s.station->home(s.t, 1), "this axis has no pulse sensor to home");
  EXPECT_EQ(s.station->home(s.t, 3), "this axis has no pulse sensor to home");
}

TEST(PortedStationPulses, ACountedPolAxisWithoutItsPulseInputIsNone) {
  CountedPol s(false);
  EXPECT_EQ(s.station->pol(), nullptr);
  EXPECT_EQ(s.station->home(0.0, 2), "this axis has no pulse sensor to home");
}

}  // namespace
}  // namespace azt::control
