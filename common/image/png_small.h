/* A small PNG of an RGBA image: to keep a look at what a timing run rendered
 * (experiments/gpu/run.sh keeps one of each timed cell) without megabytes of
 * full-size images. */
#ifndef FS_PNG_SMALL_H
#define FS_PNG_SMALL_H

/* Writes rgba (4 floats a pixel, w x h, rows top to bottom) to path, shrunk by the
 * smallest whole factor that brings its longer side to at most max_side (a box
 * filter; factor 1 when it fits). FS_OK or an error code with fs_fail set. */
int fs_write_png_small(const char *path, const float *rgba, int w, int h, int max_side);

#endif
