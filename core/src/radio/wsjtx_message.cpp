// WSJT-X UDP message decoder (the rules are in wsjtx_message.hpp).
#include "azt/radio/wsjtx_message.hpp"

#include <array>
#include <string>
#include <utility>

#include "azt/util/valid_utf8.hpp"

namespace azt::radio {
namespace {

constexpr std::uint32_t kNullLength = 0xffffffff;

enum class MessageType : std::uint32_t { Heartbeat = 0, Status = 1, Close = 6 };

/// A QDataStream read cursor: big-endian, every read checked against the end. The first failure
/// stops it and keeps its message.
class Reader {
 public:
  explicit Reader(std::string_view bytes) : bytes_(bytes) {}

  bool u8(std::uint8_t& out, std::string_view field) {
    std::uint64_t value = 0;
    if (!big_endian(value, 1, field)) return false;
    out = static_cast<std::uint8_t>(value);
    return true;
  }
  bool u32(std::uint32_t& out, std::string_view field) {
    std::uint64_t value = 0;
    if (!big_endian(value, 4, field)) return false;
    out = static_cast<std::uint32_t>(value);
    return true;
  }
  bool u64(std::uint64_t& out, std::string_view field) { return big_endian(out, 8, field); }
  bool boolean(bool& out, std::string_view field) {
    std::uint8_t byte = 0;
    if (!u8(byte, field)) return false;
    out = byte != 0;  // QDataStream reads any non-zero byte as true
    return true;
  }
  bool utf8(std::string& out, std::string_view field, bool null_allowed = true);

  [[nodiscard]] bool at_end() const { return at_ == bytes_.size(); }
  [[nodiscard]] Error failure() const { return Error{error_}; }
  bool refuse(std::string message) {
    error_ = std::move(message);
    return false;
  }

 private:
  bool big_endian(std::uint64_t& out, std::size_t size, std::string_view field);
  std::string where(std::string_view field) const {
    return std::string(field) + " at byte " + std::to_string(at_);
  }

