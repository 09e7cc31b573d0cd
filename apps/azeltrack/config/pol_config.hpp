#pragma once
// [pol]: what the polarisation axis follows (docs/eme.md, "Polarisation axis"): the mode and its
// angles, as control::PolSettings. The axis itself is [mount.pol]; the DX station is [sky]
// dx_grid, where the EME data already keeps it.

#include "azt/control/pol_target.hpp"

namespace azt::app {

class ConfigFile;

/// Throws UsageError naming the key on any invalid value.
control::PolSettings pol_settings_from(const ConfigFile& file);

}  // namespace azt::app
