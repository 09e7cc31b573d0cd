// The rigctld client session against replies as rigctld 4.5.4 (Debian 12 libhamlib-utils, the
// dummy rig -m 1) gave them by hand: `\chk_vfo` → "0", `f` → "145000000", a set → "RPRT 0",
// VFO mode's `f currVFO`, the refusals, and what happens on silence and garbage.
#include "azt/radio/rigctl_session.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <optional>
#include <string>

#include "azt/radio/rigctl_reply.hpp"

namespace azt::radio {
namespace {

/// A session past the handshake, in plain (`vfo_mode` false) or VFO mode.
RigctlSession up_session(bool vfo_mode, RigctlOptions options = {}) {
  RigctlSession session(options);
  session.connected();
  EXPECT_EQ(session.next_line(0.0), "\\chk_vfo\n");
  const auto event = session.on_line(vfo_mode ? "1" : "0");
  EXPECT_TRUE(event && event->kind == RigEventKind::VfoMode);
  EXPECT_EQ(session.link(), RigLink::Up);
  return session;
}

TEST(RigctlReply, RprtFrequenciesAndChkVfo) {
  EXPECT_EQ(parse_rprt("RPRT 0"), 0);
  EXPECT_EQ(parse_rprt("RPRT -11\r"), -11);
  EXPECT_EQ(parse_rprt("RPRT x"), std::nullopt);
  EXPECT_EQ(parse_rprt("145000000"), std::nullopt);
  EXPECT_EQ(parse_frequency_hz("145000000"), 145000000.0);
  EXPECT_EQ(parse_frequency_hz("435123456.5"), 435123456.5);
  EXPECT_EQ(parse_frequency_hz("0"), std::nullopt);
  EXPECT_EQ(parse_frequency_hz("VFOA"), std::nullopt);
  EXPECT_EQ(parse_chk_vfo("1"), true);
  EXPECT_EQ(parse_chk_vfo("CHKVFO 0"), false);
  EXPECT_EQ(parse_chk_vfo("2"), std::nullopt);
  EXPECT_EQ(hamlib_error_text(-11), "feature not available (RIG_ENAVAIL)");
  EXPECT_EQ(hamlib_error_text(-1), "invalid parameter (RIG_EINVAL)");
  EXPECT_EQ(hamlib_error_text(-99), "Hamlib error -99");
  EXPECT_EQ(hamlib_error_text(-2147483647 - 1), "Hamlib error -2147483648");
}

TEST(RigctlSession, CommandLinesInPlainAndVfoMode) {
  EXPECT_EQ(rigctl_command_line(RigCommand::SetFreq, 435123456.6, false, SplitTxVfo::VfoB),
            "F 435123457\n");
  EXPECT_EQ(rigctl_command_line(RigCommand::SetFreq, 145e6, true, SplitTxVfo::VfoB),
            "F currVFO 145000000\n");
  EXPECT_EQ(rigctl_command_line(RigCommand::GetFreq, 0, false, SplitTxVfo::VfoB), "f\n");
  EXPECT_EQ(rigctl_command_line(RigCommand::GetFreq, 0, true, SplitTxVfo::VfoB), "f currVFO\n");
  EXPECT_EQ(rigctl_command_line(RigCommand::SetSplit, 0, false, SplitTxVfo::VfoB), "S 1 VFOB\n");
  EXPECT_EQ(rigctl_command_line(RigCommand::SetSplit, 0, true, SplitTxVfo::Sub),
            "S currVFO 1 Sub\n");
  EXPECT_EQ(rigctl_command_line(RigCommand::SetSplitFreq, 145.9e6, false, SplitTxVfo::VfoB),
            "I 145900000\n");
  EXPECT_EQ(rigctl_command_line(RigCommand::GetSplitFreq, 0, true, SplitTxVfo::VfoB),
            "i currVFO\n");
}

TEST(RigctlSession, HandshakeThenSetAndReadBackTheReceiveFrequency) {
  RigctlSession session;
  EXPECT_EQ(session.next_line(0.0), std::nullopt);  // not connected: nothing to say
  EXPECT_FALSE(session.set_rx_hz(435e6));
  session.connected();
  EXPECT_EQ(session.link(), RigLink::Handshake);
  EXPECT_TRUE(session.set_rx_hz(435100000.0));  // queued behind the handshake
  EXPECT_EQ(session.next_line(0.0), "\\chk_vfo\n");
  EXPECT_EQ(session.next_line(0.1), std::nullopt);  // one command in flight
  ASSERT_TRUE(session.on_line("0"));
  EXPECT_FALSE(session.vfo_mode());
  EXPECT_EQ(session.next_line(0.2), "F 435100000\n");
  EXPECT_EQ(session.next_line(0.2), std::nullopt);
  const auto written = session.on_line("RPRT 0");
  ASSERT_TRUE(written);
  EXPECT_EQ(written->kind, RigEventKind::Written);
  EXPECT_EQ(written->command, RigCommand::SetFreq);
  EXPECT_EQ(session.next_line(0.3), "f\n");
  const auto read = session.on_line("435100000");
  ASSERT_TRUE(read);
  EXPECT_EQ(read->kind, RigEventKind::RxRead);
  EXPECT_EQ(read->hz, 435100000.0);
  EXPECT_EQ(session.rx_read_hz(), 435100000.0);
  EXPECT_TRUE(session.idle());
}

TEST(RigctlSession, VfoModeAddsCurrVfoToEveryCommand) {
  RigctlSession session = up_session(true);
  EXPECT_TRUE(session.vfo_mode());
  session.set_rx_hz(145e6);
  EXPECT_EQ(session.next_line(1.0), "F currVFO 145000000\n");
  session.on_line("RPRT 0");
  EXPECT_EQ(session.next_line(1.0), "f currVFO\n");
}

TEST(RigctlSession, AnOldRigctldWithoutChkVfoIsPlainMode) {
  RigctlSession session;
  session.connected();
  session.next_line(0.0);
  const auto event = session.on_line("RPRT -11");
  ASSERT_TRUE(event);
  EXPECT_EQ(event->kind, RigEventKind::VfoMode);
  EXPECT_FALSE(event->vfo_mode);
  EXPECT_EQ(session.link(), RigLink::Up);
}

TEST(RigctlSession, SplitIsSetOnceThenOnlyTheSplitFrequency) {
  RigctlSession session = up_session(false);
  EXPECT_FALSE(session.read_tx());  // no split yet: `i` would read some VFO, not ours
  session.set_tx_hz(145900000.0);
  EXPECT_EQ(session.next_line(0.0), "S 1 VFOB\n");
  session.on_line("RPRT 0");
  EXPECT_TRUE(session.split_on());
  EXPECT_EQ(session.next_line(0.0), "I 145900000\n");
  session.on_line("RPRT 0");
  EXPECT_EQ(session.next_line(0.0), "i\n");
  const auto read = session.on_line("145900000");
  ASSERT_TRUE(read);
  EXPECT_EQ(read->kind, RigEventKind::TxRead);
  EXPECT_EQ(session.tx_read_hz(), 145900000.0);
  session.set_tx_hz(145900010.0);
  EXPECT_EQ(session.next_line(1.0), "I 145900010\n");  // no second S
}

TEST(RigctlSession, ARigThatRefusesSplitGetsNoTransmitFrequencyUntilReconnected) {
  RigctlSession session = up_session(false);
  session.set_tx_hz(145900000.0);
  EXPECT_EQ(session.next_line(0.0), "S 1 VFOB\n");
  const auto refused = session.on_line("RPRT -11");
  ASSERT_TRUE(refused);
  EXPECT_EQ(refused->kind, RigEventKind::Refused);
  EXPECT_EQ(refused->rprt, -11);
  EXPECT_NE(refused->message.find("set_split_vfo"), std::string::npos);
  EXPECT_EQ(session.link(), RigLink::Up);  // a refusal is an answer, not a dead link
  EXPECT_TRUE(session.split_refused());
  EXPECT_EQ(session.next_line(0.0), std::nullopt);  // the queued I and i were dropped
  EXPECT_FALSE(session.set_tx_hz(145900000.0));
  session.connected();
  EXPECT_FALSE(session.split_refused());
}

TEST(RigctlSession, ARefusedGetIsReportedAndTheLinkStaysUp) {
  RigctlSession session = up_session(false);
  session.read_rx();
  session.next_line(0.0);
  const auto event = session.on_line("RPRT -5");
  ASSERT_TRUE(event);
  EXPECT_EQ(event->kind, RigEventKind::Refused);
  EXPECT_EQ(event->command, RigCommand::GetFreq);
  EXPECT_EQ(event->rprt, -5);
  EXPECT_EQ(session.link(), RigLink::Up);
  EXPECT_EQ(session.rx_read_hz(), std::nullopt);
}

TEST(RigctlSession, ANewerWantedFrequencyReplacesOneNotYetSent) {
  RigctlSession session = up_session(false);
  session.read_rx();
  EXPECT_EQ(session.next_line(0.0), "f\n");  // in flight
  session.set_rx_hz(435000000.0);
  session.set_rx_hz(435000020.0);
  session.read_rx();  // already queued behind the set: not twice
  session.on_line("435000000");
  EXPECT_EQ(session.next_line(0.1), "F 435000020\n");
  session.on_line("RPRT 0");
  EXPECT_EQ(session.next_line(0.1), "f\n");
  session.on_line("435000020");
  EXPECT_TRUE(session.idle());
}

TEST(RigctlSession, AReadQueuedBeforeASetMovesBehindIt) {
  RigctlSession session = up_session(false);
  session.set_tx_hz(145.9e6);
  session.next_line(0.0);
  session.on_line("RPRT 0");  // split on; I and i queued
  session.read_rx();          // f queued
  session.set_rx_hz(435e6);   // F must come before the f that reads it back
  EXPECT_EQ(session.next_line(0.0), "I 145900000\n");
  session.on_line("RPRT 0");
  EXPECT_EQ(session.next_line(0.0), "i\n");
  session.on_line("145900000");
  EXPECT_EQ(session.next_line(0.0), "F 435000000\n");
  session.on_line("RPRT 0");
  EXPECT_EQ(session.next_line(0.0), "f\n");
}

TEST(RigctlSession, ALateReplyFailsTheLinkOnce) {
  RigctlOptions options;
  options.reply_timeout_s = 2.0;
  RigctlSession session = up_session(false, options);
  session.read_rx();
  session.set_rx_hz(435e6);
  EXPECT_EQ(session.next_line(10.0), "F 435000000\n");
  EXPECT_EQ(session.on_tick(11.999), std::nullopt);
  const auto failed = session.on_tick(12.0);
  ASSERT_TRUE(failed);
  EXPECT_EQ(failed->kind, RigEventKind::LinkFailed);
  EXPECT_EQ(failed->message, "rigctld did not answer set_freq within 2000 ms");
  EXPECT_EQ(session.link(), RigLink::Failed);
  EXPECT_EQ(session.on_tick(20.0), std::nullopt);  // said once
  EXPECT_EQ(session.next_line(20.0), std::nullopt);
  EXPECT_FALSE(session.set_rx_hz(435e6));
  EXPECT_EQ(session.on_line("RPRT 0"), std::nullopt);  // a late answer to a dead conversation
}

TEST(RigctlSession, ALineNobodyAskedForFailsTheLink) {
  // rigctld in plain mode answers `f currVFO` with three lines; the two extra would be taken as
  // the answers to the next commands.
  RigctlSession session = up_session(false);
  session.read_rx();
  session.next_line(0.0);
  session.on_line("435000001");
  const auto event = session.on_line("0");
  ASSERT_TRUE(event);
  EXPECT_EQ(event->kind, RigEventKind::LinkFailed);
  EXPECT_EQ(event->message, "rigctld sent a line nobody asked for: \"0\"");
  EXPECT_EQ(session.link(), RigLink::Failed);
}

TEST(RigctlSession, GarbageAnswersFailTheLinkWithTheLineQuotedSafely) {
  RigctlSession session = up_session(false);
  session.set_rx_hz(435e6);
  session.next_line(0.0);
  const auto event = session.on_line(std::string("garbage\x01\x7f", 9) + std::string(100, 'x'));
  ASSERT_TRUE(event);
  EXPECT_EQ(event->kind, RigEventKind::LinkFailed);
  EXPECT_EQ(event->command, RigCommand::SetFreq);
  EXPECT_EQ(event->message,
            "rigctld answered set_freq with \"garbage??" + std::string(31, 'x') + "...\"");
  RigctlSession get = up_session(false);
  get.read_rx();
  get.next_line(0.0);
  const auto bad_get = get.on_line("VFOA");
  ASSERT_TRUE(bad_get);
  EXPECT_EQ(bad_get->kind, RigEventKind::LinkFailed);
  RigctlSession handshake;
  handshake.connected();
  handshake.next_line(0.0);
  EXPECT_EQ(handshake.on_line("maybe")->kind, RigEventKind::LinkFailed);
}

TEST(RigctlSession, NotAFrequencyIsNotQueued) {
  RigctlSession session = up_session(false);
  EXPECT_FALSE(session.set_rx_hz(0.0));
  EXPECT_FALSE(session.set_rx_hz(-145e6));
  EXPECT_FALSE(session.set_rx_hz(1e12));
  EXPECT_FALSE(session.set_rx_hz(std::numeric_limits<double>::quiet_NaN()));
  EXPECT_FALSE(session.set_tx_hz(std::numeric_limits<double>::infinity()));
  EXPECT_TRUE(session.idle());
}

TEST(RigctlSession, DisconnectedForgetsEverything) {
  RigctlSession session = up_session(true);
  session.set_tx_hz(145.9e6);
  session.next_line(0.0);
  session.on_line("RPRT 0");
  session.disconnected();
  EXPECT_EQ(session.link(), RigLink::Down);
  EXPECT_FALSE(session.vfo_mode());
  EXPECT_FALSE(session.split_on());
  EXPECT_TRUE(session.idle());
  session.connected();
  EXPECT_EQ(session.next_line(5.0), "\\chk_vfo\n");
}

}  // namespace
}  // namespace azt::radio
