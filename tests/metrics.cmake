# Area "metrics": IoU, depth/normal errors, interior mask, PSNR and SSIM on constructed images.
fs_add_test(test_metrics fs_eval test_metrics.c)
