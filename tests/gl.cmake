fs_add_test(test_gl test_gl.c)
fs_add_test(test_spheres test_spheres.c golden.c)
