#pragma once
// How the daemon starts again after the console's Restart (docs/daemon.md "Restart"): under
// systemd the service manager does it (the unit's RestartForceExitStatus names the exit status,
// so the journal shows one service, restarted); anywhere else (scripts/run, a terminal) the
// process replaces itself with a fresh copy of the same program and arguments.

#include <string>

#include "azt/util/result.hpp"

namespace azt::linux_os {

/// The exit status that asks systemd for a restart (EX_TEMPFAIL, sysexits.h).
inline constexpr int kExitRestart = 75;

/// Whether systemd started this process as a service (it sets INVOCATION_ID for each run).
bool started_by_systemd();

/// Replaces this process with /proc/self/exe and the arguments it was started with, every open
/// descriptor above stderr closed at the exec. Returns only on failure, with the reason.
Result<bool> reexec_self();

}  // namespace azt::linux_os
