/* Scripted viewer input (view.h): timed actions replayed through the same
 * handlers the GLFW callbacks call. */
#include "fs_error.h"
#include "view.h"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { A_KEY, A_DRAG, A_SCROLL, A_SHOT, A_QUIT };

static int key_code(const char *name)
{
    static const struct {
        const char *name;
        int key;
    } named[] = {
        {"space", GLFW_KEY_SPACE}, {"escape", GLFW_KEY_ESCAPE}, {"plus", GLFW_KEY_EQUAL},
        {"minus", GLFW_KEY_MINUS}, {"left", GLFW_KEY_LEFT},     {"right", GLFW_KEY_RIGHT},
        {"up", GLFW_KEY_UP},       {"down", GLFW_KEY_DOWN},     {"period", GLFW_KEY_PERIOD},
    };
    if (name[0] && !name[1]) {
        if (name[0] >= 'a' && name[0] <= 'z') return GLFW_KEY_A + (name[0] - 'a');
        if (name[0] >= '0' && name[0] <= '9') return GLFW_KEY_0 + (name[0] - '0');
    }
    for (size_t i = 0; i < sizeof named / sizeof *named; i++)
        if (!strcmp(name, named[i].name)) return named[i].key;
    return -1;
}

/* A modifier or button word: adds to *mods / sets *button; 0 if neither. */
static int modifier(const char *w, int *mods, int *button)
{
    if (!strcmp(w, "shift")) *mods |= GLFW_MOD_SHIFT;
    else if (!strcmp(w, "ctrl")) *mods |= GLFW_MOD_CONTROL;
    else if (!strcmp(w, "alt")) *mods |= GLFW_MOD_ALT;
    else if (button && !strcmp(w, "left")) *button = GLFW_MOUSE_BUTTON_LEFT;
    else if (button && !strcmp(w, "right")) *button = GLFW_MOUSE_BUTTON_RIGHT;
    else if (button && !strcmp(w, "middle")) *button = GLFW_MOUSE_BUTTON_MIDDLE;
    else return 0;
    return 1;
}

static int number(const char *w, double *out)
{
    char *end;
    *out = w ? strtod(w, &end) : 0;
    return w && end != w && !*end;
}

/* One action "frame N ACTION ARGS" split into words. */
static int parse_action(view_action *a, char **w, int n, const char *what, int line)
{
    memset(a, 0, sizeof *a);
    double f;
    if (n < 3 || strcmp(w[0], "frame") || !number(w[1], &f) || f < 0 || f > 1e8 || f != (int)f)
        return fs_fail(FS_ERR_INPUT, "%s:%d: expected 'frame N ACTION ...'", what, line);
    a->frame = (int)f;
    const char *act = w[2];
    int extra = 3; /* first word after the action's fixed arguments */
    if (!strcmp(act, "key")) {
        a->kind = A_KEY;
        if (n < 4 || (a->key = key_code(w[3])) < 0)
            return fs_fail(FS_ERR_INPUT, "%s:%d: key: unknown key name", what, line);
        extra = 4;
    } else if (!strcmp(act, "drag")) {
        a->kind = A_DRAG;
        a->button = GLFW_MOUSE_BUTTON_LEFT;
        for (int k = 0; k < 4; k++)
            if (!number(3 + k < n ? w[3 + k] : NULL, &a->a[k]))
                return fs_fail(FS_ERR_INPUT, "%s:%d: drag: expected X0 Y0 X1 Y1", what, line);
        extra = 7;
    } else if (!strcmp(act, "scroll")) {
        a->kind = A_SCROLL;
        if (!number(n > 3 ? w[3] : NULL, &a->a[0]))
            return fs_fail(FS_ERR_INPUT, "%s:%d: scroll: expected DY", what, line);
        extra = 4;
    } else if (!strcmp(act, "screenshot")) {
        a->kind = A_SHOT;
        if (n < 4 || strlen(w[3]) >= sizeof a->path)
            return fs_fail(FS_ERR_INPUT, "%s:%d: screenshot: expected a PNG path", what, line);
        strcpy(a->path, w[3]);
        extra = 4;
    } else if (!strcmp(act, "quit")) {
        a->kind = A_QUIT;
    } else {
        return fs_fail(FS_ERR_INPUT, "%s:%d: unknown action '%s' (key, drag, scroll, screenshot, quit)", what, line,
                       act);
    }
    for (int k = extra; k < n; k++) {
        int ok =
            (a->kind == A_KEY || a->kind == A_DRAG) && modifier(w[k], &a->mods, a->kind == A_DRAG ? &a->button : NULL);
        if (!ok) return fs_fail(FS_ERR_INPUT, "%s:%d: unexpected '%s'", what, line, w[k]);
    }
    return FS_OK;
}

