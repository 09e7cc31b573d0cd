#pragma once
// A RotatorService that records every request as one readable line ("goto_position c1 123.45 10")
// so session tests can compare the whole conversation with the station, in order.

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "azt/proto/rotator_service.hpp"
#include "azt/util/format_number.hpp"

namespace azt::test {

class FakeRotatorService final : public proto::RotatorService {
 public:
  /// What position() reports; nullopt simulates stale sensors.
  std::optional<proto::PositionReport> report = proto::PositionReport{123.4, 45.6, 123.4};
  /// What every request answers.
  proto::ServiceStatus status = proto::ServiceStatus::Ok;
  std::string info_text = "azeltrack test station";
  /// Requests, in order. activity() is recorded too unless `record_activity` is false.
  std::vector<std::string> calls;
  bool record_activity = true;
  mutable int position_queries = 0;

  [[nodiscard]] std::optional<proto::PositionReport> position() const override {
    ++position_queries;
    return report;
  }
  proto::ServiceStatus goto_position(std::string_view client, double az_deg,
                                     double el_deg) override {
    record("goto_position", client, format_number(az_deg) + ' ' + format_number(el_deg));
    return status;
  }
  proto::ServiceStatus goto_axis(std::string_view client, proto::Axis axis, double deg) override {
    record("goto_axis", client, std::string(name(axis)) + ' ' + format_number(deg));
    return status;
  }
  proto::ServiceStatus move(std::string_view client, proto::AxisMotion motion) override {
    record("move", client, std::to_string(motion.az) + ' ' + std::to_string(motion.el));
    return status;
  }
  void stop(std::string_view client, std::optional<proto::Axis> axis) override {
    record("stop", client, axis ? name(*axis) : "all");
  }
  proto::ServiceStatus park(std::string_view client) override {
    record("park", client, {});
    return status;
  }
  void activity(std::string_view client) override {
    if (record_activity) record("activity", client, {});
  }
  [[nodiscard]] std::string info() const override { return info_text; }

 private:
  static std::string_view name(proto::Axis axis) { return axis == proto::Axis::Az ? "az" : "el"; }

  void record(std::string_view what, std::string_view client, std::string_view args) {
    std::string line(what);
    line += ' ';
    line += client;
    if (!args.empty()) {
      line += ' ';
      line += args;
    }
    calls.push_back(std::move(line));
  }
};

}  // namespace azt::test
