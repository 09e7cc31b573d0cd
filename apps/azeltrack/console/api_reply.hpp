#pragma once
// The console API's answers as JSON: every reply and refusal of WebApi and of the handlers it
// hands a request to (a package upload's sink) looks the same to the browser.

#include <string>

#include <nlohmann/json.hpp>

#include "azt/linux/http_server.hpp"

namespace azt::app {

/// `body` as the reply; text that is not valid UTF-8 is replaced, never thrown on.
linux_os::HttpReply json_reply(unsigned status, const nlohmann::json& body);
/// {"error": message, "field": field} ("field" only when given).
linux_os::HttpReply error_reply(unsigned status, const std::string& message,
                                const std::string& field = "");

}  // namespace azt::app
