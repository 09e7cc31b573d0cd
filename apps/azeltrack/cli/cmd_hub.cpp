// `azeltrack hub`: EncoderHub frames by hand, for bench work, captures and scripts.
//   hub encode --az-bits N --el-bits M --az-raw A --el-raw E [--crc]
//     prints the whole frame (COBS bytes and the 0x00 delimiter) as lower-case two-digit hex
//     bytes separated by single spaces, e.g. "03 cc 04 02 08 01 00".
//   hub decode [--hex] [--accept any|seed|crc8] [--await-delimiter]
//     reads a byte stream on stdin and prints one JSON line per accepted frame, then one line
//     {"counters":{...},"bytes_read":N,"trailing_bytes":M}.
// The codec is core/include/azt/proto/hub_frame.hpp and hub_decoder.hpp; this file only parses
// options and prints.
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cstring>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <string_view>

#include "azt/proto/hub_decoder.hpp"
#include "cli/commands.hpp"
#include "common/usage_error.hpp"

namespace azt::app {
namespace {

struct HubEncodeOptions {
  std::string az_bits, el_bits, az_raw, el_raw;
  bool crc = false;
};

struct HubDecodeOptions {
  bool hex = false;
  std::string accept = "any";
  bool await_delimiter = false;
};

/// A whole string as an unsigned integer <= `max`: decimal, or hex with a 0x prefix. No sign,
/// spaces or trailing junk (from_chars is locale-free).
unsigned parse_unsigned_option(const std::string& option, const std::string& text, unsigned max) {
  std::string_view digits = text;
  int base = 10;
  if (digits.size() > 2 && digits[0] == '0' && (digits[1] == 'x' || digits[1] == 'X')) {
    digits.remove_prefix(2);
    base = 16;
  }
  unsigned value = 0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value, base);
  if (digits.empty() || ec != std::errc{} || end != digits.data() + digits.size() || value > max) {
    throw UsageError(option + ": '" + text + "' is not an integer from 0 to " +
                     std::to_string(max));
  }
  return value;
}

uint8_t bits_option(const std::string& option, const std::string& text) {
  const unsigned bits = parse_unsigned_option(option, text, 255);
  if (!proto::hub_bits_valid(static_cast<uint8_t>(bits))) {
    throw UsageError(option + ": " + text + " bits; the hub handles 9- to 16-bit encoders");
  }
  return static_cast<uint8_t>(bits);
}

uint16_t raw_option(const std::string& option, const std::string& text, uint8_t bits) {
  const unsigned max = static_cast<unsigned>(proto::hub_raw_limit(bits) - 1);
  const unsigned raw = parse_unsigned_option(option, text, 65535);
  if (raw > max) {
    throw UsageError(option + ": " + text + " does not fit in " + std::to_string(bits) +
                     " bits (largest " + std::to_string(max) + ")");
  }
  return static_cast<uint16_t>(raw);
}

int run_encode(const HubEncodeOptions& o) {
  proto::HubReading r{};
  r.az_bits = bits_option("--az-bits", o.az_bits);
  r.el_bits = bits_option("--el-bits", o.el_bits);
  r.az_raw = raw_option("--az-raw", o.az_raw, r.az_bits);
  r.el_raw = raw_option("--el-raw", o.el_raw, r.el_bits);
  uint8_t frame[proto::kHubMaxFrameBytes] = {};
  const auto version = o.crc ? proto::HubFrameVersion::Crc8 : proto::HubFrameVersion::Seed;
  const size_t n = proto::encode_hub_frame(r, version, frame, sizeof frame);
  if (n == 0) throw std::logic_error("hub encode: a checked reading was refused");
  static constexpr char kHex[] = "0123456789abcdef";
  std::string line;
  for (size_t i = 0; i < n; ++i) {
    if (i > 0) line += ' ';
    line += kHex[frame[i] >> 4U];
    line += kHex[frame[i] & 0x0FU];
  }
  std::cout << line << '\n';
  return 0;
}

nlohmann::ordered_json frame_json(const proto::HubFrame& f) {
  const proto::HubReading& r = f.reading;
  // An axis a CRC-8 frame has no position for (docs/encoder-hub.md) has no angle and says why.
  const auto angle = [](uint16_t raw, uint8_t bits, proto::HubAxisError error) {
    return error == proto::HubAxisError::None
               ? nlohmann::ordered_json(proto::hub_raw_to_deg(raw, bits))
               : nlohmann::ordered_json(nullptr);
  };
  nlohmann::ordered_json j{
      {"az_deg", angle(r.az_raw, r.az_bits, r.az_error)},
      {"el_deg", angle(r.el_raw, r.el_bits, r.el_error)},
      {"az_bits", r.az_bits},
      {"el_bits", r.el_bits},
      {"az_raw", r.az_raw},
      {"el_raw", r.el_raw},
      {"version", f.version == proto::HubFrameVersion::Crc8 ? "crc8" : "seed"}};
  if (r.az_error != proto::HubAxisError::None)
    j["az_error"] = proto::hub_axis_error_name(r.az_error);
  if (r.el_error != proto::HubAxisError::None)
    j["el_error"] = proto::hub_axis_error_name(r.el_error);
  return j;
}

nlohmann::ordered_json counters_json(const proto::HubCounters& c) {
  return {{"frames_seed", c.frames_seed},
          {"frames_crc8", c.frames_crc8},
          {"empty", c.empty},
          {"unsynced", c.unsynced},
          {"overlong", c.overlong},
          {"wrong_length", c.wrong_length},
          {"bad_cobs", c.bad_cobs},
          {"wrong_version", c.wrong_version},
          {"bad_crc", c.bad_crc},
          {"bad_nibble", c.bad_nibble},
          {"out_of_range", c.out_of_range},
          {"rejected", c.rejected()}};
}

/// Feeds bytes to the decoder and prints accepted frames; remembers what the summary needs.
class DecodeSink {
 public:
  DecodeSink(proto::HubAccept accept, proto::HubSync sync) : decoder_(accept, sync) {}

