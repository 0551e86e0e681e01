#!/usr/bin/env bash
# inacio2010 Tables I and II analogue: per-frame stage times of the SPH dam break
# simulated and rendered in one GL context, CPU path against GPU path, ray casting
# (volume_raycast) against spheres, at 1024 .. 131072 particles.
# experiments/tools/inacio_tables.c does the work (see its header); per count and
# path it advances SETTLE untimed frames of 1/60 s (the first timed against
# LIMIT_S: a cell whose first frame takes longer is skipped and says so), one
# untimed warm-up render per method, then FRAMES timed frames; medians over them.
# Columns of tables.csv (ms, medians of the FRAMES frames):
#   simulation  one 1/60 s frame of fs_sph_advance (adaptive steps)
#   fetch       fs_sph_get, the particles into host arrays (GPU path: a read-back,
#               which the paper's GPU path avoided with FBO -> PBO -> VBO)
#   Table I (volume_raycast, build=layered, grid GRID, rays stop at the surface):
#     volume = its "volume" stage (particle upload + single-pass layered splat);
#     raycast = "faces" + "march"; rendering = "readback" (G-buffer to the host)
#     + "renormalize" (its normals on the CPU) + the shared shading (C, fs_shade)
#   Table II (spheres, opaque, no thickness pass): rendering = particle upload +
#     "splat" + "readback" + "renormalize" + shading
#   total = the sum of the stage medians (so the percentages add up to 100)
#   volume_slice_ms (Table I rows): the volume stage with build=slice instead
#     (iwasaki2006's multi-pass slice splatting + upload), same grid, same frames
# Every row names the renderer: on OSMesa the GPU path and every GL stage run on
# llvmpipe, i.e. on the same CPU cores as the C simulation.
# Writes results/inacio2010/tables.csv and tables_frames.csv (every frame, every
# stage); prints the tables as markdown.
# Usage: experiments/inacio2010/tables.sh   (BIN=, TOOL=, COUNTS=, SETTLE=, FRAMES=,
#        SIZE=, GRID=, LIMIT_S=, TIMEOUT_S=, KEEP_FRAMES= override; without TOOL, the
#        inacio_tables of BIN's build when BIN (fluidsurf, as run_all.sh exports it) is set)
# FS_QUICK=1 (run_all.sh --quick): 1024 and 2048 particles, 1 + 1 frames, 128^2, grid 64,
# into out/quick/results.
set -uo pipefail
cd "$(dirname "$0")/../.."
source experiments/lib.sh
[ -n "${TOOL:-}" ] || TOOL=$(dirname "${BIN:-build/fluidsurf}")/experiments/inacio_tables
COUNTS=${COUNTS:-$(quick "1024 2048 4096 8192 16384 32768 65536 131072" "1024 2048")}
SETTLE=${SETTLE:-$(quick 6 1)}
FRAMES=${FRAMES:-$(quick 3 1)}
SIZE=${SIZE:-$(quick 512 128)}
GRID=${GRID:-$(quick 128 64)}
LIMIT_S=${LIMIT_S:-$(quick 60 20)}
TIMEOUT_S=${TIMEOUT_S:-$(quick 1200 60)}
OUT=$RESULTS/inacio2010
mkdir -p "$OUT"
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
prov="$STUDY_PROV; dam break (Tait, r 0.025, fluidsurf simulate's defaults); $SETTLE untimed frames of 1/60 s, warm-up render, medians of $FRAMES frames; ${SIZE}x${SIZE}; volume_raycast grid_res $GRID build=layered thickness=off; spheres thickness=off; first-frame limit ${LIMIT_S} s; $(nproc) cores; load before: $(cut -d' ' -f1-3 /proc/loadavg); $(date -u +%FT%TZ)"
frames=$T/frames.csv
echo "# inacio_tables: $prov" > "$frames"
echo "particles_requested,particles,boundary,path,sim_renderer,gl_renderer,frame,t,steps,table,stage,ms" >> "$frames"
failed=0 # cells whose run failed (a quick run fails on them)
for n in $COUNTS; do
  for path in cpu gpu; do
    t0=$(date +%s)
    timeout "$TIMEOUT_S" "$TOOL" "$n" "$path" "$SETTLE" "$FRAMES" "$SIZE" "$GRID" "$LIMIT_S" > "$T/cell.csv" 2> "$T/err"
    rc=$?
    cat "$T/cell.csv" >> "$frames"
    [ $rc = 0 ] || failed=$((failed + 1))
    if [ $rc != 0 ]; then
      echo "$n,,,$path,,,,,,note,failed_rc_${rc}_after_$(( $(date +%s) - t0 ))s,0" >> "$frames"
      tail -2 "$T/err" >&2
    fi
    echo "tables: $n $path: rc $rc, $(( $(date +%s) - t0 )) s" >&2
  done
