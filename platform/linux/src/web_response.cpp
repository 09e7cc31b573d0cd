#include "web_connection.hpp"

namespace azt::linux_os::web {

namespace http = boost::beast::http;

http::response<http::string_body> to_response(const HttpReply& reply, unsigned version,
                                              bool keep_alive) {
  http::response<http::string_body> res{static_cast<http::status>(reply.status), version};
  res.set(http::field::server, "azeltrack");
  res.set(http::field::content_type, reply.content_type);
  // The console is self-contained: nothing may frame it, load foreign code, or sniff types.
  res.set(http::field::cache_control, "no-store");
  res.set("X-Content-Type-Options", "nosniff");
  res.set("X-Frame-Options", "DENY");
  res.set("Content-Security-Policy",
          "default-src 'self'; connect-src 'self'; img-src 'self' data:; style-src 'self'; "
          "script-src 'self'; frame-ancestors 'none'; base-uri 'none'; form-action 'self'");
  res.set("Referrer-Policy", "no-referrer");
  for (const auto& [name, value] : reply.headers) res.set(name, value);
  res.body() = reply.body;
  res.keep_alive(keep_alive);
  res.prepare_payload();
  return res;
}

HttpReply plain_error(unsigned status, const std::string& message) {
  return HttpReply{status, "application/json", "{\"error\":\"" + message + "\"}", {}};
}

}  // namespace azt::linux_os::web
