// The `hamlib` backend as the one station backend over a rotator box (docs/daemon.md): Hamlib's
// in-process dummy rotator (model 1, turning at 6 deg/s in real time) is each axis's setpoint
// drive and position sensor, read and supervised by the real StationController. The box is a
// real peer moving in real time, so the loop ticks on the steady clock, with deadlines.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <thread>

#include "antenna/antenna_backend.hpp"
#include "config/config_file.hpp"
#include "config/daemon_config.hpp"

namespace azt::app {
namespace {

using Clock = std::chrono::steady_clock;

DaemonConfig hamlib_config() {
  // The dummy turns at 6 deg/s: the mount's rate says so, or its motion would be a jump.
  const std::string text =
      "[station]\ngrid = \"FN06HE\"\n[antenna]\nbackend = \"hamlib\"\n"
      "[hamlib]\nmodel = 1\npoll_s = 0.05\n"
      "[mount.az]\nmax_rate_deg_s = 6.0\n[mount.el]\nmax_rate_deg_s = 6.0\n"
      "[sim.az]\nstart_deg = 0.0\n[sim.el]\nstart_deg = 0.0\n";
  return daemon_config_from(ConfigFile::parse(text, "hamlib.toml"));
}

class HamlibBackendTest : public ::testing::Test {
 protected:
  double seconds() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

  /// Ticks at 20 Hz with `demand` until `done` or `limit_s` more seconds; true if done.
  template <typename Done>
  bool run(const control::Demand& demand, double limit_s, Done done) {
    const double end = seconds() + limit_s;
    while (seconds() < end) {
      backend_->tick(seconds(), demand, control::AzEl{});
      if (done()) return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(50));  // the tick period
    }
    return false;
  }

  [[nodiscard]] std::optional<proto::PositionReport> here() const {
    return backend_->position(seconds());
  }

  Clock::time_point start_ = Clock::now();
  std::unique_ptr<AntennaBackend> backend_ = make_hamlib_backend(hamlib_config());
};

TEST_F(HamlibBackendTest, ReachesTheTargetThroughTheStationController) {
  control::Demand go;
  go.position = control::AzEl{8.0, 4.0};
  const bool arrived = run(go, 6.0, [&] {
    const auto p = here();
    return p && std::fabs(p->az_deg - 8.0) < 0.5 && std::fabs(p->el_deg - 4.0) < 0.5;
  });
  EXPECT_TRUE(arrived) << "not at 8/4 after 6 s";
  EXPECT_TRUE(backend_->faults().empty()) << backend_->faults().front();
}

// STOP mid-move stops the box where it stands (it used to be sent rot_stop; a setpoint drive is
// now sent its present position), and the hold is not a stream of new setpoints.
TEST_F(HamlibBackendTest, StopMidMoveStopsTheBoxWhereItStands) {
  control::Demand go;
  go.position = control::AzEl{30.0, 0.0};  // 5 s away
  ASSERT_TRUE(run(go, 4.0, [&] {
    const auto p = here();
    return p && p->az_deg > 6.0;
  })) << "the box never started towards 30°";
  run(control::Demand{}, 0.3, [] { return false; });  // STOP, and the coast
  const auto stopped = here();
  ASSERT_TRUE(stopped.has_value());
  EXPECT_LT(stopped->az_deg, 20.0);
  run(control::Demand{}, 1.5, [] { return false; });
  const auto later = here();
  ASSERT_TRUE(later.has_value());
  EXPECT_NEAR(later->az_deg, stopped->az_deg, 0.7) << "the box kept moving after STOP";
  EXPECT_TRUE(backend_->faults().empty()) << backend_->faults().front();
}

// A fault stops the box: an E-stop latches, and no target moves it until it is cleared.
TEST_F(HamlibBackendTest, AnEmergencyStopHoldsTheBoxUntilCleared) {
  control::Demand go;
  go.position = control::AzEl{20.0, 0.0};
  ASSERT_TRUE(run(go, 3.0, [&] {
    const auto p = here();
    return p && p->az_deg > 3.0;
  }));
  backend_->stop_now(seconds());
  run(go, 0.3, [] { return false; });
  const double at = backend_->encoder_reading().value().az_deg;
  run(go, 1.5, [] { return false; });
  EXPECT_NEAR(backend_->encoder_reading().value().az_deg, at, 0.7)
      << "the box moved while the E-stop was latched";
  EXPECT_FALSE(backend_->faults().empty());
  backend_->clear_faults();
  EXPECT_TRUE(run(go, 5.0, [&] {
    const auto p = here();
    return p && std::fabs(p->az_deg - 20.0) < 0.5;
  })) << "the box did not go on after the fault was cleared";
}

}  // namespace
}  // namespace azt::app
