# Area "api": the C API (include/fluidsurf/fluidsurf.h) as a program links it,
# libfluidsurf.so from this build: fluidsurf_mesh_build (refused without OpenVDB)
# and the library's messages. The installed library: tests/python.cmake.
if(TARGET fluidsurf_lib)
  fs_add_test(test_api fluidsurf_lib test_api.c)
  target_link_libraries(test_api PRIVATE m)
  fs_add_test(test_api_compare fluidsurf_lib test_api_compare.c)
  target_link_libraries(test_api_compare PRIVATE m)
  fs_add_test(test_api_scene fluidsurf_lib test_api_scene.c)
  target_link_libraries(test_api_scene PRIVATE m)
endif()
