#pragma once
// [receiver] (docs/calibration.md): where the power readings of pointing scans come from.
// `rtl_power`: its CSV lines from a FIFO or a file it appends to (`rtl_power -f … -i 1 - > PATH`;
// one line, one reading: a range that fits one hop); `udp`: datagrams of one dB value per line from
// any SDR program; `sim`: the simulated receiver ([sim.receiver]) through the simulated antenna's
// true beam (the `sim` backend only); `none`: no receiver (the default).

#include <optional>
#include <string>

namespace azt::app {

class ConfigFile;

/// What decides how loud a source is at the receiver ([station] dish_m, efficiency; [receiver]
/// tsys_k, bandwidth_hz, integration_s): each absent unless the file gives it.
struct DishConfig {
  std::optional<double> dish_m;
  std::optional<double> efficiency;
  std::optional<double> tsys_k;
  std::optional<double> bandwidth_hz;
  double integration_s = 1.0;
  /// The three the estimate needs are given.
  [[nodiscard]] bool given() const { return dish_m && efficiency && tsys_k; }
};

struct ReceiverConfig {
  enum class Source { None, RtlPower, Udp, Sim };
  Source source = Source::None;
  std::string path;                ///< rtl_power: the FIFO or file
  std::string bind = "127.0.0.1";  ///< udp
  unsigned short port = 0;         ///< udp
  double stale_s = 2.0;            ///< no reading for this long: the receiver is silent
  DishConfig dish;                 ///< for the calibration session's source estimates
};

/// Throws UsageError naming the key on any invalid value.
ReceiverConfig receiver_config_from(const ConfigFile& file);

}  // namespace azt::app
