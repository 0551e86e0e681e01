/* compare --shard K/N (docs/DESIGN.md, "Sharded studies"): the work items are
 * split over N shards by estimated cost; shard K renders its own into its
 * folder, then writes the manifest DIR/shard.txt and, last, DIR/DONE.
 *
 * shard.txt, one record per line, fields separated by tabs:
 *   fluidsurf-shard 1 | shard K N | commit C | scene_hash H | cwd DIR
 *   arg TEXT (the compare command line, one per argument)
 *   prov NAME VALUE (the shard's provenance)
 *   ref ID SPEC FRAME HIT ENTRY STAGES COUNTS       (each reference view it made)
 *   entry ID LABEL FRAME FRAME_MS RUNS RENDERER COUNTS (each method view)
 *   end
 * "-" stands for an empty field; STAGES and RUNS are the first frame's timed
 * runs (resume.h), COUNTS the work counts (stage_counts.h). The same
 * file without item lines and "end" is written when the shard starts, so a
 * shard that was killed still names itself. */
#ifndef FS_SHARD_H
#define FS_SHARD_H
#include "study_dir_state.h"

#define FS_MAX_SHARDS 1024
#define FS_SHARD_MANIFEST "shard.txt"
#define FS_SHARD_DONE "DONE"

/* "K/N" with 1 <= K <= N <= FS_MAX_SHARDS, else FS_ERR_INPUT naming the text. */
int fs_shard_parse(const char *text, int *k, int *n);
/* r->owner for every work item: the longest estimated first (pixels x frame
 * file size x the method's declared cost, fs_method.cost), each to the shard
 * with the least estimated work so far (ties: the lower id, the lower K).
 * FS_ERR_RUNTIME for a method that declares no cost. */
int fs_shard_plan(fs_study_dir *r);
/* Before any work: removes DIR/DONE; refuses arguments the manifest cannot hold. */
int fs_shard_start(const fs_study_dir *r);
/* The manifest: its header once the provenance is known; finished, after the
 * shard's last item, with every item's record, then DONE. */
int fs_shard_write(const fs_study_dir *r, int finished);

#endif
