# Area "params": typed method parameters (the M.P=V splitter, the struct fill,
# settings by name).
fs_add_test(test_method_params fs_methods test_method_params.c)
