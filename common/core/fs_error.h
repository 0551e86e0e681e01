/* One-line errors ("FILE: what is wrong") and the exit codes of docs/DESIGN.md. */
#ifndef FS_ERROR_H
#define FS_ERROR_H
#include <stdarg.h>
#include <stddef.h>
#ifdef __cplusplus
extern "C" {
#endif

enum { FS_OK = 0, FS_ERR_RUNTIME = 1, FS_ERR_INPUT = 2, FS_ERR_DIFF = 3 };

/* Stores a formatted message (thread-local; control characters replaced by '?'
 * and bytes that are not UTF-8 written \xFF, so it is always one line of text)
 * and returns code, so callers write
 * `return fs_fail(FS_ERR_INPUT, "%s: truncated POINTS section", path);` */
int fs_fail(int code, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
int fs_vfail(int code, const char *fmt, va_list ap);
const char *fs_error_message(void);
/* in as one line of valid UTF-8 in out (size > 5): control characters '?', bytes
 * that are not UTF-8 written \xFF; for messages printed without fs_fail. */
void fs_text_line(char *out, size_t size, const char *in);
/* The code of the last fs_fail on this thread (FS_ERR_RUNTIME when none is
 * recorded): for layers that report a failure below them without the code. */
int fs_error_code(void);
void fs_error_clear(void);
/* A one-line note on stderr ("fluidsurf: note: ..."), for what a run leaves out
 * on purpose (far stray particles); silenced by fs_note_quiet(1) (the CLI's -q). */
void fs_note(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
void fs_note_quiet(int quiet);
int fs_note_is_quiet(void); /* -q: progress (progress.h) is silenced too */

#ifdef __cplusplus
}
#endif
#endif
