fs_add_test(test_scene fs_scene test_scene.c)
fs_add_test(test_up_axis fs_scene test_up_axis.c)
