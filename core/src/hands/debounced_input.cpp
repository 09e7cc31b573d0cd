#include "azt/hands/debounced_input.hpp"

namespace azt::hands {

bool DebouncedInput::update(double now_s, bool raw) {
  if (raw != raw_) {
    raw_ = raw;
    raw_since_s_ = now_s;
  }
  if (raw_ != level_ && now_s - raw_since_s_ >= settle_s_) level_ = raw_;
  return level_;
}

}  // namespace azt::hands
