#include "azt/calibration/drift_fit.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "azt/calibration/least_squares.hpp"

namespace azt::calibration {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kSiderealDayS = 86164.0905;  // one turn of the Earth against the stars
const double kFourLn2 = 4.0 * std::log(2.0);

/// The path: where the beam stood relative to the source, as a straight line in time.
struct Path {
  double t_mean_s = 0.0;
  SkyOffset mean;      ///< at t_mean_s
  SkyOffset velocity;  ///< degrees per second
};

Path fit_path(const std::vector<DriftBin>& bins) {
  Path p;
  const double n = static_cast<double>(bins.size());
  for (const DriftBin& b : bins) {
    p.t_mean_s += b.t_s / n;
    p.mean.xel_deg += b.pointed.xel_deg / n;
    p.mean.el_deg += b.pointed.el_deg / n;
  }
  double stt = 0.0, stx = 0.0, sty = 0.0;
  for (const DriftBin& b : bins) {
    const double dt = b.t_s - p.t_mean_s;
    stt += dt * dt;
    stx += dt * (b.pointed.xel_deg - p.mean.xel_deg);
    sty += dt * (b.pointed.el_deg - p.mean.el_deg);
  }
  if (stt > 0.0) p.velocity = {stx / stt, sty / stt};
  return p;
}

/// The lowest quarter's mean: a robust first guess of the baseline.
double low_level(std::vector<double> powers) {
  std::sort(powers.begin(), powers.end());
  const std::size_t n = std::max<std::size_t>(powers.size() / 4, 1);
  double sum = 0.0;
  for (std::size_t i = 0; i < n; ++i) sum += powers[i];
  return sum / static_cast<double>(n);
}

/// p(s) = b0 + b1·s + A·exp(−4 ln2 (s − s0)²/w²), s seconds from the path's mean time.
struct TimeGaussian {
  std::vector<double> s, p;
  [[nodiscard]] double model(const std::vector<double>& q, double x) const {
    const double d = x - q[3];
    return q[0] + q[1] * x + q[2] * std::exp(-kFourLn2 * d * d / (q[4] * q[4]));
  }
};

LeastSquaresFit fit_time_gaussian(const TimeGaussian& g, double width_s) {
  const auto top = std::max_element(g.p.begin(), g.p.end()) - g.p.begin();
  const double base = low_level(g.p);
  // Relative residuals: the receiver's noise is a share of the power (so many dB), and a Sun at
  // 25 dB would otherwise let its peak's noise pull the baseline by a few percent.
  const ResidualFunction f = [&g](const std::vector<double>& q, std::vector<double>& r) {
    for (std::size_t i = 0; i < g.s.size(); ++i) r[i] = g.model(q, g.s[i]) / g.p[i] - 1.0;
  };
  const auto i = static_cast<std::size_t>(top);
  LeastSquaresOptions options;
  options.steps = {1e-7 * base, 1e-7 * base / width_s, 1e-7 * base, 1e-6 * width_s, 1e-6 * width_s};
  return fit_least_squares(f, {base, 0.0, g.p[i] - base, g.s[i], width_s}, g.s.size(), options);
}

double rms_db(const TimeGaussian& g, const std::vector<double>& q) {
  double sum = 0.0;
  for (std::size_t i = 0; i < g.s.size(); ++i) {
    const double d = 10.0 * std::log10(g.p[i] / g.model(q, g.s[i]));
    sum += d * d;
  }
  return std::sqrt(sum / static_cast<double>(g.s.size()));
}

/// `peak_s` in the fit's own time (seconds from the path's mean time); `rms` the residuals'
/// relative rms.
Result<bool> check_fit(const DriftFit& f, double peak_s, const TimeGaussian& g, double rms,
                       double beam_deg) {
  const auto [lo, hi] = std::minmax_element(g.s.begin(), g.s.end());
  if (!(f.amplitude > 5.0 * rms * f.baseline)) {
    return fail("no clear peak: the rise is not 5 times the noise (the source missed the beam?)");
  }
  if (peak_s < *lo || peak_s > *hi) return fail("the peak lies outside the recording");
  if (f.width_deg < 0.3 * beam_deg || f.width_deg > 3.0 * beam_deg) {
    return fail("the fitted width is not within 0.3–3 beamwidths");
  }
  return true;
}

}  // namespace

Result<DriftFit> fit_drift(const std::vector<DriftBin>& bins, double beamwidth_deg) {
  if (bins.size() < kMinDriftBins) {
    return fail("too few readings: " + std::to_string(bins.size()) + " intervals (at least " +
                std::to_string(kMinDriftBins) + " needed)");
  }
  const Path path = fit_path(bins);
  DriftFit f;
  f.rate_deg_s = std::hypot(path.velocity.xel_deg, path.velocity.el_deg);
  const double span_deg = f.rate_deg_s * (bins.back().t_s - bins.front().t_s);
  if (!(span_deg > beamwidth_deg)) return fail("the source did not drift across the beam");
  f.direction = {path.velocity.xel_deg / f.rate_deg_s, path.velocity.el_deg / f.rate_deg_s};
  TimeGaussian g;
  for (const DriftBin& b : bins) {
    g.s.push_back(b.t_s - path.t_mean_s);
    g.p.push_back(b.power);
  }
  const LeastSquaresFit lsq = fit_time_gaussian(g, beamwidth_deg / f.rate_deg_s);
  if (!lsq.converged || lsq.singular || lsq.std_errors.size() != 5) {
    return fail("the fit did not converge");
  }
  const auto& q = lsq.params;
  f.peak_s = path.t_mean_s + q[3];
  f.peak_std_s = lsq.std_errors[3];
  f.width_s = std::fabs(q[4]);
  f.width_deg = f.width_s * f.rate_deg_s;
  f.width_std_deg = lsq.std_errors[4] * f.rate_deg_s;
  const SkyOffset at_peak{path.mean.xel_deg + path.velocity.xel_deg * q[3],
                          path.mean.el_deg + path.velocity.el_deg * q[3]};
  f.along_offset_deg = at_peak.xel_deg * f.direction.xel_deg + at_peak.el_deg * f.direction.el_deg;
  f.along_std_deg = f.peak_std_s * f.rate_deg_s;
  f.cross_track_deg = at_peak.el_deg * f.direction.xel_deg - at_peak.xel_deg * f.direction.el_deg;
  f.amplitude = q[2];
  f.baseline = q[0] + q[1] * q[3];
  f.slope_per_s = q[1];
  f.peak_db = 10.0 * std::log10((f.baseline + f.amplitude) / f.baseline);
  f.noise_db = rms_db(g, q);
  f.used = bins.size();
  if (auto ok = check_fit(f, q[3], g, lsq.rms_residual, beamwidth_deg); !ok) return ok.error();
  return f;
}

double sidereal_drift_rate_deg_s(double dec_deg) {
  return 360.0 / kSiderealDayS * std::cos(dec_deg * kPi / 180.0);
}

std::optional<double> drift_az_offset_deg(const DriftFit& fit, double el_deg) {
  if (std::fabs(fit.direction.xel_deg) < 0.5) return std::nullopt;
  const double xel_deg = fit.along_offset_deg / fit.direction.xel_deg;
  return xel_deg / std::cos(el_deg * kPi / 180.0);
}

}  // namespace azt::calibration
