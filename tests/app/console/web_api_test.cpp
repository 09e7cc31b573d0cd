// WebApi: routing and who may act (docs/web-api.md, docs/reliability.md R14), over a recording
// model and an injected clock. Every refused request must leave the model untouched.
#include "console/web_api.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace azt::app {
namespace {

using json = nlohmann::json;

class RecordingModel final : public ConsoleModel {
 public:
  json state() override { return {{"mode", "TRACK"}}; }
  json config() override { return {{"band", "144"}}; }
  json targets() override { return {{"targets", json::array()}}; }
  json sky(double hours) override { return {{"hours", hours}}; }
  void act(const std::string& action, const json& body, const std::string& /*source*/,
           ActDone done) override {
    actions.push_back(action + " " + body.dump());
    if (action == "config/station" && body.value("grid", "") == "ZZ99") {
      throw ApiError(400, "grid", "locator ZZ99 is not valid");
    }
    if (action == "config/park") {  // a refusal found later, as a save's would be
      done(ActResult{json::object(), ApiError(503, "slot", "the file is locked")});
      return;
    }
    done(ActResult{});
  }
  void upload_elements(std::string text, const std::string& /*source*/, ActDone done) override {
    uploads.push_back(std::move(text));
    if (uploads.back().empty()) {
      done(ActResult{json::object(), ApiError(400, "", "does not parse: empty")});
      return;
    }
    done(ActResult{{{"count", 1}}, std::nullopt});
  }
  std::vector<std::string> actions;
  std::vector<std::string> uploads;
};

const std::string kPassword = "correct horse battery";

struct Rig {
  RecordingModel model;
  std::string token = "0123456789abcdef0123456789abcdef";
  WebAuth auth{
      WebAuth::Config{hash_password(kPassword), {{"script", sha256_hex(token), "", false}}}};
  double now_s = 1000.0;
  /// Jobs sent off the loop wait here until the test runs them (run_jobs), as on the worker.
  std::vector<std::pair<std::function<void()>, std::function<void()>>> jobs;
  bool defer = false;
  WebApi api{model, auth, WebApiConfig{{"shack.local"}}, [this] { return now_s; },
             [this](std::function<void()> work, std::function<void()> done) {
               if (!defer) {
                 run_inline(work, done);
                 return;
               }
               jobs.emplace_back(std::move(work), std::move(done));
             }};

  /// The answer to `r`; status 0 while it has not come (a job still waiting).
  linux_os::HttpReply handle(const linux_os::HttpRequest& r) {
    auto reply = std::make_shared<linux_os::HttpReply>();
    reply->status = 0;
    api.handle(r, [reply](linux_os::HttpReply answer) { *reply = std::move(answer); });
    replies.push_back(reply);
    return *reply;
  }
  void run_jobs() {
    for (auto& [work, done] : std::exchange(jobs, {})) run_inline(work, done);
  }
  std::vector<std::shared_ptr<linux_os::HttpReply>> replies;

