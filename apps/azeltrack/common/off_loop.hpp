#pragma once
// How the console's handlers run what may block (a password check, a configuration save) off the
// event loop: `work` runs elsewhere, then `done` runs back on the loop. The daemon passes a
// linux_os::WorkerThread; tests and the command line pass run_inline, which does both at once.

#include <functional>

namespace azt::app {

using Offload = std::function<void(std::function<void()> work, std::function<void()> done)>;

/// Runs `work` then `done` at once, on the caller's thread (tests, one-shot commands).
inline void run_inline(const std::function<void()>& work, const std::function<void()>& done) {
  work();
  done();
}

}  // namespace azt::app
