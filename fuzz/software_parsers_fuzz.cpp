// libFuzzer target for what the daemon reads about software updates (docs/packaging.md): an
// uploaded file's ar members (check_deb_archive, on every byte a logged-in browser may send) and
// the root update helper's status file (parse_update_status). The whole input goes to both.
// Invariants:
// - an accepted archive starts with ar's magic, has a 2.x format, control.tar and data.tar
//   members, and a data member no larger than the input;
// - an accepted status has a percent of 0..100, a time >= 0, and a SHA-256 that is empty or 64
//   lower-case hex digits; parsing it twice gives the same phase;
// - error messages are short and hold no control bytes (they reach the console).
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "azt/software/deb_archive.hpp"
#include "azt/software/update_status.hpp"
#include "azt/util/result.hpp"
#include "fuzz_support.hpp"

namespace {

namespace software = azt::software;

void check_archive(std::string_view bytes) {
  const auto archive = software::check_deb_archive(bytes);
  azt::fuzz::check_error_message(archive);
  if (!archive) return;
  AZT_FUZZ_REQUIRE(bytes.substr(0, 8) == "!<arch>\n");
  AZT_FUZZ_REQUIRE(archive->format_version.substr(0, 2) == "2.");
  AZT_FUZZ_REQUIRE(archive->control_member.rfind("control.tar", 0) == 0);
  AZT_FUZZ_REQUIRE(archive->data_member.rfind("data.tar", 0) == 0);
  AZT_FUZZ_REQUIRE(archive->data_bytes <= bytes.size());
}

void check_status(std::string_view text) {
  const auto status = software::parse_update_status(text);
  azt::fuzz::check_error_message(status);
  if (!status) return;
  AZT_FUZZ_REQUIRE(status->percent >= 0 && status->percent <= 100);
  AZT_FUZZ_REQUIRE(status->at_unix_s >= 0);
  const std::string& sha = status->sha256_hex;
  AZT_FUZZ_REQUIRE(sha.empty() ||
                   (sha.size() == 64 && std::all_of(sha.begin(), sha.end(), [](char c) {
                      return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f');
                    })));
  const auto again = software::parse_update_status(text);
  AZT_FUZZ_REQUIRE(again && again->phase == status->phase);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  check_archive(input);
  check_status(input);
  return 0;
}
