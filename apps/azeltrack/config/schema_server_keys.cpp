// The schema's server keys: the PC programs' servers, the web console and the log
// (daemon_config.cpp reads them).
#include <array>

#include "config/daemon_config.hpp"
#include "config/schema_keys.hpp"

namespace azt::app {
namespace {

constexpr KeySpec bind(std::string_view help) {
  return {.key = "bind", .type = KeyType::Text, .default_toml = "\"127.0.0.1\"", .help = help};
}

constexpr KeySpec port(std::string_view key, std::string_view default_toml,
                       std::string_view default_note, std::string_view help) {
  return {.key = key,
          .type = KeyType::Integer,
          .range = closed(0.0, 65535.0),
          .default_toml = default_toml,
          .default_note = default_note,
          .help = help};
}

constexpr std::array<KeySpec, 3> kRotctld{{
    bind("the address the Hamlib rotctld server (TCP) listens on; `\"0.0.0.0\"` serves the LAN, "
         "with no authentication in this protocol"),
    port("port", "4533", "", "0 disables; at most 256 clients, 16 from one address"),
    {.key = "idle_timeout_s",
     .type = KeyType::Number,
     .unit = "s",
     .range = closed(0.0, 86400.0),
     .default_toml = "600.0",
     .help = "a client silent this long is disconnected (a dropped Wi-Fi leaves no close); 0 "
             "never, else at least 10"},
}};

constexpr auto kProtocolNames = choice_names(kSerialProtocols);

constexpr std::array<KeySpec, 3> kSerial{{
    {.key = "protocol",
     .type = KeyType::Choice,
     .choices = kProtocolNames,
     .help = "required: the dialect spoken (`spid` is Rot2Prog)"},
    {.key = "device",
     .type = KeyType::Text,
     .help = "required: `\"pty:NAME\"`, a pseudo-terminal linked as NAME in the runtime directory "
             "(`\"pty:/abs/path\"`: at that path), or a serial port (`\"/dev/ttyUSB0\"`), opened "
             "exclusively; each device once"},
    {.key = "baud",
     .type = KeyType::Integer,
     .range = closed(600.0, 115200.0),
     .default_toml = "9600",
     .help = "a serial port takes 600, 1200, 2400, 4800, 9600, 19200, 38400, 57600 or 115200 "
             "(raw 8N1)"},
}};

constexpr std::array<KeySpec, 3> kPstRotator{{
    bind("the address the PstRotator UDP server listens on"),
    port("port", "12000", "", "0 disables"),
    port("reply_port", "", "port + 1",
         "replies go to the sender's host on this port; 0 answers the sender's own port"),
}};

constexpr std::array<KeySpec, 5> kWeb{{
    bind("the address the web console and its API listen on ([web-api.md](web-api.md)); a "
         "non-loopback address needs a password set first"),
    port("port", "8080", "", "0 disables"),
    {.key = "password_hash",
     .type = KeyType::Text,
     .default_note = "generated",
     .help = "Argon2id hash of the console password (`azeltrack web password --config FILE`); "
             "without one, the first start on a loopback address generates a password, prints it "
             "once and saves its hash",
     .access = Access::Secret},
    {.key = "api_token_sha256",
     .type = KeyType::Text,
     .default_note = "none",
     .help = "SHA-256 (64 lower-case hex digits) of the bearer token scripts send (`azeltrack web "
             "token --config FILE` prints a new token once)",
     .access = Access::Secret},
    {.key = "allowed_hosts",
     .type = KeyType::TextList,
     .default_toml = "[]",
     .help = "host names accepted in the Host header besides IP addresses and `localhost` (a "
             "defence against DNS rebinding): add the name you browse to, e.g. "
             "`\"shack-pi.local\"`"},
}};

constexpr std::array<KeySpec, 3> kToken{{
    {.key = "label",
     .type = KeyType::Text,
     .help = "the name the token is listed and revoked by (1 to 40 letters, digits, spaces, `.`, "
             "`_` or `-`), different for each",
     .applies = Applies::Live,
     .access = Access::ReadOnly},
    {.key = "sha256",
     .type = KeyType::Text,
     .help = "SHA-256 (64 lower-case hex digits) of the token; the token itself is kept nowhere",
     .applies = Applies::Live,
     .access = Access::Secret},
    {.key = "created_utc",
     .type = KeyType::Text,
     .default_note = "unknown",
     .help = "when it was made (ISO 8601 UTC)",
     .applies = Applies::Live,
     .access = Access::ReadOnly},
}};

constexpr std::array<std::string_view, 3> kLogLevels{"debug", "info", "warn"};

constexpr std::array<KeySpec, 1> kLog{{
    {.key = "level",
     .type = KeyType::Choice,
     .choices = kLogLevels,
     .default_toml = "\"info\"",
     .help = "the least important messages logged"},
}};

constexpr std::array<SectionSpec, 6> kSections{{
    {.name = "rotctld",
     .chapter = Chapter::Servers,
     .keys = kRotctld,
     .title = "Hamlib's rotctld protocol",
     .help = "Gpredict, `rotctl` and anything that speaks rotctld ([daemon.md](daemon.md))."},
    {.name = "serial",
     .chapter = Chapter::Servers,
     .array_of_tables = true,
     .keys = kSerial,
     .title = "Serial protocol servers",
     .help = "GS-232, EasyComm and SPID on a pseudo-terminal or a serial port, one table each."},
    {.name = "pstrotator",
     .chapter = Chapter::Servers,
     .keys = kPstRotator,
     .title = "PstRotator's UDP protocol"},
    {.name = "web",
     .chapter = Chapter::Servers,
     .keys = kWeb,
     .title = "The web console",
     .help = "Logging in and the API: [web-api.md](web-api.md); from the internet: "
             "[remote.md](remote.md)."},
    {.name = "token",
     .chapter = Chapter::Servers,
     .array_of_tables = true,
     .keys = kToken,
     .title = "API tokens",
     .help =
         "Bearer tokens for scripts and for the touch panel's kiosk, one table each, made and "
         "revoked with `azeltrack web token` or in the console's Settings (`/api/tokens`, "
         "[web-api.md](web-api.md)); the console's apply at once, the command's at the daemon's "
         "next start."},
    {.name = "log", .chapter = Chapter::Servers, .keys = kLog, .title = "The log"},
}};

}  // namespace

std::span<const SectionSpec> server_sections() { return kSections; }

}  // namespace azt::app
