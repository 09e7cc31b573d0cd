#pragma once
// The tracked target's apparent position for the control tick: computed by the sky engine once
// per second and interpolated between (the Moon moves 0.004°/s; the interpolation error is far
// below an encoder step), so a 20 Hz tick costs a few arithmetic operations.

#include <optional>
#include <string>

#include "azt/astro/ephemeris.hpp"
#include "azt/astro/target.hpp"
#include "azt/control/modes.hpp"
#include "config/sky_config.hpp"

namespace azt::app {

struct SkyFix {
  control::AzEl position;  ///< refracted apparent az/el
  control::AzEl rate_deg_s;
};

class SkyFollower {
 public:
  SkyFollower(const astro::Ephemeris& ephemeris, const SkyConfig& station)
      : ephemeris_(ephemeris), station_(station) {}

  /// Finds a target by name among the configured ones (case-insensitive: "moon", "casa").
  [[nodiscard]] std::optional<astro::Target> find(const std::string& name) const;
  void follow(const astro::Target& target);
  /// The station's place changed: the target followed, found again by name (a configured one
  /// may depend on the place), is computed afresh.
  void refollow();
  [[nodiscard]] const std::optional<astro::Target>& target() const { return target_; }

  /// Where the target is at `utc_unix_s` (UTC seconds since 1970); nullopt when the engine cannot
  /// compute it (the error is kept in last_error()).
  std::optional<SkyFix> at(double utc_unix_s);
  [[nodiscard]] const std::string& last_error() const { return last_error_; }

 private:
  std::optional<control::AzEl> compute(double utc_unix_s);

  const astro::Ephemeris& ephemeris_;
  const SkyConfig& station_;
  std::optional<astro::Target> target_;
  double t0_ = -1.0;  ///< whole second of the cached pair
  std::optional<control::AzEl> p0_;
  std::optional<control::AzEl> p1_;
  std::string last_error_;
};

}  // namespace azt::app
