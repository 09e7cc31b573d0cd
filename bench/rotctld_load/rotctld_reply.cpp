#include "rotctld_reply.hpp"

#include <charconv>
#include <cmath>
#include <cstddef>

namespace rotctld_load {
namespace {

bool is_number(std::string_view line) {
  double value = 0.0;
  const auto [end, ec] = std::from_chars(line.data(), line.data() + line.size(), value);
  return ec == std::errc{} && end == line.data() + line.size() && std::isfinite(value);
}

}  // namespace

ReplyState judge_reply(Request request, std::string_view in) {
  const std::size_t first_end = in.find('\n');
  if (first_end == std::string_view::npos) return ReplyState::kIncomplete;
  const std::string_view first = in.substr(0, first_end);
  if (first.starts_with("RPRT")) {
    const bool ok = request == Request::kSetPos && first == "RPRT 0";
    return ok && in.size() == first_end + 1 ? ReplyState::kOk : ReplyState::kError;
  }
  if (request == Request::kSetPos) return ReplyState::kError;
  const std::size_t second_end = in.find('\n', first_end + 1);
  if (second_end == std::string_view::npos) return ReplyState::kIncomplete;
  const std::string_view second = in.substr(first_end + 1, second_end - first_end - 1);
  const bool ok = is_number(first) && is_number(second) && in.size() == second_end + 1;
  return ok ? ReplyState::kOk : ReplyState::kError;
}

}  // namespace rotctld_load
