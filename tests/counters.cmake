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
# Under the sanitizers, part 1 (the same counts on both contexts and thread counts) for
# spheres alone: the CLI's counting path is the same for every method, every method's
# counting render runs under them in test_counters_render, and the equality of the counts
# (a determinism check, not a memory one) for every method is the normal build's (its
# whole test took 181 s of the sanitizer ctest in the CI run at 1173adb, issue 51).
if(FS_SANITIZE)
  list(APPEND _counters_env "METHODS=spheres")
endif()
set_tests_properties(cli_counters PROPERTIES ENVIRONMENT "${_counters_env}")
