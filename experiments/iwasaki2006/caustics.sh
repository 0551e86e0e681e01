#!/usr/bin/env bash
# iwasaki2006 caustics bars (issue 6), through the whole surfels pipeline on
# particles (density grid, surfels, virtual screen, illumination volumes):
#   flat: a water slab 0.3 deep lit from straight above, seen from above; the
#         floor's caustic irradiance (the `caustics` AOV: eq. 2 with K = 1,
#         L_a = 0, luminance) against eq. 2 with flux ratio 1:
#         L_i T(0) exp(-c l), l = 0.3 the ideal depth, for the slab without
#         jitter (pointwise: median and max deviation over a central crop) and
#         with the default jitter (the crop's mean: flux is conserved even
#         where the jittered surface's ripples focus light);
#   curved: a ball of water 1.0 across on the floor: the floor's maximum
#         against the flat value for the longest path (l = 1.0) and for no
#         extinction at all;
#   zero:  floor pixels outside the water's shadow (an image corner).
# The sunken box is left out (object=none): it would hide the floor the bars read.
# Writes results/iwasaki2006/caustics.csv and the AOV images.
# FS_QUICK=1 (run_all.sh --quick): 128^2 (the crops scaled with it), grid 128, into
# out/quick/results.
set -euo pipefail
cd "$(dirname "$0")/../.."
source experiments/lib.sh
BIN=${BIN:-./build/fluidsurf}
R=$RESULTS/iwasaki2006
# S: image side (the scenes' 256); px N: N pixels of a 256^2 image at S^2
S=$(quick 256 128)
px() { echo $(($1 * S / 256)); }
E=experiments/iwasaki2006
mkdir -p "$R"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for s in slab_sun_flat slab_sun sphere_sun; do
  "$BIN" render "$E/$s.json" --method surfels --set surfels.object=none $(quick "" "-W $S -H $S --set surfels.grid_res=128") -q -o "$tmp/$s.exr"
  oiiotool "$tmp/$s.exr" --ch own.R,own.G,own.B -o "$R/caustics_${s}_own.png"
  oiiotool "$tmp/$s.exr" --ch caustics --mulc 0.7 --ch 0,0,0 -o "$R/caustics_${s}_aov.png"
done
# stat FILE CROP WHICH: Min|Max|Avg of the caustics channel over a crop WxH+X+Y
stat() { oiiotool "$1" --ch caustics --cut "$2" --printstats 2>&1 | awk -v w="Stats $3:" 'index($0, w) {print $3}'; }
# median of the crop's values, through a text dump
median_crop() { oiiotool "$1" --ch caustics --cut "$2" -o "$tmp/crop.exr"; oiiotool --dumpdata "$tmp/crop.exr" | awk -F: '/^ *Pixel/ {print $2+0}' | sort -g |
  awk '{a[NR]=$1} END {print (NR%2) ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2}'; }
# eq. 2 for a flat surface, light from above: luminance of T(0) exp(-c l), the scene's default c
eq2() { awk -v l="$1" -v c0="${2:-1.2}" -v c1="${3:-0.45}" -v c2="${4:-0.2}" 'BEGIN {
  n = 1.333; f = ((n - 1) / (n + 1))^2; T = 1 - f
  printf "%.6f", T * (0.2126 * exp(-c0 * l) + 0.7152 * exp(-c1 * l) + 0.0722 * exp(-c2 * l)) }'; }
verdict() { awk "BEGIN {print ($1) ? \"pass\" : \"FAIL\"}"; }
crop=$(px 48)x$(px 48)+$(px 104)+$(px 104)
flat=$(eq2 0.3)
med=$(median_crop "$tmp/slab_sun_flat.exr" $crop)
lo=$(stat "$tmp/slab_sun_flat.exr" $crop Min); hi=$(stat "$tmp/slab_sun_flat.exr" $crop Max)
avg=$(stat "$tmp/slab_sun.exr" $crop Avg)
sph_max=$(stat "$tmp/sphere_sun.exr" ${S}x$S+0+0 Max)
zero=$(stat "$tmp/slab_sun.exr" $(px 24)x$(px 24)+0+0 Max)
zero_sph=$(stat "$tmp/sphere_sun.exr" $(px 48)x$(px 48)+0+0 Max)
csv=$R/caustics.csv
{
  echo "# surfels caustics on particles (defaults, grid $(quick 256 "128, ${S}x$S (quick)")); expected = eq. 2 with F = 1: L_i T(0) exp(-c l), luminance; renderer llvmpipe"
  echo "bar,measured,expected,ratio,verdict,note"
  r=$(awk -v a="$med" -v b="$flat" 'BEGIN {printf "%.4f", a / b}')
  echo "flat_slab_no_jitter_median,$med,$flat,$r,$(verdict "$r > 0.95 && $r < 1.05"),central ${crop} crop; l = 0.3 (ideal depth)"
  r2=$(awk -v a="$lo" -v c="$hi" -v b="$flat" 'BEGIN {x = (b - a) / b; y = (c - b) / b; printf "%.4f", (x > y ? x : y)}')
  echo "flat_slab_no_jitter_max_dev,$lo..$hi,$flat,$r2,report,largest relative deviation of a pixel in the crop: the lattice's iso-surface ripples (period 2r) focus light at 12 r depth"
  r=$(awk -v a="$avg" -v b="$flat" 'BEGIN {printf "%.4f", a / b}')
  echo "jittered_slab_mean,$avg,$flat,$r,$(verdict "$r > 0.95 && $r < 1.05"),default jitter 0.1 r: ripples focus light; the crop mean keeps the flux"
  f1=$(eq2 1.0); f0=$(eq2 0 0 0 0)
  r=$(awk -v a="$sph_max" -v b="$f1" 'BEGIN {printf "%.3f", a / b}')
  echo "sphere_focus_max,$sph_max,$f1,$r,$(verdict "$sph_max > $f1"),floor maximum against the flat value for l = 1.0 (the ball's diameter)"
  r=$(awk -v a="$sph_max" -v b="$f0" 'BEGIN {printf "%.3f", a / b}')
  echo "sphere_focus_max_vs_clear,$sph_max,$f0,$r,$(verdict "$sph_max > $f0"),against T(0) with no extinction at all"
  echo "zero_outside_slab,$zero,0,,$(verdict "$zero == 0"),image corner: floor with no water above"
  echo "zero_outside_sphere,$zero_sph,0,,$(verdict "$zero_sph == 0"),image corner: floor with no water above"
} > "$csv.tmp"
publish "$csv"
stamp_csv "$csv"
column -t -s, "$csv"
