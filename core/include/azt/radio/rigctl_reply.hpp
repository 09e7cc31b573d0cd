#pragma once
// One line of a reply in Hamlib's NET rigctl protocol (rigctld), default protocol: a set answers
// `RPRT n`; a get answers its bare value, or only `RPRT n` when it failed (Hamlib/Hamlib
// doc/man1/rigctld.1:2016-2086). `n` is 0 or a negated Hamlib error code
// (include/hamlib/rig.h:205-227). Pure parsing; the conversation is rigctl_session.hpp's.

#include <optional>
#include <string>
#include <string_view>

namespace azt::radio {

/// The number of a `RPRT n` line (0 or negative on the wire); nullopt for any other line.
std::optional<int> parse_rprt(std::string_view line);

/// A get_freq / get_split_freq value (`f`, `i`): whole Hz, or decimal Hz as some backends print;
/// nullopt unless a finite number above 0 (a rig never tunes to 0 Hz; 0 means "no answer").
std::optional<double> parse_frequency_hz(std::string_view line);

/// `\chk_vfo`'s answer: whether rigctld runs in VFO mode (every VFO command then needs a VFO
/// argument). "1"/"0", or "CHKVFO 1"/"CHKVFO 0" as older rigctld versions answer (Hamlib's own
/// client reads both: rigs/dummy/netrigctl.c:254-310, netrigctl_open). nullopt for anything else.
std::optional<bool> parse_chk_vfo(std::string_view line);

/// A Hamlib error code (`RPRT -11` or 11) as words, for the log and the console:
/// "feature not available (RIG_ENAVAIL)". Unknown codes say so with the number.
std::string hamlib_error_text(int rprt_code);

}  // namespace azt::radio
