#include "azt/linux/gpio.hpp"

namespace azt::linux_os {

std::string describe(const GpioLineSpec& spec) {
  return spec.key + " (" + spec.chip + " line " + std::to_string(spec.offset) + ")";
}

}  // namespace azt::linux_os
