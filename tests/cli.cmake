# Command-line behaviour: bad input gives exit 2, one line "fluidsurf: ...", no output.
# Both use the bundled .vtk files: builds with VTK (the lean build: tests/cli_lean.sh).
if(FS_WITH_VTK)
  add_test(NAME cli_bad_input COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli_bad_input.sh $<TARGET_FILE:fluidsurf>
           ${CMAKE_SOURCE_DIR}/experiments/data/splashsurf ${CMAKE_BINARY_DIR}/test-out/cli_bad)
  add_test(NAME cli_render COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli_render.sh $<TARGET_FILE:fluidsurf>
           ${CMAKE_SOURCE_DIR} ${CMAKE_BINARY_DIR}/test-out/cli_render)
  set_tests_properties(cli_bad_input cli_render PROPERTIES
    ENVIRONMENT "${FS_TEST_ENV}")
endif()
add_test(NAME cli_compare COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli_compare.sh $<TARGET_FILE:fluidsurf>
         ${CMAKE_SOURCE_DIR} ${CMAKE_BINARY_DIR}/test-out/cli_compare)
set_tests_properties(cli_compare PROPERTIES
  ENVIRONMENT "${FS_TEST_ENV}")
# diff: text and JSON, -o heatmaps, EXRs of another size or camera refused, another scene or r
# a warning (--strict: refused), empty depth that OpenImageIO's idiff reads as finite.
add_test(NAME cli_diff COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli_diff.sh $<TARGET_FILE:fluidsurf>
         ${CMAKE_BINARY_DIR}/test-out/cli_diff)
set_tests_properties(cli_diff PROPERTIES ENVIRONMENT "${FS_TEST_ENV}")
# compare --shard K/N and merge: shards merged equal one process, bad shard sets refused.
add_test(NAME cli_shard COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli_shard.sh $<TARGET_FILE:fluidsurf>
         ${CMAKE_SOURCE_DIR} ${CMAKE_BINARY_DIR}/test-out/cli_shard)
set_tests_properties(cli_shard PROPERTIES ENVIRONMENT "${FS_TEST_ENV}")
# The reference cache of compare and render: hits, misses, corrupt entries, unusable folders.
add_test(NAME cli_cache COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli_cache.sh $<TARGET_FILE:fluidsurf>
         ${CMAKE_SOURCE_DIR} ${CMAKE_BINARY_DIR}/test-out/cli_cache)
set_tests_properties(cli_cache PROPERTIES ENVIRONMENT "${FS_TEST_ENV}")
# Every command's --help comes from its option table and lists all its options; unknown options exit 2, one line.
add_test(NAME cli_help COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli_help.sh $<TARGET_FILE:fluidsurf>
         ${CMAKE_BINARY_DIR}/test-out/cli_help)
set(_help_env "${FS_TEST_ENV}")
if(NOT FS_WITH_GLFW)
  list(APPEND _help_env "FS_NO_VIEW=1")
endif()
set_tests_properties(cli_help PROPERTIES
  ENVIRONMENT "${_help_env}")
# experiments/gpu/run.sh --quick through EGL: the prepared GPU script works end to end
# (not under the sanitizers, which only slow llvmpipe down).
if(NOT FS_SANITIZE)
  add_test(NAME gpu_quick COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/gpu_quick.sh ${CMAKE_SOURCE_DIR}
           ${CMAKE_BINARY_DIR} ${CMAKE_BINARY_DIR}/test-out/gpu_quick)
  set_tests_properties(gpu_quick PROPERTIES ENVIRONMENT "${FS_TEST_ENV}")
endif()
# Start-up: commands without a GL context or text load neither OpenImageIO nor OSMesa/LLVM.
add_test(NAME cli_startup COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli_startup.sh $<TARGET_FILE:fluidsurf>
         ${CMAKE_SOURCE_DIR} ${CMAKE_BINARY_DIR}/test-out/cli_startup $<BOOL:${FS_WITH_OSMESA}>)
