/* A study's output folder (docs/DESIGN.md, "Output folders"): which files in it
 * are fluidsurf's own, and the refusal of a folder that holds another run's.
 *
 * Every file compare (or merge) renames into the folder is recorded, as it is
 * written, in DIR/fluidsurf-outputs.txt: a first line "fluidsurf-outputs 1", then
 * one file name per line (a name may repeat). That list is what --force removes,
 * and nothing else. A folder an older fluidsurf wrote has no list; its files are
 * recognised by their fixed names (metrics.csv, report.md, panel.png, ...), and
 * its images as the EXRs that carry fluidsurf's provenance with the PNGs named
 * after them (LABEL.png, LABEL_own.png, diff_LABEL.png). */
#ifndef FS_OUTPUTS_LIST_H
#define FS_OUTPUTS_LIST_H

#define FS_OUTPUTS_LIST "fluidsurf-outputs.txt"

/* Before anything is written into dir: FS_OK when it holds no output of an
 * earlier run (fresh, empty, only other files), or resume is set (what matches
 * is kept, resume.h). Else FS_ERR_INPUT in one line naming dir and what
 * it holds, unless force: then fluidsurf's own files are removed first, never
 * any other file. what: the command, for the message ("compare", "merge"). */
int fs_outputs_claim(const char *dir, const char *what, int resume, int force);
/* compare --resume: FS_ERR_INPUT in one line when dir holds an earlier run's
 * view (an EXR, LABEL.exr or LABEL_fNNNN.exr) that is none of the n labels of
 * this run's views (another method list or sweep), whose files would stay
 * beside this run's tables; FS_OK otherwise. */
int fs_outputs_resume_check(const char *dir, const char *const *labels, int n);
/* Records path ("DIR/NAME", a file just renamed into place) in DIR's list. */
int fs_outputs_record(const char *path);

#endif
