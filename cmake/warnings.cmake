# Target-scoped warning flags: call azt_warnings(<target>) on every first-party target.
function(azt_warnings target)
  target_compile_options(${target} PRIVATE
    -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wsign-conversion -Wnon-virtual-dtor
    -Wold-style-cast -Wcast-align -Woverloaded-virtual -Wdouble-promotion
    -Wformat=2 -Wimplicit-fallthrough)
  if(AZT_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
