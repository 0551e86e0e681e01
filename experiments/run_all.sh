#!/usr/bin/env bash
# Regenerates every committed result of every study from a clean build: the four
# papers, the benchmarks, the baselines, the work counters and the main job's summary
# (results/demo/, experiments/demo/run.sh; scripts/demo.sh itself writes only out/demo/).
#
#   experiments/run_all.sh            full runs, into results/ (hours on 2 cores; commit first,
#                                     so every CSV names a clean commit)
#   experiments/run_all.sh --quick    every script at small sizes into out/quick/results/ (a few
#                                     minutes; CI runs it so that no study script can rot), then
#                                     each study's numbers against bounds (by definition, and ones a broken
#                                     method fails: scripts/check_quick.py) and the checks below; it also runs
#                                     scripts/demo.sh and fails if that changes `git status`
#   experiments/run_all.sh --check    the checks of the committed results: every generated README
#                                     table is its CSV's, and every committed CSV under results/
#                                     names a clean commit (scripts/check_results.sh)
#
# Studies run in the order below; one that fails stops the run with its name.
set -euo pipefail
cd "$(dirname "$0")/.."
mode=full
case "${1:-}" in
  --quick) mode=quick ;;
  --check) mode=check ;;
  "") ;;
  *) echo "usage: $0 [--quick|--check]" >&2; exit 2 ;;
esac

# the user + system ticks of this shell and of every child it has waited for
cpu_ticks() { awk '{ print $14 + $15 + $16 + $17 }' "/proc/$$/stat"; }
mkdir -p out/run_all
echo "study,wall_s,cpu_s" > out/run_all/times.csv
# study NAME COMMAND...: runs one study, timed (wall and CPU seconds also in
# out/run_all/times.csv), with its log in out/run_all/NAME.log
study() {
  local name=$1 t0=$SECONDS c0 cpu; shift
  c0=$(cpu_ticks)
  if "$@" > "out/run_all/$name.log" 2>&1; then
    cpu=$((($(cpu_ticks) - c0) / $(getconf CLK_TCK)))
    echo "$name,$((SECONDS - t0)),$cpu" >> out/run_all/times.csv
    echo "run_all: $name: ok ($((SECONDS - t0)) s, CPU $cpu s)"
  else
    echo "run_all: $name FAILED ($((SECONDS - t0)) s); last lines of out/run_all/$name.log:" >&2
    tail -15 "out/run_all/$name.log" >&2
    exit 1
  fi
}

readme_check() { study readme_tables bash tests/readme_tables.sh "$PWD"; }
# the prose numbers (<!--n--> notes) and the index's commit column against the committed CSVs
numbers_check() {
  study results_numbers python3 scripts/check_numbers.py
  study results_index python3 scripts/check_index.py results/README.md
}

if [ $mode = check ]; then
  readme_check
  numbers_check
  study results_clean bash scripts/check_results.sh
  study results_bounds python3 scripts/check_quick.py results --skip bench_make_splash
  exit 0
fi
if [ $mode = quick ]; then
  export FS_QUICK=1 FS_RESULTS=${FS_RESULTS:-out/quick/results}
  rm -rf "$FS_RESULTS"
fi
# every target, the experiments' tools too (scripts/demo.sh builds only fluidsurf); incremental
bash scripts/build.sh build
export BIN=${BIN:-$PWD/build/fluidsurf}

