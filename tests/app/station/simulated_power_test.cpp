// `[receiver] source = "sim"` (docs/calibration.md): the daemon's simulated receiver hears the Sun
// through the simulated mount's true beam, so the power peaks where the mount's errors put the beam
// on the Sun, not where the shafts point; it is refused on any backend but `sim`.
#include "station/simulated_power.hpp"

#include <gtest/gtest.h>

#include <optional>
#include <string>

#include "azt/astro/erfa_ephemeris.hpp"
#include "common/sky_report.hpp"
#include "common/usage_error.hpp"
#include "config/config_file.hpp"
#include "config/daemon_config.hpp"

namespace azt::app {
namespace {

constexpr double kNoonUnixS = 1750075200.0;  // 2025-06-16 12:00 UTC: the Sun high over FN06

class SimulatedPowerTest : public ::testing::Test {
 protected:
  SimulatedPowerTest() {
    settings_.observer = astro::Observer{46.18958, -79.39375, 301.0};
    errors_.ia_deg = 0.4;
    errors_.ie_deg = -0.25;
  }

  SimulatedPower make() {
    SimulatedPowerParts p;
    p.receiver.receiver.noise_db = 0.0;
    p.mount_errors = errors_;
    p.sky_at = [this](double unix_s) {
      return sky_snapshot(ephemeris_, settings_, astro::UtcInstant::from_unix_seconds(unix_s));
    };
    p.shafts_deg = [this] { return shafts_; };
    return SimulatedPower(std::move(p));
  }

  control::AzEl sun_at(double unix_s) const {
    const auto sky =
        sky_snapshot(ephemeris_, settings_, astro::UtcInstant::from_unix_seconds(unix_s));
    const auto r = sky->observe(astro::Target::sun());
    return {r->observation.place.az_deg, r->observation.el_deg};
  }

  astro::ErfaEphemeris ephemeris_;
  SkySettings settings_;
  calibration::PointingTerms errors_;
  std::optional<control::AzEl> shafts_;
};

TEST_F(SimulatedPowerTest, ThePowerPeaksWhereTheTrueBeamIsOnTheSun) {
  SimulatedPower power = make();
  const control::AzEl sun = sun_at(kNoonUnixS);
  EXPECT_FALSE(power.expected_db(kNoonUnixS).has_value()) << "no shafts known: no reading";
  // Where the beam is on the Sun, through the mount's errors, and where the shafts point at it.
  shafts_ = calibration::mount_for_sky(sun, errors_).value();
  const double on = *power.expected_db(kNoonUnixS);
  shafts_ = sun;
  const double naive = *power.expected_db(kNoonUnixS);
  shafts_ = control::AzEl{sun.az_deg + 5.0, sun.el_deg};
  const double off = *power.expected_db(kNoonUnixS);
  EXPECT_GT(on, 20.0) << "the quiet Sun in a 1.6° beam: some 25 dB over the system noise";
  EXPECT_GT(on, naive + 0.5) << "0.47° off with the shafts on the Sun";
  EXPECT_LT(off, 1.0) << "five degrees away: cold sky";
}

TEST_F(SimulatedPowerTest, BetweenWholeSecondsTheSunIsInterpolated) {
  SimulatedPower power = make();
  // Half a second on, the beam held where the Sun is then: as bright as on it at a whole second.
  const control::AzEl mid = sun_at(kNoonUnixS + 0.5);
  shafts_ = calibration::mount_for_sky(mid, errors_).value();
  const double at_mid = *power.expected_db(kNoonUnixS + 0.5);
  shafts_ = calibration::mount_for_sky(sun_at(kNoonUnixS + 1.0), errors_).value();
  EXPECT_NEAR(at_mid, *power.expected_db(kNoonUnixS + 1.0), 0.001);
}

TEST(SimulatedReceiverConfig, IsRefusedOnAnyBackendButSim) {
  const std::string text =
      "[station]\ngrid = \"FN06HE\"\n[antenna]\nbackend = \"hamlib\"\n"
      "[hamlib]\nmodel = 1\n[receiver]\nsource = \"sim\"\n";
  try {
    (void)daemon_config_from(ConfigFile::parse(text, "hamlib.toml"));
    FAIL() << "accepted";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("source"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("backend"), std::string::npos) << e.what();
  }
  const std::string sim = "[station]\ngrid = \"FN06HE\"\n[receiver]\nsource = \"sim\"\n";
  EXPECT_EQ(daemon_config_from(ConfigFile::parse(sim, "sim.toml")).receiver.source,
            ReceiverConfig::Source::Sim);
}

}  // namespace
}  // namespace azt::app