done
# KEEP_FRAMES=FILE (an earlier tables_frames.csv): its cells of counts not in
# COUNTS are kept, after the new ones, with its provenance line (re-running some
# counts, e.g. ones a loaded machine spoiled, without re-running all)
if [ -n "${KEEP_FRAMES:-}" ]; then
  cp "$KEEP_FRAMES" "$T/keep.csv"
  kept=$(awk -F, -v c=" $COUNTS " '!/^#/ && $1 != "particles_requested" && index(c, " " $1 " ") == 0 { print $1 }' "$T/keep.csv" | sort -un | tr '\n' ' ')
  { grep '^#' "$frames"; grep '^#' "$T/keep.csv" | sed 's/^# /# earlier run: /'; grep -v '^#' "$frames"; } > "$T/merged.csv"
  awk -F, -v c=" $COUNTS " '!/^#/ && $1 != "particles_requested" && index(c, " " $1 " ") == 0' "$T/keep.csv" >> "$T/merged.csv"
  mv "$T/merged.csv" "$frames"
  # the earlier run is a source of its own: its commit goes into the first line (check_results.sh)
  kc=$(grep -m1 '^#' "$T/keep.csv" | grep -oE 'commit=[0-9a-f]+; dirty=[01]' | head -1)
  src() { sed 's/commit=\([^;]*\); dirty=\(.\)/\1:dirty=\2/' <<< "${1:-commit=none; dirty=1}"; }
  sed -i "1s|\$|; sources=this_run@$(src "$STUDY_PROV"),kept@$(src "$kc")|" "$T/merged.csv"
  prov="$prov; sources=this_run@$(src "$STUDY_PROV"),kept@$(src "$kc")"
  prov="$prov; the cells of counts ${kept% } are kept from the earlier run(s) in tables_frames.csv ($(grep '^#' "$T/keep.csv" | grep -o 'load before: [^;]*; [0-9T:-]*Z' | tr '\n' ' ' | sed 's/ $//'))"
fi
cp "$frames" "$OUT/tables_frames.csv"

