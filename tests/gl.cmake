fs_add_test(test_gl fs_gl test_gl.c)
fs_add_test(test_spheres fs_test_methods test_spheres.c golden.c)
