// WSJT-X's UDP messages built byte by byte as Network/NetworkMessage.hpp documents them
// (QDataStream, big-endian), decoded: Heartbeat, Status in full and in each older, shorter form,
// Close, ignored types, and every way a datagram can be wrong.
#include "azt/radio/wsjtx_message.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

namespace azt::radio {
namespace {

/// A datagram under construction.
struct Bytes {
  std::string data;

  Bytes& be(std::uint64_t value, int size) {
    for (int shift = 8 * (size - 1); shift >= 0; shift -= 8) {
      data += static_cast<char>((value >> static_cast<unsigned>(shift)) & 0xffU);
    }
    return *this;
  }
  Bytes& u32(std::uint32_t value) { return be(value, 4); }
  Bytes& u64(std::uint64_t value) { return be(value, 8); }
  Bytes& u8(std::uint8_t value) { return be(value, 1); }
  Bytes& boolean(bool value) { return u8(value ? 1 : 0); }
  Bytes& utf8(const std::string& text) {
    u32(static_cast<std::uint32_t>(text.size()));
    data += text;
    return *this;
  }
  Bytes& null_utf8() { return u32(0xffffffff); }
};

Bytes header(std::uint32_t type, std::uint32_t schema = 3, const std::string& id = "WSJT-X") {
  Bytes b;
  b.u32(0xadbccbda).u32(schema).u32(type).utf8(id);
  return b;
}

/// A full schema-3 Status of WSJT-X 2.6 on 10368 MHz, Q65-60C, and the byte counts at which each
/// appended group ends.
struct FullStatus {
  std::string data;
  std::vector<std::size_t> group_ends;
};

FullStatus full_status() {
  Bytes b = header(1);
  FullStatus out;
  b.u64(10368100000ULL)
      .utf8("Q65")
      .utf8("DL7ABC")
      .utf8("-12")
      .utf8("Q65")
      .boolean(true)
      .boolean(false);
  out.group_ends.push_back(b.data.size());
  b.boolean(true);  // decoding
  out.group_ends.push_back(b.data.size());
  b.u32(1500).u32(1200).utf8("G4XYZ").utf8("IO91").utf8("JO62");
  out.group_ends.push_back(b.data.size());
  b.boolean(false);  // Tx watchdog
  out.group_ends.push_back(b.data.size());
  b.utf8("C").boolean(false);
  out.group_ends.push_back(b.data.size());
  b.u8(2);  // EU VHF
  out.group_ends.push_back(b.data.size());
  b.u32(100).u32(60).utf8("10 GHz EME");
  out.group_ends.push_back(b.data.size());
  b.utf8("DL7ABC G4XYZ IO91");
  out.group_ends.push_back(b.data.size());
  out.data = b.data;
  return out;
}

TEST(WsjtxMessage, HeartbeatAsAClientSendsItBeforeNegotiation) {
  Bytes b;
  b.u32(0xadbccbda).u32(2).u32(0).utf8("WSJT-X").u32(3).utf8("3.0.1").utf8("c04dd8d");
  const auto decoded = decode_wsjtx_datagram(b.data);
  ASSERT_TRUE(decoded.ok()) << decoded.error().message;
  const auto& hb = std::get<WsjtxHeartbeat>(*decoded);
  EXPECT_EQ(hb.id, "WSJT-X");
  EXPECT_EQ(hb.max_schema, 3U);
  EXPECT_EQ(hb.version, "3.0.1");
  EXPECT_EQ(hb.revision, "c04dd8d");
  // Before schema 3 a heartbeat could end after the id.
  const auto old = decode_wsjtx_datagram(header(0, 2).data);
  ASSERT_TRUE(old.ok());
  EXPECT_EQ(std::get<WsjtxHeartbeat>(*old).max_schema, std::nullopt);
}

TEST(WsjtxMessage, AFullStatus) {
  const auto decoded = decode_wsjtx_datagram(full_status().data);
  ASSERT_TRUE(decoded.ok()) << decoded.error().message;
  const auto& s = std::get<WsjtxStatus>(*decoded);
  EXPECT_EQ(s.id, "WSJT-X");
  EXPECT_EQ(s.dial_hz, 10368100000ULL);
  EXPECT_EQ(s.mode, "Q65");
  EXPECT_EQ(s.dx_call, "DL7ABC");
  EXPECT_EQ(s.report, "-12");
  EXPECT_TRUE(s.tx_enabled);
  EXPECT_FALSE(s.transmitting);
  EXPECT_EQ(s.decoding, true);
  ASSERT_TRUE(s.stations);
  EXPECT_EQ(s.stations->rx_df_hz, 1500U);
  EXPECT_EQ(s.stations->tx_df_hz, 1200U);
  EXPECT_EQ(s.stations->de_call, "G4XYZ");
  EXPECT_EQ(s.stations->de_grid, "IO91");
  EXPECT_EQ(s.stations->dx_grid, "JO62");
  EXPECT_EQ(s.tx_watchdog, false);
  ASSERT_TRUE(s.sub_mode);
  EXPECT_EQ(s.sub_mode->sub_mode, "C");
  EXPECT_EQ(s.special_op, 2);
  ASSERT_TRUE(s.periods);
  EXPECT_EQ(s.periods->frequency_tolerance_hz, 100U);
  EXPECT_EQ(s.periods->tr_period_s, 60U);
  EXPECT_EQ(s.periods->configuration_name, "10 GHz EME");
  EXPECT_EQ(s.tx_message, "DL7ABC G4XYZ IO91");
}

TEST(WsjtxMessage, EveryOlderShorterStatusIsRead) {
  const FullStatus full = full_status();
  for (std::size_t i = 0; i < full.group_ends.size(); ++i) {
    const auto decoded = decode_wsjtx_datagram(full.data.substr(0, full.group_ends[i]));
    ASSERT_TRUE(decoded.ok()) << "group " << i << ": " << decoded.error().message;
    const auto& s = std::get<WsjtxStatus>(*decoded);
    EXPECT_EQ(s.dx_call, "DL7ABC");
    EXPECT_EQ(s.decoding.has_value(), i >= 1) << i;
    EXPECT_EQ(s.stations.has_value(), i >= 2) << i;
    EXPECT_EQ(s.tx_watchdog.has_value(), i >= 3) << i;
    EXPECT_EQ(s.sub_mode.has_value(), i >= 4) << i;
    EXPECT_EQ(s.special_op.has_value(), i >= 5) << i;
    EXPECT_EQ(s.periods.has_value(), i >= 6) << i;
    EXPECT_EQ(s.tx_message.has_value(), i >= 7) << i;
  }
}

TEST(WsjtxMessage, AStatusCutInsideAGroupIsTruncated) {
  const FullStatus full = full_status();
  std::size_t boundary = 0;
  std::size_t refused = 0;
  for (std::size_t size = full.group_ends.front(); size < full.data.size(); ++size) {
    const bool at_boundary =
        std::find(full.group_ends.begin(), full.group_ends.end(), size) != full.group_ends.end();
    const auto decoded = decode_wsjtx_datagram(full.data.substr(0, size));
    EXPECT_EQ(decoded.ok(), at_boundary) << size;
    boundary += at_boundary ? 1U : 0U;
    refused += decoded.ok() ? 0U : 1U;
  }
  EXPECT_EQ(boundary, full.group_ends.size() - 1);
  EXPECT_GT(refused, 50U);
  // Every cut before the first group's end too: the first form is the least a Status has.
  for (std::size_t size = 0; size < full.group_ends.front(); ++size) {
    EXPECT_FALSE(decode_wsjtx_datagram(full.data.substr(0, size)).ok()) << size;
  }
  const auto cut = decode_wsjtx_datagram(full.data.substr(0, full.group_ends[1] + 2));
  EXPECT_EQ(cut.error().message, "truncated: Rx DF at byte 64 needs 4 bytes, 2 left");
}

TEST(WsjtxMessage, ExtraBytesAfterTheKnownFieldsAreIgnored) {
  const std::string longer = full_status().data + std::string("\x00\x00\x00\x07more", 8);
  const auto decoded = decode_wsjtx_datagram(longer);
  ASSERT_TRUE(decoded.ok());
  EXPECT_EQ(std::get<WsjtxStatus>(*decoded).tx_message, "DL7ABC G4XYZ IO91");
}

TEST(WsjtxMessage, NullStringsReadAsEmptyExceptTheId) {
  Bytes b = header(1);
  b.u64(144174000).utf8("FT8").null_utf8().null_utf8().utf8("FT8").boolean(false).boolean(true);
  const auto decoded = decode_wsjtx_datagram(b.data);
  ASSERT_TRUE(decoded.ok()) << decoded.error().message;
  EXPECT_EQ(std::get<WsjtxStatus>(*decoded).dx_call, "");
  EXPECT_TRUE(std::get<WsjtxStatus>(*decoded).transmitting);
  Bytes null_id;
  null_id.u32(0xadbccbda).u32(3).u32(1).null_utf8();
  EXPECT_EQ(decode_wsjtx_datagram(null_id.data).error().message, "null Id at byte 12");
  EXPECT_FALSE(decode_wsjtx_datagram(header(6, 3, "").data).ok());
}

TEST(WsjtxMessage, CloseAndIgnoredTypes) {
  const auto close = decode_wsjtx_datagram(header(6, 2, "WSJT-X - rig2").data);
  ASSERT_TRUE(close.ok());
  EXPECT_EQ(std::get<WsjtxClose>(*close).id, "WSJT-X - rig2");
  // A Decode (2) with its body, and a type from the future with garbage after the header.
  Bytes decode = header(2);
  decode.boolean(true).u32(3600000).be(static_cast<std::uint32_t>(-15), 4);
  const auto ignored = decode_wsjtx_datagram(decode.data);
  ASSERT_TRUE(ignored.ok());
  EXPECT_EQ(std::get<WsjtxIgnored>(*ignored).type, 2U);
  Bytes future;
  future.u32(0xadbccbda).u32(3).u32(99).u8(0xff);
  EXPECT_EQ(std::get<WsjtxIgnored>(*decode_wsjtx_datagram(future.data)).type, 99U);
}

TEST(WsjtxMessage, WrongMagicSchemaAndSizesAreRefused) {
  Bytes magic;
  magic.u32(0xadbccbdb).u32(3).u32(0).utf8("WSJT-X");
  EXPECT_EQ(decode_wsjtx_datagram(magic.data).error().message,
            "not a WSJT-X message: magic 0xadbccbdb");
  EXPECT_EQ(decode_wsjtx_datagram(header(0, 1).data).error().message,
            "schema 1: azeltrack reads schemas 2 and 3");
  EXPECT_FALSE(decode_wsjtx_datagram(header(0, 4).data).ok());
  EXPECT_EQ(decode_wsjtx_datagram("").error().message,
            "truncated: Magic at byte 0 needs 4 bytes, 0 left");
  std::string oversized = full_status().data;
  oversized.resize(kMaxDatagramBytes + 1, '\0');
  EXPECT_EQ(decode_wsjtx_datagram(oversized).error().message,
            "datagram of 8193 bytes, over the 8192 a WSJT-X message can be");
}

TEST(WsjtxMessage, StringLengthsPastTheEndOrTooLongOrNotUtf8AreRefused) {
  Bytes past;
  past.u32(0xadbccbda).u32(3).u32(6).u32(7).data += "WSJT";
  EXPECT_EQ(decode_wsjtx_datagram(past.data).error().message,
            "truncated: Id at byte 12 says 7 bytes, 4 left");
  Bytes huge;
  huge.u32(0xadbccbda).u32(3).u32(6).u32(0x7fffffff);
  EXPECT_EQ(decode_wsjtx_datagram(huge.data).error().message,
            "Id at byte 12: 2147483647 bytes, over the 512 allowed");
  Bytes latin1 = header(1);
  latin1.u64(144000000).utf8("FT8").utf8(std::string("DL\xe9", 3));
  EXPECT_EQ(decode_wsjtx_datagram(latin1.data).error().message, "DX call at byte 37 is not UTF-8");
  Bytes just_long = header(6, 3, std::string(kMaxStringBytes, 'a'));
  EXPECT_TRUE(decode_wsjtx_datagram(just_long.data).ok());
}

}  // namespace
}  // namespace azt::radio
