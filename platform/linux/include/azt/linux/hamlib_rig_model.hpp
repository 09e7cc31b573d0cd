#pragma once
// A rig reached through libhamlib directly (docs/radio.md "Through rigctld or directly"): which
// of Hamlib's rig models (`rigctl -l`), on which port, at which speed; and what Hamlib knows of a
// model, so that the configuration refuses a number Hamlib has no rig for when it is loaded, not
// when the daemon first opens the rig.

#include <string>

#include "azt/util/result.hpp"

namespace azt::linux_os {

struct HamlibRigConfig {
  int model = 0;       ///< Hamlib's rig model number (`rigctl -l`): 1 the dummy, 3073 IC-7300, …
  std::string device;  ///< rig_pathname: a serial device, or host:port for network models; ""
                       ///< keeps the model's default
  int baud = 0;        ///< serial_speed; 0 keeps the model's default
};

/// "Hamlib rig model 3073 on /dev/ttyUSB0" (the model's default port: no "on").
std::string describe_hamlib_rig(const HamlibRigConfig& config);

/// How a model's rig is reached (Hamlib's rig_port_e, reduced to what the checks need).
enum class HamlibPortKind { None, Serial, Network, Other };

struct HamlibRigModel {
  std::string name;  ///< "Hamlib Dummy", "Icom IC-7300": the maker's and the model's names
  HamlibPortKind port = HamlibPortKind::Other;
};

/// What Hamlib knows of rig model `model`; an error naming the number when Hamlib has no such
/// rig. Loads the model's backend (quickly, in-process: no I/O), under Hamlib's process lock.
Result<HamlibRigModel> hamlib_rig_model(int model);

/// Why `config` cannot open a rig ("" when it can, as far as the model tells): an unknown model,
/// or a speed for a rig that has no serial port. The speed is not held to the range of Hamlib's
/// caps: Hamlib does not hold it either, and rigs go faster than their caps say (Hamlib 4.5.4
/// gives the IC-9700 4800 to 38400 baud; its USB CI-V runs at 115200).
std::string hamlib_rig_config_problem(const HamlibRigConfig& config);

}  // namespace azt::linux_os
