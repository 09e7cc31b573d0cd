// What one Moon pointing costs: the whole chain (time scales, epoch, station, observe with radio
// refraction, echo Doppler) per backend, the per-target part alone (Epoch and Station reused, as
// the tracker does for several targets at one tick), and the same work done through libswe
// directly (swe_utc_to_jd, swe_set_topo, swe_calc_ut topocentric, swe_azalt) as a yardstick.
//
// libswe caches the last body/date it computed, so every iteration moves the instant a little;
// otherwise the libswe rows would time a cache hit.
//
// Run: build/bench/azt_bench [--benchmark_filter=erfa] (Release or RelWithDebInfo build).
// Benchmark functions are snake_case like every function here (.clang-tidy's naming), not BM_*.

#include <benchmark/benchmark.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "azt/astro/erfa_ephemeris.hpp"
#include "azt/astro/leap_seconds.hpp"
#include "azt/astro/observer.hpp"
#include "azt/astro/refraction.hpp"
#include "azt/astro/sky.hpp"
#include "azt/astro/tabulated_ephemeris.hpp"
#include "azt/astro/target.hpp"
#include "azt/astro/time_scales.hpp"
#ifdef AZT_HAVE_SWISS
#include "azt/astro/swiss_ephemeris.hpp"
#endif
#ifdef AZT_BENCH_LIBSWE
#include <swephexp.h>
#endif

