// The station's radio cycle (radio/rig_doppler_cycle.hpp) against rigctl sessions fed by hand:
// what goes to the rig for EME and for a satellite, when, and what the state says was written.
#include "radio/rig_doppler_cycle.hpp"

#include <gtest/gtest.h>

#include <string>

namespace azt::app {
namespace {

using radio::RigctlSession;

/// A session after `\chk_vfo` answered 0 (plain mode).
void connect(RigctlSession& s) {
  s.connected();
  ASSERT_EQ(s.next_line(0.0), "\\chk_vfo\n");
  s.on_line("0");
}

/// Answers every queued line as the dummy rig would; returns what was sent.
std::string answer_all(RigctlSession& s, RigDopplerCycle& cycle, RigRole role, double& rig_hz,
                       double& split_hz) {
  std::string sent;
  while (auto line = s.next_line(0.0)) {
    sent += *line;
    const char c = line->front();
    std::string reply = "RPRT 0";
    if (c == 'F') rig_hz = std::stod(line->substr(2));
    if (c == 'I') split_hz = std::stod(line->substr(2));
    if (c == 'f') reply = std::to_string(static_cast<long long>(rig_hz));
    if (c == 'i') reply = std::to_string(static_cast<long long>(split_hz));
    if (auto e = s.on_line(reply)) cycle.on_event(role, *e, 0.0);
  }
  return sent;
}

RadioInputs eme_at(double unix_s, double self_hz) {
  RadioInputs in;
  in.now_s = unix_s;
  in.unix_s = unix_s;
  in.echo_at = [self_hz](double) { return radio::EchoDoppler{self_hz, std::nullopt}; };
  return in;
}

TEST(RigDopplerCycle, EmeOwnEchoWritesDialPlusEchoAndSaysWhen) {
  RadioConfig config;
  config.doppler = DopplerSource::Eme;
  config.eme_mode = radio::EmeDopplerMode::OwnEcho;
  config.dial_mhz = 1296.1;
  RigctlSession rig;
  connect(rig);
  RigDopplerCycle cycle(config, rig, nullptr);
  double rig_hz = 0.0;
  double split_hz = 0.0;
  cycle.run(eme_at(1000.0, 1178.4));
  const std::string sent = answer_all(rig, cycle, RigRole::Main, rig_hz, split_hz);
  EXPECT_NE(sent.find("F 1296101178\n"), std::string::npos) << sent;
  EXPECT_NE(sent.find("I 1296100000\n"), std::string::npos) << sent;  // own echo: TX on dial
  ASSERT_TRUE(cycle.rx());
  EXPECT_DOUBLE_EQ(cycle.rx()->hz, 1296101178.0);
  EXPECT_DOUBLE_EQ(cycle.rx()->at_unix_s, 1000.0);
  EXPECT_NEAR(cycle.rx()->correction_hz, 1178.4, 1e-9);
  EXPECT_EQ(cycle.to_json()["doppler"], "eme");

  // The same whole Hz: nothing written; a new whole Hz: written.
  cycle.run(eme_at(1000.2, 1178.3));
  EXPECT_EQ(answer_all(rig, cycle, RigRole::Main, rig_hz, split_hz), "");
  cycle.run(eme_at(1000.4, 1179.2));
  EXPECT_NE(answer_all(rig, cycle, RigRole::Main, rig_hz, split_hz).find("F 1296101179\n"),
            std::string::npos);
}

TEST(RigDopplerCycle, FullDxWithoutDxGridSaysSoAndWritesNothing) {
  RadioConfig config;
  config.doppler = DopplerSource::Eme;
  config.eme_mode = radio::EmeDopplerMode::FullDx;
  config.dial_mhz = 1296.1;
  RigctlSession rig;
  connect(rig);
  RigDopplerCycle cycle(config, rig, nullptr);
  cycle.run(eme_at(1000.0, 1178.4));
  EXPECT_FALSE(rig.next_line(0.0));
  EXPECT_FALSE(cycle.problem().empty());
}

TEST(RigDopplerCycle, NoTxQsyWritesTheTxOncePerPeriodAndNeverWhileTransmitting) {
  RadioConfig config;
  config.doppler = DopplerSource::Eme;
  config.eme_mode = radio::EmeDopplerMode::ConstantOnMoon;
  config.dial_mhz = 1296.1;
  config.no_tx_qsy = true;
  RigctlSession rig;
  connect(rig);
  RigDopplerCycle cycle(config, rig, nullptr);
  double rig_hz = 0.0;
  double split_hz = 0.0;
  RadioInputs in = eme_at(6000.0, 1000.0);
  in.tr_period_s = 60.0;
  in.transmitting = true;
  cycle.run(in);
  EXPECT_EQ(answer_all(rig, cycle, RigRole::Main, rig_hz, split_hz).find("I "), std::string::npos);
  in.transmitting = false;
  cycle.run(in);
  EXPECT_NE(answer_all(rig, cycle, RigRole::Main, rig_hz, split_hz).find("I 1296099500\n"),
            std::string::npos);
  in.unix_s += 10.0;  // the same period: nothing more
  in.echo_at = [](double) { return radio::EchoDoppler{1200.0, std::nullopt}; };
  cycle.run(in);
  EXPECT_EQ(answer_all(rig, cycle, RigRole::Main, rig_hz, split_hz).find("I "), std::string::npos);
}

TEST(RigDopplerCycle, SatelliteFmCorrectsBothLegsAndNeedsItsTransmitter) {
  RadioConfig config;
  config.doppler = DopplerSource::Satellite;
  TransmitterConfig so50;
  so50.norad = "27607";
  so50.transmitter.downlink_hz = 436.795e6;
  so50.transmitter.uplink_hz = 145.850e6;
  config.transmitters.push_back(so50);
  RigctlSession rig;
  connect(rig);
  RigDopplerCycle cycle(config, rig, nullptr);
  double rig_hz = 0.0;
  double split_hz = 0.0;
  RadioInputs in;
  in.now_s = 5.0;
  in.unix_s = 2000.0;
  in.satellite = SatelliteNow{"99999", -5.0};
  cycle.run(in);
  EXPECT_NE(cycle.problem().find("99999"), std::string::npos);
  EXPECT_FALSE(rig.next_line(0.0));

  in.satellite = SatelliteNow{"27607", -5.0};  // approaching: heard higher, sent lower
  cycle.run(in);
  answer_all(rig, cycle, RigRole::Main, rig_hz, split_hz);
  EXPECT_NEAR(rig_hz, 436.795e6 * (1.0 + 5.0 / radio::kSpeedOfLightKmS), 1.0);
  EXPECT_NEAR(split_hz, 145.850e6 * (1.0 - 5.0 / radio::kSpeedOfLightKmS), 1.0);
  ASSERT_TRUE(cycle.tx());
  EXPECT_NEAR(cycle.tx()->correction_hz, -145.850e6 * 5.0 / radio::kSpeedOfLightKmS, 1.0);
  EXPECT_TRUE(cycle.problem().empty());
}

TEST(RigDopplerCycle, ASecondRigCarriesTheUplinkOnItsMainVfo) {
  RadioConfig config;
  config.doppler = DopplerSource::Eme;
  config.eme_mode = radio::EmeDopplerMode::CallDx;
  config.dial_mhz = 1296.1;
  RigctlSession rx_rig;
  RigctlSession tx_rig;
  connect(rx_rig);
  connect(tx_rig);
  RigDopplerCycle cycle(config, rx_rig, &tx_rig);
  double rx_hz = 0.0;
  double tx_hz = 0.0;
  double unused = 0.0;
  cycle.run(eme_at(1000.0, 1000.0));
  answer_all(rx_rig, cycle, RigRole::Main, rx_hz, unused);
  const std::string sent = answer_all(tx_rig, cycle, RigRole::Uplink, tx_hz, unused);
  EXPECT_NE(sent.find("F 1296099000\n"), std::string::npos) << sent;  // call DX: TX −self
  ASSERT_TRUE(cycle.tx());
  EXPECT_DOUBLE_EQ(cycle.tx()->hz, 1296099000.0);
}

TEST(RigDopplerCycle, OffWritesNothing) {
  RadioConfig config;
  RigctlSession rig;
  connect(rig);
  RigDopplerCycle cycle(config, rig, nullptr);
  cycle.run(eme_at(1000.0, 1000.0));
  EXPECT_FALSE(rig.next_line(0.0));
  EXPECT_EQ(cycle.to_json()["rx_hz"], nullptr);
}

}  // namespace
}  // namespace azt::app