  static linux_os::HttpRequest request(const std::string& method, const std::string& path,
                                       const std::string& body = "") {
    linux_os::HttpRequest r;
    r.method = method;
    r.path = path;
    r.body = body;
    r.host = "127.0.0.1:8080";
    r.client = "192.0.2.7";
    return r;
  }
  /// Logs in; returns the cookie header and the CSRF token.
  std::pair<std::string, std::string> login() {
    const linux_os::HttpReply r =
        handle(request("POST", "/api/login", json{{"password", kPassword}}.dump()));
    EXPECT_EQ(r.status, 200U) << r.body;
    std::string cookie;
    for (const auto& [name, value] : r.headers) {
      if (name == "Set-Cookie") cookie = value.substr(0, value.find(';'));
    }
    EXPECT_NE(cookie.find("azt_session="), std::string::npos);
    return {cookie, json::parse(r.body)["csrf"].get<std::string>()};
  }
};

TEST(WebApi, ReadingIsOpenToEveryone) {
  Rig rig;
  EXPECT_EQ(rig.handle(Rig::request("GET", "/api/state")).status, 200U);
  EXPECT_EQ(rig.handle(Rig::request("GET", "/api/config")).status, 200U);
  const linux_os::HttpReply sky = rig.handle([] {
    linux_os::HttpRequest r = Rig::request("GET", "/api/sky");
    r.query = "hours=99";
    return r;
  }());
  EXPECT_EQ(json::parse(sky.body)["hours"], 24.0);  // clamped
  EXPECT_EQ(rig.handle(Rig::request("GET", "/nope")).status, 404U);
  EXPECT_EQ(rig.handle(Rig::request("DELETE", "/api/state")).status, 405U);
}

TEST(WebApi, TheSettingsSchemaIsReadingAndItsChangesNeedTheLogin) {
  Rig rig;
  const auto schema = rig.handle(Rig::request("GET", "/api/config/schema"));
  ASSERT_EQ(schema.status, 200U);
  EXPECT_GT(json::parse(schema.body)["sections"].size(), 30U) << "the model's default: the schema";
  const std::string body = R"({"encoder_bits": 14})";
  EXPECT_EQ(rig.handle(Rig::request("PUT", "/api/config/mount.az", body)).status, 401U);
  linux_os::HttpRequest r = Rig::request("POST", "/api/config/mount.az", body);
  r.authorization = "Bearer " + rig.token;
  EXPECT_EQ(rig.handle(r).status, 405U) << "settings are changed with PUT";
  EXPECT_TRUE(rig.model.actions.empty());
  r.method = "PUT";
  EXPECT_EQ(rig.handle(r).status, 200U);
  EXPECT_EQ(rig.model.actions, std::vector<std::string>{R"(config/mount.az {"encoder_bits":14})"});
  r.body = "[1, 2]";
  EXPECT_EQ(rig.handle(r).status, 400U) << "a body that is not an object never reaches the model";
  EXPECT_EQ(rig.model.actions.size(), 1U);
}

TEST(WebApi, TheMoonPlannerIsReadingAndAModelWithoutOneSays404) {
  // GET /api/moon-windows goes to the model's asynchronous planner (docs/eme.md), open to
  // every reader like the rest of reading; this model has none.
  Rig rig;
  const auto reply = rig.handle(Rig::request("GET", "/api/moon-windows"));
  EXPECT_EQ(reply.status, 404U);
  EXPECT_NE(reply.body.find("no Moon planner"), std::string::npos) << reply.body;
}

TEST(WebApi, ActionsWithoutLoginAre401AndDoNothing) {
  Rig rig;
  for (const auto& [method, path] :
       std::vector<std::pair<std::string, std::string>>{{"POST", "/api/target"},
                                                        {"POST", "/api/stop"},
                                                        {"POST", "/api/correction"},
                                                        {"PUT", "/api/config/tilt"},
                                                        {"PUT", "/api/config/station"}}) {
    EXPECT_EQ(rig.handle(Rig::request(method, path, "{\"name\":\"moon\"}")).status, 401U)
        << method << " " << path;
  }
  EXPECT_TRUE(rig.model.actions.empty());
}

TEST(WebApi, AnElementFileNeedsTheLoginAndGoesToTheModelAsItIs) {
  Rig rig;
  const std::string file = "ISS\n1 25544U …\n2 25544 …\n";  // not JSON: passed on as text
  auto anonymous = Rig::request("POST", "/api/satellites/elements");
  EXPECT_TRUE(rig.api.body_allowance(anonymous).refusal.has_value()) << "401 from the head";
  anonymous.body = file;
  EXPECT_EQ(rig.handle(anonymous).status, 401U);
  auto r = Rig::request("POST", "/api/satellites/elements");
  r.authorization = "Bearer " + rig.token;
  const auto allowance = rig.api.body_allowance(r);
  EXPECT_FALSE(allowance.refusal.has_value());
  EXPECT_EQ(allowance.max_bytes, WebApi::kMaxElementUploadBytes);
  EXPECT_TRUE(rig.api.body_allowance(r).refusal.has_value()) << "one at a time";
  r.body = file;
  const auto reply = rig.handle(r);
  EXPECT_EQ(reply.status, 200U) << reply.body;
  ASSERT_EQ(rig.model.uploads.size(), 1U);
  EXPECT_EQ(rig.model.uploads[0], file);
  r.body.clear();
  EXPECT_EQ(rig.handle(r).status, 400U);
  EXPECT_TRUE(rig.model.actions.empty());
}

TEST(WebApi, StopFromThisMachineNeedsNoLoginAndFromTheLanDoes) {
  // The touch panel beside the controller must stop the antenna in one tap, logged in or not.
  Rig rig;
  for (const std::string client : {"127.0.0.1", "::1", "::ffff:127.0.0.1"}) {
    linux_os::HttpRequest r = Rig::request("POST", "/api/stop");
    r.client = client;
    EXPECT_EQ(rig.handle(r).status, 200U) << client;
  }
  EXPECT_EQ(rig.model.actions.size(), 3U);
  linux_os::HttpRequest lan = Rig::request("POST", "/api/stop");
  EXPECT_EQ(rig.handle(lan).status, 401U);
  // Anything else from this machine still needs the login; a page from elsewhere is refused.
  linux_os::HttpRequest target = Rig::request("POST", "/api/target", R"({"name":"moon"})");
  target.client = "127.0.0.1";
  EXPECT_EQ(rig.handle(target).status, 401U);
  linux_os::HttpRequest foreign = Rig::request("POST", "/api/stop");
  foreign.client = "127.0.0.1";
  foreign.origin = "http://evil.example";
  EXPECT_EQ(rig.handle(foreign).status, 403U);
  EXPECT_EQ(rig.model.actions.size(), 3U);
}

// docs/reliability.md "Hardening, round three" row 3: behind nginx or Caddy on the Pi every request
// comes from 127.0.0.1; one that a proxy passed on is from wherever its first sender is, and a STOP
// from there needs the login.
TEST(WebApi, StopThroughALocalProxyNeedsTheLogin) {
  Rig rig;
  linux_os::HttpRequest r = Rig::request("POST", "/api/stop");
  r.client = "127.0.0.1";
  r.forwarded = true;
  EXPECT_EQ(rig.handle(r).status, 401U);
  EXPECT_TRUE(rig.model.actions.empty());
  const auto [cookie, csrf] = rig.login();
  r.cookie = cookie;
  r.csrf = csrf;
  EXPECT_EQ(rig.handle(r).status, 200U) << "with the login it stops";
  EXPECT_EQ(rig.model.actions.size(), 1U);
}

TEST(WebApi, SessionNeedsTheCsrfTokenAndTheSameOrigin) {
  Rig rig;
  const auto [cookie, csrf] = rig.login();
  linux_os::HttpRequest r = Rig::request("POST", "/api/stop");
  r.cookie = "theme=dark; " + cookie;
  EXPECT_EQ(rig.handle(r).status, 403U);  // no token
  r.csrf = csrf.substr(0, 10);
  EXPECT_EQ(rig.handle(r).status, 403U);  // a prefix
  r.csrf = std::string(csrf.size(), 'a');
  EXPECT_EQ(rig.handle(r).status, 403U);  // same length, wrong
  r.csrf = csrf;
  r.origin = "http://evil.example";
  EXPECT_EQ(rig.handle(r).status, 403U);  // forged Origin
  r.origin = "http://127.0.0.1:8080.evil.example";
  EXPECT_EQ(rig.handle(r).status, 403U);
  EXPECT_TRUE(rig.model.actions.empty());
  r.origin = "http://127.0.0.1:8080";
  EXPECT_EQ(rig.handle(r).status, 200U);
  EXPECT_EQ(rig.model.actions.size(), 1U);
}

TEST(WebApi, BearerTokensMustMatchExactly) {
  Rig rig;
  linux_os::HttpRequest r = Rig::request("POST", "/api/target", "{\"name\":\"moon\"}");
  for (const std::string& wrong : {std::string(), rig.token.substr(0, 8), rig.token + "x",
                                   std::string(rig.token.size(), '0'), "Bearer " + rig.token}) {
    r.authorization = "Bearer " + wrong;
    EXPECT_EQ(rig.handle(r).status, 401U) << "'" << wrong << "'";
  }
  r.authorization = "Basic " + rig.token;
  EXPECT_EQ(rig.handle(r).status, 401U);
  EXPECT_TRUE(rig.model.actions.empty());
  r.authorization = "Bearer " + rig.token;
  EXPECT_EQ(rig.handle(r).status, 200U);
  EXPECT_EQ(rig.model.actions, (std::vector<std::string>{"target {\"name\":\"moon\"}"}));
}

TEST(WebApi, BruteForceIsSlowedThenBlocked) {
  Rig rig;
  const auto attempt = [&rig](const std::string& pw) {
    return rig.handle(Rig::request("POST", "/api/login", json{{"password", pw}}.dump())).status;
  };
  for (int i = 0; i < 3; ++i) EXPECT_EQ(attempt("guess" + std::to_string(i)), 401U);
  EXPECT_EQ(attempt(kPassword), 429U);  // limited: not even checked
  rig.now_s += 5.1;
  EXPECT_EQ(attempt("guess3"), 401U);
  EXPECT_EQ(attempt("guess4"), 429U);  // 10 s now
  // Ten failures within the hour block the client for the rest of the hour, whatever the delays.
  int failures = 4;
  while (failures < 10) {
    rig.now_s += 400.0;
    if (attempt("guess") == 401U) ++failures;
  }
  rig.now_s += 400.0;
  EXPECT_EQ(attempt(kPassword), 429U);
  rig.now_s += 3600.0;
  EXPECT_EQ(attempt(kPassword), 200U);
  // Another address is not affected by this one's failures.
  linux_os::HttpRequest other =
      Rig::request("POST", "/api/login", json{{"password", kPassword}}.dump());
  other.client = "192.0.2.8";
  EXPECT_EQ(rig.handle(other).status, 200U);
}

TEST(WebApi, BadValuesAndBodiesAre400NamingTheField) {
  Rig rig;
  linux_os::HttpRequest r = Rig::request("PUT", "/api/config/station", "{\"grid\":\"ZZ99\"}");
  r.authorization = "Bearer " + rig.token;
  const linux_os::HttpReply bad = rig.handle(r);
  EXPECT_EQ(bad.status, 400U);
  EXPECT_EQ(json::parse(bad.body)["field"], "grid");
  r.body = "{not json";
  EXPECT_EQ(rig.handle(r).status, 400U);
  r.body = "[1,2]";
  EXPECT_EQ(rig.handle(r).status, 400U);
  r.method = "POST";  // config changes are PUT
  r.body = "{}";
  EXPECT_EQ(rig.handle(r).status, 405U);
}

TEST(WebApi, ForeignHostNamesAreRefusedAgainstDnsRebinding) {
  Rig rig;
  linux_os::HttpRequest r = Rig::request("GET", "/api/state");
  r.host = "attacker.example:8080";
  EXPECT_EQ(rig.handle(r).status, 403U);
  r.host = "shack.local:8080";  // configured in allowed_hosts
  EXPECT_EQ(rig.handle(r).status, 200U);
  r.host = "[::1]:8080";
  EXPECT_EQ(rig.handle(r).status, 200U);
  r.host = "localhost";
  EXPECT_EQ(rig.handle(r).status, 200U);
}

TEST(WebApi, WebSocketUpgradeChecksOriginAndHost) {
  Rig rig;
  linux_os::HttpRequest r = Rig::request("GET", "/ws");
  r.websocket = true;
  r.origin = "http://127.0.0.1:8080";
  EXPECT_FALSE(rig.api.check_upgrade(r).has_value());
  r.origin = "http://evil.example";
  ASSERT_TRUE(rig.api.check_upgrade(r).has_value());
  EXPECT_EQ(rig.api.check_upgrade(r)->status, 403U);
}

TEST(WebApi, LogoutEndsTheSessionAndSessionsExpire) {
  Rig rig;
  auto [cookie, csrf] = rig.login();
  linux_os::HttpRequest r = Rig::request("POST", "/api/stop");
  r.cookie = cookie;
  r.csrf = csrf;
  EXPECT_EQ(rig.handle(r).status, 200U);
  linux_os::HttpRequest out = r;
  out.path = "/api/logout";
  EXPECT_EQ(rig.handle(out).status, 200U);
  EXPECT_EQ(rig.handle(r).status, 401U);
  std::tie(cookie, csrf) = rig.login();
  r.cookie = cookie;
  r.csrf = csrf;
  rig.now_s += 8 * 24 * 3600.0;  // past the 7-day lifetime
  EXPECT_EQ(rig.handle(r).status, 401U);
}

TEST(WebApi, CookieValuesAreFoundAmongOthers) {
  EXPECT_EQ(cookie_value("a=1; azt_session=xyz; b=2", "azt_session"), "xyz");
  EXPECT_EQ(cookie_value("azt_session_old=1", "azt_session"), "");
  EXPECT_EQ(cookie_value("", "azt_session"), "");
}

TEST(WebApi, ThePasswordCheckRunsOffTheLoopAndAnswersWhenItIsDone) {
  Rig rig;
  rig.defer = true;
  rig.handle(Rig::request("POST", "/api/login", json{{"password", kPassword}}.dump()));
  ASSERT_EQ(rig.jobs.size(), 1U);
  EXPECT_EQ(rig.replies.back()->status, 0U);  // nothing answered while Argon2id runs elsewhere
  rig.run_jobs();
  EXPECT_EQ(rig.replies.back()->status, 200U);
}

TEST(WebApi, PasswordChecksAreBoundedWhateverTheAddresses) {
  Rig rig;
  rig.defer = true;
  for (int i = 0; i < 3; ++i) {
    linux_os::HttpRequest r =
        Rig::request("POST", "/api/login", json{{"password", "guess"}}.dump());
    r.client = "198.51.100." + std::to_string(i);
    rig.handle(r);
  }
  ASSERT_EQ(rig.jobs.size(), WebAuth::kMaxChecksInFlight);
  EXPECT_EQ(rig.replies[2]->status, 503U);  // busy: never checked
  rig.run_jobs();
  EXPECT_EQ(rig.replies[0]->status, 401U);
  EXPECT_EQ(rig.replies[1]->status, 401U);
  // Parallel attempts from one address meet its limit before their checks start.
  rig.now_s += 3600.0;
  for (int i = 0; i < 5; ++i) {
    rig.handle(Rig::request("POST", "/api/login", json{{"password", "guess"}}.dump()));
    rig.run_jobs();
  }
  EXPECT_EQ(rig.replies.back()->status, 429U);
}

TEST(WebApi, TheFailedLoginTableForgetsAddressesAfterAnHour) {
  Rig rig;
  for (int i = 0; i < 20; ++i) {  // each a real Argon2id check (~0.1 s)
    linux_os::HttpRequest r =
        Rig::request("POST", "/api/login", json{{"password", "guess"}}.dump());
    r.client = "203.0.113." + std::to_string(i);
    EXPECT_EQ(rig.handle(r).status, 401U);
  }
  EXPECT_EQ(rig.auth.clients_tracked(), 20U);
  rig.now_s += 3601.0;
  EXPECT_EQ(rig.handle(Rig::request("POST", "/api/login", "{\"password\":\"x\"}")).status, 401U);
  EXPECT_EQ(rig.auth.clients_tracked(), 1U);
}

TEST(WebApi, TextThatIsNotUtf8IsAnsweredNeverThrown) {
  // docs/reliability.md "Hardening" rows 1 and 12: a Latin-1 Host and a path with a stray byte. The
  // transport makes text valid before it gets here; the API must not throw even if it did not.
  Rig rig;
  linux_os::HttpRequest r = Rig::request("GET", "/api/state");
  r.host = "caf\xe9";
  linux_os::HttpReply reply = rig.handle(r);
  EXPECT_EQ(reply.status, 403U);
  EXPECT_FALSE(json::parse(reply.body, nullptr, false).is_discarded()) << reply.body;
  reply = rig.handle(Rig::request("GET", "/\xff"));
  EXPECT_EQ(reply.status, 404U);
  EXPECT_FALSE(json::parse(reply.body, nullptr, false).is_discarded()) << reply.body;
}

TEST(WebApi, ARefusalFoundAfterTheAnswerWasDeferredIsSent) {
  Rig rig;
  const auto [cookie, csrf] = rig.login();
  linux_os::HttpRequest r = Rig::request("PUT", "/api/config/park", "{\"slot\":1}");
  r.cookie = cookie;
  r.csrf = csrf;
  const linux_os::HttpReply reply = rig.handle(r);
  EXPECT_EQ(reply.status, 503U);
  EXPECT_EQ(json::parse(reply.body)["field"], "slot");
}

}  // namespace
}  // namespace azt::app
