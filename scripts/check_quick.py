#!/usr/bin/env python3
"""Checks the numbers in the studies' CSVs against bounds, so that experiments/run_all.sh --quick
fails when a study runs to the end but measures nonsense, or when a method it studies is broken.

Each row of CHECKS below names a study of run_all.sh, a CSV under the results folder, the
rows it applies to, a value and a bound, and why the bound holds, at the quick size and at
the full one (tests/check_quick.sh also checks the committed results/). Two kinds of bound:
  - by definition: what the quantity's own definition implies (an IoU in [0, 1], the shares
    of a total adding up to 100, a conserved particle count);
  - with teeth: what the method's paper says it does, which a broken method fails: quality
    against the exact reference (coverage, normal error), a switch that changes what the
    paper says it changes (anisotropy, the normal filter, the translucent mode, the time
    step), a bar's verdict equal to the committed one, a simulation that stays bounded
    without the safety clamp. Each names the full size's value in its why.
Every study that run_all.sh runs needs at least one row; every study of a method, one with teeth.

  rows   "*" (every row), or alternatives joined by " || ", each a conjunction of
         COL=VALUE (equal as text) and COL~REGEX (re.fullmatch) joined by "&"
  value  a column, or Python arithmetic over columns (abs, min, max; c("64") for a column
         whose name is no identifier); a PNG's "width" or "height" for a .png
  bound  ("in", LO, HI)      every matching row's value in [LO, HI]
         ("same", TOL)       over the matching rows, max - min <= TOL
         ("same_rel", TOL)   over the matching rows, (max - min) / max |value| <= TOL
         ("lt", OTHER, F)    every matching row's value below F times the value of the one row
                             that OTHER (rows, as above) matches in the same CSV
         ("differ", OTHER, TOL)  every matching row's value at least TOL away from OTHER's
         ("as_committed", KEY)   value names a column: each matching row's text there equals
                             that of the committed CSV's row (--committed, default results/)
                             with the same KEY
  A bound applies to at least one row: no matching row is a failure too.

    check_quick.py [RESULTS]              (default: $FS_RESULTS, else out/quick/results)
    check_quick.py --table-only           only the table against run_all.sh's studies
    options: --run-all FILE (default experiments/run_all.sh), --only STUDY[,STUDY...]
             (check those studies' rows only, without the coverage check), --skip
             STUDY[,STUDY...] (leave those studies' rows out, e.g. on results/, which holds
             no output of the quick-only bench_make_splash), --committed DIR (the committed
             results the as_committed bounds compare with; default results)
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
    ("xiao2017_fig3", "xiao2017/fig3_slab_bands.csv", "normals=blend&filter=filter=off&region=face", "mean_deg",
     ("lt", "normals=basic&filter=filter=off&region=face", 0.7),
     "PCA smooths flat parts (xiao2017 section 3.3, Fig. 3): without the filter the blended normal's error on the "
     "slab's faces is well below the basic gradient's (full size 0.42x, quick 0.41x)"),
    ("xiao2017_fig3", "xiao2017/fig3_slab_bands.csv", "normals=basic&filter=filter=on&region=face", "mean_deg",
     ("lt", "normals=basic&filter=filter=off&region=face", 0.5),
     "the bilateral filter on the normal map (section 3.3) smooths: the filter switch must lower the face error "
     "(full size 0.17x, quick 0.26x)"),
    ("xiao2017_fig3", "xiao2017/fig3_dam_metrics.csv", "*", "mask_iou", ("in", 0.95, 1),
     "raycast_pca's march finds the reference's iso-surface: coverage against `reference` (full size 0.998)"),
    ("xiao2017_fig4", "xiao2017/fig4.csv", "*", "mask_iou", ("in", 0, 1),
     "IoU = |A and B| / |A or B| lies in [0, 1] by definition"),
    ("xiao2017_fig4", "xiao2017/fig4.csv", "method=raycast_pca", "mask_iou", ("in", 0.95, 1),
     "raycast_pca keeps the sheets and spray of the breaking cubes (Fig. 4): coverage against `reference` "
     "(full size at least 0.996)"),
    ("xiao2017_fig4", "xiao2017/fig4.csv", "frame=0&method=raycast_pca", "interior_normal_mean_deg",
     ("lt", "frame=0&method=spheres", 0.2),
     "the cubes at rest are flat with sharp corners (Fig. 4): raycast_pca's normals far closer to the iso-surface's "
     "than the spheres' bumps (full size 0.93 against 49 degrees)"),
    ("xiao2017_fig4", "xiao2017/fig4.csv", "*", "interior_normal_mean_deg", ("in", 0, 180),
     "an angle between two unit normals lies in [0, 180] degrees"),
    ("xiao2017_fig5", "xiao2017/fig5_metrics.csv", "method=spheres || method=aniso_ssf&variant=anisotropy=off;filter=curvature",
     "mask_iou", ("same", 0),
     "aniso_ssf with anisotropy=off draws plain spheres of radius r with spheres' sprite "
     "shader (shaders/common/sphere_sprite.*, methods/aniso_ssf/README.md), and its curvature "
     "flow moves depth only: the same coverage"),
    ("xiao2017_fig5", "xiao2017/fig5_metrics.csv", "*", "n_both - n_interior", ("in", 0, math.inf),
     "the interior mask is a subset of the pixels both images cover"),
    ("xiao2017_fig5", "xiao2017/fig5_metrics.csv", "method=raycast_pca", "interior_normal_mean_deg",
     ("lt", "method=aniso_ssf&variant=", 0.7),
     "Fig. 5's order: raycast_pca's normals follow the iso-surface more closely than anisotropic screen-space "
     "rendering's (full size 6.2 against 14.5 degrees)"),
    ("xiao2017_fig5", "xiao2017/fig5_metrics.csv", "method=raycast_pca", "mask_iou", ("in", 0.95, 1),
     "raycast_pca's coverage against `reference` (full size 0.998)"),
    ("xiao2017_fig6", "xiao2017/fig6.csv", "*", "mask_iou", ("in", 0.95, 1),
     "raycast_pca follows the spouts' surface: coverage against `reference` (full size at least 0.988)"),
    ("xiao2017_fig7", "xiao2017/fig7.csv", "*", "mask_iou", ("in", 0.95, 1),
     "raycast_pca keeps the splash under transparency: coverage against `reference` (full size at least 0.997)"),
    ("xiao2017_fig7", "xiao2017/fig7.csv", "*", "normal_mean_deg", ("in", 0, 15),
     "and its normals stay near the iso-surface's (full size at most 7.5 degrees)"),
    ("xiao2017_fig7", "xiao2017/fig7.csv", "*", "depth_p95_r", ("in", 0, math.inf),
     "a percentile of |error - bias| is not negative"),
    ("xiao2017_fig10", "xiao2017/fig10.csv", "*", "frame_ms - march_ms", ("in", 0, math.inf),
     "the march is one stage of the frame: its time is part of the frame's"),
    ("xiao2017_fig10", "xiao2017/fig10.csv", "*", "march_ms / frame_ms", ("in", 0.5, 1),
     "on llvmpipe raycast_pca's frame is its per-pixel march (xiao2017/README.md, Table 1): a march that samples "
     "nothing would leave the splat to dominate (full size 0.75 to 0.9)"),
    ("xiao2017_radius", "xiao2017/radius_sweep.csv", "*", "interior_deg", ("in", 0, 180),
     "an angle between two unit normals lies in [0, 180] degrees"),
    ("xiao2017_radius", "xiao2017/radius_sweep.csv", "scene=slab&normals=basic&pca_radius_r=4", "interior_deg",
     ("lt", "scene=slab&normals=basic&pca_radius_r=3", 0.9),
     "R sets eq. 2's kernel: the basic normal over R = 4 r is smoother on the slab than over 3 r (full size 2.59 "
     "against 4.07 degrees), so a radius that is not passed on fails"),
    ("xiao2017_joint", "xiao2017/joint_sweep.csv", "*", "interior_deg", ("in", 0, 180),
     "an angle between two unit normals lies in [0, 180] degrees"),
    ("xiao2017_joint", "xiao2017/joint_sweep.csv", "scene=slab&normals=blend&pca_radius_r=3&min_neighbors=4",
     "interior_deg", ("lt", "scene=slab&normals=blend&pca_radius_r=3&min_neighbors=10", 0.8),
     "PCA needs enough neighbours (xiao2017 Fig. 3): at R = 3 r a face particle has under 10, so min_neighbors = 10 "
     "leaves the basic normal and 4 lets PCA smooth (full size 2.04 against 4.07 degrees)"),
    ("xiao2017_thickness", "xiao2017/thickness.csv", "*", "ratio_of_means - method_mean_r / ref_mean_r", ("in", -1e-3, 1e-3),
     "the ratio of the mean thicknesses is the ratio of their means over the same pixels (to the CSV's 4 decimals)"),
    ("xiao2017_thickness", "xiao2017/thickness.csv", "*", "diff_abs_mean_r - abs(diff_mean_r)", ("in", -2e-4, math.inf),
     "the mean of |d| is at least |mean of d| (the triangle inequality; to the CSV's 4 decimals)"),
    ("xiao2017_thickness", "xiao2017/thickness.csv", "default=1", "ratio_of_means", ("in", 0.9, 1.2),
     "the shipped thickness (section 3.4's sprites, volume weight) follows the exact one through the fluid on every "
     "frame (full size 1.04)"),
    ("xiao2017_table1", "xiao2017/table1_ratios.csv", "series~ours_.*&size~(128|1920)", "ratio_to_512", ("in", 1.8, math.inf),
     "on llvmpipe raycast_pca's frame is its per-pixel march: the largest image (quick 4x, full size 14x the "
     "pixels of the smallest) costs at least 1.8x its time (full size 11.9x to 16.0x, quick 2.6x to 2.9x)"),
    ("xiao2017_bars", "xiao2017/bars.csv", "bar=dam_break_iou", "measured", ("in", 0, 1),
     "the bar is an IoU, in [0, 1] by definition"),
    ("xiao2017_bars", "xiao2017/bars.csv", "verdict~pass|FAIL", "verdict", ("as_committed", "bar"),
     "each bar's verdict is the committed one (results/xiao2017/bars.csv): a change that flips a bar must show in "
     "the committed results and their README, not pass unseen"),
    # --- xu2022 (aniso_ssf) ---
    ("xu2022_fig5", "xu2022/fig5_bands_summary.csv", "*",
     "visible_deg - (interface_deg * interface_px + away_deg * away_px) / (interface_px + away_px)", ("in", -1e-3, 1e-3),
     "the visible pixels split into the interface band and the rest (xu2022 Fig. 5): the "
     "visible mean is their pixel-weighted mean (to the CSV's 4 decimals)"),
    ("xu2022_fig5", "xu2022/fig5_bands_summary.csv", "reference=reference&filter=none&anisotropy=on", "visible_deg",
     ("lt", "reference=reference&filter=none&anisotropy=off", 0.8),
     "anisotropic sprites are smoother than spheres where fluid meets solids (xu2022 Fig. 5): without a filter the "
     "switch lowers the error over the visible surface (full size 26.1 against 47.4 degrees)"),
    ("xu2022_fig6", "xu2022/fig6_slab_metrics.csv", "variant~anisotropy=off;.*", "mask_iou", ("same", 0),
     "the screen-space filters (Gaussian, bilateral, curvature flow, narrow-range) smooth the "
     "depth of covered pixels only: with the same splat, the same coverage"),
    ("xu2022_fig6", "xu2022/fig6_box_metrics.csv", "variant~anisotropy=on;.*", "mask_iou", ("same", 0),
     "as above, with the anisotropic splat"),
    ("xu2022_fig6", "xu2022/fig6_slab_metrics.csv", "variant=anisotropy=on;filter=none", "interior_normal_mean_deg",
     ("lt", "variant=anisotropy=off;filter=none", 0.7),
     "anisotropy flattens the sphere beads (xu2022 Fig. 6, no filter): on the slab its interior normal error is "
     "well below the spheres' (full size 19.8 against 46.2 degrees)"),
    ("xu2022_fig6", "xu2022/fig6_slab_metrics.csv", "variant=anisotropy=off;filter=gaussian", "interior_normal_mean_deg",
     ("lt", "variant=anisotropy=off;filter=none", 0.5),
     "a depth filter smooths the splatted depth (Fig. 6's filter columns): the Gaussian far below no filter "
     "(full size 7.1 against 46.2 degrees)"),
    ("xu2022_fig4_collision", "xu2022/fig4_collision_metrics.csv", "variant~anisotropy=on;.*&reference=reference",
     "mask_iou", ("same", 0), "as in xu2022_fig6: the filters leave the anisotropic splat's coverage as it is"),
    ("xu2022_fig4_collision", "xu2022/fig4_collision_frames.csv", "*", "particles", ("same", 0),
     "the SPH double dam break neither gains nor loses particles between frames"),
    ("xu2022_fig4_collision", "xu2022/fig4_collision_metrics.csv", "variant=anisotropy=on;filter=none&reference=reference",
     "interior_normal_mean_deg", ("lt", "variant=anisotropy=off;filter=none&reference=reference", 0.8),
     "the anisotropic blocks are smoother (xu2022 Fig. 4): without a filter anisotropy lowers the interior normal "
     "error (full size 24.0 against 46.1 degrees)"),
    ("xu2022_fig4_collision", "xu2022/fig4_collision_frames.csv", "*", "v_mean", ("in", 0, 5),
     "the simulation stays bounded: two 1 m blocks falling and colliding move at a few m/s (full size at most 1.9); "
     "an exploding run held in by the safety clamp moves at tens to hundreds (inacio2010 Fig. 7)"),
    ("xu2022_fig2", "xu2022/fig2.csv", "*", "mask_iou", ("in", 0, 1), "IoU lies in [0, 1] by definition"),
    ("xu2022_fig2", "xu2022/fig2.csv", "scene=box&anisotropy=on", "normal_mean_deg", ("lt", "scene=box&anisotropy=off", 0.8),
     "anisotropic sprites are smoother than isotropic ones (xu2022 Fig. 2): on the box, no filter (full size 24.5 "
     "against 46.8 degrees)"),
    ("xu2022_fig2", "xu2022/fig2.csv", "scene=dam&anisotropy=on", "normal_mean_deg", ("lt", "scene=dam&anisotropy=off", 0.8),
     "and on the dam break (full size 25.4 against 44.7 degrees)"),
    ("xu2022_fig8", "xu2022/fig8_highlights.csv", "*", "highlight_pct", ("in", 0, 100),
     "a share of the image's pixels, in percent"),
    ("xu2022_fig8", "xu2022/fig8.csv", "filter=narrow", "interior_normal_mean_deg", ("lt", "filter=gaussian", 1.0),
     "narrow-range smooths the transparent fluid more than the Gaussian (xu2022 Fig. 8; full size 14.3 against "
     "16.6 degrees)"),
    ("xu2022_fig9", "xu2022/fig9.csv", "*", "frame_ms", ("in", 0, math.inf), "a time is not negative"),
    ("xu2022_fig9", "xu2022/timings.csv", "anisotropy=on&stage=anisotropy", "ms_median", ("in", 0.01, math.inf),
     "with anisotropy on every frame runs the anisotropy pass (WPCA of each particle's neighbours, xu2022 section "
     "4.2): a switch that skips it has no such stage"),
    ("xu2022_sigma", "xu2022/sigma_sweep.csv", "*", "interior_deg", ("in", 0, 180),
     "an angle between two unit normals lies in [0, 180] degrees"),
    ("xu2022_sigma", "xu2022/sigma_sweep.csv", "scene=box&filter=gaussian&sigma_r=0.5&anisotropy=off", "interior_deg",
     ("lt", "scene=box&filter=gaussian&sigma_r=1.5&anisotropy=off", 0.9),
     "sigma sets the Gaussian's width: on the box's edges a wider kernel blurs more (full size 7.4 against 12.6 "
     "degrees), so a sigma that is not passed on fails"),
    ("xu2022_doubts", "xu2022/doubts_narrow_bias.csv", "view=oblique", "mask_iou", ("same", 0),
     "the depth filters change depth only, not the splat's coverage"),
    ("xu2022_doubts", "xu2022/doubts_curvature.csv", "size~(128|512)&variant=iterations=320;anisotropy=off",
     "interior_normal_mean_deg", ("differ", "size~(128|512)&variant=iterations=80;anisotropy=off", 1),
     "curvature flow's iteration count changes the surface (van der Laan et al. 2009, as xu2022 uses it): 320 "
     "iterations against 80 at 512^2 (quick: 128^2) differ by degrees (full size 25.4 against 33.4)"),
    ("xu2022_bars", "xu2022/bars.csv", "bar~b_slab_curvature_aniso_.*_coverage_iou", "measured", ("in", 1, 1),
     "curvature flow (van der Laan et al. 2009, as xu2022 uses it) moves depth only: the "
     "coverage against the unfiltered image is identical, IoU 1"),
    ("xu2022_bars", "xu2022/bars.csv", "bar~a_box_.*|b_.*_coverage_iou|b_slab_curvature_aniso_off_interior_deg", "verdict",
     ("as_committed", "bar"),
     "each of these bars' verdicts is the committed one (results/xu2022/bars.csv). Left out: a_slab (its two sides "
     "within 2% of each other at either size) and the anisotropic curvature bar, which changes with the image size "
     "(dt = z / (2 f_px) makes 80 iterations a fixed diffusion per pixel: xu2022/README.md, the doubts)"),
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
    ("iwasaki2006_surfels", "iwasaki2006/dam_break_metrics.csv", "*", "mask_iou", ("in", 0.95, 1),
     "surfels sample the density grid's iso-surface, the reference's (same kernel and iso): the study's bar, IoU "
     ">= 0.95 on the dam break (full size 0.993)"),
    ("iwasaki2006_surfels", "iwasaki2006/dam_break_metrics.csv", "*", "interior_normal_mean_deg", ("in", 0, 10),
     "and their normals are the field's gradient there (full size 2.3 degrees)"),
    ("iwasaki2006_tables", "iwasaki2006/density_grid_table.csv", "*",
     "exact_cpu_ms / slice_splat_ms - exact_over_splat", ("in", -0.006, 0.006),
     "the column is the ratio of the two times (printed to 2 decimals)"),
    ("iwasaki2006_tables", "iwasaki2006/density_grid_table.csv", "*", "rel_l2_vs_exact", ("in", 0, 1e-5),
     "the table carries the slice splat's agreement with the exact grid (iwasaki2006_density_grid's bound)"),
    ("iwasaki2006_caustics", "iwasaki2006/caustics.csv", "bar=flat_slab_no_jitter_median", "ratio", ("in", 0.95, 1.05),
     "light from straight above through a flat surface is neither focused nor spread (flux "
     "ratio 1), so the floor's irradiance is eq. 2's L_i T(0) exp(-c l) at the ideal depth; "
     "5% leaves room for the lattice's iso-surface ripples (period 2r) that the bar's note names"),
    ("iwasaki2006_fig7", "iwasaki2006/fig7_metrics.csv", "*", "n_both - n_interior", ("in", 0, math.inf),
     "the interior mask is a subset of the pixels both images cover"),
    ("iwasaki2006_fig7", "iwasaki2006/fig7_metrics.csv", "*", "mask_iou", ("in", 0.95, 1),
     "from the second viewpoint surfels keep the reference's silhouette (full size 0.993)"),
    ("iwasaki2006_fig9_wavemaker", "iwasaki2006/fig9_wavemaker_metrics.csv", "*", "n_both - n_interior",
     ("in", 0, math.inf), "the interior mask is a subset of the pixels both images cover"),
    ("iwasaki2006_fig9_wavemaker", "iwasaki2006/fig9_wavemaker_frames.csv", "*", "particles", ("same", 0),
     "the shaken tank neither gains nor loses particles between frames"),
    ("iwasaki2006_fig9_wavemaker", "iwasaki2006/fig9_wavemaker_metrics.csv", "*", "mask_iou", ("in", 0.95, 1),
     "surfels follow the waves' surfaces (iwasaki2006 Fig. 9): coverage against `reference` on every frame (full "
     "size at least 0.998)"),
    ("iwasaki2006_fig9_wavemaker", "iwasaki2006/fig9_wavemaker_frames.csv", "*", "v_mean", ("in", 0, 3),
     "the shaken tank's simulation stays bounded: its water moves at about a metre a second (full size at most "
     "1.3 m/s); an exploding run held in by the clamp moves far faster (inacio2010 Fig. 7)"),
    ("iwasaki2006_fig8", "iwasaki2006/fig8.csv", "image=splat&against=exact", "mask_iou", ("in", 0.99, 1),
     "the splatted grid equals the exact one up to float rounding (density_grid.csv): only "
     "a pixel whose ray grazes the iso-surface can change coverage"),
    ("iwasaki2006_fig8", "iwasaki2006/fig8.csv", "image=splat&against=exact", "interior_normal_mean_deg", ("in", 0, 0.1),
     "a field that differs by ~1e-7 relative turns its gradient by ~1e-5 rad, far under 0.1 degree"),
    # --- inacio2010 (volume_raycast, the SPH simulator) ---
    ("inacio2010_tables", "inacio2010/tables.csv", "table=I",
     "simulation_pct + fetch_pct + volume_pct + raycast_pct + rendering_pct", ("in", 99.7, 100.3),
     "total is the sum of the stage medians (tables.sh), so the shares add up to 100 "
     "(five values printed to 0.1: +-0.25)"),
    ("inacio2010_tables", "inacio2010/tables.csv", "*", "steps_per_frame", ("in", 1, 100),
     "the simulation stays bounded: a frame of 1/60 s at the CFL bound takes tens of adaptive steps (full size 27 "
     "to 61); an exploding run (hundreds of m/s, inacio2010 Fig. 7) would need hundreds"),
    ("inacio2010_fig6", "inacio2010/fig6_timestep.csv", "*", "particles", ("same", 0),
     "every cell simulates the same block, and the simulator neither creates nor removes "
     "particles: mass (equal particle masses) is conserved"),
    ("inacio2010_fig6", "inacio2010/fig6_timestep.csv", "steps_x_dt=10x0.001", "clamps", ("in", 0, 0),
     "ten steps of 0.001 s stay in the tank without the safety clamp (a smaller step is more stable, inacio2010 "
     "Fig. 7)"),
    ("inacio2010_fig6", "inacio2010/fig6_timestep.csv", "eos=tait&steps_x_dt=10x0.001&path=cpu", "clamps",
     ("lt", "eos=tait&steps_x_dt=1x0.01&path=cpu", 1),
     "and one step of 0.01 s, far beyond the CFL bound, needs it: the two step sizes differ as the paper says "
     "(full size 0 against 765750 clamps)"),
    ("inacio2010_fig2", "inacio2010/fig2_timings.csv", "*", "ms_median - ms_min", ("in", 0, math.inf),
     "a median is not below the minimum of the same runs"),
    ("inacio2010_fig2", "inacio2010/fig2_metrics.csv", "method=volume_raycast", "mask_iou", ("in", 0.95, 1),
     "the ray-cast volume's surface is the reference's (same kernel and iso; full size 0.998)"),
    ("inacio2010_fig2", "inacio2010/fig2_metrics.csv", "method=volume_raycast", "interior_normal_mean_deg",
     ("lt", "method=spheres", 0.2),
     "the ray-cast surface is continuous where spheres are beads (inacio2010 Fig. 2; full size 0.47 against 47 "
     "degrees)"),
    ("inacio2010_fig9", "inacio2010/fig9.csv", "*", "render_ms", ("in", 0, math.inf), "a time is not negative"),
    ("inacio2010_fig9", "inacio2010/fig9.csv", "*", "steps / t", ("in", 100, 5000),
     "each count's simulation stays bounded: its adaptive steps per simulated second (full size 1198 to 2402) "
     "stay far below what an exploding run at the CFL bound takes"),
    ("inacio2010_fig7", "inacio2010/fig7.csv", "*", "particles", ("same", 0),
     "both step sizes simulate the same block; particles (mass) are conserved"),
    ("inacio2010_fig7", "inacio2010/fig7.csv", "steps_x_dt=10x0.001", "clamps_total + (v_max_peak > 15)", ("in", 0, 0),
     "the small step's collapse stays bounded: no clamp and no speed beyond a dam break's few m/s (full size "
     "7.1 m/s; the large step's explosion: 274 m/s and 68878 clamps)"),
    ("inacio2010_volume_raycast", "inacio2010/volume_raycast_bar.csv", "*", "normal_mean_deg", ("same", 0),
     "inacio2010's surface and translucent transfer functions shade the same G-buffer: the "
     "same normals"),
    ("inacio2010_volume_raycast", "inacio2010/volume_raycast_bar.csv", "*", "mask_iou", ("in", 0.9, 1),
     "the ray-cast volume's coverage against `reference`: the study's bar is 0.95 at 512^2 with grid 256 (full size "
     "0.996); the quick run's coarser grid gives 0.947"),
    ("inacio2010_fig8", "inacio2010/fig8.csv", "row=translucent image against surface image",
     "image_rms_error - image_mean_error", ("in", -1e-6, math.inf),
     "the mean of |e| is at most its root mean square (Cauchy-Schwarz)"),
    ("inacio2010_fig8", "inacio2010/fig8.csv", "row=translucent image against surface image",
     "image_max_error - image_rms_error", ("in", -1e-6, math.inf), "the RMS of |e| is at most its largest value"),
    ("inacio2010_fig8", "inacio2010/fig8.csv", "row=translucent image against surface image", "image_rms_error",
     ("in", 0.01, math.inf),
     "the translucent transfer function shows the floor and inner surfaces through the water (inacio2010 Fig. 8): "
     "its image differs from the opaque one (full size RMS 0.034)"),
    ("inacio2010_sim_bar", "inacio2010/sim_bar_cpu_frames.csv", "*", "particles", ("same", 0),
     "the simulation conserves mass: the same particles in every frame"),
    ("inacio2010_sim_bar", "inacio2010/sim_bar_gpu_frames.csv", "*", "particles", ("same", 0),
     "the simulation conserves mass: the same particles in every frame"),
    ("inacio2010_sim_bar", "inacio2010/sim_bar.csv", "*", "depth / depth_expected - 1 - depth_rel_err", ("in", -1e-4, 1e-4),
     "the column is the relative depth error's definition (printed to 4 decimals)"),
    ("inacio2010_sim_bar", "inacio2010/sim_bar.csv", "*", "clamps + abs(depth_rel_err) * 100", ("in", 0, 3),
     "the simulator's bar: the dam break settles without the safety clamp to within 3% of the depth its mass "
     "fills (full size 0.5%, no clamp)"),
    ("inacio2010_sim_speed", "inacio2010/sim_speed.csv", "*", "abs(1000 / ms_per_step - steps_per_s) - 0.5 / ms_per_step ** 2",
     ("in", -math.inf, 0.05),
     "steps per second is 1000 over the milliseconds per step: they agree to the rounding of "
     "both (steps_per_s to 0.1, ms_per_step to 0.001, which moves 1000 / ms by 0.5 / ms^2)"),
    ("inacio2010_sim_speed", "inacio2010/sim_speed.csv", "particles_requested=1024", "steps", ("same", 0),
     "the CPU and GPU paths simulate the same SPH (README_sim.md) and so take the same adaptive steps (full size "
     "268 both)"),
    # --- benchmarks, baselines, counters, the main job ---
    ("bench_make_splash", "bench/make_splash/dam_break_splash.stats.csv", "*", "particles", ("same", 0),
     "the simulation conserves mass: the same particles in every frame"),
    ("bench_make_splash", "bench/make_splash/dam_break_splash.stats.csv", "*", "clamps + outside", ("in", 0, 0),
     "the splash's simulation stays bounded: no particle needs the safety clamp or leaves the tank"),
    ("bench_foundation", "bench/foundation.csv", "*", "ms_median", ("in", 0, math.inf), "a time is not negative"),
    ("bench_foundation", "bench/foundation.csv", "scene~dam_break_24k_ref[0-9]+&method=reference", "peak_rss_kib", ("same", 0),
     "one process renders every stage of a scene: its one peak RSS stands on each stage's row"),
    ("bench_info", "bench/info.csv", "*", "estimated_r / true_r - ratio", ("in", -1e-3, 1e-3),
     "the ratio column is estimated r over true r (printed to 4 decimals)"),
    ("bench_info", "bench/info.csv", "kind=lattice || kind=developed", "abs(ratio - 1) - target", ("in", -math.inf, 0),
     "info's radius estimate meets its targets: within 10% of the true r on a lattice, 20% on a developed frame "
     "(full size 3% and 2%)"),
    ("study_up_axis", "study/up_axis.csv", "right~[01]", "right", ("in", 1, 1),
     "the up guess (common/scene/up_axis.c) is the known up axis on every frame whose up is known: y on the "
     "SPlisHSPlasH frames, z on the shapes stood on z = 0 and the DualSPHysics frames (full size: all 13)"),
    ("bench_memory", "bench/memory.csv", "*", "peak_rss_kib_median - peak_rss_kib_min", ("in", 0, math.inf),
     "a median is not below the minimum of the same runs"),
    ("bench_memory", "bench/memory.csv", "*", "peak_rss_kib_max - peak_rss_kib_median", ("in", 0, math.inf),
     "a median is not above the maximum of the same runs"),
    ("bench_memory", "bench/memory.csv", "state~(after|current)&input=synthetic&method=raycast_pca&n~(27000|1000000)",
     "peak_rss_kib_median", ("lt", "state~(after|current)&input=synthetic&method=raycast_pca&n~(4096|97336)", 1.5),
     "a particle costs raycast_pca tens of bytes beside the image's fixed buffers (docs/DESIGN.md): ten times the "
     "particles raise the peak by under half (full size 1.09x from 97,336 to 1,000,000)"),
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
    ("baselines", "baselines/quality.csv", "method=mesh", "mask_iou", ("in", 0.95, 1),
     "marching cubes over the scene's field meshes the reference's iso-surface (full size 0.996)"),
    ("baselines", "baselines/quality.csv", "method=levelset", "mask_iou", ("in", 0.6, 1),
     "OpenVDB's level set of the particle spheres covers much of the reference's surface (full size 0.741: its "
     "spheres' union is not the kernel's iso-surface, methods/levelset/README.md)"),
    ("counters", "counters/work.csv", "scene=dam_break&total~[1-9][0-9]*", "total / per_pixel", ("same_rel", 1e-3),
     "per_pixel is the total over the image's pixels (4 significant digits): the same divisor "
     "for every counter of a scene (a counter the method does not count is 0 and left out)"),
    ("counters", "counters/work.csv", "scene=dam_break&total~[1-9][0-9]*", "total / per_particle", ("same_rel", 1e-3),
     "per_particle is the total over the particle count: the same divisor for every counter"),
    ("counters", "counters/work.csv", "scene=dam_break&method=raycast_pca&counter=march_samples", "per_pixel",
     ("lt", "scene=dam_break&method=volume_raycast&counter=march_samples", 0.5),
     "raycast_pca starts each ray at the splatted depth, near the iso-surface (xiao2017 section 3.1), so it samples "
     "far less per pixel than a march through the whole volume (full size 3.9 against 114)"),
    ("counters", "counters/work.csv", "scene=dam_break&method=raycast_pca&counter=march_samples", "per_pixel",
     ("in", 0.5, math.inf), "and it does march: a ray per covered pixel, more than one sample each (full size 3.9)"),
    ("slurm_scaling", "slurm/scaling.csv", "*", "wall_s_median - wall_s_min", ("in", 0, math.inf),
     "a median is not below the minimum of the same runs"),
    ("demo", "demo/metrics.csv", "*", "mask_iou", ("in", 0, 1), "IoU lies in [0, 1] by definition"),
    ("demo", "demo/metrics.csv", "method=raycast_pca || method=surfels || method=volume_raycast || method=mesh&field=isotropic",
     "mask_iou", ("in", 0.95, 1),
     "the methods that find the kernel's iso-surface cover the reference's pixels on the dam break (full size "
     "0.992 to 0.998)"),
    ("demo", "demo/metrics.csv", "method=raycast_pca", "interior_normal_mean_deg", ("in", 0, 12),
     "raycast_pca's PCA-blended, filtered normals stay near the iso-surface's (full size 6.1 degrees)"),
    ("demo", "demo/metrics.csv", "method=spheres || method=aniso_ssf", "mask_iou", ("in", 0.8, 1),
     "the splatted sprites cover the fluid, a radius beyond its silhouette (full size 0.872 and 0.877)"),
    ("readme_pivots", "xiao2017/table1_growth.csv", "series=paper_gtx970&particles=779752", 'c("512")', ("in", 0.9995, 1.0005),
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


def check(results, study, path, rows, expr, bound, why, committed="results"):
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
    if bound[0] == "as_committed":
        return as_committed(where, os.path.join(committed, path), picked, expr, bound[1], why)
    values = []
    for r in picked:
        try:
            values.append((evaluate(expr, r), r))
        except (KeyError, ValueError, ZeroDivisionError, SyntaxError, NameError, TypeError) as e:
            return ["%s: row %s: %s: %s" % (where, describe(r), expr, e)]
    kinds = {"in": in_range, "same": same, "same_rel": same, "lt": versus, "differ": versus}
    if bound[0] not in kinds:
        return ["%s: unknown bound %r" % (where, bound)]
    return kinds[bound[0]](where, table, expr, values, bound, why)


def in_range(where, table, expr, values, bound, why):
    lo, hi = bound[1], bound[2]
    return ["%s: row %s: %s = %.6g, want in [%g, %g]: %s" % (where, describe(r), expr, v, lo, hi, why)
            for v, r in values if not (lo <= v <= hi)]


def same(where, table, expr, values, bound, why):
    vs = [v for v, _ in values]
    spread = max(vs) - min(vs)
    if bound[0] == "same_rel":
        scale = max(abs(v) for v in vs)
        spread = spread / scale if scale > 0 else 0
    if spread <= bound[1]:
        return []
    lo_v, lo_r = min(values, key=lambda x: x[0])
    hi_v, hi_r = max(values, key=lambda x: x[0])
    return ["%s: %s differs over %d rows%s: %.6g (row %s) .. %.6g (row %s), want a spread <= %g: %s"
            % (where, expr, len(values), " (relative)" if bound[0] == "same_rel" else "", lo_v, describe(lo_r), hi_v,
               describe(hi_r), bound[1], why)]


def versus(where, table, expr, values, bound, why):
    """("lt", OTHER, F): each value below F times the value of the one row OTHER matches;
    ("differ", OTHER, TOL): each value at least TOL away from it."""
    other = [r for r in table if matcher(bound[1])(r)]
    if len(other) != 1:
        return ["%s: %r matches %d rows, want one (the row to compare with: %s)" % (where, bound[1], len(other), why)]
    try:
        ov = evaluate(expr, other[0])
    except (KeyError, ValueError, ZeroDivisionError, SyntaxError, NameError, TypeError) as e:
        return ["%s: row %s: %s: %s" % (where, describe(other[0]), expr, e)]
    if bound[0] == "lt":
        return ["%s: row %s: %s = %.6g, want below %g x %.6g (row %s): %s" % (
            where, describe(r), expr, v, bound[2], ov, describe(other[0]), why) for v, r in values if not v < bound[2] * ov]
    return ["%s: row %s: %s = %.6g, want at least %g away from %.6g (row %s): %s" % (
        where, describe(r), expr, v, bound[2], ov, describe(other[0]), why) for v, r in values if abs(v - ov) < bound[2]]


def as_committed(where, path, picked, col, key, why):
    """Each picked row's text in col equals the committed CSV's row with the same key."""
    try:
        committed = {r.get(key): r.get(col) for r in read_csv(path)}
    except OSError as e:
        return ["%s: cannot read the committed %s: %s" % (where, path, e)]
    out = []
    for r in picked:
        if r.get(col) is None:
            return ["%s: no column %s" % (where, col)]
        if committed.get(r.get(key)) != r[col]:
            out.append("%s: row %s: %s is %r, the committed %s says %r: %s" % (
                where, describe(r), col, r[col], path, committed.get(r.get(key)), why))
    return out


USAGE = ("usage: check_quick.py [RESULTS] [--table-only] [--run-all FILE] [--only STUDY,...] [--skip STUDY,...] "
         "[--committed DIR]")


def parse(argv):
    """The options as a dict, or an exit status (0 for --help, 2 for bad usage)."""
    o = {"results": None, "run_all": "experiments/run_all.sh", "only": None, "skip": set(), "table_only": False,
         "committed": "results"}
    args = list(argv)
    while args:
        a = args.pop(0)
        if a == "--table-only":
            o["table_only"] = True
        elif a in ("--run-all", "--committed") and args:
            o[a[2:].replace("-", "_")] = args.pop(0)
        elif a in ("--only", "--skip") and args:
            o[a[2:]] = set(args.pop(0).split(","))
        elif a in ("-h", "--help"):
            print(__doc__)
            return 0
        elif not a.startswith("-") and o["results"] is None:
            o["results"] = a
        else:
            print(USAGE, file=sys.stderr)
            return 2
    o["results"] = o["results"] or os.environ.get("FS_RESULTS") or "out/quick/results"
    return o


def table_errors(run_all, skip):
    """The table against run_all.sh's studies, and each row's syntax."""
    fails = []
    studies = studies_of(run_all)
    listed = {c[0] for c in CHECKS}
    for s in sorted(skip - listed):
        fails.append("%s: --skip names a study without a row in the table" % s)
    for s in studies:
        if s not in listed and s not in NOT_STUDIES:
            fails.append("%s: a study of %s without a row in check_quick.py's table: add a bound it must "
                         "meet by definition" % (s, run_all))
    for s in sorted(listed - set(studies)):
        fails.append("%s: a row in check_quick.py's table for a study %s does not run" % (s, run_all))
    return fails


def main(argv):
    o = parse(argv)
    if not isinstance(o, dict):
        return o
    fails = []
    if o["only"] is None:
        try:
            fails += table_errors(o["run_all"], o["skip"])
        except OSError as e:
            print("check_quick: %s: %s" % (o["run_all"], e), file=sys.stderr)
            return 2
    for c in CHECKS:
        try:
            matcher(c[2])
            compile(c[3], "<value>", "eval")
        except (ValueError, SyntaxError) as e:
            fails.append("%s: %s: bad table row: %s" % (c[0], c[1], e))
    if not o["table_only"]:
        if not os.path.isdir(o["results"]):
            print("check_quick: %s: no such folder (run experiments/run_all.sh --quick)" % o["results"], file=sys.stderr)
            return 2
        rows = [c for c in CHECKS if (o["only"] is None or c[0] in o["only"]) and c[0] not in o["skip"]]
        if o["only"] is not None and not rows:
            print("check_quick: --only %s: no such study in the table" % ",".join(sorted(o["only"])), file=sys.stderr)
            return 2
        for study, path, spec, expr, bound, why in rows:
            fails += check(o["results"], study, path, spec, expr, bound, why, o["committed"])
    for line in fails:
        print("check_quick: FAIL %s" % line)
    checked = "the table" if o["table_only"] else o["results"]
    if fails:
        print("check_quick: %d failure(s) in %s" % (len(fails), checked))
        return 1
    print("check_quick: %s: every bound holds (%d rows)" % (checked, len(CHECKS)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
