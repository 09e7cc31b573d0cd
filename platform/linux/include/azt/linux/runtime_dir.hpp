#pragma once
// Where the daemon puts what lives only while it runs (the pseudo-terminals' links): the
// runtime directory, never a shared /tmp path that another user could create first and fill
// with links of their own (docs/reliability.md "Hardening" row 10).

#include <string>

#include "azt/util/result.hpp"

namespace azt::linux_os {

/// systemd's `$RUNTIME_DIRECTORY` under the unit (RuntimeDirectory=azeltrack); else
/// `/run/azeltrack` as root, `$XDG_RUNTIME_DIR/azeltrack` otherwise (`/tmp/azeltrack-UID` when
/// XDG_RUNTIME_DIR is unset).
std::string runtime_dir();

/// Makes sure `dir` is a directory this process may trust: created 0700 if missing (parents
/// too); refused, naming it, when it is a symbolic link, not a directory, or owned by another
/// user.
Result<bool> ensure_private_dir(const std::string& dir);

}  // namespace azt::linux_os
