// libFuzzer target for element sets as downloads bring them (docs/satellites.md): the readers
// (TLE; OMM XML, JSON, KVN, CSV), then the screening against a source's previous download, the
// merge by NORAD number, the propagator's start, and the element cache's round trip; the input is
// also read as a cache file (one left by a killed daemon or edited by hand).
// Invariants:
// - nothing throws; every reading says something (a set or an error), in valid UTF-8;
// - an accepted download has no entry error, at least one set, every epoch within the limits
//   of now, at least a tenth of the previous count, and no satellite older than before;
// - the merge holds each NORAD number once, with an epoch no older than any input's for it;
// - the cache gives back exactly the sets it was given.
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "azt/orbit/element_screening.hpp"
#include "azt/orbit/sgp4.hpp"
#include "azt/util/valid_utf8.hpp"
#include "elements/element_cache.hpp"
#include "fuzz_support.hpp"
#include "satellites/element_sets.hpp"

namespace {

namespace orbit = azt::orbit;

constexpr double kNowUnixS = 1709296200.0;  // 2024-03-01 12:30 UTC

/// The previous download: three sets around the seed corpus's epochs (early 2024).
std::vector<orbit::Elements> previous() {
  std::vector<orbit::Elements> out;
  for (const char* number : {"25544", "7530", "43017"}) {
    orbit::Elements e;
    e.catalog = number;
    e.epoch_jd = 2460360.5;  // 2024-02-24
    e.epoch_jd_frac = 0.25;
    e.mean_motion_rev_day = 15.5;
    out.push_back(e);
  }
  return out;
}

void check_accepted(const orbit::ElementDownload& d, const std::vector<orbit::Elements>& before,
                    const orbit::ScreeningLimits& limits) {
  AZT_FUZZ_REQUIRE(d.errors.empty() && !d.sets.empty());
  AZT_FUZZ_REQUIRE(orbit::implausible_epoch(d.sets, kNowUnixS, limits).empty());
  AZT_FUZZ_REQUIRE(static_cast<double>(d.sets.size()) >=
                   limits.min_count_ratio * static_cast<double>(before.size()));
  std::map<std::string, double> was;
  for (const auto& e : before) was[orbit::norad_key(e.catalog)] = orbit::epoch_jd(e);
  for (const auto& e : d.sets) {
    const auto it = was.find(orbit::norad_key(e.catalog));
    AZT_FUZZ_REQUIRE(it == was.end() || orbit::epoch_jd(e) >= it->second - 1e-6);
  }
}

void check_merge(const std::vector<const std::vector<orbit::Elements>*>& inputs) {
  const std::vector<orbit::Elements> merged = orbit::merge_newest(inputs);
  std::map<std::string, double> newest;
  for (const auto& e : merged) {
    AZT_FUZZ_REQUIRE(newest.emplace(orbit::norad_key(e.catalog), orbit::epoch_jd(e)).second);
  }
  for (const auto* input : inputs) {
    for (const auto& e : *input) {
      AZT_FUZZ_REQUIRE(orbit::epoch_jd(e) <= newest.at(orbit::norad_key(e.catalog)) + 1e-6);
    }
  }
  for (const auto& e : merged) (void)orbit::Sgp4::make(e);  // an error is fine; a crash is not
}

void check_cache(const std::vector<orbit::Elements>& sets) {
  const std::string text = azt::app::element_cache_text({{"https://x/y", kNowUnixS, sets}});
  const auto back = azt::app::read_element_cache(text);
  AZT_FUZZ_REQUIRE(back && back.value().size() == 1);
  const auto& got = back.value().front().sets;
  AZT_FUZZ_REQUIRE(got.size() == sets.size());
  for (std::size_t i = 0; i < sets.size(); ++i) {
    AZT_FUZZ_REQUIRE(got[i].catalog == sets[i].catalog && got[i].name == sets[i].name);
    AZT_FUZZ_REQUIRE(got[i].epoch_jd == sets[i].epoch_jd &&
                     got[i].epoch_jd_frac == sets[i].epoch_jd_frac);
    AZT_FUZZ_REQUIRE(got[i].mean_motion_rev_day == sets[i].mean_motion_rev_day);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const azt::app::ElementSetFile file = azt::app::parse_element_sets(text, "fuzz");
  AZT_FUZZ_REQUIRE(!file.sets.empty() || !file.errors.empty());
  for (const auto& e : file.errors) AZT_FUZZ_REQUIRE(azt::is_valid_utf8(e));
  for (const auto& e : file.sets) AZT_FUZZ_REQUIRE(azt::is_valid_utf8(e.name));

  const orbit::ElementDownload download{file.sets, file.errors};
  const orbit::ScreeningLimits limits;
  const std::vector<orbit::Elements> before = previous();
  for (const auto* history : {&before, static_cast<const std::vector<orbit::Elements>*>(nullptr)}) {
    const std::vector<orbit::Elements> none;
    const auto& prior = history != nullptr ? *history : none;
    if (orbit::screen_download(download, prior, kNowUnixS, limits).accepted()) {
      check_accepted(download, prior, limits);
    }
  }
  check_merge({&before, &file.sets});
  check_cache(file.sets);
  (void)azt::app::read_element_cache(text);  // a hostile cache file: an error, never a throw
  return 0;
}

#ifdef AZT_FUZZ_STANDALONE
int main(int argc, char** argv) { return azt::fuzz::replay_files("element_sets_fuzz", argc, argv); }
#endif
