#pragma once
// FODTRACK, the parallel-port protocol of seed 003's PIC16F870 interface (and of Hamlib's
// `fodtrack` backend, rotctl -m 301): the PC puts an 8-bit angle on the data lines,
// selects the axis with AUTOFEED (asserted: azimuth, released: elevation) and pulses STROBE to
// say the data is valid. The interface latches the byte when STROBE becomes active.
//
// Angles are byte / 255 of a full scale that the tracking program sets (Hamlib: the rotator's
// max_az and max_el). The seed's interface has 0–360° azimuth and 0–90° elevation (FLIP off), so
// its resolution is 360/255 = 1.41° in azimuth and 90/255 = 0.35° in elevation: no better than
// the byte allows, whatever the encoders behind it.
//
// Pure: feed() takes the port's lines as logical levels (true = asserted), whatever their
// electrical polarity; the Linux ppdev adapter reads and inverts them.

#include <cstdint>
#include <optional>

#include "azt/util/result.hpp"

namespace azt::proto {

struct ParallelSample {
  std::uint8_t data = 0;
  bool strobe = false;    ///< asserted: the data lines hold a valid angle
  bool autofeed = false;  ///< asserted: azimuth; released: elevation
};

struct FodtrackScale {
  double az_full_scale_deg = 360.0;  ///< the angle of byte 255
  double el_full_scale_deg = 90.0;

  /// Validates: each full scale 1–720°.
  static Result<FodtrackScale> make(double az_full_scale_deg, double el_full_scale_deg);
  [[nodiscard]] double az_step_deg() const { return az_full_scale_deg / 255.0; }
  [[nodiscard]] double el_step_deg() const { return el_full_scale_deg / 255.0; }
};

/// What one STROBE latched.
struct FodtrackLatch {
  bool azimuth = false;
  double angle_deg = 0.0;
  std::uint8_t raw = 0;
};

class FodtrackDecoder {
 public:
  explicit FodtrackDecoder(FodtrackScale scale = {}) : scale_(scale) {}

  /// One sample of the lines. Returns the angle latched when STROBE has just become active
  /// (one latch per pulse, however long the pulse is sampled).
  std::optional<FodtrackLatch> feed(const ParallelSample& sample);

  [[nodiscard]] std::optional<double> az_deg() const { return az_deg_; }
  [[nodiscard]] std::optional<double> el_deg() const { return el_deg_; }
  [[nodiscard]] const FodtrackScale& scale() const { return scale_; }

  /// The byte a FODTRACK program sends for `angle_deg` (Hamlib truncates angle/full·255).
  [[nodiscard]] static std::uint8_t encode(double angle_deg, double full_scale_deg);

 private:
  FodtrackScale scale_;
  bool strobe_ = false;
  std::optional<double> az_deg_;
  std::optional<double> el_deg_;
};

}  // namespace azt::proto
