# fluidsurf view: a GLFW window under Xvfb driven by scripted input (tests/view.sh).
find_program(XVFB_RUN xvfb-run)
if(NOT XVFB_RUN)
  message(FATAL_ERROR "xvfb-run not found: the viewer test needs it. Run scripts/setup.sh (Debian package xvfb).")
endif()
add_test(NAME cli_view COMMAND ${XVFB_RUN} -a -s "-screen 0 1024x768x24"
         bash ${CMAKE_CURRENT_SOURCE_DIR}/view.sh $<TARGET_FILE:fluidsurf> ${CMAKE_SOURCE_DIR} ${CMAKE_BINARY_DIR}/test-out/view)
set_tests_properties(cli_view PROPERTIES TIMEOUT 180
  ENVIRONMENT "LSAN_OPTIONS=suppressions=${CMAKE_SOURCE_DIR}/tests/lsan.supp:print_suppressions=0")
fs_add_test(test_orbit_camera fs_scene test_orbit_camera.c)
