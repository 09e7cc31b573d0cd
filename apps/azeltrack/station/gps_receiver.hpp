#pragma once
// The station's GPS receiver (docs/gps.md): gpsd through the Linux client, what it says kept by
// the core's GpsMonitor (for the console's `gps` state) and SiteSurvey (the station's position
// from a held fix). Everything runs on the daemon's loop; nothing here waits for gpsd. With
// [gps] use_position, a finished survey (timed by the receiver's clock) is offered to `adopt`
// (which saves and applies it) unless it is a jump of more than jump_m while the station tracks:
// that is logged and shown instead.

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "azt/gnss/gps_monitor.hpp"
#include "azt/gnss/site_survey.hpp"
#include "azt/linux/asio.hpp"
#include "azt/linux/gpsd_client.hpp"
#include "config/gps_config.hpp"

namespace azt::app {

struct GpsReceiverParts {
  GpsConfig config;
  std::function<double()> monotonic_s;
  std::function<bool()> tracking;  ///< the station follows a target: a jump is not adopted
  /// Saves and applies a surveyed site as the station's position; calls `done(true)` once it is
  /// in use (false: the save failed, and the survey is offered again later).
  std::function<void(const gnss::Site&, std::function<void(bool)> done)> adopt;
  std::function<void(const std::string&)> log;
};

class GpsReceiver {
 public:
  GpsReceiver(boost::asio::io_context& io, GpsReceiverParts parts);

  /// The console's `gps`: state, lat_deg, lon_deg, alt_m, sats_used, sats_visible, hdop,
  /// time_utc, position_in_use, satellites, the last jump refused, and the fixes refused as off
  /// the Earth (fixes_refused, last_fix_refused).
  [[nodiscard]] nlohmann::json to_json() const;

 private:
  void on_fix(const gnss::GpsFix& reported);
  /// The fix as the station may use it: one whose place is off the Earth becomes no fix.
  gnss::GpsFix screened(const gnss::GpsFix& reported);
  void offer_survey();

  GpsReceiverParts p_;
  gnss::GpsMonitor monitor_;
  gnss::SiteSurvey survey_;
  std::unique_ptr<linux_os::GpsdClient> client_;  ///< none when [gps] is not enabled
  std::optional<gnss::Site> in_use_;              ///< the site adopted from the GPS this run
  std::optional<gnss::Site> refused_;             ///< the latest jump not adopted while tracking
  bool adopting_ = false;
  std::uint64_t fixes_refused_ = 0;
  std::string last_fix_refused_;
  bool refusing_ = false;  ///< the latest fix was refused: a run of them is logged once
};

}  // namespace azt::app
