# Area "strays": a real frame plus a few particles thousands of metres away,
# rendered by every registered method through the run layer on OSMesa.
fs_add_test(test_strays fs_test_methods test_strays.c test_render.c)
