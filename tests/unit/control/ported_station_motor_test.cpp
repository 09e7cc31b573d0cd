// PortedStation's brake lines and motor sensors: the brake's output leaves through its port
// beside the drive, the readings arrive through theirs each tick.
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>

#include "azt/control/ported_station.hpp"

namespace azt::control {
namespace {

constexpr double kTickS = 0.05;

struct FakeMotor {
  double duty = 0.0;
  double deg = 0.0;
  bool release = false;
  int brake_writes = 0;
  int brake_offs = 0;
  ports::MotorSample sample;
  std::optional<std::string> read_error;
  std::optional<std::string> brake_error;
};

class Drive final : public ports::AxisDrive {
 public:
  explicit Drive(std::shared_ptr<FakeMotor> m) : m_(std::move(m)) {}
  Result<bool> apply(double /*now_s*/, double duty, std::optional<double> /*sp*/) override {
    m_->duty = duty;
    return true;
  }
  void off(double /*now_s*/) override { m_->duty = 0.0; }
  [[nodiscard]] std::string describe() const override { return "drive"; }

 private:
  std::shared_ptr<FakeMotor> m_;
};

class Sensor final : public ports::AxisSensor {
 public:
  explicit Sensor(std::shared_ptr<FakeMotor> m) : m_(std::move(m)) {}
  Result<ports::SensorReading> read(double now_s) override {
    return ports::SensorReading{ports::AxisSample{m_->deg, now_s}};
  }
  [[nodiscard]] std::string describe() const override { return "sensor"; }

 private:
  std::shared_ptr<FakeMotor> m_;
};

class Line final : public ports::BrakeLine {
 public:
  explicit Line(std::shared_ptr<FakeMotor> m) : m_(std::move(m)) {}
  Result<bool> apply(double /*now_s*/, bool release) override {
    if (m_->brake_error) return fail(*m_->brake_error);
    m_->release = release;
    ++m_->brake_writes;
    return true;
  }
  void off(double /*now_s*/) override {
    m_->release = false;
    ++m_->brake_offs;
  }
  [[nodiscard]] std::string describe() const override { return "brake"; }

 private:
  std::shared_ptr<FakeMotor> m_;
};

class Readings final : public ports::MotorSensor {
 public:
  explicit Readings(std::shared_ptr<FakeMotor> m) : m_(std::move(m)) {}
  Result<ports::MotorSample> read(double /*now_s*/) override {
    if (m_->read_error) return fail(*m_->read_error);
    return m_->sample;
  }
  [[nodiscard]] std::string describe() const override { return "motor sensor"; }

 private:
  std::shared_ptr<FakeMotor> m_;
};

struct Station {
  std::array<std::shared_ptr<FakeMotor>, 2> m{std::make_shared<FakeMotor>(),
                                              std::make_shared<FakeMotor>()};
  std::unique_ptr<PortedStation> station;
  double t = 0.0;

