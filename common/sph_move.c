/* Moving the container (sph.h fs_sph_move_box), for the viewer's "push the
 * fluid" drag as in inacio2010's video: the boundary particles and the box
 * translate; the fluid is then pushed by the walls' pressure like by any wall
 * (and, past a wall, by the safety clamp into the moved box). */
#include "fs_error.h"
#include "sph_internal.h"

int fs_sph_move_box(fs_sph *s, const float delta[3])
{
    for (size_t i = 0; i < s->nb; i++) { /* boundary particles: static, so their CPU copy is current */
        s->x[i] += delta[0];
        s->y[i] += delta[1];
        s->z[i] += delta[2];
    }
    for (int a = 0; a < 3; a++) {
        s->box_lo[a] += delta[a];
        s->box_hi[a] += delta[a];
    }
    return s->gpu && s->nb ? fs_sph_gpu_upload(s, 0, s->nb) : FS_OK;
}
