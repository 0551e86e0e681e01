# Area "params": typed method parameters (the M.P=V splitter, the struct fill,
# settings by name) and the method READMEs' parameter tables against the code.
fs_add_test(test_method_params "fs_methods;fs_run" test_method_params.c)
fs_add_test(test_method_readmes fs_methods test_method_readmes.c)
