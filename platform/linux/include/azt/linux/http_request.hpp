#pragma once
// A request as Boost.Beast parsed it, turned into the HttpRequest the console's handlers see:
// every text field made valid UTF-8, so a Latin-1 or binary byte in a header never reaches JSON
// or a log line as it is (docs/reliability.md "Hardening" row 1). The server (web_server.cpp) and
// the request fuzz target (fuzz/web_request_fuzz.cpp) both call this one function.

#include <boost/beast/http/message.hpp>
#include <boost/beast/http/string_body.hpp>

#include <string>

#include "azt/linux/http_server.hpp"

namespace azt::linux_os {

/// The head alone (HttpRequest::body empty): what decides a body's allowance, and a streamed
/// body's request. `peer` is the client's address without the port (HttpRequest::client).
HttpRequest to_http_request(const boost::beast::http::request_header<>& head,
                            const std::string& peer);
/// The head and its body.
HttpRequest to_http_request(const boost::beast::http::request<boost::beast::http::string_body>& req,
                            const std::string& peer);

}  // namespace azt::linux_os
