fs_add_test(test_orbit_camera fs_scene test_orbit_camera.c)
# fluidsurf view: a GLFW window under Xvfb driven by scripted input (tests/view.sh).
if(NOT FS_WITH_GLFW) # the lean build refuses view (tests/cli_lean.sh)
  return()
endif()
find_program(XVFB_RUN xvfb-run)
if(NOT XVFB_RUN)
  message(FATAL_ERROR "xvfb-run not found: the viewer test needs it. Run scripts/setup.sh (Debian package xvfb).")
endif()
add_test(NAME cli_view COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/xvfb.sh 1024x768x24
         bash ${CMAKE_CURRENT_SOURCE_DIR}/view.sh $<TARGET_FILE:fluidsurf> ${CMAKE_SOURCE_DIR} ${CMAKE_BINARY_DIR}/test-out/view)
set_tests_properties(cli_view PROPERTIES TIMEOUT 180
  ENVIRONMENT "${FS_TEST_ENV}")
# Every registered method shows the fluid in both viewer modes (tests/view_methods.sh;
# 19 viewer runs, ~40 s wall on 2 shared cores in a release build: the timeout leaves room
# for the sanitizer build).
find_program(PYTHON3 python3)
if(NOT PYTHON3)
  message(FATAL_ERROR "python3 not found: tests/view_methods.sh reads its screenshots with it. Run scripts/setup.sh.")
endif()
# Under the sanitizers only the playing scene (each method takes a new particle set every
# frame): a still scene renders through each method's code that the method tests run under
# them too, and the simulator and the viewer's own code run in cli_view; the normal build
# runs all three modes (the 22 viewer runs took 104 s in the CI run at 1173adb, issue 51).
set(_modes "sequence still simulate")
if(FS_SANITIZE)
  set(_modes "sequence")
endif()
add_test(NAME cli_view_methods COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/xvfb.sh 1024x768x24
         env PYTHON3=${PYTHON3} "VIEW_MODES=${_modes}" bash ${CMAKE_CURRENT_SOURCE_DIR}/view_methods.sh
         $<TARGET_FILE:fluidsurf> ${CMAKE_SOURCE_DIR} ${CMAKE_BINARY_DIR}/test-out/view_methods)
set_tests_properties(cli_view_methods PROPERTIES TIMEOUT 300 SKIP_RETURN_CODE 77 # a skipped case
  ENVIRONMENT "${FS_TEST_ENV}")
