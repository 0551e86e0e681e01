# Area "io": particle storage and particle file readers/writers.
fs_add_test(test_io_read test_io_read.c)
fs_add_test(test_io_roundtrip test_io_roundtrip.c)
fs_add_test(test_io_bad test_io_bad.c)
