#include "azt/proto/spid.hpp"

#include <cmath>

namespace azt::proto {
namespace {

bool valid_resolution(int pulses) { return pulses == 1 || pulses == 2 || pulses == 4; }

bool known_k(std::uint8_t k) { return k == kSpidKStop || k == kSpidKStatus || k == kSpidKSet; }

/// Four (or `count`) ASCII digits starting at `first`.
std::optional<int> ascii_digits(std::span<const std::uint8_t> frame, std::size_t first,
                                std::size_t count) {
  int value = 0;
  for (std::size_t i = first; i < first + count; ++i) {
    if (frame[i] < '0' || frame[i] > '9') return std::nullopt;
    value = value * 10 + (frame[i] - '0');
  }
  return value;
}

/// (deg + 360) * 10 as four binary digits, or nothing if it does not fit.
std::optional<std::array<std::uint8_t, 4>> binary_digits(double deg) {
  if (!std::isfinite(deg)) return std::nullopt;
  const long tenths = std::lround((deg + 360.0) * 10.0);
  if (tenths < 0 || tenths > 9999) return std::nullopt;
  return std::array<std::uint8_t, 4>{
      static_cast<std::uint8_t>(tenths / 1000), static_cast<std::uint8_t>(tenths / 100 % 10),
      static_cast<std::uint8_t>(tenths / 10 % 10), static_cast<std::uint8_t>(tenths % 10)};
}

/// Writes `value` as four ASCII digits at frame[first].
bool put_ascii(SpidFrame& frame, std::size_t first, long value) {
  if (value < 0 || value > 9999) return false;
  for (std::size_t i = 4; i-- > 0;) {
    frame[first + i] = static_cast<std::uint8_t>('0' + value % 10);
    value /= 10;
  }
  return true;
}

Result<SpidCommand> parse_set(std::span<const std::uint8_t> frame, const SpidConfig& config) {
  SpidCommand cmd{SpidOp::Set};
  if (config.dialect == SpidDialect::Rot1Prog) {
    const auto h = ascii_digits(frame, 1, 3);
    if (!h || frame[4] != '0') return fail("SPID: set azimuth must be ASCII digits");
    cmd.az_deg = *h - 360.0;
  } else {
    const auto h = ascii_digits(frame, 1, 4);
    const auto v = ascii_digits(frame, 6, 4);
    if (!h || !v) return fail("SPID: set angles must be ASCII digits");
    cmd.az_deg = *h / static_cast<double>(config.pulses_per_deg_az) - 360.0;
    cmd.el_deg = *v / static_cast<double>(config.pulses_per_deg_el) - 360.0;
    if (cmd.el_deg < config.el_min_deg || cmd.el_deg > config.el_max_deg) {
      return fail("SPID: elevation out of range");
    }
  }
  if (cmd.az_deg < config.az_min_deg || cmd.az_deg > config.az_max_deg) {
    return fail("SPID: azimuth out of range");
  }
  return cmd;
}

}  // namespace

Result<SpidCommand> parse_spid(std::span<const std::uint8_t> frame, const SpidConfig& config) {
  if (frame.size() != kSpidCommandBytes) return fail("SPID: a command frame is 13 bytes");
  if (frame[0] != kSpidStart || frame[12] != kSpidEnd) return fail("SPID: bad start or end byte");
  if (!valid_resolution(config.pulses_per_deg_az) || !valid_resolution(config.pulses_per_deg_el)) {
    return fail("SPID: pulses per degree must be 1, 2 or 4");
  }
  switch (frame[11]) {
    case kSpidKStop:
      return SpidCommand{SpidOp::Stop};
    case kSpidKStatus:
      return SpidCommand{SpidOp::Status};
    case kSpidKSet:
      return parse_set(frame, config);
    default:
      return fail("SPID: unknown command byte K");
  }
}

Result<std::array<std::uint8_t, kSpidRot2ReplyBytes>> format_spid_rot2_reply(
    double az_deg, double el_deg, const SpidConfig& config) {
  if (!valid_resolution(config.pulses_per_deg_az) || !valid_resolution(config.pulses_per_deg_el)) {
    return fail("SPID: pulses per degree must be 1, 2 or 4");
  }
  const auto h = binary_digits(az_deg);
  const auto v = binary_digits(el_deg);
  if (!h || !v) return fail("SPID: position does not fit the reply");
  return std::array<std::uint8_t, kSpidRot2ReplyBytes>{
      kSpidStart,
      (*h)[0],
      (*h)[1],
      (*h)[2],
      (*h)[3],
      static_cast<std::uint8_t>(config.pulses_per_deg_az),
      (*v)[0],
      (*v)[1],
      (*v)[2],
      (*v)[3],
      static_cast<std::uint8_t>(config.pulses_per_deg_el),
      kSpidEnd};
}

Result<std::array<std::uint8_t, kSpidRot1ReplyBytes>> format_spid_rot1_reply(double az_deg) {
  if (!std::isfinite(az_deg)) return fail("SPID: position is not finite");
  const long h = std::lround(az_deg + 360.0);
  if (h < 0 || h > 999) return fail("SPID: position does not fit the reply");
  return std::array<std::uint8_t, kSpidRot1ReplyBytes>{
      kSpidStart, static_cast<std::uint8_t>(h / 100), static_cast<std::uint8_t>(h / 10 % 10),
      static_cast<std::uint8_t>(h % 10), kSpidEnd};
}

Result<SpidFrame> encode_spid_set(double az_deg, double el_deg, const SpidConfig& config) {
  if (!std::isfinite(az_deg) || !std::isfinite(el_deg)) return fail("SPID: target not finite");
  if (!valid_resolution(config.pulses_per_deg_az) || !valid_resolution(config.pulses_per_deg_el)) {
    return fail("SPID: pulses per degree must be 1, 2 or 4");
  }
  SpidFrame frame{kSpidStart};
  frame[11] = kSpidKSet;
  frame[12] = kSpidEnd;
  // Hamlib converts to unsigned int: truncation, not rounding.
  const double h = config.pulses_per_deg_az * (360.0 + az_deg);
  const double v = config.pulses_per_deg_el * (360.0 + el_deg);
  if (h < 0.0 || v < 0.0 || h >= 10000.0 || v >= 10000.0) return fail("SPID: target out of range");
  bool ok = true;
  if (config.dialect == SpidDialect::Rot1Prog) {
    ok = put_ascii(frame, 1, static_cast<long>(360.0 + az_deg) * 10) &&
         static_cast<long>(360.0 + az_deg) <= 999;
    for (std::size_t i = 5; i < 11; ++i) frame[i] = 0;
  } else {
    ok = put_ascii(frame, 1, static_cast<long>(h)) && put_ascii(frame, 6, static_cast<long>(v));
    frame[5] = static_cast<std::uint8_t>(config.pulses_per_deg_az);
    frame[10] = static_cast<std::uint8_t>(config.pulses_per_deg_el);
  }
  if (!ok) return fail("SPID: target out of range");
  return frame;
}

std::optional<SpidFrame> SpidFrameAssembler::push(std::uint8_t byte) {
  if (size_ == 0 && byte != kSpidStart) {
    ++dropped_bytes_;
    return std::nullopt;
  }
  buffer_[size_++] = byte;
  if (size_ < kSpidCommandBytes) return std::nullopt;
  if (buffer_[12] == kSpidEnd && known_k(buffer_[11])) {
    size_ = 0;
    return buffer_;
  }
  resync();
  return std::nullopt;
}

void SpidFrameAssembler::resync() {
  // Drop the bad start byte and everything up to the next 'W'.
  std::size_t next = 1;
  while (next < size_ && buffer_[next] != kSpidStart) ++next;
  dropped_bytes_ += next;
  for (std::size_t i = next; i < size_; ++i) buffer_[i - next] = buffer_[i];
  size_ -= next;
}

}  // namespace azt::proto
