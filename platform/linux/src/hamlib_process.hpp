#pragma once
// What every use of libhamlib in the process shares (the rotator, hamlib_rotator.cpp; the rig,
// hamlib_rig.cpp; the model check, hamlib_rig_model.cpp): the lock around Hamlib's process-wide
// state, its one-line reason for a status, and which statuses mean the link is gone. Private to
// the Linux adapters.

#include <mutex>
#include <string>

namespace azt::linux_os {

/// Hamlib 4.5 keeps process-wide state without locks: the backend registry (rig_init, rot_init,
/// rig_check_backend), the lists of opened rigs and rotators (rig_open/rig_close and the rot_
/// ones), the debug level and rigerror2()'s static buffer. Every caller takes this lock around
/// those calls; blocking I/O (get/set/stop) runs without it, so one slow device does not stall
/// another.
std::mutex& hamlib_global_mutex();

/// Hamlib's one-line reason for a negative status, with the status: "IO error (Hamlib status
/// -6)". rigerror() is not used: in 4.5 it returns Hamlib's whole recent debug history
/// (kilobytes, multi-line) even at RIG_DEBUG_NONE.
std::string hamlib_status_text(int rc);

/// Errors that mean the link (port, device or peer) is gone or garbled, as opposed to a command
/// the device refused (out of range, not implemented): the former close and reopen the handle.
bool is_hamlib_link_error(int rc);

/// Hamlib prints its debug trail to stderr unless told not to; once, before the first use.
void quiet_hamlib();

}  // namespace azt::linux_os
