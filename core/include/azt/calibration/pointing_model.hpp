#pragma once
// The pointing model of an alt-azimuth mount (docs/calibration.md): where the beam points on the
// sky for given encoder angles, with the classical geometric terms named as in TPOINT (P. T.
// Wallace, "TPOINT — A Telescope Pointing Analysis System", Starlink SUN/100; the alt-az terms IA,
// IE, CA, NPAE, AN, AW and the tube-flexure term, here the elevation sag) and the seven-term
// Haystack practice of astronomy-and-eme.md §8. The geometry is exact (rotations, not the
// first-order sums), so a mount that is off by a degree in several terms is still modelled to
// micro-degrees; to first order the terms act as the sums in the comments below.
//
// The names are TPOINT's; the signs are this file's own, stated term by term below.
//
// Frame: east-north-up at the station, azimuth from north through east, elevation above the
// horizontal; a mount angle is what the (offset-corrected) encoder reads.

#include <array>
#include <optional>

#include "azt/control/modes.hpp"

namespace azt::calibration {

/// The terms, in degrees. Signs are physical; first-order effects with A, E the beam's sky
/// azimuth and elevation, a, e the mount's readings:
struct PointingTerms {
  double ia_deg = 0.0;    ///< az encoder reads IA more than the mount's azimuth: a − A ⊃ +IA
  double ie_deg = 0.0;    ///< el encoder reads IE more than the mount's elevation: e − E ⊃ +IE
  double ca_deg = 0.0;    ///< beam CA clockwise of square to the el axis: a − A ⊃ −CA·sec E
  double npae_deg = 0.0;  ///< el axis's clockwise end raised by NPAE: a − A ⊃ +NPAE·tan E
  /// Azimuth axis tilted towards the north by AN: a − A ⊃ +AN·sin A·tan E, e − E ⊃ +AN·cos A.
  double an_deg = 0.0;
  /// Azimuth axis tilted towards the east by AW: a − A ⊃ −AW·cos A·tan E, e − E ⊃ +AW·sin A.
  double aw_deg = 0.0;
  double sag_deg = 0.0;  ///< the beam droops by SAG·cos e (gravity): e − E ⊃ +SAG·cos E

  static constexpr int kCount = 7;
  /// The terms as an array, in the order above (for fits), and back.
  [[nodiscard]] std::array<double, kCount> as_array() const;
  static PointingTerms from_array(const std::array<double, kCount>& v);
  [[nodiscard]] bool is_zero() const;
};

/// An azimuth-axis tilt of `tilt_deg` towards azimuth `toward_deg`, as AN and AW.
PointingTerms tilt_terms(double tilt_deg, double toward_deg);

/// Where the beam points on the sky when the encoders read `mount` (elevation up to 180° on flip
/// mounts: the beam then looks back over the zenith, and the result is a sky direction with
/// elevation ≤ 90°).
control::AzEl beam_on_sky(const control::AzEl& mount, const PointingTerms& terms);

/// The mount angles at which the beam points at `sky` (the inverse of beam_on_sky, by Newton's
/// method from the sky direction; elevation ≤ 90°). nullopt when it does not converge (within a
/// fraction of a degree of the zenith with large terms).
std::optional<control::AzEl> mount_for_sky(const control::AzEl& sky, const PointingTerms& terms);

/// The beam's direction as a reading in the mount's own frame: beam_on_sky, expressed over the
/// zenith for a flip mount's reading above 90°. Within 5° of the zenith the azimuth correction is
/// held at its value 5° away: the azimuth of a beam at the zenith is undefined, and a controller
/// must not chase it round the sky (the elevation correction stays exact).
control::AzEl corrected_reading(const control::AzEl& mount, const PointingTerms& terms);

/// Great-circle angle between two sky directions, degrees.
double separation_deg(const control::AzEl& a, const control::AzEl& b);

/// An offset from a source as the scans use it: coordinates in the plane tangent to the sky at
/// the source (the gnomonic projection), along increasing azimuth (cross-elevation) and
/// elevation, in degrees. Small offsets are ΔA·cos E and ΔE; unlike those, they stay true
/// lines on the sky near the zenith, where a line of constant elevation is a tight circle.
struct SkyOffset {
  double xel_deg = 0.0;
  double el_deg = 0.0;
};

/// The offset of `beam` from `source` (tangent-plane coordinates; |offset| < 90°).
SkyOffset offset_between(const control::AzEl& source, const control::AzEl& beam);

/// `source` moved by `offset`: the inverse of offset_between.
control::AzEl apply_offset(const control::AzEl& source, const SkyOffset& offset);

}  // namespace azt::calibration
