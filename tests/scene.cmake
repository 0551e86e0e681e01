fs_add_test(test_scene test_scene.c)
