#pragma once
// The client side of one TCP connection to Hamlib's rigctld (NET rigctl protocol), as a pure state
// machine: the caller says which rig frequencies it wants and passes each received line in; the
// session says which line to send next. No socket, no clock of its own (times are passed in,
// seconds on any monotonic scale), no logging: events come back for the transport to log once.
//
// The conversation (Hamlib/Hamlib doc/man1/rigctld.1; behaviour of rigctld 4.5.4 checked by hand):
//   - On connect: `\chk_vfo` (rigctld.1:1704). Its answer decides the form of every later command:
//     in VFO mode each needs a VFO first (`F currVFO 435000000`), otherwise none may have one: in
//     plain mode rigctld reads `f currVFO` as `f` followed by a second command and answers three
//     lines, which would shift every later reply by two. A rigctld too old for `\chk_vfo`
//     (answering RPRT) is taken as plain mode. `\set_vfo_opt` is never sent: the mode belongs to
//     whoever started rigctld (Gpredict sends it, csete/gpredict src/gtk-rig-ctrl.c:2624-2657).
//   - Receive frequency: `F <Hz>` on the current (main) VFO, then `f` to read back what the rig
//     took (rigs round to their tuning step; Gpredict does the same, gtk-rig-ctrl.c:1754-1783).
//   - Transmit frequency: split on once per connection with `S 1 <TX VFO>` (rigctld.1:772), then
//     `I <Hz>` and `i` (rigctld.1:801-809). A rig that refuses split gets no TX frequency until the
//     next connection (the refusal is reported once, not every second).
//   - Frequencies are sent as whole Hz: rigctld truncates a decimal (`F 435123456.7` reads back
//     435123456).
//   - One command in flight: the next line is released only after the reply to the last one.
//     A reply that does not arrive within reply_timeout_s, a line nobody asked for, or a reply
//     that fits no form fails the link: the transport closes and reconnects.
//   - A wanted frequency not yet sent is replaced by a newer one, and a read already queued is not
//     queued twice, so the queue holds at most one of each command.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "azt/radio/rig_port.hpp"

namespace azt::radio {

enum class RigLink {
  Down,       ///< no connection (before connected(), after disconnected())
  Handshake,  ///< connected, `\chk_vfo` not answered yet
  Up,         ///< talking
  Failed,     ///< timeout or garbage: the transport must close and reconnect
};

struct RigctlOptions {
  double reply_timeout_s = 2.0;  ///< rigctld answers a dummy rig in 20 ms, a real one in < 1 s
  SplitTxVfo split_tx_vfo = SplitTxVfo::VfoB;
};

/// The line that sends `command` (with its '\n'): `vfo_mode` adds `currVFO`, `hz` is rounded to
/// whole Hz for the sets.
std::string rigctl_command_line(RigCommand command, double hz, bool vfo_mode, SplitTxVfo tx_vfo);

class RigctlSession final : public RigPort {
 public:
  explicit RigctlSession(RigctlOptions options = {}) : options_(options) {}

  /// A new connection: forgets the last one and starts with `\chk_vfo`.
  void connected();
  /// The connection is gone: nothing is queued or in flight any more.
  void disconnected();

  /// Queue a receive (main VFO) frequency. False, and nothing queued, if the link is down or
  /// failed, or `hz` is not a frequency (not finite, ≤ 0, ≥ 1 THz).
  bool set_rx_hz(double hz) override;
  /// Queue a transmit (split) frequency; also false when the rig refused split.
  bool set_tx_hz(double hz) override;
  /// Queue a read of the main VFO (`f`): the dial, to see whether the operator turned the knob.
  bool read_rx() override;
  /// Queue a read of the split frequency (`i`); false until split is on.
  bool read_tx();

  /// The line to write now (with '\n'), or nullopt: nothing queued, or a reply still awaited.
  std::optional<std::string> next_line(double now_s);
  /// One line received (the '\n' removed). What it meant; nullopt only once the link has failed
  /// (the rest of a dead conversation is dropped).
  std::optional<RigEvent> on_line(std::string_view line);
  /// The reply timeout: LinkFailed once when the reply to the command in flight is late.
  std::optional<RigEvent> on_tick(double now_s);

  [[nodiscard]] RigLink link() const { return link_; }
  [[nodiscard]] bool up() const override { return link_ == RigLink::Up; }
  [[nodiscard]] bool vfo_mode() const { return vfo_mode_; }
  [[nodiscard]] bool split_on() const { return split_on_; }
  [[nodiscard]] bool split_refused() const { return split_refused_; }
  /// Nothing queued and nothing in flight.
  [[nodiscard]] bool idle() const { return queue_.empty() && !in_flight_; }
  /// The last values read back (this connection).
  [[nodiscard]] std::optional<double> rx_read_hz() const { return rx_read_hz_; }
  [[nodiscard]] std::optional<double> tx_read_hz() const { return tx_read_hz_; }

 private:
  struct Pending {
    RigCommand command;
    double hz;
  };

  [[nodiscard]] bool accepting() const;
  void enqueue(RigCommand command, double hz);
  void read_back(RigCommand get);
  void remove_queued(RigCommand command);
  RigEvent fail(std::string message);
  RigEvent answer_chk_vfo(std::string_view line);
  RigEvent answer_get(RigCommand command, std::string_view line);
  RigEvent answer_set(RigCommand command, std::string_view line);

  RigctlOptions options_;
  RigLink link_ = RigLink::Down;
  bool vfo_mode_ = false;
  bool split_on_ = false;
  bool split_refused_ = false;
  std::vector<Pending> queue_;
  std::optional<Pending> in_flight_;
  double sent_at_s_ = 0.0;
  std::optional<double> rx_read_hz_;
  std::optional<double> tx_read_hz_;
};

/// The name of a command as rigctld's manual gives it (set_freq, get_split_freq, …), for messages.
std::string_view rigctl_command_name(RigCommand command);

}  // namespace azt::radio
