#pragma once
// What every libFuzzer target in fuzz/ shares: the invariant check that aborts (libFuzzer saves
// the input as a crash), a reader for the control bytes at the front of an input, and, with
// AZT_FUZZ_STANDALONE, a replay main() so any compiler can run a corpus as a regression test.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "azt/util/result.hpp"

namespace azt::fuzz {

[[noreturn]] inline void invariant_failed(const char* condition, const char* file, int line) {
  std::fprintf(stderr, "%s:%d: invariant failed: %s\n", file, line, condition);
  std::abort();
}

/// Control bytes first, then the payload. Reading past the end gives zeros, so every input,
/// even an empty one, picks a variant.
class FuzzInput {
 public:
  FuzzInput(const std::uint8_t* data, std::size_t size)
      : bytes_(reinterpret_cast<const char*>(data), size) {}

  std::uint8_t take() {
    if (bytes_.empty()) return 0;
    const auto byte = static_cast<std::uint8_t>(bytes_.front());
    bytes_.remove_prefix(1);
    return byte;
  }
  /// Everything not taken yet.
  [[nodiscard]] std::string_view rest() const { return bytes_; }

 private:
  std::string_view bytes_;
};

/// A position in 0..size picked by a control byte: where to cut the payload in two feeds.
inline std::size_t split_point(std::uint8_t byte, std::size_t size) {
  return static_cast<std::size_t>(byte) % (size + 1);
}

}  // namespace azt::fuzz

/// A failed invariant aborts, which libFuzzer reports as a crash with the input saved.
#define AZT_FUZZ_REQUIRE(condition)   \
  ((condition) ? static_cast<void>(0) \
               : ::azt::fuzz::invariant_failed(#condition, __FILE__, __LINE__))

namespace azt::fuzz {

/// A parser's refusal reaches logs and the console: its message is short, not empty, and holds
/// no control bytes.
inline constexpr std::size_t kMaxMessageChars = 200;

template <typename T>
void check_error_message(const Result<T>& result) {
  if (result) return;
  const std::string& message = result.error().message;
  AZT_FUZZ_REQUIRE(!message.empty() && message.size() <= kMaxMessageChars);
  AZT_FUZZ_REQUIRE(std::none_of(message.begin(), message.end(),
                                [](char c) { return static_cast<unsigned char>(c) < 0x20; }));
}

}  // namespace azt::fuzz

#ifdef AZT_FUZZ_STANDALONE
#include <fstream>
#include <iostream>
#include <iterator>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace azt::fuzz {

/// Replays the files named on the command line (a corpus), as libFuzzer would run them once.
inline int replay_files(const char* target, int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    std::ifstream in(argv[i], std::ios::binary);
    if (!in) {
      std::cerr << target << ": cannot read " << argv[i] << '\n';
      return 1;
    }
    const std::vector<char> bytes((std::istreambuf_iterator<char>(in)),
                                  std::istreambuf_iterator<char>());
    LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
  }
  std::cout << target << ": replayed " << (argc - 1) << " inputs\n";
  return 0;
}

}  // namespace azt::fuzz
#endif
