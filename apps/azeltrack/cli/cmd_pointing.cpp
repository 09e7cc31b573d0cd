// `azeltrack pointing fit --csv FILE [--hold TERMS] [--json]` (docs/calibration.md): the pointing
// model fitted offline to a scan log (the daemon's, an export, another tool's), the terms the
// scans cannot determine held at 0 with the reason, and each scan's residual.

#include <cctype>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "azt/calibration/pointing_fit.hpp"
#include "azt/calibration/scan_log_csv.hpp"
#include "azt/calibration/term_selection.hpp"
#include "azt/linux/atomic_file.hpp"
#include "calibration/fit_report.hpp"
#include "cli/commands.hpp"
#include "common/usage_error.hpp"

namespace azt::app {
namespace {

struct PointingOptions {
  std::string csv;
  std::string hold;  ///< comma-separated term names
  bool json = false;
};

std::string lower(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

/// "ca,npae" (or their [pointing] keys, any case) to the mask of terms to fit.
calibration::TermMask fit_mask(const std::string& hold) {
  calibration::TermMask mask = calibration::kAllTerms;
  std::stringstream list(hold);
  for (std::string name; std::getline(list, name, ',');) {
    name = lower(name);
    bool known = false;
    for (std::size_t i = 0; i < mask.size(); ++i) {
      if (name == lower(calibration::term_name(i)) || name == calibration::term_key(i)) {
        mask.at(i) = false;
        known = true;
      }
    }
    if (!known)
      throw UsageError("--hold: no term \"" + name + "\" (ia, ie, ca, npae, an, aw, sag)");
  }
  return mask;
}

std::vector<calibration::ScanLogEntry> read_log(const std::string& path) {
  const auto text = linux_os::read_file(path);
  if (!text) throw UsageError("--csv: " + text.error().message);
  auto log = calibration::read_scan_log_csv(*text);
  if (!log) throw UsageError(path + ": " + log.error().message);
  return std::move(log).value();
}

void print_text(const calibration::PointingFit& fit) {
  const auto terms = fit.terms.as_array(), errors = fit.std_errors.as_array();
  std::cout << std::fixed << std::setprecision(4);
  for (std::size_t i = 0; i < terms.size(); ++i) {
    std::cout << std::setw(5) << calibration::term_name(i) << " " << std::setw(8) << terms.at(i)
              << "°";
    if (fit.held.at(i).empty()) {
      std::cout << " ± " << errors.at(i) << "°\n";
    } else {
      std::cout << "  held: " << fit.held.at(i) << '\n';
    }
  }
  std::cout << fit.observations << " scans: rms " << fit.rms_before_deg << "° before, "
            << fit.rms_deg << "° after (largest " << fit.max_deg << "°)\n";
}

int run_fit(const PointingOptions& o) {
  const std::vector<calibration::ScanLogEntry> log = read_log(o.csv);
  calibration::FitOptions options;
  options.fit = fit_mask(o.hold);
  const auto fit =
      calibration::fit_pointing_model(calibration::observations_from_log(log), {}, options);
  if (!fit) {
    if (o.json) std::cout << nlohmann::json{{"refused", fit.error().message}}.dump() << '\n';
    print_error("the fit was refused: " + fit.error().message);
    return kExitFailure;
  }
  if (o.json) {
    std::cout << fit_json(*fit, log).dump() << '\n';
  } else {
    print_text(*fit);
  }
  return 0;
}

}  // namespace

Runner add_pointing_command(CLI::App& app) {
  auto opts = std::make_shared<PointingOptions>();
  CLI::App* cmd = app.add_subcommand("pointing", "The pointing model from scan logs");
  cmd->require_subcommand(1);
  CLI::App* fit = cmd->add_subcommand(
      "fit", "Fit the pointing model to a scan log (CSV: utc, az, el, daz, del, …)");
  fit->add_option("--csv", opts->csv, "The scan log")->required();
  fit->add_option("--hold", opts->hold, "Terms to hold at 0, comma-separated (e.g. npae,sag)");
  fit->add_flag("--json", opts->json, "Print one JSON object");
  return [opts] { return run_fit(*opts); };
}

}  // namespace azt::app
