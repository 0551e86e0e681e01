/* Typed parameters: the one "METHOD.PARAM=VALUE" splitter and its messages
 * (scene, --set, sweeps), the fill of a method's parameter struct by table
 * offsets, parameters set by name reaching create() as named fields, and the
 * tables of every built-in method fitting their structs, and every built-in
 * declaring its cost. */
#include "fs_error.h"
#include "fs_test.h"
#include "method.h"
#include "builtin_methods.h"
#include "method_params.h"
#include "run.h"
#include "sweep.h"
#include <math.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

/* A test-only method whose struct lists its fields in another order than its
 * table, with a member that is not a parameter: only the offsets can place them. */
typedef enum { MODE_A, MODE_B, MODE_C } probe_mode;
typedef struct probe_params {
    double gain;
    int unused;
    probe_mode mode;
    bool enabled;
} probe_params;

/* Spelled out here; the methods use FS_PARAM_FIELD, which also names each entry. */
static const fs_param_def probe_table[] = {
    {"enabled", offsetof(probe_params, enabled), FS_CTYPE_BOOL, FS_PARAM_BOOL, 1, 0, 1, NULL, "on/off"},
    {"mode", offsetof(probe_params, mode), FS_CTYPE_INT, FS_PARAM_ENUM, 1, 0, 2, "a|b|c", "a choice"},
    {"gain", offsetof(probe_params, gain), FS_CTYPE_DOUBLE, FS_PARAM_FLOAT, 0.5, 0, 10, NULL, "a number"},
};

static probe_params created; /* what the last create() received */

static void *probe_create(const fs_method_setup *setup)
{
    if (fs_method_params_copy("probe", setup, &created, sizeof created)) return NULL;
    return &created;
}
static void probe_destroy(void *self) { (void)self; }

static const fs_method probe = {
    .name = "probe",
    .description = "test-only: records its parameters",
    .paper = "",
    .params = probe_table,
    .nparams = 3,
    .params_size = sizeof(probe_params),
    .create = probe_create,
    .destroy = probe_destroy,
};

static void split(void)
{
    fs_param_setting s;
    CHECK(fs_param_split("spheres.radius_scale=0.5", &s) == FS_OK && !strcmp(s.method, "spheres") &&
              !strcmp(s.param, "radius_scale") && !strcmp(s.value, "0.5"),
          "split spheres.radius_scale=0.5");
    CHECK(fs_param_split("m.p=a.b=c", &s) == FS_OK && !strcmp(s.param, "p") && !strcmp(s.value, "a.b=c"),
          "the value keeps its '.' and '='");
    const char *bad[] = {"spheres", "spheres.radius_scale", ".p=1", "m.=1", "m.p=", "a=b.c", NULL};
    for (int i = 0; bad[i]; i++) {
        CHECK(fs_param_split(bad[i], &s) == FS_ERR_INPUT && strstr(fs_error_message(), "expected METHOD.PARAM=VALUE"),
              "%s refused: %s", bad[i], fs_error_message());
    }
    char longname[200];
    memset(longname, 'x', 100);
    strcpy(longname + 100, ".p=1");
    CHECK(fs_param_split(longname, &s) == FS_ERR_INPUT && strstr(fs_error_message(), "too long"), "long name refused");
}

/* The scene, the settings and the sweeps report a bad setting the same way. */
static void same_messages(void)
{
    const char *bad[] = {"spheres", "nosuch.x=1", "spheres.nosuch=1", NULL};
    for (int i = 0; bad[i]; i++) {
        fs_method_setting set;
        fs_method_setting_find(bad[i], &set);
        char want[300];
        snprintf(want, sizeof want, "%s", fs_error_message());
        fs_sweep sw[FS_MAX_SWEEPS];
        int n = 0;
        CHECK(fs_sweep_add(sw, &n, bad[i]) == FS_ERR_INPUT && !strcmp(fs_error_message(), want), "sweep %s: %s vs %s",
              bad[i], fs_error_message(), want);
        fs_scene s;
        fs_scene_defaults(&s);
        int rc = fs_scene_add_set(&s, bad[i]);
        if (!rc) rc = fs_method_params_resolve(fs_method_find("spheres"), &s, (double[FS_MAX_PARAMS]){0});
        CHECK(rc == FS_ERR_INPUT && !strcmp(fs_error_message(), want), "scene %s: %s vs %s", bad[i], fs_error_message(),
              want);
    }
}

static void fill(void)
{
    probe_params p;
    memset(&p, 0xff, sizeof p);
    CHECK(fs_method_params_fill(&probe, NULL, &p) == FS_OK, "fill defaults");
    CHECK(p.enabled && p.mode == MODE_B && p.gain == 0.5 && p.unused == 0, "defaults %d %d %g %d", p.enabled, p.mode,
          p.gain, p.unused);
    double v[3] = {0, 2, 7.25}; /* table order: enabled, mode, gain */
    CHECK(fs_method_params_fill(&probe, v, &p) == FS_OK && !p.enabled && p.mode == MODE_C && p.gain == 7.25,
          "values at their offsets, in their types: %d %d %g", p.enabled, p.mode, p.gain);
    /* an entry whose field's C type does not fit its kind (a bool parameter on an int field) */
    fs_param_def wrong[3];
    memcpy(wrong, probe_table, sizeof wrong);
    wrong[0].ctype = FS_CTYPE_INT;
    fs_method mistyped = probe;
    mistyped.params = wrong;
    CHECK(fs_method_params_fill(&mistyped, NULL, &p) == FS_ERR_RUNTIME && strstr(fs_error_message(), "C type"),
          "a field whose C type does not fit its kind is refused: %s", fs_error_message());
    fs_method small = probe;
    small.params_size = sizeof(double);
    CHECK(fs_method_params_fill(&small, NULL, &p) == FS_ERR_RUNTIME && strstr(fs_error_message(), "outside"),
          "a table that does not fit its struct: %s", fs_error_message());
    CHECK(fs_method_params_alloc(&small, NULL) == NULL, "alloc refuses it too");
}

