// libFuzzer target for the scan log's CSV reader (docs/calibration.md): the whole input is one
// file, as an import or the daemon's own log brings it.
// Invariants:
// - a refusal is a short message without control bytes that names its line (or says the
//   header is missing);
// - an accepted log has at most kScanLogMaxRows rows, each within the ranges the reader checks;
// - what the writer makes of an accepted log reads back, and writing that again gives the same
//   text (the export is a fixed point after one round).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "azt/calibration/scan_log_csv.hpp"
#include "fuzz_support.hpp"

namespace {

namespace cal = azt::calibration;

bool within(const std::optional<double>& v, double low, double high) {
  return !v || (std::isfinite(*v) && *v >= low && *v <= high);
}

void check_entry(const cal::ScanLogEntry& e) {
  AZT_FUZZ_REQUIRE(e.az_deg >= 0.0 && e.az_deg <= 360.0);
  AZT_FUZZ_REQUIRE(e.el_deg >= 0.0 && e.el_deg <= 90.0);
  AZT_FUZZ_REQUIRE(std::fabs(e.daz_deg) <= 180.0 && std::fabs(e.del_deg) <= 90.0);
  AZT_FUZZ_REQUIRE(e.weight >= 0.0 && e.weight <= 1e6);
  AZT_FUZZ_REQUIRE(within(e.sigma_xel_deg, 1e-300, 10.0) && within(e.sigma_el_deg, 1e-300, 10.0));
  AZT_FUZZ_REQUIRE(within(e.snr_db, -100.0, 300.0) && within(e.rise_db, -100.0, 300.0));
  AZT_FUZZ_REQUIRE(within(e.beamwidth_deg, 1e-300, 30.0));
  AZT_FUZZ_REQUIRE(e.source.size() <= cal::kScanLogMaxSourceChars);
  AZT_FUZZ_REQUIRE(e.source.find_first_of(",\"\n\r") == std::string::npos);
}

void check_refusal(const azt::Result<std::vector<cal::ScanLogEntry>>& log) {
  azt::fuzz::check_error_message(log);
  if (log) return;
  const std::string& m = log.error().message;
  AZT_FUZZ_REQUIRE(m.rfind("line ", 0) == 0 || m.rfind("no header line", 0) == 0);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  const auto log = cal::read_scan_log_csv(input);
  check_refusal(log);
  if (!log) return 0;
  AZT_FUZZ_REQUIRE(log->size() <= cal::kScanLogMaxRows);
  for (const cal::ScanLogEntry& e : *log) check_entry(e);
  // Only the time can fail to read back: a millisecond's rounding can carry the last instant
  // of the parser's years (2200-12-31T23:59:59.9996Z) out of them.
  const std::string written = cal::write_scan_log_csv(*log);
  const auto again = cal::read_scan_log_csv(written);
  if (!again) {
    AZT_FUZZ_REQUIRE(again.error().message.find(": utc: ") != std::string::npos);
    return 0;
  }
  AZT_FUZZ_REQUIRE(again->size() == log->size());
  const auto third = cal::read_scan_log_csv(cal::write_scan_log_csv(*again));
  AZT_FUZZ_REQUIRE(third && cal::write_scan_log_csv(*third) == cal::write_scan_log_csv(*again));
  return 0;
}

#ifdef AZT_FUZZ_STANDALONE
int main(int argc, char** argv) { return azt::fuzz::replay_files("scan_log_csv_fuzz", argc, argv); }
#endif
