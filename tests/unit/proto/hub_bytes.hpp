#pragma once
// Bytes on an EncoderHub link for the hub frame tests (tests/unit/proto/hub_*_test.cpp): frames
// made by the encoder or from any payload, and what a decoder makes of a stream of them.

#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <vector>

#include "azt/proto/hub_decoder.hpp"

namespace azt::proto::hub_test {

using Bytes = std::vector<uint8_t>;

inline Bytes encode(const HubReading& r, HubFrameVersion version) {
  uint8_t buf[kHubMaxFrameBytes] = {};
  const size_t n = encode_hub_frame(r, version, buf, sizeof buf);
  return Bytes(buf, buf + n);
}

/// COBS bytes of an arbitrary payload, delimiter included: frames the encoder refuses to make.
inline Bytes frame_of(const Bytes& payload) {
  Bytes out(payload.size() + 2, 0xEE);
  const size_t n = hub_cobs_encode(payload.data(), payload.size(), out.data(), out.size());
  EXPECT_EQ(n, payload.size() + 1);
  out[n] = 0;
  out.resize(n + 1);
  return out;
}

/// Every outcome (non-Pending status) of pushing `bytes`, and the frames accepted.
struct Fed {
  std::vector<HubFrameStatus> outcomes;
  std::vector<HubFrame> frames;
};

inline Fed feed(HubDecoder& decoder, const Bytes& bytes) {
  Fed fed;
  for (uint8_t b : bytes) {
    HubFrame frame{};
    const HubFrameStatus s = decoder.push(b, frame);
    if (s == HubFrameStatus::Pending) continue;
    fed.outcomes.push_back(s);
    if (s == HubFrameStatus::Ok) fed.frames.push_back(frame);
  }
  return fed;
}

/// The single outcome of one chunk fed to a fresh in-sync decoder.
inline HubFrameStatus status_of(const Bytes& frame, HubAccept accept = HubAccept::Any) {
  HubDecoder d(accept, HubSync::InSync);
  const Fed fed = feed(d, frame);
  EXPECT_EQ(fed.outcomes.size(), 1U);
  return fed.outcomes.empty() ? HubFrameStatus::Pending : fed.outcomes.front();
}

inline Bytes concat(Bytes a, const Bytes& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

}  // namespace azt::proto::hub_test
