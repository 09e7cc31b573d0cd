#include "azt/linux/pot_sensors.hpp"

#include <algorithm>
#include <utility>

namespace azt::linux_os {

Ads1115Chip::Ads1115Chip(std::unique_ptr<I2cBus> bus, std::uint8_t address)
    : bus_(std::move(bus)), adc_(*bus_, address, proto::Ads1115Range::Fs4V096) {}

bool Ads1115Chip::has_channel(unsigned channel) const {
  return std::find(channels_.begin(), channels_.end(), channel) != channels_.end() ||
         std::find(slow_.begin(), slow_.end(), channel) != slow_.end();
}

Ads1115Chip::Step Ads1115Chip::step(unsigned channel, double now_s) {
  if (!in_flight_) return begin(channel, now_s);
  // Another axis's conversion, or one started by this tick's other axis: not this poll's.
  if (*in_flight_ != channel || now_s <= started_s_) return std::optional<std::int16_t>{};
  auto done = adc_.poll();
  if (!done) return lose(done.error());
  if (!done.value()) {
    if (++polls_ < kMaxPolls) return std::optional<std::int16_t>{};
    return lose(
        adc_.error(channel, "conversion not done after " + std::to_string(kMaxPolls) + " ticks"));
  }
  auto code = adc_.fetch();
  if (!code) return lose(code.error());
  // A start that fails spoils only the next reading: the next step starts again and reports
  // the failure if the bus still fails.
  (void)begin(next_after(channel), now_s);
  return std::optional<std::int16_t>{code.value()};
}

Ads1115Chip::Step Ads1115Chip::begin(unsigned channel, double now_s) {
  if (auto r = adc_.start(channel); !r) return lose(r.error());
  in_flight_ = channel;
  started_s_ = now_s;
  polls_ = 0;
  // A slow channel's turn, whoever started it: the next slow turn is the one after it.
  if (const auto it = std::find(slow_.begin(), slow_.end(), channel); it != slow_.end()) {
    next_slow_ = static_cast<std::size_t>(it + 1 - slow_.begin()) % slow_.size();
  }
  return std::optional<std::int16_t>{};
}

Ads1115Chip::Step Ads1115Chip::lose(Error why) {
  in_flight_.reset();
  return why;
}

unsigned Ads1115Chip::next_after(unsigned channel) const {
  if (channels_.empty()) return next_slow();
  const auto it = std::find(channels_.begin(), channels_.end(), channel);
  if (it == channels_.end()) return channels_.front();  // after a slow channel: the pots again
  if (it + 1 != channels_.end()) return *(it + 1);
  return slow_.empty() ? channels_.front() : next_slow();  // a round of the pots is done
}

unsigned Ads1115Chip::next_slow() const { return slow_.at(next_slow_); }

namespace {

class Mcp3008PotSensor final : public ports::AxisSensor {
 public:
  Mcp3008PotSensor(std::unique_ptr<SpiBus> bus, unsigned channel,
                   const control::PotInputConfig& pot, std::string what)
      : bus_(std::move(bus)), adc_(*bus_), channel_(channel), pot_(pot), what_(std::move(what)) {}
  Result<ports::SensorReading> read(double now_s) override {
    auto code = adc_.read(channel_);
    if (!code) {
      pot_.reset();
      return code.error();
    }
    return control::pot_sensor_reading(pot_.push(code.value()), now_s, what_);
  }
  [[nodiscard]] std::string describe() const override { return what_; }

 private:
  std::unique_ptr<SpiBus> bus_;
  Mcp3008Reader adc_;
  unsigned channel_;
  control::PotInput pot_;
  std::string what_;
};

class Ads1115PotSensor final : public ports::AxisSensor {
 public:
  Ads1115PotSensor(std::shared_ptr<Ads1115Chip> chip, unsigned channel,
                   const control::PotInputConfig& pot, std::string what)
      : chip_(std::move(chip)), channel_(channel), pot_(pot), what_(std::move(what)) {}
  Result<ports::SensorReading> read(double now_s) override {
    auto code = chip_->step(channel_, now_s);
    if (!code) {
      pot_.reset();
      return code.error();
    }
    if (!code.value()) return ports::SensorReading{};
    return control::pot_sensor_reading(pot_.push(*code.value()), now_s, what_);
  }
  [[nodiscard]] std::string describe() const override { return what_; }

 private:
  std::shared_ptr<Ads1115Chip> chip_;
  unsigned channel_;
  control::PotInput pot_;
  std::string what_;
};

}  // namespace

std::unique_ptr<ports::AxisSensor> make_mcp3008_pot_sensor(std::unique_ptr<SpiBus> bus,
                                                           unsigned channel,
                                                           const control::PotInputConfig& pot,
                                                           std::string what) {
  return std::make_unique<Mcp3008PotSensor>(std::move(bus), channel, pot, std::move(what));
}

std::unique_ptr<ports::AxisSensor> make_ads1115_pot_sensor(std::shared_ptr<Ads1115Chip> chip,
                                                           unsigned channel,
                                                           const control::PotInputConfig& pot,
                                                           std::string what) {
  return std::make_unique<Ads1115PotSensor>(std::move(chip), channel, pot, std::move(what));
}

}  // namespace azt::linux_os
