#pragma once
// A bounded line assembler for the serial text protocols (GS-232, EasyComm).
//
// Bytes go in one at a time; a complete line (without its terminator) comes out when a terminator
// byte arrives. A line longer than the bound is garbage: it is discarded up to and including the
// next terminator and counted, so a flood of junk can never grow memory.
// Ignored bytes (GS-232 ignores LF) are dropped silently; they neither end nor extend a line.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace azt::proto {

class BoundedLineAssembler {
 public:
  /// `terminators`: bytes that end a line. `ignored`: bytes dropped wherever they appear.
  BoundedLineAssembler(std::size_t max_line_chars, std::string_view terminators,
                       std::string_view ignored = {})
      : max_line_chars_(max_line_chars), terminators_(terminators), ignored_(ignored) {
    line_.reserve(max_line_chars_);
  }

  /// Feeds one byte; returns the finished line when `byte` is a terminator. An overlong line is
  /// dropped (returns nothing) and counted in overlong_lines().
  std::optional<std::string> push(char byte) {
    if (ignored_.find(byte) != std::string::npos) return std::nullopt;
    if (terminators_.find(byte) != std::string::npos) {
      if (discarding_) {
        discarding_ = false;
        return std::nullopt;
      }
      std::string out = line_;
      line_.clear();
      return out;
    }
    if (discarding_) return std::nullopt;
    if (line_.size() >= max_line_chars_) {
      line_.clear();
      discarding_ = true;
      ++overlong_lines_;
      return std::nullopt;
    }
    line_.push_back(byte);
    return std::nullopt;
  }

  /// Lines dropped because they exceeded the bound.
  [[nodiscard]] std::uint64_t overlong_lines() const { return overlong_lines_; }
  /// Characters of the unfinished line held now (never more than the bound).
  [[nodiscard]] std::size_t pending_chars() const { return line_.size(); }
  void reset() {
    line_.clear();
    discarding_ = false;
  }

 private:
  std::size_t max_line_chars_;
  std::string terminators_;
  std::string ignored_;
  std::string line_;
  bool discarding_ = false;
  std::uint64_t overlong_lines_ = 0;
};

}  // namespace azt::proto
