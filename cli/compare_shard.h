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
 * runs (compare_resume.h), COUNTS the work counts (stage_counts.h). The same
 * file without item lines and "end" is written when the shard starts, so a
 * shard that was killed still names itself. */
#ifndef FS_COMPARE_SHARD_H
#define FS_COMPARE_SHARD_H
#include "compare.h"

#define CMP_MAX_SHARDS 1024
#define CMP_SHARD_MANIFEST "shard.txt"
#define CMP_SHARD_DONE "DONE"

/* "K/N" with 1 <= K <= N <= CMP_MAX_SHARDS, else FS_ERR_INPUT naming the text. */
int cmp_shard_parse(const char *text, int *k, int *n);
/* r->owner for every work item: the longest estimated first (pixels x frame
 * file size x the method's declared cost, fs_method.cost), each to the shard
 * with the least estimated work so far (ties: the lower id, the lower K).
 * FS_ERR_RUNTIME for a method that declares no cost. */
int cmp_shard_plan(cmp_run *r);
/* Before any work: removes DIR/DONE; refuses arguments the manifest cannot hold. */
int cmp_shard_start(const cmp_run *r);
/* The manifest: its header once the provenance is known; finished, after the
 * shard's last item, with every item's record, then DONE. */
int cmp_shard_write(const cmp_run *r, int finished);

#endif
