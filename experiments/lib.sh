# Shell helpers shared by the experiment scripts (source it after cd to the repository root).

# median: the median of the numbers on stdin, one per line (empty when there are none).
median() { sort -g | awk '{a[NR]=$1} END {if (NR == 0) print ""; else print (NR%2) ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2}'; }

# csv_awk [-v VAR=VALUE]... PROGRAM FILE: runs the awk statements PROGRAM on each row of
# the CSV FILE ('#' lines and the header skipped), where col("NAME") is the row's value of
# the header's column NAME (a missing column stops awk with exit 2). Read compare's CSVs
# this way, never by position: metrics.csv has one column per swept parameter after
# `variant` (docs/DESIGN.md, "Output folders").
csv_awk() {
  local n=$# file=${!#} prog=${*: -2:1}
  awk -F, "${@:1:n-2}" 'function col(name) { if (!(name in C)) { printf "csv_awk: %s has no column %s\n", FILENAME, name > "/dev/stderr"; exit 2 } return $(C[name]) }
    /^#/ { next } !H { for (i = 1; i <= NF; i++) C[$i] = i; H = 1; next } { '"$prog"' }' "$file"
}

# prov FILE KEY: KEY's value in the provenance line a CSV starts with ("# k=v; k=v;", fs_provenance_line)
prov() { head -1 "$1" | tr ';' '\n' | sed -n "s/^ *$2=//p" | head -1; }
# exr_attr FILE NAME: a fluidsurf provenance attribute of an EXR (iinfo: openimageio-tools)
exr_attr() { iinfo -v "$1" | sed -n "s/^ *fluidsurf:$2: \"\(.*\)\"$/\1/p" | head -1; }
# kv "eye=a,b,c;target=..." KEY
kv() { tr ';' '\n' <<<"$1" | sed -n "s/^$2=//p"; }
json_vec() { echo "[${1//,/, }]"; }

# auto_camera BIN SCENE.json WORK: the camera fluidsurf frames SCENE with (read back
# from a 16x16 render's provenance). Sets P_R, P_EYE, P_TGT, P_UP, FOV, and P_CAMERA
# (the camera as JSON, without its size) so other tools can be given the same view.
auto_camera() {
  local bin=$1 scene=$2 exr=$3/$(basename "$2" .json).cam.exr cam
  "$bin" render "$scene" --method reference -W 16 -H 16 -q -o "$exr"
  cam=$(exr_attr "$exr" camera)
  P_R=$(exr_attr "$exr" r)
  P_EYE=$(kv "$cam" eye); P_TGT=$(kv "$cam" target); P_UP=$(kv "$cam" up); FOV=$(kv "$cam" fov)
  P_CAMERA="\"eye\": $(json_vec "$P_EYE"), \"target\": $(json_vec "$P_TGT"), \"up\": $(json_vec "$P_UP"), \"fov\": $FOV"
}

# view_from_above AXIS: turns the camera auto_camera read (P_EYE, P_TGT, P_UP, P_CAMERA) to
# look straight down the scene's up axis AXIS (x, y or z) at the same target from the same
# distance: the view from above, with y as the image's up for AXIS z and z otherwise.
view_from_above() {
  read -r P_EYE P_UP < <(awk -v e="$P_EYE" -v t="$P_TGT" -v ax="$1" 'BEGIN {
    split(e, E, ","); split(t, T, ","); d = 0; for (i = 1; i <= 3; i++) d += (E[i] - T[i]) ^ 2
    a = index("xyz", ax); u = a == 3 ? 2 : 3
    for (i = 1; i <= 3; i++) { X[i] = T[i] + (i == a ? sqrt(d) : 0); U[i] = i == u }
    printf "%.9g,%.9g,%.9g %d,%d,%d\n", X[1], X[2], X[3], U[1], U[2], U[3] }')
  P_CAMERA="\"eye\": $(json_vec "$P_EYE"), \"target\": $(json_vec "$P_TGT"), \"up\": $(json_vec "$P_UP"), \"fov\": $FOV"
}

