// The EncoderHub frames' CRC-8/AUTOSAR: the catalogue's check value and residue (Greg Cook,
// "Catalogue of parametrised CRC algorithms"), and the errors it must catch in a CRC frame, every
// one of them checked: up to three flipped bits, any one corrupted byte, data or COBS code byte.
#include "azt/proto/hub_crc8.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <random>
#include <string>

#include "azt/proto/hub_cobs.hpp"
#include "azt/proto/hub_frame.hpp"
#include "proto/hub_bytes.hpp"

namespace azt::proto {
namespace {

using hub_test::Bytes;

TEST(HubCrc8, CatalogueCheckValue) {
  // Greg Cook's catalogue, CRC-8/AUTOSAR: check=0xdf for "123456789".
  const std::string check = "123456789";
  Bytes data(check.begin(), check.end());
  EXPECT_EQ(hub_crc8(data.data(), data.size()), 0xDF);
  // By hand, the byte 0x01: register 0xFF ^ 0x01 = FE, then eight shifts, XOR 0x2F when the top
  // bit falls out: FE -> D3 -> 89 -> 3D -> 7A -> F4 -> C7 -> A1 -> 6D; final XOR 0xFF: 0x92.
  const uint8_t one = 0x01;
  EXPECT_EQ(hub_crc8(&one, 1), 0x92);
  EXPECT_EQ(hub_crc8(nullptr, 0), 0x00);  // initial value, then the final XOR undoes it
  const uint8_t zeros[5] = {};
  EXPECT_NE(hub_crc8(zeros, 5), 0x00);  // one reason for this CRC: a zeroed payload fails
}

TEST(HubCrc8, AppendingTheCrcGivesTheCatalogueResidue) {
  // Catalogue: residue=0x42, the register before the final XOR after a whole codeword; the
  // function applies the XOR, so it returns 0x42 ^ 0xFF for every correct codeword.
  std::mt19937_64 rng(20240901);
  for (int n = 0; n < 200; ++n) {
    Bytes data(static_cast<size_t>(n % 9));
    for (auto& b : data) b = static_cast<uint8_t>(rng());
    data.push_back(hub_crc8(data.data(), data.size()));
    EXPECT_EQ(hub_crc8(data.data(), data.size()), 0x42 ^ 0xFF);
  }
}

/// Whether a CRC frame whose decoded payload is off by `e` (XOR) still passes the check.
/// hub_crc8 is affine (crc(a ^ b) = crc(a) ^ crc(b) ^ crc(0), tested below), so a codeword P
/// corrupted to P ^ e passes exactly when crc(e[0..4]) ^ crc(0) == e[5], whatever P was.
bool error_passes_crc(const uint8_t (&e)[6]) {
  const uint8_t zeros[5] = {};
  return (hub_crc8(e, 5) ^ hub_crc8(zeros, 5)) == e[5];
}

TEST(HubCrc8, IsAffine) {
  std::mt19937_64 rng(0xAFF);
  const uint8_t zeros[5] = {};
  for (int i = 0; i < 1000; ++i) {
    uint8_t a[5], b[5], x[5];
    for (int k = 0; k < 5; ++k) {
      a[k] = static_cast<uint8_t>(rng());
      b[k] = static_cast<uint8_t>(rng());
      x[k] = static_cast<uint8_t>(a[k] ^ b[k]);
    }
    ASSERT_EQ(hub_crc8(x, 5), hub_crc8(a, 5) ^ hub_crc8(b, 5) ^ hub_crc8(zeros, 5));
  }
}

/// True if flipping `bits` (0..47) of a CRC codeword goes unnoticed.
bool bit_error_passes_crc(std::initializer_list<unsigned> bits) {
  uint8_t e[6] = {};
  for (const unsigned bit : bits) e[bit / 8] = static_cast<uint8_t>(e[bit / 8] ^ 1U << (bit % 8));
  return error_passes_crc(e);
}

TEST(HubCorruption, EveryErrorOfUpToThreeBitsIsCaught) {
  // Hamming distance 4 over the 48-bit codeword: all 48 + 1128 + 17296 patterns of 1 to 3 bits.
  int patterns = 0;
  for (unsigned a = 0; a < 48; ++a) {
    ASSERT_FALSE(bit_error_passes_crc({a}));
    ++patterns;
    for (unsigned b = a + 1; b < 48; ++b) {
      ASSERT_FALSE(bit_error_passes_crc({a, b}));
      ++patterns;
      for (unsigned c = b + 1; c < 48; ++c) {
        ASSERT_FALSE(bit_error_passes_crc({a, b, c})) << a << " " << b << " " << c;
        ++patterns;
      }
    }
  }
  EXPECT_EQ(patterns, 48 + 1128 + 17296);
}

TEST(HubCorruption, NoSingleByteErrorInACrcFrameSlipsThrough) {
  // One byte of a CRC frame's 7-byte COBS chunk replaced by another non-zero value (a zero would
  // split the chunk and fail on length).
  // A data byte: the payload is off in that one byte, an error burst of at most 8 bits. Every
  // such error, checked exhaustively:
  for (size_t pos = 0; pos < 6; ++pos) {
    for (unsigned v = 1; v < 256; ++v) {
      uint8_t e[6] = {};
      e[pos] = static_cast<uint8_t>(v);
      ASSERT_FALSE(error_passes_crc(e)) << pos << " " << v;
    }
  }
  // A code byte: the chunk parses differently. Only values 1..7 can still fit in 7 bytes, and
  // only data bytes of 1..6 can act as codes in the new parse; every other data value behaves
  // the same. So payloads over {0, 1..6, 0x80} give every possible new parse, and through the
  // affine property every error a code byte can cause, whatever the real payload.
  const uint8_t alphabet[8] = {0, 1, 2, 3, 4, 5, 6, 0x80};
  long reparsed = 0;
  for (unsigned index = 0; index < 8 * 8 * 8 * 8 * 8 * 8; ++index) {
    uint8_t payload[6];
    for (unsigned k = 0, rest = index; k < 6; ++k, rest /= 8) payload[k] = alphabet[rest % 8];
    uint8_t chunk[kHubCrc8EncodedBytes];
    ASSERT_EQ(hub_cobs_encode(payload, 6, chunk, sizeof chunk), sizeof chunk);
    for (size_t m = 0; m < sizeof chunk; m += chunk[m]) {  // the code bytes: each one says where
      for (unsigned v = 1; v <= 7; ++v) {                  // the next one is
        if (v == chunk[m]) continue;
        uint8_t hit[kHubCrc8EncodedBytes];
        std::copy(chunk, chunk + sizeof chunk, hit);
        hit[m] = static_cast<uint8_t>(v);
        uint8_t decoded[8];
        size_t n = 0;
        if (!hub_cobs_decode(hit, sizeof hit, decoded, sizeof decoded, n) || n != 6) continue;
        uint8_t e[6];
        for (size_t k = 0; k < 6; ++k) e[k] = static_cast<uint8_t>(payload[k] ^ decoded[k]);
        ASSERT_FALSE(error_passes_crc(e)) << "payload index " << index << " code " << m;
        ++reparsed;
      }
    }
  }
  EXPECT_GT(reparsed, 0);
  RecordProperty("code_byte_errors_that_parse", std::to_string(reparsed));
}

}  // namespace
}  // namespace azt::proto
