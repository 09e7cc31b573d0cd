#include "station/direction_test.hpp"

#include <cmath>
#include <utility>

namespace azt::app {

using json = nlohmann::json;

namespace {
/// The test's verdict from the motion of the reading for a positive (clockwise / up) command.
std::string verdict_of(double moved_deg) {
  if (std::fabs(moved_deg) < DirectionTest::kMovedDeg) return "no movement";
  return moved_deg > 0.0 ? "ok" : "reversed";
}
}  // namespace

std::optional<std::string> DirectionTest::refusal() const {
  if (running()) return "a direction test is already running";
  if (p_.modes.mode() == control::Mode::Track || p_.commands.tracking_satellite()) {
    return "the antenna is tracking: STOP it first";
  }
  if (p_.transmitting()) return "the transmitter is keyed: no motion while it transmits";
  if (const auto faults = p_.antenna.faults(); !faults.empty()) {
    return "a fault is latched: " + faults.front();
  }
  const auto at = p_.antenna.position(p_.monotonic_s());
  if (!at) return "the antenna's position is unknown";
  if (at->moving) return "the antenna is moving: wait until it stands still";
  return std::nullopt;
}

std::optional<double> DirectionTest::reading_deg() const {
  const auto at = p_.antenna.position(p_.monotonic_s());
  if (!at) return std::nullopt;
  return azimuth_ ? at->az_mount_deg : at->el_deg;
}

std::optional<std::string> DirectionTest::start(const std::string& axis, const std::string& source,
                                                DirectionTestDone done) {
  if (axis != "az" && axis != "el") return "axis must be \"az\" or \"el\"";
  if (axis == "el" && p_.el_fixed)
    return "the elevation is fixed ([mount.el] fixed_deg): it has no motor to test";
  if (auto no = refusal()) return no;
  // The console's STOP first: nothing else drives while the test runs, and PC programs stay out
  // after it as after any console STOP.
  p_.commands.stop(CommandSource{CommandSource::Kind::Console, source + " (direction test)"});
  azimuth_ = axis == "az";
  started_s_ = p_.monotonic_s();
  before_deg_ = *reading_deg();
  done_ = std::move(done);
  return std::nullopt;
}

std::optional<control::Demand> DirectionTest::demand(double now_s) const {
  if (!running() || now_s - started_s_ >= kDriveS) return std::nullopt;
  control::Demand d{std::nullopt,
                    azimuth_ ? "direction test: azimuth" : "direction test: elevation",
                    std::nullopt};
  d.test = control::AxisTest{azimuth_, 1};
  return d;
}

void DirectionTest::tick(double now_s) {
  if (!running()) return;
  if (const auto faults = p_.antenna.faults(); !faults.empty()) {
    interrupt("a fault stopped it: " + faults.front());
    return;
  }
  if (now_s - started_s_ < kDriveS + kSettleS) return;
  const auto after = reading_deg();
  if (!after) {
    interrupt("the position was lost during the test");
    return;
  }
  const double moved = *after - before_deg_;
  finish(json{{"axis", azimuth_ ? "az" : "el"},
              {"commanded", azimuth_ ? "cw" : "up"},
              {"before_deg", before_deg_},
              {"after_deg", *after},
              {"moved_deg", moved},
              {"verdict", verdict_of(moved)}},
         std::nullopt);
}

void DirectionTest::interrupt(const std::string& why) {
  if (running()) finish(json::object(), "the test ended early: " + why);
}

void DirectionTest::finish(json result, std::optional<std::string> error) {
  auto done = std::exchange(done_, nullptr);
  done(std::move(result), std::move(error));
}

}  // namespace azt::app
