#!/usr/bin/env bash
# Machine-independent work of every method (docs/DESIGN.md, "Work counters"):
# compare --counters --no-cache at 1024x1024 on the dam break (24k particles) and
# the 100k box, then results/counters/counters.csv (every stage's counts),
# work.csv (per method and counter: total, per pixel, per particle) and
# README.md, whose tables are generated here from the CSV; also the generated
# work paragraph of each paper study's README (between its counters markers).
# Usage: experiments/counters/work.sh            (uses build/fluidsurf; FLUIDSURF=... to override)
#        experiments/counters/work.sh --tables   (only regenerate the tables and paragraphs from counters.csv)
# FS_QUICK=1 (run_all.sh --quick): 128x128, the dam break and a 30^3 box (box_27k, box_100k's
# lattice), surfels' and volume_raycast's grids at 64 points (their default 256 takes minutes on a
# compact box), into out/quick/results/counters; no paper study's README is touched: the
# paragraphs go to out/quick/results/counters/paragraphs.md instead.
set -euo pipefail
cd "$(dirname "$0")/../.."
source experiments/lib.sh # quick, RESULTS
BIN=${FLUIDSURF:-build/fluidsurf}
OUT=$RESULTS/counters
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
mkdir -p "$OUT"
W=${WORK_W:-$(quick 1024 128)} H=${WORK_H:-$(quick 1024 128)}
SCENES=$(quick "dam_break box_100k" "dam_break box_27k")
QSET=$(quick "" "--set surfels.grid_res=64 --set volume_raycast.grid_res=64")
# scene_of NAME: experiments/scenes/NAME.json; quick mode's box_27k is box_100k at 30^3, in $TMP
scene_of() {
  if [ "$FS_QUICK:$1" = 1:box_27k ]; then
    sed 's/"size": \[46, 46, 46\]/"size": [30, 30, 30]/' experiments/scenes/box_100k.json > "$TMP/box_27k.json"
    grep -q '"size": \[30, 30, 30\]' "$TMP/box_27k.json" || { echo "work.sh: no box size in box_100k.json" >&2; exit 1; }
    echo "$TMP/box_27k.json"
  else
    echo "experiments/scenes/$1.json"
  fi
}

tables_only=0
[ "${1:-}" = --tables ] && tables_only=1
for s in $SCENES; do
  [ $tables_only = 1 ] && break
  echo "work.sh: $s at ${W}x$H" >&2
  scene=$(scene_of "$s")
  # every registered method, the reference among them (compare's default leaves it out: it is the ground truth)
  "$BIN" compare "$scene" --methods "$("$BIN" methods | awk '/^[^ ]/ { print $1 }' | paste -sd,)" \
    -W $W -H $H --repeat 1 --no-cache --counters -q $QSET -o "$TMP/$s"
  "$BIN" convert "$scene" -o "$TMP/$s.ply" > /dev/null
  "$BIN" info "$TMP/$s.ply" | sed -n 's/^particles: \([0-9]*\).*/\1/p' > "$TMP/$s.n"
done

if [ $tables_only = 0 ]; then
python3 - "$TMP" "$OUT" $SCENES <<'PY'
import csv, os, sys
tmp, out, scenes = sys.argv[1], sys.argv[2], sys.argv[3:]
rows, prov, npart = [], [], {}
for s in scenes:
    npart[s] = int(open(os.path.join(tmp, s + ".n")).read().split()[0])
    with open(os.path.join(tmp, s, "counters.csv")) as f:
        lines = f.read().splitlines()
    prov.append("# scene=%s; particles=%d; %s" % (s, npart[s], lines[0].lstrip("# ")))
    for r in csv.DictReader(lines[1:]):
        r["scene"] = s
        rows.append(r)
cols = ["scene", "method", "variant", "frame", "stage", "counter", "value"]
with open(os.path.join(out, "counters.csv"), "w", newline="") as f:
    f.write("\n".join(prov) + "\n")
    w = csv.writer(f, lineterminator="\n")
    w.writerow(cols)
    for r in rows:
        w.writerow([r[c] for c in cols])
PY
fi

python3 - "$OUT" "$FS_QUICK" <<'PY'
import csv, os, re, sys
out, quick = sys.argv[1], sys.argv[2] == "1"
# counters.csv: one provenance line per scene ("# scene=S; particles=N; ...size=WxH;"), then the rows
with open(os.path.join(out, "counters.csv")) as f:
    lines = f.read().splitlines()
