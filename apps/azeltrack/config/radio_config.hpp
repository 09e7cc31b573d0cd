#pragma once
// [radio] and [[satellites.transmitter]] (docs/radio.md): which rig azeltrack keeps on frequency,
// through Hamlib's rigctld or libhamlib directly, and for which Doppler. One writer per rig: with
// doppler = "off" no frequency is ever written.

#include <optional>
#include <string>
#include <vector>

#include "azt/linux/hamlib_rig_model.hpp"
#include "azt/radio/eme_doppler_modes.hpp"
#include "azt/radio/satellite_doppler.hpp"
#include "config/host_port.hpp"

namespace azt::app {

class ConfigFile;

enum class DopplerSource { Off, Satellite, Eme };

/// One `[[satellites.transmitter]]`: the frequencies of a satellite's transmitter (satellite
/// frame) that the rig follows while that satellite is tracked.
struct TransmitterConfig {
  std::string norad;  ///< the catalogue number as text ("25544"), as the element sets spell it
  radio::SatelliteTransmitter transmitter;
};

struct RadioConfig {
  /// The rig: through rigctld, or libhamlib directly (`model`); at most one is set.
  std::optional<HostPort> rigctld;
  std::optional<linux_os::HamlibRigConfig> hamlib;
  /// A second rig for the uplink, either way; neither: the uplink is the rig's split VFO.
  std::optional<HostPort> tx_rigctld;
  std::optional<linux_os::HamlibRigConfig> tx_hamlib;
  DopplerSource doppler = DopplerSource::Off;
  radio::EmeDopplerMode eme_mode = radio::EmeDopplerMode::FullDx;
  double dial_mhz = 0.0;  ///< EME: the nominal dial frequency
  double step_hz = 10.0;  ///< the satellite update step, quoted at 435 MHz
  bool no_tx_qsy = false;
  std::vector<TransmitterConfig> transmitters;

  /// A rig is named, either way.
  [[nodiscard]] bool has_rig() const { return rigctld || hamlib; }
  /// The transmitter of the satellite `norad`, or null.
  [[nodiscard]] const TransmitterConfig* transmitter_of(const std::string& norad) const;
};

std::string_view doppler_source_name(DopplerSource source);
/// "fm", "linear" or "linear_inverting", as `[[satellites.transmitter]] mode` spells it.
std::string_view transponder_mode_name(radio::TransponderMode mode);

/// Throws UsageError naming the key on any invalid value or combination: a rig named both ways, a
/// model Hamlib does not know, a speed the model cannot take.
RadioConfig radio_config_from(const ConfigFile& file);

}  // namespace azt::app
