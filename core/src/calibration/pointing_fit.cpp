#include "azt/calibration/pointing_fit.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <string>

#include "azt/calibration/least_squares.hpp"
#include "azt/util/format_number.hpp"

namespace azt::calibration {
namespace {

constexpr std::size_t kN = PointingTerms::kCount;
constexpr double kMaxTermDeg = 10.0;
constexpr double kStepDeg = 1e-6;  ///< the Jacobian's forward difference

bool counts(const PointingObservation& o) {
  return o.weight > 0.0 && std::isfinite(o.weight) && (o.has_xel || o.has_el);
}

/// Each measured offset's factor in χ²: √weight, times σ_ref/σ when every measured offset has
/// its σ (σ_ref their rms, so the factors stay relative and the residuals stay in degrees).
struct Factors {
  std::vector<SkyOffset> of;
};

Factors factors(const std::vector<PointingObservation>& used) {
  const bool by_sigma = std::all_of(used.begin(), used.end(), [](const PointingObservation& o) {
    return (!o.has_xel || o.sigma.xel_deg > 0.0) && (!o.has_el || o.sigma.el_deg > 0.0);
  });
  double sum = 0.0, n = 0.0;
  for (const PointingObservation& o : used) {
    if (o.has_xel) sum += o.sigma.xel_deg * o.sigma.xel_deg, n += 1.0;
    if (o.has_el) sum += o.sigma.el_deg * o.sigma.el_deg, n += 1.0;
  }
  const double ref = n > 0.0 ? std::sqrt(sum / n) : 1.0;
  Factors f;
  for (const PointingObservation& o : used) {
    const double w = std::sqrt(o.weight);
    f.of.push_back({by_sigma && o.has_xel ? w * ref / o.sigma.xel_deg : w,
                    by_sigma && o.has_el ? w * ref / o.sigma.el_deg : w});
  }
  return f;
}

std::size_t components(const std::vector<PointingObservation>& used) {
  std::size_t n = 0;
  for (const PointingObservation& o : used) n += (o.has_xel ? 1U : 0U) + (o.has_el ? 1U : 0U);
  return n;
}

/// The measured offsets of the beam from each source, times their factors.
void weighted_offsets(const std::vector<PointingObservation>& used, const Factors& f,
                      const PointingTerms& t, std::vector<double>& r) {
  std::size_t k = 0;
  for (std::size_t i = 0; i < used.size(); ++i) {
    const SkyOffset o = offset_between(used[i].sky, beam_on_sky(used[i].mount, t));
    if (used[i].has_xel) r[k++] = o.xel_deg * f.of[i].xel_deg;
    if (used[i].has_el) r[k++] = o.el_deg * f.of[i].el_deg;
  }
}

/// JᵀJ for all seven terms at `at` (forward differences), 7×7 row-major.
std::vector<double> normal_matrix(const std::vector<PointingObservation>& used, const Factors& f,
                                  const PointingTerms& at) {
  const std::size_t n = components(used);
  std::vector<double> r0(n), r(n), jac(n * kN), out(kN * kN, 0.0);
  weighted_offsets(used, f, at, r0);
  for (std::size_t j = 0; j < kN; ++j) {
    auto v = at.as_array();
    v.at(j) += kStepDeg;
    weighted_offsets(used, f, PointingTerms::from_array(v), r);
    for (std::size_t i = 0; i < n; ++i) jac[i * kN + j] = (r[i] - r0[i]) / kStepDeg;
  }
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t a = 0; a < kN; ++a) {
      for (std::size_t b = 0; b < kN; ++b) out[a * kN + b] += jac[i * kN + a] * jac[i * kN + b];
    }
  }
  return out;
}

CoverageSpan span_of(const std::vector<PointingObservation>& used) {
  CoverageSpan s{90.0, -90.0, 0.0};
  std::vector<double> az;
  for (const PointingObservation& o : used) {
    s.min_el_deg = std::min(s.min_el_deg, o.sky.el_deg);
    s.max_el_deg = std::max(s.max_el_deg, o.sky.el_deg);
    az.push_back(o.sky.az_deg);
  }
  s.az_arc_deg = azimuth_arc_deg(az);
  return s;
}

PointingTerms with_free(const PointingTerms& held, const TermMask& mask,
                        const std::vector<double>& free) {
  auto v = held.as_array();
  std::size_t k = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (mask.at(i)) v.at(i) = free[k++];
  }
  return PointingTerms::from_array(v);
}

struct Spread {
  double rms = 0.0;
  double max = 0.0;
};

/// The offsets on the sky, as measured (both components of a whole scan, one of a line).
Spread spread(const std::vector<PointingObservation>& obs, const PointingTerms& t) {
  Spread s;
  double measured = 0.0;
  for (const PointingObservation& o : obs) {
    const SkyOffset off = offset_between(o.sky, beam_on_sky(o.mount, t));
    const double x = o.has_xel ? off.xel_deg : 0.0, y = o.has_el ? off.el_deg : 0.0;
    s.rms += x * x + y * y;
    s.max = std::max(s.max, std::hypot(x, y));
    measured += (o.has_xel ? 0.5 : 0.0) + (o.has_el ? 0.5 : 0.0);
  }
  s.rms = measured == 0.0 ? 0.0 : std::sqrt(s.rms / measured);
  return s;
}

