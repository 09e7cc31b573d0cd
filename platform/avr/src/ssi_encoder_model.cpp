#include "azt/avr/ssi_encoder_model.hpp"

#include "azt/proto/hub_frame.hpp"
#include "ssi_reading.hpp"

namespace azt::avr {

std::uint8_t SsiEncoderModel::word_bits() const {
  return kind_ == EncoderModelKind::As5045 ? hub::kAs5045WordBits : bits_;
}

std::uint32_t SsiEncoderModel::word_for(std::uint16_t raw) const {
  if (kind_ == EncoderModelKind::As5045) {
    return hub::make_as5045_word(raw, true, false, false, false, false);
  }
  const auto limited = static_cast<std::uint16_t>(raw & (proto::hub_raw_limit(bits_) - 1U));
  return kind_ == EncoderModelKind::SsiGray ? hub::binary_to_gray(limited) : limited;
}

void SsiEncoderModel::latch() {
  word_ = word_for(raw_);
  ++words_;
  if (fault_ == EncoderFault::Flip && words_ % 2U == 0) word_ ^= 1U << (word_bits() / 2U);
  if (fault_ == EncoderFault::Glitch && words_ % 8U == 0) {
    noise_ ^= noise_ << 13U;
    noise_ ^= noise_ >> 17U;
    noise_ ^= noise_ << 5U;
    word_ ^= noise_ & ((std::uint32_t{1} << word_bits()) - 1U);
  }
  next_bit_ = 0;
}

void SsiEncoderModel::on_chip_select(bool high, double now_us) {
  if (kind_ != EncoderModelKind::As5045) return;
  if (!high) {
    latch();
    level_ = true;
  } else {
    next_bit_ = -1;
    level_ = true;
    released_at_us_ = now_us;
  }
}

bool SsiEncoderModel::idle(double now_us) const {
  if (next_bit_ < 0) return now_us - released_at_us_ >= kMonoflopUs;
  // A word clocked to its last bit with no trailer clock is over once the line rests.
  return next_bit_ >= word_bits() && now_us - last_edge_us_ >= kMonoflopUs;
}

void SsiEncoderModel::on_clock(bool high, double now_us) {
  const bool falling = clock_high_ && !high;
  const bool rising = !clock_high_ && high;
  clock_high_ = high;
  const bool generic = kind_ != EncoderModelKind::As5045;
  // Generic SSI: the first falling edge of an idle line latches the count.
  if (generic && falling && idle(now_us)) latch();
  last_edge_us_ = now_us;
  if (!rising || next_bit_ < 0) return;
  const int n = word_bits();
  if (next_bit_ < n) {
    level_ = ((word_ >> (n - 1 - next_bit_)) & 1U) != 0;
    ++next_bit_;
    return;
  }
  level_ = false;  // past the word: the monoflop time (AS5045: zeros until chip select rises)
  if (generic) {
    next_bit_ = -1;
    released_at_us_ = now_us;
  }
}

bool SsiEncoderModel::data(double now_us) const {
  if (fault_ == EncoderFault::Stuck) return false;
  if (fault_ == EncoderFault::Open) return true;
  if (kind_ != EncoderModelKind::As5045 && idle(now_us)) return true;
  if (kind_ != EncoderModelKind::As5045 && next_bit_ < 0) return false;  // in the monoflop time
  return level_;
}

}  // namespace azt::avr
