// rigctld client session (the rules are in rigctl_session.hpp).
#include "azt/radio/rigctl_session.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "azt/radio/rigctl_reply.hpp"

namespace azt::radio {
namespace {

constexpr std::size_t kMaxQuotedChars = 40;

/// What rigctld sent, for a log line: printable ASCII only, cut short.
std::string quoted(std::string_view line) {
  std::string out = "\"";
  for (const char c : line.substr(0, kMaxQuotedChars)) {
    const bool printable = c >= ' ' && c <= '~';
    out += printable ? c : '?';
  }
  if (line.size() > kMaxQuotedChars) out += "...";
  return out + "\"";
}

std::string_view vfo_token(SplitTxVfo vfo) {
  switch (vfo) {
    case SplitTxVfo::VfoB:
      return "VFOB";
    case SplitTxVfo::Sub:
      return "Sub";
  }
  return "VFOB";
}

bool is_get(RigCommand command) {
  return command == RigCommand::GetFreq || command == RigCommand::GetSplitFreq;
}

RigEvent make_event(RigEventKind kind, RigCommand command) {
  RigEvent event;
  event.kind = kind;
  event.command = command;
  return event;
}

std::string whole_hz(double hz) { return std::to_string(std::llround(hz)); }

}  // namespace

std::string_view rigctl_command_name(RigCommand command) {
  switch (command) {
    case RigCommand::ChkVfo:
      return "chk_vfo";
    case RigCommand::GetFreq:
      return "get_freq";
    case RigCommand::SetFreq:
      return "set_freq";
    case RigCommand::SetSplit:
      return "set_split_vfo";
    case RigCommand::GetSplitFreq:
      return "get_split_freq";
    case RigCommand::SetSplitFreq:
      return "set_split_freq";
  }
  return "unknown";
}

std::string rigctl_command_line(RigCommand command, double hz, bool vfo_mode, SplitTxVfo tx_vfo) {
  const std::string vfo = vfo_mode ? " currVFO" : "";
  switch (command) {
    case RigCommand::ChkVfo:
      return "\\chk_vfo\n";
    case RigCommand::GetFreq:
      return "f" + vfo + "\n";
    case RigCommand::SetFreq:
      return "F" + vfo + " " + whole_hz(hz) + "\n";
    case RigCommand::SetSplit:
      return "S" + vfo + " 1 " + std::string(vfo_token(tx_vfo)) + "\n";
    case RigCommand::GetSplitFreq:
      return "i" + vfo + "\n";
    case RigCommand::SetSplitFreq:
      return "I" + vfo + " " + whole_hz(hz) + "\n";
  }
  return "\n";
}

void RigctlSession::connected() {
  *this = RigctlSession(options_);
  link_ = RigLink::Handshake;
  queue_.push_back({RigCommand::ChkVfo, 0.0});
}

void RigctlSession::disconnected() { *this = RigctlSession(options_); }

bool RigctlSession::accepting() const {
  return link_ == RigLink::Handshake || link_ == RigLink::Up;
}

void RigctlSession::enqueue(RigCommand command, double hz) {
  const auto same = std::find_if(queue_.begin(), queue_.end(),
                                 [command](const Pending& p) { return p.command == command; });
  if (same != queue_.end()) {
    same->hz = hz;  // not sent yet: the newer value replaces it
    return;
  }
  queue_.push_back({command, hz});
}

void RigctlSession::read_back(RigCommand get) {
  // A read queued earlier would answer before the set: it moves behind it.
  remove_queued(get);
  queue_.push_back({get, 0.0});
}

void RigctlSession::remove_queued(RigCommand command) {
  queue_.erase(std::remove_if(queue_.begin(), queue_.end(),
                              [command](const Pending& p) { return p.command == command; }),
               queue_.end());
}

bool RigctlSession::set_rx_hz(double hz) {
  if (!accepting() || !is_rig_frequency(hz)) return false;
  enqueue(RigCommand::SetFreq, hz);
  read_back(RigCommand::GetFreq);
  return true;
}

bool RigctlSession::set_tx_hz(double hz) {
  if (!accepting() || split_refused_ || !is_rig_frequency(hz)) return false;
  if (!split_on_) enqueue(RigCommand::SetSplit, 0.0);
  enqueue(RigCommand::SetSplitFreq, hz);
  read_back(RigCommand::GetSplitFreq);
  return true;
}

bool RigctlSession::read_rx() {
  if (!accepting()) return false;
  enqueue(RigCommand::GetFreq, 0.0);
  return true;
}

bool RigctlSession::read_tx() {
  if (!accepting() || !split_on_) return false;
  enqueue(RigCommand::GetSplitFreq, 0.0);
  return true;
}

std::optional<std::string> RigctlSession::next_line(double now_s) {
  if (!accepting() || in_flight_ || queue_.empty()) return std::nullopt;
  in_flight_ = queue_.front();
  queue_.erase(queue_.begin());
  sent_at_s_ = now_s;
  return rigctl_command_line(in_flight_->command, in_flight_->hz, vfo_mode_, options_.split_tx_vfo);
}

RigEvent RigctlSession::fail(std::string message) {
  link_ = RigLink::Failed;
  const RigCommand command = in_flight_ ? in_flight_->command : RigCommand::ChkVfo;
  queue_.clear();
  in_flight_.reset();
  RigEvent event = make_event(RigEventKind::LinkFailed, command);
  event.message = std::move(message);
  return event;
}

std::optional<RigEvent> RigctlSession::on_line(std::string_view line) {
  if (!accepting()) return std::nullopt;
  if (!in_flight_) return fail("rigctld sent a line nobody asked for: " + quoted(line));
  const RigCommand command = in_flight_->command;
  if (command == RigCommand::ChkVfo) return answer_chk_vfo(line);
  return is_get(command) ? answer_get(command, line) : answer_set(command, line);
}

std::optional<RigEvent> RigctlSession::on_tick(double now_s) {
  if (!accepting() || !in_flight_) return std::nullopt;
  if (now_s - sent_at_s_ < options_.reply_timeout_s) return std::nullopt;
  return fail("rigctld did not answer " + std::string(rigctl_command_name(in_flight_->command)) +
              " within " + std::to_string(std::lround(options_.reply_timeout_s * 1000)) + " ms");
}

RigEvent RigctlSession::answer_chk_vfo(std::string_view line) {
  const auto mode = parse_chk_vfo(line);
  // An RPRT: a rigctld older than \chk_vfo, which has no VFO mode to ask about.
  if (!mode && !parse_rprt(line)) return fail("rigctld answered chk_vfo with " + quoted(line));
  in_flight_.reset();
  vfo_mode_ = mode.value_or(false);
  link_ = RigLink::Up;
  RigEvent event = make_event(RigEventKind::VfoMode, RigCommand::ChkVfo);
  event.vfo_mode = vfo_mode_;
  return event;
}

RigEvent RigctlSession::answer_get(RigCommand command, std::string_view line) {
  in_flight_.reset();
  if (const auto code = parse_rprt(line)) {
    RigEvent event = make_event(RigEventKind::Refused, command);
    event.rprt = *code;
    event.message = std::string(rigctl_command_name(command)) + ": " + hamlib_error_text(*code);
    return event;
  }
  const auto hz = parse_frequency_hz(line);
  if (!hz)
    return fail("rigctld answered " + std::string(rigctl_command_name(command)) + " with " +
                quoted(line));
  const bool rx = command == RigCommand::GetFreq;
  (rx ? rx_read_hz_ : tx_read_hz_) = *hz;
  RigEvent event = make_event(rx ? RigEventKind::RxRead : RigEventKind::TxRead, command);
  event.hz = *hz;
  return event;
}

RigEvent RigctlSession::answer_set(RigCommand command, std::string_view line) {
  const auto code = parse_rprt(line);
  if (!code)
    return fail("rigctld answered " + std::string(rigctl_command_name(command)) + " with " +
                quoted(line));
  in_flight_.reset();
  if (*code == 0) {
    split_on_ = split_on_ || command == RigCommand::SetSplit;
    return make_event(RigEventKind::Written, command);
  }
  if (command == RigCommand::SetSplit) {
    split_refused_ = true;  // no TX until the next connection: the refusal is said once
    remove_queued(RigCommand::SetSplitFreq);
    remove_queued(RigCommand::GetSplitFreq);
  }
  RigEvent event = make_event(RigEventKind::Refused, command);
  event.rprt = *code;
  event.message = std::string(rigctl_command_name(command)) + ": " + hamlib_error_text(*code);
  return event;
}

}  // namespace azt::radio
