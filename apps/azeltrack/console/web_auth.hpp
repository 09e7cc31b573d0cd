#pragma once
// Who may act through the web console (docs/web-api.md "Acting"): a password for people (a
// session cookie plus a CSRF token), a bearer token for scripts, and a login rate limit. Time is
// a parameter (monotonic seconds), so the limits are tested without sleeping.

#include <cstddef>
#include <deque>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace azt::app {

/// libsodium's Argon2id string ("$argon2id$v=19$m=…"), interactive limits (~0.1 s, 64 MiB).
std::string hash_password(std::string_view password);
/// False for a wrong password and for a hash that is not in that format.
bool verify_password(const std::string& hash, std::string_view password);
/// `size` bytes as lower-case hex (a digest's usual form).
std::string to_hex(const unsigned char* data, std::size_t size);
/// Lower-case hex SHA-256, the form `[web] api_token_sha256` keeps.
std::string sha256_hex(std::string_view data);
/// `bytes` random bytes as lower-case hex.
std::string random_hex(std::size_t bytes);
/// A password for people to type: 16 characters from an alphabet without look-alikes (~80 bits).
std::string random_password();
/// Compares in time that depends only on the lengths (never on where the first difference is).
bool constant_time_equal(std::string_view a, std::string_view b);

/// A bearer token as the settings keep it: a label people know it by and its digest.
struct ApiToken {
  std::string label;        ///< "panel", "logger script"
  std::string sha256;       ///< lower-case hex SHA-256 of the token
  std::string created_utc;  ///< ISO 8601 UTC; empty when not known
  bool legacy = false;      ///< `[web] api_token_sha256`, not a [[token]] item
};

class WebAuth {
 public:
  struct Config {
    std::string password_hash;     ///< empty: no password, nobody can log in
    std::vector<ApiToken> tokens;  ///< empty: no bearer token is accepted
    double session_lifetime_s = 7 * 24 * 3600.0;
  };
  explicit WebAuth(Config config) : config_(std::move(config)) {}

  enum class LoginOutcome { Ok, Wrong, Limited, Busy, Checking };
  struct Login {
    LoginOutcome outcome = LoginOutcome::Wrong;
    std::string session;         ///< the cookie value (Ok only)
    std::string csrf;            ///< the token the page sends back in X-CSRF-Token (Ok only)
    double retry_after_s = 0.0;  ///< Limited, Busy: when the client may try again
  };

  /// A login attempt from `client` (its address), in two halves around the password check,
  /// which is slow (Argon2id, ~0.1 s) and runs off the event loop (verify_password on a worker).
  /// begin_login answers Limited (after 3 failures within a minute each further attempt waits
  /// 5 s, doubling per failure to 5 min; over 10 failures in an hour the client waits until the
  /// oldest is an hour old), Busy (kMaxChecksInFlight checks are running, whoever asked: many
  /// addresses cannot queue many checks), or Checking: the check may start, and counts as a
  /// failure until finish_login hears it matched. A limited or busy attempt is not checked.
  Login begin_login(const std::string& client, double now_s);
  /// After a check that begin_login admitted: `matched` gives a session, else the failure stays.
  Login finish_login(const std::string& client, bool matched, double now_s);
  [[nodiscard]] const std::string& password_hash() const { return config_.password_hash; }
  void logout(std::string_view session);
  /// The session's CSRF token while the session is valid.
  [[nodiscard]] std::optional<std::string> csrf_of(std::string_view session, double now_s) const;
  /// Whether `token` hashes to one of the configured tokens.
  [[nodiscard]] bool bearer_ok(std::string_view token) const {
    return bearer_label(token).has_value();
  }
  /// The label of the token `token` hashes to, if any.
  [[nodiscard]] std::optional<std::string> bearer_label(std::string_view token) const;
  /// The settings changed while running (a token made or revoked, the password changed): the
  /// sessions of a changed password end, except `keep_session` (the one that changed it).
  void set_tokens(std::vector<ApiToken> tokens) { config_.tokens = std::move(tokens); }
  void set_password_hash(std::string hash, std::string_view keep_session);
  [[nodiscard]] const std::vector<ApiToken>& tokens() const { return config_.tokens; }
  [[nodiscard]] bool has_password() const { return !config_.password_hash.empty(); }
  /// Addresses with failures on record (pruned as they age; bounded by kMaxClientsTracked).
  [[nodiscard]] std::size_t clients_tracked() const { return failures_.size(); }

  static constexpr std::size_t kMaxChecksInFlight = 2;
  static constexpr std::size_t kMaxClientsTracked = 4096;  ///< the stalest goes beyond this
  static constexpr std::size_t kMaxSessions = 64;          ///< the oldest goes when a 65th logs in

 private:
  struct Session {
    std::string csrf;
    double created_s = 0.0;
  };
  struct Failures {
    std::deque<double> at_s;  ///< failure times within the last hour
  };
  [[nodiscard]] double blocked_until(const Failures& f) const;
  void prune(double now_s);

  Config config_;
  std::size_t checks_in_flight_ = 0;
  std::map<std::string, Session, std::less<>> sessions_;
  std::map<std::string, Failures, std::less<>> failures_;
};

}  // namespace azt::app
