# Area "sph": the SPH simulator (CPU and GPU paths, boundaries, time step, scenes).
fs_add_test(test_sph fs_sph test_sph.c)
set_tests_properties(test_sph PROPERTIES TIMEOUT 120)
fs_add_test(test_sph_obstacles fs_sph test_sph_obstacles.c)
set_tests_properties(test_sph_obstacles PROPERTIES TIMEOUT 120)
# fluidsurf simulate: bad input (exit 2, one line, no file) and short CPU/GPU runs
# (it writes and reads .vtk sequences: builds with VTK).
if(FS_WITH_VTK)
  add_test(NAME cli_simulate COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli_simulate.sh $<TARGET_FILE:fluidsurf>
           ${CMAKE_BINARY_DIR}/test-out/cli_simulate)
  set_tests_properties(cli_simulate PROPERTIES TIMEOUT 120
    ENVIRONMENT "${FS_TEST_ENV}")
endif()