/* Set by name in a scene, resolved, filled: create() reads named fields. */
static void by_name(void)
{
    fs_scene s;
    fs_scene_defaults(&s);
    CHECK(fs_scene_add_set(&s, "probe.gain=3") == FS_OK && fs_scene_add_set(&s, "probe.mode=c") == FS_OK &&
              fs_scene_add_set(&s, "spheres.thickness=off") == FS_OK,
          "settings");
    fs_run *run = NULL; /* resolves the settings by name and fills the struct */
    CHECK(fs_run_open(&run, &probe, &s, NULL, NULL) == FS_OK, "open: %s", fs_error_message());
    fs_run_close(run);
    CHECK(created.gain == 3 && created.mode == MODE_C && created.enabled, "created with %g %d %d", created.gain,
          created.mode, created.enabled);
}

/* Settings are parsed once, when added: a bad one is refused there, and a run reads the
 * stored value, not the text (overwritten here to prove it). */
static void parsed_once(void)
{
    fs_scene s;
    fs_scene_defaults(&s);
    CHECK(fs_scene_add_set(&s, "probe.mode=zz") == FS_ERR_INPUT && strstr(fs_error_message(), "probe.mode") &&
              s.nsets == 0,
          "a bad value is refused when added: %s", fs_error_message());
    CHECK(fs_scene_add_set(&s, "probe.nosuch=1") == FS_ERR_INPUT && s.nsets == 0, "an unknown parameter too: %s",
          fs_error_message());
    CHECK(fs_scene_add_set(&s, "probe.gain=4.5") == FS_OK && s.sets[0].method == &probe && s.sets[0].value == 4.5,
          "stored resolved: method %p, param %d, value %g", s.sets[0].method, s.sets[0].param, s.sets[0].value);
    snprintf(s.sets[0].text, sizeof s.sets[0].text, "probe.gain=9");
    double v[FS_MAX_PARAMS];
    CHECK(fs_method_params_resolve(&probe, &s, v) == FS_OK && v[2] == 4.5, "resolve reads the parsed value: %g", v[2]);
}

/* Every built-in table fits its struct, one distinct double per parameter, and
 * every method refuses a setup without its struct (before touching OpenGL). */
static void builtin_tables(void)
{
    for (int i = 0; i < fs_method_count(); i++) {
        const fs_method *m = fs_method_at(i);
        /* every field is a parameter (a field without a table entry would stay 0): laid out in
         * offset order, each field starts where the one before ends, aligned, and the struct
         * ends after the last (a field hidden in alignment padding is not seen) */
        CHECK(m->nparams <= FS_MAX_PARAMS, "%s: %d parameters", m->name, m->nparams);
        size_t end = 0, align = 1;
        for (size_t off = 0, n = 0; n < (size_t)m->nparams; n++) {
            int at = -1;
            for (int a = 0; a < m->nparams; a++)
                if (m->params[a].offset >= off && (at < 0 || m->params[a].offset < m->params[at].offset)) at = a;
            size_t size = fs_param_ctype_size(m->params[at].ctype);
            size_t want = (end + size - 1) / size * size;
            CHECK(m->params[at].offset == want, "%s: %s at byte %zu, the field before it ends at %zu", m->name,
                  m->params[at].name, m->params[at].offset, end);
            end = m->params[at].offset + size, off = end, align = size > align ? size : align;
        }
        CHECK(m->params_size == (end + align - 1) / align * align, "%s: %zu bytes, its fields end at %zu", m->name,
              m->params_size, end);
        void *p = fs_method_params_alloc(m, NULL);
        CHECK(p != NULL, "%s: fill: %s", m->name, fs_error_message());
        free(p);
    }
}

/* Every listed method declares its cost for compare --shard's split (a method
 * without one would be refused there), in units of spheres' view. */
static void declared_costs(void)
{
    CHECK(fs_method_count() >= 6, "%d built-in methods registered", fs_method_count());
    for (int i = 0; i < fs_method_count(); i++) {
        const fs_method *m = fs_method_at(i);
        CHECK(m->cost > 0 && isfinite(m->cost), "%s: cost %g, must be > 0 (fs_method.cost)", m->name, m->cost);
    }
    const fs_method *unit = fs_method_find("spheres");
    CHECK(unit && unit->cost == 1, "spheres is the unit of cost");
}

int main(void)
{
    fs_methods_register_builtin();
    CHECK(fs_method_register(&probe, FS_METHOD_HIDDEN) == FS_OK, "register probe");
    split();
    same_messages();
    fill();
    by_name();
    parsed_once();
    builtin_tables();
    declared_costs();
    TEST_DONE();
}
