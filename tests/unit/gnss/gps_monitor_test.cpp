// The GPS state the console shows (docs/gps.md), driven by injected times.
#include "azt/gnss/gps_monitor.hpp"

#include <gtest/gtest.h>

namespace azt::gnss {
namespace {

GpsFix fix3d(double lat, double lon, double alt) {
  return GpsFix{FixMode::Fix3d, lat, lon, alt, 1741910407.0};
}

GpsSky sky(int used, int visible) {
  GpsSky s{used, visible, 0.94, {}};
  for (int i = 0; i < visible; ++i)
    s.satellites.push_back({i + 1, 10.0 * i, 30.0 * i, 35, i < used});
  return s;
}

TEST(GpsMonitor, OffWhenNotEnabledWhateverItHears) {
  GpsMonitor m({false, 3.0});
  m.on_connected(0.0);
  m.on_fix(0.0, fix3d(46.0, -79.0, 300.0));
  m.on_sky(0.0, sky(8, 12));
  const GpsStatus s = m.status(0.5);
  EXPECT_EQ(s.state, GpsState::Off);
  EXPECT_FALSE(s.lat_deg.has_value());
  EXPECT_FALSE(s.time_unix_s.has_value());
  EXPECT_EQ(s.sats_used, 0);
  EXPECT_TRUE(s.satellites.empty());
  EXPECT_EQ(to_string(s.state), "off");
}

TEST(GpsMonitor, NoGpsdUntilConnectedThenNoFixUntilATpv) {
  GpsMonitor m({true, 3.0});
  EXPECT_EQ(m.status(0.0).state, GpsState::NoGpsd);
  EXPECT_EQ(to_string(m.status(0.0).state), "no_gpsd");
  m.on_connected(1.0);
  EXPECT_EQ(m.status(1.0).state, GpsState::NoFix);
  m.on_fix(2.0, GpsFix{FixMode::None, 0, 0, std::nullopt, std::nullopt});
  EXPECT_EQ(m.status(2.0).state, GpsState::NoFix);
  EXPECT_FALSE(m.status(2.0).lat_deg.has_value());
}

TEST(GpsMonitor, TwoAndThreeDimensionalFixes) {
  GpsMonitor m({true, 3.0});
  m.on_connected(0.0);
  m.on_fix(1.0, GpsFix{FixMode::Fix2d, 46.5, -79.5, 290.0, std::nullopt});
  GpsStatus s = m.status(1.0);
  EXPECT_EQ(s.state, GpsState::Fix2d);
  EXPECT_EQ(to_string(s.state), "fix2d");
  EXPECT_DOUBLE_EQ(*s.lat_deg, 46.5);
  EXPECT_FALSE(s.alt_m.has_value()) << "a 2D fix has no altitude";
  m.on_fix(2.0, fix3d(46.1, -79.4, 301.0));
  s = m.status(2.0);
  EXPECT_EQ(s.state, GpsState::Fix3d);
  EXPECT_EQ(to_string(s.state), "fix3d");
  EXPECT_DOUBLE_EQ(*s.lon_deg, -79.4);
  EXPECT_DOUBLE_EQ(*s.alt_m, 301.0);
  EXPECT_DOUBLE_EQ(*s.time_unix_s, 1741910407.0);
}

TEST(GpsMonitor, AReceiverThatStopsTalkingHasNoFixAfterTheStaleTime) {
  GpsMonitor m({true, 3.0});
  m.on_connected(0.0);
  m.on_fix(10.0, fix3d(46.0, -79.0, 300.0));
  m.on_sky(10.0, sky(8, 12));
  EXPECT_EQ(m.status(13.0).state, GpsState::Fix3d);  // exactly the stale time: still fresh
  EXPECT_EQ(m.status(13.0).sats_used, 8);
  const GpsStatus late = m.status(13.01);
  EXPECT_EQ(late.state, GpsState::NoFix);
  EXPECT_FALSE(late.lat_deg.has_value());
  EXPECT_EQ(late.sats_used, 0);
  EXPECT_EQ(late.sats_visible, 0);
  EXPECT_TRUE(late.satellites.empty());
  EXPECT_FALSE(late.hdop.has_value());
}

TEST(GpsMonitor, SkyCarriesSatellitesAndHdop) {
  GpsMonitor m({true, 3.0});
  m.on_connected(0.0);
  m.on_sky(1.0, sky(5, 9));
  const GpsStatus s = m.status(1.5);
  EXPECT_EQ(s.state, GpsState::NoFix);  // satellites seen, no fix yet
  EXPECT_EQ(s.sats_used, 5);
  EXPECT_EQ(s.sats_visible, 9);
  EXPECT_DOUBLE_EQ(*s.hdop, 0.94);
  ASSERT_EQ(s.satellites.size(), 9U);
  EXPECT_TRUE(s.satellites[4].used);
  EXPECT_FALSE(s.satellites[5].used);
}

TEST(GpsMonitor, ASkyGoesStaleOnItsOwn) {
  GpsMonitor m({true, 3.0});
  m.on_connected(0.0);
  m.on_sky(1.0, sky(6, 10));
  for (int t = 1; t <= 6; ++t) m.on_fix(t, fix3d(46.0, -79.0, 300.0));
  EXPECT_EQ(m.status(4.0).sats_visible, 10);  // 3 s old: still fresh
  const GpsStatus s = m.status(6.0);          // 5 s old
  EXPECT_EQ(s.state, GpsState::Fix3d) << "a fresh fix stands without a fresh sky";
  EXPECT_EQ(s.sats_used, 0);
  EXPECT_EQ(s.sats_visible, 0);
  EXPECT_TRUE(s.satellites.empty());
  EXPECT_FALSE(s.hdop.has_value());
  m.on_sky(6.5, sky(7, 11));
  EXPECT_EQ(m.status(7.0).sats_used, 7);
}

TEST(GpsMonitor, ANewFixAfterSilenceComesBack) {
  GpsMonitor m({true, 3.0});
  m.on_connected(0.0);
  m.on_fix(1.0, fix3d(46.0, -79.0, 300.0));
  EXPECT_EQ(m.status(10.0).state, GpsState::NoFix);
  m.on_fix(10.0, GpsFix{FixMode::Fix2d, 46.2, -79.1, std::nullopt, std::nullopt});
  EXPECT_EQ(m.status(10.0).state, GpsState::Fix2d);
  EXPECT_DOUBLE_EQ(*m.status(10.0).lat_deg, 46.2);
}

TEST(GpsMonitor, TheTimeIsTheLatestTpvThatHadOne) {
  GpsMonitor m({true, 3.0});
  m.on_connected(0.0);
  m.on_fix(1.0, GpsFix{FixMode::None, 0, 0, std::nullopt, 1741910400.0});
  GpsStatus s = m.status(1.0);
  EXPECT_EQ(s.state, GpsState::NoFix);
  EXPECT_DOUBLE_EQ(*s.time_unix_s, 1741910400.0) << "a receiver knows the time before a fix";
  m.on_fix(2.0, GpsFix{FixMode::Fix3d, 46.0, -79.0, 300.0, std::nullopt});
  s = m.status(2.0);
  EXPECT_EQ(s.state, GpsState::Fix3d);
  EXPECT_DOUBLE_EQ(*s.time_unix_s, 1741910400.0);
  m.on_fix(3.0, GpsFix{FixMode::Fix3d, 46.0, -79.0, 300.0, 1741910402.0});
  EXPECT_DOUBLE_EQ(*m.status(3.0).time_unix_s, 1741910402.0);
}

TEST(GpsMonitor, ADisconnectForgetsTheFixAndTheSky) {
  GpsMonitor m({true, 3.0});
  m.on_connected(0.0);
  m.on_fix(1.0, fix3d(46.0, -79.0, 300.0));
  m.on_sky(1.0, sky(8, 12));
  m.on_disconnected(1.5);
  GpsStatus s = m.status(1.6);
  EXPECT_EQ(s.state, GpsState::NoGpsd);
  EXPECT_FALSE(s.lat_deg.has_value());
  EXPECT_EQ(s.sats_used, 0);
  EXPECT_TRUE(s.satellites.empty());
  m.on_connected(2.0);
  s = m.status(2.0);
  EXPECT_EQ(s.state, GpsState::NoFix) << "the old fix must not come back with gpsd";
  EXPECT_FALSE(s.time_unix_s.has_value());
  EXPECT_EQ(s.sats_used, 0) << "nor the old sky";
}

}  // namespace
}  // namespace azt::gnss
