# OSMesa, GLFW and EGL together: full builds only (the lean build's EGL runs in
# every GL test there, its refusals of OSMesa and GLFW in tests/cli_lean.sh).
if(NOT (FS_WITH_GLFW AND FS_WITH_OSMESA))
  return()
endif()
# The GLFW window context needs an X server: the test runs under Xvfb (xvfb-run).
find_program(XVFB_RUN xvfb-run)
if(NOT XVFB_RUN)
  message(FATAL_ERROR "xvfb-run not found: the GLFW context test needs it. Run scripts/setup.sh (Debian package xvfb).")
endif()
add_executable(test_context_glfw test_context_glfw.c)
target_link_libraries(test_context_glfw PRIVATE fs_run fs_image fs_methods fs_sph)
target_compile_definitions(test_context_glfw PRIVATE FS_TEST_DATA="${CMAKE_SOURCE_DIR}/experiments/data"
  FS_TEST_OUT="${CMAKE_BINARY_DIR}/test-out")
set(_ctx_lsan "${FS_TEST_ENV}")
# OSMesa, a GLFW window (GLX on Xvfb) and EGL render the same block; OSMesa survives the switches.
add_test(NAME test_context_glfw
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/xvfb.sh 1024x768x24 $<TARGET_FILE:test_context_glfw>)
set_tests_properties(test_context_glfw PROPERTIES TIMEOUT 60 ENVIRONMENT "${_ctx_lsan}")
# No display and no EGL vendor: GLFW and EGL fail with one line each, OSMesa keeps working.
add_test(NAME test_context_failures COMMAND test_context_glfw --expect-failures)
set_tests_properties(test_context_failures PROPERTIES TIMEOUT 60
  ENVIRONMENT "${_ctx_lsan};DISPLAY=;WAYLAND_DISPLAY=;__EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent/egl_vendor.json")
