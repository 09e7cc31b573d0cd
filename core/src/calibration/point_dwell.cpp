#include "azt/calibration/point_dwell.hpp"

#include <cmath>

namespace azt::calibration {

void PointDwell::note_stillness(double now_s, bool driving,
                                const std::optional<control::AzEl>& encoders) {
  const bool unchanged = encoders && last_encoders_ && encoders->az_deg == last_encoders_->az_deg &&
                         encoders->el_deg == last_encoders_->el_deg;
  if (!unchanged || driving) still_since_s_.reset();
  if (unchanged && !driving && !still_since_s_) still_since_s_ = now_s;
  if (!unchanged) last_encoders_ = encoders;
  still_ = still_since_s_ && now_s - *still_since_s_ >= kStillS;
}

void PointDwell::tick(double now_s, bool driving, const std::optional<control::AzEl>& encoders) {
  if (finished_) return;
  note_stillness(now_s, driving, encoders);
  if (!dwelling_) {
    if (still_since_s_ && now_s - *still_since_s_ >= timing_.settle_s) {
      dwelling_ = true;
    } else if (now_s - start_s_ > timing_.max_settle_s) {
      finished_ = true;  // missed
    }
  } else {
    if (still_) dwelt_s_ += now_s - last_tick_s_;
    // A mount that never stands still long enough (wind) ends the dwell with what it has.
    finished_ = dwelt_s_ >= timing_.dwell_s ||
                now_s - start_s_ > timing_.max_settle_s + 3.0 * timing_.dwell_s;
  }
  last_tick_s_ = now_s;
}

bool PointDwell::reading(double power_db) {
  if (finished_ || !dwelling_ || !still_ || !std::isfinite(power_db)) return false;
  power_sum_ += std::pow(10.0, power_db / 10.0);
  ++readings_;
  return true;
}

std::optional<double> PointDwell::mean_db() const {
  if (readings_ == 0) return std::nullopt;
  return 10.0 * std::log10(power_sum_ / readings_);
}

}  // namespace azt::calibration
