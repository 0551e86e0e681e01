# Area "counters": the work counters (docs/DESIGN.md, "Work counters"): the core
# table and its overflow errors; every method's counting render against its
# timed render (same G-buffer, plausible counts), the GL counters' 64-bit carry
# and overflow, the refusal of a method without counters; the CLI across
# contexts and thread counts, and the counts in the reference cache.
fs_add_test(test_counters fs_core test_counters.c)
fs_add_test(test_counters_render fs_test_methods test_counters_render.c test_render.c)
add_test(NAME cli_counters COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli_counters.sh $<TARGET_FILE:fluidsurf>
         ${CMAKE_SOURCE_DIR} ${CMAKE_BINARY_DIR}/test-out/cli_counters)
set(_counters_env "${FS_TEST_ENV}")
if(NOT FS_WITH_OSMESA)
  list(APPEND _counters_env "FS_NO_OSMESA=1")
endif()
set_tests_properties(cli_counters PROPERTIES ENVIRONMENT "${_counters_env}")
