/* Where the study's work items come from (study.h): the caller's hooks asked
 * once per item, for the executor and the caller's plans alike. */
#include "study.h"

fs_item_where fs_study_item_where(const fs_study *s, const fs_study_io *io, int is_ref, int index, int f)
{
    if (!is_ref && s->entries[index].imported) return FS_ITEM_SKIP;
    return io && io->where ? io->where(io->user, s, fs_study_item_id(s, is_ref, index, f)) : FS_ITEM_RENDER;
}

int fs_study_needs_gl(const fs_study *s, const fs_study_io *io)
{
    for (int i = 0; i < s->nentries; i++)
        for (int f = 0; s->entries[i].v.m && s->entries[i].v.m->needs_gl && f < s->nframes; f++)
            if (fs_study_item_where(s, io, 0, i, f) == FS_ITEM_RENDER) return 1;
    return 0;
}

long fs_study_items_here(const fs_study *s, const fs_study_io *io)
{
    long n = 0;
    for (int f = 0; f < s->nframes; f++)
        for (int i = -s->nrefs; i < s->nentries; i++) {
            int is_ref = i < 0, index = is_ref ? i + s->nrefs : i;
            n += fs_study_item_where(s, io, is_ref, index, f) != FS_ITEM_SKIP;
        }
    return n;
}
