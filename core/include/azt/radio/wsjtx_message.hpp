#pragma once
// WSJT-X's UDP messages (WSJTX/wsjtx Network/NetworkMessage.hpp), the ones azeltrack listens to:
// Heartbeat (0), Status (1) and Close (6). Every other type is recognised and ignored, as the
// protocol's rule 1 asks (NetworkMessage.hpp:78-100).
//
// Wire format: Qt's QDataStream, big-endian. Header quint32 magic 0xadbccbda, quint32 schema
// (2 = Qt_5_2, 3 = Qt_5_4; both encode the types read here the same way), quint32 type, utf8 id.
// utf8 = quint32 length + bytes (no terminator); length 0xffffffff is a null string. bool = 1 byte,
// non-zero true (as QDataStream reads it). Extra bytes after the known fields are ignored (rule 2).
//
// Fields are only ever appended, so an older WSJT-X sends a shorter Status. The decoder accepts a
// Status that ends where a group of fields was appended (WSJTX/wsjtx git history of
// Network/NetworkMessage.hpp): after Transmitting (the first form), after Decoding (6bf8361, 2015),
// after DX grid (Rx DF .. DX grid, 3ec6d21, 2016), after Tx watchdog (49cc27c, 2016), after Fast
// mode (Sub-mode, Fast mode, 336eb0c, 2016), after Special operation mode (025a016, 2018), after
// Configuration name (Frequency tolerance, T/R period, Configuration name, 183bf4a, 2019), after Tx
// message (dd48b48, 2020). A datagram that ends anywhere else is truncated: an error. A Heartbeat
// may end after the id (before schema 3 it had no "maximum schema" field) or after any field.
//
// Null strings: WSJT-X writes QString::toUtf8(), which is null for an empty field, so a null
// string reads as empty, except the id, which must be there (it keys the client).
// Refused (an error, never a crash): datagrams over kMaxDatagramBytes, a wrong magic, a schema
// other than 2 or 3, a length past the end, a string over kMaxStringBytes or not UTF-8.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>

#include "azt/util/result.hpp"

namespace azt::radio {

inline constexpr std::uint32_t kWsjtxMagic = 0xadbccbda;
/// WSJT-X's largest message is a few hundred bytes; a UDP datagram can be 64 KiB.
inline constexpr std::size_t kMaxDatagramBytes = 8192;
/// Calls, grids, modes and messages are tens of bytes; a configuration name is the user's.
inline constexpr std::size_t kMaxStringBytes = 512;
/// "Not applicable" in Frequency tolerance and T/R period (NetworkMessage.hpp, Status).
inline constexpr std::uint32_t kWsjtxNotApplicable = 0xffffffff;

struct WsjtxHeartbeat {
  std::string id;
  std::optional<std::uint32_t> max_schema;  ///< absent: the client speaks schema 2
  std::optional<std::string> version;
  std::optional<std::string> revision;
};

/// WSJT-X's Special operation mode (Settings > Advanced), NetworkMessage.hpp's enumeration.
enum class WsjtxSpecialOp : std::uint8_t {
  None = 0,
  NaVhf = 1,
  EuVhf = 2,
  FieldDay = 3,
  RttyRu = 4,
  WwDigi = 5,
  Fox = 6,
  Hound = 7,
  ArrlDigi = 8,
};

struct WsjtxStatus {
  std::string id;
  std::uint64_t dial_hz = 0;
  std::string mode;
  std::string dx_call;
  std::string report;
  std::string tx_mode;
  bool tx_enabled = false;
  bool transmitting = false;
  std::optional<bool> decoding;
  struct Stations {  // appended together
    std::uint32_t rx_df_hz = 0;
    std::uint32_t tx_df_hz = 0;
    std::string de_call;
    std::string de_grid;
    std::string dx_grid;
  };
  std::optional<Stations> stations;
  std::optional<bool> tx_watchdog;
  struct SubMode {
    std::string sub_mode;
    bool fast_mode = false;
  };
  std::optional<SubMode> sub_mode;
  /// The raw byte: values past ArrlDigi are kept (a newer WSJT-X), not refused.
  std::optional<std::uint8_t> special_op;
  struct Periods {
    std::uint32_t frequency_tolerance_hz = kWsjtxNotApplicable;
    std::uint32_t tr_period_s = kWsjtxNotApplicable;
    std::string configuration_name;
  };
  std::optional<Periods> periods;
  std::optional<std::string> tx_message;
};

struct WsjtxClose {
  std::string id;
};

/// A valid header of a type azeltrack does not read (Decode, Clear, QSO logged, …).
struct WsjtxIgnored {
  std::uint32_t type = 0;
};

using WsjtxMessage = std::variant<WsjtxHeartbeat, WsjtxStatus, WsjtxClose, WsjtxIgnored>;

/// One datagram as received. The error's message says what was wrong and where, for a counter's
/// log line.
Result<WsjtxMessage> decode_wsjtx_datagram(std::string_view datagram);

/// The T/R period of a Status, given or inferred from its mode: azt/radio/wsjtx_tr_period.hpp.

}  // namespace azt::radio
