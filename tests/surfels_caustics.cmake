# Area "surfels" (iwasaki2006), caustics: illumination volumes from synthetic surfel sets.
fs_add_test(test_caustics fs_test_methods test_caustics.c)
