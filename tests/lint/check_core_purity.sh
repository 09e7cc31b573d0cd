#!/usr/bin/env bash
# Fails if the portable core includes anything that ties it to an OS, a clock, threads, Boost or a
# logger (docs/architecture.md: azt_core may use the C++ standard library and ERFA only). The Swiss
# Ephemeris adapter is the one allowed outside library, behind the Ephemeris interface.
set -euo pipefail
core=${1:?usage: check_core_purity.sh CORE_DIR}
forbidden='#[[:space:]]*include[[:space:]]*[<"](unistd\.h|fcntl\.h|termios\.h|pthread\.h|sys/[^>"]*|linux/[^>"]*|windows\.h|thread|mutex|condition_variable|future|atomic|chrono|ctime|time\.h|fstream|filesystem|cstdio|stdio\.h|iostream|random|boost/[^>"]*|spdlog/[^>"]*|fmt/[^>"]*|gpiod[^>"]*|asio[^>"]*)[>"]'
calls='(std::chrono|system_clock|steady_clock|std::thread|std::getenv|getenv\(|fopen\(|std::time\(|[^_a-z]time\(nullptr\)|printf\(|std::cout|std::cerr)'
status=0
if grep -rEn "$forbidden" "$core"; then
  echo "core_purity: forbidden include in core/ (see above)" >&2; status=1
fi
if grep -rEn --include='*.cpp' --include='*.hpp' "$calls" "$core"; then
  echo "core_purity: OS, clock or console call in core/ (see above)" >&2; status=1
fi
files=$(find "$core" -name '*.cpp' -o -name '*.hpp' | wc -l)
if [ "$files" -lt 5 ]; then
  echo "core_purity: only $files source files found under $core: wrong directory?" >&2; status=1
fi
[ $status -eq 0 ] && echo "core_purity: $files files clean"
exit $status
