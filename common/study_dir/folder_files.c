/* The study folder's files (study_dir_state.h): their paths, each opened
 * through a temporary file and listed in the folder's fluidsurf-outputs.txt
 * before it is written (outputs_list.h), PNGs and the CSV tables. */
#include "study_dir_state.h"
#include "outputs_list.h"
#include "study_tables.h"
#include "fs_error.h"
#include "image_io.h"
#include <stdio.h>

void fs_study_dir_path(const fs_study_dir *r, const char *name, char *buf, int size)
{
    snprintf(buf, size, "%s/%s", r->outdir, name);
}

void fs_study_dir_view_path(const fs_study_dir *r, const char *dir, const char *label, int frame, const char *suffix,
                            const char *ext, char *path, int size)
{
    if (r->s->sequence) snprintf(path, size, "%s/%s%s_f%04d.%s", dir ? dir : r->outdir, label, suffix, frame, ext);
    else snprintf(path, size, "%s/%s%s.%s", dir ? dir : r->outdir, label, suffix, ext);
}

int fs_study_dir_open(const fs_study_dir *r, const char *name, fs_output *cf)
{
    char path[1400];
    fs_study_dir_path(r, name, path, sizeof path);
    int rc = fs_outputs_record(path);
    return rc ? rc : fs_output_open(cf, path);
}

int fs_study_dir_close(fs_output *cf) { return fs_output_close(cf, 1); }

int fs_study_dir_write_rgba(const fs_study_dir *r, const char *name, const fs_rgba_image *im)
{
    char path[1400];
    fs_study_dir_path(r, name, path, sizeof path);
    const char *names[4] = {"R", "G", "B", "A"};
    fs_image img = {im->w, im->h, 4, names, im->pix};
    int rc = fs_outputs_record(path);
    return rc ? rc : fs_write_png(path, &img);
}

/* DIR/NAME.csv: the study's table NAME (study_tables.h). */
int fs_study_dir_write_table(const fs_study_dir *r, const char *name)
{
    fs_output cf;
    char file[64];
    snprintf(file, sizeof file, "%s.csv", name);
    int rc = fs_study_dir_open(r, file, &cf);
    if (rc) return rc;
    rc = fs_study_write_table(r->s, name, cf.f);
    return rc ? (fs_output_close(&cf, 0), rc) : fs_study_dir_close(&cf);
}
