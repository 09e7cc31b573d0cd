// [radio], [[satellites.transmitter]] and [wsjtx] (docs/radio.md): the defaults write to no rig
// and listen to nothing; every key is read; bad values are refused by name.
#include "config/radio_config.hpp"

#include <gtest/gtest.h>

#include <string>

#include "common/usage_error.hpp"
#include "config/config_file.hpp"
#include "config/wsjtx_config.hpp"

namespace azt::app {
namespace {

RadioConfig from(const std::string& text) {
  return radio_config_from(ConfigFile::parse(text, "test.toml"));
}

std::string refusal(const std::string& text) {
  try {
    from(text);
    wsjtx_config_from(ConfigFile::parse(text, "test.toml"));
  } catch (const UsageError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(RadioConfig, DefaultsWriteToNoRigAndListenToNothing) {
  const RadioConfig c = from("");
  EXPECT_FALSE(c.rigctld);
  EXPECT_FALSE(c.tx_rigctld);
  EXPECT_EQ(c.doppler, DopplerSource::Off);
  EXPECT_DOUBLE_EQ(c.step_hz, 10.0);
  EXPECT_FALSE(c.no_tx_qsy);
  EXPECT_TRUE(c.transmitters.empty());
  const WsjtxConfig w = wsjtx_config_from(ConfigFile::parse("", "test.toml"));
  EXPECT_FALSE(w.listen);
  EXPECT_TRUE(w.follow_dx_grid);
  EXPECT_TRUE(w.hold_motion_while_transmitting);
  EXPECT_DOUBLE_EQ(w.move_in_last_s, 0.0);
}

TEST(RadioConfig, EveryKeyIsRead) {
  const RadioConfig c = from(
      "[radio]\nrigctld = \"127.0.0.1:4532\"\ntx_rigctld = \"[::1]:4534\"\ndoppler = \"eme\"\n"
      "eme_mode = \"on_dx\"\ndial_mhz = 10368.1\nstep_hz = 20\nno_tx_qsy = true\n"
      "[satellites]\n[[satellites.transmitter]]\nnorad = \"43017\"\ndownlink_mhz = 145.96\n"
      "uplink_mhz = 435.65\nmode = \"linear_inverting\"\n[[satellites.transmitter]]\n"
      "norad = \"25544\"\ndownlink_mhz = 437.8\n");
  ASSERT_TRUE(c.rigctld);
  EXPECT_EQ(c.rigctld->host, "127.0.0.1");
  EXPECT_EQ(c.rigctld->port, 4532);
  ASSERT_TRUE(c.tx_rigctld);
  EXPECT_EQ(c.tx_rigctld->host, "::1");
  EXPECT_EQ(c.tx_rigctld->text(), "[::1]:4534");
  EXPECT_EQ(c.doppler, DopplerSource::Eme);
  EXPECT_EQ(c.eme_mode, radio::EmeDopplerMode::OnDxEcho);
  EXPECT_DOUBLE_EQ(c.dial_mhz, 10368.1);
  EXPECT_DOUBLE_EQ(c.step_hz, 20.0);
  EXPECT_TRUE(c.no_tx_qsy);
  ASSERT_EQ(c.transmitters.size(), 2U);
  const TransmitterConfig* ao = c.transmitter_of("43017");
  ASSERT_NE(ao, nullptr);
  EXPECT_DOUBLE_EQ(ao->transmitter.downlink_hz, 145.96e6);
  EXPECT_DOUBLE_EQ(*ao->transmitter.uplink_hz, 435.65e6);
  EXPECT_EQ(ao->transmitter.mode, radio::TransponderMode::LinearInverting);
  const TransmitterConfig* iss = c.transmitter_of("25544");
  ASSERT_NE(iss, nullptr);
  EXPECT_FALSE(iss->transmitter.uplink_hz);  // receive only
  EXPECT_EQ(iss->transmitter.mode, radio::TransponderMode::Fm);
  EXPECT_EQ(c.transmitter_of("1"), nullptr);

  const WsjtxConfig w = wsjtx_config_from(
      ConfigFile::parse("[wsjtx]\nlisten = \"224.0.0.1:2237\"\nfollow_dx_grid = false\n"
                        "hold_motion_while_transmitting = false\nmove_in_last_s = 5\n",
                        "test.toml"));
  ASSERT_TRUE(w.listen);
  EXPECT_EQ(w.listen->text(), "224.0.0.1:2237");
  EXPECT_FALSE(w.follow_dx_grid);
  EXPECT_FALSE(w.hold_motion_while_transmitting);
  EXPECT_DOUBLE_EQ(w.move_in_last_s, 5.0);
}

TEST(RadioConfig, BadValuesAreRefusedByName) {
  EXPECT_NE(refusal("[radio]\nrigctld = \"localhost\"\n").find("[radio].rigctld"),
            std::string::npos);
  EXPECT_NE(refusal("[radio]\nrigctld = \"h:0\"\n").find("[radio].rigctld"), std::string::npos);
  EXPECT_NE(refusal("[radio]\ndoppler = \"eme\"\ndial_mhz = 1296\n").find("[radio].rigctld"),
            std::string::npos);
  EXPECT_NE(refusal("[radio]\nrigctld = \"h:4532\"\ndoppler = \"eme\"\n").find("dial_mhz"),
            std::string::npos);
  EXPECT_NE(refusal("[radio]\ndoppler = \"gpredict\"\n").find("doppler"), std::string::npos);
  EXPECT_NE(refusal("[radio]\neme_mode = \"both\"\n").find("eme_mode"), std::string::npos);
  EXPECT_NE(refusal("[[satellites.transmitter]]\ndownlink_mhz = 145.9\n").find("norad"),
            std::string::npos);
  EXPECT_NE(refusal("[[satellites.transmitter]]\nnorad = \"1\"\ndownlink_mhz = 145.9\n"
                    "mode = \"linear\"\n")
                .find("uplink_mhz"),
            std::string::npos);
  EXPECT_NE(refusal("[[satellites.transmitter]]\nnorad = \"1\"\ndownlink_mhz = 1\nshift = 2\n")
                .find("shift"),
            std::string::npos);
  EXPECT_NE(refusal("[wsjtx]\nlisten = \"2237\"\n").find("[wsjtx].listen"), std::string::npos);
}

}  // namespace
}  // namespace azt::app
