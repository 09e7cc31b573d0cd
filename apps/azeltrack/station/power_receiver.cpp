#include "station/power_receiver.hpp"

#include <utility>

#include "azt/proto/power_line.hpp"
#include "azt/proto/rtl_power_csv.hpp"
#include "common/usage_error.hpp"

namespace azt::app {
namespace {

calibration::PowerFeedSettings settings(const ReceiverConfig& config) {
  calibration::PowerFeedSettings s;
  s.stale_s = config.stale_s;
  return s;
}

std::string source_name(ReceiverConfig::Source s) {
  switch (s) {
    case ReceiverConfig::Source::RtlPower:
      return "rtl_power";
    case ReceiverConfig::Source::Udp:
      return "udp";
    case ReceiverConfig::Source::Sim:
      return "sim";
    case ReceiverConfig::Source::None:
      break;
  }
  return "none";
}

}  // namespace

PowerReceiver::PowerReceiver(boost::asio::io_context& io, const ReceiverConfig& config,
                             std::function<double()> monotonic_s,
                             std::function<void(const std::string&)> log)
    : config_(config),
      now_s_(std::move(monotonic_s)),
      log_(std::move(log)),
      feed_(settings(config)) {
  if (config_.source == ReceiverConfig::Source::RtlPower) {
    linux_os::LineFeedConfig c;
    c.path = config_.path;
    lines_ = std::make_unique<linux_os::LineFeed>(
        io, c,
        linux_os::LineFeedEvents{[this](std::string_view line) { rtl_power_line(line); },
                                 [this](const std::string& problem) {
                                   problem_ = problem;
                                   if (!problem.empty()) log_("receiver: " + problem);
                                 }});
  } else if (config_.source == ReceiverConfig::Source::Udp) {
    auto server = linux_os::UdpDatagramServer::open(
        io, "receiver", config_.bind, config_.port, 0,
        [this](std::string_view datagram, const std::string& /*client*/) {
          this->datagram(datagram);
          return std::string{};  // no reply
        });
    if (!server) throw UsageError("[receiver]: " + server.error().message);
    // A cut datagram's last line would read as a false power: none of it counts.
    server.value()->on_oversized([this](std::size_t bytes, const std::string& /*client*/) {
      feed_.malformed(now_s_(), "a datagram of " + std::to_string(bytes) + " bytes is over " +
                                    std::to_string(linux_os::UdpDatagramServer::kMaxDatagramBytes) +
                                    " and was dropped whole");
    });
    udp_ = std::move(server).value();
  }
}

void PowerReceiver::simulate(std::function<std::optional<double>()> read, double rate_hz) {
  simulated_ = std::move(read);
  period_s_ = 1.0 / rate_hz;
  next_s_ = now_s_();
}

void PowerReceiver::tick(double now_s) {
  if (!simulated_) return;
  if (now_s - next_s_ > 1.0) next_s_ = now_s;  // a stalled loop does not read a burst after
  while (next_s_ <= now_s) {
    if (const auto db = simulated_()) feed_.accept(now_s, *db);
    next_s_ += period_s_;
  }
}

void PowerReceiver::rtl_power_line(std::string_view line) {
  const auto sweep = proto::parse_rtl_power_line(line);
  if (!sweep) {
    feed_.malformed(now_s_(), sweep.error().message);
    return;
  }
  feed_.accept(now_s_(), proto::sweep_power_db(*sweep));
}

void PowerReceiver::datagram(std::string_view datagram) {
  for (const auto& reading : proto::parse_power_lines(datagram)) {
    if (reading) {
      feed_.accept(now_s_(), *reading);
    } else {
      feed_.malformed(now_s_(), reading.error().message);
    }
  }
}

nlohmann::json PowerReceiver::to_json() const {
  using nlohmann::json;
  if (config_.source == ReceiverConfig::Source::None)
    return json{{"source", "none"}, {"state", "off"}};
  const double now = now_s_();
  const auto latest = feed_.latest(now);
  const calibration::PowerFeedCounts counts = feed_.counts();
  json j{{"source", source_name(config_.source)},
         {"state", latest ? "receiving" : "silent"},
         {"power_db", latest ? json(latest->power_db) : json(nullptr)},
         {"age_s", latest ? json(now - latest->t_s) : json(nullptr)},
         {"good", counts.good},
         {"malformed", counts.malformed},
         {"missing", counts.missing},
         {"last_malformed", feed_.last_malformed_reason()},
         {"problem", problem_}};
  if (udp_) j["listen"] = config_.bind + ":" + std::to_string(udp_->port());
  if (lines_) j["path"] = config_.path;
  return j;
}

}  // namespace azt::app
