#include "azt/linux/gpio.hpp"

namespace azt::linux_os {

std::string describe(const GpioLineSpec& spec) {
  return spec.key + " (" + spec.chip + " line " + std::to_string(spec.offset) + ")";
}

// By value as in input(): the providers that can report edges move the handler into the line.
// NOLINTBEGIN(performance-unnecessary-value-param)
Result<std::unique_ptr<GpioInput>> GpioProvider::event_input(const GpioLineSpec& spec,
                                                             GpioBias /*bias*/,
                                                             GpioEventHandler /*on_event*/) {
  return fail(describe(spec) + ": this GPIO provider does not report single edges");
}
// NOLINTEND(performance-unnecessary-value-param)

}  // namespace azt::linux_os
