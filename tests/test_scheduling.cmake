# How ctest shares the machine among the tests (included last by tests/CMakeLists.txt, once every
# test is registered).

# Two cores, shared through ctest's resources (tests/ctest_resources.json: two "cpus" slots;
# scripts/test names it). Every test takes one slot, lint both, except the tests that spend their
# minutes waiting for the daemon's real-time clock (a pass's AOS, a scan's settling): they take
# none, so they run beside two working tests instead of holding a core idle. Without the file
# (a plain `ctest -j2`) the slots are ignored.
set(azt_waiting_tests schedule_daemon sim_receiver scan calibration_session)
get_property(azt_registered_tests DIRECTORY PROPERTY TESTS)
foreach(azt_test IN LISTS azt_registered_tests)
  if(NOT azt_test IN_LIST azt_waiting_tests)
    set_tests_properties(${azt_test} PROPERTIES RESOURCE_GROUPS cpus:1)
  endif()
endforeach()
set_tests_properties(lint PROPERTIES RESOURCE_GROUPS cpus:2)

# The longest tests start first (ctest runs the highest COST first when it has no timings of an
# earlier run, as in a fresh clone), so that two at a time they end together rather than one
# long test running alone at the end. Seconds each took on the 2-core machine.
set_tests_properties(lint PROPERTIES COST 600)
set_tests_properties(schedule_daemon PROPERTIES COST 300)
set_tests_properties(sim_receiver PROPERTIES COST 140)
set_tests_properties(scan PROPERTIES COST 125)
set_tests_properties(calibration_session PROPERTIES COST 140)
set_tests_properties(browser_console PROPERTIES COST 100)
set_tests_properties(browser_calibration PROPERTIES COST 60)
set_tests_properties(daemon_clients PROPERTIES COST 55)
set_tests_properties(moon_windows_oracle PROPERTIES COST 53)
set_tests_properties(recording PROPERTIES COST 20)
