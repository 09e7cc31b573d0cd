#include "azt/sim/simulated_station.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>

#include "azt/control/pot_calibration.hpp"
#include "azt/proto/hub_axis.hpp"
#include "azt/sim/model_hub.hpp"

namespace azt::sim {
namespace {

class SimDrive final : public ports::AxisDrive {
 public:
  SimDrive(std::shared_ptr<PlantRig> rig, std::size_t axis) : rig_(std::move(rig)), axis_(axis) {}
  Result<bool> apply(double /*now_s*/, double duty, std::optional<double> /*setpoint*/) override {
    rig_->set_duty(axis_, duty);
    return true;
  }
  void off(double /*now_s*/) override { rig_->set_duty(axis_, 0.0); }
  [[nodiscard]] std::string describe() const override { return rig_->hub().describe(); }

 private:
  std::shared_ptr<PlantRig> rig_;
  std::size_t axis_;
};

class SimSensor final : public ports::AxisSensor {
 public:
  SimSensor(std::shared_ptr<PlantRig> rig, std::size_t axis) : rig_(std::move(rig)), axis_(axis) {}
  Result<ports::SensorReading> read(double now_s) override {
    const auto frame = rig_->frame_for(axis_, now_s);
    if (!frame) return ports::SensorReading{};  // between frames, or a frame lost on the link
    const proto::HubAxis axis = proto::hub_axis(frame->reading, axis_);
    if (axis.error != proto::HubAxisError::None)
      return fail(proto::hub_axis_fault(axis_, axis.error));
    return ports::SensorReading{
        ports::AxisSample{proto::hub_raw_to_deg(axis.raw, axis.bits), frame->at_s}};
  }
  [[nodiscard]] std::string describe() const override { return rig_->hub().describe(); }

 private:
  std::shared_ptr<PlantRig> rig_;
  std::size_t axis_;
};

/// The polarisation plant's motor.
class SimPolDrive final : public ports::AxisDrive {
 public:
  explicit SimPolDrive(std::shared_ptr<PlantRig> rig) : rig_(std::move(rig)) {}
  Result<bool> apply(double /*now_s*/, double duty, std::optional<double> /*setpoint*/) override {
    rig_->set_pol_duty(duty);
    return true;
  }
  void off(double /*now_s*/) override { rig_->set_pol_duty(0.0); }
  [[nodiscard]] std::string describe() const override { return "simulated polarisation motor"; }

 private:
  std::shared_ptr<PlantRig> rig_;
};

/// The polarisation plant's absolute encoder, read each tick (no hub link between).
class SimPolSensor final : public ports::AxisSensor {
 public:
  SimPolSensor(std::shared_ptr<PlantRig> rig, std::uint8_t bits)
      : rig_(std::move(rig)), bits_(bits) {}
  Result<ports::SensorReading> read(double now_s) override {
    const auto raw = rig_->pol_raw(now_s);
    if (!raw) return fail("the simulated station has no polarisation plant");
    return ports::SensorReading{ports::AxisSample{proto::hub_raw_to_deg(*raw, bits_), now_s}};
  }
  [[nodiscard]] std::string describe() const override {
    return "simulated polarisation encoder (" + std::to_string(bits_) + "-bit)";
  }

 private:
  std::shared_ptr<PlantRig> rig_;
  std::uint8_t bits_;
};

/// The brake plant's solenoid.
class SimBrakeLine final : public ports::BrakeLine {
 public:
  SimBrakeLine(std::shared_ptr<PlantRig> rig, std::size_t axis)
      : rig_(std::move(rig)), axis_(axis) {}
  Result<bool> apply(double /*now_s*/, bool release) override {
    rig_->set_brake(axis_, release);
    return true;
  }
  void off(double /*now_s*/) override { rig_->set_brake(axis_, false); }
  [[nodiscard]] std::string describe() const override { return "simulated brake"; }

 private:
  std::shared_ptr<PlantRig> rig_;
  std::size_t axis_;
};

/// A temperature sensor on the simulated motor's winding.
class SimMotorSensor final : public ports::MotorSensor {
 public:
  SimMotorSensor(std::shared_ptr<PlantRig> rig, std::size_t axis)
      : rig_(std::move(rig)), axis_(axis) {}
  Result<ports::MotorSample> read(double now_s) override {
    return ports::MotorSample{std::nullopt, rig_->motor_temperature_c(axis_, now_s), std::nullopt};
  }
  [[nodiscard]] std::string describe() const override { return "simulated motor temperature"; }