  Station() {
    StationControlConfig c;
    c.tick_s = kTickS;
    c.az_drive.brake = BrakeConfig{0.6, 0.3, 1.0};
    MotorTripsConfig trips;
    trips.axis = "az";
    trips.temperature_limit_c = 75.0;
    c.az_drive.trips = trips;
    ports::StationPorts p;
    for (std::size_t i = 0; i < 2; ++i) {
      p.drives.at(i) = std::make_unique<Drive>(m.at(i));
      p.sensors.at(i) = std::make_unique<Sensor>(m.at(i));
    }
    p.brakes[0] = std::make_unique<Line>(m[0]);
    p.motor_sensors[0] = std::make_unique<Readings>(m[0]);
    p.brakes[1] = std::make_unique<Line>(m[1]);  // el has a line but no brake: never written
    station =
        std::make_unique<PortedStation>(c, AzEl{0.0, 10.0}, PositionCorrections{}, std::move(p));
    m[1]->deg = 10.0;
  }
  void run(const Demand& demand, double seconds) {
    for (const double end = t + seconds; t < end - 1e-9; t += kTickS) {
      station->tick(t, demand, AzEl{});
      // The shaft turns only with its brake's line on.
      if (m[0]->release) m[0]->deg += m[0]->duty * 1.5 * kTickS;
      ASSERT_TRUE(m[0]->duty == 0.0 || m[0]->release) << "pulled against the brake at " << t;
    }
  }
  [[nodiscard]] bool faults_contain(std::string_view text) const {
    const auto f = station->faults();
    return std::any_of(f.begin(), f.end(),
                       [&](const std::string& s) { return s.find(text) != std::string::npos; });
  }
};

Demand go_to(double az_deg, double el_deg) {
  Demand d;
  d.position = AzEl{az_deg, el_deg};
  return d;
}

TEST(PortedStationBrake, TheBrakeLineIsReleasedBeforeTheMotorPullsAndAppliedOnAStop) {
  Station s;
  s.run(go_to(20.0, 10.0), 0.5);
  EXPECT_TRUE(s.m[0]->release);
  EXPECT_EQ(s.m[0]->duty, 0.0);  // still releasing
  s.run(go_to(20.0, 10.0), 2.0);
  EXPECT_GT(s.m[0]->duty, 0.0);
  EXPECT_GT(s.m[0]->deg, 0.5);
  EXPECT_EQ(s.m[1]->brake_writes, 0);
  s.station->stop_with(s.t, "operator stop");
  EXPECT_FALSE(s.m[0]->release);
  EXPECT_EQ(s.m[0]->brake_offs, 1);
}

TEST(PortedStationBrake, AnOverTemperatureReadingTripsTheAxisAndTheOperatorIsToldWhyItStays) {
  Station s;
  s.m[0]->sample.temperature_c = 50.0;
  s.run(go_to(40.0, 10.0), 2.0);
  ASSERT_GT(s.m[0]->duty, 0.0);
  s.m[0]->sample.temperature_c = 81.0;
  s.run(go_to(40.0, 10.0), kTickS);
  EXPECT_EQ(s.m[0]->duty, 0.0);
  EXPECT_FALSE(s.m[0]->release);
  EXPECT_TRUE(s.faults_contain("az: motor_trip: motor temperature 81.0 °C above 75 °C"));
  s.m[0]->sample.temperature_c = 73.0;
  s.run(go_to(40.0, 10.0), kTickS);
  s.station->clear_faults();
  EXPECT_TRUE(s.faults_contain("az: motor temperature 73.0 °C is not yet below 70 °C"));
  s.run(go_to(40.0, 10.0), 1.0);
  EXPECT_EQ(s.m[0]->duty, 0.0);
  s.m[0]->sample.temperature_c = 60.0;
  s.run(go_to(40.0, 10.0), kTickS);
  s.station->clear_faults();
  EXPECT_TRUE(s.station->faults().empty());
  s.run(go_to(40.0, 10.0), 1.5);
  EXPECT_GT(s.m[0]->duty, 0.0);
}

TEST(PortedStationBrake, AMotorSensorThatCannotBeReadTripsItsAxisAndABrakeWriteErrorStops) {
  Station s;
  s.m[0]->read_error = "adc: no answer";
  s.run(go_to(20.0, 10.0), 0.2);
  EXPECT_TRUE(s.faults_contain("az motor sensor: adc: no answer"));
  EXPECT_TRUE(s.faults_contain("az: motor_trip: motor temperature reading is not a number"));
  Station w;
  w.m[0]->brake_error = "gpio: gone";
  w.run(go_to(20.0, 10.0), 0.2);
  EXPECT_TRUE(w.faults_contain("az brake: gpio: gone"));
  EXPECT_TRUE(w.station->station().faulted());
}

TEST(PortedStationBrake, ThePolAxisHasItsOwnBrakeLineAndMotorSensor) {
  auto pol = std::make_shared<FakeMotor>();
  std::array<std::shared_ptr<FakeMotor>, 2> axes{std::make_shared<FakeMotor>(),
                                                 std::make_shared<FakeMotor>()};
  StationControlConfig c;
  c.tick_s = kTickS;
  PolAxisConfig p;
  p.control.lsb_deg = 360.0 / 4096;
  p.travel = PolTravel{-95.0, 95.0};
  p.drive.brake = BrakeConfig{0.5, 0.3, 1.0};
  MotorTripsConfig trips;
  trips.axis = "pol";
  trips.temperature_limit_c = 60.0;
  p.drive.trips = trips;
  c.pol = p;
  ports::StationPorts ports;
  for (std::size_t i = 0; i < 2; ++i) {
    ports.drives.at(i) = std::make_unique<Drive>(axes.at(i));
    ports.sensors.at(i) = std::make_unique<Sensor>(axes.at(i));
  }
  ports.pol_drive = std::make_unique<Drive>(pol);
  ports.pol_sensor = std::make_unique<Sensor>(pol);
  ports.pol_brake = std::make_unique<Line>(pol);
  ports.pol_motor_sensor = std::make_unique<Readings>(pol);
  PortedStation station(c, AzEl{}, PositionCorrections{}, std::move(ports));
  double t = 0.0;
  double first_duty_s = -1.0;
  for (int i = 0; i < 40; ++i, t += kTickS) {
    station.tick(t, Demand{}, AzEl{}, PolDemand{30.0, 0.0});
    if (pol->duty != 0.0 && first_duty_s < 0.0) first_duty_s = t;
    ASSERT_TRUE(pol->duty == 0.0 || pol->release) << t;
  }
  EXPECT_GE(first_duty_s, 0.5 - 1e-9);
  pol->sample.temperature_c = 65.0;
  station.tick(t, Demand{}, AzEl{}, PolDemand{30.0, 0.0});
  EXPECT_EQ(pol->duty, 0.0);
  EXPECT_FALSE(pol->release);
  const auto f = station.faults();
  EXPECT_TRUE(std::find(f.begin(), f.end(),
                        "pol: motor_trip: motor temperature 65.0 °C above 60 °C") != f.end())
      << (f.empty() ? "" : f.front());
}

}  // namespace
}  // namespace azt::control