# vdb_aperture FOV_DEG: vdb_tool -render's aperture for a vertical field of view
# (its focal length is 100: aperture = 100 tan(fov / 2))
vdb_aperture() { awk -v f="$1" 'BEGIN {printf "%.4g", 100 * sin(f * 3.14159265358979 / 360) / cos(f * 3.14159265358979 / 360)}'; }

# ---- study mode (experiments/run_all.sh) ------------------------------------------
# FS_QUICK=1 runs a study at small sizes (a smoke run: every script runs, none rots) and
# writes under $FS_RESULTS (default out/quick/results) instead of results/, so a quick
# run never touches committed results. A script sources this file, then writes into
# "$RESULTS/<study>" and picks its sizes with `quick FULL SMALL`.
FS_QUICK=${FS_QUICK:-0}
if [ "$FS_QUICK" = 1 ]; then RESULTS=${FS_RESULTS:-out/quick/results}; else RESULTS=${FS_RESULTS:-results}; fi
# quick FULL SMALL: FULL normally, SMALL with FS_QUICK=1
quick() { if [ "$FS_QUICK" = 1 ]; then echo "$2"; else echo "$1"; fi; }
# study_commit: "commit=<HEAD, 10 digits>; dirty=0|1" for a CSV's provenance line; dirty=1
# when the tree has uncommitted changes outside results/ (what the binaries were built from)
study_commit() {
  local d=0
  git diff --quiet HEAD -- . ':!results' 2> /dev/null || d=1
  echo "commit=$(git rev-parse --short=10 HEAD 2> /dev/null || echo unknown); dirty=$d"
}
# The commit a study's numbers are made at: taken once, when the script starts.
STUDY_PROV=$(study_commit)
PROV_RE='^#.*(^|[ ;#])commit=[0-9a-f]{7,40}[;, ].*(^|[ ;])dirty=[01]([; ,]|$)'
# stamp_csv FILE...: makes sure each CSV's first '#' line names the commit and the tree's
# state (STUDY_PROV), putting them first on that line, or on a new first line when the file
# has none; a CSV that names them already (fluidsurf's own provenance) is left as it is.
# Call it on the CSVs a script measured, never on CSVs of other runs.
stamp_csv() {
  local f first
  for f; do
    first=$(grep -m1 '^#' "$f" || true)
    if grep -qE "$PROV_RE" <<< "$first"; then continue; fi
    if [ -n "$first" ] && [ "$(head -1 "$f")" = "$first" ]; then
      sed -i "1s/^# */# $STUDY_PROV; /" "$f"
    else
      sed -i "1i # $STUDY_PROV" "$f"
    fi
  done
}
# csv_commit FILE...: "commit=...; dirty=..." for a CSV assembled from the CSVs named: the
# first one's, and "sources=NAME@COMMIT,..." when they were not all made at one commit
csv_commit() {
  local f c all=() first=""
  for f; do
    c=$(grep -m1 '^#' "$f" | grep -oE 'commit=[0-9a-f]{7,40}(-dirty)?; dirty=[01]' | head -1)
    [ -n "$c" ] || c="commit=none; dirty=1"
    [ -n "$first" ] || first=$c
    all+=("$(basename "$f")@$(sed 's/commit=\([^;]*\); dirty=\(.\)/\1 dirty=\2/' <<< "$c" | tr ' ' ':')")
  done
  if [ "$(printf '%s\n' "${all[@]}" | sed 's/^[^@]*@//' | sort -u | wc -l)" -gt 1 ]; then
    echo "$first; sources=$(IFS=,; echo "${all[*]}")"
  else echo "$first"; fi
}

