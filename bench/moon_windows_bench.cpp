// Thirty days of common Moon windows for one station pair (FN06HE and JO62QM), the planner
// page's question (docs/eme.md); it must take under a second, so the page can answer as the
// operator types. ERFA's ephemeris (and Swiss Ephemeris when built in).
//
// Run: build/bench/azt_moon_windows_bench (Release or RelWithDebInfo build).

#include <benchmark/benchmark.h>

#include <memory>

#include "azt/astro/erfa_ephemeris.hpp"
#include "azt/astro/leap_seconds.hpp"
#include "azt/eme/moon_windows.hpp"
#ifdef AZT_HAVE_SWISS
#include "azt/astro/swiss_ephemeris.hpp"
#endif

namespace {

constexpr double kFrom = 1740787200.0;  // 2025-03-01 00:00 UTC

void thirty_days(benchmark::State& state, const azt::astro::Ephemeris& ephemeris) {
  const azt::astro::Observer own{46.1875, -79.375, 300.0};
  const azt::astro::Observer dx{52.52, 14.96, 0.0};
  azt::eme::MoonWindowSettings s;
  s.from_unix_s = kFrom;
  s.days = 30.0;
  std::size_t windows = 0;
  for (auto _ : state) {  // NOLINT(clang-analyzer-deadcode.DeadStores): the benchmark loop idiom
    const auto w =
        azt::eme::moon_windows(ephemeris, own, dx, s, azt::astro::LeapSecondTable::builtin());
    windows = w ? w.value().size() : 0;
    benchmark::DoNotOptimize(windows);
  }
  state.counters["windows"] = static_cast<double>(windows);
}

void moon_windows_30_days_erfa(benchmark::State& state) {
  const azt::astro::ErfaEphemeris eph;
  thirty_days(state, eph);
}
BENCHMARK(moon_windows_30_days_erfa)->Unit(benchmark::kMillisecond);

#ifdef AZT_HAVE_SWISS
void moon_windows_30_days_swiss(benchmark::State& state) {
  const auto eph = azt::astro::SwissEphemeris::open();
  if (!eph) {
    state.SkipWithError("no Swiss Ephemeris data files");
    return;
  }
  thirty_days(state, *eph);
}
BENCHMARK(moon_windows_30_days_swiss)->Unit(benchmark::kMillisecond);
#endif

}  // namespace

BENCHMARK_MAIN();