namespace {

using azt::astro::Atmosphere;
using azt::astro::Ephemeris;
using azt::astro::Epoch;
using azt::astro::LeapSecondTable;
using azt::astro::Observer;
using azt::astro::RefractionModel;
using azt::astro::Station;
using azt::astro::Target;
using azt::astro::UtcInstant;

// The oracle README's test instant and site: 2025-03-14 06:00 UTC, 46.189 N 79.393 W, 300 m.
constexpr double kBaseUnixS = 1741932000.0;
constexpr double kLatDeg = 46.189;
constexpr double kLonDeg = -79.393;
constexpr double kHeightM = 300.0;
constexpr double kDut1S = 0.0;
constexpr double kEchoFreqMhz = 10368.0;
// Step between iterations: small (the Moon moves ~0.5″ in 1 s) but never repeating an instant
// within a run of 4096 iterations.
constexpr double kStepS = 0.0137;
constexpr std::size_t kInstantCycle = 4096;
// Precomputed Epoch/Station pairs for the per-target rows.
constexpr std::size_t kPrecomputed = 64;

double instant_s(std::size_t i) {
  return kBaseUnixS + static_cast<double>(i % kInstantCycle) * kStepS;
}

Atmosphere radio_atmosphere() {
  return Atmosphere::make(1013.25, 10.0, 0.5, RefractionModel::Radio).value();
}

Observer site() { return Observer::make(kLatDeg, kLonDeg, kHeightM).value(); }

/// The whole chain for one Moon pointing, as a tracker tick does it.
void run_full_moon(benchmark::State& state, const Ephemeris& ephemeris) {
  const Atmosphere atmosphere = radio_atmosphere();
  const Observer observer = site();
  const Target moon = Target::moon();
  std::size_t i = 0;
  for (auto _ : state) {  // NOLINT(clang-analyzer-deadcode.DeadStores): the benchmark loop idiom
    const auto time = azt::astro::make_time_scales(UtcInstant::from_unix_seconds(instant_s(i++)),
                                                   kDut1S, LeapSecondTable::builtin());
    const auto epoch = azt::astro::make_epoch(ephemeris, time.value());
    const Station station = azt::astro::make_station(epoch.value(), observer);
    const auto seen = azt::astro::observe(moon, ephemeris, epoch.value(), station, atmosphere);
    const double doppler_hz = azt::astro::self_echo_doppler_hz(
        kEchoFreqMhz, seen.value().place.range_rate_km_s.value_or(0.0));
    benchmark::DoNotOptimize(seen.value().el_deg);
    benchmark::DoNotOptimize(doppler_hz);
  }
}

/// observe(moon) only, Epoch and Station reused (cycling through a few so libswe cannot cache).
void run_moon_target_only(benchmark::State& state, const Ephemeris& ephemeris) {
  const Atmosphere atmosphere = radio_atmosphere();
  const Observer observer = site();
  const Target moon = Target::moon();
  std::vector<Epoch> epochs;
  std::vector<Station> stations;
  for (std::size_t k = 0; k < kPrecomputed; ++k) {
    const auto time = azt::astro::make_time_scales(UtcInstant::from_unix_seconds(instant_s(k)),
                                                   kDut1S, LeapSecondTable::builtin());
    epochs.push_back(azt::astro::make_epoch(ephemeris, time.value()).value());
    stations.push_back(azt::astro::make_station(epochs.back(), observer));
  }
  std::size_t i = 0;
  for (auto _ : state) {  // NOLINT(clang-analyzer-deadcode.DeadStores): the benchmark loop idiom
    const std::size_t k = i++ % kPrecomputed;
    const auto seen = azt::astro::observe(moon, ephemeris, epochs[k], stations[k], atmosphere);
    benchmark::DoNotOptimize(seen.value().el_deg);
  }
}

void moon_full_erfa(benchmark::State& state) {
  const azt::astro::ErfaEphemeris ephemeris;
  run_full_moon(state, ephemeris);
}
BENCHMARK(moon_full_erfa);

void moon_target_only_erfa(benchmark::State& state) {
  const azt::astro::ErfaEphemeris ephemeris;
  run_moon_target_only(state, ephemeris);
}
BENCHMARK(moon_target_only_erfa);

/// The ERFA theories through a 10-minute Hermite table (built once, outside the timed loop, as a
/// tracker builds one per day): the full chain without the 20 µs of eraEpv00 per call.
void moon_full_erfa_tabulated(benchmark::State& state) {
  const azt::astro::ErfaEphemeris erfa;
  const auto start = azt::astro::make_time_scales(UtcInstant::from_unix_seconds(kBaseUnixS), kDut1S,
                                                  LeapSecondTable::builtin());
  auto table = azt::astro::TabulatedEphemeris::build(erfa, start.value().tt, 1.0);
  if (!table) {
    state.SkipWithError(table.error().message.c_str());
    return;
  }
  run_full_moon(state, *table);
}
BENCHMARK(moon_full_erfa_tabulated);

#ifdef AZT_HAVE_SWISS
void moon_full_swiss(benchmark::State& state) {
  const auto ephemeris = azt::astro::SwissEphemeris::open();
  if (!ephemeris) {
    state.SkipWithError(ephemeris.error().message.c_str());
    return;
  }
  run_full_moon(state, *ephemeris);
}
BENCHMARK(moon_full_swiss);

void moon_target_only_swiss(benchmark::State& state) {
  const auto ephemeris = azt::astro::SwissEphemeris::open();
  if (!ephemeris) {
    state.SkipWithError(ephemeris.error().message.c_str());
    return;
  }
  run_moon_target_only(state, *ephemeris);
}
BENCHMARK(moon_target_only_swiss);
#endif

#ifdef AZT_BENCH_LIBSWE
// libswe's own route: topocentric apparent RA/Dec of date, then its az/alt with its refraction.
constexpr int32 kSweMoonFlags = SEFLG_SWIEPH | SEFLG_TOPOCTR | SEFLG_EQUATORIAL | SEFLG_SPEED;

/// One Moon az/alt through libswe; returns the refracted altitude (deg) or nullopt on error.
std::optional<double> libswe_moon(double jd_ut, std::array<double, 3>& geopos) {
  std::array<double, 6> xx{};
  std::array<double, 3> xaz{};
  std::array<char, AS_MAXCH> err{};
  if (swe_calc_ut(jd_ut, SE_MOON, kSweMoonFlags, xx.data(), err.data()) < 0) return std::nullopt;
  swe_azalt(jd_ut, SE_EQU2HOR, geopos.data(), 1013.25, 10.0, xx.data(), xaz.data());
  return xaz[2];
}

void moon_full_libswe_direct(benchmark::State& state) {
  swe_set_ephe_path(nullptr);
  std::array<double, 3> geopos{kLonDeg, kLatDeg, kHeightM};
  std::array<char, AS_MAXCH> err{};
  std::size_t i = 0;
  for (auto _ : state) {  // NOLINT(clang-analyzer-deadcode.DeadStores): the benchmark loop idiom
    // 06:00:00 UTC plus the per-iteration step (always < 60 s, so minutes stay 0).
    const double sec = static_cast<double>(i++ % kInstantCycle) * kStepS;
    std::array<double, 2> jd{};  // [0] TT, [1] UT1 (libswe's own ΔT)
    if (swe_utc_to_jd(2025, 3, 14, 6, 0, sec, SE_GREG_CAL, jd.data(), err.data()) < 0) {
      state.SkipWithError("swe_utc_to_jd failed");
      return;
    }
    swe_set_topo(kLonDeg, kLatDeg, kHeightM);
    const auto alt = libswe_moon(jd[1], geopos);
    if (!alt) {
      state.SkipWithError("swe_calc_ut failed");
      return;
    }
    benchmark::DoNotOptimize(*alt);
  }
}
BENCHMARK(moon_full_libswe_direct);

void moon_target_only_libswe_direct(benchmark::State& state) {
  swe_set_ephe_path(nullptr);
  swe_set_topo(kLonDeg, kLatDeg, kHeightM);
  std::array<double, 3> geopos{kLonDeg, kLatDeg, kHeightM};
  // JD (UT) of the base instant; 2440587.5 = 1970-01-01T00:00.
  const double jd0 = 2440587.5 + kBaseUnixS / 86400.0;
  std::size_t i = 0;
  for (auto _ : state) {  // NOLINT(clang-analyzer-deadcode.DeadStores): the benchmark loop idiom
    const double jd = jd0 + static_cast<double>(i++ % kInstantCycle) * kStepS / 86400.0;
    const auto alt = libswe_moon(jd, geopos);
    if (!alt) {
      state.SkipWithError("swe_calc_ut failed");
      return;
    }
    benchmark::DoNotOptimize(*alt);
  }
}
BENCHMARK(moon_target_only_libswe_direct);
#endif

}  // namespace

BENCHMARK_MAIN();
