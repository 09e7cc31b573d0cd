#pragma once
// rotctld_load's result: one Markdown table row (with --header, the table's head first) or one
// JSON object (--json).

#include <cstdint>
#include <string>

#include "options.hpp"

namespace rotctld_load {

struct Summary {
  std::string label;
  int clients = 0;
  int idle = 0;
  double measured_s = 0.0;
  std::uint64_t requests = 0;
  double rps = 0.0;
  double p50_us = 0.0;
  double p99_us = 0.0;
  double max_us = 0.0;
  std::uint64_t errors = 0;
};

void print_summary(const Summary& s, const Options& o);

}  // namespace rotctld_load
