#pragma once
// A rig as the station's Doppler cycle drives it (docs/radio.md "In the daemon"): the receive
// frequency on the main VFO, the transmit frequency as the split frequency, and the dial read.
// Two adapters carry it: rigctld's client session (azt/radio/rigctl_session.hpp, over TCP on the
// loop) and libhamlib itself on a worker thread (azt/linux/hamlib_rig.hpp). Both only queue: a
// call never waits for the rig, and what the rig answered comes back later as RigEvents, in the
// order asked, through the adapter's own channel.

#include <cmath>
#include <string>

namespace azt::radio {

/// What was asked of the rig, in the words of rigctld's commands (the libhamlib adapter calls
/// the functions of the same names: rig_set_freq, rig_get_split_freq, …).
enum class RigCommand { ChkVfo, GetFreq, SetFreq, SetSplit, GetSplitFreq, SetSplitFreq };

enum class RigEventKind {
  VfoMode,     ///< rigctld's `\chk_vfo` answered: `vfo_mode` says which
  RxRead,      ///< the main VFO read `hz`
  TxRead,      ///< the split frequency read `hz`
  Written,     ///< a set was taken (rigctld's RPRT 0, Hamlib's RIG_OK)
  Refused,     ///< a set or get was refused with Hamlib status `rprt` (< 0); the link stays up
  LinkFailed,  ///< the link failed: `message` says why
};

struct RigEvent {
  RigEventKind kind = RigEventKind::Written;
  RigCommand command = RigCommand::GetFreq;
  double hz = 0.0;
  int rprt = 0;
  bool vfo_mode = false;
  std::string message;  ///< for Refused and LinkFailed: a sentence for the log
};

/// The VFO that transmits in split: VFOB on most rigs, Sub on rigs with main/sub receivers.
enum class SplitTxVfo { VfoB, Sub };

/// Above any rig Hamlib knows (its ranges stop in the hundreds of GHz) and well inside the
/// integers a double holds exactly, so a whole-Hz value is always exact.
constexpr double kMaxRigFrequencyHz = 1e12;

/// A frequency a rig may be sent: finite, above 0 and below kMaxRigFrequencyHz.
inline bool is_rig_frequency(double hz) {
  return std::isfinite(hz) && hz > 0.0 && hz < kMaxRigFrequencyHz;
}

class RigPort {
 public:
  RigPort() = default;
  RigPort(const RigPort&) = default;
  RigPort& operator=(const RigPort&) = default;
  RigPort(RigPort&&) = default;
  RigPort& operator=(RigPort&&) = default;
  virtual ~RigPort() = default;

  /// Queue the receive frequency (the main VFO), then a read of what the rig took (rigs round
  /// to their step): Written (SetFreq), then RxRead. False, and nothing queued, while the link
  /// is down or when `hz` is not a frequency (is_rig_frequency). Whole Hz go to the rig.
  virtual bool set_rx_hz(double hz) = 0;
  /// Queue the transmit frequency as the split frequency, split turned on first once per
  /// connection, then a read back: Written (SetSplitFreq), then TxRead. Also false once the rig
  /// refused split (until it reconnects).
  virtual bool set_tx_hz(double hz) = 0;
  /// Queue a read of the main VFO: the dial, to see whether the operator turned the knob.
  virtual bool read_rx() = 0;
  /// The rig answers now: what is queued will be sent.
  [[nodiscard]] virtual bool up() const = 0;
};

}  // namespace azt::radio
