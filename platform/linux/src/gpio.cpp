#include "azt/linux/gpio.hpp"

namespace azt::linux_os {

std::string describe(const GpioLineSpec& spec) {
  return spec.key + " (" + spec.chip + " line " + std::to_string(spec.offset) + ")";
}

Result<std::unique_ptr<GpioInput>> GpioProvider::event_input(const GpioLineSpec& spec,
                                                             GpioBias /*bias*/,
                                                             GpioEventHandler /*on_event*/) {
  return fail(describe(spec) + ": this GPIO provider does not report single edges");
}

}  // namespace azt::linux_os
