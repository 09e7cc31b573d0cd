// WebApi: routing and who may act (issue 5 §2, reliability notes R14), over a recording model and
// an injected clock. Every refused request must leave the model untouched.
#include "web_api.hpp"

#include <gtest/gtest.h>

#include <string>
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
  json act(const std::string& action, const json& body) override {
    actions.push_back(action + " " + body.dump());
    if (action == "config/station" && body.value("grid", "") == "ZZ99") {
      throw ApiError(400, "grid", "locator ZZ99 is not valid");
    }
    return json::object();
  }
  std::vector<std::string> actions;
};

const std::string kPassword = "correct horse battery";

struct Rig {
  RecordingModel model;
  std::string token = "0123456789abcdef0123456789abcdef";
  WebAuth auth{WebAuth::Config{hash_password(kPassword), sha256_hex(token)}};
  double now_s = 1000.0;
  WebApi api{model, auth, WebApiConfig{{"shack.local"}}, [this] { return now_s; }};

  static WebRequest request(const std::string& method, const std::string& path,
                            const std::string& body = "") {
    WebRequest r;
    r.method = method;
    r.path = path;
    r.body = body;
    r.host = "127.0.0.1:8080";
    r.client = "192.0.2.7";
    return r;
  }
  /// Logs in; returns the cookie header and the CSRF token.
  std::pair<std::string, std::string> login() {
    const WebReply r =
        api.handle(request("POST", "/api/login", json{{"password", kPassword}}.dump()));
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
  EXPECT_EQ(rig.api.handle(Rig::request("GET", "/api/state")).status, 200U);
  EXPECT_EQ(rig.api.handle(Rig::request("GET", "/api/config")).status, 200U);
  const WebReply sky = rig.api.handle([] {
    WebRequest r = Rig::request("GET", "/api/sky");
    r.query = "hours=99";
    return r;
  }());
  EXPECT_EQ(json::parse(sky.body)["hours"], 24.0);  // clamped
  EXPECT_EQ(rig.api.handle(Rig::request("GET", "/nope")).status, 404U);
  EXPECT_EQ(rig.api.handle(Rig::request("DELETE", "/api/state")).status, 405U);
}

TEST(WebApi, ActionsWithoutLoginAre401AndDoNothing) {
  Rig rig;
  for (const auto& [method, path] :
       std::vector<std::pair<std::string, std::string>>{{"POST", "/api/target"},
                                                        {"POST", "/api/stop"},
                                                        {"POST", "/api/correction"},
                                                        {"PUT", "/api/config/tilt"},
                                                        {"PUT", "/api/config/station"}}) {
    EXPECT_EQ(rig.api.handle(Rig::request(method, path, "{\"name\":\"moon\"}")).status, 401U)
        << method << " " << path;
  }
  EXPECT_TRUE(rig.model.actions.empty());
}

TEST(WebApi, SessionNeedsTheCsrfTokenAndTheSameOrigin) {
  Rig rig;
  const auto [cookie, csrf] = rig.login();
  WebRequest r = Rig::request("POST", "/api/stop");
  r.cookie = "theme=dark; " + cookie;
  EXPECT_EQ(rig.api.handle(r).status, 403U);  // no token
  r.csrf = csrf.substr(0, 10);
  EXPECT_EQ(rig.api.handle(r).status, 403U);  // a prefix
  r.csrf = std::string(csrf.size(), 'a');
  EXPECT_EQ(rig.api.handle(r).status, 403U);  // same length, wrong
  r.csrf = csrf;
  r.origin = "http://evil.example";
  EXPECT_EQ(rig.api.handle(r).status, 403U);  // forged Origin
  r.origin = "http://127.0.0.1:8080.evil.example";
  EXPECT_EQ(rig.api.handle(r).status, 403U);
  EXPECT_TRUE(rig.model.actions.empty());
  r.origin = "http://127.0.0.1:8080";
  EXPECT_EQ(rig.api.handle(r).status, 200U);
  EXPECT_EQ(rig.model.actions.size(), 1U);
}

TEST(WebApi, BearerTokensMustMatchExactly) {
  Rig rig;
  WebRequest r = Rig::request("POST", "/api/target", "{\"name\":\"moon\"}");
  for (const std::string& wrong : {std::string(), rig.token.substr(0, 8), rig.token + "x",
                                   std::string(rig.token.size(), '0'), "Bearer " + rig.token}) {
    r.authorization = "Bearer " + wrong;
    EXPECT_EQ(rig.api.handle(r).status, 401U) << "'" << wrong << "'";
  }
  r.authorization = "Basic " + rig.token;
  EXPECT_EQ(rig.api.handle(r).status, 401U);
  EXPECT_TRUE(rig.model.actions.empty());
  r.authorization = "Bearer " + rig.token;
  EXPECT_EQ(rig.api.handle(r).status, 200U);
  EXPECT_EQ(rig.model.actions, (std::vector<std::string>{"target {\"name\":\"moon\"}"}));
}

TEST(WebApi, BruteForceIsSlowedThenBlocked) {
  Rig rig;
  const auto attempt = [&rig](const std::string& pw) {
    return rig.api.handle(Rig::request("POST", "/api/login", json{{"password", pw}}.dump())).status;
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
  WebRequest other = Rig::request("POST", "/api/login", json{{"password", kPassword}}.dump());
  other.client = "192.0.2.8";
  EXPECT_EQ(rig.api.handle(other).status, 200U);
}

TEST(WebApi, BadValuesAndBodiesAre400NamingTheField) {
  Rig rig;
  WebRequest r = Rig::request("PUT", "/api/config/station", "{\"grid\":\"ZZ99\"}");
  r.authorization = "Bearer " + rig.token;
  const WebReply bad = rig.api.handle(r);
  EXPECT_EQ(bad.status, 400U);
  EXPECT_EQ(json::parse(bad.body)["field"], "grid");
  r.body = "{not json";
  EXPECT_EQ(rig.api.handle(r).status, 400U);
  r.body = "[1,2]";
  EXPECT_EQ(rig.api.handle(r).status, 400U);
  r.method = "POST";  // config changes are PUT
  r.body = "{}";
  EXPECT_EQ(rig.api.handle(r).status, 405U);
}

TEST(WebApi, ForeignHostNamesAreRefusedAgainstDnsRebinding) {
  Rig rig;
  WebRequest r = Rig::request("GET", "/api/state");
  r.host = "attacker.example:8080";
  EXPECT_EQ(rig.api.handle(r).status, 403U);
  r.host = "shack.local:8080";  // configured in allowed_hosts
  EXPECT_EQ(rig.api.handle(r).status, 200U);
  r.host = "[::1]:8080";
  EXPECT_EQ(rig.api.handle(r).status, 200U);
  r.host = "localhost";
  EXPECT_EQ(rig.api.handle(r).status, 200U);
}

TEST(WebApi, WebSocketUpgradeChecksOriginAndHost) {
  Rig rig;
  WebRequest r = Rig::request("GET", "/ws");
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
  WebRequest r = Rig::request("POST", "/api/stop");
  r.cookie = cookie;
  r.csrf = csrf;
  EXPECT_EQ(rig.api.handle(r).status, 200U);
  WebRequest out = r;
  out.path = "/api/logout";
  EXPECT_EQ(rig.api.handle(out).status, 200U);
  EXPECT_EQ(rig.api.handle(r).status, 401U);
  std::tie(cookie, csrf) = rig.login();
  r.cookie = cookie;
  r.csrf = csrf;
  rig.now_s += 8 * 24 * 3600.0;  // past the 7-day lifetime
  EXPECT_EQ(rig.api.handle(r).status, 401U);
}

TEST(WebApi, CookieValuesAreFoundAmongOthers) {
  EXPECT_EQ(cookie_value("a=1; azt_session=xyz; b=2", "azt_session"), "xyz");
  EXPECT_EQ(cookie_value("azt_session_old=1", "azt_session"), "");
  EXPECT_EQ(cookie_value("", "azt_session"), "");
}

}  // namespace
}  // namespace azt::app
