#include "options.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <string_view>

namespace rotctld_load {
namespace {

constexpr int kMaxClients = 4096;
constexpr int kMaxIdle = 16384;
constexpr double kMaxSeconds = 3600.0;

bool parse_int(std::string_view text, int lo, int hi, int& out) {
  int value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc{} || end != text.data() + text.size() || value < lo || value > hi) {
    return false;
  }
  out = value;
  return true;
}

bool parse_seconds(std::string_view text, double lo, double& out) {
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc{} || end != text.data() + text.size() || !std::isfinite(value) ||
      value < lo || value > kMaxSeconds) {
    return false;
  }
  out = value;
  return true;
}

// Applies one "--name value" pair; false when the name is unknown or the value out of range.
bool apply_option(Options& o, std::string_view name, std::string_view value) {
  int port = 0;
  if (name == "--host") {
    o.host = value;
  } else if (name == "--port") {
    if (!parse_int(value, 1, 65535, port)) return false;
    o.port = value;
  } else if (name == "--label") {
    o.label = value;
    std::replace(o.label.begin(), o.label.end(), '|', '/');  // keep the Markdown row parseable
  } else if (name == "--clients") {
    return parse_int(value, 0, kMaxClients, o.clients);
  } else if (name == "--idle") {
    return parse_int(value, 0, kMaxIdle, o.idle);
  } else if (name == "--timeout-ms") {
    return parse_int(value, 10, 600000, o.timeout_ms);
  } else if (name == "--seconds") {
    return parse_seconds(value, 0.1, o.seconds);
  } else if (name == "--warmup") {
    return parse_seconds(value, 0.0, o.warmup_s);
  } else {
    return false;
  }
  return true;
}

}  // namespace

void print_usage(FILE* out) {
  std::fprintf(out,
               "usage: rotctld_load --port N [--host 127.0.0.1] [--clients C] [--seconds S]\n"
               "                    [--warmup 1] [--label NAME] [--idle K] [--timeout-ms 2000]\n"
               "                    [--json] [--header] [--burst]\n");
}

std::optional<Options> parse_options(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "--json") {
      o.json = true;
    } else if (arg == "--header") {
      o.header = true;
    } else if (arg == "--burst") {
      o.burst = true;
    } else if (arg == "--help" || arg == "-h") {
      print_usage(stdout);
      std::exit(0);
    } else if (i + 1 >= argc || !apply_option(o, arg, argv[i + 1])) {
      std::fprintf(stderr, "rotctld_load: bad or incomplete option '%s'\n", argv[i]);
      return std::nullopt;
    } else {
      ++i;
    }
  }
  if (o.port.empty()) {
    std::fprintf(stderr, "rotctld_load: --port is required\n");
    return std::nullopt;
  }
  return o;
}

}  // namespace rotctld_load
