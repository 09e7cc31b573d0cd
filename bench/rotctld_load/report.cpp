#include "report.hpp"

#include <cstdio>
#include <string_view>

namespace rotctld_load {
namespace {

std::string json_escape(std::string_view text) {
  std::string out;
  for (const char ch : text) {
    if (ch == '"' || ch == '\\') {
      out += '\\';
      out += ch;
    } else if (static_cast<unsigned char>(ch) < 0x20) {
      out += ' ';
    } else {
      out += ch;
    }
  }
  return out;
}

}  // namespace

void print_summary(const Summary& s, const Options& o) {
  if (o.json) {
    std::printf(
        "{\"label\":\"%s\",\"clients\":%d,\"idle\":%d,\"seconds\":%.3f,\"requests\":%llu,"
        "\"rps\":%.1f,\"p50_us\":%.1f,\"p99_us\":%.1f,\"max_us\":%.1f,\"errors\":%llu}\n",
        json_escape(s.label).c_str(), s.clients, s.idle, s.measured_s,
        static_cast<unsigned long long>(s.requests), s.rps, s.p50_us, s.p99_us, s.max_us,
        static_cast<unsigned long long>(s.errors));
    return;
  }
  if (o.header) {
    std::printf("| server | clients | req/s | p50 µs | p99 µs | max µs | errors |\n");
    std::printf("|---|---:|---:|---:|---:|---:|---:|\n");
  }
  std::printf("| %s | %d | %.0f | %.1f | %.1f | %.1f | %llu |\n", s.label.c_str(), s.clients, s.rps,
              s.p50_us, s.p99_us, s.max_us, static_cast<unsigned long long>(s.errors));
}

}  // namespace rotctld_load