prov = [l for l in lines if l.startswith("#")]
rows = list(csv.DictReader([l for l in lines if not l.startswith("#")]))
scenes, npart, pix = [], {}, {}
for l in prov:
    s = re.search(r"scene=([^;]*);", l).group(1)
    scenes.append(s)
    npart[s] = int(re.search(r"particles=(\d+)", l).group(1))
    w, h = re.search(r"size=(\d+)x(\d+)", l).groups()
    pix[s] = int(w) * int(h)
W, H = int(w), int(h)  # the same size for every scene
pixels = W * H
# work.csv: the totals, per pixel and per particle
work = [r for r in rows if r["stage"] == "total"]
with open(os.path.join(out, "work.csv"), "w", newline="") as f:
    f.write("\n".join(prov) + "\n")
    w = csv.writer(f, lineterminator="\n")
    w.writerow(["scene", "method", "variant", "counter", "total", "per_pixel", "per_particle"])
    for r in work:
        v = int(r["value"])
        w.writerow([r["scene"], r["method"], r["variant"], r["counter"], v, "%.4g" % (v / pixels), "%.4g" % (v / npart[r["scene"]])])

def val(scene, method, stage, counter):
    t = 0
    for r in rows:
        if r["variant"] == "ground truth": continue  # the same reference as the method variant "reference"
        if r["scene"] == scene and r["method"] == method and r["counter"] == counter and (stage is None and r["stage"] != "total" or r["stage"] == stage):
            t += int(r["value"])
    return t
def pp(x): return "%.3g" % (x / pixels)
def pn(x, s): return "%.3g" % (x / npart[s])

names = ["field_evals", "neighbours_visited", "march_samples", "fragments_shaded", "filter_taps", "texels_written"]
methods = []
for r in work:
    if r["method"] not in methods and r["variant"] != "ground truth": methods.append(r["method"])
def table(scene, per):
    t = "| method | " + " | ".join(names) + " |\n|---|" + "---|" * len(names) + "\n"
    for m in methods:
        cells = []
        for c in names:
            hit = [r for r in work if r["scene"] == scene and r["method"] == m and r["counter"] == c and r["variant"] != "ground truth"]
            cells.append(("%.3g" % (int(hit[0]["value"]) / per)) if hit else "—")
        t += "| %s | %s |\n" % (m, " | ".join(cells))
    return t

s0 = scenes[0]
readme = ["# Work counters: what each method does, in units that do not depend on the machine", "",
          "Generated by `experiments/counters/work.sh` from `counters.csv` (every stage) and `work.csv` (totals, per pixel, per particle); do not edit by hand.",
          "Each method (the reference among them; `counters.csv` also holds its ground-truth rows, the same counts) was rendered by `fluidsurf compare --counters --no-cache` at %dx%d with default parameters; the counts come from a separate counting render after the timed one. docs/DESIGN.md (\"Work counters\") defines each unit; each method's README lists what it counts in which stage. — marks a counter the method does not report; 0, one it reports that these parameters do not use (surfels and volume_raycast evaluate the field only with their exact CPU grid builder)." % (W, H), ""]
for s in scenes:
    readme += ["## %s (%d particles, %d pixels)" % (s, npart[s], pixels), "", "Per pixel:", "", table(s, pixels), "Per particle:", "", table(s, npart[s])]
readme += ["## Per stage", "", "The stages that do the work (first scene, `%s`), per pixel:" % s0, "",
           "| method | stage | counter | per pixel |", "|---|---|---|---|"]
for r in rows:
    if r["scene"] == s0 and r["stage"] != "total" and r["variant"] != "ground truth":
        readme.append("| %s | %s | %s | %s |" % (r["method"], r["stage"], r["counter"], pp(int(r["value"]))))
open(os.path.join(out, "README.md"), "w").write("\n".join(readme) + "\n")

# the paper studies' paragraphs
def block(scene_lines):
    return "\n".join(scene_lines)
