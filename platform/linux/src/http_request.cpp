#include "azt/linux/http_request.hpp"

#include <boost/beast/http/field.hpp>
#include <boost/beast/websocket/rfc6455.hpp>

#include <string_view>

#include "azt/util/valid_utf8.hpp"

namespace azt::linux_os {

namespace http = boost::beast::http;

namespace {

/// Beast's string_view is Boost's; the sanitizer takes the standard one.
std::string clean(boost::beast::string_view text) {
  return valid_utf8(std::string_view(text.data(), text.size()));
}

/// A header's value as valid UTF-8 ("" when absent): a Latin-1 or binary byte in a header must
/// never reach JSON or a log line as it is (docs/reliability.md "Hardening" row 1).
std::string header(const http::request_header<>& req, http::field f) {
  const auto it = req.find(f);
  return it == req.end() ? std::string() : clean(it->value());
}

/// Any header a reverse proxy (nginx, Caddy, Apache) adds on the way: RFC 7239's Forwarded,
/// the de-facto X-Forwarded-For/-Host/-Proto, nginx's X-Real-IP, and Via (RFC 9110 §7.6.3).
bool forwarded(const http::request_header<>& req) {
  for (const char* name :
       {"Forwarded", "X-Forwarded-For", "X-Forwarded-Host", "X-Forwarded-Proto", "X-Real-IP"}) {
    if (req.find(name) != req.end()) return true;
  }
  return req.find(http::field::via) != req.end();
}

}  // namespace

HttpRequest to_http_request(const http::request_header<>& req, const std::string& peer) {
  HttpRequest r;
  r.method = clean(req.method_string());
  const std::string target = clean(req.target());  // "/\xff" is a 404, not a crash
  const auto q = target.find('?');
  r.path = target.substr(0, q);
  if (q != std::string::npos) r.query = target.substr(q + 1);
  r.origin = header(req, http::field::origin);
  r.host = header(req, http::field::host);
  r.cookie = header(req, http::field::cookie);
  r.authorization = header(req, http::field::authorization);
  if (const auto it = req.find("X-CSRF-Token"); it != req.end()) r.csrf = clean(it->value());
  r.client = peer;
  r.websocket = boost::beast::websocket::is_upgrade(req);
  r.forwarded = forwarded(req);
  return r;
}

HttpRequest to_http_request(const http::request<http::string_body>& req, const std::string& peer) {
  HttpRequest r = to_http_request(static_cast<const http::request_header<>&>(req), peer);
  r.body = req.body();
  return r;
}

}  // namespace azt::linux_os
