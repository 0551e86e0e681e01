fs_add_test(test_scene fs_scene test_scene.c)
