// The station's radio cycle (radio/rig_doppler_cycle.hpp) against rigctl sessions fed by hand:
// what goes to the rig for EME and for a satellite, when, and what the state says was written.
#include "radio/rig_doppler_cycle.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>

#include "azt/astro/time_scales.hpp"
#include "azt/radio/rigctl_session.hpp"

namespace azt::app {
namespace {

using radio::RigctlSession;

constexpr double kLightKmS = 299792.458;

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
  EXPECT_EQ(cycle.to_json()["eme_mode"], "self");
  EXPECT_TRUE(cycle.to_json()["transmitter"].is_null());

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
  EXPECT_NEAR(rig_hz, 436.795e6 / (1.0 - 5.0 / kLightKmS), 1.0);
  EXPECT_NEAR(split_hz, 145.850e6 / (1.0 + 5.0 / kLightKmS), 1.0);
  ASSERT_TRUE(cycle.tx());
  EXPECT_NEAR(cycle.tx()->correction_hz, 145.850e6 / (1.0 + 5.0 / kLightKmS) - 145.850e6, 1.0);
  EXPECT_TRUE(cycle.problem().empty());
}

TEST(RigDopplerCycle, TheStateNamesTheRigsTheModeAndTheTransmitterFollowed) {
  RadioConfig config;
  config.doppler = DopplerSource::Satellite;
  config.rigctld = HostPort{"127.0.0.1", 4532};
  config.tx_rigctld = HostPort{"::1", 4534};
  config.transmitters.push_back({"43017", {145.96e6, 435.65e6, radio::TransponderMode::Linear}});
  config.transmitters.push_back({"27607", {436.795e6, std::nullopt, radio::TransponderMode::Fm}});
  RigctlSession rig;
  RigDopplerCycle cycle(config, rig, nullptr);
  nlohmann::json j = cycle.to_json();
  EXPECT_EQ(j["rigctld"], "127.0.0.1:4532");
  EXPECT_EQ(j["tx_rigctld"], "[::1]:4534");
  EXPECT_TRUE(j["eme_mode"].is_null()) << "no EME mode while the Doppler is the satellite's";
  EXPECT_TRUE(j["transmitter"].is_null()) << "nothing tracked yet";
  RadioInputs in;
  in.satellite = SatelliteNow{"27607", 1.0};
  cycle.run(in);
  j = cycle.to_json()["transmitter"];
  EXPECT_EQ(j["norad"], "27607");
  EXPECT_DOUBLE_EQ(j["downlink_mhz"].get<double>(), 436.795);
  EXPECT_TRUE(j["uplink_mhz"].is_null()) << "receive only";
  EXPECT_EQ(j["mode"], "fm");
  in.satellite = SatelliteNow{"43017", 1.0};
  cycle.run(in);
  EXPECT_EQ(cycle.to_json()["transmitter"]["mode"], "linear");
  EXPECT_DOUBLE_EQ(cycle.to_json()["transmitter"]["uplink_mhz"].get<double>(), 435.65);
  in.satellite = SatelliteNow{"99999", 1.0};  // no transmitter for it: none followed
  cycle.run(in);
  EXPECT_TRUE(cycle.to_json()["transmitter"].is_null());
  in.satellite.reset();
  cycle.run(in);
  EXPECT_TRUE(cycle.to_json()["transmitter"].is_null());
}

RadioConfig inverting_transponder() {
  RadioConfig config;
  config.doppler = DopplerSource::Satellite;
  TransmitterConfig fo29;
  fo29.norad = "24278";
  fo29.transmitter = {435.850e6, 145.950e6, radio::TransponderMode::LinearInverting};
  config.transmitters.push_back(fo29);
  return config;
}

/// Runs `cycle` at `in` and answers the rig; the lines sent.
std::string cycle_and_answer(RigDopplerCycle& cycle, RigctlSession& rig, const RadioInputs& in,
                             double& rig_hz, double& split_hz) {
  cycle.run(in);
  return answer_all(rig, cycle, RigRole::Main, rig_hz, split_hz);
}

RadioInputs satellite_at(double now_s, double range_rate_km_s) {
  RadioInputs in;
  in.now_s = now_s;
  in.unix_s = 1990.0 + now_s;
  in.satellite = SatelliteNow{"24278", range_rate_km_s};
  return in;
}

TEST(RigDopplerCycle, EachLegSaysTheInstantItWasComputedFor) {
  // The operator turns the dial: the cycle that sees it writes the TX and leaves the RX where it
  // is, so the two legs on the rig were computed for different instants and the state says both.
  const RadioConfig config = inverting_transponder();
  RigctlSession rig;
  connect(rig);
  RigDopplerCycle cycle(config, rig, nullptr);
  double rig_hz = 435.0e6;  // where the operator left the rig
  double split_hz = 145.0e6;
  cycle_and_answer(cycle, rig, satellite_at(10.0, 2.0), rig_hz, split_hz);
  cycle_and_answer(cycle, rig, satellite_at(10.2, 2.0), rig_hz, split_hz);
  ASSERT_TRUE(cycle.rx() && cycle.tx());
  const double rx_at_unix_s = cycle.rx()->at_unix_s;
  rig_hz -= 20000.0;  // the knob
  std::optional<double> tx_written_at;
  for (const double now_s : {10.4, 10.6, 10.8}) {
    const RadioInputs in = satellite_at(now_s, 2.0);
    if (cycle_and_answer(cycle, rig, in, rig_hz, split_hz).find("I ") != std::string::npos) {
      tx_written_at = in.unix_s;
      break;
    }
  }
  ASSERT_TRUE(tx_written_at);
  const nlohmann::json j = cycle.to_json();
  EXPECT_DOUBLE_EQ(j["at_unix_s"].get<double>(), rx_at_unix_s);
  EXPECT_DOUBLE_EQ(j["tx_at_unix_s"].get<double>(), *tx_written_at);
  EXPECT_EQ(j["tx_at"], astro::format_iso8601_utc_unix(*tx_written_at));
}

TEST(RigDopplerCycle, AKnobTurnedJustBeforeADueWriteIsNotWrittenOver) {
  // A second after the last write the RX is due (the Doppler moved 14.5 Hz, over the 10 Hz step)
  // and the operator has just turned the dial down 20 kHz: the dial is read before anything is
  // written, so the rig stays at the new place and the inverting uplink rises by as much.
  const RadioConfig config = inverting_transponder();
  RigctlSession rig;
  connect(rig);
  RigDopplerCycle cycle(config, rig, nullptr);
  double rig_hz = 435.0e6;  // where the operator left the rig
  double split_hz = 145.0e6;
  cycle_and_answer(cycle, rig, satellite_at(10.0, 2.0), rig_hz, split_hz);
  cycle_and_answer(cycle, rig, satellite_at(10.2, 2.0), rig_hz, split_hz);
  const double turned_hz = 435.850e6 / (1.0 + 2.0 / kLightKmS) - 20000.0;
  ASSERT_NEAR(rig_hz, turned_hz + 20000.0, 0.5);
  rig_hz = std::round(turned_hz);
  const double rate = 2.0 + 0.01;  // 435.85e6 · 0.01 / c = 14.5 Hz
  cycle_and_answer(cycle, rig, satellite_at(11.2, rate), rig_hz, split_hz);
  cycle_and_answer(cycle, rig, satellite_at(11.4, rate), rig_hz, split_hz);
  EXPECT_NEAR(rig_hz, turned_hz, 20.0);
  // The place in the passband is the dial heard at the rate of the read, f·(1 + ṙ/c); inverting,
  // the uplink rises by what that fell (nearly the 20 kHz: less the 14.5 Hz the Doppler moved).
  const double sat_down_hz = rig_hz * (1.0 + rate / kLightKmS);
  const double nominal_tx_hz = 145.950e6 / (1.0 - rate / kLightKmS);
  EXPECT_NEAR(split_hz, (145.950e6 + (435.850e6 - sat_down_hz)) / (1.0 - rate / kLightKmS), 1.0);
  EXPECT_NEAR(split_hz - nominal_tx_hz, 20000.0 - 14.5, 1.0);
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