set_tests_properties(cli_startup PROPERTIES ENVIRONMENT "${FS_TEST_ENV}")
# The OpenImageIO module: loaded only for text and tiled or deep EXRs (never for PNG/EXR renders), found in an installed tree.
if(FS_WITH_OIIO)
  add_test(NAME cli_plugin COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli_plugin.sh $<TARGET_FILE:fluidsurf>
           ${CMAKE_SOURCE_DIR} ${CMAKE_BINARY_DIR} ${CMAKE_BINARY_DIR}/test-out/cli_plugin)
  set_tests_properties(cli_plugin PROPERTIES ENVIRONMENT "${FS_TEST_ENV}")
endif()
# Interrupted, resumed and starved runs: SIGINT/SIGTERM, compare --resume, progress on a
# terminal (script) and off it, a full tmpfs (mounted when run as root), device nodes.
# Its progress case meshes (OpenVDB).
if(FS_WITH_OPENVDB)
  add_test(NAME cli_interrupt COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli_interrupt.sh $<TARGET_FILE:fluidsurf>
           ${CMAKE_SOURCE_DIR} ${CMAKE_BINARY_DIR}/test-out/cli_interrupt)
  set_tests_properties(cli_interrupt PROPERTIES ENVIRONMENT "${FS_TEST_ENV}")
endif()
# A real one-node Slurm cluster (slurm-wlm, munge): submit.sh's array and merge job,
# a cancelled and a failed task, --resume. Once per CI, in the normal build.
if(NOT FS_SANITIZE AND FS_WITH_OSMESA)
  add_test(NAME slurm_cluster COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/slurm_cluster.sh $<TARGET_FILE:fluidsurf>
           ${CMAKE_SOURCE_DIR} ${CMAKE_BINARY_DIR}/test-out/slurm_cluster)
  set_tests_properties(slurm_cluster PROPERTIES ENVIRONMENT "${FS_TEST_ENV}" TIMEOUT 180)
endif()
add_test(NAME cli_obstacles COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli_obstacles.sh $<TARGET_FILE:fluidsurf>
         ${CMAKE_BINARY_DIR}/test-out/cli_obstacles)
set_tests_properties(cli_obstacles PROPERTIES ENVIRONMENT "${FS_TEST_ENV}" TIMEOUT 300)
# The context on a machine that is not ours: EGL's renderer line (once, not under -q, not
# on OSMesa), --require-gpu and FLUIDSURF_REQUIRE_GPU=1 refusing llvmpipe, in every command
# and in render_bench. Real EGL on Mesa's software device; in the lean build too.
add_test(NAME cli_require_gpu COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli_require_gpu.sh $<TARGET_FILE:fluidsurf>
         ${CMAKE_SOURCE_DIR} ${CMAKE_BINARY_DIR}/test-out/cli_require_gpu $<BOOL:${FS_WITH_OSMESA}>
         $<BOOL:${FS_WITH_GLFW}> $<TARGET_FILE:render_bench>)
set_tests_properties(cli_require_gpu PROPERTIES ENVIRONMENT "${FS_TEST_ENV}" TIMEOUT 180 SKIP_RETURN_CODE 77)
# A particle file's scene from the command line: --up auto|x|y|z with its note, the
# field options, r_source in the provenance (read from the EXRs: OpenImageIO's iinfo).
if(FS_WITH_OIIO)
  add_test(NAME cli_scene_axes COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli_scene_axes.sh $<TARGET_FILE:fluidsurf>
           ${CMAKE_SOURCE_DIR} ${CMAKE_BINARY_DIR}/test-out/cli_scene_axes)
  set_tests_properties(cli_scene_axes PROPERTIES ENVIRONMENT "${FS_TEST_ENV}")
  # The camera (--camera, --camera-from, --save-scene) and frame patterns of render and compare.
  add_test(NAME cli_camera COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli_camera.sh $<TARGET_FILE:fluidsurf>
           ${CMAKE_SOURCE_DIR} ${CMAKE_BINARY_DIR}/test-out/cli_camera)
  set_tests_properties(cli_camera PROPERTIES ENVIRONMENT "${FS_TEST_ENV}")
endif()
