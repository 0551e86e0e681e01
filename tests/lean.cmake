# Builds without some optional library (scripts/build_lean.sh turns all five off):
# tests/cli_lean.sh renders every method on the default context (EGL when OSMesa is
# left out), runs compare and diff, and checks each left-out library's refusal.
set(_off "")
foreach(_opt VTK OPENVDB OIIO GLFW OSMESA)
  if(NOT FS_WITH_${_opt})
    list(APPEND _off ${_opt})
  endif()
endforeach()
if(NOT _off)
  return()
endif()
string(REPLACE ";" " " _off "${_off}")
add_test(NAME cli_lean COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli_lean.sh $<TARGET_FILE:fluidsurf>
         ${CMAKE_SOURCE_DIR} ${CMAKE_BINARY_DIR}/test-out/cli_lean "${_off}")
set_tests_properties(cli_lean PROPERTIES TIMEOUT 300 ENVIRONMENT "${FS_TEST_ENV}")
# The lean build proper: what the binary links (scripts/check_lean.sh), and a
# packed copy (scripts/pack_lean.sh) that runs with its own libraries only.
if(_off STREQUAL "VTK OPENVDB OIIO GLFW OSMESA")
  add_test(NAME lean_ldd COMMAND bash ${CMAKE_SOURCE_DIR}/scripts/check_lean.sh $<TARGET_FILE:fluidsurf>)
  add_test(NAME lean_pack COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/lean_pack.sh ${CMAKE_SOURCE_DIR} ${CMAKE_BINARY_DIR}
           ${CMAKE_BINARY_DIR}/test-out/lean_pack)
  set_tests_properties(lean_pack PROPERTIES TIMEOUT 120 ENVIRONMENT "${FS_TEST_ENV}")
endif()
