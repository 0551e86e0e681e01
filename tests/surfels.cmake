# Area "surfels" (iwasaki2006): surfel extraction, the GL method against the
# reference, splat vs exact grids, the own appearance and the exports.
fs_add_test(test_surfels fs_test_methods test_surfels.c test_render.c)
