#pragma once
// Work that may block (an Argon2id password check, a configuration save that waits for a lock
// and fsyncs) runs on one background thread, never on the event loop (docs/daemon.md: no handler
// blocks the loop). A job is two halves: `work` runs on the worker, then `done` is posted back to
// the io_context and runs on the loop, where it may touch the daemon's state. Jobs run one at a
// time in the order posted, so saves reach the disk in order.

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <mutex>
#include <thread>

#include "azt/linux/asio.hpp"

namespace azt::linux_os {

class WorkerThread {
 public:
  using Work = std::function<void()>;
  using Done = std::function<void()>;

  explicit WorkerThread(boost::asio::io_context& io);
  /// finish(), if it has not been called.
  ~WorkerThread();
  WorkerThread(const WorkerThread&) = delete;
  WorkerThread& operator=(const WorkerThread&) = delete;

  /// Queues a job. `work` must not touch loop state; it hands its outcome to `done` through what
  /// both capture. An exception escaping `work` is contained and `done` still runs (finding no
  /// outcome), so a failed job is reported, never lost.
  void post(Work work, Done done);  ///< ignored once finish() has begun
  /// Stops taking jobs, finishes every job asked for (a queued E-stop latch write must reach the
  /// disk), then joins; later calls return at once. An owner calls it before destroying anything
  /// a job may reach, as StationDaemon's destructor does first of all. The `done`
  /// halves of jobs finished after the loop ended never run.
  void finish();
  /// Jobs queued or running (for bounds and tests).
  [[nodiscard]] std::size_t pending() const;

 private:
  void run();

  boost::asio::io_context& io_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<std::pair<Work, Done>> jobs_;
  std::size_t running_ = 0;
  bool stopping_ = false;
  std::thread thread_;  ///< last: starts once everything it uses exists
};

}  // namespace azt::linux_os
