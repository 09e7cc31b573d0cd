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

std::optional<TestedAxis> axis_of(const std::string& name) {
  if (name == "az") return TestedAxis::Az;
  if (name == "el") return TestedAxis::El;
  if (name == "pol") return TestedAxis::Pol;
  return std::nullopt;
}

const char* name_of(TestedAxis axis) {
  switch (axis) {
    case TestedAxis::Az:
      return "az";
    case TestedAxis::El:
      return "el";
    case TestedAxis::Pol:
      return "pol";
  }
  return "?";
}

/// What the positive command is called: a pol feed turns clockwise seen from behind the antenna.
const char* command_of(TestedAxis axis) { return axis == TestedAxis::El ? "up" : "cw"; }
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

std::optional<std::string> DirectionTest::pol_refusal() const {
  const auto pol = p_.antenna.pol_status();
  if (!pol) return "this station has no polarisation axis ([mount.pol])";
  if (!pol->fault.empty()) return "the polarisation axis is faulted: " + pol->fault;
  if (pol->moving) return "the polarisation axis is moving: wait until it stands still";
  return std::nullopt;
}

std::optional<double> DirectionTest::reading_deg() const {
  if (axis_ == TestedAxis::Pol) {
    const auto pol = p_.antenna.pol_status();
    if (!pol || !pol->fault.empty()) return std::nullopt;
    return pol->mount_deg;
  }
  const auto at = p_.antenna.position(p_.monotonic_s());
  if (!at) return std::nullopt;
  return axis_ == TestedAxis::Az ? at->az_mount_deg : at->el_deg;
}

std::optional<std::string> DirectionTest::start(const std::string& axis, const std::string& source,
                                                DirectionTestDone done) {
  const auto tested = axis_of(axis);
  if (!tested) return "axis must be \"az\", \"el\" or \"pol\"";
  if (*tested == TestedAxis::El && p_.el_fixed)
    return "the elevation is fixed ([mount.el] fixed_deg): it has no motor to test";
  if (auto no = refusal()) return no;
  if (*tested == TestedAxis::Pol) {
    if (auto no = pol_refusal()) return no;
  }
  // The console's STOP first: nothing else drives while the test runs, and PC programs stay out
  // after it as after any console STOP.
  p_.commands.stop(CommandSource{CommandSource::Kind::Console, source + " (direction test)"});
  axis_ = *tested;
  started_s_ = p_.monotonic_s();
  before_deg_ = *reading_deg();  // known: refusal() and pol_refusal() asked
  done_ = std::move(done);
  return std::nullopt;
}

std::optional<control::Demand> DirectionTest::demand(double now_s) const {
  if (!running() || now_s - started_s_ >= kDriveS) return std::nullopt;
  control::Demand d{std::nullopt, std::string("direction test: ") + name_of(axis_), std::nullopt};
  // The pol axis is driven through its own demand (pol_demand()); azimuth and elevation hold.
  if (axis_ != TestedAxis::Pol) d.test = control::AxisTest{axis_ == TestedAxis::Az, 1};
  return d;
}

std::optional<control::PolDemand> DirectionTest::pol_demand(double now_s) const {
  if (!running() || axis_ != TestedAxis::Pol || now_s - started_s_ >= kDriveS + kSettleS) {
    return std::nullopt;
  }
  // Driven for kDriveS, then held (no feed angle) while it comes to rest.
  return control::PolDemand{std::nullopt, 0.0, now_s - started_s_ < kDriveS ? 1 : 0};
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
  finish(json{{"axis", name_of(axis_)},
              {"commanded", command_of(axis_)},
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
