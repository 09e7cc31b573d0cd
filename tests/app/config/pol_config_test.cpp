// [pol], [mount.pol] and [sim.pol] (docs/eme.md, "Polarisation axis"): without [mount.pol] the
// station has no pol axis; every key is read into the controller's and the plant's settings; bad
// values are refused by name.
#include "config/pol_config.hpp"

#include <gtest/gtest.h>

#include <string>

#include "common/usage_error.hpp"
#include "config/config_file.hpp"
#include "config/sim_config.hpp"

namespace azt::app {
namespace {

const std::string kStation = "[station]\ngrid = \"FN06\"\n";

SimConfig sim_from(const std::string& text) {
  return sim_config_from(ConfigFile::parse(kStation + text, "test.toml"));
}

std::string refusal(const std::string& text) {
  try {
    sim_from(text);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(PolConfig, WithoutMountPolThereIsNoPolAxisAndTheModeIsOff) {
  const SimConfig c = sim_from("");
  EXPECT_FALSE(c.mount.pol.has_value());
  EXPECT_FALSE(c.setup.station.pol.has_value());
  EXPECT_FALSE(c.setup.plant.pol.has_value());
  EXPECT_EQ(c.pol.mode, control::PolMode::Off);
  EXPECT_FALSE(c.pol.hold_while_keyed);
}

TEST(PolConfig, EveryKeyIsRead) {
  const SimConfig c = sim_from(
      "[mount.pol]\nmax_rate_deg_s = 3.0\nencoder_bits = 10\nmin_deg = -100.0\nmax_deg = 100.0\n"
      "window_deg = 0.3\n[sim.pol]\nbacklash_deg = 0.2\nstart_deg = 20.0\n"
      "[pol]\nmode = \"split\"\nfixed_deg = 10.0\nself_offset_deg = -5.0\ndx_offset_deg = 12.0\n"
      "hold_while_keyed = true\n");
  ASSERT_TRUE(c.setup.station.pol.has_value());
  const control::PolAxisConfig& axis = *c.setup.station.pol;
  EXPECT_DOUBLE_EQ(axis.control.max_rate_deg_s, 3.0);
  EXPECT_DOUBLE_EQ(axis.control.window_deg, 0.3);
  EXPECT_DOUBLE_EQ(axis.control.lsb_deg, 360.0 / 1024);
  EXPECT_DOUBLE_EQ(axis.supervisor.max_rate_deg_s, 3.0);
  EXPECT_DOUBLE_EQ(axis.travel.min_deg, -100.0);
  EXPECT_DOUBLE_EQ(axis.travel.max_deg, 100.0);
  ASSERT_TRUE(c.setup.plant.pol.has_value());
  EXPECT_DOUBLE_EQ(c.setup.plant.pol->max_rate_deg_s, 3.0);  // the mount's, never its own
  EXPECT_DOUBLE_EQ(c.setup.plant.pol->backlash_deg, 0.2);
  EXPECT_DOUBLE_EQ(c.setup.plant.pol->start_deg, 20.0);
  EXPECT_DOUBLE_EQ(c.setup.plant.pol->min_deg, -100.0);  // the travel's stops by default
  EXPECT_EQ(c.pol.mode, control::PolMode::Split);
  EXPECT_DOUBLE_EQ(c.pol.fixed_deg, 10.0);
  EXPECT_DOUBLE_EQ(c.pol.self_offset_deg, -5.0);
  EXPECT_DOUBLE_EQ(c.pol.dx_offset_deg, 12.0);
  EXPECT_TRUE(c.pol.hold_while_keyed);
}

TEST(PolConfig, BadValuesAreRefusedByName) {
  EXPECT_NE(refusal("[pol]\nmode = \"circular\"\n").find("[pol].mode must be"), std::string::npos);
  EXPECT_NE(refusal("[mount.pol]\nmin_deg = -80.0\nmax_deg = 80.0\n")
                .find("[mount.pol].min_deg the polarisation travel"),
            std::string::npos);
  EXPECT_NE(refusal("[sim.pol]\nbacklash_deg = 0.1\n").find("[sim.pol] models the axis of"),
            std::string::npos);
  EXPECT_NE(refusal("[mount.pol]\n[sim.pol]\nstart_deg = 120.0\n").find("[sim.pol].start_deg"),
            std::string::npos);
}

}  // namespace
}  // namespace azt::app
