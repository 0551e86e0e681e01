/* The camera's one-line text (camera_text.h). */
#include "camera_text.h"
#include "fs_error.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { KEY_EYE = 8, KEY_TARGET = 16 };

/* n comma-separated finite numbers filling the whole of v; 0 when malformed. */
static int numbers(const char *v, float *out, int n)
{
    for (int i = 0; i < n; i++) {
        char *end;
        out[i] = strtof(v, &end);
        if (end == v || !isfinite(out[i]) || *end != (i + 1 < n ? ',' : '\0')) return 0;
        v = end + 1;
    }
    return 1;
}

/* up as an axis letter or three numbers, not zero. */
static int up_value(const char *v, float up[3])
{
    if (v[0] >= 'x' && v[0] <= 'z' && !v[1]) {
        for (int i = 0; i < 3; i++) up[i] = i == v[0] - 'x' ? 1.0f : 0.0f;
        return 1;
    }
    return numbers(v, up, 3) && up[0] * up[0] + up[1] * up[1] + up[2] * up[2] > 0;
}

static int size_value(const char *v, int *w, int *h)
{
    char *end;
    long a = strtol(v, &end, 10), b = *end == 'x' ? strtol(end + 1, &end, 10) : 0;
    if (*end || a < 1 || a > 16384 || b < 1 || b > 16384) return 0;
    *w = (int)a, *h = (int)b;
    return 1;
}

static const char *const KEYS[] = {"up", "fov", "size", "eye", "target"};
static const char *const BAD[] = {"up must be x, y, z or three numbers, not all 0",
                                  "fov must be a number of degrees in [1, 170]", "size must be WxH, each 1 to 16384",
                                  "eye must be three numbers X,Y,Z", "target must be three numbers X,Y,Z"};

/* The value v of KEYS[k] into c; 0 when malformed. */
static int parse_value(int k, const char *v, fs_camera *c)
{
    switch (k) {
    case 0: return up_value(v, c->up);
    case 1: return numbers(v, &c->fovy_deg, 1) && c->fovy_deg >= 1 && c->fovy_deg <= 170;
    case 2: return size_value(v, &c->width, &c->height);
    default: return numbers(v, k == 3 ? c->eye : c->target, 3);
    }
}

/* One "key=value" item into c: the key's bit, or 0 with why set. */
static unsigned parse_item(const char *item, fs_camera *c, const char **why)
{
    const char *v = strchr(item, '=');
    size_t klen = v ? (size_t)(v - item) : strlen(item);
    for (int k = 0; k < 5; k++) {
        if (strlen(KEYS[k]) != klen || strncmp(item, KEYS[k], klen)) continue;
        if (v && parse_value(k, v + 1, c)) return 1u << k;
        *why = BAD[k];
        return 0;
    }
    *why = "unknown key (the keys: eye, target, up, fov, size)";
    return 0;
}

int fs_camera_parse(const char *text, const char *what, fs_camera *c, unsigned *given)
{
    char buf[FS_CAMERA_TEXT_MAX];
    if (strlen(text) >= sizeof buf) return fs_fail(FS_ERR_INPUT, "%s: camera '%.60s...': too long", what, text);
    strcpy(buf, text);
    fs_camera t = *c;
    unsigned got = 0;
    const char *why = NULL;
    for (char *save, *item = strtok_r(buf, ";", &save); item && !why; item = strtok_r(NULL, ";", &save)) {
        unsigned bit = parse_item(item, &t, &why);
        if (bit & got) why = "a key is given twice";
        got |= bit;
    }
    if (!why && !(got & KEY_EYE)) why = "eye=X,Y,Z is missing";
    if (!why && !(got & KEY_TARGET)) why = "target=X,Y,Z is missing";
    float d[3] = {t.target[0] - t.eye[0], t.target[1] - t.eye[1], t.target[2] - t.eye[2]};
    if (!why && !(d[0] * d[0] + d[1] * d[1] + d[2] * d[2] > 1e-20f)) why = "target must differ from eye";
    if (why) return fs_fail(FS_ERR_INPUT, "%s: camera '%s': %s", what, text, why);
    *c = t;
    if (given) *given = got & (FS_CAMERA_HAS_UP | FS_CAMERA_HAS_FOV | FS_CAMERA_HAS_SIZE);
    return FS_OK;
}

void fs_camera_format(const fs_camera *c, char *buf, int size)
{
    snprintf(buf, (size_t)size, "eye=%.9g,%.9g,%.9g;target=%.9g,%.9g,%.9g;up=%.9g,%.9g,%.9g;fov=%.9g;size=%dx%d",
             c->eye[0], c->eye[1], c->eye[2], c->target[0], c->target[1], c->target[2], c->up[0], c->up[1], c->up[2],
             c->fovy_deg, c->width, c->height);
}
