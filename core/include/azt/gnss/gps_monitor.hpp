#pragma once
// The GPS state the console shows (docs/gps.md): off, no gpsd, no fix, 2D or 3D fix, with the
// latest position, satellites and receiver time. Pure: the gpsd adapter reports what it hears,
// with the control loop's monotonic time, and status() ages it. A receiver that stops talking
// makes gpsd fall silent, so a fix older than stale_after_s is no fix.

#include <optional>
#include <string_view>
#include <vector>

#include "azt/gnss/gps_fix.hpp"

namespace azt::gnss {

enum class GpsState { Off, NoGpsd, NoFix, Fix2d, Fix3d };

/// "off", "no_gpsd", "no_fix", "fix2d", "fix3d" (the console's and the API's words).
std::string_view to_string(GpsState s);

struct GpsStatus {
  GpsState state = GpsState::Off;
  std::optional<double> lat_deg;  ///< with a 2D or 3D fix
  std::optional<double> lon_deg;
  std::optional<double> alt_m;  ///< with a 3D fix that carried one
  int sats_used = 0;            ///< from the latest SKY (0 when none, or stale)
  int sats_visible = 0;
  std::optional<double> hdop;
  std::optional<double> time_unix_s;  ///< the receiver's UTC of the latest fix that had one
  std::vector<GpsSatellite> satellites;
};

struct GpsMonitorSettings {
  bool enabled = false;
  double stale_after_s = 3.0;
};

class GpsMonitor {
 public:
  explicit GpsMonitor(GpsMonitorSettings settings) : settings_(settings) {}

  /// The adapter reached gpsd. `now_s` is the caller's monotonic clock, in seconds.
  void on_connected(double now_s);
  /// gpsd went away (or could not be reached): what it said is forgotten.
  void on_disconnected(double now_s);
  /// Each TPV, as heard at `now_s`.
  void on_fix(double now_s, const GpsFix& fix);
  /// Each SKY, as heard at `now_s`.
  void on_sky(double now_s, const GpsSky& sky);

  /// The state at `now_s`: Off when not enabled; NoGpsd until connected; NoFix with no TPV, a
  /// TPV older than stale_after_s or one without a fix; else Fix2d / Fix3d. A SKY older than
  /// stale_after_s is left out.
  [[nodiscard]] GpsStatus status(double now_s) const;

 private:
  [[nodiscard]] bool fresh(const std::optional<double>& at_s, double now_s) const;

  GpsMonitorSettings settings_;
  bool connected_ = false;
  std::optional<GpsFix> fix_;
  std::optional<double> fix_at_s_;
  std::optional<GpsSky> sky_;
  std::optional<double> sky_at_s_;
  std::optional<double> time_unix_s_;  ///< the latest TPV's that had one
};

}  // namespace azt::gnss
