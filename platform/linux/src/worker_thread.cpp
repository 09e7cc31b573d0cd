#include "azt/linux/worker_thread.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <utility>

namespace azt::linux_os {

WorkerThread::WorkerThread(boost::asio::io_context& io) : io_(io), thread_([this] { run(); }) {}

WorkerThread::~WorkerThread() { finish(); }

void WorkerThread::finish() {
  {
    const std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  if (thread_.joinable()) thread_.join();
}

void WorkerThread::post(Work work, Done done) {
  {
    const std::lock_guard lock(mutex_);
    if (stopping_) return;
    jobs_.emplace_back(std::move(work), std::move(done));
  }
  wake_.notify_one();
}

std::size_t WorkerThread::pending() const {
  const std::lock_guard lock(mutex_);
  return jobs_.size() + running_;
}

void WorkerThread::run() {
  // Low priority: on a 2-core board an Argon2id check must never take a core from the control
  // loop. Nice 10 gives it about a tenth of the loop's share when both want the CPU, yet a login
  // still finishes in well under a second on a busy machine (nice 19 took seconds there). Linux
  // applies nice values per thread; a failure only means normal priority.
  (void)::setpriority(PRIO_PROCESS, static_cast<id_t>(::gettid()), 10);
  for (;;) {
    std::pair<Work, Done> job;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [this] { return stopping_ || !jobs_.empty(); });
      // Stopping still finishes what was asked (an E-stop latch write, a save): only the done
      // halves are lost, with the loop that would have run them.
      if (jobs_.empty()) return;
      job = std::move(jobs_.front());
      jobs_.pop_front();
      running_ = 1;
    }
    // A job's own errors travel in what it captured; anything escaping would end the thread
    // and with it every later save, so it is contained here and the done half still runs.
    try {
      job.first();
    } catch (...) {  // NOLINT(bugprone-empty-catch): the done half reports the missing result
    }
    boost::asio::post(io_, std::move(job.second));  // never run once the loop has ended
    const std::lock_guard lock(mutex_);
    running_ = 0;
  }
}

}  // namespace azt::linux_os
