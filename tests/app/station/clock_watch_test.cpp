// The station's clock watched (docs/time.md): the reading off the loop becomes the console's
// `time`; a change of verdict is logged once; a reading that stops coming goes stale; the NTP
// servers are refused unless chrony is managed, checked, applied and read back.
#include "station/clock_watch.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace azt::app {
namespace {

timekeeping::ChronyTracking gps_tracking() {
  timekeeping::ChronyTracking t;
  t.ref_id_hex = "47505300";
  t.ref_name = "GPS";
  t.stratum = 1;
  t.system_offset_s = 0.000002;
  t.root_dispersion_s = 0.00003;
  t.leap = "Normal";
  return t;
}

class ClockWatchTest : public ::testing::Test {
 protected:
  ClockWatch& watch(bool managed) {
    TimeConfig config;
    config.poll_s = 5.0;
    config.manage_chrony = managed;
    watch_.emplace(io_, ClockWatchParts{config, [this] { return now_s_; }, run_inline,
                                        [this] {
                                          ++probes_;
                                          return reading_;
                                        },
                                        [this](const std::vector<std::string>& s) -> Result<bool> {
                                          if (!apply_ok_) return fail("chronyd said no");
                                          file_ = s;
                                          return true;
                                        },
                                        [this] { return file_; },
                                        [this](const std::string& l) { log_.push_back(l); }});
    return *watch_;
  }

  boost::asio::io_context io_;
  double now_s_ = 100.0;
  int probes_ = 0;
  timekeeping::ClockReading reading_;
  std::vector<std::string> file_;
  bool apply_ok_ = true;
  std::vector<std::string> log_;
  std::optional<ClockWatch> watch_;
};

TEST_F(ClockWatchTest, AGpsLockedChronyIsShownSynced) {
  reading_.tracking = gps_tracking();
  reading_.kernel_synced = true;
  reading_.rtc_present = true;
  timekeeping::ChronySource gps;
  gps.mode = '#';
  gps.state = '*';
  gps.name = "GPS";
  gps.poll_log2_s = -1;
  gps.reach = 0377;
  reading_.sources = {gps};
  const auto j = watch(false).to_json();
  EXPECT_EQ(probes_, 1) << "a look at once, not after the first poll";
  EXPECT_EQ(j["synced"], true);
  EXPECT_EQ(j["reason"], nullptr);
  EXPECT_EQ(j["stratum"], 1);
  EXPECT_EQ(j["ref"], "GPS");
  EXPECT_DOUBLE_EQ(j["offset_s"].get<double>(), 0.000002);
  EXPECT_DOUBLE_EQ(j["root_dispersion_s"].get<double>(), 0.00003);
  EXPECT_EQ(j["rtc"], true);
  EXPECT_EQ(j["kernel_synced"], true);
  ASSERT_EQ(j["sources"].size(), 1U);
  EXPECT_EQ(j["sources"][0]["state"], "selected");
  EXPECT_EQ(j["sources"][0]["mode"], "refclock");
  EXPECT_DOUBLE_EQ(j["sources"][0]["poll_s"].get<double>(), 0.5);
  EXPECT_EQ(j["managed"], false);
  EXPECT_EQ(j["servers"], nullptr);
  ASSERT_EQ(log_.size(), 1U);
  EXPECT_NE(log_[0].find("synchronised (GPS)"), std::string::npos) << log_[0];
}

TEST_F(ClockWatchTest, LosingSyncIsLoggedOnceAndShownWithItsReason) {
  reading_.tracking = gps_tracking();
  ClockWatch& w = watch(false);
  reading_.tracking->stratum = 0;
  reading_.tracking->leap = "Not synchronised";
  w.check_now();
  w.check_now();
  const auto j = w.to_json();
  EXPECT_EQ(j["synced"], false);
  EXPECT_NE(j["reason"].get<std::string>().find("no usable time source"), std::string::npos);
  ASSERT_EQ(log_.size(), 2U) << "synced, then not synced: one line each";
  EXPECT_NE(log_[1].find("tracking carries on"), std::string::npos);
}

TEST_F(ClockWatchTest, NoChronydIsAReasonNotAFailure) {
  reading_.chrony_error = "506 Cannot talk to daemon";
  reading_.kernel_synced = false;
  const auto j = watch(false).to_json();
  EXPECT_EQ(j["synced"], false);
  EXPECT_EQ(j["chrony_error"], "506 Cannot talk to daemon");
  EXPECT_EQ(j["stratum"], nullptr);
  EXPECT_EQ(j["kernel_synced"], false);
}

TEST_F(ClockWatchTest, AReadingThatStopsComingGoesStale) {
  reading_.tracking = gps_tracking();
  ClockWatch& w = watch(false);
  now_s_ += 19.0;  // 3 × 5 s + 5 s allowed
  EXPECT_EQ(w.to_json()["synced"], true);
  now_s_ += 2.0;
  const auto j = w.to_json();
  EXPECT_EQ(j["synced"], false);
  EXPECT_NE(j["reason"].get<std::string>().find("stale"), std::string::npos);
}

TEST_F(ClockWatchTest, ServersAreRefusedUnlessManaged) {
  std::optional<Result<bool>> outcome;
  watch(false).set_servers({"a.example"}, [&](const Result<bool>& r) { outcome = r; });
  ASSERT_TRUE(outcome.has_value());
  ASSERT_FALSE(*outcome);
  EXPECT_NE(outcome->error().message.find("manage_chrony is off"), std::string::npos);
  EXPECT_TRUE(file_.empty()) << "nothing written";
}

TEST_F(ClockWatchTest, ManagedServersAreCheckedAppliedAndReadBack) {
  ClockWatch& w = watch(true);
  std::optional<Result<bool>> outcome;
  w.set_servers({"a.example\nallow all"}, [&](const Result<bool>& r) { outcome = r; });
  ASSERT_TRUE(outcome && !*outcome) << "a directive smuggled in a name is refused";
  EXPECT_TRUE(file_.empty());
  const int before = probes_;
  w.set_servers({"192.168.1.10", "europe.pool.ntp.org"},
                [&](const Result<bool>& r) { outcome = r; });
  ASSERT_TRUE(outcome && *outcome);
  EXPECT_EQ(file_, (std::vector<std::string>{"192.168.1.10", "europe.pool.ntp.org"}));
  EXPECT_EQ(probes_, before + 1) << "chrony is looked at again at once";
  const auto j = w.to_json();
  EXPECT_EQ(j["managed"], true);
  EXPECT_EQ(j["servers"], nlohmann::json({"192.168.1.10", "europe.pool.ntp.org"}));
  apply_ok_ = false;
  w.set_servers({"b.example"}, [&](const Result<bool>& r) { outcome = r; });
  ASSERT_TRUE(outcome && !*outcome);
  EXPECT_EQ(outcome->error().message, "chronyd said no");
  EXPECT_EQ(w.to_json()["servers"], nlohmann::json({"192.168.1.10", "europe.pool.ntp.org"}));
}

}  // namespace
}  // namespace azt::app
