# Area "levelset" (OpenVDB's union-of-spheres level set, ray traced): only in a
# build with OpenVDB, where the method exists. The method against the exact
# union of its spheres, the export, bad parameters; the CLI against the exact
# union, its refusals and its .vdb export (read by vdb_print when installed; the
# test reports Skipped, exit 77, when vdb_print is not). The three rasterisers
# (levelset.rasterizer) against the analytic sphere of a ball of particles.
# cli_levelset takes 74 s alone in the sanitizer build and ran past 120 s in CI
# beside test_levelset: 300 s, as cli_mesh.
if(FS_WITH_OPENVDB)
  fs_add_test(test_levelset fs_test_methods test_levelset.c test_render.c)
  fs_add_test(test_levelset_raster fs_test_methods test_levelset_raster.c test_render.c)
  add_test(NAME cli_levelset COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli_levelset.sh $<TARGET_FILE:fluidsurf>
           ${CMAKE_SOURCE_DIR} ${CMAKE_BINARY_DIR}/test-out/cli_levelset)
  set_tests_properties(cli_levelset PROPERTIES TIMEOUT 300 SKIP_RETURN_CODE 77 ENVIRONMENT "${FS_TEST_ENV}")
endif()
