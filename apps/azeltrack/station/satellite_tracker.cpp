#include "station/satellite_tracker.hpp"

#include <cmath>
#include <memory>

#include "azt/track/satellite_pass_track.hpp"

namespace azt::app {
namespace {

constexpr double kSearchHours = 48.0;
constexpr double kRetryS = 600.0;

/// The log's word on a pass the mount cannot fly on the satellite throughout.
std::string loss_note(const track::PassPlan& plan) {
  if (plan.loss_s <= 0.0) return "";
  return ", " + std::to_string(std::lround(plan.loss_s)) + " s planned beyond " +
         std::to_string(std::lround(plan.loss_error_deg)) + "° from " +
         astro::format_iso8601_utc_unix(plan.loss_from_s);
}

}  // namespace

SatelliteTracker::SatelliteTracker(SatelliteSettings settings,
                                   std::function<void(const std::string&)> log)
    : s_(std::move(settings)), log_(std::move(log)) {}

void SatelliteTracker::adopt(SatelliteCatalogue catalogue, double unix_s) {
  catalogue_ = std::move(catalogue);
  upcoming_.clear();
  // The followed satellite's new elements give a new plan (not mid-pass: the old one finishes).
  if (planned_ && unix_s >= planned_->pass.aos_s) return;
  planned_.reset();
  next_plan_s_ = -1e9;
}

const orbit::Satellite* SatelliteTracker::current() const {
  if (!following_) return nullptr;
  for (const auto& s : catalogue_.satellites()) {
    if (s.elements.catalog == *following_) return &s;
  }
  return nullptr;
}

Result<std::string> SatelliteTracker::follow(const std::string& name_or_norad, double unix_s,
                                             double mount_az_deg) {
  const orbit::Satellite* sat = nullptr;
  try {
    sat = &catalogue_.find(name_or_norad);
  } catch (const std::exception& e) {
    return fail(e.what());
  }
  const double age = element_age_days(sat->elements, astro::UtcInstant::from_unix_seconds(unix_s));
  if (std::string why = orbit::element_age_refusal(sat->elements.label(), age, s_.age);
      !why.empty()) {
    return fail(why);
  }
  following_ = sat->elements.catalog;
  planned_.reset();
  next_plan_s_ = -1e9;
  problem_.clear();
  plan_next(unix_s, mount_az_deg);
  return sat->elements.label();
}

void SatelliteTracker::plan_next(double unix_s, double mount_az_deg) {
  const orbit::Satellite* sat = current();
  if (sat == nullptr || unix_s < next_plan_s_) return;
  const astro::UtcInstant from = astro::UtcInstant::from_unix_seconds(unix_s);
  // Elements that aged past refuse_days while followed are not flown: the antenna would point
  // where the satellite is not. Fresh ones from the feed lift this at its next publish.
  problem_ = orbit::element_age_refusal(sat->elements.label(),
                                        element_age_days(sat->elements, from), s_.age);
  if (!problem_.empty()) {
    next_plan_s_ = unix_s + kRetryS;
    return;
  }
  auto passes = find_satellite_passes(*sat, from, kSearchHours, s_.mask, s_.dut1_s, s_.site);
  next_plan_s_ = unix_s + kRetryS;
  if (!passes || passes.value().empty()) {
    problem_ = passes ? "no pass in the next 48 h" : passes.error().message;
    return;
  }
  const orbit::Pass& p = passes.value().front();
  Planned next;
  next.pass = p;
  // Sampled every second from AOS (or now, mid-pass) to LOS, in Unix seconds.
  auto sky = track::sample_pass(*sat, from, p, s_.dut1_s, s_.site, unix_s);
  if (!sky) {
    problem_ = sky.error().message;
    return;
  }
  next.sky = std::move(sky).value();
  if (next.sky.size() < 2) {
    problem_ = "the pass is too short to plan";
    return;
  }
  auto plan = track::plan_pass(next.sky, s_.mount, mount_az_deg);
  if (!plan) {
    problem_ = plan.error().message;
    return;
  }
  next.plan = std::move(plan).value();
  for (double* t : {&next.pass.aos_s, &next.pass.tca_s, &next.pass.los_s}) *t += unix_s;
  log_("satellites: " + sat->elements.label() + " next pass AOS " +
       astro::format_iso8601_utc_unix(next.pass.aos_s) + ", max el " +
       std::to_string(static_cast<int>(std::lround(p.max_el_deg))) + "°" +
       (next.plan.flip ? ", flipped" : "") + loss_note(next.plan));
  problem_.clear();
  planned_ = std::move(next);
}

void SatelliteTracker::set_site(const astro::Observer& site) {
  s_.site = site;
  for (auto& u : upcoming_) u.at_s = -1e9;
  site_changed_ = true;
  next_plan_s_ = -1e9;
}

control::Demand SatelliteTracker::demand(double unix_s, double mount_az_deg, control::AzEl& rate) {
  rate = control::AzEl{};
  if (planned_ && unix_s > planned_->pass.los_s) planned_.reset();
  if (planned_ && site_changed_ && unix_s < planned_->pass.aos_s) planned_.reset();
  if (!planned_) site_changed_ = false;
  if (!planned_) plan_next(unix_s, mount_az_deg);
  control::Demand d;
  if (!planned_) {
    d.reason = "satellite: " + problem_;
    return d;
  }
  const track::MountPoint here = planned_->plan.at(unix_s);
  d.position = control::AzEl{here.az_deg, here.el_deg};
  d.mount = true;
  if (unix_s >= planned_->pass.aos_s) {
    const track::MountPoint ahead = planned_->plan.at(unix_s + 1.0);
    rate = control::AzEl{ahead.az_deg - here.az_deg, ahead.el_deg - here.el_deg};
    d.reason = "tracking pass";
  } else {
    d.reason = "pre-positioned for AOS";
  }
  return d;
}

nlohmann::json SatelliteTracker::status(double unix_s) const {
  const orbit::Satellite* sat = current();
  if (sat == nullptr) return nullptr;
  const double age = element_age_days(sat->elements, astro::UtcInstant::from_unix_seconds(unix_s));
  const std::string refusal = orbit::element_age_refusal(sat->elements.label(), age, s_.age);
  nlohmann::json j{
      {"sat", sat->elements.label()},
      {"norad", sat->elements.catalog},
      {"element_age_days", age},
      {"stale", orbit::judge_element_age(age, s_.age) != orbit::ElementAge::Fresh},
      {"refused", refusal.empty() ? nlohmann::json() : nlohmann::json(refusal)},
      {"problem", problem_.empty() ? nlohmann::json(nullptr) : nlohmann::json(problem_)}};
  if (auto l = look(*sat, astro::UtcInstant::from_unix_seconds(unix_s), s_.dut1_s, s_.site)) {
    j["az_deg"] = l->az_deg;
    j["el_deg"] = l->el_deg;
    j["range_km"] = l->range_km;
    j["range_rate_km_s"] = l->range_rate_km_s;
  }
  if (planned_) {
    // Where the antenna is meant to point now: the satellite during the pass, where the pass
    // starts before it (so the console's pointing error means something while waiting).
    const track::SkyPoint aim = track::mount_to_sky(planned_->plan.at(unix_s));
    j["aim_az_deg"] = aim.az_deg;
    j["aim_el_deg"] = aim.el_deg;
    j["phase"] = unix_s < planned_->pass.aos_s ? "waiting for AOS" : "tracking";
    j["aos"] = astro::format_iso8601_utc_unix(planned_->pass.aos_s);
    j["tca"] = astro::format_iso8601_utc_unix(planned_->pass.tca_s);
    j["los"] = astro::format_iso8601_utc_unix(planned_->pass.los_s);
    j["max_el_deg"] = planned_->pass.max_el_deg;
    j["flip"] = planned_->plan.flip;
    j["planned_max_error_deg"] = planned_->plan.max_error_deg;
    // The planned loss, known before AOS: how long the beam will be further than half the
    // beamwidth from the satellite (a swing through the travel, or a wait at a stop), and when.
    const track::PassPlan& plan = planned_->plan;
    j["planned_loss"] = {
        {"seconds", plan.loss_s},
        {"beyond_deg", plan.loss_error_deg},
        {"from", plan.loss_s > 0.0
                     ? nlohmann::json(astro::format_iso8601_utc_unix(plan.loss_from_s))
                     : nullptr},
        {"to", plan.loss_s > 0.0 ? nlohmann::json(astro::format_iso8601_utc_unix(plan.loss_to_s))
                                 : nullptr}};
  } else {
    j["phase"] = "no pass planned";
  }
  return j;
}

void SatelliteTracker::refresh_passes(double unix_s) {
  const auto& sats = catalogue_.satellites();
  if (sats.empty()) return;
  if (upcoming_.size() != sats.size()) upcoming_.assign(sats.size(), Upcoming{});
  next_refresh_ %= sats.size();
  Upcoming& u = upcoming_[next_refresh_];
  const orbit::Satellite& sat = sats[next_refresh_];
  next_refresh_ = (next_refresh_ + 1) % sats.size();
  if (unix_s - u.at_s < 60.0) return;  // each satellite's list at most once a minute
  u.at_s = unix_s;
  u.passes = nlohmann::json::array();
  const astro::UtcInstant now = astro::UtcInstant::from_unix_seconds(unix_s);
  auto passes = find_satellite_passes(sat, now, 24.0, s_.mask, s_.dut1_s, s_.site);
  if (!passes) return;
  for (const auto& p : passes.value()) {
    if (p.max_el_deg < s_.list_min_el_deg) continue;
    // A pass predicted from stale elements is marked: its times may be tens of seconds off.
    const double age = element_age_days(sat.elements, astro::utc_plus(now, p.aos_s));
    u.passes.push_back(
        {{"stale", orbit::judge_element_age(age, s_.age) != orbit::ElementAge::Fresh},
         {"aos", astro::format_iso8601_utc_unix(unix_s + p.aos_s)},
         {"tca", astro::format_iso8601_utc_unix(unix_s + p.tca_s)},
         {"los", astro::format_iso8601_utc_unix(unix_s + p.los_s)},
         {"max_el_deg", p.max_el_deg},
         {"aos_az_deg", p.aos_az_deg},
         {"los_az_deg", p.los_az_deg}});
  }
}

nlohmann::json SatelliteTracker::list(double unix_s) const {
  nlohmann::json out = nlohmann::json::array();
  const astro::UtcInstant now = astro::UtcInstant::from_unix_seconds(unix_s);
  const auto& sats = catalogue_.satellites();
  for (std::size_t i = 0; i < sats.size(); ++i) {
    const orbit::Satellite& sat = sats[i];
    // Where it is now costs one propagation; the passes come from refresh_passes().
    const double age = element_age_days(sat.elements, now);
    const std::string refusal = orbit::element_age_refusal(sat.elements.label(), age, s_.age);
    nlohmann::json j{{"name", sat.elements.label()},
                     {"norad", sat.elements.catalog},
                     {"element_age_days", age},
                     {"stale", orbit::judge_element_age(age, s_.age) != orbit::ElementAge::Fresh},
                     {"refused", refusal.empty() ? nlohmann::json() : nlohmann::json(refusal)}};
    if (auto l = look(sat, now, s_.dut1_s, s_.site)) {
      j["az_deg"] = l->az_deg;
      j["el_deg"] = l->el_deg;
    } else {
      j["error"] = l.error().message;
    }
    const nlohmann::json passes = i < upcoming_.size() && !upcoming_[i].passes.is_null()
                                      ? upcoming_[i].passes
                                      : nlohmann::json::array();
    if (!passes.empty()) j["next_pass"] = passes.front();
    j["passes"] = passes;
    out.push_back(std::move(j));
  }
  return out;
}

nlohmann::json SatelliteTracker::pass_track() const {
  nlohmann::json out = nlohmann::json::array();
  if (!planned_) return out;
  const auto& sky = planned_->sky;
  for (std::size_t i = 0; i < sky.size(); i += 10) {
    out.push_back({{"utc", astro::format_iso8601_utc_unix(sky[i].t_s)},
                   {"az_deg", sky[i].az_deg},
                   {"el_deg", sky[i].el_deg}});
  }
  // The end of the pass too, so a short (grazing) pass still draws as a line from AOS to LOS.
  if (sky.size() > 1 && (sky.size() - 1) % 10 != 0) {
    const auto& s = sky.back();
    out.push_back({{"utc", astro::format_iso8601_utc_unix(s.t_s)},
                   {"az_deg", s.az_deg},
                   {"el_deg", s.el_deg}});
  }
  return out;
}

}  // namespace azt::app
