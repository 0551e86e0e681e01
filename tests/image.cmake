# Area "image": image files, the shared shading pass, the golden-image helper.
fs_add_test(test_image_io fs_image test_image_io.c golden.c)
fs_add_test(test_shading fs_image test_shading.c golden.c)
