#include "gl_counters.h"
#include "counters.h"
#include "fs_error.h"
#include "gl.h"
#include <stdint.h>
#include <stdio.h>

#define WORDS (2 * FS_NCOUNTERS + 1) /* pairs, then the overflow bits */

static GLuint buf;

const char *fs_gl_counter_defines(void)
{
    static char text[800];
    if (text[0]) return text;
    int n =
        snprintf(text, sizeof text, "FS_COUNTERS 1\nFS_CNT_BINDING %d\nFS_CNT_WORDS %d", FS_GL_COUNTER_BINDING, WORDS);
    static const char *const macro[FS_NCOUNTERS] = {"FS_CNT_FIELD_EVALS",         "FS_CNT_NEIGHBOURS",
                                                    "FS_CNT_MARCH_SAMPLES",       "FS_CNT_FRAGMENTS",
                                                    "FS_CNT_FILTER_TAPS",         "FS_CNT_TEXELS",
                                                    "FS_CNT_CROSSINGS",           "FS_CNT_CELLS_WALKED",
                                                    "FS_CNT_CELLS_MARCHED",       "FS_CNT_CELLS_MARCHED_INSIDE",
                                                    "FS_CNT_CELLS_PROVEN_INSIDE", "FS_CNT_CELLS_PROVEN_OUTSIDE",
                                                    "FS_CNT_REFINE_EVALS",        "FS_CNT_INSIDE_EVALS",
                                                    "FS_CNT_SPLAT_PIXELS",        "FS_CNT_SPLAT_ATOMICS"};
    for (int c = 0; c < FS_NCOUNTERS; c++) n += snprintf(text + n, sizeof text - n, "\n%s %du", macro[c], c);
    return text;
}

/* Adds the buffer's counts to the pending table and zeroes it. */
static void collect(void)
{
    if (!buf) return;
    uint32_t w[WORDS];
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glGetNamedBufferSubData(buf, 0, sizeof w, w);
    for (int c = 0; c < FS_NCOUNTERS; c++) {
        fs_count_add((fs_counter)c, (uint64_t)w[2 * c + 1] << 32 | w[2 * c]);
        if (w[2 * FS_NCOUNTERS] & FS_CNT_BIT(c)) fs_counters_overflowed((fs_counter)c);
    }
    uint32_t zero = 0;
    glClearNamedBufferData(buf, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
}

int fs_gl_counters_begin(void)
{
    GLint nb = 0;
    glGetIntegerv(GL_MAX_SHADER_STORAGE_BUFFER_BINDINGS, &nb);
    if (nb <= FS_GL_COUNTER_BINDING)
        return fs_fail(FS_ERR_RUNTIME, "work counters need storage buffer binding %d; the context has %d",
                       FS_GL_COUNTER_BINDING, nb);
    uint32_t zero[WORDS] = {0};
    glCreateBuffers(1, &buf);
    glNamedBufferData(buf, sizeof zero, zero, GL_DYNAMIC_READ);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, FS_GL_COUNTER_BINDING, buf);
    fs_counters_set_collector(collect);
    return FS_OK;
}

void fs_gl_counters_end(void)
{
    if (!buf) return;
    collect();
    fs_counters_set_collector(NULL);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, FS_GL_COUNTER_BINDING, 0);
    glDeleteBuffers(1, &buf);
    buf = 0;
}
