// libFuzzer target for WSJT-X's UDP message decoder (decode_wsjtx_datagram), reliability notes
// R24: a fuzz target for every parser. The whole input is one datagram. Invariants:
// - it decodes or is refused with a short printable message, never a crash or a hang;
// - the same datagram decodes the same way twice;
// - every decoded string is valid UTF-8 and at most kMaxStringBytes, every id non-empty;
// - a Status with every field WSJT-X writes (Tx message present) still decodes to the same
//   fields with bytes appended (the protocol's rule 2: extra trailing fields are ignored);
// - a datagram over kMaxDatagramBytes is refused.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <variant>

#include "azt/radio/wsjtx_message.hpp"
#include "azt/util/valid_utf8.hpp"
#include "fuzz_support.hpp"

namespace {

namespace radio = azt::radio;

void check_text(const std::string& text) {
  AZT_FUZZ_REQUIRE(text.size() <= radio::kMaxStringBytes);
  AZT_FUZZ_REQUIRE(azt::is_valid_utf8(text));
}

void check_status(const radio::WsjtxStatus& s) {
  for (const std::string* text : {&s.id, &s.mode, &s.dx_call, &s.report, &s.tx_mode}) {
    check_text(*text);
  }
  if (s.stations) {
    check_text(s.stations->de_call);
    check_text(s.stations->de_grid);
    check_text(s.stations->dx_grid);
  }
  if (s.sub_mode) check_text(s.sub_mode->sub_mode);
  if (s.periods) check_text(s.periods->configuration_name);
  if (s.tx_message) check_text(*s.tx_message);
  // The groups are appended in order: a later one is there only if every earlier one is.
  AZT_FUZZ_REQUIRE(!s.tx_message || s.periods);
  AZT_FUZZ_REQUIRE(!s.periods || s.special_op);
  AZT_FUZZ_REQUIRE(!s.special_op || s.sub_mode);
  AZT_FUZZ_REQUIRE(!s.sub_mode || s.tx_watchdog);
  AZT_FUZZ_REQUIRE(!s.tx_watchdog || s.stations);
  AZT_FUZZ_REQUIRE(!s.stations || s.decoding);
}

void check_message(const radio::WsjtxMessage& message) {
  if (const auto* hb = std::get_if<radio::WsjtxHeartbeat>(&message)) {
    AZT_FUZZ_REQUIRE(!hb->id.empty());
    check_text(hb->id);
    if (hb->version) check_text(*hb->version);
    if (hb->revision) check_text(*hb->revision);
  } else if (const auto* status = std::get_if<radio::WsjtxStatus>(&message)) {
    AZT_FUZZ_REQUIRE(!status->id.empty());
    check_status(*status);
  } else if (const auto* close = std::get_if<radio::WsjtxClose>(&message)) {
    AZT_FUZZ_REQUIRE(!close->id.empty());
    check_text(close->id);
  }
}

bool same_status(const radio::WsjtxStatus& a, const radio::WsjtxStatus& b) {
  return a.id == b.id && a.dial_hz == b.dial_hz && a.dx_call == b.dx_call &&
         a.transmitting == b.transmitting && a.tx_message == b.tx_message &&
         (a.stations.has_value() == b.stations.has_value()) &&
         (!a.stations || a.stations->dx_grid == b.stations->dx_grid);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view datagram(reinterpret_cast<const char*>(data), size);
  const auto decoded = radio::decode_wsjtx_datagram(datagram);
  azt::fuzz::check_error_message(decoded);
  const auto again = radio::decode_wsjtx_datagram(datagram);
  AZT_FUZZ_REQUIRE(decoded.ok() == again.ok());
  if (size > radio::kMaxDatagramBytes) AZT_FUZZ_REQUIRE(!decoded.ok());
  if (!decoded) {
    AZT_FUZZ_REQUIRE(decoded.error().message == again.error().message);
    return 0;
  }
  check_message(*decoded);
  const auto* status = std::get_if<radio::WsjtxStatus>(&*decoded);
  if (status == nullptr || !status->tx_message || size + 3 > radio::kMaxDatagramBytes) return 0;
  const std::string longer = std::string(datagram) + "\x01\x02\x03";
  const auto extended = radio::decode_wsjtx_datagram(longer);
  AZT_FUZZ_REQUIRE(extended.ok());
  const auto* extended_status = std::get_if<radio::WsjtxStatus>(&*extended);
  AZT_FUZZ_REQUIRE(extended_status != nullptr && same_status(*status, *extended_status));
  return 0;
}

#ifdef AZT_FUZZ_STANDALONE
int main(int argc, char** argv) {
  return azt::fuzz::replay_files("wsjtx_message_fuzz", argc, argv);
}
#endif
