/* Progress of long work on stderr (docs/DESIGN.md, "The stderr contract"): on a
 * terminal a bar with an ETA, redrawn in place; otherwise one line per finished item
 * (none for a one-item job: a single render); nothing under -q (fs_note_quiet). One job at a time, begun by a command; the
 * layers below report finer work within the current item (fs_progress_sub), from
 * any thread. What was finished is what an interrupted run reports (interrupt.h). */
#ifndef FS_PROGRESS_H
#define FS_PROGRESS_H
#include <stddef.h>
#ifdef __cplusplus
extern "C" {
#endif

/* A job of total items called unit ("frames", "work items"), for command cmd. */
void fs_progress_begin(const char *cmd, const char *unit, long total);
/* One item finished; detail (may be NULL) says which, and what it measured. */
void fs_progress_item(const char *detail);
/* Finer work within the current item: sub_total parts (set once per item, by the
 * code doing them), of which n more are done. Thread-safe. */
void fs_progress_sub_total(long sub_total);
void fs_progress_sub(long n);
/* Ends the job (clears the bar). */
void fs_progress_end(void);
/* "3 of 10 frames finished" (or "" with no job) into buf; async-signal-safe. */
void fs_progress_summary(char *buf, size_t size);

#ifdef __cplusplus
}
#endif
#endif
