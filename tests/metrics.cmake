# Area "metrics": IoU, depth/normal errors, interior mask, PSNR and SSIM on constructed images.
fs_add_test(test_metrics fs_eval test_metrics.c)
# Static obstacles: geometry, the shading's depth compositing, the metrics that leave out hidden pixels.
fs_add_test(test_obstacles fs_eval test_obstacles.c)
