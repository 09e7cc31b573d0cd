#pragma once
// The T/R period WSJT-X runs in, from its Status message (azt/radio/wsjtx_message.hpp).
//
// WSJT-X sends the period only where the operator chooses it: its Status carries the "T/R period"
// spin box's value when that box is shown and enabled, and "not applicable" (0xffffffff)
// otherwise (WSJTX/wsjtx widgets/mainwindow.cpp, MainWindow::statusUpdate, lines 13935-13944 at
// commit c04dd8d; FST4W's period has a box of its own and is always sent). WSJT-X before 2.2 sends
// no period at all (the field was appended in 183bf4a, 2019). So in FT8 and FT4, the modes most
// used, the Status never says the period: it is the mode's own, fixed when the mode is chosen
// (the same file, each mode's on_action…_triggered):
//   FT8 15 s (line 10984), FT4 7.5 s (10891), JT4 60 s (11133), JT65 60 s (11278),
//   JT9 60 s unless in fast mode (11236; fast JT9 shows the box), WSPR 120 s (11518).
// Q65, FST4, FST4W, MSK144, fast JT9 and FreqCal take the period from the box (Q65 15 to 300 s,
// FST4 15 to 1800 s, MSK144 5 to 30 s): without the Status's value it is not known. Echo mode's
// 3 s cycle (11562) is not a T/R period of alternating stations and is left out too.

#include <optional>
#include <string_view>

#include "azt/radio/wsjtx_message.hpp"

namespace azt::radio {

/// The period WSJT-X fixes for `mode` (the Status's Mode, "FT8"), or none when the operator
/// chooses it. `fast_mode`: the Status's Fast mode flag (JT9's fast sub-modes choose theirs).
std::optional<double> mode_tr_period_s(std::string_view mode, bool fast_mode);

/// The T/R period that applies to a Status: its own T/R period when it gives one, else its mode's
/// fixed period; none when neither is known.
std::optional<double> tr_period_s(const WsjtxStatus& status);

}  // namespace azt::radio
