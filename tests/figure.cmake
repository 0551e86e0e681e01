# Area "figure": text, heatmaps with colour bars, panels.
fs_add_test(test_figure fs_figure test_figure.c)
