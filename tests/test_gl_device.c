/* The EGL device choice and the software-renderer list (common/gl/gl_device.h):
 * hardware before software, enumeration order kept within each, an all-software
 * machine still gets its first device, an empty list fails in one line; a device
 * whose GL_RENDERER turns out to be llvmpipe gives way to a later GPU. The
 * machines of test_choose are tables of devices, since this one has no GPU. */
#include "fs_error.h"
#include "fs_test.h"
#include "gl_device.h"
#include <stdio.h>

#define U FS_GL_DEVICE_UNKNOWN
#define HW FS_GL_DEVICE_HARDWARE
#define SW FS_GL_DEVICE_SOFTWARE

/* order of cls[0..n-1] as a string of indices, "" on failure */
static const char *order_of(const fs_gl_device_class *cls, int n)
{
    static char s[32];
    int order[16];
    s[0] = 0;
    if (fs_gl_device_order(cls, n, order)) return s;
    for (int i = 0; i < n; i++) s[i] = (char)('0' + order[i]);
    s[n] = 0;
    return s;
}

static void test_classify(void)
{
    /* what Mesa 22.3's llvmpipe device lists (measured): software despite the drm word */
    CHECK(fs_gl_device_classify("EGL_MESA_device_software EGL_EXT_device_drm_render_node") == SW,
          "Mesa software device");
    CHECK(fs_gl_device_classify("EGL_EXT_device_drm EGL_EXT_device_drm_render_node") == HW, "a DRM device");
    CHECK(fs_gl_device_classify("EGL_NV_device_cuda EGL_EXT_device_persistent_id") == HW, "an NVIDIA device");
    CHECK(fs_gl_device_classify("EGL_EXT_device_drm_render_node") == U, "a render node word is not a DRM device file");
    CHECK(fs_gl_device_classify("") == U && fs_gl_device_classify(NULL) == U, "nothing known");
    CHECK(fs_gl_device_classify("EGL_EXT_device_drm EGL_MESA_device_software") == SW, "the software mark wins");
}

static void test_order(void)
{
    const fs_gl_device_class sw_first[] = {SW, HW};
    CHECK(!strcmp(order_of(sw_first, 2), "10"), "hardware before software: %s", order_of(sw_first, 2));
    const fs_gl_device_class mixed[] = {SW, HW, U, SW, HW};
    CHECK(!strcmp(order_of(mixed, 5), "12403"), "order kept in each group: %s", order_of(mixed, 5));
    const fs_gl_device_class all_sw[] = {SW, SW, SW};
    CHECK(!strcmp(order_of(all_sw, 3), "012"), "all software: the first first: %s", order_of(all_sw, 3));
    const fs_gl_device_class one[] = {HW};
    CHECK(!strcmp(order_of(one, 1), "0"), "one device");
    int order[1];
    fs_error_clear();
    int rc = fs_gl_device_order(NULL, 0, order);
    CHECK(rc == FS_ERR_RUNTIME && !strcmp(fs_error_message(), "OpenGL: EGL: no EGL device"), "empty list: rc %d, %s",
          rc, fs_error_message());
}

/* A machine for fs_gl_device_choose: per device, EGL's class, whether it opens,
 * and whether its GL_RENDERER then names a software rasterizer. */
typedef struct machine {
    int n;
    fs_gl_device_class cls[8];
    int opens[8], soft[8];
    int open_now[8];
    char log[64]; /* "o1 c1 o0 " */
} machine;

static int m_open(void *data, int i)
{
    machine *m = data;
    snprintf(m->log + strlen(m->log), sizeof m->log - strlen(m->log), "o%d ", i);
    if (!m->opens[i]) return -1;
    m->open_now[i] = 1;
    return m->soft[i];
}

static void m_close(void *data, int i)
{
    machine *m = data;
    snprintf(m->log + strlen(m->log), sizeof m->log - strlen(m->log), "c%d ", i);
    m->open_now[i] = 0;
}

