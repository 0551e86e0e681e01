#!/usr/bin/env bash
# The up-axis guess (`--up auto`, common/scene/up_axis.c) on every third-party frame the
# project has, bundled (experiments/data/) and shared ($SHARED, default ../shared/data), and
# on fluidsurf's own splash frame: what `fluidsurf info` guesses, why, the shares of the
# particles within r of each axis's low end (what the floor rule reads), and the up axis
# each frame is known to have, with how it is known ("" where nothing says). A shared copy
# of a bundled file (the same bytes) is listed once. Writes $RESULTS/study/up_axis.csv and,
# in a full run, its table in README.md ("Scenes"). A full run needs the shared
# DualSPHysics frame (exit 2 without it); a quick run takes what is there.
set -euo pipefail
cd "$(dirname "$0")/../.."
source experiments/lib.sh
BIN=${BIN:-./build/fluidsurf}
SHARED=${SHARED:-../shared/data}
out=$RESULTS/study
mkdir -p "$out"
csv=$out/up_axis.csv

# known NAME: "AXIS|how it is known" for a frame whose up is known, else "|" (the READMEs
# beside the frames say more: experiments/data/splashsurf/, experiments/data/splash/ and
# $SHARED/dualsphysics/)
known() {
  case "$1" in
    dam_break_frame_* | double_dam_break_* | cube_2366_*) echo "y|SPlisHSPlasH: gravity along -y" ;;
    dual_dodec_* | hilbert2_* | octocat_* | pentagonal_hexecontahedron_*) echo "z|a shape stood on z = 0" ;;
    dambreak200k_*) echo "z|DualSPHysics: gravity along -z" ;;
    dam_break_splash_*) echo "y|fluidsurf's simulation: y up" ;;
    *) echo "|" ;;
  esac
}

frames=(experiments/data/splashsurf/*.{vtk,vtu,bgeo,ply} experiments/data/dualsphysics/*.vtk experiments/data/splash/*.ply)
dsph=$SHARED/dualsphysics/dambreak200k_t0.300.vtk
[ -f "$dsph" ] || [ "$FS_QUICK" = 1 ] || { echo "up_axis.sh: $dsph missing (set SHARED)" >&2; exit 2; }
seen=$(sha256sum "${frames[@]}" | cut -c1-64)
for f in "$SHARED"/*/*.{vtk,vtu,bgeo,ply}; do
  [ -f "$f" ] || continue
  grep -q "$(sha256sum "$f" | cut -c1-64)" <<< "$seen" || frames+=("$f")
done

{
  echo "# $STUDY_PROV; fluidsurf info's up guess (r from the spacing) on every bundled and shared third-party frame and fluidsurf's splash frame"
  echo "frame,where,particles,expected,known_from,guess,right,low_end_x_pct,low_end_y_pct,low_end_z_pct,reason"
  for f in "${frames[@]}"; do
    "$BIN" info "$f" > "$out/up_axis.info"
    name=$(basename "$f")
    where=$(case "$f" in "$SHARED"/*) echo shared ;; *) echo bundled ;; esac)
    IFS='|' read -r expected how <<< "$(known "$name")"
    guess=$(sed -n 's/^up (auto): \(.\) .*/\1/p' "$out/up_axis.info")
    reason=$(sed -n 's/^up (auto): . (\(.*\))$/\1/p' "$out/up_axis.info")
    read -r sx sy sz < <(sed -n 's/^within r of the low end: x \(.*\)%, y \(.*\)%, z \(.*\)%$/\1 \2 \3/p' "$out/up_axis.info")
    right=$([ -z "$expected" ] && echo "" || { [ "$guess" = "$expected" ] && echo 1 || echo 0; })
    n=$(sed -n 's/^particles: //p' "$out/up_axis.info")
    echo "$name,$where,$n,$expected,$how,$guess,$right,$sx,$sy,$sz,\"$reason\""
  done
} > "$csv.tmp"
mv "$csv.tmp" "$csv"
rm -f "$out/up_axis.info"
cat "$csv"
[ "$FS_QUICK" = 1 ] || python3 experiments/tools/csv_table.py "$csv" README.md