 private:
  std::shared_ptr<PlantRig> rig_;
  std::size_t axis_;
};

/// The elevation actuator's reed and home switch (PlantSetup::el_actuator).
class SimActuatorPulses final : public ports::PulseInput {
 public:
  explicit SimActuatorPulses(std::shared_ptr<PlantRig> rig) : rig_(std::move(rig)) {}
  /// The azimuth's sensor, read first each tick, has run the plants up to the tick.
  std::vector<ports::PulseEdge> take_edges() override { return rig_->take_el_edges(); }
  [[nodiscard]] bool home_closed() const override { return rig_->el_home_closed(); }
  [[nodiscard]] std::string describe() const override {
    return "simulated actuator reed and home switch";
  }

 private:
  std::shared_ptr<PlantRig> rig_;
};

/// The elevation actuator's feedback pot on an ADC (PlantSetup::el_actuator with a pot): the
/// length becomes the code the converter would return, through the calibration's inverse, and
/// the daemon's own PotInput turns the code back into the angle through the triangle. So the
/// station sees the ADC's quantisation, its averaging, and a length outside the stroke as the
/// real axis would.
class SimActuatorPot final : public ports::AxisSensor {
 public:
  SimActuatorPot(std::shared_ptr<PlantRig> rig, const control::PotInputConfig& pot)
      : rig_(std::move(rig)), pot_(pot) {}
  Result<ports::SensorReading> read(double now_s) override {
    const auto length_mm = rig_->el_length_mm(now_s);
    if (!length_mm) return fail("the simulated station has no elevation actuator");
    const control::PotInputConfig& c = pot_.config();
    // The calibration's "degrees" are millimetres on an actuator (PotInputConfig::actuator).
    const double code = std::round(c.calibration.to_counts(*length_mm));
    const auto counts =
        static_cast<std::int32_t>(std::clamp(code, 0.0, static_cast<double>(c.adc.max_counts())));
    return control::pot_sensor_reading(pot_.push(counts), now_s, describe());
  }
  [[nodiscard]] std::string describe() const override {
    return "simulated actuator pot (" + std::to_string(pot_.config().adc.bits) + "-bit ADC)";
  }

 private:
  std::shared_ptr<PlantRig> rig_;
  control::PotInput pot_;
};

}  // namespace

std::unique_ptr<SimulatedHub> make_model_hub(const PlantSetup& plant) {
  return std::make_unique<ModelHub>(plant.az.encoder_bits, plant.el.encoder_bits,
                                    plant.frame_version, plant.link, plant.seed);
}

SimulatedStation make_simulated_station(const PlantSetup& plant,
                                        std::unique_ptr<SimulatedHub> hub) {
  auto rig = std::make_shared<PlantRig>(plant, std::move(hub));
  SimulatedStation station;
  for (std::size_t i = 0; i < (plant.el_axis ? 2U : 1U); ++i) {
    station.ports.drives.at(i) = std::make_unique<SimDrive>(rig, i);
    if (i == 1 && plant.el_actuator) {
      // The actuator's own sensor, as on the real dish: its reed's count, or its pot.
      if (const control::PotInputConfig* pot = plant.el_actuator->pot()) {
        station.ports.sensors.at(i) = std::make_unique<SimActuatorPot>(rig, *pot);
      } else {
        station.ports.pulse_inputs.at(i) = std::make_unique<SimActuatorPulses>(rig);
      }
    } else {
      station.ports.sensors.at(i) = std::make_unique<SimSensor>(rig, i);
    }
    if (plant.brakes.at(i)) station.ports.brakes.at(i) = std::make_unique<SimBrakeLine>(rig, i);
    if (plant.thermal.at(i))
      station.ports.motor_sensors.at(i) = std::make_unique<SimMotorSensor>(rig, i);
  }
  if (plant.pol) {
    station.ports.pol_drive = std::make_unique<SimPolDrive>(rig);
    station.ports.pol_sensor = std::make_unique<SimPolSensor>(rig, plant.pol->encoder_bits);
  }
  station.rig = rig;
  return station;
}

}  // namespace azt::sim
