# Area "reference": neighbour grid, particle statistics, kernels (CPU),
# synthetic scenes with their analytic G-buffer, and the exact reference method.
fs_add_test(test_grid test_grid.c)
fs_add_test(test_kernels_cpu test_kernels_cpu.c)
fs_add_test(test_synthetic test_synthetic.c)
fs_add_test(test_reference test_reference.c)
fs_add_test(test_reference_golden test_reference_golden.c golden.c)