/* chooses on m; the chosen device is the only one left open */
static int choose(machine *m, const char *what)
{
    int i = fs_gl_device_choose(m->cls, m->n, m_open, m_close, m);
    int open = 0;
    for (int k = 0; k < m->n; k++) open += m->open_now[k];
    CHECK(i < 0 ? open == 0 : open == 1 && m->open_now[i], "%s: %d device(s) left open, chose %d (%s)", what, open, i,
          m->log);
    return i;
}

static void test_choose(void)
{
    machine sw_hw = {.n = 2, .cls = {SW, HW}, .opens = {1, 1}, .soft = {1, 0}};
    CHECK(choose(&sw_hw, "sw_hw") == 1 && !strcmp(sw_hw.log, "o1 "), "the GPU, llvmpipe never opened: %s", sw_hw.log);
    machine all_sw = {.n = 3, .cls = {SW, SW, SW}, .opens = {1, 1, 1}, .soft = {1, 1, 1}};
    CHECK(choose(&all_sw, "all_sw") == 0 && !strcmp(all_sw.log, "o0 "), "all software: the first, opened once: %s",
          all_sw.log);
    /* a device EGL says nothing about, or a DRM device, whose renderer is llvmpipe gives way */
    machine u_hw = {.n = 3, .cls = {U, HW, HW}, .opens = {1, 1, 1}, .soft = {1, 1, 0}};
    CHECK(choose(&u_hw, "u_hw") == 2 && !strcmp(u_hw.log, "o0 c0 o1 c1 o2 "), "a hardware renderer first: %s",
          u_hw.log);
    machine u_sw = {.n = 2, .cls = {SW, U}, .opens = {1, 1}, .soft = {1, 1}};
    CHECK(choose(&u_sw, "u_sw") == 1 && !strcmp(u_sw.log, "o1 c1 o1 "), "nothing better: the first in order: %s",
          u_sw.log);
    machine hw_fails = {.n = 2, .cls = {HW, SW}, .opens = {0, 1}, .soft = {0, 1}};
    CHECK(choose(&hw_fails, "hw_fails") == 1 && !strcmp(hw_fails.log, "o0 o1 "),
          "a GPU that fails is not tried twice: %s", hw_fails.log);
    machine none = {.n = 2, .cls = {HW, SW}, .opens = {0, 0}, .soft = {0, 0}};
    CHECK(choose(&none, "none") == -1, "no device opens: -1 (%s)", none.log);
    machine empty = {0};
    fs_error_clear();
    CHECK(choose(&empty, "empty") == -1 && !strcmp(fs_error_message(), "OpenGL: EGL: no EGL device") && !empty.log[0],
          "no device: -1, one line: %s", fs_error_message());
}

static void test_software_renderers(void)
{
    const char *soft[] = {"llvmpipe (LLVM 15.0.6, 256 bits)",
                          "softpipe",
                          "Mesa X11 swrast",
                          "LAVAPIPE",
                          "Software Rasterizer",
                          "Microsoft Basic Render Driver Software Rasterizer"};
    for (size_t i = 0; i < sizeof soft / sizeof *soft; i++)
        CHECK(fs_gl_renderer_is_software(soft[i]), "software: %s", soft[i]);
    const char *hard[] = {"NVIDIA H200/PCIe/SSE2", "AMD Radeon RX 7900 XTX (radeonsi, navi31, LLVM 15.0.6, DRM 3.54)",
                          "Mesa Intel(R) UHD Graphics 630 (CFL GT2)", "", NULL};
    for (size_t i = 0; i < sizeof hard / sizeof *hard; i++)
        CHECK(!fs_gl_renderer_is_software(hard[i]), "hardware: %s", hard[i] ? hard[i] : "(null)");
}

int main(void)
{
    test_classify();
    test_order();
    test_choose();
    test_software_renderers();
    TEST_DONE();
}
