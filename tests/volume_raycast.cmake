# Area "volume_raycast" (inacio2010): the single-pass layered density grid
# against the exact one, the method against the reference, layered / slice /
# exact builds giving the same image, the translucent transfer function, the
# .vdb export.
fs_add_test(test_volume_raycast fs_test_methods test_volume_raycast.c test_render.c)
# The march over the layered and over the slice (and exact) build of inacio_tables'
# SPH frame hits the same surface (issue 52: the 0.1 ms march on the H200).
fs_add_test(test_volume_raycast_builds fs_test_methods test_volume_raycast_builds.c)
target_link_libraries(test_volume_raycast_builds PRIVATE fs_sph)
