#!/usr/bin/env python3
"""Checks numbers in the studies' CSVs against bounds that hold by definition, so that
experiments/run_all.sh --quick fails when a study runs to the end but measures nonsense.

Each row of CHECKS below names a study of run_all.sh, a CSV under the results folder, the
rows it applies to, a value and a bound, and why the bound holds: what the method's paper
or the quantity's own definition implies, at any image size or particle count, never what
a run happened to measure. Every study that run_all.sh runs needs at least one row.

  rows   "*" (every row), or alternatives joined by " || ", each a conjunction of
         COL=VALUE (equal as text) and COL~REGEX (re.fullmatch) joined by "&"
  value  a column, or Python arithmetic over columns (abs, min, max; c("64") for a column
         whose name is no identifier); a PNG's "width" or "height" for a .png
  bound  ("in", LO, HI)      every matching row's value in [LO, HI]
         ("same", TOL)       over the matching rows, max - min <= TOL
         ("same_rel", TOL)   over the matching rows, (max - min) / max |value| <= TOL
  A bound applies to at least one row: no matching row is a failure too.

    check_quick.py [RESULTS]              (default: $FS_RESULTS, else out/quick/results)
    check_quick.py --table-only           only the table against run_all.sh's studies
    options: --run-all FILE (default experiments/run_all.sh), --only STUDY[,STUDY...]
             (check those studies' rows only, without the coverage check), --skip
             STUDY[,STUDY...] (leave those studies' rows out, e.g. on results/, which holds
             no output of the quick-only bench_make_splash)
Exit 0 when every bound holds, 1 naming each study, CSV, row and number that does not (and
each study without a row), 2 on bad usage.
"""
import csv
import math
import os
import re
import struct
import sys

R = "r"  # a reminder that depths are in multiples of the particle radius r