int view_script_parse(view_script *s, const char *text, const char *what)
{
    memset(s, 0, sizeof *s);
    char *buf = strdup(text);
    if (!buf) return fs_fail(FS_ERR_RUNTIME, "out of memory");
    /* positions: lines of a file; actions of a one-line --events text */
    int rc = FS_OK, line = 1, cap = 0, by_action = !strchr(text, '\n');
    for (char *p = buf; *p && !rc;) {
        size_t len = strcspn(p, ";\n");
        int newline = p[len] == '\n', end = !p[len];
        p[len] = 0;
        char *hash = strchr(p, '#');
        if (hash) *hash = 0;
        char *w[16];
        int n = 0;
        for (char *tok = strtok(p, " \t\r"); tok; tok = strtok(NULL, " \t\r")) {
            if (n == 16) {
                rc = fs_fail(FS_ERR_INPUT, "%s:%d: too many words", what, line);
                break;
            }
            w[n++] = tok;
        }
        if (!rc && n) {
            if (s->n == cap) {
                cap = cap ? 2 * cap : 16;
                view_action *na = realloc(s->act, cap * sizeof *na);
                if (!na) {
                    rc = fs_fail(FS_ERR_RUNTIME, "out of memory");
                    break;
                }
                s->act = na;
            }
            if (!(rc = parse_action(&s->act[s->n], w, n, what, line))) s->n++;
        }
        line += newline || by_action;
        p += len + !end;
    }
    free(buf);
    if (rc) {
        view_script_free(s);
        return rc;
    }
    /* insertion sort by frame: stable, so one frame's actions keep their written order */
    for (int i = 1; i < s->n; i++)
        for (int j = i; j > 0 && s->act[j].frame < s->act[j - 1].frame; j--) {
            view_action t = s->act[j];
            s->act[j] = s->act[j - 1];
            s->act[j - 1] = t;
        }
    return FS_OK;
}

void view_script_apply(view_script *s, fs_view *v, int frame)
{
    for (; s->next < s->n && s->act[s->next].frame <= frame; s->next++) {
        const view_action *a = &s->act[s->next];
        switch (a->kind) {
        case A_KEY: view_key(v, a->key, a->mods); break;
        case A_DRAG:
            /* press, move in a few steps as a hand would, release */
            view_button(v, a->button, 1, a->mods, a->a[0], a->a[1]);
            for (int k = 1; k <= 4; k++)
                view_cursor(v, a->a[0] + (a->a[2] - a->a[0]) * k / 4, a->a[1] + (a->a[3] - a->a[1]) * k / 4);
            view_button(v, a->button, 0, a->mods, a->a[2], a->a[3]);
            break;
        case A_SCROLL: view_scroll(v, a->a[0]); break;
        case A_SHOT:
            v->shot = 1;
            snprintf(v->shot_path, sizeof v->shot_path, "%s", a->path);
            break;
        case A_QUIT: v->quit = 1; break;
        }
    }
}

void view_script_free(view_script *s)
{
    free(s->act);
    memset(s, 0, sizeof *s);
}
