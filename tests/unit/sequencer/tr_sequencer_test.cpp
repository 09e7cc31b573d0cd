// The T/R sequencer (docs/reliability.md R17, R18) in virtual time.
#include "azt/sequencer/tr_sequencer.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>
#include <vector>

namespace azt::sequencer {
namespace {

/// Drives a sequencer through PTT edges (time, level), calling update() at every edge and every
/// deadline in between, as the daemon's timer does; returns every transition.
std::vector<Transition> run(TrSequencer& seq, const std::vector<std::pair<double, bool>>& edges,
                            double until_ms) {
  std::vector<Transition> all;
  std::size_t next_edge = 0;
  bool level = false;
  double t = 0.0;
  while (t <= until_ms) {
    const double edge_t = next_edge < edges.size() ? edges[next_edge].first : until_ms + 1.0;
    const double deadline = seq.next_deadline_ms().value_or(until_ms + 1.0);
    t = std::min(edge_t, deadline);
    if (t > until_ms) break;
    while (next_edge < edges.size() && edges[next_edge].first <= t)
      level = edges[next_edge++].second;
    const auto out = seq.update(t, level);
    all.insert(all.end(), out.begin(), out.end());
  }
  return all;
}

std::vector<std::tuple<double, std::size_t, bool>> flat(const std::vector<Transition>& ts) {
  std::vector<std::tuple<double, std::size_t, bool>> out;
  for (const auto& t : ts) out.emplace_back(t.t_ms, t.line, t.on);
  return out;
}

TEST(TrSequencer, KeysInOrderAndReleasesInReverse) {
  TrSequencer seq(SequencerConfig::seed_default());
  const auto ts = run(seq, {{0.0, true}, {1000.0, false}}, 2000.0);
  const std::vector<std::tuple<double, std::size_t, bool>> expected = {
      {10, 0, true},    {30, 1, true},    {50, 2, true},    {70, 3, true},
      {1010, 3, false}, {1030, 2, false}, {1050, 1, false}, {1070, 0, false}};
  EXPECT_EQ(flat(ts), expected);
  EXPECT_FALSE(seq.motion_hold());
}

TEST(TrSequencer, AReleaseMidSequenceReleasesWhatWasKeyed) {
  TrSequencer seq(SequencerConfig::seed_default());
  const auto ts = run(seq, {{0.0, true}, {35.0, false}}, 500.0);
  const std::vector<std::tuple<double, std::size_t, bool>> expected = {
      {10, 0, true}, {30, 1, true}, {45, 1, false}, {65, 0, false}};
  EXPECT_EQ(flat(ts), expected);  // the amplifier and the radio were never keyed
}

TEST(TrSequencer, BounceShorterThanTheDebounceIsIgnored) {
  TrSequencer seq(SequencerConfig::seed_default());
  const auto ts = run(seq, {{0.0, true}, {4.0, false}, {6.0, true}, {9.0, false}}, 200.0);
  EXPECT_TRUE(ts.empty());
}

TEST(TrSequencer, PressedAgainDuringAReleaseFinishesTheReleaseFirst) {
  TrSequencer seq(SequencerConfig::seed_default());
  const auto ts = run(seq, {{0.0, true}, {100.0, false}, {125.0, true}}, 400.0);
  // released from 110: radio, amp (130), relay (150), preamp (170); keyed again from 170
  const std::vector<std::tuple<double, std::size_t, bool>> expected = {
      {10, 0, true},   {30, 1, true},   {50, 2, true},   {70, 3, true},
      {110, 3, false}, {130, 2, false}, {150, 1, false}, {170, 0, false},
      {170, 0, true},  {190, 1, true},  {210, 2, true},  {230, 3, true}};
  EXPECT_EQ(flat(ts), expected);
}

TEST(TrSequencer, TheTimeOutReleasesEverythingAndLatchesUntilPttIsReleased) {
  auto config = *SequencerConfig::make({"preamp", "trx_relay", "amplifier", "radio"},
                                       {20.0, 20.0, 20.0}, 10.0, 5.0, true);
  TrSequencer seq(config);
  const auto ts = run(seq, {{0.0, true}, {20000.0, false}, {21000.0, true}}, 21200.0);
  ASSERT_GE(ts.size(), 12U);
  EXPECT_EQ(flat({ts[4]}), (std::vector<std::tuple<double, std::size_t, bool>>{{5010, 3, false}}));
  EXPECT_EQ(flat({ts[7]}), (std::vector<std::tuple<double, std::size_t, bool>>{{5070, 0, false}}));
  EXPECT_EQ(ts[8].t_ms, 21010.0);  // keyed again only after a release and a new press
  EXPECT_FALSE(seq.timed_out());
}

TEST(TrSequencer, ConfigurationsThatWouldBeUnsafeAreRefused) {
  EXPECT_FALSE(SequencerConfig::make({}, {}, 10, 600, true).ok());
  EXPECT_FALSE(SequencerConfig::make({"a", "a"}, {20}, 10, 600, true).ok());
  EXPECT_FALSE(SequencerConfig::make({"a", "b"}, {}, 10, 600, true).ok());
  EXPECT_FALSE(SequencerConfig::make({"a", "b"}, {0.0}, 10, 600, true).ok());
  EXPECT_FALSE(SequencerConfig::make({"a", "b"}, {20}, 10, 0, true).ok());  // no time-out
  EXPECT_FALSE(SequencerConfig::make({"a", "b"}, {20}, 10, 1e9, true).ok());
  EXPECT_FALSE(SequencerConfig::make({"a", "b"}, {20}, -1, 600, true).ok());
  EXPECT_TRUE(SequencerConfig::make({"a", "b"}, {20}, 0, 600, true).ok());
}

// 10 000 key/unkey cycles with random bounce, releases in the middle of the sequence and holds
// past the time-out: the transitions must always obey the chain's rules.
TEST(TrSequencer, TenThousandRandomCyclesNeverBreakTheChain) {
  const auto config = *SequencerConfig::make({"preamp", "trx_relay", "amplifier", "radio"},
                                             {25.0, 15.0, 30.0}, 8.0, 2.0, true);
  TrSequencer seq(config);
  std::mt19937 rng(20261124);
  std::uniform_real_distribution<double> bounce_gap(0.5, 7.0);
  std::uniform_int_distribution<int> bounces(0, 6);
  std::uniform_real_distribution<double> hold(1.0, 120.0);    // presses: some shorter than debounce
  std::uniform_real_distribution<double> pause(10.0, 120.0);  // releases: always seen
  std::vector<std::pair<double, bool>> edges;
  std::vector<std::pair<double, double>> long_holds;  // (press settles, release)
  double t = 0.0;
  for (int cycle = 0; cycle < 10000; ++cycle) {
    for (const bool level : {true, false}) {
      for (int b = bounces(rng); b > 0; --b) {  // contact bounce around the edge
        edges.emplace_back(t, level);
        t += bounce_gap(rng);
        edges.emplace_back(t, !level);
        t += bounce_gap(rng);
      }
      edges.emplace_back(t, level);
      const double settled = t;
      // every 50th press is held past the 2 s time-out; others are short, often mid-sequence
      t += level ? (cycle % 50 == 0 ? 3000.0 : hold(rng)) : pause(rng);
      if (level && cycle % 50 == 0) long_holds.emplace_back(settled, t);
    }
  }
  const auto ts = run(seq, edges, t + 1000.0);

  constexpr double kEps = 1e-6;  // the differences of two absolute times round
  std::vector<bool> on(4, false);
  std::vector<double> changed(4, -1e9);
  std::optional<Transition> previous;
  int violations = 0;
  for (const auto& tr : ts) {
    if (tr.on) {
      for (std::size_t k = 0; k < tr.line; ++k) violations += on[k] ? 0 : 1;
      if (tr.line > 0) {
        // never keyed before the previous output has settled: T/R relay before the amplifier
        violations +=
            tr.t_ms - changed[tr.line - 1] >= config.delays_ms[tr.line - 1] - kEps ? 0 : 1;
      }
    } else {
      for (std::size_t k = tr.line + 1; k < 4; ++k) violations += on[k] ? 1 : 0;
    }
    if (previous && previous->on == tr.on) {
      const std::size_t gap = std::min(previous->line, tr.line);
      violations += tr.t_ms - previous->t_ms >= config.delays_ms[gap] - kEps ? 0 : 1;
    }
    violations += on[tr.line] == tr.on ? 1 : 0;  // a transition must change something
    on[tr.line] = tr.on;
    changed[tr.line] = tr.t_ms;
    previous = tr;
  }
  EXPECT_EQ(violations, 0);
  EXPECT_EQ(std::count(on.begin(), on.end(), true), 0);  // all released at the end
  EXPECT_GT(ts.size(), 20000U);                          // plenty of full and partial chains

  // The time-out: within 1 s of its setting after the press settled, everything released.
  int late = 0;
  for (const auto& [pressed, released] : long_holds) {
    std::vector<bool> state(4, false);
    bool all_off_in_time = false;
    for (const auto& tr : ts) {
      if (tr.t_ms > released) break;
      state[tr.line] = tr.on;
      if (tr.t_ms >= pressed + 2000.0 && tr.t_ms <= pressed + 3000.0 && !tr.on &&
          std::count(state.begin(), state.end(), true) == 0) {
        all_off_in_time = true;
      }
    }
    late += all_off_in_time ? 0 : 1;
  }
  EXPECT_EQ(late, 0) << "of " << long_holds.size() << " holds past the time-out";
}

}  // namespace
}  // namespace azt::sequencer
