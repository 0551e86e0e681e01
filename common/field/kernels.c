#include "kernels.h"
#include <string.h>

static const char *const names[FS_KERNEL_COUNT] = {"cubic", "poly6", "spiky", "wyvill"};

const char *fs_kernel_name(fs_kernel k) { return (unsigned)k < FS_KERNEL_COUNT ? names[k] : "?"; }

int fs_kernel_from_name(const char *name)
{
    for (int i = 0; i < FS_KERNEL_COUNT; i++)
        if (!strcmp(name, names[i])) return i;
    return -1;
}

float fs_kernel_max_dw(fs_kernel k, float H)
{
    double H4 = (double)H * H * H * H;
    switch (k) {
    case FS_KERNEL_POLY6: /* max of 6 d (H^2-d^2)^2 at d = H/sqrt5 */
        return (float)(315.0 / (64.0 * FS_PI) * 6.0 * (1.0 / sqrt(5.0)) * (16.0 / 25.0) / H4 * 1.0001);
    case FS_KERNEL_SPIKY: return (float)(45.0 / FS_PI / H4 * 1.0001);
    case FS_KERNEL_WYVILL: { /* |a p'(a)|/a... sampled densely, it is smooth */
        double m = 0;
        for (int i = 0; i <= 4096; i++) {
            double d = H * i / 4096.0, v = fabs(fs_wyvill_dw((float)d, H));
            if (v > m) m = v;
        }
        return (float)(m * 1.01);
    }
    default: return (float)(16.0 / FS_PI / H4 * 1.0001); /* at q = 1/3 */
    }
}
