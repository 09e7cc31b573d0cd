#pragma once
// rotctld_load's command line (bench/rotctld_load/rotctld_load.cpp has the usage).

#include <cstdio>
#include <optional>
#include <string>

namespace rotctld_load {

struct Options {
  std::string host = "127.0.0.1";
  std::string port;
  int clients = 1;
  double seconds = 5.0;
  double warmup_s = 1.0;
  std::string label = "server";
  int idle = 0;
  int timeout_ms = 2000;
  bool json = false;
  bool header = false;
  bool burst = false;  // open every connection at once instead of one handshake at a time
};

void print_usage(FILE* out);

/// The options, or nullopt after printing why to stderr; --help prints the usage and exits.
std::optional<Options> parse_options(int argc, char** argv);

}  // namespace rotctld_load
