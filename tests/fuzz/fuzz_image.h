/* The image readers (fs_read_image, fs_read_image_attr) on the input, with the
 * extension FS_FUZZ_EXT: a read image has pixels for its size and a name per
 * channel. */
#include "fuzz_input.h"
#include "image_io.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const char *path = fs_fuzz_file(data, size, FS_FUZZ_EXT);
    fs_image img;
    fs_error_clear();
    int rc = fs_read_image(path, &img);
    fs_fuzz_check_message(rc);
    if (rc == FS_OK) {
        if (img.w <= 0 || img.h <= 0 || img.nch <= 0 || !img.pix || !img.chnames) abort();
        volatile float sum = 0;
        for (size_t i = 0; i < (size_t)img.w * img.h * img.nch; i++) sum += img.pix[i]; /* every pixel readable */
        (void)sum;
        for (int c = 0; c < img.nch; c++)
            if (!img.chnames[c]) abort();
        fs_image_free(&img);
    }
    char buf[256];
    fs_error_clear();
    int a = fs_read_image_attr(path, "fluidsurf:commit", buf, sizeof buf);
    if (a < 0) fs_fuzz_check_message(FS_ERR_INPUT);
    return 0;
}
