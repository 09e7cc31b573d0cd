# The fuzz targets replayed with gcc on their seed corpora (fuzz/corpus/<target>/, which also
# hold the inputs that found bugs), in the main build: the libFuzzer builds themselves are the fuzz
# preset, which scripts/test runs briefly after this suite. Included by tests/CMakeLists.txt.

# The fuzz target's invariants replayed on a small corpus with any compiler (the gcc build); the
# libFuzzer build itself is the fuzz preset, which scripts/test runs briefly after this suite.
add_executable(hub_decoder_replay ${PROJECT_SOURCE_DIR}/fuzz/hub_decoder_fuzz.cpp)
target_compile_definitions(hub_decoder_replay PRIVATE AZT_FUZZ_STANDALONE)
target_link_libraries(hub_decoder_replay PRIVATE azt_core)
azt_warnings(hub_decoder_replay)
add_test(NAME hub_fuzz_replay COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/fuzz_smoke.sh $<TARGET_FILE:hub_decoder_replay>)
set_tests_properties(hub_fuzz_replay PROPERTIES LABELS fuzz)

# The protocol fuzz targets (fuzz/*_session_fuzz.cpp, fuzz/pstrotator_fuzz.cpp, the WSJT-X
# decoder's wsjtx_message_fuzz.cpp, the scan log's scan_log_csv_fuzz.cpp) replayed with gcc on
# their seed corpora, fuzz/corpus/<target>/, which also hold the inputs that found bugs.
foreach(fuzz_target rotctld_session_fuzz gs232_session_fuzz easycomm_session_fuzz
        spid_session_fuzz pstrotator_fuzz power_parsers_fuzz wsjtx_message_fuzz scan_log_csv_fuzz)
  string(REPLACE "_fuzz" "_replay" replay ${fuzz_target})
  add_executable(${replay} ${PROJECT_SOURCE_DIR}/fuzz/${fuzz_target}.cpp)
  target_compile_definitions(${replay} PRIVATE AZT_FUZZ_STANDALONE)
  target_link_libraries(${replay} PRIVATE azt_core)
  azt_warnings(${replay})
  add_test(NAME ${replay}
    COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/fuzz_run.sh $<TARGET_FILE:${replay}> 1 1
            ${PROJECT_SOURCE_DIR}/fuzz/corpus/${fuzz_target})
  set_tests_properties(${replay} PROPERTIES LABELS fuzz)
endforeach()

# The configuration loader's fuzz target, replayed the same way (it needs the program's sources).
add_executable(config_replay ${PROJECT_SOURCE_DIR}/fuzz/config_fuzz.cpp)
target_compile_definitions(config_replay PRIVATE AZT_FUZZ_STANDALONE)
target_link_libraries(config_replay PRIVATE azt_app)
azt_warnings(config_replay)
add_test(NAME config_replay
  COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/fuzz_run.sh $<TARGET_FILE:config_replay> 1 1
          ${PROJECT_SOURCE_DIR}/fuzz/corpus/config_fuzz)
set_tests_properties(config_replay PROPERTIES LABELS fuzz)

# The element sets' fuzz target (readers, screening, merge, cache), replayed the same way.
add_executable(element_sets_replay ${PROJECT_SOURCE_DIR}/fuzz/element_sets_fuzz.cpp)
target_compile_definitions(element_sets_replay PRIVATE AZT_FUZZ_STANDALONE)
target_link_libraries(element_sets_replay PRIVATE azt_app)
azt_warnings(element_sets_replay)
add_test(NAME element_sets_replay
  COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/fuzz_run.sh $<TARGET_FILE:element_sets_replay> 1 1
          ${PROJECT_SOURCE_DIR}/fuzz/corpus/element_sets_fuzz)
set_tests_properties(element_sets_replay PROPERTIES LABELS fuzz)
