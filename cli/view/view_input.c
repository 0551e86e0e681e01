/* Keyboard and mouse handling of the viewer: the GLFW callbacks and the test
 * scripts both call these, so scripted tests run the real code paths. */
#include "view.h"
#include "vec3.h"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <math.h>

/* The camera's right and forward directions laid flat on the floor plane: a
 * box drag moves the container horizontally whatever the camera's pitch. */
static void flat_axes(const fs_view *v, float right[3], float fwd[3])
{
    fs_camera c = {0};
    float up[3];
    fs_orbit_apply(&v->orbit, &c);
    fs_camera_basis(&c, right, up, fwd);
    int u = v->orbit.up_axis;
    right[u] = fwd[u] = 0;
    float lr = fs_v3_len(right);
    float lf = fs_v3_len(fwd);
    for (int k = 0; k < 3; k++) {
        right[k] = lr > 0 ? right[k] / lr : 0;
        fwd[k] = lf > 0 ? fwd[k] / lf : 0;
    }
}

static void move_box(fs_view *v, float along_right, float along_fwd)
{
    if (!v->can_move_box) return;
    float right[3], fwd[3];
    flat_axes(v, right, fwd);
    for (int k = 0; k < 3; k++) v->box_move[k] += along_right * right[k] + along_fwd * fwd[k];
}

static void set_scale(fs_view *v, float s) { v->scale = fmaxf(1.0f / 16, fminf(2.0f, s)); }

void view_key(fs_view *v, int key, int mods)
{
    (void)mods;
    if (key >= GLFW_KEY_1 && key <= GLFW_KEY_9) {
        int i = key - GLFW_KEY_1;
        if (i < v->nmethods) v->method = i;
        return;
    }
    switch (key) {
    case GLFW_KEY_ESCAPE:
    case GLFW_KEY_Q: v->quit = 1; break;
    case GLFW_KEY_SPACE: v->playing = !v->playing; break;
    case GLFW_KEY_N:
    case GLFW_KEY_PERIOD:
        v->step = 1;
        v->playing = 0;
        break;
    case GLFW_KEY_S:
        v->shot = 1;
        v->shot_path[0] = 0;
        break;
    case GLFW_KEY_O: v->own = !v->own; break;
    case GLFW_KEY_R: v->orbit = v->home; break;
    case GLFW_KEY_EQUAL: /* '+' shares the key with '=' on US layouts */
    case GLFW_KEY_KP_ADD: set_scale(v, v->scale * 1.25f); break;
    case GLFW_KEY_MINUS:
    case GLFW_KEY_KP_SUBTRACT: set_scale(v, v->scale / 1.25f); break;
    case GLFW_KEY_LEFT: move_box(v, -v->box_step, 0); break;
    case GLFW_KEY_RIGHT: move_box(v, v->box_step, 0); break;
    case GLFW_KEY_UP: move_box(v, 0, v->box_step); break;
    case GLFW_KEY_DOWN: move_box(v, 0, -v->box_step); break;
    default: break;
    }
}

void view_button(fs_view *v, int button, int press, int mods, double x, double y)
{
    v->mx = x;
    v->my = y;
    if (!press) {
        v->drag = VIEW_DRAG_NONE;
        return;
    }
    if (button == GLFW_MOUSE_BUTTON_LEFT)
        v->drag = (mods & (GLFW_MOD_SHIFT | GLFW_MOD_CONTROL)) && v->can_move_box ? VIEW_DRAG_BOX : VIEW_DRAG_ORBIT;
    else if (button == GLFW_MOUSE_BUTTON_RIGHT || button == GLFW_MOUSE_BUTTON_MIDDLE) v->drag = VIEW_DRAG_PAN;
}

void view_cursor(fs_view *v, double x, double y)
{
    float dx = (float)(x - v->mx), dy = (float)(y - v->my);
    v->mx = x;
    v->my = y;
    switch (v->drag) {
    case VIEW_DRAG_ORBIT: fs_orbit_rotate(&v->orbit, dx, dy); break;
    case VIEW_DRAG_PAN: fs_orbit_pan(&v->orbit, dx, dy, v->view_h); break;
    case VIEW_DRAG_BOX: {
        /* the container follows the cursor on the floor plane: up the screen is away */
        float s = fs_orbit_pixel_size(&v->orbit, v->view_h);
        move_box(v, dx * s, -dy * s);
        break;
    }
    default: break;
    }
}

void view_scroll(fs_view *v, double dy) { fs_orbit_zoom(&v->orbit, (float)dy); }
