#!/usr/bin/env python3
"""The peers study's plot (peers.sh): for each frame, every variant's interior normal
error against the share of the reference's thin pixels it keeps, from peers.csv alone.

    peers_plot.py DIR     reads DIR/peers.csv, writes DIR/peers.png
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    d = sys.argv[1]
    with open(os.path.join(d, "peers.csv")) as f:
        lines = f.read().splitlines()
    prov = lines[0].lstrip("# ")
    rows = list(csv.DictReader(lines[1:]))
    frames = list(dict.fromkeys(r["frame"] for r in rows))
    fig, axes = plt.subplots(1, len(frames), figsize=(4.2 * len(frames), 3.8), squeeze=False)
    for ax, frame in zip(axes[0], frames):
        for r in (r for r in rows if r["frame"] == frame):
            x, y = float(r["interior_normal_mean_deg"]), float(r["thin_kept"])
            ax.scatter(x, y, marker="o" if r["method"] == "mesh" else "s", s=28)
            ax.annotate(f"{r['method']} {r['variant']}", (x, y), fontsize=7, xytext=(3, 3), textcoords="offset points")
        ax.set_title(frame, fontsize=9)
        ax.set_xlabel("interior normal error (deg)")
        ax.set_ylabel("thin pixels kept")
        ax.set_ylim(0, 1.08)
        ax.grid(alpha=0.3)
    fig.suptitle(f"peers against the exact reference ({prov[:90]})", fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(d, "peers.png"), dpi=100)


if __name__ == "__main__":
    main()