# fmt: off
CHECKS = [
    # --- xiao2017 (raycast_pca) ---
    ("xiao2017_fig3", "xiao2017/fig3_dam_metrics.csv", "*", "mask_iou", ("same", 0),
     "the variants differ only in the normal estimator and the normal filter, which xiao2017 "
     "computes after the ray march: coverage is the march's, the same for all"),
    ("xiao2017_fig3", "xiao2017/fig3_slab_metrics.csv", "*", "depth_bias_r", ("same", 0),
     "as above: the depth is the march's, the same for every normal variant"),
    ("xiao2017_fig4", "xiao2017/fig4.csv", "*", "mask_iou", ("in", 0, 1),
     "IoU = |A and B| / |A or B| lies in [0, 1] by definition"),
    ("xiao2017_fig4", "xiao2017/fig4.csv", "*", "interior_normal_mean_deg", ("in", 0, 180),
     "an angle between two unit normals lies in [0, 180] degrees"),
    ("xiao2017_fig5", "xiao2017/fig5_metrics.csv", "method=spheres || method=aniso_ssf&variant=anisotropy=off;filter=curvature",
     "mask_iou", ("same", 0),
     "aniso_ssf with anisotropy=off draws plain spheres of radius r with spheres' sprite "
     "shader (shaders/common/sphere_sprite.*, methods/aniso_ssf/README.md), and its curvature "
     "flow moves depth only: the same coverage"),
    ("xiao2017_fig5", "xiao2017/fig5_metrics.csv", "*", "n_both - n_interior", ("in", 0, math.inf),
     "the interior mask is a subset of the pixels both images cover"),
    ("xiao2017_fig6", "xiao2017/fig6.csv", "*", "mask_iou", ("in", 0, 1), "IoU lies in [0, 1] by definition"),
    ("xiao2017_fig7", "xiao2017/fig7.csv", "*", "mask_iou", ("in", 0, 1), "IoU lies in [0, 1] by definition"),
    ("xiao2017_fig7", "xiao2017/fig7.csv", "*", "depth_p95_r", ("in", 0, math.inf),
     "a percentile of |error - bias| is not negative"),
    ("xiao2017_fig10", "xiao2017/fig10.csv", "*", "frame_ms - march_ms", ("in", 0, math.inf),
     "the march is one stage of the frame: its time is part of the frame's"),
    ("xiao2017_radius", "xiao2017/radius_sweep.csv", "*", "interior_deg", ("in", 0, 180),
     "an angle between two unit normals lies in [0, 180] degrees"),
    ("xiao2017_joint", "xiao2017/joint_sweep.csv", "*", "interior_deg", ("in", 0, 180),
     "an angle between two unit normals lies in [0, 180] degrees"),
    ("xiao2017_thickness", "xiao2017/thickness.csv", "*", "ratio_of_means - method_mean_r / ref_mean_r", ("in", -1e-3, 1e-3),
     "the ratio of the mean thicknesses is the ratio of their means over the same pixels (to the CSV's 4 decimals)"),
    ("xiao2017_thickness", "xiao2017/thickness.csv", "*", "diff_abs_mean_r - abs(diff_mean_r)", ("in", -2e-4, math.inf),
     "the mean of |d| is at least |mean of d| (the triangle inequality; to the CSV's 4 decimals)"),
    ("xiao2017_table1", "xiao2017/table1_ratios.csv", "series=paper_gtx970&size=512", "ratio_to_512", ("in", 0.9995, 1.0005),
     "t(512) / t(512) = 1 (printed to 3 decimals): the ratio's definition, on the paper's Table 1"),
    ("xiao2017_bars", "xiao2017/bars.csv", "bar=dam_break_iou", "measured", ("in", 0, 1),
     "the bar is an IoU, in [0, 1] by definition"),
    # --- xu2022 (aniso_ssf) ---
    ("xu2022_fig5", "xu2022/fig5_bands_summary.csv", "*",
     "visible_deg - (interface_deg * interface_px + away_deg * away_px) / (interface_px + away_px)", ("in", -1e-3, 1e-3),
     "the visible pixels split into the interface band and the rest (xu2022 Fig. 5): the "
     "visible mean is their pixel-weighted mean (to the CSV's 4 decimals)"),
    ("xu2022_fig6", "xu2022/fig6_slab_metrics.csv", "variant~anisotropy=off;.*", "mask_iou", ("same", 0),
     "the screen-space filters (Gaussian, bilateral, curvature flow, narrow-range) smooth the "
     "depth of covered pixels only: with the same splat, the same coverage"),
    ("xu2022_fig6", "xu2022/fig6_box_metrics.csv", "variant~anisotropy=on;.*", "mask_iou", ("same", 0),
     "as above, with the anisotropic splat"),
    ("xu2022_fig4_collision", "xu2022/fig4_collision_metrics.csv", "variant~anisotropy=on;.*&reference=reference",
     "mask_iou", ("same", 0), "as in xu2022_fig6: the filters leave the anisotropic splat's coverage as it is"),
    ("xu2022_fig4_collision", "xu2022/fig4_collision_frames.csv", "*", "particles", ("same", 0),
     "the SPH double dam break neither gains nor loses particles between frames"),
    ("xu2022_fig2", "xu2022/fig2.csv", "*", "mask_iou", ("in", 0, 1), "IoU lies in [0, 1] by definition"),
    ("xu2022_fig8", "xu2022/fig8_highlights.csv", "*", "highlight_pct", ("in", 0, 100),
     "a share of the image's pixels, in percent"),
    ("xu2022_fig9", "xu2022/fig9.csv", "*", "frame_ms", ("in", 0, math.inf), "a time is not negative"),
    ("xu2022_sigma", "xu2022/sigma_sweep.csv", "*", "interior_deg", ("in", 0, 180),
     "an angle between two unit normals lies in [0, 180] degrees"),
    ("xu2022_doubts", "xu2022/doubts_narrow_bias.csv", "view=oblique", "mask_iou", ("same", 0),
     "the depth filters change depth only, not the splat's coverage"),
    ("xu2022_bars", "xu2022/bars.csv", "bar~b_slab_curvature_aniso_.*_coverage_iou", "measured", ("in", 1, 1),
     "curvature flow (van der Laan et al. 2009, as xu2022 uses it) moves depth only: the "
     "coverage against the unfiltered image is identical, IoU 1"),
    # --- iwasaki2006 (surfels) ---
    ("iwasaki2006_density_grid", "iwasaki2006/density_grid.csv", "method=slice_splat", "rel_l2_vs_exact", ("in", 0, 1e-5),
     "iwasaki2006's slice splatting adds the same kernel terms as the exact sum; only "
     "float32 rounding of the additive blend differs, about (terms per voxel) x 2^-24"),
    ("iwasaki2006_density_grid", "iwasaki2006/density_grid.csv", "method=exact_cpu", "rel_l2_vs_exact", ("in", 0, 0),
     "the exact grid against itself"),
    ("iwasaki2006_surfels", "iwasaki2006/dam_break_metrics.csv", "*", "mask_iou", ("same", 0),
     "caustics add light to the floor's shading; the surfels' G-buffer is the same"),
    ("iwasaki2006_surfels", "iwasaki2006/double_dam_metrics.csv", "*", "interior_normal_mean_deg", ("same", 0),
     "as above: the normals do not depend on the caustics switch"),
    ("iwasaki2006_tables", "iwasaki2006/density_grid_table.csv", "*",
     "exact_cpu_ms / slice_splat_ms - exact_over_splat", ("in", -0.006, 0.006),
     "the column is the ratio of the two times (printed to 2 decimals)"),
    ("iwasaki2006_caustics", "iwasaki2006/caustics.csv", "bar=flat_slab_no_jitter_median", "ratio", ("in", 0.95, 1.05),
     "light from straight above through a flat surface is neither focused nor spread (flux "
     "ratio 1), so the floor's irradiance is eq. 2's L_i T(0) exp(-c l) at the ideal depth; "
     "5% leaves room for the lattice's iso-surface ripples (period 2r) that the bar's note names"),
    ("iwasaki2006_fig7", "iwasaki2006/fig7_metrics.csv", "*", "n_both - n_interior", ("in", 0, math.inf),
     "the interior mask is a subset of the pixels both images cover"),
    ("iwasaki2006_fig9_wavemaker", "iwasaki2006/fig9_wavemaker_metrics.csv", "*", "n_both - n_interior",
     ("in", 0, math.inf), "the interior mask is a subset of the pixels both images cover"),
    ("iwasaki2006_fig9_wavemaker", "iwasaki2006/fig9_wavemaker_frames.csv", "*", "particles", ("same", 0),
     "the shaken tank neither gains nor loses particles between frames"),
    ("iwasaki2006_fig8", "iwasaki2006/fig8.csv", "image=splat&against=exact", "mask_iou", ("in", 0.99, 1),
     "the splatted grid equals the exact one up to float rounding (density_grid.csv): only "
     "a pixel whose ray grazes the iso-surface can change coverage"),
    ("iwasaki2006_fig9_wavemaker", "iwasaki2006/fig9_wavemaker_metrics.csv", "*", "n_both - n_interior",
     ("in", 0, math.inf), "the interior mask is a subset of the pixels both images cover"),
    ("iwasaki2006_fig9_wavemaker", "iwasaki2006/fig9_wavemaker_frames.csv", "*", "particles", ("same", 0),
     "the shaken tank neither gains nor loses particles between frames"),
    ("iwasaki2006_fig8", "iwasaki2006/fig8.csv", "image=splat&against=exact", "interior_normal_mean_deg", ("in", 0, 0.1),
     "a field that differs by ~1e-7 relative turns its gradient by ~1e-5 rad, far under 0.1 degree"),
    # --- inacio2010 (volume_raycast, the SPH simulator) ---
    ("inacio2010_tables", "inacio2010/tables.csv", "table=I",
     "simulation_pct + fetch_pct + volume_pct + raycast_pct + rendering_pct", ("in", 99.7, 100.3),
     "total is the sum of the stage medians (tables.sh), so the shares add up to 100 "
     "(five values printed to 0.1: +-0.25)"),
    ("inacio2010_fig6", "inacio2010/fig6_timestep.csv", "*", "particles", ("same", 0),
     "every cell simulates the same block, and the simulator neither creates nor removes "
     "particles: mass (equal particle masses) is conserved"),
    ("inacio2010_fig2", "inacio2010/fig2_timings.csv", "*", "ms_median - ms_min", ("in", 0, math.inf),
     "a median is not below the minimum of the same runs"),
    ("inacio2010_fig9", "inacio2010/fig9.csv", "*", "render_ms", ("in", 0, math.inf), "a time is not negative"),
    ("inacio2010_fig7", "inacio2010/fig7.csv", "*", "particles", ("same", 0),
     "both step sizes simulate the same block; particles (mass) are conserved"),
    ("inacio2010_volume_raycast", "inacio2010/volume_raycast_bar.csv", "*", "normal_mean_deg", ("same", 0),
     "inacio2010's surface and translucent transfer functions shade the same G-buffer: the "
     "same normals"),
    ("inacio2010_fig8", "inacio2010/fig8.csv", "row=translucent image against surface image",
     "image_rms_error - image_mean_error", ("in", -1e-6, math.inf),
     "the mean of |e| is at most its root mean square (Cauchy-Schwarz)"),
    ("inacio2010_fig8", "inacio2010/fig8.csv", "row=translucent image against surface image",
     "image_max_error - image_rms_error", ("in", -1e-6, math.inf), "the RMS of |e| is at most its largest value"),
    ("inacio2010_sim_bar", "inacio2010/sim_bar_cpu_frames.csv", "*", "particles", ("same", 0),
     "the simulation conserves mass: the same particles in every frame"),
    ("inacio2010_sim_bar", "inacio2010/sim_bar_gpu_frames.csv", "*", "particles", ("same", 0),
     "the simulation conserves mass: the same particles in every frame"),
    ("inacio2010_sim_bar", "inacio2010/sim_bar.csv", "*", "depth / depth_expected - 1 - depth_rel_err", ("in", -1e-4, 1e-4),
     "the column is the relative depth error's definition (printed to 4 decimals)"),
    ("inacio2010_sim_speed", "inacio2010/sim_speed.csv", "*", "abs(1000 / ms_per_step - steps_per_s) - 0.5 / ms_per_step ** 2",
     ("in", -math.inf, 0.05),
     "steps per second is 1000 over the milliseconds per step: they agree to the rounding of "
     "both (steps_per_s to 0.1, ms_per_step to 0.001, which moves 1000 / ms by 0.5 / ms^2)"),
    # --- benchmarks, baselines, counters, the main job ---
    ("bench_make_splash", "bench/make_splash/dam_break_splash.stats.csv", "*", "particles", ("same", 0),
     "the simulation conserves mass: the same particles in every frame"),
    ("bench_foundation", "bench/foundation.csv", "*", "ms_median", ("in", 0, math.inf), "a time is not negative"),
    ("bench_foundation", "bench/foundation.csv", "scene~dam_break_24k_ref[0-9]+&method=reference", "peak_rss_kib", ("same", 0),
     "one process renders every stage of a scene: its one peak RSS stands on each stage's row"),
    ("bench_info", "bench/info.csv", "*", "estimated_r / true_r - ratio", ("in", -1e-3, 1e-3),
     "the ratio column is estimated r over true r (printed to 4 decimals)"),
    ("bench_memory", "bench/memory.csv", "*", "peak_rss_kib_median - peak_rss_kib_min", ("in", 0, math.inf),
     "a median is not below the minimum of the same runs"),
    ("bench_memory", "bench/memory.csv", "*", "peak_rss_kib_max - peak_rss_kib_median", ("in", 0, math.inf),
     "a median is not above the maximum of the same runs"),
    ("bench_speed", "bench/speed.csv", "set=splash&width~(?!8$)[0-9]+&method~reference( thickness=off|@a548d02)?", "coverage", ("same", 0),
     "the thickness switch does not move the surface, and the old commit's reference is the "
     "same ground truth (the speed-up must not change the image); the image-size runs, not the 8x8 ones"),
    ("bench_speed", "bench/speed.csv", "coverage~.+", "coverage", ("in", 0, 1),
     "a share of the image's pixels (none read from fluidsurf's PNGs, whose background is drawn)"),
    ("bench_thickness_counts", "bench/thickness_counts.csv", "stage=march", "crossings - hits", ("in", 0, 0),
     "the first-hit march ends at its ray's first crossing, and a pixel is a hit when it has one"),
    ("bench_thickness_counts", "bench/thickness_counts.csv", "variant=thickness_on&stage=thickness", "crossings - hits",
     ("in", 0, math.inf), "with thickness on every hit's ray also crosses out of the fluid after its first crossing"),
    ("bench_interior_auto", "bench/interior_auto.csv", "variant=off", "interior_ms", ("in", 0, 0),
     "interior=off builds no interior bits: no interior stage"),
    ("bench_interior_auto", "bench/interior_auto.csv", "variant~(on|auto)", "built - (interior_ms > 0)", ("in", 0, 0),
     "a render built the bits exactly when it has an interior stage (interior=on always does)"),
    ("baselines", "baselines/quality.csv", "method=reference", "mask_iou", ("in", 1, 1),
     "the reference against itself: IoU 1"),
    ("baselines", "baselines/quality.csv", "method=reference",
     "abs(depth_bias_r) + depth_rmse_r + normal_mean_deg", ("in", 0, 0), "the reference against itself: no error"),
    ("counters", "counters/work.csv", "scene=dam_break&total~[1-9][0-9]*", "total / per_pixel", ("same_rel", 1e-3),
     "per_pixel is the total over the image's pixels (4 significant digits): the same divisor "
     "for every counter of a scene (a counter the method does not count is 0 and left out)"),
    ("counters", "counters/work.csv", "scene=dam_break&total~[1-9][0-9]*", "total / per_particle", ("same_rel", 1e-3),
     "per_particle is the total over the particle count: the same divisor for every counter"),
    ("slurm_scaling", "slurm/scaling.csv", "*", "wall_s_median - wall_s_min", ("in", 0, math.inf),
     "a median is not below the minimum of the same runs"),
    ("demo", "demo/metrics.csv", "method=reference", "mask_iou", ("in", 1, 1), "the reference against itself: IoU 1"),
    ("demo", "demo/metrics.csv", "method=reference", "abs(depth_bias_r) + depth_rmse_r + normal_mean_deg",
     ("in", 0, 0), "the reference against itself: no error"),
    ("demo", "demo/metrics.csv", "*", "mask_iou", ("in", 0, 1), "IoU lies in [0, 1] by definition"),
    ("tables", "xiao2017/table1_growth.csv", "series=paper_gtx970&particles=779752", 'c("512")', ("in", 0.9995, 1.0005),
     "the pivot of t(size) / t(512) at 512 is 1 by definition"),
    ("plots", "xiao2017/fig10.png", "*", "width", ("in", 900, 900),
     "plots.sh draws only PNGs; plot_csv.py draws every plot 900 wide (pngcairo size 900,560)"),
    ("plots", "xiao2017/fig10.png", "*", "height", ("in", 560, 560), "and 560 high"),
]
# fmt: on

