#pragma once
// How old a satellite's elements may be (docs/satellites.md, "Element age"): SGP4's along-track
// error of a LEO set grows by kilometres a day (Vallado et al. 2006, AIAA 2006-6753, §1), so
// beyond a few weeks a pass's times are off by tens of seconds and beyond two months the antenna
// would point where the satellite is not. Past `stale_days` passes are shown and tracked but
// marked; past `refuse_days` the satellite is not tracked.
//
// Pure: the age is a parameter.

#include <string>

namespace azt::orbit {

struct ElementAgeLimits {
  double stale_days = 14.0;
  double refuse_days = 60.0;
};

enum class ElementAge { Fresh, Stale, Refused };

/// The verdict on elements `age_days` from their epoch (negative: the epoch is ahead, which
/// ages the same way, so the magnitude counts).
ElementAge judge_element_age(double age_days, const ElementAgeLimits& limits);

/// Why a satellite is not tracked: "the elements of NAME are 75.2 days from their epoch
/// (beyond [satellites] refuse_days = 60): fetch fresh ones"; empty when it may be.
std::string element_age_refusal(const std::string& name, double age_days,
                                const ElementAgeLimits& limits);

}  // namespace azt::orbit
