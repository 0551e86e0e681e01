# Area "api": the C API (include/fluidsurf/fluidsurf.h) as a program links it,
# libfluidsurf.so from this build: fluidsurf_mesh_build (refused without OpenVDB)
# and the library's messages; the version-6 calls (test_api_io: metrics as diff,
# an EXR's provenance and camera, writers, info); the version-8 calls (test_api_scene:
# --camera's text, a frame pattern as the source, render --save-scene); that a dlclose
# leaves it (and OpenMP) loaded.
# The installed library: tests/python.cmake.
if(TARGET fluidsurf_lib)
  fs_add_test(test_api fluidsurf_lib test_api.c)
  target_link_libraries(test_api PRIVATE m)
  fs_add_test(test_api_compare fluidsurf_lib test_api_compare.c)
  target_link_libraries(test_api_compare PRIVATE m)
  fs_add_test(test_api_scene fluidsurf_lib test_api_scene.c)
  target_link_libraries(test_api_scene PRIVATE m)
  fs_add_test(test_api_io fluidsurf_lib test_api_io.c)
  target_link_libraries(test_api_io PRIVATE m)
  # dlopen'ed, not linked (an instrumented library cannot be loaded into an uninstrumented program)
  if(NOT FS_SANITIZE)
    add_executable(test_api_unload test_api_unload.c)
    target_include_directories(test_api_unload PRIVATE ${CMAKE_SOURCE_DIR}/include ${CMAKE_CURRENT_SOURCE_DIR})
    target_compile_definitions(test_api_unload PRIVATE FS_LIBRARY_PATH="$<TARGET_FILE:fluidsurf_lib>")
    # libm loaded with the program, as in Python: VTK's libvtkkissfft, which dlopen
    # brings in, resolves its IFUNC sincos from libm (glibc crashes relocating it otherwise)
    target_link_libraries(test_api_unload PRIVATE ${CMAKE_DL_LIBS} -Wl,--no-as-needed m)
    add_dependencies(test_api_unload fluidsurf_lib)
    add_test(NAME test_api_unload COMMAND test_api_unload)
  endif()
endif()
