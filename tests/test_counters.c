/* The work counters of the core layer (counters.h, stage_counts.h): pending
 * counts land in the next stage, nothing is counted while counting is off, a
 * 64-bit overflow is an error naming the counter and the stage, and the cache
 * text of a run's counts reads back as written. */
#include "counters.h"
#include "fs_error.h"
#include "fs_test.h"
#include "stage_counts.h"
#include "timing.h"
#include <stdint.h>
#include <string.h>

static uint64_t count_of(const fs_stages *st, const char *stage, int c)
{
    for (int i = 0; i < st->n; i++)
        if (!strcmp(st->name[i], stage)) return st->count[i][c];
    return UINT64_MAX;
}

static void test_names(void)
{
    const char *want[] = {"field_evals", "neighbours_visited", "march_samples", "fragments_shaded", "filter_taps",
                          "texels_written"};
    CHECK(FS_NCOUNTERS == 6, "%d counters", FS_NCOUNTERS);
    for (int c = 0; c < FS_NCOUNTERS; c++) {
        CHECK(!strcmp(fs_counter_name(c), want[c]), "counter %d is %s", c, fs_counter_name(c));
        CHECK(fs_counter_index(want[c]) == c, "index of %s", want[c]);
    }
    CHECK(!fs_counter_name(FS_NCOUNTERS) && fs_counter_index("voxels") == -1, "out of range");
}

static void test_attribution(void)
{
    fs_stages st = {0};
    fs_counters_reset();
    fs_count_add(FS_CNT_FIELD_EVALS, 5); /* off: dropped */
    fs_stages_add(&st, "a", 1);
    CHECK(count_of(&st, "a", FS_CNT_FIELD_EVALS) == 0, "counted while off");
    fs_counting_set(1);
    fs_count_add(FS_CNT_FIELD_EVALS, 7);
    fs_count_add(FS_CNT_TEXELS, 3);
    fs_stages_add(&st, "b", 1);
    fs_count_add(FS_CNT_FIELD_EVALS, 2);
    fs_stages_add(&st, "a", 1); /* again: added to a's counts */
    fs_counting_set(0);
    CHECK(count_of(&st, "b", FS_CNT_FIELD_EVALS) == 7 && count_of(&st, "b", FS_CNT_TEXELS) == 3, "b's counts");
    CHECK(count_of(&st, "a", FS_CNT_FIELD_EVALS) == 2 && count_of(&st, "a", FS_CNT_TEXELS) == 0, "a's counts");
    CHECK(st.ms[0] == 2 && st.ms[1] == 1, "times still add up: %g %g", st.ms[0], st.ms[1]);
    CHECK(fs_counters_check() == FS_OK, "no overflow: %s", fs_error_message());
}

static void test_overflow(void)
{
    fs_stages st = {0};
    fs_counters_reset();
    fs_counting_set(1);
    fs_count_add(FS_CNT_NEIGHBOURS, UINT64_MAX - 1);
    fs_count_add(FS_CNT_NEIGHBOURS, 2); /* wraps the pending sum */
    fs_stages_add(&st, "march", 1);
    fs_counting_set(0);
    CHECK(fs_counters_check() == FS_ERR_RUNTIME && strstr(fs_error_message(), "neighbours_visited") &&
              strstr(fs_error_message(), "march"),
          "pending overflow: %s", fs_error_message());
    /* the stage's own sum wrapping */
    memset(&st, 0, sizeof st);
    fs_counters_reset();
    fs_counting_set(1);
    fs_count_add(FS_CNT_TEXELS, UINT64_MAX);
    fs_stages_add(&st, "splat", 1);
    fs_count_add(FS_CNT_TEXELS, 1);
    fs_stages_add(&st, "splat", 1);
    fs_counting_set(0);
    CHECK(fs_counters_check() == FS_ERR_RUNTIME && strstr(fs_error_message(), "texels_written") &&
              strstr(fs_error_message(), "splat"),
          "stage overflow: %s", fs_error_message());
    fs_counters_reset();
    CHECK(fs_counters_check() == FS_OK, "reset clears the overflow");
}

static void test_text(void)
{
    fs_stages st = {0}, back;
    fs_counters_reset();
    fs_counting_set(1);
    fs_count_add(FS_CNT_MARCH_SAMPLES, 123456789012345ull);
    fs_stages_add(&st, "march", 1);
    fs_count_add(FS_CNT_FIELD_EVALS, 9);
    fs_stages_add(&st, "bounds", 1);
    fs_counting_set(0);
    char text[640];
    CHECK(fs_stage_counts_format(&st, text, sizeof text) == FS_OK, "format");
    CHECK(!strcmp(text, "1:march=0,0,123456789012345,0,0,0;bounds=9,0,0,0,0,0"), "text: %s", text);
    CHECK(fs_stage_counts_parse(text, &back) == FS_OK && back.n == 2, "parse");
    CHECK(!strcmp(back.name[1], "bounds") && !memcmp(back.count, st.count, sizeof st.count), "read back");
    CHECK(fs_stage_counts_parse("", &back) != FS_OK, "empty text is no counts");
    CHECK(fs_stage_counts_parse("1:march=1,2,3", &back) != FS_OK, "too few values");
    CHECK(fs_stage_counts_parse("2:march=1,2,3,4,5,6", &back) != FS_OK, "another format");
    CHECK(fs_stage_counts_format(&st, text, 20) != FS_OK, "too long for the buffer");
}

int main(void)
{
    test_names();
    test_attribution();
    test_overflow();
    test_text();
    TEST_DONE();
}
