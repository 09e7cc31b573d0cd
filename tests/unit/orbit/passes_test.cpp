// Pass search (docs/satellites.md) on a synthetic sky whose rises and sets are known in closed
// form: el(t) = A·sin(2πt/P) − B, az(t) = 360·t/P. The roots are where sin = (B + mask)/A.
#include "azt/orbit/passes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace azt::orbit {
namespace {

constexpr double kPeriod = 1000.0;

LookFunction sky(double amplitude, double offset, int* calls = nullptr) {
  return [=](double t) -> Result<LookAngles> {
    if (calls != nullptr) ++*calls;
    LookAngles l;
    l.el_deg = amplitude * std::sin(2.0 * std::numbers::pi * t / kPeriod) - offset;
    l.az_deg = std::fmod(360.0 * t / kPeriod, 360.0);
    return l;
  };
}

/// The first rise and set of el = A sin − B above `min_el`, in [0, P).
std::pair<double, double> analytic(double amplitude, double offset, double min_el) {
  const double x = std::asin((offset + min_el) / amplitude);
  return {kPeriod * x / (2.0 * std::numbers::pi),
          kPeriod * (std::numbers::pi - x) / (2.0 * std::numbers::pi)};
}

PassSearch window(double from, double to, double min_el = 0.0) {
  PassSearch s;
  s.from_s = from;
  s.to_s = to;
  s.mask = HorizonMask::flat(min_el);
  s.base_step_s = 20.0;
  return s;
}

TEST(Passes, RisesSetsAndTheHighestPointToAMillisecond) {
  const auto passes = find_passes(sky(30.0, 10.0), window(-100.0, 2900.0));
  ASSERT_TRUE(passes.ok()) << passes.error().message;
  ASSERT_EQ(passes.value().size(), 3U);
  const auto [rise, set] = analytic(30.0, 10.0, 0.0);
  for (std::size_t k = 0; k < 3; ++k) {
    const Pass& p = passes.value()[k];
    const double base = kPeriod * static_cast<double>(k);
    EXPECT_NEAR(p.aos_s, base + rise, 1e-3);
    EXPECT_NEAR(p.los_s, base + set, 1e-3);
    EXPECT_NEAR(p.tca_s, base + kPeriod / 4.0, 0.05);  // a flat top: time is loose, height not
    EXPECT_NEAR(p.max_el_deg, 20.0, 1e-9);
    EXPECT_NEAR(p.aos_az_deg, 360.0 * rise / kPeriod, 1e-3);
    EXPECT_FALSE(p.starts_before_window || p.ends_after_window);
  }
}

TEST(Passes, AGrazingPassIsFoundAndAMissIsNot) {
  auto grazing = find_passes(sky(10.05, 10.0), window(0.0, 1000.0));
  ASSERT_TRUE(grazing.ok());
  ASSERT_EQ(grazing.value().size(), 1U);
  EXPECT_NEAR(grazing.value()[0].max_el_deg, 0.05, 1e-9);
  auto miss = find_passes(sky(9.95, 10.0), window(0.0, 1000.0));
  ASSERT_TRUE(miss.ok());
  EXPECT_TRUE(miss.value().empty());
}

TEST(Passes, TheMaskRaisesTheHorizonInItsSector) {
  // 15° from azimuth 0 to 90 (where this sky rises), 0° elsewhere (where it sets).
  auto mask = HorizonMask::make({{0.0, 15.0}, {90.0, 0.0}});
  ASSERT_TRUE(mask.ok());
  PassSearch s = window(0.0, 1000.0);
  s.mask = mask.value();
  auto passes = find_passes(sky(30.0, 10.0), s);
  ASSERT_TRUE(passes.ok());
  ASSERT_EQ(passes.value().size(), 1U);
  EXPECT_NEAR(passes.value()[0].aos_s, analytic(30.0, 10.0, 15.0).first, 1e-3);
  EXPECT_NEAR(passes.value()[0].los_s, analytic(30.0, 10.0, 0.0).second, 1e-3);
  EXPECT_DOUBLE_EQ(mask.value().min_el_at(45.0), 15.0);
  EXPECT_DOUBLE_EQ(mask.value().min_el_at(359.0), 0.0);
  EXPECT_FALSE(HorizonMask::make({{90.0, 0.0}, {10.0, 5.0}}).ok());
  EXPECT_FALSE(HorizonMask::make({{0.0, 95.0}}).ok());
}

TEST(Passes, AWindowThatCutsAPassSaysSo) {
  const auto [rise, set] = analytic(30.0, 10.0, 0.0);
  auto early = find_passes(sky(30.0, 10.0), window(rise + 10.0, kPeriod));
  ASSERT_TRUE(early.ok());
  ASSERT_EQ(early.value().size(), 1U);
  EXPECT_TRUE(early.value()[0].starts_before_window);
  EXPECT_DOUBLE_EQ(early.value()[0].aos_s, rise + 10.0);
  EXPECT_NEAR(early.value()[0].los_s, set, 1e-3);
  auto late = find_passes(sky(30.0, 10.0), window(0.0, set - 20.0));
  ASSERT_TRUE(late.ok());
  ASSERT_EQ(late.value().size(), 1U);
  EXPECT_TRUE(late.value()[0].ends_after_window);
  EXPECT_DOUBLE_EQ(late.value()[0].los_s, set - 20.0);
  // Opening after the highest point: the pass is reported from the window's start.
  auto past_peak = find_passes(sky(30.0, 10.0), window(kPeriod / 4.0 + 50.0, kPeriod));
  ASSERT_TRUE(past_peak.ok());
  ASSERT_EQ(past_peak.value().size(), 1U);
  EXPECT_TRUE(past_peak.value()[0].starts_before_window);
  EXPECT_NEAR(past_peak.value()[0].los_s, set, 1e-3);
}

TEST(Passes, AnErrorEndsTheSearchWithIt) {
  const LookFunction decays = [](double t) -> Result<LookAngles> {
    if (t > 500.0) return fail("decayed");
    return LookAngles{0.0, -20.0, 1000.0, 0.0};
  };
  auto r = find_passes(decays, window(0.0, 1000.0));
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().message, "decayed");
  EXPECT_FALSE(find_passes(decays, window(10.0, 10.0)).ok());
}

