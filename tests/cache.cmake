# The reference cache: the hash and the key (method layer), the entry store
# (image layer); tests/cli_cache.sh covers compare and render end to end.
fs_add_test(test_cache_key fs_method test_cache_key.c)
fs_add_test(test_gbuffer_cache fs_image test_gbuffer_cache.c)
