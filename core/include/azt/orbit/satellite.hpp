#pragma once
// One satellite from a station: its element set with the SGP4 propagator made from it,
// where it is seen at an instant, and its passes.
//
// Times: SGP4 is fed the UTC Julian date; the Earth's rotation uses UT1 = UTC + DUT1 (the
// convention of docs/satellites.md). A satellite whose orbit has decayed is an error naming it.

#include <vector>

#include "azt/astro/observer.hpp"
#include "azt/astro/time_scales.hpp"
#include "azt/orbit/elements.hpp"
#include "azt/orbit/look_angles.hpp"
#include "azt/orbit/passes.hpp"
#include "azt/orbit/sgp4.hpp"
#include "azt/util/result.hpp"

namespace azt::orbit {

struct Satellite {
  Elements elements;
  Sgp4 sgp4;
};

/// The element set's age at `utc`, days (negative: the epoch is in the future).
double element_age_days(const Elements& e, const astro::UtcInstant& utc);

/// Where `sat` is seen from `site` at `utc`.
Result<LookAngles> look(const Satellite& sat, const astro::UtcInstant& utc, double dut1_s,
                        const astro::Observer& site);

/// Passes in [from, from + hours] above `mask`. Times in the result are seconds after `from`.
Result<std::vector<Pass>> find_satellite_passes(const Satellite& sat, const astro::UtcInstant& from,
                                                double hours, const HorizonMask& mask,
                                                double dut1_s, const astro::Observer& site);

}  // namespace azt::orbit
