#include "hands/hand_pad.hpp"

#include <utility>

namespace azt::app {

HandPad::HandPad(const GamepadConfig& config, Opener open, StationCommands& commands,
                 std::function<double()> monotonic_s, std::function<void(const std::string&)> log)
    : config_(config),
      open_(std::move(open)),
      monotonic_s_(std::move(monotonic_s)),
      log_(std::move(log)),
      control_(hands::HandControlConfig{config.speed}),
      door_(commands, CommandSource{CommandSource::Kind::Hands, "game pad"}, config.park_slot) {
  layout_.dead_zone = config.dead_zone;
}

void HandPad::look_for_pad(double now_s) {
  if (pad_ && pad_->present()) return;
  if (pad_) {
    log_("game pad: " + pad_->name() + " went away; looking for it every 2 s");
    pad_.reset();
    last_error_.clear();
    next_look_s_ = now_s + kRetryS;
  }
  if (now_s < next_look_s_) return;
  next_look_s_ = now_s + kRetryS;
  auto opened = open_(config_.device);
  if (!opened) {
    if (opened.error().message != last_error_) log_("game pad: " + opened.error().message);
    last_error_ = opened.error().message;
    return;
  }
  pad_ = std::move(opened).value();
  last_error_.clear();
  log_("game pad: " + pad_->name() + " on " + config_.device);
}

hands::HandInputs HandPad::held() const {
  // No pad, or one gone: nothing held, so a move in progress is let go this tick.
  if (!pad_ || !pad_->present()) return {};
  hands::HandInputs in = hands::pad_inputs(layout_, pad_->state());
  in.az_deflection *= config_.speed;
  in.el_deflection *= config_.speed;
  return in;
}

void HandPad::tick() {
  look_for_pad(monotonic_s_());
  door_.apply(control_.update(held()));
}

std::unique_ptr<HandPad> make_hand_pad(boost::asio::io_context& io,
                                       const std::optional<GamepadConfig>& config,
                                       StationCommands& commands,
                                       std::function<double()> monotonic_s,
                                       std::function<void(const std::string&)> log) {
  if (!config) return nullptr;
  // The pad's loss is seen at the next tick through present(); nothing to do at once.
  auto open = [&io](const std::string& path) {
    return linux_os::open_evdev_pad(io, path, [](const std::string&) {});
  };
  return std::make_unique<HandPad>(*config, open, commands, std::move(monotonic_s), std::move(log));
}

std::string HandPad::connected_name() const {
  return pad_ && pad_->present() ? pad_->name() : std::string{};
}

nlohmann::json HandPad::to_json() const {
  const std::string name = connected_name();
  return {{"device", config_.device},
          {"connected", !name.empty()},
          {"name", name.empty() ? nlohmann::json(nullptr) : nlohmann::json(name)},
          {"error", last_error_.empty() || !name.empty() ? nlohmann::json(nullptr)
                                                         : nlohmann::json(last_error_)}};
}

}  // namespace azt::app
