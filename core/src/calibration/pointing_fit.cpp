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

/// Every measured offset has its standard error: weight by them.
bool weighted(const std::vector<PointingObservation>& obs) {
  return std::all_of(obs.begin(), obs.end(), [](const PointingObservation& o) {
    return (!o.has_xel || o.sigma.xel_deg > 0.0) && (!o.has_el || o.sigma.el_deg > 0.0);
  });
}

/// The beam's offsets from each source, (xel, el) pairs, divided by their standard errors when
/// `by_sigma`.
void offsets(const std::vector<PointingObservation>& obs, const PointingTerms& t, bool by_sigma,
             std::vector<double>& r) {
  for (std::size_t i = 0; i < obs.size(); ++i) {
    const SkyOffset o = offset_between(obs[i].sky, beam_on_sky(obs[i].mount, t));
    const double wx = by_sigma && obs[i].has_xel ? 1.0 / obs[i].sigma.xel_deg : 1.0;
    const double wy = by_sigma && obs[i].has_el ? 1.0 / obs[i].sigma.el_deg : 1.0;
    r[2 * i] = obs[i].has_xel ? o.xel_deg * wx : 0.0;
    r[2 * i + 1] = obs[i].has_el ? o.el_deg * wy : 0.0;
  }
}

/// The rms of the standard errors (to turn weighted sensitivities back into degrees per degree).
double rms_sigma(const std::vector<PointingObservation>& obs) {
  double sum = 0.0, n = 0.0;
  for (const PointingObservation& o : obs) {
    if (o.has_xel) sum += o.sigma.xel_deg * o.sigma.xel_deg, n += 1.0;
    if (o.has_el) sum += o.sigma.el_deg * o.sigma.el_deg, n += 1.0;
  }
  return n > 0.0 ? std::sqrt(sum / n) : 1.0;
}

struct Spread {
  double rms = 0.0;
  double max = 0.0;
};

/// The offsets on the sky, as measured (both components of a whole scan, one of a line).
Spread spread(const std::vector<PointingObservation>& obs, const PointingTerms& t) {
  Spread s;
  double components = 0.0;
  for (const PointingObservation& o : obs) {
    const SkyOffset off = offset_between(o.sky, beam_on_sky(o.mount, t));
    const double x = o.has_xel ? off.xel_deg : 0.0, y = o.has_el ? off.el_deg : 0.0;
    s.rms += x * x + y * y;
    s.max = std::max(s.max, std::hypot(x, y));
    components += (o.has_xel ? 0.5 : 0.0) + (o.has_el ? 0.5 : 0.0);
  }
  s.rms = components == 0.0 ? 0.0 : std::sqrt(s.rms / components);
  return s;
}

/// Measured offsets, in scans' worth (a scan measures two).
std::size_t scans_worth(const std::vector<PointingObservation>& obs) {
  std::size_t n = 0;
  for (const PointingObservation& o : obs) n += (o.has_xel ? 1U : 0U) + (o.has_el ? 1U : 0U);
  return n / 2;
}

}  // namespace

Result<PointingFit> fit_pointing_model(const std::vector<PointingObservation>& observations,
                                       const PointingTerms& start, const TermMask& fit) {
  const auto n_free = static_cast<std::size_t>(std::count(fit.begin(), fit.end(), true));
  if (n_free == 0) return fail("no term to fit");
  const std::size_t scans = scans_worth(observations);
  if (scans < n_free + 1) {
    return fail("too few sources for " + std::to_string(n_free) +
                " terms: " + std::to_string(scans) + " scans, at least " +
                std::to_string(n_free + 1) + " needed");
  }
  std::vector<double> free;
  const auto start_v = start.as_array();
  for (std::size_t i = 0; i < start_v.size(); ++i) {
    if (fit.at(i)) free.push_back(start_v.at(i));
  }
  const bool by_sigma = weighted(observations);
  const ResidualFunction f = [&](const std::vector<double>& p, std::vector<double>& r) {
    offsets(observations, with_free(start, fit, p), by_sigma, r);
  };
  LeastSquaresOptions options;
  options.steps.assign(n_free, 1e-6);
  const LeastSquaresFit lsq = fit_least_squares(f, free, 2 * observations.size(), options);
  // A term that 0.01° of scan noise would move by more than a degree is not determined.
  const double to_degrees = by_sigma ? rms_sigma(observations) : 1.0;
  const bool weak = std::any_of(lsq.sensitivities.begin(), lsq.sensitivities.end(),
                                [to_degrees](double s) { return s * to_degrees > 100.0; });
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
  out.observations = scans;
  return out;
}

}  // namespace azt::calibration
