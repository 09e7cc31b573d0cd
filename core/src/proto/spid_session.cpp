// SPID Rot2Prog/Rot1Prog session: SpidFrameAssembler + parse_spid + the RotatorService (rules in
// sessions.hpp).
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>

#include "azt/proto/sessions.hpp"
#include "azt/proto/spid.hpp"

namespace azt::proto {
namespace {

template <std::size_t N>
std::string to_bytes(const std::array<std::uint8_t, N>& frame) {
  std::string out;
  out.reserve(N);
  for (const std::uint8_t byte : frame) out.push_back(static_cast<char>(byte));
  return out;
}

class SpidSession final : public ProtocolSession {
 public:
  SpidSession(RotatorService& service, std::string client, SpidConfig config)
      : service_(service), client_(std::move(client)), config_(config) {}

  std::string feed(std::string_view bytes) override {
    std::string out;
    for (const char byte : bytes) {
      if (const auto frame = frames_.push(static_cast<std::uint8_t>(byte))) {
        service_.activity(client_);
        out += answer(*frame);
      }
    }
    return out;
  }

 private:
  std::string answer(const SpidFrame& frame) {
    const auto command = parse_spid(std::span<const std::uint8_t>(frame), config_);
    if (!command) {
      service_.refused(client_, command.error().message);
      return {};  // SPID has no error frame
    }
    switch (command->op) {
      case SpidOp::Set:
        // The controller never answers a set, so a refusal cannot be reported either.
        if (config_.dialect == SpidDialect::Rot1Prog) {
          service_.goto_axis(client_, Axis::Az, command->az_deg);
        } else {
          service_.goto_position(client_, command->az_deg, command->el_deg);
        }
        return {};
      case SpidOp::Stop:
        service_.stop(client_, std::nullopt);
        return position_reply();
      case SpidOp::Status:
        return position_reply();
    }
    return {};
  }

  /// The dialect's position frame, or nothing when there is no position to put in it.
  std::string position_reply() const {
    const auto position = service_.position();
    if (!position) return {};
    if (config_.dialect == SpidDialect::Rot1Prog) {
      const auto reply = format_spid_rot1_reply(position->az_deg);
      return reply ? to_bytes(*reply) : std::string();
    }
    const auto reply = format_spid_rot2_reply(position->az_deg, position->el_deg, config_);
    return reply ? to_bytes(*reply) : std::string();
  }

  RotatorService& service_;
  std::string client_;
  SpidConfig config_;
  SpidFrameAssembler frames_;
};

}  // namespace

std::unique_ptr<ProtocolSession> make_spid_session(RotatorService& service, std::string client,
                                                   SpidConfig config) {
  return std::make_unique<SpidSession>(service, std::move(client), config);
}

}  // namespace azt::proto
