#include "hands/hand_buttons.hpp"

#include "common/usage_error.hpp"

namespace azt::app {

HandButtons::HandButtons(const ButtonsConfig& config, linux_os::GpioProvider& gpio,
                         StationCommands& commands, std::function<double()> monotonic_s)
    : monotonic_s_(std::move(monotonic_s)),
      control_(hands::HandControlConfig{config.speed}),
      door_(commands, CommandSource{CommandSource::Kind::Hands, "buttons"}, config.park_slot) {
  request(buttons_[Cw], config.cw, gpio, config.debounce_s);
  request(buttons_[Ccw], config.ccw, gpio, config.debounce_s);
  request(buttons_[Up], config.up, gpio, config.debounce_s);
  request(buttons_[Down], config.down, gpio, config.debounce_s);
  request(buttons_[Stop], config.stop, gpio, config.debounce_s);
  request(buttons_[Park], config.park, gpio, config.debounce_s);
}

void HandButtons::request(Button& button, const std::optional<linux_os::GpioLineSpec>& spec,
                          linux_os::GpioProvider& gpio, double debounce_s) {
  button.debounced = hands::DebouncedInput(debounce_s);
  if (!spec) return;
  auto line = gpio.input(*spec, linux_os::GpioBias::PullUp, [this, &button](bool active) {
    button.debounced.update(monotonic_s_(), active);
  });
  if (!line) throw UsageError(line.error().message);
  button.line = std::move(line).value();
  button.debounced.update(monotonic_s_(), button.line->active());
}

hands::HandInputs HandButtons::held() const {
  const auto level = [this](Index i) { return buttons_[i].debounced.level(); };
  hands::HandInputs in;
  in.cw = level(Cw);
  in.ccw = level(Ccw);
  in.up = level(Up);
  in.down = level(Down);
  in.stop = level(Stop);
  in.park = level(Park);
  return in;
}

void HandButtons::tick() {
  const double now_s = monotonic_s_();
  for (Button& b : buttons_) {
    if (b.line) b.debounced.update(now_s, b.line->active());
  }
  door_.apply(control_.update(held()));
}

}  // namespace azt::app
