#include "azt/calibration/scan_fit.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "azt/calibration/least_squares.hpp"
#include "azt/util/format_number.hpp"

namespace azt::calibration {
namespace {

const double kFourLn2 = 4.0 * std::log(2.0);

struct Point {
  SkyOffset planned;
  double x = 0.0;  ///< where the antenna pointed
  double y = 0.0;
  double power = 0.0;  ///< linear
};

double linear(double db) { return std::pow(10.0, db / 10.0); }
double to_db(double ratio) { return 10.0 * std::log10(ratio); }

/// The good readings, as linear power; counts the missing ones.
std::vector<Point> good_points(const std::vector<ScanSample>& samples, std::size_t& missing) {
  std::vector<Point> out;
  for (const ScanSample& s : samples) {
    if (s.power_db && std::isfinite(*s.power_db)) {
      const SkyOffset at = s.pointed.value_or(s.point.offset);
      out.push_back({s.point.offset, at.xel_deg, at.el_deg, linear(*s.power_db)});
    } else {
      ++missing;
    }
  }
  return out;
}

Error too_few(std::size_t good, std::size_t missing, std::size_t needed, const char* what) {
  return fail(std::string("too few good readings ") + what + ": " + std::to_string(good) + " of " +
              std::to_string(good + missing) + " (" + std::to_string(missing) +
              " missing or malformed; at least " + std::to_string(needed) + " needed)");
}

/// The lowest quarter's mean: a robust first guess of the baseline.
double low_level(std::vector<double> powers) {
  std::sort(powers.begin(), powers.end());
  const std::size_t n = std::max<std::size_t>(powers.size() / 4, 1);
  double sum = 0.0;
  for (std::size_t i = 0; i < n; ++i) sum += powers[i];
  return sum / static_cast<double>(n);
}

struct Peak {
  double centre_deg = 0.0;
  double width_deg = 0.0;
  double amplitude = 0.0;       ///< linear, above the baseline
  double baseline = 0.0;        ///< linear, at the centre
  double rms = 0.0;             ///< linear residual rms
  double rms_db = 0.0;          ///< residual rms in dB (the receiver's noise as it reads it)
  double centre_std_deg = 0.0;  ///< the fit's standard error of the centre
  double other_std_deg = 0.0;   ///< a raster's: of the other centre coordinate
  double slope = 0.0;           ///< linear per degree: the baseline's tilt along a line
};

/// rms of measured − fitted, in dB.
double rms_db(const std::vector<double>& measured, const std::vector<double>& fitted) {
  double sum = 0.0;
  for (std::size_t i = 0; i < measured.size(); ++i) {
    const double d = to_db(measured[i] / fitted[i]);
    sum += d * d;
  }
  return measured.empty() ? 0.0 : std::sqrt(sum / static_cast<double>(measured.size()));
}

/// Gaussian + linear baseline along one coordinate: p = b0 + b1·s + A·exp(−4 ln2 (s − s0)²/W²).
Result<Peak> fit_line(const std::vector<double>& s, const std::vector<double>& p, double width) {
  const auto peak_at = std::max_element(p.begin(), p.end()) - p.begin();
  const double base = low_level(p);
  const ResidualFunction f = [&](const std::vector<double>& q, std::vector<double>& r) {
    for (std::size_t i = 0; i < s.size(); ++i) {
      const double d = s[i] - q[3];
      r[i] = q[0] + q[1] * s[i] + q[2] * std::exp(-kFourLn2 * d * d / (q[4] * q[4])) - p[i];
    }
  };
  const std::vector<double> start{base, 0.0, p[static_cast<std::size_t>(peak_at)] - base,
                                  s[static_cast<std::size_t>(peak_at)], width};
  LeastSquaresOptions options;
  options.steps = {1e-7 * base, 1e-7 * base / width, 1e-7 * base, 1e-6 * width, 1e-6 * width};
  const LeastSquaresFit fit = fit_least_squares(f, start, s.size(), options);
  if (!fit.converged || fit.singular) return fail("the fit did not converge");
  const auto& q = fit.params;
  std::vector<double> r(s.size()), model(s.size());
  f(q, r);
  for (std::size_t i = 0; i < s.size(); ++i) model[i] = p[i] + r[i];
  const double centre_std = fit.std_errors.size() == 5 ? fit.std_errors[3] : 0.0;
  return Peak{q[3],
              std::fabs(q[4]),
              q[2],
              q[0] + q[1] * q[3],
              fit.rms_residual,
              rms_db(p, model),
              centre_std,
              0.0,
              q[1]};
}

/// Round Gaussian + constant baseline over the grid: p = b + A·exp(−4 ln2 r²/W²).
Result<Peak> fit_grid(const std::vector<Point>& pts, double width, double& y_centre) {
  std::vector<double> powers;
  powers.reserve(pts.size());
  for (const Point& pt : pts) powers.push_back(pt.power);
  const auto top = std::max_element(
      pts.begin(), pts.end(), [](const Point& a, const Point& b) { return a.power < b.power; });
  const double base = low_level(powers);
  const ResidualFunction f = [&](const std::vector<double>& q, std::vector<double>& r) {
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const double dx = pts[i].x - q[2], dy = pts[i].y - q[3];
      r[i] = q[0] + q[1] * std::exp(-kFourLn2 * (dx * dx + dy * dy) / (q[4] * q[4])) - pts[i].power;
    }
  };
  LeastSquaresOptions options;
  options.steps = {1e-7 * base, 1e-7 * base, 1e-6 * width, 1e-6 * width, 1e-6 * width};
  const LeastSquaresFit fit =
      fit_least_squares(f, {base, top->power - base, top->x, top->y, width}, pts.size(), options);
  if (!fit.converged || fit.singular) return fail("the fit did not converge");
  const auto& q = fit.params;
  y_centre = q[3];
  std::vector<double> r(pts.size()), model(pts.size()), measured(pts.size());
  f(q, r);
  for (std::size_t i = 0; i < pts.size(); ++i) {
    measured[i] = pts[i].power;
    model[i] = pts[i].power + r[i];
  }
  const bool has_errors = fit.std_errors.size() == 5;
  return Peak{q[2],
              std::fabs(q[4]),
              q[1],
              q[0],
              fit.rms_residual,
              rms_db(measured, model),
              has_errors ? fit.std_errors[2] : 0.0,
              has_errors ? fit.std_errors[3] : 0.0};
}

/// The checks every fitted peak must pass; `what` names the line in the message.
Result<bool> check_peak(const Peak& pk, double lo, double hi, double beamwidth, const char* what) {
  const std::string line(what);
  if (!(pk.amplitude > 5.0 * pk.rms) || !(pk.baseline > 0.0)) {
    return fail(
        "no clear peak " + line + ": " +
        format_fixed(to_db(1.0 + std::max(pk.amplitude, 0.0) / std::max(pk.baseline, 1e-300)), 2) +
        " dB against noise " +
        format_fixed(to_db(1.0 + pk.rms / std::max(pk.baseline, 1e-300)), 3) + " dB");
  }
  if (pk.centre_deg < lo || pk.centre_deg > hi) {
    return fail("the peak " + line + " lies outside the scan (at " +
                format_fixed(pk.centre_deg, 3) + "°)");
  }
  if (pk.width_deg < 0.3 * beamwidth || pk.width_deg > hi - lo) {
    return fail("the width " + line + " (" + format_fixed(pk.width_deg, 3) +
                "°) is not a beam's: the scan saw no source, or only noise");
  }
  return true;
}

ScanFit to_scan_fit(const Peak& x, const Peak& y, double y_centre, std::size_t used,
                    std::size_t missing) {
  ScanFit out;
  out.peak = {x.centre_deg, y_centre};
  out.peak_std = {x.centre_std_deg, &x == &y ? x.other_std_deg : y.centre_std_deg};
  out.width_xel_deg = x.width_deg;
  out.width_el_deg = y.width_deg;
  out.peak_db = to_db(1.0 + x.amplitude / x.baseline);
  out.noise_db = std::max(x.rms_db, y.rms_db);
  out.used = used;
  out.missing = missing;
  out.xel_curve = {x.baseline, x.slope, x.amplitude};
  out.el_curve = {y.baseline, y.slope, y.amplitude};
  return out;
}

Result<ScanFit> fit_cross(const std::vector<Point>& pts, std::size_t missing, double bw) {
  std::vector<double> xs, xp, ys, yp;
  for (const Point& pt : pts) {
    if (pt.planned.el_deg == 0.0) {
      xs.push_back(pt.x);
      xp.push_back(pt.power);
    }
    if (pt.planned.xel_deg == 0.0) {
      ys.push_back(pt.y);
      yp.push_back(pt.power);
    }
  }
  if (xs.size() < kMinPointsPerLine)
    return too_few(xs.size(), missing, kMinPointsPerLine, "in cross-elevation");
  if (ys.size() < kMinPointsPerLine)
    return too_few(ys.size(), missing, kMinPointsPerLine, "in elevation");
  auto x = fit_line(xs, xp, bw);
  if (!x) return fail("cross-elevation: " + x.error().message);
  auto y = fit_line(ys, yp, bw);
  if (!y) return fail("elevation: " + y.error().message);
  const auto [xlo, xhi] = std::minmax_element(xs.begin(), xs.end());
  const auto [ylo, yhi] = std::minmax_element(ys.begin(), ys.end());
  if (auto ok = check_peak(*x, *xlo, *xhi, bw, "in cross-elevation"); !ok) return ok.error();
  if (auto ok = check_peak(*y, *ylo, *yhi, bw, "in elevation"); !ok) return ok.error();
  return to_scan_fit(*x, *y, y->centre_deg, pts.size(), missing);
}

Result<ScanFit> fit_raster(const std::vector<Point>& pts, std::size_t missing, double bw) {
  if (pts.size() < kMinRasterPoints)
    return too_few(pts.size(), missing, kMinRasterPoints, "in the raster");
  double y_centre = 0.0;
  auto pk = fit_grid(pts, bw, y_centre);
  if (!pk) return pk.error();
  double lo = pts.front().x, hi = lo, ylo = pts.front().y, yhi = ylo;
  for (const Point& pt : pts) {
    lo = std::min(lo, pt.x);
    hi = std::max(hi, pt.x);
    ylo = std::min(ylo, pt.y);
    yhi = std::max(yhi, pt.y);
  }
  if (auto ok = check_peak(*pk, lo, hi, bw, "in cross-elevation"); !ok) return ok.error();
  Peak as_y = *pk;
  as_y.centre_deg = y_centre;
  if (auto ok = check_peak(as_y, ylo, yhi, bw, "in elevation"); !ok) return ok.error();
  return to_scan_fit(*pk, *pk, y_centre, pts.size(), missing);
}

/// The classical five-point solution for a Gaussian of unknown width: with P₀ at the centre and
/// P± at ±h (baseline removed), W² = 8 ln2 h² / ln(P₀²/(P₊P₋)) and s₀ = W² ln(P₊/P₋)/(16 ln2 h).
Result<Peak> five_point_axis(double p_minus, double p0, double p_plus, double h) {
  if (!(p_minus > 0.0 && p0 > 0.0 && p_plus > 0.0))
    return fail("a point is at or below the baseline");
  const double curvature = std::log(p0 * p0 / (p_plus * p_minus));
  if (!(curvature > 0.0)) return fail("the centre is not above its neighbours");
  const double w2 = 2.0 * kFourLn2 * h * h / curvature;
  const double s0 = w2 * std::log(p_plus / p_minus) / (4.0 * kFourLn2 * h);
  const double amplitude = p0 * std::exp(kFourLn2 * s0 * s0 / w2);
  return Peak{s0, std::sqrt(w2), amplitude, 0.0, 0.0, 0.0, 0.0, 0.0};
}

Result<ScanFit> fit_five_point(const std::vector<ScanSample>& samples, double bw) {
  std::vector<double> refs;
  std::array<std::optional<double>, 5> on{};  // centre, −x, +x, −y, +y
  for (const ScanSample& s : samples) {
    if (!s.power_db || !std::isfinite(*s.power_db)) continue;
    const double p = linear(*s.power_db);
    const SkyOffset o = s.point.offset;
    if (s.point.reference)
      refs.push_back(p);
    else if (o.xel_deg == 0.0 && o.el_deg == 0.0)
      on[0] = p;
    else if (o.el_deg == 0.0)
      on[o.xel_deg < 0.0 ? 1 : 2] = p;
    else
      on[o.el_deg < 0.0 ? 3 : 4] = p;
  }
  const auto good = static_cast<std::size_t>(
      std::count_if(on.begin(), on.end(), [](auto& v) { return v.has_value(); }));
  if (good < 5 || refs.empty()) {
    return too_few(good + refs.size(), samples.size() - good - refs.size(), 6,
                   "in the five-point scan (all five and a reference)");
  }
  double base = 0.0;
  for (const double r : refs) base += r;
  base /= static_cast<double>(refs.size());
  const double h = 0.5 * bw;
  auto x = five_point_axis(*on[1] - base, *on[0] - base, *on[2] - base, h);
  if (!x) return fail("cross-elevation: " + x.error().message);
  auto y = five_point_axis(*on[3] - base, *on[0] - base, *on[4] - base, h);
  if (!y) return fail("elevation: " + y.error().message);
  for (Peak* pk : {&x.value(), &y.value()}) pk->baseline = base;
  if (std::fabs(x->centre_deg) > bw || std::fabs(y->centre_deg) > bw) {
    return fail(
        "the source is more than a beamwidth off: the five points cannot place it (use a cross "
        "scan)");
  }
  return to_scan_fit(*x, *y, y->centre_deg, good + refs.size(),
                     samples.size() - good - refs.size());
}

}  // namespace

Result<ScanFit> fit_scan(ScanKind kind, const std::vector<ScanSample>& samples,
                         double beamwidth_deg) {
  if (!(beamwidth_deg > 0.0)) return fail("beamwidth_deg must be positive");
  if (kind == ScanKind::FivePoint) return fit_five_point(samples, beamwidth_deg);
  std::size_t missing = 0;
  const std::vector<Point> pts = good_points(samples, missing);
  if (kind == ScanKind::Raster) return fit_raster(pts, missing, beamwidth_deg);
  return fit_cross(pts, missing, beamwidth_deg);
}

double deconvolved_beamwidth_deg(double measured_deg, double source_deg) {
  const double d = measured_deg * measured_deg - source_deg * source_deg;
  return d > 0.0 ? std::sqrt(d) : 0.0;
}

}  // namespace azt::calibration
