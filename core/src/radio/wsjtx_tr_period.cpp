#include "azt/radio/wsjtx_tr_period.hpp"

#include <array>
#include <utility>

namespace azt::radio {
namespace {

// The periods WSJT-X fixes, by the name its Status gives the mode (wsjtx_tr_period.hpp cites
// each one's line of widgets/mainwindow.cpp).
constexpr std::array<std::pair<std::string_view, double>, 6> kFixedPeriods{{
    {"FT8", 15.0},
    {"FT4", 7.5},
    {"JT4", 60.0},
    {"JT9", 60.0},
    {"JT65", 60.0},
    {"WSPR", 120.0},
}};

}  // namespace

std::optional<double> mode_tr_period_s(std::string_view mode, bool fast_mode) {
  if (fast_mode && mode == "JT9") return std::nullopt;
  for (const auto& [name, period_s] : kFixedPeriods) {
    if (name == mode) return period_s;
  }
  return std::nullopt;
}

std::optional<double> tr_period_s(const WsjtxStatus& status) {
  if (status.periods && status.periods->tr_period_s != kWsjtxNotApplicable &&
      status.periods->tr_period_s != 0) {
    return static_cast<double>(status.periods->tr_period_s);
  }
  return mode_tr_period_s(status.mode, status.sub_mode && status.sub_mode->fast_mode);
}

}  // namespace azt::radio
