# Every shader program the binary compiles, as it hands it to the driver, accepted by the
# Khronos reference compiler (glslangValidator, Debian glslang-tools): tests/glsl_validate.sh.
# In the normal build (OSMesa; the viewer's programs under Xvfb), not under the sanitizers.
if(FS_WITH_OSMESA AND NOT FS_SANITIZE)
  find_program(GLSLANG_VALIDATOR glslangValidator)
  if(NOT GLSLANG_VALIDATOR)
    message(FATAL_ERROR "glslangValidator not found: the GLSL test needs it. Run scripts/setup.sh (Debian package glslang-tools).")
  endif()
  set(_view "")
  if(FS_WITH_GLFW)
    set(_view view)
  endif()
  add_test(NAME glsl_validate COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/glsl_validate.sh ${CMAKE_SOURCE_DIR}
           $<TARGET_FILE:fluidsurf> ${CMAKE_BINARY_DIR}/test-out/glsl_validate ${_view})
  set_tests_properties(glsl_validate PROPERTIES TIMEOUT 600 ENVIRONMENT "${FS_TEST_ENV}")
endif()
