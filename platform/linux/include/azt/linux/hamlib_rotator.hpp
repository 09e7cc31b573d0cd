#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "azt/util/result.hpp"

// Hamlib's handle type, declared here so this header does not drag <hamlib/rotator.h> (and its
// warnings) into every includer.
struct s_rot;

/// Drives an existing rotator controller (GS-232, SPID, EasyComm boxes, a remote rotctld, ...)
/// through libhamlib 4.5.
///
/// Hamlib calls block (serial timeouts of hundreds of ms times retries), and the daemon's event
/// loop must never block, so every Hamlib call after open() runs on one worker thread owned by
/// this object. The event-loop side only touches a mutex-protected mailbox: the latest commanded
/// setpoint, a pending stop, the latest reading, the link state and the last error. Nothing here
/// throws or logs; failures are returned or kept as strings for the app to log.
namespace azt::linux_os {

struct HamlibConfig {
  int model = 1;        ///< Hamlib rotator model number (`rotctl -l`); 1 = dummy, 2 = NET rotctl
  std::string device;   ///< rot_pathname: serial device, or host:port for model 2; empty = default
  int baud = 0;         ///< serial_speed; 0 keeps the backend's default (must be 0 for network)
  double poll_s = 0.2;  ///< period of rot_get_position
  double min_move_deg = 0.1;  ///< a setpoint closer than this on both axes to the last one sent
                              ///< is not resent (saves the bus; boxes restart their move)
  double reconnect_s = 1.0;   ///< back-off between reconnect attempts after a link error
};

class HamlibRotator {
 public:
  /// One rot_get_position answer, in the rotator's own frame (az as the box reports it, which
  /// may exceed 360 on overlap rotators). `at` is when the request was sent (steady clock), a
  /// conservative age for the caller's staleness check.
  struct Reading {
    double az_deg = 0.0;
    double el_deg = 0.0;
    std::chrono::steady_clock::time_point at;
  };

  /// rot_init + configuration + rot_open, done on the worker thread; returns once the first
  /// rot_open has finished. Fails on an invalid config, an unknown model (named in the message),
  /// a setting the model does not have, or a failing rot_open (device and Hamlib's reason named;
  /// nothing leaks). BLOCKS the caller for as long as rot_open takes (a TCP connect or the
  /// backend's first exchange): call it before the event loop runs. After a successful open,
  /// link failures are recovered by reconnecting in the background.
  static Result<std::unique_ptr<HamlibRotator>> open(const HamlibConfig& config);

  /// Stops the worker, which sends a final rot_stop if the link is up, then closes and frees the
  /// Hamlib handle. Joins the worker: may wait for one in-flight Hamlib call to time out.
  ~HamlibRotator();

  HamlibRotator(const HamlibRotator&) = delete;
  HamlibRotator& operator=(const HamlibRotator&) = delete;
  HamlibRotator(HamlibRotator&&) = delete;
  HamlibRotator& operator=(HamlibRotator&&) = delete;

  /// Asks for a move; never blocks. The latest call wins over any not yet sent. Non-finite
  /// values are ignored and reported through last_error(). A setpoint that failed to go out
  /// because the link dropped is sent after reconnecting unless a newer command replaced it.
  void command_position(double az_deg, double el_deg);

  /// Asks for rot_stop; never blocks. Discards any setpoint not yet sent and wakes the worker so
  /// the stop goes out next (after at most the Hamlib call in flight). Positions commanded after
  /// this call are sent after the stop.
  void command_stop();

  /// The most recent successful reading, kept across link failures (judge staleness by `at`);
  /// empty until the first poll succeeds.
  [[nodiscard]] std::optional<Reading> latest() const;

  /// The most recent failure, kept after recovery; empty if nothing has failed yet.
  [[nodiscard]] std::string last_error() const;

  /// True while the Hamlib handle is open and no exchange has failed with a link error
  /// (timeout, I/O, protocol) since; a rejected command leaves the link up.
  [[nodiscard]] bool connected() const;

 private:
  struct Setpoint {
    double az_deg = 0.0;
    double el_deg = 0.0;
  };
  struct Work {
    bool exit = false;
    bool stop = false;
    std::optional<Setpoint> position;
  };
  enum class OpenState : std::uint8_t { Opening, Open, Failed };

  explicit HamlibRotator(HamlibConfig config);

  Result<bool> start_worker();
  Result<bool> await_first_open();
  void run();
  void serve();
  Result<bool> connect();
  Result<bool> configure(s_rot* rot) const;
  void disconnect();
  void drop_link(const std::string& error);
  bool wait_for_shutdown(std::chrono::steady_clock::time_point deadline);
  Work take_work(std::chrono::steady_clock::time_point deadline);
  bool send_stop();
  bool send_position(const Setpoint& target);
  void poll_position();
  bool handle_failure(int rc, const std::string& what);
  void record_error(const std::string& error);
  [[nodiscard]] std::string describe() const;

  const HamlibConfig config_;

  // Worker-thread state (after open() returns, touched by the worker only).
  s_rot* rot_ = nullptr;
  std::string model_name_;
  std::optional<Setpoint> last_sent_;
  std::chrono::steady_clock::time_point next_poll_;

  // The mailbox, shared with the event-loop side.
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  bool stopping_ = false;
  bool stop_pending_ = false;
  std::optional<Setpoint> pending_;
  std::optional<Reading> latest_;
  std::string last_error_;
  bool connected_ = false;
  OpenState open_state_ = OpenState::Opening;
  std::string open_error_;

  std::thread worker_;  // last: started after, and joined before, everything above is destroyed
};

}  // namespace azt::linux_os
