#pragma once
// The last line of defence when the process dies by a fatal signal (a crash: SIGSEGV, SIGBUS,
// SIGILL, SIGFPE, or SIGABRT from std::terminate), where no destructor runs. GPIO lines from the
// character device are released by the kernel when the process's descriptors close, but a sysfs
// PWM channel keeps its duty after the process is gone (reference R16), so a bridge would keep
// driving. Drivers register here the sysfs writes that make them safe ("0" to duty_cycle and
// enable); the handler replays them with async-signal-safe calls only (open, write, close), then
// lets the signal kill the process as it would have (core dump and all).

#include <string>
#include <string_view>

namespace azt::linux_os {

/// Remembers that `text` must be written to `path` if the process crashes. Bounded (32 writes,
/// 255-byte paths, 15-byte texts): beyond that it returns false and the write is not kept.
bool register_crash_write(const std::string& path, std::string_view text);
/// Forgets every write to `path` (the output was closed cleanly).
void forget_crash_writes(const std::string& path);
/// Installs the handler for the fatal signals (idempotent).
void install_crash_handlers();
/// Runs the registered writes now, as the handler would (for tests). Returns how many succeeded.
int run_crash_writes();

}  // namespace azt::linux_os
