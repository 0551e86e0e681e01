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
#include <stdio.h>
#include <string.h>

static uint64_t count_of(const fs_stages *st, const char *stage, int c)
{
    for (int i = 0; i < st->n; i++)
        if (!strcmp(st->name[i], stage)) return st->count[i][c];
    return UINT64_MAX;
}

static void test_names(void)
{
    const char *want[] = {"field_evals",   "neighbours_visited",   "march_samples",       "fragments_shaded",
                          "filter_taps",   "texels_written",       "crossings",           "cells_walked",
                          "cells_marched", "cells_marched_inside", "cells_proven_inside", "cells_proven_outside",
                          "refine_evals",  "inside_evals",         "splat_pixels",        "splat_atomics"};
    CHECK(FS_NCOUNTERS == 16, "%d counters", FS_NCOUNTERS);
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
    CHECK(!strcmp(text, "1:march=0,0,123456789012345,0,0,0,0,0,0,0,0,0,0,0,0,0;bounds=9,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0"),
          "text: %s", text);
    CHECK(fs_stage_counts_parse(text, &back) == FS_OK && back.n == 2, "parse");
    CHECK(!strcmp(back.name[1], "bounds") && !memcmp(back.count, st.count, sizeof st.count), "read back");
    CHECK(fs_stage_counts_parse("", &back) != FS_OK, "empty text is no counts");
    /* the 6 counters before issue 33: an older cache entry, counted again */
    CHECK(fs_stage_counts_parse("1:march=1,2,3,4,5,6", &back) != FS_OK, "too few values");
    /* the 14 counters before issue 47 */
    CHECK(fs_stage_counts_parse("1:march=1,2,3,4,5,6,7,8,9,10,11,12,13,14", &back) != FS_OK, "14 values");
    CHECK(fs_stage_counts_parse("2:march=1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16", &back) != FS_OK, "another format");
    CHECK(fs_stage_counts_format(&st, text, 20) != FS_OK, "too long for the buffer");
    /* strict: exactly the format, digits only, below 2^64 */
    const char *bad[] = {
        "1:",
        "1:;",
        "1:march=1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16;",
        "1:march=1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16;;",
        "1:=1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16",
        "1:march=-1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16",
        "1:march= 1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16",
        "1:march=+1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16",
        "1:march=1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16 ",
        "1:march=1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16,17",
        "1:march=1,,3,4,5,6,7,8,9,10,11,12,13,14,15,16",
        "1:march=01,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16",
        "1:march=18446744073709551616,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0",
        "1:march=99999999999999999999,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0",
        "1:march=1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16;march=1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16",
        "1:march=1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16x",
        "1:a,b=1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16",
        "1:a=18446744073709551615,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0;b=1,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0" /* the total would wrap */};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++)
        CHECK(fs_stage_counts_parse(bad[i], &back) == FS_ERR_INPUT, "rejects '%s'", bad[i]);
    CHECK(fs_stage_counts_parse(
              "1:march=18446744073709551615,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0;b=0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,1", &back) ==
                  FS_OK &&
              back.count[0][0] == UINT64_MAX && back.count[1][15] == 1 && back.n == 2,
          "2^64 - 1 and a second stage read back");
}

/* The worst case (16 stages, longest names, 20-digit values) fits the
 * buffer the reference cache uses, exactly. */
static void test_text_worst_case(void)
{
    static char names[FS_MAX_STAGES][FS_STAGE_NAME_MAX + 1];
    static char text[FS_STAGE_COUNTS_MAX];
    fs_stages st = {0};
    for (int i = 0; i < FS_MAX_STAGES; i++) {
        snprintf(names[i], sizeof names[i], "%02d_%0*d", i, FS_STAGE_NAME_MAX - 3, 0);
        st.name[st.n++] = names[i];
        for (int c = 0; c < FS_NCOUNTERS; c++) st.count[i][c] = UINT64_MAX;
    }
    CHECK(fs_stage_counts_format(&st, text, sizeof text) == FS_OK && strlen(text) == sizeof text - 1,
          "worst case fits exactly: %zu of %zu", strlen(text), sizeof text);
    CHECK(fs_stage_counts_format(&st, text, sizeof text - 1) != FS_OK, "one byte less does not");
    static char longer[FS_STAGE_NAME_MAX + 2];
    memset(longer, 'x', sizeof longer - 1);
    st.name[0] = longer;
    CHECK(fs_stage_counts_format(&st, text, sizeof text) != FS_OK, "a name too long to read back is not written");
}

/* The one sum over stages (fs_stages_count_total) detects a wrap. */
static void test_totals(void)
{
    fs_stages st = {0};
    uint64_t t = 0;
    st.n = 2;
    st.name[0] = "a";
    st.name[1] = "b";
    st.count[0][1] = UINT64_MAX - 1;
    st.count[1][1] = 1;
    CHECK(!fs_stages_count_total(&st, 1, &t) && t == UINT64_MAX, "sum to 2^64 - 1");
    st.count[1][1] = 2;
    CHECK(fs_stages_count_total(&st, 1, &t) && t == UINT64_MAX, "a wrap is reported");
    CHECK(!fs_stages_count_total(&st, 0, &t) && t == 0, "zero");
}

/* A full stage table while counting is an error; counts after the last stage
 * stay pending for fs_run_count to refuse. */
static void test_never_dropped(void)
{
    static const char *const names[FS_MAX_STAGES + 1] = {"s0", "s1",  "s2",  "s3",  "s4",  "s5",  "s6",  "s7", "s8",
                                                         "s9", "s10", "s11", "s12", "s13", "s14", "s15", "s16"};
    fs_stages st = {0};
    fs_counters_reset();
    for (int i = 0; i <= FS_MAX_STAGES; i++) fs_stages_add(&st, names[i], 1);
    CHECK(st.n == FS_MAX_STAGES && fs_counters_check() == FS_OK,
          "not counting: the 17th stage's time is dropped, no error");
    memset(&st, 0, sizeof st);
    fs_counting_set(1);
    for (int i = 0; i <= FS_MAX_STAGES; i++) {
        fs_count_add(FS_CNT_FILTER_TAPS, 1);
        fs_stages_add(&st, names[i], 1);
    }
    fs_counting_set(0);
    CHECK(fs_counters_check() == FS_ERR_RUNTIME && strstr(fs_error_message(), "s16"), "full table while counting: %s",
          fs_error_message());
    CHECK(fs_counters_unattributed() == FS_CNT_BIT(FS_CNT_FILTER_TAPS), "the 17th stage's count is still pending");
    fs_counters_reset();
    CHECK(!fs_counters_unattributed() && fs_counters_check() == FS_OK, "reset");
    fs_counting_set(1);
    fs_count_add(FS_CNT_TEXELS, 4);
    fs_counting_set(0);
    CHECK(fs_counters_unattributed() == FS_CNT_BIT(FS_CNT_TEXELS), "a count after the last stage is seen");
    fs_counters_reset();
}

int main(void)
{
    test_names();
    test_attribution();
    test_overflow();
    test_text();
    test_text_worst_case();
    test_totals();
    test_never_dropped();
    TEST_DONE();
}