# per cell and table: the median of each stage over the frames (composite stages
# summed per frame first). Quoted fields (renderers) hold commas: protected as \001.
awk -v prov="$prov" -v limit="$LIMIT_S" '
  function unq(line,   out, s) {
    out = ""
    while (match(line, /"[^"]*"/)) { s = substr(line, RSTART, RLENGTH); gsub(/,/, "\001", s)
      out = out substr(line, 1, RSTART - 1) s; line = substr(line, RSTART + RLENGTH) }
    return out line }
  function median(str,   n, i, j, a, tmp) {
    n = split(str, a, " ");
    if (n == 0) return 0;
    for (i = 2; i <= n; i++) for (j = i; j > 1 && a[j - 1] + 0 > a[j] + 0; j--) { tmp = a[j]; a[j] = a[j - 1]; a[j - 1] = tmp }
    return (n % 2) ? a[(n + 1) / 2] : (a[n / 2] + a[n / 2 + 1]) / 2 }
  /^#/ || /^particles_requested/ { next }
  { split(unq($0), g, ",")
    cell = g[1] SUBSEP g[4]
    if (!(cell in seen)) { seen[cell] = 1; order[++k] = cell }
    if (g[2] != "") { NP[cell] = g[2]; NB[cell] = g[3]; SR[cell] = g[5]; GR[cell] = g[6] }
    if (g[11] ~ /^skipped/) { note[cell] = sprintf("skipped: the first frame took %.1f s > %s s", g[12] / 1000, limit); next }
    if (g[10] == "note") { note[cell] = g[11]; next }
    f = g[7]
    if (!((cell, f) in fseen)) { fseen[cell, f] = 1; nfr[cell]++; FR[cell] = FR[cell] " " f; if (!(cell in t1)) t1[cell] = g[8]; t2[cell] = g[8]; STEPS[cell] = STEPS[cell] " " g[9] }
    x[cell, f, g[10], g[11]] += g[12] }
  END {
    print "# " prov
    print "# ms, medians over the timed frames; total = the sum of the stage medians; rendering: Table I readback + renormalize + shading, Table II particle upload + splat + readback + renormalize + shading"
    print "table,particles_requested,particles,boundary,path,sim_renderer,gl_renderer,frames,t_first,t_last,steps_per_frame,simulation_ms,fetch_ms,volume_ms,raycast_ms,rendering_ms,total_ms,simulation_pct,fetch_pct,volume_pct,raycast_pct,rendering_pct,volume_slice_ms,note"
    for (tb = 1; tb <= 2; tb++) for (i = 1; i <= k; i++) {
      cell = order[i]; split(cell, c, SUBSEP); T = tb == 1 ? "I" : "II"
      if (!(cell in nfr)) { line = sprintf("%s,%s,%s,%s,%s,%s,%s,0,,,,,,,,,,,,,,,,%s", T, c[1], NP[cell], NB[cell], c[2], SR[cell], GR[cell], note[cell])
                            gsub(/\001/, ",", line); print line; continue }
      nf = split(FR[cell], F, " "); S = ""; FE = ""; V = ""; RC = ""; RE = ""; VS = ""
      for (j = 1; j <= nf; j++) { f = F[j]
        S = S " " x[cell, f, "sim", "simulation"]; FE = FE " " x[cell, f, "sim", "fetch"]
        if (tb == 1) { V = V " " x[cell, f, "I", "volume"]; VS = VS " " x[cell, f, "I_slice", "volume"]; RC = RC " " (x[cell, f, "I", "faces"] + x[cell, f, "I", "march"])
                       RE = RE " " (x[cell, f, "I", "readback"] + x[cell, f, "I", "renormalize"] + x[cell, f, "I", "shade"]) }
        else RE = RE " " (x[cell, f, "II", "upload"] + x[cell, f, "II", "splat"] + x[cell, f, "II", "readback"] + x[cell, f, "II", "renormalize"] + x[cell, f, "II", "shade"]) }
      s = median(S); fe = median(FE); v = median(V); rc = median(RC); re = median(RE); tot = s + fe + v + rc + re
      line = sprintf("%s,%s,%s,%s,%s,%s,%s,%d,%s,%s,%s,%.1f,%.2f,%s,%s,%.1f,%.1f,%.1f,%.2f,%s,%s,%.1f,%s,%s", T, c[1], NP[cell], NB[cell], c[2],
        SR[cell], GR[cell], nfr[cell], t1[cell], t2[cell], median(STEPS[cell]), s, fe,
        tb == 1 ? sprintf("%.1f", v) : "", tb == 1 ? sprintf("%.1f", rc) : "", re, tot,
        100 * s / tot, 100 * fe / tot, tb == 1 ? sprintf("%.1f", 100 * v / tot) : "", tb == 1 ? sprintf("%.1f", 100 * rc / tot) : "",
        100 * re / tot, tb == 1 ? sprintf("%.1f", median(VS)) : "", (cell in note) ? note[cell] : "")
      gsub(/\001/, ",", line); print line }
  }' "$frames" > "$T/tables.csv"
# rows by table, then particle count, then path
{ grep -E '^(#|table,)' "$T/tables.csv"; grep -vE '^(#|table,)' "$T/tables.csv" | sort -t, -k1,1 -k2,2n -k5,5; } > "$OUT/tables.csv"

if [ "$FS_QUICK" = 1 ] && [ $failed -gt 0 ]; then echo "tables: $failed cells failed" >&2; exit 1; fi

# markdown, for the README
awk -F, '/^#/ || $1 == "table" { next }
  { line = $0; gsub(/"[^"]*"/, "R", line); split(line, a, ",")
    if (a[1] != last) { last = a[1]; print ""
      if (a[1] == "I") { print "| particles (fluid) | path | simulation | fetch | volume | ray casting | rendering | total | volume, slice build |"; print "|---|---|---|---|---|---|---|---|---|" }
      else { print "| particles (fluid) | path | simulation | fetch | rendering (spheres) | total |"; print "|---|---|---|---|---|---|" } }
    if (a[8] == 0) { printf "| %s | %s | %s |\n", a[3] != "" ? a[3] : a[2], a[5], a[24]; next }
    if (a[1] == "I") printf "| %s | %s | %s (%s%%) | %s | %s (%s%%) | %s (%s%%) | %s (%s%%) | %s | %s |\n", a[3], a[5], a[12], a[18], a[13], a[14], a[20], a[15], a[21], a[16], a[22], a[17], a[23]
    else printf "| %s | %s | %s (%s%%) | %s | %s (%s%%) | %s |\n", a[3], a[5], a[12], a[18], a[13], a[16], a[22], a[17] }' "$OUT/tables.csv"
