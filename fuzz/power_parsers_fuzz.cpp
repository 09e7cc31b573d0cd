// libFuzzer target for the receiver power feed codecs (docs/calibration.md): rtl_power's CSV lines
// (parse_rtl_power_line, sweep_power_db) and the one-reading-a-line feed (parse_power_line,
// parse_power_lines). The whole input is one line for each parser and one datagram.
// Invariants:
// - an accepted rtl_power line has 1..kRtlPowerMaxBins bins, each finite within ±300 dB,
//   0 <= Hz low <= Hz high, Hz step > 0, samples >= 0, and its total power is finite and lies
//   between its weakest and strongest bins;
// - an accepted power reading is finite within ±300 dB;
// - a trailing "\r\n" (and, for a reading, blanks around it) does not change what a line means;
// - a datagram gives one result per line that is not blank, each what parse_power_line says;
// - error messages are short and hold no control bytes (they reach logs and the console).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "azt/proto/power_line.hpp"
#include "azt/proto/rtl_power_csv.hpp"
#include "azt/util/result.hpp"
#include "azt/util/text_lines.hpp"
#include "fuzz_support.hpp"

namespace {

namespace proto = azt::proto;

bool has_terminator(std::string_view text) {
  return text.find_first_of("\r\n") != std::string_view::npos;
}

void check_sweep(const proto::RtlPowerSweep& sweep) {
  AZT_FUZZ_REQUIRE(!sweep.bins_db.empty() && sweep.bins_db.size() <= proto::kRtlPowerMaxBins);
  AZT_FUZZ_REQUIRE(std::isfinite(sweep.hz_low) && std::isfinite(sweep.hz_high));
  AZT_FUZZ_REQUIRE(sweep.hz_low >= 0.0 && sweep.hz_high >= sweep.hz_low);
  AZT_FUZZ_REQUIRE(std::isfinite(sweep.hz_step) && sweep.hz_step > 0.0);
  AZT_FUZZ_REQUIRE(sweep.samples >= 0);
  for (const double db : sweep.bins_db) {
    AZT_FUZZ_REQUIRE(std::isfinite(db) && std::fabs(db) <= proto::kRtlPowerMaxAbsBinDb);
  }
  const auto [weakest, strongest] = std::minmax_element(sweep.bins_db.begin(), sweep.bins_db.end());
  const double total = proto::sweep_power_db(sweep);
  AZT_FUZZ_REQUIRE(std::isfinite(total));
  AZT_FUZZ_REQUIRE(total >= *weakest - 1e-9 && total <= *strongest + 1e-9);
}

void check_rtl_power(std::string_view line) {
  const auto parsed = proto::parse_rtl_power_line(line);
  azt::fuzz::check_error_message(parsed);
  if (parsed) check_sweep(*parsed);
  if (has_terminator(line)) return;
  const auto terminated = proto::parse_rtl_power_line(std::string(line) + "\r\n");
  AZT_FUZZ_REQUIRE(terminated.ok() == parsed.ok());
  if (parsed) AZT_FUZZ_REQUIRE(terminated->bins_db == parsed->bins_db);
}

void check_power_line(std::string_view line) {
  const auto parsed = proto::parse_power_line(line);
  azt::fuzz::check_error_message(parsed);
  if (parsed) {
    AZT_FUZZ_REQUIRE(std::isfinite(*parsed) && std::fabs(*parsed) <= proto::kPowerLineMaxAbsDb);
  }
  if (has_terminator(line) || line.size() + 2 > proto::kPowerLineMaxChars) return;
  const auto padded = proto::parse_power_line(" " + std::string(line) + "\t\r\n");
  AZT_FUZZ_REQUIRE(padded.ok() == parsed.ok());
  if (parsed) AZT_FUZZ_REQUIRE(*padded == *parsed);
}

void check_datagram(std::string_view datagram) {
  const auto readings = proto::parse_power_lines(datagram);
  std::size_t i = 0;
  for (const std::string_view line : azt::split_lines(datagram)) {
    if (azt::trim(line).empty()) continue;
    AZT_FUZZ_REQUIRE(i < readings.size());
    const auto alone = proto::parse_power_line(line);
    AZT_FUZZ_REQUIRE(readings[i].ok() == alone.ok());
    if (alone) AZT_FUZZ_REQUIRE(*readings[i] == *alone);
    ++i;
  }
  AZT_FUZZ_REQUIRE(i == readings.size());
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  check_rtl_power(input);
  check_power_line(input);
  check_datagram(input);
  return 0;
}

#ifdef AZT_FUZZ_STANDALONE
int main(int argc, char** argv) {
  return azt::fuzz::replay_files("power_parsers_fuzz", argc, argv);
}
#endif
