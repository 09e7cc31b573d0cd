#pragma once
// The rotctld exchange rotctld_load's clients make: `p` (get position, reply "az\nel\n") and
// `P az el` (set position, reply "RPRT 0\n"), and whether the bytes received so far are a whole,
// right reply.

#include <string_view>

namespace rotctld_load {

enum class Request { kGetPos, kSetPos };

enum class ReplyState { kIncomplete, kOk, kError };

// Judges the reply bytes so far: `p` wants two numeric lines unless the first is an RPRT line;
// `P` wants one "RPRT 0" line. Extra bytes after a complete reply are a protocol error.
ReplyState judge_reply(Request request, std::string_view in);

}  // namespace rotctld_load
