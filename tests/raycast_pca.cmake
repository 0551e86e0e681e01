# Area "raycast_pca" (xiao2017): Jacobi eigen-solver and the CPU normal maths,
# then the GL method against the reference and its switches.
fs_add_test(test_rpca_math fs_methods test_rpca_math.c)
fs_add_test(test_raycast_pca fs_test_methods test_raycast_pca.c test_render.c)