  std::string_view bytes_;
  std::size_t at_ = 0;
  std::string error_;
};

bool Reader::big_endian(std::uint64_t& out, std::size_t size, std::string_view field) {
  if (bytes_.size() - at_ < size) {
    return refuse("truncated: " + where(field) + " needs " + std::to_string(size) + " bytes, " +
                  std::to_string(bytes_.size() - at_) + " left");
  }
  out = 0;
  for (std::size_t i = 0; i < size; ++i) {
    out = (out << 8U) | static_cast<unsigned char>(bytes_[at_ + i]);
  }
  at_ += size;
  return true;
}

bool Reader::utf8(std::string& out, std::string_view field, bool null_allowed) {
  const std::string at = where(field);  // messages name the field's first byte, its length
  std::uint32_t length = 0;
  if (!u32(length, field)) return false;
  if (length == kNullLength) {
    out.clear();
    return null_allowed || refuse("null " + at);
  }
  if (length > kMaxStringBytes) {
    return refuse(at + ": " + std::to_string(length) + " bytes, over the " +
                  std::to_string(kMaxStringBytes) + " allowed");
  }
  if (bytes_.size() - at_ < length) {
    return refuse("truncated: " + at + " says " + std::to_string(length) + " bytes, " +
                  std::to_string(bytes_.size() - at_) + " left");
  }
  const std::string_view text = bytes_.substr(at_, length);
  if (!is_valid_utf8(text)) return refuse(at + " is not UTF-8");
  out.assign(text);
  at_ += length;
  return true;
}

// Status, in the groups in which WSJT-X appended its fields.
bool read_first_fields(Reader& r, WsjtxStatus& s) {
  return r.u64(s.dial_hz, "Dial frequency") && r.utf8(s.mode, "Mode") &&
         r.utf8(s.dx_call, "DX call") && r.utf8(s.report, "Report") &&
         r.utf8(s.tx_mode, "Tx mode") && r.boolean(s.tx_enabled, "Tx enabled") &&
         r.boolean(s.transmitting, "Transmitting");
}

bool read_decoding(Reader& r, WsjtxStatus& s) {
  bool decoding = false;
  if (!r.boolean(decoding, "Decoding")) return false;
  s.decoding = decoding;
  return true;
}

bool read_stations(Reader& r, WsjtxStatus& s) {
  WsjtxStatus::Stations st;
  if (!(r.u32(st.rx_df_hz, "Rx DF") && r.u32(st.tx_df_hz, "Tx DF") &&
        r.utf8(st.de_call, "DE call") && r.utf8(st.de_grid, "DE grid") &&
        r.utf8(st.dx_grid, "DX grid"))) {
    return false;
  }
  s.stations = std::move(st);
  return true;
}

bool read_watchdog(Reader& r, WsjtxStatus& s) {
  bool watchdog = false;
  if (!r.boolean(watchdog, "Tx watchdog")) return false;
  s.tx_watchdog = watchdog;
  return true;
}

bool read_sub_mode(Reader& r, WsjtxStatus& s) {
  WsjtxStatus::SubMode sub;
  if (!(r.utf8(sub.sub_mode, "Sub-mode") && r.boolean(sub.fast_mode, "Fast mode"))) return false;
  s.sub_mode = std::move(sub);
  return true;
}

bool read_special_op(Reader& r, WsjtxStatus& s) {
  std::uint8_t special = 0;
  if (!r.u8(special, "Special operation mode")) return false;
  s.special_op = special;
  return true;
}

bool read_periods(Reader& r, WsjtxStatus& s) {
  WsjtxStatus::Periods periods;
  if (!(r.u32(periods.frequency_tolerance_hz, "Frequency tolerance") &&
        r.u32(periods.tr_period_s, "T/R period") &&
        r.utf8(periods.configuration_name, "Configuration name"))) {
    return false;
  }
  s.periods = std::move(periods);
  return true;
}

bool read_tx_message(Reader& r, WsjtxStatus& s) {
  std::string message;
  if (!r.utf8(message, "Tx message")) return false;
  s.tx_message = std::move(message);
  return true;
}

using StatusGroup = bool (*)(Reader&, WsjtxStatus&);
constexpr std::array<StatusGroup, 7> kAppendedGroups = {
    read_decoding,   read_stations, read_watchdog,  read_sub_mode,
    read_special_op, read_periods,  read_tx_message};

Result<WsjtxMessage> read_status(Reader& r, std::string id) {
  WsjtxStatus s;
  s.id = std::move(id);
  if (!read_first_fields(r, s)) return r.failure();
  for (const StatusGroup group : kAppendedGroups) {
    if (r.at_end()) break;
    if (!group(r, s)) return r.failure();
  }
  return WsjtxMessage{std::move(s)};
}

Result<WsjtxMessage> read_heartbeat(Reader& r, std::string id) {
  WsjtxHeartbeat h;
  h.id = std::move(id);
  std::uint32_t schema = 0;
  std::string text;
  if (r.at_end()) return WsjtxMessage{std::move(h)};
  if (!r.u32(schema, "Maximum schema")) return r.failure();
  h.max_schema = schema;
  if (r.at_end()) return WsjtxMessage{std::move(h)};
  if (!r.utf8(text, "Version")) return r.failure();
  h.version = std::move(text);
  if (r.at_end()) return WsjtxMessage{std::move(h)};
  if (!r.utf8(text, "Revision")) return r.failure();
  h.revision = std::move(text);
  return WsjtxMessage{std::move(h)};
}

std::string hex(std::uint32_t value) {
  constexpr std::string_view kDigits = "0123456789abcdef";
  std::string text = "0x";
  for (int shift = 28; shift >= 0; shift -= 4) {
    text += kDigits[(value >> static_cast<unsigned>(shift)) & 0xfU];
  }
  return text;
}

bool read_header(Reader& r, std::uint32_t& type) {
  std::uint32_t magic = 0;
  std::uint32_t schema = 0;
  if (!r.u32(magic, "Magic")) return false;
  if (magic != kWsjtxMagic) return r.refuse("not a WSJT-X message: magic " + hex(magic));
  if (!r.u32(schema, "Schema")) return false;
  if (schema != 2 && schema != 3) {
    return r.refuse("schema " + std::to_string(schema) + ": azeltrack reads schemas 2 and 3");
  }
  return r.u32(type, "Type");
}

Result<WsjtxMessage> read_body(Reader& r, MessageType type, std::string id) {
  switch (type) {
    case MessageType::Heartbeat:
      return read_heartbeat(r, std::move(id));
    case MessageType::Status:
      return read_status(r, std::move(id));
    case MessageType::Close:
      return WsjtxMessage{WsjtxClose{std::move(id)}};
  }
  return WsjtxMessage{WsjtxIgnored{static_cast<std::uint32_t>(type)}};
}

bool is_read(std::uint32_t type) {
  return type == static_cast<std::uint32_t>(MessageType::Heartbeat) ||
         type == static_cast<std::uint32_t>(MessageType::Status) ||
         type == static_cast<std::uint32_t>(MessageType::Close);
}

}  // namespace

Result<WsjtxMessage> decode_wsjtx_datagram(std::string_view datagram) {
  if (datagram.size() > kMaxDatagramBytes) {
    return fail("datagram of " + std::to_string(datagram.size()) + " bytes, over the " +
                std::to_string(kMaxDatagramBytes) + " a WSJT-X message can be");
  }
  Reader r(datagram);
  std::uint32_t type = 0;
  if (!read_header(r, type)) return r.failure();
  if (!is_read(type)) return WsjtxMessage{WsjtxIgnored{type}};
  std::string id;
  if (!r.utf8(id, "Id", false)) return r.failure();
  if (id.empty()) return fail("empty Id: WSJT-X names every client");
  return read_body(r, static_cast<MessageType>(type), std::move(id));
}

}  // namespace azt::radio
