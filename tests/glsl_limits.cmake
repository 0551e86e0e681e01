# The GL limits' needs (common/gl/gl_limits.c) against what every shader program the
# binary compiles uses, from the sources glsl_validate dumped (tests/gl_limits_needs.py):
# it runs after glsl_validate, where that runs. (This file sorts after glsl.cmake.)
if(TEST glsl_validate)
  set_tests_properties(glsl_validate PROPERTIES FIXTURES_SETUP glsl_dumps)
  add_test(NAME gl_limits_needs COMMAND sh -c "\"$0\" --table > \"$2.tsv\" && python3 \"$1\" \"$2\" \"$2.tsv\""
           $<TARGET_FILE:test_gl_limits> ${CMAKE_CURRENT_SOURCE_DIR}/gl_limits_needs.py
           ${CMAKE_BINARY_DIR}/test-out/glsl_validate/dump)
  set_tests_properties(gl_limits_needs PROPERTIES FIXTURES_REQUIRED glsl_dumps)
endif()
