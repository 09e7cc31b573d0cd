#pragma once
// The EncoderHub's streaming decoder: bytes in as the serial port delivers them, frames out
// (azt/proto/hub_frame.hpp), and a counter for every outcome, as a link's error budget needs.
//
// Written as hub_frame.hpp is (C++14, <stdint.h>/<stddef.h> only, no heap, no exceptions, no STL),
// so that it builds wherever that header does, the AVR firmware's compiler included.

#include <stddef.h>
#include <stdint.h>

#include "azt/proto/hub_frame.hpp"

namespace azt {
namespace proto {

/// One counter per outcome. Every 0x00 pushed into a HubDecoder adds exactly one to exactly one
/// counter, so their sum (chunks()) equals the delimiters seen since construction or reset().
/// Counters wrap modulo 2^32: take rates from differences in unsigned arithmetic.
struct HubCounters {
  uint32_t frames_seed;
  uint32_t frames_crc8;
  uint32_t empty;
  uint32_t unsynced;
  uint32_t overlong;
  uint32_t wrong_length;
  uint32_t bad_cobs;
  uint32_t wrong_version;
  uint32_t bad_crc;
  uint32_t bad_nibble;
  uint32_t out_of_range;

  uint32_t frames_ok() const { return frames_seed + frames_crc8; }
  /// Frames lost to the link or the sender: what an error budget ("> 20 bad frames a minute is
  /// a fault", OnStepX) should count. Empty chunks and the one unsynced start-up chunk are not
  /// link errors.
  uint32_t rejected() const {
    return overlong + wrong_length + bad_cobs + wrong_version + bad_crc + bad_nibble + out_of_range;
  }
  uint32_t chunks() const { return frames_ok() + rejected() + empty + unsynced; }
};

/// Where a new or reset decoder starts.
/// AwaitDelimiter: discard everything up to the first 0x00, as the seed's controller does
/// ("searches for the frame_end delimiter character"): on a live serial port the first bytes are
/// usually the tail of a frame. InSync: the input starts at a frame boundary (a capture file, a
/// test, a pipe).
enum class HubSync : uint8_t { AwaitDelimiter, InSync };

/// Streaming decoder: push bytes as they arrive; a fixed 7-byte buffer, no heap.
/// After a chunk overflows the buffer, bytes are discarded up to the next 0x00, which ends the
/// chunk as Overlong; every delimiter resets the framing, so one stray byte costs at most the frame
/// it lands in (electricui-embedded #180).
class HubDecoder {
 public:
  explicit HubDecoder(HubAccept accept, HubSync sync = HubSync::AwaitDelimiter)
      : accept_(accept), sync_(sync) {
    reset();
  }

  /// Feeds one byte. Returns Pending unless `byte` is a delimiter; then returns what the chunk it
  /// ends was, and on Ok writes the frame to `out` (untouched otherwise).
  HubFrameStatus push(uint8_t byte, HubFrame& out) {
    if (byte != 0) {
      if (state_ == State::AwaitingDelimiter) {
        had_bytes_ = true;
      } else if (state_ == State::Collecting) {
        if (length_ < kHubCrc8EncodedBytes) {
          buffer_[length_++] = byte;
        } else {
          state_ = State::Discarding;
        }
      }
      return HubFrameStatus::Pending;
    }
    const HubFrameStatus status = finish_chunk(out);
    uint32_t* counter = counter_for(counters_, status, out);
    if (counter != nullptr) ++*counter;
    state_ = State::Collecting;
    length_ = 0;
    had_bytes_ = false;
    return status;
  }

  const HubCounters& counters() const { return counters_; }

  /// Drops any partial frame and waits for the next delimiter, keeping the counters (a link that
  /// was lost and is back: what came before the break must not be glued to what comes after).
  void resync() {
    state_ = State::AwaitingDelimiter;
    length_ = 0;
    had_bytes_ = false;
  }

  /// Back to the freshly constructed state: framing as chosen by HubSync, counters zero.
  void reset() {
    counters_ = HubCounters{};
    state_ = sync_ == HubSync::InSync ? State::Collecting : State::AwaitingDelimiter;
    length_ = 0;
    had_bytes_ = false;
  }

 private:
  enum class State : uint8_t { AwaitingDelimiter, Collecting, Discarding };

  HubFrameStatus finish_chunk(HubFrame& out) const {
    switch (state_) {
      case State::AwaitingDelimiter:
        return had_bytes_ ? HubFrameStatus::Unsynced : HubFrameStatus::Empty;
      case State::Discarding:
        return HubFrameStatus::Overlong;
      case State::Collecting:
        break;
    }
    return decode_hub_chunk(buffer_, length_, accept_, out);
  }

  /// The counter an outcome adds one to; none for Pending. `frame` is read only on Ok.
  static uint32_t* counter_for(HubCounters& c, HubFrameStatus status, const HubFrame& frame) {
    switch (status) {
      case HubFrameStatus::Pending:
        return nullptr;
      case HubFrameStatus::Ok:
        return frame.version == HubFrameVersion::Crc8 ? &c.frames_crc8 : &c.frames_seed;
      case HubFrameStatus::Empty:
        return &c.empty;
      case HubFrameStatus::Unsynced:
        return &c.unsynced;
      case HubFrameStatus::Overlong:
        return &c.overlong;
      case HubFrameStatus::WrongLength:
        return &c.wrong_length;
      case HubFrameStatus::BadCobs:
        return &c.bad_cobs;
      case HubFrameStatus::WrongVersion:
        return &c.wrong_version;
      case HubFrameStatus::BadCrc:
        return &c.bad_crc;
      case HubFrameStatus::BadNibble:
        return &c.bad_nibble;
      case HubFrameStatus::OutOfRange:
        return &c.out_of_range;
    }
    return nullptr;
  }

  HubAccept accept_;
  HubSync sync_;
  State state_ = State::AwaitingDelimiter;
  uint8_t buffer_[kHubCrc8EncodedBytes] = {};
  size_t length_ = 0;
  bool had_bytes_ = false;  // any byte since the last delimiter while awaiting the first one
  HubCounters counters_ = {};
};

}  // namespace proto
}  // namespace azt
