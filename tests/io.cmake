# Area "io": particle storage and particle file readers/writers.
# They read and write every format, VTK and VDB among them: full builds only
# (the lean build's refusals are tests/cli_lean.sh's).
if(FS_WITH_VTK AND FS_WITH_OPENVDB)
  fs_add_test(test_io_read fs_particles test_io_read.c)
  fs_add_test(test_io_roundtrip fs_particles test_io_roundtrip.c)
  fs_add_test(test_io_bad fs_particles test_io_bad.c)
  fs_add_test(test_io_arrays fs_particles test_io_arrays.c) # every point array read, written back
endif()
# The child-process isolation those readers run in (read_in_child.h), every build.
fs_add_test(test_read_in_child fs_particles test_read_in_child.c)