# run_all.sh's entries that check rather than measure: no row needed
# (main_job: scripts/demo.sh writes out/quick/demo, not results; the study demo checks the same run)
NOT_STUDIES = {"readme_tables", "results_clean", "quick_bounds", "results_numbers", "results_index", "results_bounds",
               "main_job"}


def studies_of(run_all):
    """The study names run_all.sh runs, in order (`study NAME COMMAND...`)."""
    names = []
    with open(run_all) as f:
        for line in f:
            m = re.match(r"\s*(?:\[[^]]*\]\s*&&\s*)?study\s+([A-Za-z0-9_]+)\s", line)
            if m and m.group(1) not in names:
                names.append(m.group(1))
    return names


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def png_size(path):
    with open(path, "rb") as f:
        head = f.read(24)
    if head[:8] != b"\x89PNG\r\n\x1a\n" or head[12:16] != b"IHDR":
        raise ValueError("not a PNG")
    w, h = struct.unpack(">II", head[16:24])
    return [{"width": str(w), "height": str(h)}]


def matcher(spec):
    if spec == "*":
        return lambda row: True
    alts = []
    for alt in spec.split(" || "):
        conds = []
        for cond in alt.split("&"):
            m = re.match(r"([^=~]+)([=~])(.*)$", cond)
            if not m:
                raise ValueError("bad row filter %r" % cond)
            conds.append(m.groups())
        alts.append(conds)

    def match(row):
        for conds in alts:
            ok = True
            for col, op, val in conds:
                have = row.get(col)
                if have is None or (op == "=" and have != val) or (op == "~" and not re.fullmatch(val, have)):
                    ok = False
                    break
            if ok:
                return True
        return False

    return match


