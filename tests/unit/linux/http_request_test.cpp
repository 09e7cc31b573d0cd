// A request a reverse proxy passed on is marked as such, whatever its spelling of the header
// (docs/reliability.md "Hardening, round three" row 3: a STOP through nginx on the Pi had counted
// as one from this machine).
#include "azt/linux/http_request.hpp"

#include <gtest/gtest.h>

#include <string>

namespace azt::linux_os {
namespace {

namespace http = boost::beast::http;

HttpRequest with_header(const std::string& name, const std::string& value) {
  http::request<http::string_body> req{http::verb::post, "/api/stop", 11};
  req.set(http::field::host, "localhost:8080");
  if (!name.empty()) req.set(name, value);
  return to_http_request(req, "127.0.0.1");
}

TEST(HttpRequestForwarded, EveryProxyHeaderMarksTheRequest) {
  for (const std::string name : {"Forwarded", "X-Forwarded-For", "x-forwarded-for",
                                 "X-Forwarded-Host", "X-Forwarded-Proto", "X-Real-IP", "Via"}) {
    const HttpRequest r = with_header(name, "203.0.113.7");
    EXPECT_TRUE(r.forwarded) << name;
    EXPECT_EQ(r.client, "127.0.0.1");
  }
}

TEST(HttpRequestForwarded, ARequestWithoutOneIsNot) {
  EXPECT_FALSE(with_header("", "").forwarded);
  EXPECT_FALSE(with_header("X-Requested-With", "XMLHttpRequest").forwarded);
}

}  // namespace
}  // namespace azt::linux_os
