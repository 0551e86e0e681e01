/* Safe output: write to "<dir>/.<name>.tmpXXXXXX", then rename over the target
 * on success, or remove it on failure. Nothing half-written is ever left. */
#ifndef FS_OUTPUT_FILE_H
#define FS_OUTPUT_FILE_H
#ifdef __cplusplus
extern "C" {
#endif

/* Fills tmp with a fresh temporary path next to final (created empty, mode 0644).
 * FS_ERR_INPUT when the folder does not exist or is not writable, or when final
 * exists and is not a regular file (a device node, a FIFO: never replaced). */
int fs_output_begin(const char *final, char *tmp, int size);
/* ok != 0: rename tmp to final; else unlink tmp. Returns FS_OK or an error. */
int fs_output_end(const char *final, const char *tmp, int ok);
/* Removes every temporary of an output still in progress (async-signal-safe). */
void fs_output_abandon_all(void);
/* 1 when path ends in suffix, ignoring case (".vdb", ".bgeo.gz"). */
int fs_path_ends_with(const char *path, const char *suffix);

#ifdef __cplusplus
}
#endif
#endif