/// The fitted terms' least squares from `start`.
LeastSquaresFit solve(const std::vector<PointingObservation>& used, const Factors& f,
                      const PointingTerms& start, const TermMask& mask) {
  std::vector<double> free;
  const auto start_v = start.as_array();
  for (std::size_t i = 0; i < kN; ++i) {
    if (mask.at(i)) free.push_back(start_v.at(i));
  }
  const ResidualFunction residuals = [&](const std::vector<double>& p, std::vector<double>& r) {
    weighted_offsets(used, f, with_free(start, mask, p), r);
  };
  LeastSquaresOptions options;
  options.steps.assign(free.size(), kStepDeg);
  return fit_least_squares(residuals, free, components(used), options);
}

/// The last term in the fitting order whose sensitivity in the whole fit is too large (the
/// terms fitted together can leave one undetermined that each alone would not); kN: none.
std::size_t weakest(const LeastSquaresFit& lsq, const TermMask& mask, double max_sensitivity) {
  std::array<double, kN> sensitivity{};
  std::size_t k = 0;
  for (std::size_t i = 0; i < kN && k < lsq.sensitivities.size(); ++i) {
    if (mask.at(i)) sensitivity.at(i) = lsq.sensitivities[k++];
  }
  for (auto it = kTermOrder.rbegin(); it != kTermOrder.rend(); ++it) {
    if (mask.at(*it) && (lsq.singular || sensitivity.at(*it) > max_sensitivity)) return *it;
  }
  return kN;
}

std::string undetermined_together(const LeastSquaresFit& lsq, const TermMask& mask, std::size_t j) {
  if (lsq.singular) return "the scans cannot separate it from the other fitted terms";
  std::size_t k = 0;
  for (std::size_t i = 0; i < j; ++i) k += mask.at(i) ? 1U : 0U;
  return "with the other fitted terms the scans barely determine it: 0.01° of scan noise would "
         "move it by " +
         format_fixed(0.01 * lsq.sensitivities.at(k), 3) + "°";
}

std::string nothing_to_fit(const std::array<std::string, kN>& held) {
  std::string out = "no term can be fitted:";
  for (std::size_t i = 0; i < kN; ++i)
    out += std::string(" ") + term_name(i) + ": " + held.at(i) + ";";
  out.pop_back();
  return out;
}

PointingFit result_of(const std::vector<PointingObservation>& obs,
                      const std::vector<PointingObservation>& used, const PointingTerms& start,
                      const TermSelection& sel, const LeastSquaresFit& lsq) {
  PointingFit out;
  out.terms = with_free(start, sel.fitted, lsq.params);
  std::array<double, kN> errors{};
  std::size_t k = 0;
  for (std::size_t i = 0; i < kN && k < lsq.std_errors.size(); ++i) {
    if (sel.fitted.at(i)) errors.at(i) = lsq.std_errors[k++];
  }
  out.std_errors = PointingTerms::from_array(errors);
  out.held = sel.held;
  out.rms_before_deg = spread(used, start).rms;
  const Spread after = spread(used, out.terms);
  out.rms_deg = after.rms;
  out.max_deg = after.max;
  out.observations = components(used) / 2;
  for (const PointingObservation& o : obs) {
    out.residuals.push_back({offset_between(o.sky, beam_on_sky(o.mount, start)),
                             offset_between(o.sky, beam_on_sky(o.mount, out.terms)), counts(o)});
  }
  return out;
}

}  // namespace

Result<PointingFit> fit_pointing_model(const std::vector<PointingObservation>& observations,
                                       const PointingTerms& start, const FitOptions& options) {
  std::vector<PointingObservation> used;
  std::copy_if(observations.begin(), observations.end(), std::back_inserter(used), counts);
  const std::size_t scans = components(used) / 2;
  if (scans < options.min_scans) {
    return fail("too few scans to fit: " + std::to_string(scans) + ", at least " +
                std::to_string(options.min_scans) + " needed");
  }
  const Factors f = factors(used);
  TermSelection sel = select_terms(normal_matrix(used, f, start), options.fit, scans, span_of(used),
                                   options.limits);
  for (std::size_t round = 0; round <= kN; ++round) {
    if (std::none_of(sel.fitted.begin(), sel.fitted.end(), [](bool b) { return b; })) {
      return fail(nothing_to_fit(sel.held));
    }
    const LeastSquaresFit lsq = solve(used, f, start, sel.fitted);
    const std::size_t weak = weakest(lsq, sel.fitted, options.limits.max_sensitivity);
    if (weak < kN) {
      sel.held.at(weak) = undetermined_together(lsq, sel.fitted, weak);
      sel.fitted.at(weak) = false;
      continue;
    }
    if (!lsq.converged) return fail("the fit did not converge: the scans disagree");
    PointingFit out = result_of(observations, used, start, sel, lsq);
    const auto fitted = out.terms.as_array();
    for (std::size_t i = 0; i < kN; ++i) {
      if (!(std::fabs(fitted.at(i)) <= kMaxTermDeg)) {
        return fail(std::string(term_name(i)) + " came out beyond ±10°: the scans disagree");
      }
    }
    return out;
  }
  return fail("no term can be fitted");
}

}  // namespace azt::calibration
