# Area "aniso_ssf" (xu2022): the C anisotropy on its own, then the GL method:
# C vs GLSL anisotropy, ellipsoid sprite depth, filters, normals, the anisotropic reference.
fs_add_test(test_anisotropy fs_scene test_anisotropy.c)
fs_add_test(test_aniso_ssf fs_test_methods test_aniso_ssf.c test_render.c)
