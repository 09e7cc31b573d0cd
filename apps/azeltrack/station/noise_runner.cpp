#include "station/noise_runner.hpp"

#include <utility>
#include <vector>

#include "azt/calibration/pointing_model.hpp"

namespace azt::app {

using nlohmann::json;

Result<bool> NoiseRunner::ready(double now_s) const {
  if (feed_ == nullptr) return fail("no receiver: set [receiver] to measure noise");
  if (feed_->stale(now_s)) return fail("the receiver is silent: no reading to measure with");
  return true;
}

Result<bool> NoiseRunner::start(const std::string& source, const calibration::NoisePlan& plan,
                                const calibration::ScanTiming& timing,
                                const std::optional<NoiseExpected>& expected, double now_s) {
  if (auto ok = ready(now_s); !ok) return ok;
  auto m = calibration::NoiseMeasurement::start(plan, timing, now_s);
  if (!m) return m.error();
  measurement_ = std::move(m).value();
  last_.reset();
  expected_ = expected;
  result_.reset();
  sky_.reset();
  source_ = source;
  state_ = "running";
  reason_.clear();
  last_reading_s_ = now_s;
  return true;
}

void NoiseRunner::stop(const std::string& why) {
  if (!measurement_) return;
  last_ = std::move(measurement_);
  measurement_.reset();
  state_ = "stopped";
  reason_ = why;
}

std::optional<control::AzEl> NoiseRunner::aim(const control::AzEl& source_now) const {
  if (!measurement_) return std::nullopt;
  const auto offset = measurement_->offset();
  if (!offset) return std::nullopt;
  return calibration::apply_offset(source_now, *offset);
}

void NoiseRunner::tick(double now_s, bool driving, const std::optional<control::AzEl>& encoders,
                       const std::optional<control::AzEl>& source_now) {
  if (!measurement_) return;
  if (source_now) sky_ = source_now;
  measurement_->tick(now_s, driving, encoders);
  // The readings that arrived since the last tick (oldest first), each passed on once.
  const std::vector<calibration::PowerReading> fresh = feed_->readings_since(last_reading_s_);
  for (const calibration::PowerReading& r : fresh) {
    if (r.t_s > last_reading_s_) measurement_->reading(r.power_db);
  }
  if (!fresh.empty()) last_reading_s_ = fresh.back().t_s;
  if (measurement_->done()) finish();
}

void NoiseRunner::finish() {
  last_ = std::move(measurement_);
  measurement_.reset();
  auto r = last_->result();
  if (!r) {
    state_ = "refused";
    reason_ = r.error().message;
    return;
  }
  state_ = "done";
  result_ = *r;
  if (record_) record_(result_json());
}

/// The finished measurement as the log keeps it: the source and where it was, the plan, the
/// Y-factor and, when the station and flux were given, what was expected and the figure of merit.
json NoiseRunner::result_json() const {
  const calibration::NoisePlan& plan = last_->plan();
  json j{{"source", source_},
         {"az_deg", sky_ ? json(sky_->az_deg) : json(nullptr)},
         {"el_deg", sky_ ? json(sky_->el_deg) : json(nullptr)},
         {"beamwidth_deg", plan.beamwidth_deg},
         {"offset_beams", plan.offset_beams},
         {"repeats", plan.repeats},
         {"y_factor_db", result_->y_db},
         {"std_error_db", result_->std_error_db},
         {"pairs", result_->pair_y_db.size()},
         {"pair_y_db", result_->pair_y_db},  // each on/off pair's Y: the scatter the console plots
         {"missed", result_->missed}};
  if (!expected_) return j;
  const auto x = calibration::expected_noise(expected_->station, expected_->source);
  if (!x) return j;
  j["expected"] = {
      {"y_db", x->y_db},
      {"flux_sfu", x->flux_jy / calibration::kJanskyPerSfu},
      {"antenna_k", x->antenna_k},
      {"size_factor", x->size_factor},
      {"g_over_t_db", calibration::g_over_t_db(result_->y_db, x->flux_jy,
                                               expected_->station.freq_mhz, x->size_factor)},
      {"implied_tsys_k", calibration::implied_tsys_k(result_->y_db, x->antenna_k)}};
  return j;
}

json NoiseRunner::to_json() const {
  const calibration::NoiseMeasurement* m =
      measurement_ ? &*measurement_ : (last_ ? &*last_ : nullptr);
  json j{{"state", state_}, {"source", source_}, {"reason", reason_}};
  if (m == nullptr) return j;
  j["plan"] = {{"beamwidth_deg", m->plan().beamwidth_deg},
               {"offset_beams", m->plan().offset_beams},
               {"repeats", m->plan().repeats}};
  j["steps_done"] = m->steps_done();
  j["steps_total"] = m->steps().size();
  json steps = json::array();
  for (std::size_t i = 0; i < m->steps_done(); ++i) {
    const calibration::NoiseStep& s = m->steps()[i];
    steps.push_back({{"on", s.on},
                     {"side", s.side},
                     {"power_db", s.power_db ? json(*s.power_db) : json(nullptr)},
                     {"readings", s.readings}});
  }
  j["steps"] = steps;
  if (result_) j["result"] = result_json();
  return j;
}

}  // namespace azt::app
