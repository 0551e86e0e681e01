# Area "levelset" (OpenVDB's union-of-spheres level set, ray traced): only in a
# build with OpenVDB, where the method exists. The method against the exact
# union of its spheres, the export, bad parameters; the CLI against the exact
# union, its refusals and its .vdb export (read by vdb_print when installed; the
# test reports Skipped, exit 77, when vdb_print is not).
if(FS_WITH_OPENVDB)
  fs_add_test(test_levelset fs_test_methods test_levelset.c test_render.c)
  add_test(NAME cli_levelset COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli_levelset.sh $<TARGET_FILE:fluidsurf>
           ${CMAKE_SOURCE_DIR} ${CMAKE_BINARY_DIR}/test-out/cli_levelset)
  set_tests_properties(cli_levelset PROPERTIES TIMEOUT 120 SKIP_RETURN_CODE 77 ENVIRONMENT "${FS_TEST_ENV}")
endif()