  void push(uint8_t byte) {
    ++bytes_read_;
    since_delimiter_ = byte == 0 ? 0 : since_delimiter_ + 1;
    proto::HubFrame frame{};
    if (decoder_.push(byte, frame) == proto::HubFrameStatus::Ok) {
      std::cout << frame_json(frame).dump() << '\n';
    }
  }

  void finish() const {
    std::cout << nlohmann::ordered_json{{"counters", counters_json(decoder_.counters())},
                                        {"bytes_read", bytes_read_},
                                        {"trailing_bytes", since_delimiter_}}
                     .dump()
              << '\n';
  }

 private:
  proto::HubDecoder decoder_;
  unsigned long long bytes_read_ = 0;
  unsigned long long since_delimiter_ = 0;  // bytes after the last 0x00: an unfinished frame
};

/// Raw bytes from stdin. read(2) rather than std::cin so that frames from a live port or a pipe
/// are printed as they arrive instead of when a stream buffer fills.
void decode_binary(DecodeSink& sink) {
  uint8_t buf[4096];
  for (;;) {
    const ssize_t n = ::read(STDIN_FILENO, buf, sizeof buf);
    if (n == 0) return;
    if (n < 0) {
      if (errno == EINTR) continue;
      throw std::runtime_error(std::string("hub decode: reading stdin: ") + std::strerror(errno));
    }
    for (ssize_t i = 0; i < n; ++i) sink.push(buf[i]);
    std::cout.flush();
  }
}

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

/// Hex text from stdin: whitespace-separated tokens of whole bytes, so both "03 cc 04" and the
/// "03cc04" lines of `xxd -p` work.
void decode_hex(DecodeSink& sink) {
  std::string line;
  for (unsigned long line_no = 1; std::getline(std::cin, line); ++line_no) {
    int high = -1;
    for (const char c : line) {
      if (c == ' ' || c == '\t' || c == '\r') {
        if (high >= 0) break;  // odd digit count in a token: reported below
        continue;
      }
      const int d = hex_digit(c);
      if (d < 0) {
        throw std::runtime_error("hub decode --hex: line " + std::to_string(line_no) + ": '" +
                                 std::string(1, c) + "' is not a hex digit");
      }
      if (high < 0) {
        high = d;
      } else {
        sink.push(static_cast<uint8_t>(high << 4 | d));
        high = -1;
      }
    }
    if (high >= 0) {
      throw std::runtime_error("hub decode --hex: line " + std::to_string(line_no) +
                               ": a token has an odd number of hex digits");
    }
    std::cout.flush();
  }
}

int run_decode(const HubDecodeOptions& o) {
  proto::HubAccept accept = proto::HubAccept::Any;
  if (o.accept == "seed") accept = proto::HubAccept::SeedOnly;
  if (o.accept == "crc8") accept = proto::HubAccept::Crc8Only;
  // A capture or a pipe normally starts at a frame boundary; a live port usually does not.
  DecodeSink sink(accept,
                  o.await_delimiter ? proto::HubSync::AwaitDelimiter : proto::HubSync::InSync);
  if (o.hex) {
    decode_hex(sink);
  } else {
    decode_binary(sink);
  }
  sink.finish();
  return 0;
}

}  // namespace

Runner add_hub_command(CLI::App& app) {
  CLI::App* hub = app.add_subcommand("hub", "EncoderHub frames: encode one, decode a stream");
  hub->require_subcommand(1);

  auto enc = std::make_shared<HubEncodeOptions>();
  CLI::App* encode = hub->add_subcommand(
      "encode", "Print the frame for one reading as hex bytes, delimiter included");
  encode->add_option("--az-bits", enc->az_bits, "Azimuth encoder resolution, 9-16 bits")
      ->required();
  encode->add_option("--el-bits", enc->el_bits, "Elevation encoder resolution, 9-16 bits")
      ->required();
  encode->add_option("--az-raw", enc->az_raw, "Azimuth count, 0 to 2^bits - 1 (decimal or 0x..)")
      ->required();
  encode->add_option("--el-raw", enc->el_raw, "Elevation count, 0 to 2^bits - 1 (decimal or 0x..)")
      ->required();
  encode->add_flag("--crc", enc->crc, "Append the CRC-8 byte (our hub firmware's version)");

  auto dec = std::make_shared<HubDecodeOptions>();
  CLI::App* decode = hub->add_subcommand(
      "decode", "Read frames on stdin; one JSON line per accepted frame, then the counters");
  decode->add_flag("--hex", dec->hex, "Stdin is hex text (\"03 cc 04\" or xxd -p), not bytes");
  decode->add_option("--accept", dec->accept, "Frame versions to take: any (default), seed, crc8")
      ->check(CLI::IsMember({"any", "seed", "crc8"}));
  decode->add_flag("--await-delimiter", dec->await_delimiter,
                   "Discard bytes up to the first 0x00 (joining a live stream mid-frame)");

  return [encode, decode, enc, dec] {
    if (encode->parsed()) return run_encode(*enc);
    if (decode->parsed()) return run_decode(*dec);
    throw UsageError("hub: give encode or decode");
  };
}

}  // namespace azt::app
