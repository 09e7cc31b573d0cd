# Target-scoped warning flags: call azt_warnings(<target>) on every first-party target.
function(azt_warnings target)
  target_compile_options(${target} PRIVATE
    -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wsign-conversion -Wnon-virtual-dtor
    -Wold-style-cast -Wcast-align -Woverloaded-virtual -Wdouble-promotion
    -Wformat=2 -Wimplicit-fallthrough)
  # GCC 12 at -O3 reports impossible overlaps in std::string concatenation (GCC bug 105329,
  # fixed in 13): a false positive that would fail the release build under -Werror.
  target_compile_options(${target} PRIVATE
    $<$<AND:$<CXX_COMPILER_ID:GNU>,$<VERSION_LESS:$<CXX_COMPILER_VERSION>,13>>:-Wno-restrict>)
  if(AZT_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