def number(row, col):
    if col not in row:
        raise KeyError("no column %s" % col)
    try:
        return float(row[col])
    except (TypeError, ValueError):
        raise ValueError("%s is %r, not a number" % (col, row[col]))


class Columns(dict):
    def __init__(self, row):
        super().__init__()
        self.row = row

    def __missing__(self, key):
        return number(self.row, key)


def evaluate(expr, row):
    env = {"__builtins__": {}, "abs": abs, "min": min, "max": max, "c": lambda k: number(row, k)}
    return float(eval(expr, env, Columns(row)))


def describe(row, keys=3):
    """A row named by its first columns, for a failure message."""
    return ", ".join("%s=%s" % (k, v) for k, v in list(row.items())[:keys])


def check(results, study, path, rows, expr, bound, why):
    """Failure lines of one table row (empty when it holds)."""
    full = os.path.join(results, path)
    where = "%s: %s" % (study, full)
    try:
        table = png_size(full) if path.endswith(".png") else read_csv(full)
        picked = [r for r in table if matcher(rows)(r)]
    except (OSError, ValueError) as e:
        return ["%s: cannot read: %s" % (where, e)]
    if not picked:
        return ["%s: no row matches %r (the bound needs one: %s)" % (where, rows, why)]
    values = []
    for r in picked:
        try:
            values.append((evaluate(expr, r), r))
        except (KeyError, ValueError, ZeroDivisionError, SyntaxError, NameError, TypeError) as e:
            return ["%s: row %s: %s: %s" % (where, describe(r), expr, e)]
    kind = bound[0]
    if kind == "in":
        lo, hi = bound[1], bound[2]
        return ["%s: row %s: %s = %.6g, want in [%g, %g]: %s" % (where, describe(r), expr, v, lo, hi, why)
                for v, r in values if not (lo <= v <= hi)]
    vs = [v for v, _ in values]
    spread = max(vs) - min(vs)
    if kind == "same_rel":
        scale = max(abs(v) for v in vs)
        spread = spread / scale if scale > 0 else 0
    if kind in ("same", "same_rel") and spread <= bound[1]:
        return []
    if kind not in ("same", "same_rel"):
        return ["%s: unknown bound %r" % (where, bound)]
    lo_v, lo_r = min(values, key=lambda x: x[0])
    hi_v, hi_r = max(values, key=lambda x: x[0])
    return ["%s: %s differs over %d rows%s: %.6g (row %s) .. %.6g (row %s), want a spread <= %g: %s"
            % (where, expr, len(values), " (relative)" if kind == "same_rel" else "", lo_v, describe(lo_r), hi_v,
               describe(hi_r), bound[1], why)]


