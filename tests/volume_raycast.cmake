# Area "volume_raycast" (inacio2010): the single-pass layered density grid
# against the exact one, the method against the reference, layered / slice /
# exact builds giving the same image, the translucent transfer function, the
# .vdb export.
fs_add_test(test_volume_raycast fs_test_methods test_volume_raycast.c test_render.c)
