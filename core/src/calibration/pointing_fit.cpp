#include "azt/calibration/pointing_fit.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "azt/calibration/least_squares.hpp"

namespace azt::calibration {
namespace {

constexpr double kMaxTermDeg = 10.0;
constexpr const char* kTermNames[PointingTerms::kCount] = {"IA", "IE", "CA", "NPAE",
                                                           "AN", "AW", "SAG"};

PointingTerms with_free(const PointingTerms& held, const TermMask& mask,
                        const std::vector<double>& free) {
  auto v = held.as_array();
  std::size_t k = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (mask.at(i)) v.at(i) = free[k++];
  }
  return PointingTerms::from_array(v);
}

/// The beam's offsets from each source, (xel, el) pairs.
void offsets(const std::vector<PointingObservation>& obs, const PointingTerms& t,
             std::vector<double>& r) {
  for (std::size_t i = 0; i < obs.size(); ++i) {
    const SkyOffset o = offset_between(obs[i].sky, beam_on_sky(obs[i].mount, t));
    r[2 * i] = o.xel_deg;
    r[2 * i + 1] = o.el_deg;
  }
}

struct Spread {
  double rms = 0.0;
  double max = 0.0;
};

Spread spread(const std::vector<PointingObservation>& obs, const PointingTerms& t) {
  Spread s;
  for (const PointingObservation& o : obs) {
    const double d = separation_deg(o.sky, beam_on_sky(o.mount, t));
    s.rms += d * d;
    s.max = std::max(s.max, d);
  }
  s.rms = obs.empty() ? 0.0 : std::sqrt(s.rms / static_cast<double>(obs.size()));
  return s;
}

}  // namespace

Result<PointingFit> fit_pointing_model(const std::vector<PointingObservation>& observations,
                                       const PointingTerms& start, const TermMask& fit) {
  const auto n_free = static_cast<std::size_t>(std::count(fit.begin(), fit.end(), true));
  if (n_free == 0) return fail("no term to fit");
  if (observations.size() < n_free + 1) {
    return fail("too few sources for " + std::to_string(n_free) +
                " terms: " + std::to_string(observations.size()) + " scans, at least " +
                std::to_string(n_free + 1) + " needed");
  }
  std::vector<double> free;
  const auto start_v = start.as_array();
  for (std::size_t i = 0; i < start_v.size(); ++i) {
    if (fit.at(i)) free.push_back(start_v.at(i));
  }
  const ResidualFunction f = [&](const std::vector<double>& p, std::vector<double>& r) {
    offsets(observations, with_free(start, fit, p), r);
  };
  LeastSquaresOptions options;
  options.steps.assign(n_free, 1e-6);
  const LeastSquaresFit lsq = fit_least_squares(f, free, 2 * observations.size(), options);
  // A term that 0.01° of scan noise would move by more than a degree is not determined.
  const bool weak = std::any_of(lsq.sensitivities.begin(), lsq.sensitivities.end(),
                                [](double s) { return s > 100.0; });
  if (lsq.singular || weak) {
    return fail(
        "the sources do not separate the terms: scan sources spread over azimuth and "
        "elevation, or fit fewer terms");
  }
  PointingFit out;
  out.terms = with_free(start, fit, lsq.params);
  const auto fitted = out.terms.as_array();
  for (std::size_t i = 0; i < fitted.size(); ++i) {
    if (!(std::fabs(fitted.at(i)) <= kMaxTermDeg)) {
      return fail(std::string(kTermNames[i]) + " came out beyond ±10°: the scans disagree");
    }
  }
  std::array<double, PointingTerms::kCount> errors{};
  std::size_t k = 0;
  for (std::size_t i = 0; i < errors.size() && k < lsq.std_errors.size(); ++i) {
    if (fit.at(i)) errors.at(i) = lsq.std_errors[k++];
  }
  out.std_errors = PointingTerms::from_array(errors);
  out.rms_before_deg = spread(observations, start).rms;
  const Spread after = spread(observations, out.terms);
  out.rms_deg = after.rms;
  out.max_deg = after.max;
  out.observations = observations.size();
  return out;
}

}  // namespace azt::calibration
