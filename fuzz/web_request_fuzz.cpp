// libFuzzer target for the web console's request handling (docs/reliability.md R14,
// R24): the bytes a client sends on one connection, parsed by Boost.Beast's request parser with
// the server's limits, turned into an azt::linux_os::HttpRequest by the server's own
// azt::linux_os::to_http_request (azt/linux/http_request.hpp), then dispatched as
// azt::linux_os::HttpServer's HttpSession does: has_session, then a WebSocket upgrade to
// WebApi::check_upgrade, anything else to WebApi::handle. Behind the API: a fake station
// (ConsoleModel), a real WebAuth and run_inline for what the daemon runs off the loop (password
// checks, saves), so every answer comes before handle returns.
//
// Input: byte 0 picks the variant, byte 1 where to cut the payload in two feeds (the parser sees
// the bytes as two reads), the rest is what the client sends: up to kMaxRequests requests one
// after the other, as keep-alive pipelining sends them, sharing one WebAuth (a logout or a failed
// login carries over to the next request). Variant bits, for what the fuzzer cannot guess:
//   0 a valid "Authorization: Bearer" token;  1 a session cookie (logged in before the first
//   request), 2 with its X-CSRF-Token, 3 expired (the clock a week and a day on);
//   4 the model refuses every action at once (ApiError thrown), 5 later (through done);
//   6-7 the method: as sent, GET, POST, PUT.
// Invariants (a violation aborts, and libFuzzer keeps the input):
// - azt::linux_os::to_http_request gives valid UTF-8 in every text field but the body;
// - nothing throws out of handle, check_upgrade or has_session;
// - handle calls respond exactly once;
// - every reply's status is 200..599, its body valid UTF-8 that parses as JSON when its type is
//   application/json, its type and headers free of CR and LF;
// - the model acts only for a request that has_session() accepted (a valid bearer or session).
// The crash this would have found: a Latin-1 Host echoed into the 403's JSON made
// nlohmann::json::dump throw out of handle (docs/reliability.md "Hardening" row 1, before its
// fix); today the header is made valid UTF-8 and every dump replaces (seed latin1_host).
// AZT_FUZZ_TRACE=1 in the environment prints each request and its answer (to triage an input).
#include <sodium.h>

#include <boost/asio/buffer.hpp>
#include <boost/beast/http/error.hpp>
#include <boost/beast/http/field.hpp>
#include <boost/beast/http/parser.hpp>
#include <boost/beast/http/string_body.hpp>
#include <boost/beast/http/verb.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

#include "azt/linux/http_request.hpp"
#include "azt/linux/http_server.hpp"
#include "azt/util/valid_utf8.hpp"
#include "common/off_loop.hpp"
#include "console/web_api.hpp"
#include "console/web_auth.hpp"
#include "fuzz_support.hpp"

namespace {

namespace app = azt::app;
namespace fuzz = azt::fuzz;
namespace http = boost::beast::http;
using json = nlohmann::json;

// The server's limits (web_server.cpp kMaxHeaderBytes, kMaxBodyBytes).
constexpr std::size_t kMaxHeaderBytes = std::size_t{8} * 1024;
constexpr std::size_t kMaxBodyBytes = std::size_t{64} * 1024;
/// Requests answered per input: enough for a login, an action and a logout in one connection.
constexpr int kMaxRequests = 4;

const std::string kPeer = "192.0.2.7";
const std::string kPassword = "correct horse battery";
const std::string kToken = "0123456789abcdef0123456789abcdef";
constexpr double kNow = 1000.0;
constexpr double kExpired = kNow + 8 * 24 * 3600.0;  // past the 7-day session lifetime

enum Variant : std::uint8_t {
  kBearer = 1U << 0U,
  kSession = 1U << 1U,
  kCsrf = 1U << 2U,
  kExpiredSession = 1U << 3U,
  kRefuseAtOnce = 1U << 4U,
  kRefuseLater = 1U << 5U,
};

/// An Argon2id string computed once. The daemon's hash_password uses libsodium's interactive
/// limits (~0.1 s and 64 MiB per check), which would make every fuzzed login a tenth of a second;
/// this hash has the minimum limits, so verify_password (the same code) takes microseconds.
const std::string& password_hash() {
  static const std::string hash = [] {
    AZT_FUZZ_REQUIRE(sodium_init() >= 0);
    char out[crypto_pwhash_STRBYTES];
    AZT_FUZZ_REQUIRE(crypto_pwhash_str(out, kPassword.data(), kPassword.size(),
                                       crypto_pwhash_OPSLIMIT_MIN,
                                       crypto_pwhash_MEMLIMIT_MIN) == 0);
    std::string h(out);
    AZT_FUZZ_REQUIRE(app::verify_password(h, kPassword));
    AZT_FUZZ_REQUIRE(!app::verify_password(h, "wrong"));
    return h;
  }();
  return hash;
}

const std::string& token_sha256() {
  static const std::string digest = app::sha256_hex(kToken);
  return digest;
}

/// The station as the console sees it: small fixed JSON, and actions that succeed, fail at once
/// or fail later. Refusals echo what the client sent (the action, the first key, the body), as
/// the daemon's messages name the field and value at fault.
class FakeModel final : public app::ConsoleModel {
 public:
  FakeModel(bool refuse_at_once, bool refuse_later)
      : refuse_at_once_(refuse_at_once), refuse_later_(refuse_later) {}

