# Area "reference": neighbour grid, particle statistics, kernels (CPU),
# synthetic scenes with their analytic G-buffer, and the exact reference method.
fs_add_test(test_grid fs_field test_grid.c)
fs_add_test(test_kernels_cpu fs_field test_kernels_cpu.c)
fs_add_test(test_synthetic fs_eval test_synthetic.c)
fs_add_test(test_reference fs_test_methods test_reference.c)
if(FS_WITH_VTK) # its golden is of the bundled .vtk cube
  fs_add_test(test_reference_golden fs_test_methods test_reference_golden.c golden.c)
endif()
fs_add_test(test_reference_accel fs_test_methods test_reference_accel.c test_render.c)
fs_add_test(test_reference_supersample fs_test_methods test_reference_supersample.c)
fs_add_test(test_reference_taylor fs_methods test_reference_taylor.c)
fs_add_test(test_reference_demand fs_test_methods test_reference_demand.c test_render.c)
# Zhu & Bridson's phi (field=zhu_bridson): the formula, its gradient and the Lipschitz bound
# the reference marches on; the reference on a slab and a lattice ball.
fs_add_test(test_zhu_bridson fs_field test_zhu_bridson.c)
fs_add_test(test_reference_zb fs_test_methods test_reference_zb.c test_render.c)
