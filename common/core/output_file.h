/* Safe output: write to "<dir>/.<name>.tmpXXXXXX", then rename over the target
 * on success, or remove it on failure. Nothing half-written is ever left. */
#ifndef FS_OUTPUT_FILE_H
#define FS_OUTPUT_FILE_H
#include <stdio.h>
#ifdef __cplusplus
extern "C" {
#endif

/* Fills tmp with a fresh temporary path next to final (created empty, mode 0644).
 * FS_ERR_INPUT when the folder does not exist or is not writable, or when final
 * exists and is not a regular file (a device node, a FIFO: never replaced). */
int fs_output_begin(const char *final, char *tmp, int size);
/* ok != 0: rename tmp to final; else unlink tmp. Returns FS_OK or an error. */
int fs_output_end(const char *final, const char *tmp, int ok);
/* The same through stdio, for every file written with a FILE: fs_output_open
 * makes the temporary and opens it for binary writing; fs_output_close checks
 * every write (ferror) and the close, then renames it into place, or removes it
 * when ok is 0 or anything failed: FS_OK, FS_ERR_RUNTIME "FINAL: cannot write:
 * REASON" after a failed write or close, or FS_ERR_RUNTIME with the caller's
 * message when ok is 0 (the caller's own failure). */
typedef struct fs_output {
    char final[4096], tmp[4096];
    FILE *f;
} fs_output;
int fs_output_open(fs_output *o, const char *final);
int fs_output_close(fs_output *o, int ok);
/* Removes every temporary of an output still in progress (async-signal-safe). */
void fs_output_abandon_all(void);
/* 1 when path ends in suffix, ignoring case (".vdb", ".bgeo.gz"). */
int fs_path_ends_with(const char *path, const char *suffix);

#ifdef __cplusplus
}
#endif
#endif
