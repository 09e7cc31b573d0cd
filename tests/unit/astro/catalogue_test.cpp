#include "azt/astro/catalogue.hpp"

#include <gtest/gtest.h>

#include <string>

#include "azt/astro/bands.hpp"

namespace azt::astro {
namespace {

TEST(Catalogue, SeedButtonsResolveToTheirRadioSources) {
  // Seed 000: "track by predefine touch buttons Sun, Moon, Sagittarius, Cassiopeia, Taurus, Leo
  // and Pictor". Leo has no strong source; it means Virgo A (documented in catalogue.cpp).
  const std::pair<const char*, const char*> buttons[] = {{"Sagittarius", "sgra"},
                                                         {"Cassiopeia", "casa"},
                                                         {"Taurus", "taua"},
                                                         {"Leo", "vira"},
                                                         {"Pictor", "pica"}};
  for (const auto& [button, key] : buttons) {
    const RadioSource* s = find_radio_source(button);
    ASSERT_NE(s, nullptr) << button;
    EXPECT_EQ(s->key, key) << button;
  }
}

TEST(Catalogue, NamesAliasesAndSpellings) {
  EXPECT_EQ(find_radio_source("Sgr A*")->key, "sgra");
  EXPECT_EQ(find_radio_source("CYG_A")->key, "cyga");
  EXPECT_EQ(find_radio_source("3C 461")->key, "casa");
  EXPECT_EQ(find_radio_source("crab")->key, "taua");
  EXPECT_EQ(find_radio_source("M87")->key, "vira");
  EXPECT_EQ(find_radio_source("orion a")->key, "oria");
  EXPECT_EQ(find_radio_source("jupiter"), nullptr);
  EXPECT_EQ(find_radio_source(""), nullptr);
  EXPECT_EQ(find_radio_source("  "), nullptr);
}

TEST(Catalogue, CalibrationSourcesOfTheReferenceStudyArePresent) {
  // ../shared/reference/astronomy-and-eme.md §5 table.
  for (const char* key :
       {"casa", "cyga", "taua", "vira", "sgra", "pica", "hyda", "hera", "oria", "m17", "cena"}) {
    EXPECT_NE(find_radio_source(key), nullptr) << key;
  }
}

TEST(Catalogue, PositionsAsPublished) {
  // Cas A 23h23m24.0s +58°48′54″ (§5 table) = 350.85°, +58.815°.
  const RadioSource* cas = find_radio_source("casa");
  EXPECT_NEAR(cas->ra_deg, 350.85, 1e-9);
  EXPECT_NEAR(cas->dec_deg, 58.815, 1e-9);
  // Sgr A* 17h45m40.0409s −29°00′28.118″: the sign applies to the whole sexagesimal value.
  const RadioSource* sgr = find_radio_source("sgra");
  EXPECT_NEAR(sgr->ra_deg, 266.41683708, 1e-7);
  EXPECT_NEAR(sgr->dec_deg, -29.00781056, 1e-7);
}

TEST(Catalogue, EntriesAreWellFormed) {
  for (const auto& s : radio_sources()) {
    EXPECT_GE(s.ra_deg, 0.0) << s.key;
    EXPECT_LT(s.ra_deg, 360.0) << s.key;
    EXPECT_LE(std::abs(s.dec_deg), 90.0) << s.key;
    EXPECT_FALSE(s.position_ref.empty()) << s.key;
    EXPECT_EQ(find_radio_source(s.key), &s) << s.key;
    EXPECT_EQ(find_radio_source(s.name), &s) << s.key;
    if (s.flux_1296_jy) {
      EXPECT_FALSE(s.flux_ref.empty()) << s.key;
      // Synchrotron sources fade with frequency.
      EXPECT_GT(*s.flux_1296_jy, *s.flux_2304_jy) << s.key;
      EXPECT_GT(*s.flux_2304_jy, *s.flux_10368_jy) << s.key;
    }
  }
}

TEST(Bands, CoverSixMetresToFourMillimetres) {
  const auto bands = eme_bands();
  ASSERT_GE(bands.size(), 14u);
  EXPECT_NEAR(bands.front().freq_mhz, 50.19, 0.5);
  EXPECT_NEAR(bands.back().freq_mhz, 76032.1, 1.0);
  for (std::size_t i = 1; i < bands.size(); ++i)
    EXPECT_GT(bands[i].freq_mhz, bands[i - 1].freq_mhz);
  EXPECT_EQ(find_band("10g"), find_band("10368"));
  EXPECT_EQ(find_band("2M"), find_band("144"));
  EXPECT_EQ(find_band("47088")->freq_mhz, 47088.1);
  EXPECT_EQ(find_band("11g"), nullptr);
}

// The console shows each band by its wavelength (from /api/targets); an operator may type it.
TEST(Bands, EachWavelengthNamesItsBand) {
  for (const AmateurBand& b : eme_bands()) {
    ASSERT_FALSE(b.wavelength.empty()) << b.name;
    std::string typed(b.wavelength);
    std::erase(typed, ' ');
    const AmateurBand* found = find_band(typed);
    ASSERT_NE(found, nullptr) << typed;
    EXPECT_EQ(found->name, b.name) << typed;
    // The wavelength is c / f to within the band names' rounding (1.25 m is 240 MHz, 6 mm 50 GHz).
    const double metres = 299.792458 / b.freq_mhz;
    const double named = std::stod(typed) * (typed.ends_with("cm")   ? 0.01
                                             : typed.ends_with("mm") ? 0.001
                                                                     : 1.0);
    EXPECT_NEAR(named / metres, 1.0, 0.2) << typed;
  }
}

}  // namespace
}  // namespace azt::astro
