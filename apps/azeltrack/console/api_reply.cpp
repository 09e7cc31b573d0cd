#include "console/api_reply.hpp"

namespace azt::app {

using json = nlohmann::json;

linux_os::HttpReply json_reply(unsigned status, const json& body) {
  // Replace, never throw: whatever text reached the body (a header echoed in a message, a name
  // from a file), the answer is sent (docs/reliability.md "Hardening" rows 1, 2, 12).
  return linux_os::HttpReply{
      status, "application/json", body.dump(-1, ' ', false, json::error_handler_t::replace), {}};
}

linux_os::HttpReply error_reply(unsigned status, const std::string& message,
                                const std::string& field) {
  json body{{"error", message}};
  if (!field.empty()) body["field"] = field;
  return json_reply(status, body);
}

}  // namespace azt::app