# ---- simulated sequences (xiao2017 fig4.sh, fig6.sh) ---------------------------------
# simulated_frames BIN SCENE N LAST PATTERN: fluidsurf's SPH of SCENE with about N particles,
# frames 0..LAST into PATTERN (printf, one %d; per-frame stats beside it), unless frame
# LAST is there already (the simulation is deterministic).
simulated_frames() {
  [ -f "$(printf "$5" "$4")" ] ||
    "$1" simulate "$2" --particles "$3" --frames "$4" -o "$5" --stats "$(dirname "$5")/stats.csv" -q
}
# frame_scene PATTERN F SIZE [CAMERA]: the scene JSON of frame F of PATTERN, for a scene file
# written one folder above the frames: the file's radius, y up, water over the checker,
# SIZE^2, and CAMERA (auto_camera's P_CAMERA) or the automatic framing.
frame_scene() {
  local cam=${4:+$4, }
  printf '{"particles": "%s/%s", "up": "y", "material": "water", "background": "checker",\n "camera": {%s"width": %d, "height": %d}}\n' \
    "$(basename "$(dirname "$1")")" "$(basename "$(printf "$1" "$2")")" "$cam" "$3" "$3"
}
# frames_mosaic OUT.png COLSxROWS TILE [--cut WxH+X+Y] FILE...: the images (each first
# cropped to the box, when given) shrunk to TILE (WxH) and tiled
frames_mosaic() {
  local out=$1 grid=$2 tile=$3 cut=() args=()
  shift 3
  if [ "${1:-}" = --cut ]; then cut=(--cut "$2"); shift 2; fi
  for f in "$@"; do args+=("$f" "${cut[@]}" --resize "$tile"); done
  oiiotool "${args[@]}" --mosaic "$grid" --ch R,G,B -o "$out"
}

# replace_block MD NAME FILE: the lines of MD between "<!-- NAME -->" and "<!-- end NAME -->"
# become FILE's lines (a generated table inside a README whose other text is kept)
replace_block() {
  awk -v t="$3" -v b="<!-- $2 -->" -v e="<!-- end $2 -->" '
    $0 == b {print; while ((getline l < t) > 0) print l; skip = 1; next}
    $0 == e {skip = 0}
    !skip' "$1" > "$1.tmp" && publish "$1"
}

# publish FILE...: moves each FILE.tmp over FILE. A script writes its outputs as FILE.tmp
# (git ignores *.tmp*) and publishes them when they are whole, so a failed or killed run
# leaves the earlier FILE, never half of a new one where readers look.
publish() {
  local f
  for f; do mv "$f.tmp" "$f"; done
}

# reference_frames [BIN DIR]: sets the array frames to "NAME|PARTICLE FILE|RENDER INPUT AND
# OPTIONS" of the reference studies (thickness_counts.sh, interior_auto.sh, peers.sh):
# fluidsurf's splash frame and the bundled dam break, and in full mode first the DualSPHysics
# frame ($SHARED, z up, r = 0.00365 as its README gives), auto-framed, and with BIN and DIR also
# from above (dualsphysics_above: a scene written into DIR with the camera of view_from_above,
# which BIN frames); exits 2 when that frame is missing
reference_frames() {
  frames=("splash|experiments/data/splash/dam_break_splash_100k.ply|experiments/data/splash/dam_break_splash_100k.ply"
          "dam_break|experiments/data/splashsurf/dam_break_frame_23_24389_particles.vtk|experiments/scenes/dam_break.json")
  [ "$FS_QUICK" = 1 ] && return 0
  local dsph=${SHARED:-../shared/data}/dualsphysics/dambreak200k_t0.300.vtk part
  [ -f "$dsph" ] || { echo "$(basename "$0"): $dsph missing (set SHARED to the shared data folder)" >&2; exit 2; }
  if [ $# -lt 2 ]; then frames=("dualsphysics|$dsph|$dsph --up z --radius 0.00365" "${frames[@]}"); return 0; fi
  part="\"particles\": \"$(realpath "$dsph")\", \"up\": \"z\", \"radius\": 0.00365"
  echo "{$part}" > "$2/dualsphysics.json"
  auto_camera "$1" "$2/dualsphysics.json" "$2"
  view_from_above z
  echo "{$part, \"camera\": {$P_CAMERA}}" > "$2/dualsphysics_above.json"
  frames=("dualsphysics|$dsph|$dsph --up z --radius 0.00365" "dualsphysics_above|$dsph|$2/dualsphysics_above.json"
          "${frames[@]}")
}
# zb_sweep BIN: the demo's mesh twice, on the SPH field and on Zhu & Bridson's (issue 38),
# where BIN has mesh (a build with OpenVDB); nothing otherwise.
zb_sweep() { if "$1" methods 2> /dev/null | grep '^mesh ' > /dev/null; then echo "--set mesh.field=isotropic,zhu_bridson"; fi; }
