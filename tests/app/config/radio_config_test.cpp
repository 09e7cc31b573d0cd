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

TEST(RadioConfig, ARigThroughLibhamlibIsReadWithItsPortAndSpeed) {
  const RadioConfig dummy = from("[radio]\nmodel = 1\ndoppler = \"eme\"\ndial_mhz = 1296.1\n");
  EXPECT_FALSE(dummy.rigctld);
  ASSERT_TRUE(dummy.hamlib);
  EXPECT_EQ(dummy.hamlib->model, 1);
  EXPECT_EQ(dummy.hamlib->device, "");
  EXPECT_EQ(dummy.hamlib->baud, 0);
  EXPECT_TRUE(dummy.has_rig());
  EXPECT_FALSE(dummy.tx_hamlib);

  const RadioConfig pair = from(
      "[radio]\nmodel = 1020\ndevice = \"/dev/ttyUSB0\"\nbaud = 38400\n"
      "tx_model = 1041\ntx_device = \"/dev/ttyUSB1\"\n");
  ASSERT_TRUE(pair.hamlib);
  EXPECT_EQ(pair.hamlib->model, 1020);
  EXPECT_EQ(pair.hamlib->device, "/dev/ttyUSB0");
  EXPECT_EQ(pair.hamlib->baud, 38400);
  ASSERT_TRUE(pair.tx_hamlib);
  EXPECT_EQ(pair.tx_hamlib->model, 1041);
  EXPECT_EQ(pair.tx_hamlib->device, "/dev/ttyUSB1");

  // Either way for each rig: the rig through rigctld, the uplink's directly.
  const RadioConfig mixed = from("[radio]\nrigctld = \"h:4532\"\ntx_model = 1\n");
  EXPECT_TRUE(mixed.rigctld);
  EXPECT_FALSE(mixed.hamlib);
  EXPECT_TRUE(mixed.tx_hamlib);
}

TEST(RadioConfig, ADirectRigIsCheckedAgainstHamlibWhenLoaded) {
  const std::string unknown = refusal("[radio]\nmodel = 99999\n");
  EXPECT_NE(unknown.find("[radio].model"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("Hamlib has no rig model 99999"), std::string::npos) << unknown;
  const std::string both = refusal("[radio]\nrigctld = \"h:4532\"\nmodel = 1\n");
  EXPECT_NE(both.find("both name the rig"), std::string::npos) << both;
  EXPECT_NE(refusal("[radio]\ntx_rigctld = \"h:4534\"\nmodel = 1\ntx_model = 1\n")
                .find("[radio].tx_model"),
            std::string::npos);
  EXPECT_NE(refusal("[radio]\ndevice = \"/dev/ttyUSB0\"\n").find("needs model"), std::string::npos);
  EXPECT_NE(refusal("[radio]\nmodel = 1\ntx_baud = 9600\n").find("needs tx_model"),
            std::string::npos);
  const std::string not_serial = refusal("[radio]\nmodel = 1\nbaud = 9600\n");
  EXPECT_NE(not_serial.find("model 1 (Hamlib Dummy) is not a serial rig"), std::string::npos)
      << not_serial;
  // Faster than Hamlib's caps say (4800 to 38400 for the IC-9700) is the rig's business: its
  // USB CI-V runs at 115200, and Hamlib itself opens it so.
  EXPECT_EQ(refusal("[radio]\nmodel = 3081\nbaud = 115200\n"), "accepted");
  EXPECT_NE(refusal("[radio]\nmodel = 1020\ndevice = \"/dev/ttyS0\"\ntx_model = 1020\n"
                    "tx_device = \"/dev/ttyS0\"\n")
                .find("[radio].tx_device"),
            std::string::npos);
  EXPECT_NE(refusal("[radio]\ntx_model = 1\n").find("no rig"), std::string::npos);
  EXPECT_NE(refusal("[radio]\nmodel = -1\n").find("[radio].model"), std::string::npos);
  const std::string no_rig = refusal("[radio]\ndoppler = \"satellite\"\n");
  EXPECT_NE(no_rig.find("model = N"), std::string::npos) << no_rig;
}

}  // namespace
}  // namespace azt::app
