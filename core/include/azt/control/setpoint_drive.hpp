#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "azt/util/result.hpp"

namespace azt::control {

// A rotator whose own control box closes the loop (seed 001: an ORBIT-360 box compares its
// control pot with the rotor's feedback pot and runs the motor "When the error signal exceeds a
// minimum threshold"). The control pot is replaced by an SPI digital pot, a Microchip MCP41010:
// 256 taps, wiper code 0..255, written as a 16-bit block (command byte, wiper byte). We only
// choose the wiper code; the box does the rest, so there is no hysteresis or timing here — the
// box's own threshold is the deadband.

/// The straight line between wiper code and the angle the box turns the rotator to, through two
/// measured points (set a code, wait for the box to settle, read the antenna's angle). The
/// MCP41010's wiper sits code/256 of the way from terminal B to terminal A (MCP41XXX/42XXX
/// datasheet, DS11195), linear in the code; code 255 is 255/256 of the travel, not all of it,
/// which is one reason to calibrate with measured points rather than the nominal ends. A pot
/// wired the other way round simply has deg_b < deg_a. The default is the worked example of
/// a 450° rotator (the Yaesu G-5400/5500/5600 class that seed 001 also names): code 0 at 0°,
/// code 255 at 450°, 450/255 ≈ 1.765° per code.
struct SetpointCalibration {
  double wiper_a = 0.0;
  double deg_a = 0.0;
  double wiper_b = 255.0;
  double deg_b = 450.0;

  /// Validates: all finite, wipers within 0..255 and distinct, angles distinct.
  static Result<SetpointCalibration> make(double wiper_a, double deg_a, double wiper_b,
                                          double deg_b);

  /// The (unrounded, unclamped) wiper code for an angle.
  [[nodiscard]] double wiper_from_deg(double deg) const;
  /// The angle a (possibly fractional) code turns the rotator to.
  [[nodiscard]] double deg_from_wiper(double wiper) const;
  /// Degrees per wiper code: the finest setpoint step, and so the least tracking error to expect.
  [[nodiscard]] double step_deg() const;
};

/// How a target mapped onto the wiper.
enum class SetpointStatus : std::uint8_t {
  InRange,    ///< the target lies within the angles of codes 0..255
  Clamped,    ///< beyond them: the wiper is the nearer end, the rotator stops short of the target
  NotFinite,  ///< NaN or infinite target: nothing is sent, the box keeps its last setpoint
};

/// One update's outcome.
struct SetpointUpdate {
  /// The code to write to the pot now; empty when the pot already holds it (or NotFinite).
  std::optional<std::uint8_t> send;
  /// The code the target maps to (rounded to the nearest code, then clamped); 0 when NotFinite.
  std::uint8_t wiper = 0;
  SetpointStatus status = SetpointStatus::InRange;

  [[nodiscard]] bool clamped() const { return status == SetpointStatus::Clamped; }
};

/// Turns target angles into wiper writes, sending only when the code changes. The MCP41010 keeps
/// its code only while powered (volatile register), so repeating it is bus traffic with no
/// effect; after a power loss it comes back at mid-scale (a user's report: Parallax forum,
/// "MCP41010 - Not 'Set and Forget'?", the output went "back to 1/2 the voltage supply"). After
/// the interface or the pot has been reconnected or powered up, call force_resend() so the next
/// update rewrites the code, or the box turns the rotator to the middle of its range.
///
/// Clamping: a target outside the calibrated span goes to the nearer end (code 0 or 255) and is
/// reported as Clamped (the caller's limits, wrap and warnings decide what to tell the user); it
/// is the exact, unrounded code that decides, so a target just past an end is Clamped even
/// though it rounds to that end anyway. Stopping is not this class's business: the box holds the
/// rotator at the setpoint; to stop a move, send the present position as the target (as
/// EasyComm's `SA SE` sets the setpoint to the current position).
class SetpointDrive {
 public:
  /// Precondition: SetpointCalibration::make(...) accepted the calibration.
  explicit SetpointDrive(const SetpointCalibration& calibration) : calibration_(calibration) {}

  SetpointUpdate update(double target_deg);
  /// Forget what the pot holds: the next finite update sends its code even if unchanged.
  void force_resend() { last_sent_.reset(); }

  /// The code last sent; empty before the first send and after force_resend().
  [[nodiscard]] std::optional<std::uint8_t> last_sent() const { return last_sent_; }
  [[nodiscard]] const SetpointCalibration& calibration() const { return calibration_; }

 private:
  SetpointCalibration calibration_;
  std::optional<std::uint8_t> last_sent_;
};

/// The 16-bit SPI block that sets the MCP41010's wiper (datasheet DS11195, "Write Data"): the
/// command byte 0x11 (command bits 01 = write data, pot-select bits 01 = potentiometer 0), then
/// the wiper code; sent most significant bit first in SPI mode 0 with CS low for all 16 clocks.
[[nodiscard]] constexpr std::array<std::uint8_t, 2> mcp41010_write_frame(std::uint8_t wiper) {
  return {std::uint8_t{0x11}, wiper};
}

}  // namespace azt::control
