// Refraction models against worked values of their published formulas.
// Tables: ../shared/reference/astronomy-and-eme.md §3.4 (values computed there from ITU-R P.834
// eqs. 9/14, Sæmundsson/Meeus and ERFA eraRefco).
#include "azt/astro/refraction.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace azt::astro {
namespace {

constexpr double kArcmin = 1.0 / 60.0;

TEST(ItuP834, ReferenceAtmosphereAtSeaLevel) {
  // §3.4 table, column "ITU-R P.834 τ_s (radio, h=0)".
  EXPECT_NEAR(itu_p834_refraction_deg(0.0, 0.0) / kArcmin, 34.7, 0.05);
  EXPECT_NEAR(itu_p834_refraction_deg(1.0, 0.0) / kArcmin, 26.0, 0.05);
  EXPECT_NEAR(itu_p834_refraction_deg(2.0, 0.0) / kArcmin, 20.3, 0.05);
  EXPECT_NEAR(itu_p834_refraction_deg(5.0, 0.0) / kArcmin, 11.2, 0.05);
  EXPECT_NEAR(itu_p834_refraction_deg(10.0, 0.0) / kArcmin, 5.5, 0.05);
}

TEST(ItuP834, LessBendingAtAHigherStation) {
  EXPECT_LT(itu_p834_refraction_deg(0.0, 2.0), itu_p834_refraction_deg(0.0, 0.0));
}

TEST(Saemundsson, MeeusTableAt1010HpaAnd10C) {
  // §3.4 table, column "Sæmundsson (optical)".
  const double expected[][2] = {{0, 29.0}, {1, 21.7}, {2, 16.9}, {5, 9.7},
                                {10, 5.4}, {20, 2.7}, {45, 1.0}};
  for (const auto& row : expected) {
    EXPECT_NEAR(saemundsson_refraction_deg(row[0], 1010.0, 10.0) / kArcmin, row[1], 0.06) << row[0];
  }
  EXPECT_NEAR(saemundsson_refraction_deg(90.0, 1010.0, 10.0), 0.0, 1e-6);
}

TEST(RadioRefractivity, DryStandardAtmosphere) {
  // Dry air, 1013.25 hPa, 15 °C: N = 77.6·P/T = 272.9 N-units (ITU-R P.453 dry term).
  EXPECT_NEAR(radio_refractivity(1013.25, 15.0, 0.0), 272.9, 0.1);
}

TEST(RadioRefractivity, WaterVapourRaisesIt) {
  EXPECT_GT(radio_refractivity(1013.25, 25.0, 0.9), radio_refractivity(1013.25, 25.0, 0.1) + 50.0);
}

TEST(RadioRefraction, ErfaRadioModelAboveFifteenDegrees) {
  // §3.4 table, columns "eraRefco radio 10 °C 50 %" and "25 °C 90 %" (at 1013.25 hPa).
  const Atmosphere mild{1013.25, 10.0, 0.5, RefractionModel::Radio};
  const Atmosphere humid{1013.25, 25.0, 0.9, RefractionModel::Radio};
  EXPECT_NEAR(refraction_deg(20.0, 0.0, mild) / kArcmin, 2.9, 0.05);
  EXPECT_NEAR(refraction_deg(45.0, 0.0, mild) / kArcmin, 1.05, 0.01);
  EXPECT_NEAR(refraction_deg(20.0, 0.0, humid) / kArcmin, 3.6, 0.05);
  EXPECT_NEAR(refraction_deg(45.0, 0.0, humid) / kArcmin, 1.32, 0.01);
}

TEST(RadioRefraction, HorizonValueFollowsSurfaceRefractivity) {
  // At 0° the model is P.834 scaled by N_surface/315: a station whose weather gives N = 315 gets
  // the reference 34.7′; drier air gets proportionally less.
  const Atmosphere dry{1013.25, 15.0, 0.0, RefractionModel::Radio};
  const double n = radio_refractivity(1013.25, 15.0, 0.0);
  EXPECT_NEAR(refraction_deg(0.0, 0.0, dry) / kArcmin, 34.72 * n / 315.0, 0.02);
}

TEST(RadioRefraction, SmoothAndDecreasingFromBelowHorizonToZenith) {
  const Atmosphere atm{1013.25, 10.0, 0.5, RefractionModel::Radio};
  double previous = refraction_deg(-1.0, 300.0, atm);
  for (double el = -0.99; el <= 90.0; el += 0.01) {
    const double r = refraction_deg(el, 300.0, atm);
    EXPECT_LE(r, previous + 1e-12) << el;
    // No jump anywhere, in particular at the 5° and 15° blend edges: < 0.5″ per 0.01°.
    EXPECT_LT(previous - r, 0.2 * kArcmin) << el;
    previous = r;
  }
  EXPECT_LT(refraction_deg(90.0, 300.0, atm), 1e-6);
}

TEST(Refraction, FadesOutBelowTheHorizon) {
  const Atmosphere atm{1013.25, 10.0, 0.5, RefractionModel::Radio};
  const double at_minus_one = refraction_deg(-1.0, 0.0, atm);
  EXPECT_GT(at_minus_one, 0.5);
  EXPECT_NEAR(refraction_deg(-1.5, 0.0, atm), at_minus_one / 2.0, 1e-9);
  EXPECT_EQ(refraction_deg(-2.0, 0.0, atm), 0.0);
  EXPECT_EQ(refraction_deg(-45.0, 0.0, atm), 0.0);
  EXPECT_EQ(refraction_deg(std::nan(""), 0.0, atm), 0.0);
}

TEST(Refraction, NoneModelIsZero) {
  const Atmosphere atm{1013.25, 10.0, 0.5, RefractionModel::None};
  EXPECT_EQ(refraction_deg(0.0, 0.0, atm), 0.0);
  EXPECT_EQ(refraction_deg(30.0, 0.0, atm), 0.0);
}

TEST(Refraction, RadioExceedsOpticalInHumidAir) {
  // §3.4: radio refraction is 8–36 % larger than optical, driven by humidity.
  Atmosphere radio{1013.25, 25.0, 0.9, RefractionModel::Radio};
  Atmosphere optical = radio;
  optical.model = RefractionModel::Optical;
  for (double el : {0.0, 2.0, 10.0, 30.0, 60.0}) {
    EXPECT_GT(refraction_deg(el, 0.0, radio), 1.08 * refraction_deg(el, 0.0, optical)) << el;
  }
}

TEST(Atmosphere, ValidatesRanges) {
  EXPECT_TRUE(Atmosphere::make(1013.25, 10.0, 0.5, RefractionModel::Radio).ok());
  EXPECT_FALSE(Atmosphere::make(-1.0, 10.0, 0.5, RefractionModel::Radio).ok());
  EXPECT_FALSE(Atmosphere::make(1013.25, 99.0, 0.5, RefractionModel::Radio).ok());
  EXPECT_FALSE(Atmosphere::make(1013.25, 10.0, 1.5, RefractionModel::Radio).ok());
  EXPECT_FALSE(Atmosphere::make(std::nan(""), 10.0, 0.5, RefractionModel::Radio).ok());
}

TEST(RefractionModelName, ParsesAndPrints) {
  for (auto m : {RefractionModel::None, RefractionModel::Optical, RefractionModel::Radio}) {
    auto parsed = parse_refraction_model(to_string(m));
    ASSERT_TRUE(parsed.ok());
    EXPECT_EQ(*parsed, m);
  }
  auto bad = parse_refraction_model("bennett");
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().message.find("bennett"), std::string::npos);
}

}  // namespace
}  // namespace azt::astro