  json state() override { return {{"mode", "TRACK"}, {"az", 181.5}, {"el", 12.25}}; }
  json config() override { return {{"station", {{"grid", "JO65"}}}, {"park", json::array()}}; }
  json targets() override { return {{"targets", json::array({"moon", "sun"})}}; }
  json sky(double hours) override {
    AZT_FUZZ_REQUIRE(std::isfinite(hours) && hours >= 0.0 && hours <= 24.0);
    return {{"hours", hours}, {"passes", json::array()}};
  }
  void act(const std::string& action, const json& body, const std::string& source,
           app::ActDone done) override {
    acted = true;
    AZT_FUZZ_REQUIRE(source.rfind("console ", 0) == 0);
    AZT_FUZZ_REQUIRE(body.is_object());
    const std::string field = body.empty() ? std::string() : body.begin().key();
    if (refuse_at_once_ || body.contains("refuse")) {
      throw app::ApiError(400, field, "refused " + action + ": " + body.dump());
    }
    if (body.contains("fail")) {
      // Not an ApiError, and not UTF-8: the 500 path must still answer valid JSON.
      throw std::runtime_error("model failed on \xff\xfe " + action);
    }
    if (refuse_later_ || body.contains("later")) {
      done(app::ActResult{json::object(), app::ApiError(409, field, "not now: " + action)});
      return;
    }
    json fields{{"action", action}};
    if (const auto it = body.find("echo"); it != body.end()) fields["echo"] = *it;
    done(app::ActResult{fields, std::nullopt});
  }

  bool acted = false;

 private:
  bool refuse_at_once_;
  bool refuse_later_;
};

bool has_line_break(std::string_view text) {
  return text.find_first_of("\r\n") != std::string_view::npos;
}

const bool kTrace = std::getenv("AZT_FUZZ_TRACE") != nullptr;

void trace(const azt::linux_os::HttpRequest& request, const azt::linux_os::HttpReply* reply) {
  if (!kTrace) return;
  std::fprintf(stderr, "%s %s -> %u %s\n", request.method.c_str(), request.path.c_str(),
               reply != nullptr ? reply->status : 0U,
               reply != nullptr ? reply->body.substr(0, 200).c_str() : "(accepted)");
}

void check_reply(const azt::linux_os::HttpReply& reply) {
  AZT_FUZZ_REQUIRE(reply.status >= 200 && reply.status <= 599);
  AZT_FUZZ_REQUIRE(azt::is_valid_utf8(reply.body));
  AZT_FUZZ_REQUIRE(!has_line_break(reply.content_type));
  if (reply.content_type == "application/json") {
    AZT_FUZZ_REQUIRE(!json::parse(reply.body, nullptr, false).is_discarded());
  }
  for (const auto& [name, value] : reply.headers) {
    AZT_FUZZ_REQUIRE(!name.empty() && !has_line_break(name) && !has_line_break(value));
    AZT_FUZZ_REQUIRE(azt::is_valid_utf8(name) && azt::is_valid_utf8(value));
  }
}

void check_request(const azt::linux_os::HttpRequest& r) {
  for (const std::string* text : {&r.method, &r.path, &r.query, &r.origin, &r.host, &r.cookie,
                                  &r.csrf, &r.authorization, &r.client}) {
    AZT_FUZZ_REQUIRE(azt::is_valid_utf8(*text));
  }
}

[[noreturn]] void threw(const char* where) {
  try {
    throw;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s threw: %s\n", where, e.what());
  } catch (...) {
    std::fprintf(stderr, "%s threw something that is not a std::exception\n", where);
  }
  fuzz::invariant_failed("nothing throws out of the API", __FILE__, __LINE__);
}

/// What the client sends, as reads deliver it: the payload cut in two.
class Connection {
 public:
  Connection(std::string_view payload, std::size_t cut)
      : first_(payload.substr(0, cut)), second_(payload.substr(cut)) {}

