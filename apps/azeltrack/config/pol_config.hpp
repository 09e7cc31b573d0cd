#pragma once
// [pol]: what the polarisation axis follows (docs/eme.md, "Polarisation axis"): the mode and its
// angles, as control::PolSettings. The axis itself is [mount.pol]; the DX station is [sky]
// dx_grid, where the EME data already keeps it.

#include "azt/control/pol_target.hpp"

namespace azt::app {

class ConfigFile;
struct DaemonConfig;

/// Throws UsageError naming the key on any invalid value.
control::PolSettings pol_settings_from(const ConfigFile& file);

/// [mount.pol] and [hardware.pol] against [antenna] backend: the `sim` backend simulates the
/// axis, `hardware` needs [hardware.pol], `pwm` and `hamlib` cannot drive one (refused, not
/// ignored). Throws UsageError naming the key.
void check_pol_backend(const ConfigFile& file, const DaemonConfig& config);

}  // namespace azt::app
