// libFuzzer target for the EncoderHub frame codec (reliability notes, R24: a fuzz target for
// every parser). Arbitrary bytes go through HubDecoder under every policy and both start-up
// modes; every outcome is checked against invariants rather than expected values:
// - an accepted frame is a valid reading (bits 9..16, raw < 2^bits, angle in [0, 360); or an
//   axis error with no angle) of a version the policy allows, and re-encoding it gives back exactly
//   the bytes of its chunk;
// - the streaming decoder agrees with decode_hub_chunk on every chunk after the first delimiter;
// - each 0x00 adds exactly one to exactly one counter.
// The input is also read as readings to round-trip through the encoder.
//
// Built with clang -fsanitize=fuzzer,address,undefined (the fuzz preset). With
// AZT_FUZZ_STANDALONE defined it gets a main() that replays the files named on the command line,
// so any compiler can run a corpus as a regression test.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "azt/proto/hub_decoder.hpp"

namespace {

namespace proto = azt::proto;

/// A failed invariant: abort, which libFuzzer reports as a crash with the input saved.
void require(bool condition) {
  if (!condition) std::abort();
}

bool policy_allows(proto::HubAccept accept, proto::HubFrameVersion version) {
  switch (accept) {
    case proto::HubAccept::Any:
      return true;
    case proto::HubAccept::SeedOnly:
      return version == proto::HubFrameVersion::Seed;
    case proto::HubAccept::Crc8Only:
      return version == proto::HubFrameVersion::Crc8;
  }
  return false;
}

void check_accepted(const proto::HubFrame& frame, const std::vector<uint8_t>& chunk,
                    proto::HubAccept accept) {
  const proto::HubReading& r = frame.reading;
  require(proto::hub_reading_valid(r));
  require(policy_allows(accept, frame.version));
  // An axis that reports an error (CRC-8 frames: nibble 1) has no angle: hub_raw_to_deg says -1.
  const auto angle_ok = [](uint16_t raw, uint8_t bits, proto::HubAxisError error) {
    const double deg = proto::hub_raw_to_deg(raw, bits);
    return error != proto::HubAxisError::None ? deg == -1.0 : deg >= 0.0 && deg < 360.0;
  };
  require(angle_ok(r.az_raw, r.az_bits, r.az_error) && angle_ok(r.el_raw, r.el_bits, r.el_error));
  uint8_t again[proto::kHubMaxFrameBytes] = {};
  const size_t n = proto::encode_hub_frame(r, frame.version, again, sizeof again);
  require(n == chunk.size() + 1 && again[n - 1] == 0);
  for (size_t i = 0; i < chunk.size(); ++i) require(again[i] == chunk[i]);
}

void check_stream(const uint8_t* data, size_t size, proto::HubAccept accept, proto::HubSync sync) {
  proto::HubDecoder decoder(accept, sync);
  std::vector<uint8_t> chunk;  // bytes since the last delimiter
  bool synced = sync == proto::HubSync::InSync;
  uint32_t delimiters = 0;
  for (size_t i = 0; i < size; ++i) {
    proto::HubFrame frame{};
    const proto::HubFrameStatus status = decoder.push(data[i], frame);
    if (data[i] != 0) {
      require(status == proto::HubFrameStatus::Pending);
      chunk.push_back(data[i]);
      continue;
    }
    ++delimiters;
    if (!synced) {
      require(status ==
              (chunk.empty() ? proto::HubFrameStatus::Empty : proto::HubFrameStatus::Unsynced));
    } else {
      proto::HubFrame alone{};
      require(proto::decode_hub_chunk(chunk.data(), chunk.size(), accept, alone) == status);
      if (status == proto::HubFrameStatus::Ok) {
        check_accepted(frame, chunk, accept);
        require(alone.reading == frame.reading && alone.version == frame.version);
      }
    }
    require(decoder.counters().chunks() == delimiters);
    synced = true;
    chunk.clear();
  }
}

/// Every 6 input bytes as a reading (bits folded into 9..16, raws masked to fit): encode, then
/// decode with a fresh decoder; the reading must come back.
void check_round_trips(const uint8_t* data, size_t size) {
  for (size_t i = 0; i + 6 <= size; i += 6) {
    const auto az_bits = static_cast<uint8_t>(proto::kHubMinBits + data[i] % 8);
    const auto el_bits = static_cast<uint8_t>(proto::kHubMinBits + data[i + 1] % 8);
    const proto::HubReading r{
        az_bits, el_bits,
        static_cast<uint16_t>(static_cast<uint32_t>(data[i + 2] << 8 | data[i + 3]) %
                              proto::hub_raw_limit(az_bits)),
        static_cast<uint16_t>(static_cast<uint32_t>(data[i + 4] << 8 | data[i + 5]) %
                              proto::hub_raw_limit(el_bits))};
    const auto version =
        (data[i] & 0x80U) != 0 ? proto::HubFrameVersion::Crc8 : proto::HubFrameVersion::Seed;
    uint8_t frame[proto::kHubMaxFrameBytes] = {};
    const size_t n = proto::encode_hub_frame(r, version, frame, sizeof frame);
    require(n == (version == proto::HubFrameVersion::Crc8 ? proto::kHubCrc8FrameBytes
                                                          : proto::kHubSeedFrameBytes));
    proto::HubDecoder decoder(proto::HubAccept::Any, proto::HubSync::InSync);
    proto::HubFrame out{};
    for (size_t k = 0; k + 1 < n; ++k) {
      require(frame[k] != 0 && decoder.push(frame[k], out) == proto::HubFrameStatus::Pending);
    }
    require(decoder.push(frame[n - 1], out) == proto::HubFrameStatus::Ok);
    require(out.reading == r && out.version == version);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  for (const auto accept :
       {proto::HubAccept::Any, proto::HubAccept::SeedOnly, proto::HubAccept::Crc8Only}) {
    check_stream(data, size, accept, proto::HubSync::InSync);
    check_stream(data, size, accept, proto::HubSync::AwaitDelimiter);
  }
  check_round_trips(data, size);
  return 0;
}

#ifdef AZT_FUZZ_STANDALONE
#include <fstream>
#include <iostream>
#include <iterator>

/// Replays the files named on the command line (a corpus), as libFuzzer would run them once.
int main(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    std::ifstream in(argv[i], std::ios::binary);
    if (!in) {
      std::cerr << "hub_decoder_fuzz: cannot read " << argv[i] << '\n';
      return 1;
    }
    const std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)),
                                     std::istreambuf_iterator<char>());
    LLVMFuzzerTestOneInput(bytes.data(), bytes.size());
  }
  std::cout << "hub_decoder_fuzz: replayed " << (argc - 1) << " inputs\n";
  return 0;
}
#endif
