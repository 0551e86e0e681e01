#!/usr/bin/env python3
"""A notebook-style study with the fluidsurf module: two methods against the
exact reference on every frame of a sequence, the per-frame errors plotted.

    PYTHONPATH=PREFIX/lib/python3.11/dist-packages python3 examples/python/compare_sequence.py

The sequence is a dam break from fluidsurf's own SPH simulator (`fluidsurf
simulate`, written as PLY frames into a temporary folder), unless --frames-glob
names frames of your own. Writes compare_sequence.csv and compare_sequence.png
beside this script (or into --out)."""
import argparse
import csv
import glob
import os
import shutil
import subprocess
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import fluidsurf  # noqa: E402

here = os.path.dirname(os.path.abspath(__file__))
ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
ap.add_argument("--methods", default="raycast_pca,aniso_ssf")
ap.add_argument("--frames-glob", help="particle files of a sequence, e.g. 'out/frame_*.ply' (default: simulate)")
ap.add_argument("--frames", type=int, default=16, help="frames to simulate")
ap.add_argument("--size", type=int, default=256)
ap.add_argument("--bin", default=shutil.which("fluidsurf") or "build/fluidsurf", help="fluidsurf, for simulate")
ap.add_argument("--out", default=here)
args = ap.parse_args()
methods = args.methods.split(",")

# 1. A sequence: yours, or a dam break simulated for the purpose.
tmp = None
if args.frames_glob:
    files = sorted(glob.glob(args.frames_glob))
else:
    tmp = tempfile.mkdtemp(prefix="fluidsurf-seq-")
    subprocess.run([args.bin, "simulate", "dam_break", "--frames", str(args.frames), "--particles", "6000",
                    "-o", os.path.join(tmp, "frame_%04d.ply"), "-q"], check=True)
    files = sorted(glob.glob(os.path.join(tmp, "frame_*.ply")))
if not files:
    raise SystemExit("compare_sequence: no frames found")

# 2. The study, through the engine of `fluidsurf compare` (fluidsurf.compare with a
#    list of frames): the reference once per frame, each method against it, one
#    camera for the whole sequence (framed on the first frame), 3 timed renders
#    per frame after a warm-up. The metrics table has metrics.csv's columns.
frames = [fluidsurf.read_particles(path) for path in files]
table = fluidsurf.compare([f["positions"] for f in frames], frames[0].get("radius"), methods=methods,
                          width=args.size, height=args.size, tables=True)
metrics = table["metrics"].to_dict("records") if hasattr(table["metrics"], "to_dict") else table["metrics"]
renderer = {r["method"]: r["renderer"] for r in (table["timings"].to_dict("records")
                                                 if hasattr(table["timings"], "to_dict") else table["timings"])}
rows = [{"frame": r["frame"], "method": r["method"], "mask_iou": r["mask_iou"], "normal_mean_deg": r["normal_mean_deg"],
         "depth_rmse_r": r["depth_rmse_r"], "frame_ms": r["frame_ms"], "renderer": renderer[r["method"]]}
        for r in metrics]
for m in methods:
    mine = [x["normal_mean_deg"] for x in rows if x["method"] == m]
    print(f"{m}: mean normal error {sum(mine) / len(mine):.2f} deg over {len(mine)} frames")
if tmp:
    shutil.rmtree(tmp)

# 3. The table and the plot.
os.makedirs(args.out, exist_ok=True)
csv_path = os.path.join(args.out, "compare_sequence.csv")
with open(csv_path, "w", newline="") as f:
    f.write(f"# fluidsurf {fluidsurf.version()}; {len(files)} frames at {args.size}x{args.size}\n")
    w = csv.DictWriter(f, fieldnames=list(rows[0]))
    w.writeheader()
    w.writerows(rows)
fig, axes = plt.subplots(1, 3, figsize=(12, 3.4))
for m in methods:
    mine = [x for x in rows if x["method"] == m]
    for ax, key, label in zip(axes, ("normal_mean_deg", "depth_rmse_r", "mask_iou"),
                              ("mean normal error (deg)", "depth RMSE (r)", "coverage IoU")):
        ax.plot([x["frame"] for x in mine], [x[key] for x in mine], marker="o", ms=3, label=m)
        ax.set_xlabel("frame")
        ax.set_ylabel(label)
        ax.grid(alpha=0.3)
axes[0].legend()
fig.suptitle(f"against the exact reference, simulated dam break, {args.size}x{args.size} "
             f"({fluidsurf.version()})", fontsize=9)
fig.tight_layout()
png_path = os.path.join(args.out, "compare_sequence.png")
fig.savefig(png_path, dpi=110)
print(f"wrote {csv_path} and {png_path}")
