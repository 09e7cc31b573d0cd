# The browser tests (included by tests/CMakeLists.txt, in its scope): the console's pages and the
# touch panel in Debian's Chromium against a real daemon.
# The web console in Debian's Chromium (playwright-core from tests/browser/package.json, which
# scripts/test installs), against a real daemon; screenshots in build/browser-shots/.
add_test(NAME browser_console
  COMMAND node ${CMAKE_CURRENT_LIST_DIR}/console_test.js $<TARGET_FILE:azeltrack>
          ${PROJECT_BINARY_DIR}/browser-shots)
set_tests_properties(browser_console PROPERTIES LABELS browser TIMEOUT 300)
# The Settings and Login pages: every section's form from the schema, saved and applied or
# waiting for the Restart button, refusals beside their field, the file exported and imported,
# the password and the API tokens; screenshots at 1280×800 and 390×844.
add_test(NAME browser_settings
  COMMAND node ${CMAKE_CURRENT_LIST_DIR}/settings_test.js $<TARGET_FILE:azeltrack>
          ${PROJECT_BINARY_DIR}/browser-shots)
set_tests_properties(browser_settings PROPERTIES LABELS browser TIMEOUT 300)
# The 480×320 touch panel (/panel, docs/panel.md) in the same Chromium with touch: every screen
# fits without scrolling, 44 px controls, STOP everywhere, the login keyboard; screenshots in
# build/panel-shots/.
add_test(NAME browser_panel
  COMMAND node ${CMAKE_CURRENT_LIST_DIR}/panel_test.js $<TARGET_FILE:azeltrack>
          ${PROJECT_BINARY_DIR}/panel-shots)
set_tests_properties(browser_panel PROPERTIES LABELS browser TIMEOUT 180)
# The console's Software page (the AnTrack-Pro manual's "Software Updating") in the same Chromium,
# against a daemon started with --update-inbox/--update-status; the test plays the root update
# helper (it takes request.deb and writes the status file); screenshots in build/software-shots/.
add_test(NAME browser_software
  COMMAND node ${CMAKE_CURRENT_LIST_DIR}/software_test.js $<TARGET_FILE:azeltrack>
          ${PROJECT_BINARY_DIR}/software-shots)
set_tests_properties(browser_software PROPERTIES LABELS browser TIMEOUT 180)
# The console's Radio page against a daemon that keeps Hamlib's dummy rig (`rigctld -m 1`) on a
# tracked satellite's frequencies: the page shows what `rigctl` reads back, WSJT-X as heard, the
# link's failure and, with `[radio] doppler = "off"`, why azeltrack writes nothing; skipped (77)
# without Hamlib's programs; screenshots in build/radio-shots/.
add_test(NAME browser_radio
  COMMAND node ${CMAKE_CURRENT_LIST_DIR}/radio_page_test.js $<TARGET_FILE:azeltrack>
          ${PROJECT_BINARY_DIR}/radio-shots)
set_tests_properties(browser_radio PROPERTIES LABELS browser TIMEOUT 60 SKIP_RETURN_CODE 77)
# The console's Schedule page against a daemon that follows a [[schedule]] of satellites whose
# elements are from now: the timeline as GET /api/schedule plans it, Resume after another command
# held the schedule, the priority list edited and saved (POST /api/schedule), a refusal beside its
# row; screenshots in build/schedule-shots/.
add_test(NAME browser_schedule
  COMMAND node ${CMAKE_CURRENT_LIST_DIR}/schedule_page_test.js $<TARGET_FILE:azeltrack>
          ${PROJECT_BINARY_DIR}/schedule-shots)
set_tests_properties(browser_schedule PROPERTIES LABELS browser TIMEOUT 60)
# The console's Calibration page against a daemon on the simulated receiver with the Sun high: a
# Sun noise measurement from the form, shown with its pairs and the expected value and logged; a
# recording started, stopped, listed and downloaded; screenshots in build/calibration-shots/.
add_test(NAME browser_calibration
  COMMAND node ${CMAKE_CURRENT_LIST_DIR}/calibration_page_test.js $<TARGET_FILE:azeltrack>
          ${PROJECT_BINARY_DIR}/calibration-shots)
set_tests_properties(browser_calibration PROPERTIES LABELS browser TIMEOUT 180)
# The main screen's cards for the antennas people have (docs/web-api.md): the polarisation card with
# [mount.pol] (the mode set and followed, a refusal's words), the beam line of a fixed-elevation
# array, the direction test offering the station's own axes only, each on a daemon restarted on its
# own file; the Drives card on `antenna.axes` the test adds to the state messages, its Home posted to
# the daemon; screenshots in build/antennas-shots/.
add_test(NAME browser_antennas
  COMMAND node ${CMAKE_CURRENT_LIST_DIR}/antennas_test.js $<TARGET_FILE:azeltrack>
          ${PROJECT_BINARY_DIR}/antennas-shots)
set_tests_properties(browser_antennas PROPERTIES LABELS browser TIMEOUT 300)
