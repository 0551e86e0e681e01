# Area "run": the method-run layer with a test-only method registered through
# the registry's API (hidden), written to EXR and read back; links no methods.
fs_add_test(test_run "fs_run;fs_image" test_run.c)
