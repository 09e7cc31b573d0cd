// When the station's clock is trusted (docs/time.md): chrony on a real source with the kernel
// agreeing; every other case is a banner with its reason.
#include "azt/timekeeping/clock_status.hpp"

#include <gtest/gtest.h>

namespace azt::timekeeping {
namespace {

ChronyTracking tracking(int stratum, const std::string& ref_id, const std::string& leap) {
  ChronyTracking t;
  t.stratum = stratum;
  t.ref_id_hex = ref_id;
  t.leap = leap;
  return t;
}

ClockReading reading(std::optional<ChronyTracking> t, std::optional<bool> kernel) {
  ClockReading r;
  r.read_at_s = 100.0;
  r.tracking = std::move(t);
  if (!r.tracking) r.chrony_error = "506 Cannot talk to daemon";
  r.kernel_synced = kernel;
  return r;
}

TEST(ClockStatus, GpsWithTheKernelAgreeingIsSynced) {
  const auto s = assess_clock(reading(tracking(1, "47505300", "Normal"), true), 101.0, 15.0);
  EXPECT_TRUE(s.synced);
  EXPECT_TRUE(s.chrony_synced);
  EXPECT_EQ(s.reason, "");
  // The kernel not asked (no adjtimex here) does not veto chrony.
  EXPECT_TRUE(
      assess_clock(reading(tracking(2, "C0A8010A", "Normal"), std::nullopt), 101.0, 15.0).synced);
}

TEST(ClockStatus, EveryUnsynchronisedCaseSaysWhy) {
  const auto never = assess_clock(std::nullopt, 0.0, 15.0);
  EXPECT_FALSE(never.synced);
  EXPECT_NE(never.reason.find("not been checked"), std::string::npos);

  const auto stale = assess_clock(reading(tracking(1, "47505300", "Normal"), true), 116.0, 15.0);
  EXPECT_FALSE(stale.synced);
  EXPECT_NE(stale.reason.find("stale"), std::string::npos);

  const auto no_chronyd = assess_clock(reading(std::nullopt, false), 101.0, 15.0);
  EXPECT_FALSE(no_chronyd.synced);
  EXPECT_NE(no_chronyd.reason.find("506 Cannot talk to daemon"), std::string::npos);

  const auto no_source =
      assess_clock(reading(tracking(0, "00000000", "Not synchronised"), true), 101.0, 15.0);
  EXPECT_FALSE(no_source.synced);
  EXPECT_NE(no_source.reason.find("no usable time source"), std::string::npos);

  // chrony's `local stratum` answers clients but is no source of truth for the station.
  const auto local = assess_clock(reading(tracking(10, kLocalRefIdHex, "Normal"), true), 101, 15);
  EXPECT_FALSE(local.synced);
  EXPECT_FALSE(local.chrony_synced);
  EXPECT_NE(local.reason.find("own clock"), std::string::npos);

  const auto kernel = assess_clock(reading(tracking(1, "47505300", "Normal"), false), 101, 15);
  EXPECT_FALSE(kernel.synced);
  EXPECT_TRUE(kernel.chrony_synced);
  EXPECT_NE(kernel.reason.find("kernel"), std::string::npos);
}

TEST(ClockStatus, WithoutChronydTheKernelsWordIsEnough) {
  // systemd-timesyncd or ntpd keeping the clock: chronyd is absent, the kernel is synchronised.
  const auto s = assess_clock(reading(std::nullopt, true), 101.0, 15.0);
  EXPECT_TRUE(s.synced);
  EXPECT_FALSE(s.chrony_synced);
  EXPECT_FALSE(assess_clock(reading(std::nullopt, std::nullopt), 101.0, 15.0).synced);
}

}  // namespace
}  // namespace azt::timekeeping
