#include "console/web_auth.hpp"

#include <sodium.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <stdexcept>

namespace azt::app {
namespace {

void init_sodium() {
  // Idempotent and thread-safe; fails only if no entropy source can be opened.
  if (sodium_init() < 0) throw std::runtime_error("libsodium could not initialise");
}

constexpr double kMinute = 60.0;
constexpr double kHour = 3600.0;
constexpr std::size_t kFreeFailuresPerMinute = 3;
constexpr std::size_t kMaxFailuresPerHour = 10;
constexpr double kFirstDelayS = 5.0;
constexpr double kMaxDelayS = 300.0;

}  // namespace

std::string to_hex(const unsigned char* data, std::size_t size) {
  std::string out(size * 2 + 1, '\0');
  sodium_bin2hex(out.data(), out.size(), data, size);
  out.pop_back();
  return out;
}

std::string hash_password(std::string_view password) {
  init_sodium();
  char out[crypto_pwhash_STRBYTES];
  if (crypto_pwhash_str(out, password.data(), password.size(), crypto_pwhash_OPSLIMIT_INTERACTIVE,
                        crypto_pwhash_MEMLIMIT_INTERACTIVE) != 0) {
    throw std::runtime_error("out of memory while hashing the password");
  }
  return out;
}

bool verify_password(const std::string& hash, std::string_view password) {
  init_sodium();
  if (hash.size() >= crypto_pwhash_STRBYTES) return false;
  return crypto_pwhash_str_verify(hash.c_str(), password.data(), password.size()) == 0;
}

std::string sha256_hex(std::string_view data) {
  init_sodium();
  unsigned char digest[crypto_hash_sha256_BYTES];
  crypto_hash_sha256(digest, reinterpret_cast<const unsigned char*>(data.data()), data.size());
  return to_hex(digest, sizeof digest);
}

std::string random_hex(std::size_t bytes) {
  init_sodium();
  std::string raw(bytes, '\0');
  randombytes_buf(raw.data(), raw.size());
  return to_hex(reinterpret_cast<const unsigned char*>(raw.data()), raw.size());
}

std::string random_password() {
  init_sodium();
  static constexpr std::string_view kAlphabet = "abcdefghjkmnpqrstuvwxyz23456789";  // no 0/o 1/l/i
  std::string out;
  for (int i = 0; i < 16; ++i) {
    out += kAlphabet[randombytes_uniform(static_cast<std::uint32_t>(kAlphabet.size()))];
  }
  return out;
}

bool constant_time_equal(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;  // the lengths are not secret (a hash, a token)
  if (a.empty()) return true;
  return sodium_memcmp(a.data(), b.data(), a.size()) == 0;
}

double WebAuth::blocked_until(const Failures& f) const {
  if (f.at_s.size() >= kMaxFailuresPerHour) return f.at_s.front() + kHour;
  const double last = f.at_s.empty() ? 0.0 : f.at_s.back();
  const auto in_last_minute = static_cast<std::size_t>(
      std::count_if(f.at_s.begin(), f.at_s.end(), [last](double t) { return t > last - kMinute; }));
  if (in_last_minute < kFreeFailuresPerMinute) return 0.0;
  const double exponent = static_cast<double>(in_last_minute - kFreeFailuresPerMinute);
  return last + std::min(kMaxDelayS, kFirstDelayS * std::pow(2.0, exponent));
}

void WebAuth::prune(double now_s) {
  for (auto it = failures_.begin(); it != failures_.end();) {
    auto& at = it->second.at_s;
    while (!at.empty() && at.front() <= now_s - kHour) at.pop_front();
    it = at.empty() ? failures_.erase(it) : std::next(it);
  }
  while (failures_.size() > kMaxClientsTracked) {
    const auto stalest = std::min_element(failures_.begin(), failures_.end(), [](auto& a, auto& b) {
      return a.second.at_s.back() < b.second.at_s.back();
    });
    failures_.erase(stalest);
  }
}

WebAuth::Login WebAuth::begin_login(const std::string& client, double now_s) {
  prune(now_s);
  Login result;
  if (const auto it = failures_.find(client); it != failures_.end()) {
    if (const double until = blocked_until(it->second); until > now_s) {
      result.outcome = LoginOutcome::Limited;
      result.retry_after_s = until - now_s;
      return result;
    }
  }
  if (checks_in_flight_ >= kMaxChecksInFlight) {
    result.outcome = LoginOutcome::Busy;
    result.retry_after_s = 1.0;
    return result;
  }
  // Counted now, so that parallel attempts from one address meet the limit before their checks.
  failures_[client].at_s.push_back(now_s);
  ++checks_in_flight_;
  result.outcome = LoginOutcome::Checking;
  return result;
}

WebAuth::Login WebAuth::finish_login(const std::string& client, bool matched, double now_s) {
  if (checks_in_flight_ > 0) --checks_in_flight_;
  Login result;
  if (!matched || !has_password()) {
    result.outcome = LoginOutcome::Wrong;
    return result;
  }
  failures_.erase(client);
  if (sessions_.size() >= kMaxSessions) {
    const auto oldest = std::min_element(
        sessions_.begin(), sessions_.end(),
        [](const auto& a, const auto& b) { return a.second.created_s < b.second.created_s; });
    sessions_.erase(oldest);
  }
  result.outcome = LoginOutcome::Ok;
  result.session = random_hex(32);
  result.csrf = random_hex(32);
  sessions_[result.session] = Session{result.csrf, now_s};
  return result;
}

void WebAuth::logout(std::string_view session) {
  if (const auto it = sessions_.find(session); it != sessions_.end()) sessions_.erase(it);
}

std::optional<std::string> WebAuth::csrf_of(std::string_view session, double now_s) const {
  // A map lookup by the secret itself: the token is 256 random bits, so the timing of a failed
  // lookup tells an attacker nothing usable.
  const auto it = sessions_.find(session);
  if (it == sessions_.end() || now_s - it->second.created_s > config_.session_lifetime_s) {
    return std::nullopt;
  }
  return it->second.csrf;
}

std::optional<std::string> WebAuth::bearer_label(std::string_view token) const {
  if (token.empty()) return std::nullopt;
  const std::string digest = sha256_hex(token);
  std::optional<std::string> found;
  // Every token compared, whichever matches: the time taken says nothing about which one.
  for (const ApiToken& t : config_.tokens) {
    if (constant_time_equal(digest, t.sha256) && !found) found = t.label;
  }
  return found;
}

void WebAuth::set_password_hash(std::string hash, std::string_view keep_session) {
  config_.password_hash = std::move(hash);
  for (auto it = sessions_.begin(); it != sessions_.end();) {
    it = it->first == keep_session ? std::next(it) : sessions_.erase(it);
  }
}

}  // namespace azt::app