# the papers
study xiao2017_fig3 bash experiments/xiao2017/fig3.sh
study xiao2017_fig4 bash experiments/xiao2017/fig4.sh
study xiao2017_fig5 bash experiments/xiao2017/fig5.sh
study xiao2017_fig6 bash experiments/xiao2017/fig6.sh
study xiao2017_fig7 bash experiments/xiao2017/fig7.sh
study xiao2017_fig10 bash experiments/xiao2017/fig10.sh
study xiao2017_radius bash experiments/xiao2017/radius.sh
study xiao2017_joint bash experiments/xiao2017/joint_sweep.sh
study xiao2017_thickness bash experiments/xiao2017/thickness.sh
study xiao2017_table1 bash experiments/xiao2017/table1.sh
study xiao2017_bars bash experiments/xiao2017/bars.sh
study xu2022_fig5 bash experiments/xu2022/fig5.sh
study xu2022_fig6 bash experiments/xu2022/fig6.sh
study xu2022_fig4_collision bash experiments/xu2022/fig4_collision.sh
study xu2022_fig2 bash experiments/xu2022/fig2.sh # after fig6.sh: its images
study xu2022_fig8 bash experiments/xu2022/fig8.sh
study xu2022_fig9 bash experiments/xu2022/fig9.sh
study xu2022_sigma bash experiments/xu2022/sigma.sh
study xu2022_doubts bash experiments/xu2022/doubts.sh
study xu2022_bars bash experiments/xu2022/bars.sh
study iwasaki2006_density_grid bash experiments/iwasaki2006/density_grid.sh
study iwasaki2006_surfels bash experiments/iwasaki2006/surfels.sh
study iwasaki2006_tables bash experiments/iwasaki2006/tables.sh # after density_grid.sh and surfels.sh
study iwasaki2006_caustics bash experiments/iwasaki2006/caustics.sh
study iwasaki2006_fig7 bash experiments/iwasaki2006/fig7.sh
study iwasaki2006_fig8 bash experiments/iwasaki2006/fig8.sh
study iwasaki2006_fig9_wavemaker bash experiments/iwasaki2006/fig9_wavemaker.sh
study inacio2010_tables bash experiments/inacio2010/tables.sh
study inacio2010_fig6 bash experiments/inacio2010/fig6_timestep.sh
study inacio2010_fig2 bash experiments/inacio2010/fig2.sh
study inacio2010_fig9 bash experiments/inacio2010/fig9.sh
study inacio2010_fig7 bash experiments/inacio2010/fig7.sh
study inacio2010_volume_raycast bash experiments/inacio2010/volume_raycast.sh
study inacio2010_fig8 bash experiments/inacio2010/fig8.sh # after volume_raycast.sh: its images
study inacio2010_sim_bar bash experiments/inacio2010/sim_bar.sh
study inacio2010_sim_speed bash experiments/inacio2010/sim_speed.sh
# benchmarks, baselines, counters, the main job. The splash frame the speed study reads is
# bundled data (experiments/data/splash/): make_splash.sh remakes it (15-30 min), so a full
# run leaves it alone and a quick run only checks that the script works.
[ $mode = quick ] && study bench_make_splash bash experiments/bench/make_splash.sh
study bench_foundation bash experiments/bench/foundation.sh
study bench_info bash experiments/bench/info.sh
study study_up_axis bash experiments/study/up_axis.sh # the up guess on every third-party frame: README's table
study bench_memory bash experiments/bench/memory.sh
study bench_speed bash experiments/bench/speed.sh $([ $mode = quick ] && echo --quick)
study bench_thickness_counts bash experiments/bench/thickness_counts.sh
study bench_interior_auto bash experiments/bench/interior_auto.sh
study baselines bash experiments/baselines/run.sh
study counters bash experiments/counters/work.sh
study slurm_scaling bash experiments/slurm/scaling.sh
if [ $mode = quick ]; then
  # the main job as a user runs it (setup, build, compare): its outputs go to out/, which git
  # ignores, so it must leave `git status` as it found it (docs/DESIGN.md, "Output folders")
  clean_before=$(git status --porcelain)
  study main_job bash scripts/demo.sh
  if [ "$(git status --porcelain)" != "$clean_before" ]; then
    echo "run_all: main_job: scripts/demo.sh changed git status:" >&2
    diff <(echo "$clean_before") <(git status --porcelain) >&2 || true
    exit 1
  fi
fi
study demo bash experiments/demo/run.sh # the main job's committed summary, results/demo/
study readme_pivots bash experiments/readme_pivots.sh # after every study: pivots of their CSVs for the READMEs
study plots bash experiments/plots.sh # last: draws from every study's CSVs

if [ $mode = quick ]; then
  # a study that ran to the end can still measure nonsense, or a method be broken: its numbers
  # against bounds that hold by definition and ones with teeth (quality against the reference,
  # a switch that changes what its paper says, a bar's committed verdict, a bounded simulation;
  # scripts/check_quick.py)
  study quick_bounds python3 scripts/check_quick.py "$FS_RESULTS"
  readme_check
  numbers_check
  study results_clean bash scripts/check_results.sh
fi
echo "run_all: every study ran ($mode)"
