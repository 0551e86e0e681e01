# Area "sph": the SPH simulator (CPU and GPU paths, boundaries, time step, scenes).
fs_add_test(test_sph test_sph.c)
set_tests_properties(test_sph PROPERTIES TIMEOUT 120)