para = {}
L = []
for s in scenes:
    ms, nb = val(s, "raycast_pca", "march", "march_samples"), val(s, "raycast_pca", "march", "neighbours_visited")
    fr = val(s, "raycast_pca", "splat", "fragments_shaded")
    pn_nb = val(s, "raycast_pca", "normals", "neighbours_visited")
    rs, rn = val(s, "reference", None, "march_samples"), val(s, "reference", None, "neighbours_visited")
    L.append("- %s (%d particles, %dx%d): the narrow-band march takes %s samples per pixel and visits %s neighbours per pixel (%s per sample), against %s splat fragments per pixel; the PCA normals visit %s neighbours per pixel. So per splat fragment the ray cast takes %.2g samples and %.3g neighbour visits. The exact reference: %s samples and %s neighbours per pixel." % (
        s, npart[s], W, H, pp(ms), pp(nb), "%.3g" % (nb / ms if ms else 0), pp(fr), pp(pn_nb), ms / fr if fr else 0, nb / fr if fr else 0, pp(rs), pp(rn)))
para["xiao2017"] = ["xiao2017 claims the narrow-band ray casting costs little next to splatting. In machine-independent work (`results/counters/`):"] + L
L = []
for s in scenes:
    an = val(s, "aniso_ssf", "anisotropy", "neighbours_visited")
    L.append("- %s: the WPCA anisotropy visits %s neighbours per particle; the ellipsoid splat shades %s fragments per pixel; the default filter reads %s taps per pixel (normals %s)." % (
        s, pn(an, s), pp(val(s, "aniso_ssf", "splat", "fragments_shaded")), pp(val(s, "aniso_ssf", "filter", "filter_taps")), pp(val(s, "aniso_ssf", "normals", "filter_taps"))))
para["xu2022"] = ["aniso_ssf's work in machine-independent units (`results/counters/`, %dx%d, default parameters):" % (W, H)] + L
L = []
for s in scenes:
    L.append("- %s: the slice-splat density grid shades %s fragments and writes %s voxels per particle; surfel splatting shades %s fragments per pixel (visibility and blend passes); the caustics %s fragments per pixel; the thickness march %s samples per pixel." % (
        s, pn(val(s, "surfels", "density_grid", "fragments_shaded"), s), pn(val(s, "surfels", "density_grid", "texels_written"), s),
        pp(val(s, "surfels", "visibility", "fragments_shaded") + val(s, "surfels", "blend", "fragments_shaded")),
        pp(val(s, "surfels", "caustics", "fragments_shaded")), pp(val(s, "surfels", "thickness", "march_samples"))))
para["iwasaki2006"] = ["surfels' work in machine-independent units (`results/counters/`, %dx%d, default parameters):" % (W, H)] + L
L = []
for s in scenes:
    L.append("- %s: volume generation shades %s fragments (one voxel each) per particle; the ray cast takes %s texture samples per pixel; the spheres baseline shades %s fragments per pixel (depth and thickness passes)." % (
        s, pn(val(s, "volume_raycast", "volume", "fragments_shaded"), s), pp(val(s, "volume_raycast", "march", "march_samples")),
        pp(val(s, "spheres", None, "fragments_shaded"))))
para["inacio2010"] = ["volume_raycast's and the spheres baseline's work in machine-independent units (`results/counters/`, %dx%d, default parameters):" % (W, H)] + L

BEGIN, END = "<!-- counters:begin (generated by experiments/counters/work.sh) -->", "<!-- counters:end -->"
if quick:  # quick mode: the blocks beside the CSVs; no study's README is touched
    with open(os.path.join(out, "paragraphs.md"), "w") as f:
        for study, lines in para.items():
            f.write("# %s\n\n" % study + BEGIN + "\n## Work counters\n\n" + lines[0] + "\n\n" + "\n".join(lines[1:]) + "\n" + END + "\n\n")
    sys.exit(0)
for study, lines in para.items():
    p = os.path.join("results", study, "README.md")
    text = open(p).read()
    blk = BEGIN + "\n## Work counters\n\n" + lines[0] + "\n\n" + "\n".join(lines[1:]) + "\n" + END
    if BEGIN in text:
        a, b = text.index(BEGIN), text.index(END) + len(END)
        text = text[:a] + blk + text[b:]
    else:
        text = text.rstrip("\n") + "\n\n" + blk + "\n"
    open(p, "w").write(text)
PY
echo "work.sh: wrote $OUT/counters.csv, $OUT/work.csv, $OUT/README.md and $(quick "the studies' counter paragraphs" "$OUT/paragraphs.md")" >&2
