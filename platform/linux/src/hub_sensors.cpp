#include "azt/linux/hub_sensors.hpp"

#include <chrono>
#include <optional>
#include <string>
#include <utility>

#include "azt/proto/hub_axis.hpp"

namespace azt::linux_os {
namespace {

constexpr std::array<const char*, 2> kAxisNames{"az", "el"};

/// What the two sensors share: the link, each axis's latest frame and its bits fault.
class HubReadings {
 public:
  HubReadings(std::array<std::uint8_t, 2> mount_bits, std::array<bool, 2> used, std::string device)
      : mount_bits_(mount_bits), used_(used), device_(std::move(device)) {}

  void attach(std::unique_ptr<HubSerialLink> link) { link_ = std::move(link); }

  void on_frame(const proto::HubFrame& f) {
    // Stamped with when the frame arrived, not with the next tick: staleness counts from it.
    const double at = clock_s();
    for (std::size_t i = 0; i < 2; ++i) {
      if (!used_.at(i)) continue;
      const proto::HubAxis axis = proto::hub_axis(f.reading, i);
      if (axis.error != proto::HubAxisError::None) {
        // The hub says it has no position for this axis: a fault naming it until a good frame.
        fresh_.at(i).reset();
        axis_error_.at(i) = proto::hub_axis_fault(i, axis.error);
        continue;
      }
      if (!bits_agree(i, axis.bits)) continue;
      axis_error_.at(i).reset();
      fresh_.at(i) = ports::AxisSample{proto::hub_raw_to_deg(axis.raw, axis.bits), at};
    }
  }
  void on_event(const std::string& event) { event_ = event; }

  Result<ports::SensorReading> read(std::size_t axis, double now_s) {
    last_tick_s_ = now_s;
    last_tick_wall_ = std::chrono::steady_clock::now();
    if (link_ && !link_->connected()) return fail("hub: " + event_);
    if (axis_error_.at(axis)) return fail(*axis_error_.at(axis));
    return std::exchange(fresh_.at(axis), std::nullopt);
  }

  [[nodiscard]] const std::optional<std::string>& bits_fault(std::size_t axis) const {
    return bits_fault_.at(axis);
  }
  void clear_bits_fault(std::size_t axis) { bits_fault_.at(axis).reset(); }
  [[nodiscard]] std::string describe() const { return "EncoderHub on " + device_; }

 private:
  /// Whether a frame's resolution for axis `i` is the mount's. A hub re-jumpered, or the wrong
  /// [mount] encoder_bits, would put every angle and the 1-LSB window off by a power of two.
  bool bits_agree(std::size_t i, std::uint8_t frame_bits) {
    if (frame_bits == mount_bits_.at(i)) return true;
    const std::string axis = kAxisNames.at(i);
    bits_fault_.at(i) = axis + ": the EncoderHub reports " + std::to_string(frame_bits) +
                        "-bit frames but [mount." + axis +
                        "] encoder_bits = " + std::to_string(mount_bits_.at(i)) +
                        ": set the jumpers or the configuration to agree";
    return false;
  }

  /// The frames arrive between ticks: their time on the tick's clock is the last tick's plus
  /// the wall time since.
  [[nodiscard]] double clock_s() const {
    return last_tick_s_ +
           std::chrono::duration<double>(std::chrono::steady_clock::now() - last_tick_wall_)
               .count();
  }

  std::array<std::uint8_t, 2> mount_bits_;
  std::array<bool, 2> used_;
  std::string device_;
  std::unique_ptr<HubSerialLink> link_;
  std::array<std::optional<ports::AxisSample>, 2> fresh_;
  std::array<std::optional<std::string>, 2> bits_fault_;
  std::array<std::optional<std::string>, 2> axis_error_;  ///< the hub's own reason, until good
  std::string event_;
  double last_tick_s_ = 0.0;
  std::chrono::steady_clock::time_point last_tick_wall_ = std::chrono::steady_clock::now();
};

class HubAxisSensor final : public ports::AxisSensor {
 public:
  HubAxisSensor(std::shared_ptr<HubReadings> hub, std::size_t axis)
      : hub_(std::move(hub)), axis_(axis) {}
  Result<ports::SensorReading> read(double now_s) override { return hub_->read(axis_, now_s); }
  [[nodiscard]] std::optional<std::string> latched_fault() const override {
    return hub_->bits_fault(axis_);
  }
  void clear_fault() override { hub_->clear_bits_fault(axis_); }  // a bad frame latches again
  [[nodiscard]] std::string describe() const override { return hub_->describe(); }

 private:
  std::shared_ptr<HubReadings> hub_;
  std::size_t axis_;
};

}  // namespace

Result<std::array<std::unique_ptr<ports::AxisSensor>, 2>> open_hub_sensors(
    boost::asio::io_context& io, const HubSensorsConfig& config) {
  auto hub = std::make_shared<HubReadings>(config.mount_bits, config.used, config.link.device);
  // The link lives inside `hub`, so its callbacks never outlive what they write to.
  auto link = HubSerialLink::open(
      io, config.link, [raw = hub.get()](const proto::HubFrame& f) { raw->on_frame(f); },
      [raw = hub.get()](const std::string& event) { raw->on_event(event); });
  if (!link) return link.error();
  hub->attach(std::move(link).value());
  std::array<std::unique_ptr<ports::AxisSensor>, 2> sensors;
  for (std::size_t i = 0; i < 2; ++i) {
    if (config.used.at(i)) sensors.at(i) = std::make_unique<HubAxisSensor>(hub, i);
  }
  return sensors;
}

}  // namespace azt::linux_os
