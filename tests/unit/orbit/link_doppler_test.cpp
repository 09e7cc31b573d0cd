// The one-way Doppler of a satellite link against its closed forms (classical, ground frame):
// heard f/(1 + ṙ/c), sent f/(1 − ṙ/c), with hand-worked values in the comments, and how far the
// first-order forms Gpredict sends lie from them.
#include "azt/orbit/link_doppler.hpp"

#include <gtest/gtest.h>

namespace azt::orbit {
namespace {

TEST(LinkDoppler, HeardIsTheSatelliteFrequencyOverOnePlusTheRangeRate) {
  // 435e6 / (1 + 7/299792.458) = 435e6 / 1.0000233494... = 434989843.2104 Hz (receding: lower)
  EXPECT_NEAR(downlink_hz(435e6, 7.0), 434989843.2104, 1e-3);
  // 435e6 / (1 − 7/299792.458) = 435010157.2639 Hz (approaching: higher)
  EXPECT_NEAR(downlink_hz(435e6, -7.0), 435010157.2639, 1e-3);
  EXPECT_EQ(downlink_hz(435e6, 0.0), 435e6);
}

TEST(LinkDoppler, SentIsTheSatelliteFrequencyOverOneMinusTheRangeRate) {
  // 145.9e6 / (1 − 7/299792.458) = 145903406.7697 Hz (receding: send higher)
  EXPECT_NEAR(uplink_hz(145.9e6, 7.0), 145903406.7697, 1e-3);
  // 145.9e6 / (1 + 7/299792.458) = 145896593.3894 Hz
  EXPECT_NEAR(uplink_hz(145.9e6, -7.0), 145896593.3894, 1e-3);
}

TEST(LinkDoppler, TheSatelliteFrameIsTheInverseOfTheHeardFrequency) {
  for (const double rate : {-7.5, -1.0, 0.0, 3.0, 7.5}) {
    EXPECT_NEAR(satellite_downlink_hz(downlink_hz(2400.1e6, rate), rate), 2400.1e6, 1e-5);
  }
  // 435 090 000 · (1 + 3/299792.458) = 435 094 353.9121
  EXPECT_NEAR(satellite_downlink_hz(435090000.0, 3.0), 435094353.9121, 1e-3);
}

TEST(LinkDoppler, TheFirstOrderFormsDifferByTheSquareOfTheRangeRate) {
  // f·(ṙ/c)² at 7 km/s: 0.2372 Hz at 435 MHz, 1.3085 Hz at 2.4 GHz; below every rig's step.
  constexpr double beta = 7.0 / kLightKmS;
  EXPECT_NEAR(uplink_hz(435e6, 7.0) - 435e6 * (1.0 + beta), 435e6 * beta * beta, 1e-4);
  EXPECT_NEAR(downlink_hz(435e6, 7.0) - 435e6 * (1.0 - beta), 435e6 * beta * beta, 1e-4);
  EXPECT_NEAR(435e6 * beta * beta, 0.2372, 1e-3);
}

}  // namespace
}  // namespace azt::orbit