def main(argv):
    results, run_all, only, skip, table_only = None, "experiments/run_all.sh", None, set(), False
    args = list(argv)
    while args:
        a = args.pop(0)
        if a == "--table-only":
            table_only = True
        elif a == "--run-all" and args:
            run_all = args.pop(0)
        elif a == "--only" and args:
            only = set(args.pop(0).split(","))
        elif a == "--skip" and args:
            skip = set(args.pop(0).split(","))
        elif a in ("-h", "--help"):
            print(__doc__)
            return 0
        elif not a.startswith("-") and results is None:
            results = a
        else:
            print("usage: check_quick.py [RESULTS] [--table-only] [--run-all FILE] [--only STUDY,...] [--skip STUDY,...]",
                  file=sys.stderr)
            return 2
    results = results or os.environ.get("FS_RESULTS") or "out/quick/results"
    fails = []
    if only is None:
        try:
            studies = studies_of(run_all)
        except OSError as e:
            print("check_quick: %s: %s" % (run_all, e), file=sys.stderr)
            return 2
        listed = {c[0] for c in CHECKS}
        for s in sorted(skip - listed):
            fails.append("%s: --skip names a study without a row in the table" % s)
        for s in studies:
            if s not in listed and s not in NOT_STUDIES:
                fails.append("%s: a study of %s without a row in check_quick.py's table: add a bound it must "
                             "meet by definition" % (s, run_all))
        for s in sorted(listed - set(studies)):
            fails.append("%s: a row in check_quick.py's table for a study %s does not run" % (s, run_all))
    for c in CHECKS:
        try:
            matcher(c[2])
            compile(c[3], "<value>", "eval")
        except (ValueError, SyntaxError) as e:
            fails.append("%s: %s: bad table row: %s" % (c[0], c[1], e))
    if not table_only:
        if not os.path.isdir(results):
            print("check_quick: %s: no such folder (run experiments/run_all.sh --quick)" % results, file=sys.stderr)
            return 2
        n = 0
        for study, path, rows, expr, bound, why in CHECKS:
            if (only is not None and study not in only) or study in skip:
                continue
            n += 1
            fails += check(results, study, path, rows, expr, bound, why)
        if only is not None and n == 0:
            print("check_quick: --only %s: no such study in the table" % ",".join(sorted(only)), file=sys.stderr)
            return 2
    for line in fails:
        print("check_quick: FAIL %s" % line)
    checked = "the table" if table_only else "%s" % results
    if fails:
        print("check_quick: %d failure(s) in %s" % (len(fails), checked))
        return 1
    print("check_quick: %s: every bound holds (%d rows)" % (checked, len(CHECKS)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
