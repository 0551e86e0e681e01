/* The interactive viewer's state and input handling (cmd_view.c runs the
 * window; view_input.c handles keys and the mouse; view_script.c replays timed
 * input from a script through the same handlers, for tests). Keys and mouse
 * buttons are GLFW codes. */
#ifndef FS_VIEW_H
#define FS_VIEW_H
#include "orbit_camera.h"

enum { VIEW_DRAG_NONE = 0, VIEW_DRAG_ORBIT, VIEW_DRAG_PAN, VIEW_DRAG_BOX };

typedef struct fs_view {
    fs_orbit orbit, home; /* current and initial camera (R resets) */
    int view_h;           /* window height in pixels, for pan and box drags */
    int nmethods, method; /* registry index of the method shown */
    int own;              /* 1: the method's own appearance where it has one */
    float scale;          /* G-buffer size / window size */
    int playing, step;    /* step: advance one frame while paused */
    int quit;
    int redraw;           /* counts window exposures: draw again */
    int shot;             /* save a screenshot after the next frame */
    char shot_path[1024]; /* "" : a numbered name in the working folder */
    int drag;             /* VIEW_DRAG_* while a button is held */
    double mx, my;        /* last cursor position */
    int can_move_box;     /* a simulator runs: the container can be moved */
    float box_move[3];    /* container translation asked for, not yet applied */
    float box_step;       /* world units per arrow key press */
} fs_view;

void view_key(fs_view *v, int key, int mods);
void view_button(fs_view *v, int button, int press, int mods, double x, double y);
void view_cursor(fs_view *v, double x, double y);
void view_scroll(fs_view *v, double dy);

/* Scripted input: lines "frame N ACTION ARGS" (also ';'-separated), '#' comments.
 *   key NAME [shift|ctrl|alt]...      NAME: a-z, 0-9, space, escape, plus, minus,
 *                                     left, right, up, down, period
 *   drag X0 Y0 X1 Y1 [left|right|middle] [shift|ctrl|alt]...
 *   scroll DY
 *   screenshot PATH
 *   quit                                                                   */
typedef struct view_action {
    int frame, kind;
    int key, button, mods;
    double a[4];
    char path[1024];
} view_action;
typedef struct view_script {
    view_action *act;
    int n, next;
} view_script;

/* FS_ERR_INPUT "what:LINE: ..." for a malformed line; actions sorted by frame. */
int view_script_parse(view_script *s, const char *text, const char *what);
/* Applies the actions of frame `frame` through the handlers above. */
void view_script_apply(view_script *s, fs_view *v, int frame);
void view_script_free(view_script *s);

#endif
