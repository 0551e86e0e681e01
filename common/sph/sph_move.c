/* Moving the container (sph.h fs_sph_move_box), for the viewer's "push the
 * fluid" drag as in inacio2010's video: the boundary particles and the box
 * translate, and the walls push the fluid like any wall (past a wall, the
 * safety clamp into the moved box); a scene's obstacles move with them. The walls move a little before every step,
 * in proportion to its length: a jump of even r/10 is felt at once through the
 * stiff near-wall repulsion and throws the fluid at several m/s. */
#include "fs_error.h"
#include "sph_internal.h"

static int translate(fs_sph *s, const float d[3])
{
    for (size_t i = 0; i < s->nb; i++) { /* boundary particles: static, so their CPU copy is current */
        s->x[i] += d[0];
        s->y[i] += d[1];
        s->z[i] += d[2];
    }
    for (int a = 0; a < 3; a++) {
        s->box_lo[a] += d[a];
        s->box_hi[a] += d[a];
    }
    for (int k = 0; k < s->obstacles.n; k++) /* the solids' boundary particles moved with the walls */
        fs_obstacle_transform(&s->obstacles.o[k], 1.0f, d);
    return s->gpu && s->nb ? fs_sph_gpu_upload(s, 0, s->nb) : FS_OK;
}

int fs_sph_move_box(fs_sph *s, const float delta[3], double frame_dt)
{
    if (!(frame_dt > 0)) return translate(s, delta);
    double end = s->st.t + frame_dt;
    while (s->st.t < end - 1e-7 * frame_dt) { /* the step choice of fs_sph_advance */
        double left = end - s->st.t, dt = s->prm.fixed_dt > 0 ? s->prm.fixed_dt : fs_sph_dt_bound(s);
        if (dt >= left) dt = left;
        else if (dt > 0.5 * left && !(s->prm.fixed_dt > 0)) dt = 0.5 * left;
        float f = (float)(dt / frame_dt), d[3] = {delta[0] * f, delta[1] * f, delta[2] * f};
        int rc = translate(s, d);
        if (!rc) rc = fs_sph_step(s, (float)dt);
        if (rc) return rc;
    }
    return FS_OK;
}
