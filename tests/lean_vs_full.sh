#!/usr/bin/env bash
# The lean build against the full one: every method renders the bundled dam break
# (experiments/scenes/dam_break.json at 128x128) with the full build on OSMesa and
# the lean build on EGL (both llvmpipe here), to EXR; `fluidsurf diff` of each pair
# must give IoU 1 and zero depth and normal error. Each build's diff reads the
# other's EXR (OpenImageIO vs OpenEXRCore). The lean build reads no VTK, so the
# frame goes through PLY (float32, as VTK's points are) converted by the full build.
# usage: tests/lean_vs_full.sh FULL_BIN LEAN_BIN [OUT]
set -u
FULL=$1 LEAN=$2 T=${3:-${TMPDIR:-/tmp}/fluidsurf-lean-vs-full}
SRC=$(cd "$(dirname "$0")/.." && pwd)
rm -rf "$T"; mkdir -p "$T"; T=$(cd "$T" && pwd) # the scene copy names its frame by absolute path
fails=0
check() { if eval "$1"; then echo "ok   $2"; else echo "FAIL $2"; fails=$((fails + 1)); fi; }
scene=$SRC/experiments/scenes/dam_break.json
vtk=$SRC/experiments/data/splashsurf/dam_break_frame_23_24389_particles.vtk
"$FULL" convert "$vtk" -o "$T/dam_break.ply" || exit 1
# the scene with the PLY frame and the size of this check
sed -e "s|\"particles\": *\"[^\"]*\"|\"particles\": \"$T/dam_break.ply\"|" \
    -e 's|"width": *[0-9]*|"width": 128|' -e 's|"height": *[0-9]*|"height": 128|' "$scene" > "$T/dam_break.json"
check 'grep -q "dam_break.ply" "$T/dam_break.json" && ! cmp -s "$scene" "$T/dam_break.json"' "scene copy reads the PLY frame"
methods=$("$LEAN" methods | grep -v '^ ' | awk '{print $1}')
printf '%-15s %-9s %-9s %-12s %-12s %-12s %-14s %-8s %s\n' method iou depth_bias depth_rmse_r depth_p95_r normal_mean normal_p95_deg psnr ssim
for m in $methods; do
  "$FULL" render "$T/dam_break.json" --method "$m" --gl osmesa -q -o "$T/$m.full.exr" || { check false "$m: full render"; continue; }
  "$LEAN" render "$T/dam_break.json" --method "$m" --gl egl -q -o "$T/$m.lean.exr" || { check false "$m: lean render"; continue; }
  for b in lean full; do
    bin=$LEAN; [ $b = full ] && bin=$FULL
    "$bin" diff "$T/$m.lean.exr" "$T/$m.full.exr" --fail-iou 1 --fail-normal-deg 0 --fail-depth-r 0 > "$T/$m.$b.diff" 2>&1
    echo $? > "$T/$m.$b.rc"
  done
  v() { awk -v k="$1" '$1 == k {print $2}' "$T/$m.lean.diff"; }
  printf '%-15s %-9s %-9s %-12s %-12s %-12s %-14s %-8s %s\n' "$m" "$(v mask_iou)" "$(v depth_bias_r)" "$(v depth_rmse_r)" \
    "$(v depth_p95_r)" "$(v normal_mean_deg)" "$(v normal_p95_deg)" "$(v psnr_db)" "$(v ssim)"
  zero='[ "$(v mask_iou)" = 1 ] && [ "$(v depth_bias_r)" = 0 ] && [ "$(v depth_rmse_r)" = 0 ] && [ "$(v depth_p95_r)" = 0 ] && [ "$(v normal_mean_deg)" = 0 ] && [ "$(v normal_p95_deg)" = 0 ]'
  check "[ \"\$(cat $T/$m.lean.rc)\" = 0 ] && $zero" "$m: lean (EGL) = full (OSMesa): IoU 1, zero depth and normal error (lean's diff)"
  check "[ \"\$(cat $T/$m.full.rc)\" = 0 ] && cmp -s <(grep -v '^[ab]:' $T/$m.lean.diff) <(grep -v '^[ab]:' $T/$m.full.diff)" \
    "$m: the full build's diff reads the same metrics"
done
# The two writers' headers: the same channels, compression and attributes, apart from
# the time of writing and the build's commit (iinfo: openimageio-tools).
# scripts/setup.sh installs it: a missing iinfo is a failure, not a skipped check.
check 'command -v iinfo > /dev/null' "iinfo is installed (openimageio-tools, scripts/setup.sh)"
hdr() { iinfo -v "$1" | sed 1d | grep -Ev '^ *(DateTime|fluidsurf:commit):' | sed 's/ *$//'; }
for m in spheres surfels; do
  check 'command -v iinfo > /dev/null && cmp -s <(hdr "$T/$m.lean.exr") <(hdr "$T/$m.full.exr")' \
    "$m: the lean EXR header equals the full one (but time and commit)"
done
# The lean reader takes the full build's provenance: diff gets r from A's attributes.
"$LEAN" diff "$T/spheres.full.exr" "$T/spheres.lean.exr" > "$T/r.diff" 2>&1
check 'grep -qx "r: 0.025" "$T/r.diff"' "the lean build reads r from the full build's EXR attributes"
[ $fails -eq 0 ] && echo "all checks passed" || echo "$fails check(s) failed"
exit $((fails > 0))
