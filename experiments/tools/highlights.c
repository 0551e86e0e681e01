/* highlights: how the specular highlight of a shaded G-buffer is laid out, for
 * xu2022's Fig. 8 claim that a smooth transparent surface "forms an obvious
 * bright area" where a noisy one scatters speckles.
 *
 *   highlights [--threshold Y] [--min-area PX] IMAGE.exr...
 *
 * Over the pixels the image covers (coverage > 0.5), a highlight pixel has linear
 * luminance (Rec. 709) of at least Y (default 0.7; no one value separates the
 * specular term from bright refracted background everywhere, so studies sweep it).
 * Highlight pixels are grouped into 4-connected areas. Prints CSV rows
 *   file,covered_px,highlight_px,highlight_pct,areas,largest_px,share_in_large_pct
 * where share_in_large is the part of the highlight pixels that lie in areas of at
 * least PX pixels (default 16): near 100 for a few broad highlights, low for speckle. */
#include "fs_error.h"
#include "image_io.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The size of the 4-connected area of marked pixels holding pixel s, which it
 * clears; stack has room for w*h indices. */
static long flood(unsigned char *mark, int w, int h, long s, long *stack)
{
    long n = 0, top = 0;
    stack[top++] = s;
    mark[s] = 0;
    while (top) {
        long p = stack[--top];
        n++;
        int x = (int)(p % w), y = (int)(p / w);
        long next[4] = {x > 0 ? p - 1 : -1, x + 1 < w ? p + 1 : -1, y > 0 ? p - w : -1, y + 1 < h ? p + w : -1};
        for (int k = 0; k < 4; k++)
            if (next[k] >= 0 && mark[next[k]]) mark[next[k]] = 0, stack[top++] = next[k];
    }
    return n;
}

static int measure(const char *path, float threshold, long min_area)
{
    fs_image img;
    if (fs_read_image(path, &img)) return 1;
    int r = fs_image_channel(&img, "R"), g = fs_image_channel(&img, "G"), b = fs_image_channel(&img, "B");
    int cov = fs_image_channel(&img, "coverage");
    if (r < 0 || g < 0 || b < 0 || cov < 0) {
        fs_image_free(&img);
        return fs_fail(FS_ERR_INPUT, "%s: needs channels R, G, B and coverage (a fluidsurf G-buffer EXR)", path), 1;
    }
    long n = (long)img.w * img.h, covered = 0, lit = 0;
    unsigned char *mark = calloc((size_t)n, 1);
    long *stack = malloc((size_t)n * sizeof *stack);
    if (!mark || !stack) {
        free(mark), free(stack), fs_image_free(&img);
        return fs_fail(FS_ERR_RUNTIME, "out of memory"), 1;
    }
    for (long i = 0; i < n; i++) {
        const float *px = img.pix + i * img.nch;
        if (!(px[cov] > 0.5f)) continue;
        covered++;
        float y = 0.2126f * px[r] + 0.7152f * px[g] + 0.0722f * px[b];
        if (y >= threshold) mark[i] = 1, lit++;
    }
    long areas = 0, largest = 0, in_large = 0;
    for (long i = 0; i < n; i++) {
        if (!mark[i]) continue;
        long a = flood(mark, img.w, img.h, i, stack);
        areas++;
        if (a > largest) largest = a;
        if (a >= min_area) in_large += a;
    }
    printf("%s,%ld,%ld,%.3f,%ld,%ld,%.1f\n", path, covered, lit, covered ? 100.0 * lit / covered : 0.0, areas, largest,
           lit ? 100.0 * in_large / lit : 0.0);
    free(mark);
    free(stack);
    fs_image_free(&img);
    return 0;
}

int main(int argc, char **argv)
{
    float threshold = 0.7f;
    long min_area = 16;
    int i = 1;
    for (; i + 1 < argc && argv[i][0] == '-' && argv[i][1] == '-'; i += 2) {
        if (!strcmp(argv[i], "--threshold")) threshold = strtof(argv[i + 1], NULL);
        else if (!strcmp(argv[i], "--min-area")) min_area = strtol(argv[i + 1], NULL, 10);
        else break;
    }
    if (i >= argc || !(threshold > 0) || min_area < 1) {
        fprintf(stderr, "usage: highlights [--threshold Y] [--min-area PX] IMAGE.exr...\n");
        return 2;
    }
    printf("file,covered_px,highlight_px,highlight_pct,areas,largest_px,share_in_large_pct\n");
    for (; i < argc; i++)
        if (measure(argv[i], threshold, min_area)) {
            fprintf(stderr, "highlights: %s\n", fs_error_message());
            return 1;
        }
    return 0;
}