TEST(Passes, FarBelowTheHorizonTheStepsAreLongButNothingIsMissed) {
  int slow = 0;
  int fast = 0;
  PassSearch s = window(0.0, 20 * kPeriod);
  auto base = find_passes(sky(60.0, 40.0, &slow), s);
  // Bounds that hold for this sky: its elevation changes at most 60·2π/1000 = 0.377°/s, which is
  // speed / distance for a body 1000 km away at that speed (plus 5 %).
  s.horizon_km = 1000.0;
  s.max_speed_km_s = 1000.0 * 0.377 * std::numbers::pi / 180.0 * 1.05;
  auto adaptive = find_passes(sky(60.0, 40.0, &fast), s);
  ASSERT_TRUE(base.ok() && adaptive.ok());
  ASSERT_EQ(base.value().size(), 20U);
  ASSERT_EQ(adaptive.value().size(), 20U);
  for (std::size_t i = 0; i < 20; ++i) {
    EXPECT_NEAR(adaptive.value()[i].aos_s, base.value()[i].aos_s, 1e-3);
  }
  EXPECT_LT(fast, slow) << "the bound did not lengthen any step";
}

TEST(HorizonMaskParse, ReadsOneElevationOrSectors) {
  auto flat = HorizonMask::parse("5");
  ASSERT_TRUE(flat.ok());
  EXPECT_DOUBLE_EQ(flat->min_el_at(123.0), 5.0);
  auto sectors = HorizonMask::parse("0:5,90:12,200:3");
  ASSERT_TRUE(sectors.ok());
  EXPECT_DOUBLE_EQ(sectors->min_el_at(100.0), 12.0);
  EXPECT_DOUBLE_EQ(sectors->min_el_at(359.0), 3.0);
}

TEST(HorizonMaskParse, QuotesWhatItCouldNotRead) {
  EXPECT_EQ(HorizonMask::parse("low").error().message, "'low' is not a number of degrees");
  EXPECT_EQ(HorizonMask::parse("0:5,90").error().message, "'90' is not AZ:MIN_EL (e.g. 0:5,90:10)");
  EXPECT_EQ(HorizonMask::parse("0:5,,90:1").error().message,
            "'' is not AZ:MIN_EL (e.g. 0:5,90:10)");
  EXPECT_FALSE(HorizonMask::parse("90:5,10:1").ok());  // not increasing: make() refuses it
}

}  // namespace
}  // namespace azt::orbit
