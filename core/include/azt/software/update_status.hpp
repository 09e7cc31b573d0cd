#pragma once
// What the root update helper (packaging/azeltrack-update) reports about the package it was
// handed (docs/packaging.md): key=value lines, rewritten whole (by rename) at each step, read by
// the daemon for the console's Software page. Unknown keys are skipped, so a newer helper may say
// more; a known key with a bad value makes the whole report an error, never half a report.
//   phase=installing
//   percent=40
//   message=Unpacking azeltrack (0.1.1) over (0.1.0)
//   from=0.1.0
//   to=0.1.1
//   sha256=<the package's SHA-256, 64 hex digits>
//   signer=<who signed it, as the trusted key names itself, and the key's fingerprint>
//   at=<Unix seconds when this step began>

#include <cstdint>
#include <string>
#include <string_view>

#include "azt/util/result.hpp"

namespace azt::software {

enum class UpdatePhase {
  Checking,    ///< copying the package and checking its name, architecture and version
  Refused,     ///< not installed: the message says why (nothing was changed)
  Installing,  ///< apt is installing it; percent is apt's
  Installed,   ///< installed; the package's postinst restarted the daemon
  Failed,      ///< apt failed: the message has its last words
};

struct UpdateStatus {
  UpdatePhase phase = UpdatePhase::Checking;
  int percent = 0;  ///< 0..100, of the current phase
  std::string message;
  std::string from_version;  ///< what was installed when the helper began
  std::string to_version;    ///< the package's version ("" until read from it)
  std::string sha256_hex;    ///< of the package the helper copied: ties it to an upload
  /// Whose trusted key signed it ("" until the signature is verified): docs/packaging.md.
  std::string signer;
  std::int64_t at_unix_s = 0;
};

std::string_view to_string(UpdatePhase phase);
/// Whether the helper is done with the package (refused, installed or failed).
[[nodiscard]] bool finished(UpdatePhase phase);

/// The helper's report; an Error names the line at fault.
Result<UpdateStatus> parse_update_status(std::string_view text);

}  // namespace azt::software
