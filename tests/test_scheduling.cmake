# How ctest shares the machine among the tests (included last by tests/CMakeLists.txt, once every
# test is registered).

# Two cores, shared through ctest's resources (tests/ctest_resources.json: two "cpus" slots;
# scripts/test names it). Every test takes one slot, lint both, except the tests that spend most
# of their time waiting for the daemon's real-time clock (a pass's AOS, a scan's settling, a
# feed's poll, a page's update): they take none, so they run beside two working tests instead of
# holding a core idle. Each below used at most a third of a core over its run (CPU seconds of the
# test and its children against its wall time, measured with /usr/bin/time: browser_console 32 of
# 110 s, browser_calibration 10 of 53, web_api 3.5 of 38, gps 7 of 33, noise_api 1.5 of 31,
# handover 1.7 of 18, time 2.3 of 21). The hardening tests stay working tests: they measure the
# loop's lateness, which a busier machine would blur. Without the file (a plain `ctest -j2`) the
# slots are ignored.
set(azt_waiting_tests schedule_daemon sim_receiver scan calibration_session browser_console
  browser_calibration web_api gps noise_api handover time)
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
