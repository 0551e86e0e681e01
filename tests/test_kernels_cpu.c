/* CPU kernels (kernels.h): 3D normalisation, derivative against a finite
 * difference, and the derivative bound the reference's safe steps rely on. */
#include "fs_test.h"
#include "kernels.h"

int main(void)
{
    const float H = 0.1f; /* 4r with r = 0.025, the default */
    for (int k = 0; k < FS_KERNEL_COUNT; k++) {
        const char *name = fs_kernel_name((fs_kernel)k);
        CHECK(fs_kernel_from_name(name) == k, "name %s round trip", name);

        /* Radial Simpson quadrature of 4 pi d^2 W(d) over [0, H]; 4096 intervals
         * put the cubic spline's joint at H/2 on a node. */
        int m = 4096;
        double h = H / m, sum = 0;
        for (int i = 0; i <= m; i++) {
            double d = i * h, f = 4.0 * FS_PI * d * d * fs_kernel_w((fs_kernel)k, (float)d, H);
            sum += f * (i == 0 || i == m ? 1 : (i % 2 ? 4 : 2));
        }
        sum *= h / 3;
        printf("%-7s integral %.7f\n", name, sum);
        CHECK_NEAR(sum, 1.0, 1e-4, name);
        CHECK(fs_kernel_w((fs_kernel)k, H, H) == 0 && fs_kernel_w((fs_kernel)k, 1.5f * H, H) == 0,
              "%s vanishes at and beyond H", name);

        /* Derivative against a central difference, and the bound on |dW/dd|. */
        float bound = fs_kernel_max_dw((fs_kernel)k, H);
        double worst = 0, peak = 0;
        for (int i = 1; i < 1000; i++) {
            double d = H * i / 1000.0, e = 1e-4 * H;
            double fd =
                ((double)fs_kernel_w((fs_kernel)k, (float)(d + e), H) - fs_kernel_w((fs_kernel)k, (float)(d - e), H)) /
                (2 * e);
            double dw = fs_kernel_dw((fs_kernel)k, (float)d, H);
            if (fabs(fd - dw) > worst) worst = fabs(fd - dw);
        }
        for (int i = 0; i <= 200000; i++) {
            double v = fabs(fs_kernel_dw((fs_kernel)k, (float)(H * i / 200000.0), H));
            if (v > peak) peak = v;
        }
        printf("%-7s |dW - finite difference| max %.3g (of max|dW| %.4g), bound %.6g, sampled max %.6g\n", name, worst,
               peak, bound, peak);
        CHECK(worst < 2e-3 * peak, "%s derivative differs from the finite difference by %g", name, worst);
        CHECK(bound >= peak, "%s: max_dw %g below the sampled %g", name, bound, peak);
        CHECK(bound <= 1.02 * peak, "%s: max_dw %g much looser than the sampled %g", name, bound, peak);
        /* Monotone decrease: the reference's segment bounds assume it. */
        int mono = 1;
        for (int i = 1; i <= 1000; i++)
            if (fs_kernel_w((fs_kernel)k, H * i / 1000.0f, H) > fs_kernel_w((fs_kernel)k, H * (i - 1) / 1000.0f, H))
                mono = 0;
        CHECK(mono, "%s does not decrease with distance", name);
    }
    CHECK(fs_kernel_from_name("gauss") == -1, "unknown kernel name");
    TEST_DONE();
}
