// Which saved settings wait for a restart (restart_needed.hpp): the keys applied at the next start
// whose effective value changed, never the ones the console applies at once, never secrets.
#include "console/restart_needed.hpp"

#include <gtest/gtest.h>

namespace azt::app {
namespace {

using Keys = std::vector<std::string>;

Keys between(const std::string& started, const std::string& saved) {
  return restart_needed(toml::parse(started), toml::parse(saved));
}

TEST(RestartNeeded, NothingWhenNothingChanged) {
  const std::string file = "[control]\nwindow_deg = 0.1\n[[serial]]\nprotocol = \"spid\"\n";
  EXPECT_EQ(between(file, file), Keys{});
}

TEST(RestartNeeded, ListsChangedRestartKeysByTheirDottedNames) {
  EXPECT_EQ(between("[control]\nwindow_deg = 0.1\n", "[control]\nwindow_deg = 0.2\n"),
            Keys{"control.window_deg"});
  EXPECT_EQ(between("", "[mount.az]\nencoder_bits = 14\n[log]\nlevel = \"debug\"\n"),
            (Keys{"mount.az.encoder_bits", "log.level"}));
  EXPECT_EQ(between("[[serial]]\nbaud = 9600\n", "[[serial]]\nbaud = 1200\n[[serial]]\n"),
            Keys{"serial.1.baud"});
  EXPECT_EQ(between("", "[[serial]]\nprotocol = \"spid\"\ndevice = \"pty:x\"\n"),
            (Keys{"serial.1.protocol", "serial.1.device"}));
}

TEST(RestartNeeded, ItemsOfAnArrayOfTablesInsideATableAreCompared) {
  const std::string one = "[[satellites.transmitter]]\nnorad = \"25544\"\ndownlink_mhz = 437.8\n";
  EXPECT_EQ(between(one, one), Keys{});
  EXPECT_EQ(between(one, "[[satellites.transmitter]]\nnorad = \"25544\"\ndownlink_mhz = 437.9\n"),
            Keys{"satellites.transmitter.1.downlink_mhz"});
  EXPECT_EQ(between("", one),
            (Keys{"satellites.transmitter.1.norad", "satellites.transmitter.1.downlink_mhz"}));
}

TEST(RestartNeeded, AnAbsentKeyIsItsDefault) {
  EXPECT_EQ(between("", "[control]\nwindow_deg = 0.0\ntick_hz = 20.0\n"), Keys{});
  EXPECT_EQ(between("[control]\ntick_hz = 20\n", ""), Keys{});
  EXPECT_EQ(between("[control]\nramp_s = 2\n", "[control]\nramp_s = 2.0\n"), Keys{});
  EXPECT_EQ(between("[control]\nramp_s = 2.0\n", ""), Keys{"control.ramp_s"});
}

TEST(RestartNeeded, LiveKeysAndSecretsAreNeverListed) {
  EXPECT_EQ(between("[station]\ngrid = \"FN06\"\n[sky]\nband = \"144\"\n",
                    "[station]\ngrid = \"JO65\"\n[sky]\nband = \"432\"\n[[park]]\nname = \"x\"\n"
                    "[web]\npassword_hash = \"$argon2id$new\"\n"),
            Keys{});
}

}  // namespace
}  // namespace azt::app
