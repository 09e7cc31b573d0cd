#pragma once
// One rig through libhamlib directly (docs/radio.md "Through rigctld or directly"): the rig's
// CAT port opened by this process, as the rotator backend opens its box (hamlib_rotator.hpp).
//
// Hamlib's calls block on the rig's port (a serial timeout of seconds, times the model's
// retries: Hamlib 4.5.4's IC-9700 backend takes 9 s to open a silent port and 4.4 s to give up
// a read; a missing device takes 2 s to fail), and no handler may block the daemon's loop. So
// every Hamlib call runs on a worker thread of this object's own, and the loop side only queues:
// set_rx_hz, set_tx_hz and read_rx fill a mailbox (a newer frequency replaces one not yet sent,
// as rigctld's session does), flush() hands it to the worker, and what the rig answered is
// posted back to the loop as the same RigEvents rigctld's session gives, in the order the calls
// were made: rig_set_freq then rig_get_freq (Written, RxRead), rig_set_split_vfo once per
// connection, then rig_set_split_freq and rig_get_split_freq (Written, TxRead).
//
// The link is up once rig_open succeeded and the rig answered a first read of the dial (many
// backends open the port of a rig that is switched off). A link error (Hamlib's timeout, I/O,
// protocol or bus errors) closes the rig, the loss is posted, and rig_open is tried again after
// a back-off that doubles from retry_s up to max_retry_s; a refusal (RIG_ENAVAIL, RIG_EINVAL) is
// posted as Refused and the link stays up. When nothing was asked for idle_check_s, the worker
// reads the dial without reporting it, so a rig switched off shows as down even while no
// frequency is due. On destruction the worker closes the rig; the destructor waits close_wait_s
// at most for a call in flight, then leaves the worker to finish that call and close the rig on
// its own (it posts nothing more).
//
// Nothing here keys the transmitter: no rig_set_ptt.

#include <memory>
#include <optional>
#include <string>
#include <thread>

#include "azt/linux/asio.hpp"
#include "azt/linux/hamlib_rig_model.hpp"
#include "azt/linux/rig_connection.hpp"
#include "azt/radio/rig_port.hpp"

namespace azt::linux_os {

struct HamlibRigOptions {
  double retry_s = 0.5;       ///< the first retry after a failed open or a lost link
  double max_retry_s = 4.0;   ///< back-off cap: a rig switched off costs one rig_open every 4 s
  double idle_check_s = 2.0;  ///< a silent dial read after this long with nothing asked
  double close_wait_s = 2.0;  ///< how long the destructor waits for a call in flight
  radio::SplitTxVfo split_tx_vfo = radio::SplitTxVfo::VfoB;
};

class HamlibRig final : public RigConnection, public radio::RigPort {
 public:
  /// Starts the worker, which opens the rig at once; events arrive on `io`'s loop.
  HamlibRig(boost::asio::io_context& io, HamlibRigConfig config, HamlibRigOptions options,
            RigLinkEvents events);
  ~HamlibRig() override;
  HamlibRig(const HamlibRig&) = delete;
  HamlibRig& operator=(const HamlibRig&) = delete;
  HamlibRig(HamlibRig&&) = delete;
  HamlibRig& operator=(HamlibRig&&) = delete;

  radio::RigPort& port() override { return *this; }
  /// Hands what is queued to the worker.
  void flush() override;
  [[nodiscard]] RigLinkState state() const override { return state_; }
  [[nodiscard]] const std::string& down_reason() const override { return down_reason_; }
  /// "Hamlib rig model 3073 on /dev/ttyUSB0"
  [[nodiscard]] std::string describe() const override;

  bool set_rx_hz(double hz) override;
  bool set_tx_hz(double hz) override;
  bool read_rx() override;
  [[nodiscard]] bool up() const override { return state_ == RigLinkState::Up; }

  /// How many times rig_open was called, as the loop last heard (the tests count retries).
  [[nodiscard]] unsigned open_attempts() const { return open_attempts_; }

 private:
  /// What the worker asks of the rig in one turn (the mailbox).
  struct Requests {
    std::optional<double> rx_hz;
    std::optional<double> tx_hz;
    bool read_rx = false;
    [[nodiscard]] bool any() const { return rx_hz || tx_hz || read_rx; }
  };
  /// What the worker tells the loop.
  struct Report {
    enum class Kind { Opened, Lost, Answer } kind = Kind::Answer;
    std::string why;  ///< Lost: why the open failed or the link went
    radio::RigEvent answer;
    unsigned open_attempts = 0;
  };
  struct Worker;  ///< the worker thread's side, shared with it (hamlib_rig.cpp)

  void on_report(const Report& report);
  void on_lost(const std::string& why);

  HamlibRigConfig config_;
  RigLinkEvents events_;
  RigLinkState state_ = RigLinkState::Connecting;
  std::string down_reason_;
  bool down_reported_ = false;
  bool split_refused_ = false;
  unsigned open_attempts_ = 0;
  Requests queued_;
  std::shared_ptr<bool> alive_ = std::make_shared<bool>(true);
  std::shared_ptr<Worker> worker_;
  std::thread thread_;  ///< last: started once everything it uses exists
};

}  // namespace azt::linux_os
