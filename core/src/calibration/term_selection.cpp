#include "azt/calibration/term_selection.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "azt/calibration/least_squares.hpp"
#include "azt/util/format_number.hpp"

namespace azt::calibration {
namespace {

constexpr std::size_t kN = PointingTerms::kCount;
constexpr const char* kNames[kN] = {"IA", "IE", "CA", "NPAE", "AN", "AW", "SAG"};
constexpr const char* kKeys[kN] = {"ia_deg", "ie_deg", "ca_deg", "npae_deg",
                                   "an_deg", "aw_deg", "sag_deg"};
/// A contribution this large (of the term's column length) names a term the held one resembles.
constexpr double kNamedShare = 0.3;

/// Term `j` regressed on the taken terms: the coefficients, and what is left of N_jj.
struct Regression {
  std::vector<double> beta;
  double left = 0.0;
  bool ok = false;
};

Regression regress(const std::vector<double>& n, const std::vector<std::size_t>& taken,
                   std::size_t j) {
  const std::size_t m = taken.size();
  Regression r;
  r.left = n[j * kN + j];
  if (m == 0) {
    r.ok = true;
    return r;
  }
  std::vector<double> a(m * m);
  r.beta.resize(m);
  for (std::size_t p = 0; p < m; ++p) {
    r.beta[p] = n[taken[p] * kN + j];
    for (std::size_t q = 0; q < m; ++q) a[p * m + q] = n[taken[p] * kN + taken[q]];
  }
  std::vector<double> rhs = r.beta;
  r.ok = solve_symmetric(a, r.beta, m);
  for (std::size_t p = 0; r.ok && p < m; ++p) r.left -= rhs[p] * r.beta[p];
  return r;
}

/// The taken terms whose share of term j's column is large, largest first, as "IA and CA".
std::string resembled(const std::vector<double>& n, const std::vector<std::size_t>& taken,
                      std::size_t j, const Regression& r) {
  std::vector<std::pair<double, std::size_t>> shares;
  const double own = std::sqrt(std::max(n[j * kN + j], 1e-300));
  for (std::size_t p = 0; p < taken.size() && p < r.beta.size(); ++p) {
    const double share =
        std::fabs(r.beta[p]) * std::sqrt(std::max(n[taken[p] * kN + taken[p]], 0.0)) / own;
    if (share >= kNamedShare) shares.emplace_back(share, taken[p]);
  }
  std::sort(shares.begin(), shares.end(), [](const auto& x, const auto& y) {
    return x.first > y.first || (x.first == y.first && x.second < y.second);
  });
  std::string out;
  for (std::size_t i = 0; i < shares.size() && i < 3; ++i) {
    if (i > 0) out += i + 1 == std::min<std::size_t>(shares.size(), 3) ? " and " : ", ";
    out += kNames[shares[i].second];
  }
  return out;
}

/// What of the sky the term needs, when the scans lack it.
std::string coverage_hint(std::size_t j, const CoverageSpan& span) {
  const bool by_elevation = j == 2 || j == 3 || j == 6;  // CA, NPAE, SAG: sec E, tan E, cos E
  const bool by_azimuth = j == 4 || j == 5;              // AN, AW: sin A, cos A
  if (by_elevation) {
    return "the scans' elevations span " + format_fixed(span.min_el_deg, 1) + "–" +
           format_fixed(span.max_el_deg, 1) + "°";
  }
  if (by_azimuth) return "the scans' azimuths span " + format_fixed(span.az_arc_deg, 0) + "°";
  return "";
}

std::string not_separated(const std::vector<double>& n, const std::vector<std::size_t>& taken,
                          std::size_t j, const Regression& r, const CoverageSpan& span) {
  const std::string like = resembled(n, taken, j, r);
  const std::string hint = coverage_hint(j, span);
  std::string out =
      like.empty() ? "the scans barely see it" : "the scans cannot tell it from " + like;
  if (!hint.empty()) out += " (" + hint + ")";
  return out;
}

std::string noise_moves(double sensitivity) {
  return "0.01° of scan noise would move it by " + format_fixed(0.01 * sensitivity, 3) + "°";
}

}  // namespace

const char* term_name(std::size_t index) { return index < kN ? kNames[index] : "?"; }
const char* term_key(std::size_t index) { return index < kN ? kKeys[index] : "?"; }

TermSelection select_terms(const std::vector<double>& normal, const TermMask& requested,
                           std::size_t scans, const CoverageSpan& span,
                           const SelectionLimits& limits) {
  TermSelection out;
  std::vector<std::size_t> taken;
  const std::size_t room = scans > 0 ? scans - 1 : 0;
  for (const std::size_t j : kTermOrder) {
    if (!requested.at(j)) {
      out.held.at(j) = "held by request";
      continue;
    }
    if (taken.size() >= room) {
      out.held.at(j) = "too few scans: " + std::to_string(scans) + " determine at most " +
                       std::to_string(room) + " terms (one is left to measure the scatter)";
      continue;
    }
    const Regression r = regress(normal, taken, j);
    const double whole = normal.at(j * kN + j);
    const double independence = whole > 0.0 && r.ok ? r.left / whole : 0.0;
    const double sensitivity = r.ok && r.left > 0.0 ? 1.0 / std::sqrt(r.left) : 1e300;
    if (independence < limits.min_independence) {
      out.held.at(j) = not_separated(normal, taken, j, r, span);
    } else if (sensitivity > limits.max_sensitivity) {
      out.held.at(j) = not_separated(normal, taken, j, r, span) + ": " + noise_moves(sensitivity);
    } else {
      out.fitted.at(j) = true;
      taken.push_back(j);
    }
  }
  return out;
}

double azimuth_arc_deg(std::vector<double> az_deg) {
  if (az_deg.size() < 2) return 0.0;
  for (double& a : az_deg) a = std::fmod(std::fmod(a, 360.0) + 360.0, 360.0);
  std::sort(az_deg.begin(), az_deg.end());
  double widest_gap = 360.0 - (az_deg.back() - az_deg.front());
  for (std::size_t i = 1; i < az_deg.size(); ++i)
    widest_gap = std::max(widest_gap, az_deg[i] - az_deg[i - 1]);
  return 360.0 - widest_gap;
}

}  // namespace azt::calibration
