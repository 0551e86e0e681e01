/* compare --resume: a work item (one variant on one frame) whose EXR is in the
 * output folder, stamped with this run's provenance, is loaded instead of rendered.
 * The EXR is written last of an item's files and renamed into place whole, so its
 * presence means the item finished. It carries the item's timings, so the tables
 * of a resumed run hold the times measured when each item was rendered. */
#ifndef FS_RESUME_H
#define FS_RESUME_H
#include "study_dir_state.h"

/* Adds to prov the item's key (a digest of prov as it is: commit, scene, camera,
 * method, parameters, frame), its frame time and, on the first frame, its timed
 * runs' stages. */
void fs_resume_stamp(fs_provenance *prov, const fs_study_entry *e, int f);
/* 1 when exr holds this item (prov: as before fs_resume_stamp): v is loaded and
 * e's frame time (and on f == 0 its `repeat` runs) restored; 0 when it must be
 * rendered (missing, another run's, timed with another --repeat, unreadable);
 * never an error. */
int fs_resume_load(fs_study_entry *e, int f, int repeat, const fs_provenance *prov, const char *exr, fs_run_image *v);

/* Timed runs as one line, "stage=ms/gpu_ms,...;..." (a ';' between runs): 0 when
 * it does not fit in size. Parsed back into at most max runs: their count, 0 when
 * the text does not parse (stage names are interned: at most 64 distinct ones). */
int fs_runs_format(const fs_stages *runs, int nruns, char *buf, int size);
int fs_runs_parse(const char *text, fs_stages *runs, int max);

#endif
