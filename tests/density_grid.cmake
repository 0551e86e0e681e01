# Area "density_grid": the exact CPU density grid, iwasaki2006's slice splatting
# against it, the VDB adapter; then, where openvdb-tools is installed, vdb_print
# reads the grid the C test wrote.
fs_add_test(test_density_grid fs_image test_density_grid.c)
set_tests_properties(test_density_grid PROPERTIES FIXTURES_SETUP density_grid_vdb)
find_program(FS_VDB_PRINT vdb_print)
if(FS_VDB_PRINT AND FS_WITH_OPENVDB)
  add_test(NAME test_density_grid_vdb_print COMMAND sh -c
    "\"$0\" -l \"$1\" > \"$1.txt\" && grep -q '^Name: density' \"$1.txt\" && grep -q 'Tree_float' \"$1.txt\""
    ${FS_VDB_PRINT} ${CMAKE_BINARY_DIR}/test-out/density_grid.vdb)
  set_tests_properties(test_density_grid_vdb_print PROPERTIES FIXTURES_REQUIRED density_grid_vdb)
endif()
