# Area "io": particle storage and particle file readers/writers.
fs_add_test(test_io_read fs_particles test_io_read.c)
fs_add_test(test_io_roundtrip fs_particles test_io_roundtrip.c)
fs_add_test(test_io_bad fs_particles test_io_bad.c)
