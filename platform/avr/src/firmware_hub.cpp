#include "azt/avr/firmware_hub.hpp"

#include <utility>

namespace azt::avr {
namespace {

HubAxisSetup encoder_for(const sim::AxisParams& axis) {
  if (axis.encoder_bits == 12) return {EncoderModelKind::As5045, 12};
  return {EncoderModelKind::SsiBinary, axis.encoder_bits};
}

}  // namespace

Result<std::unique_ptr<FirmwareHub>> FirmwareHub::load(const sim::PlantSetup& plant,
                                                       const std::string& elf_path) {
  AvrHubSetup setup;
  setup.elf_path = elf_path;
  setup.az = encoder_for(plant.az);
  setup.el = encoder_for(plant.el);
  auto avr = AvrHub::load(setup);
  if (!avr) return avr.error();
  return std::unique_ptr<FirmwareHub>(new FirmwareHub(std::move(avr).value()));
}

FirmwareHub::FirmwareHub(std::unique_ptr<AvrHub> avr) : avr_(std::move(avr)) {
  avr_->on_byte = [this](std::uint8_t byte, double at_us) {
    proto::HubFrame f{};
    if (decoder_.push(byte, f) == proto::HubFrameStatus::Ok) {
      frame_ = f.reading;
      frame_at_us_ = at_us;
    }
  };
}

void FirmwareHub::run(const sim::SimAntenna& plants, double step_s) {
  avr_->set_counts(plants.az().encoder_raw(), plants.el().encoder_raw());
  avr_->run_for(step_s);
}

std::optional<sim::HubArrival> FirmwareHub::take_frame(const sim::SimAntenna& /*plants*/,
                                                       double now_s) {
  if (!frame_ || frame_at_us_ == taken_at_us_) return std::nullopt;
  taken_at_us_ = frame_at_us_;
  return sim::HubArrival{*frame_, now_s - (avr_->now_us() - frame_at_us_) / 1e6};
}

}  // namespace azt::avr
