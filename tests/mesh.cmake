# Area "mesh" (marching cubes of the scene's field, rasterised): only in a build
# with OpenVDB, where the method exists. The mesh's topology, volume and normals,
# smoothing, the dam break against the reference, the memory refusal; the CLI:
# compare, `fluidsurf mesh` with every export read back by VTK's own readers,
# sequences, refusals. smooth=weighted (splashsurf's) on a thick slab and a thin sheet,
# and attributes (velocity, colour) interpolated onto the vertices.
if(FS_WITH_OPENVDB)
  fs_add_test(test_mesh fs_test_methods test_mesh.c test_render.c)
  fs_add_test(test_mesh_weighted fs_test_methods test_mesh_weighted.c test_render.c)
  fs_add_test(test_mesh_zb fs_test_methods test_mesh_zb.c) # field=zhu_bridson on a slab and a ball
  fs_add_test(test_mesh_degenerate fs_test_methods test_mesh_degenerate.c) # no zero normal or zero-area face after smoothing
  add_test(NAME cli_mesh COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli_mesh.sh $<TARGET_FILE:fluidsurf>
           ${CMAKE_SOURCE_DIR} ${CMAKE_BINARY_DIR}/test-out/cli_mesh)
  set_tests_properties(cli_mesh PROPERTIES TIMEOUT 300 ENVIRONMENT "${FS_TEST_ENV}")
endif()