  /// The next request, or nullopt when the connection ends without one: the bytes ran out
  /// mid-request, the request was malformed, or over a limit (the server answers 431 or 413
  /// with its own fixed text and closes).
  std::optional<http::request<http::string_body>> next() {
    http::request_parser<http::string_body> parser;
    parser.header_limit(kMaxHeaderBytes);
    parser.body_limit(kMaxBodyBytes);
    boost::beast::error_code ec;
    while (!parser.is_done()) {
      if (buffer_.empty() && !read()) break;
      const std::size_t used = parser.put(boost::asio::buffer(buffer_), ec);
      buffer_.erase(0, used);
      if (ec == http::error::need_more || (!ec && used == 0)) {
        ec = {};
        if (!read()) break;
      } else if (ec) {
        return std::nullopt;
      }
    }
    if (!parser.is_done()) {
      if (!parser.got_some()) return std::nullopt;  // the client closed between requests
      parser.put_eof(ec);  // as http::async_read does when the stream ends mid-request
      if (ec || !parser.is_done()) return std::nullopt;
    }
    return parser.release();
  }

 private:
  /// Appends the next read to the buffer; false at the end of the stream.
  bool read() {
    while (reads_ < 2) {
      const std::string_view piece = reads_++ == 0 ? first_ : second_;
      if (!piece.empty()) {
        buffer_.append(piece);
        return true;
      }
    }
    return false;
  }

  std::string_view first_;
  std::string_view second_;
  std::string buffer_;
  int reads_ = 0;
};

/// The headers the variant adds to what was sent.
void apply_variant(std::uint8_t variant, const app::WebAuth::Login& login,
                   http::request<http::string_body>& req) {
  switch (variant >> 6U) {
    case 1:
      req.method(http::verb::get);
      break;
    case 2:
      req.method(http::verb::post);
      break;
    case 3:
      req.method(http::verb::put);
      break;
    default:
      break;
  }
  if ((variant & kBearer) != 0) req.set(http::field::authorization, "Bearer " + kToken);
  if ((variant & kSession) != 0) {
    const auto sent = req.find(http::field::cookie);
    const std::string others =
        sent == req.end() ? std::string() : std::string(sent->value()) + "; ";
    req.set(http::field::cookie, others + "azt_session=" + login.session);
    if ((variant & kCsrf) != 0) req.set("X-CSRF-Token", login.csrf);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::FuzzInput input(data, size);
  const std::uint8_t variant = input.take();
  const std::uint8_t cut = input.take();
  const std::string_view payload = input.rest();

  double now_s = kNow;
  FakeModel model((variant & kRefuseAtOnce) != 0, (variant & kRefuseLater) != 0);
  app::WebAuth auth(app::WebAuth::Config{password_hash(), {{"script", token_sha256(), "", false}}});
  app::WebApi api(
      model, auth, app::WebApiConfig{{"shack.local"}}, [&now_s] { return now_s; }, app::run_inline);
  app::WebAuth::Login login;
  if ((variant & kSession) != 0) {
    AZT_FUZZ_REQUIRE(auth.begin_login(kPeer, now_s).outcome ==
                     app::WebAuth::LoginOutcome::Checking);
    login = auth.finish_login(kPeer, true, now_s);
    AZT_FUZZ_REQUIRE(login.outcome == app::WebAuth::LoginOutcome::Ok);
    if ((variant & kExpiredSession) != 0) now_s = kExpired;
  }

  Connection connection(payload, fuzz::split_point(cut, payload.size()));
  for (int n = 0; n < kMaxRequests; ++n) {
    auto req = connection.next();
    if (!req) break;
    apply_variant(variant, login, *req);
    const azt::linux_os::HttpRequest request = azt::linux_os::to_http_request(*req, kPeer);
    check_request(request);

    bool session = false;
    try {
      session = api.has_session(request);
    } catch (...) {
      threw("has_session");
    }
    if (request.websocket && request.path == "/ws") {
      std::optional<azt::linux_os::HttpReply> refusal;
      try {
        refusal = api.check_upgrade(request);
      } catch (...) {
        threw("check_upgrade");
      }
      trace(request, refusal ? &*refusal : nullptr);
      if (refusal) check_reply(*refusal);
      break;  // accepted: the connection is a WebSocket now; refused: answered and closed
    }

    model.acted = false;
    int answers = 0;
    try {
      api.handle(request, [&answers, &request](const azt::linux_os::HttpReply& reply) {
        ++answers;
        AZT_FUZZ_REQUIRE(answers == 1);
        trace(request, &reply);
        check_reply(reply);
      });
    } catch (...) {
      threw("handle");
    }
    AZT_FUZZ_REQUIRE(answers == 1);
    AZT_FUZZ_REQUIRE(!model.acted || session);
    if (!req->keep_alive()) break;
  }
  return 0;
}

#ifdef AZT_FUZZ_STANDALONE
int main(int argc, char** argv) { return azt::fuzz::replay_files("web_request_fuzz", argc, argv); }
#endif
