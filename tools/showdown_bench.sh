#!/usr/bin/env bash
# Lesson 10's benchmark (issue 15): every hard-shadow technique at EQUAL TOTAL TEXELS per light
# (uniform, PSM with the fixes, LiSPSM, cascades, sample-distribution cascades; the hybrid maps
# render the same full map before merging; the stencil volumes have no texels), through lesson
# 10's parameters, over the committed camera paths (bench/paths: the city and terrain orbits put
# the light behind, along, beside and facing the view; the forest walk) and a sweep of sun
# directions over the sphere
# (psm_light_sweep). Each run is measured against Embree's ground truth (misclassified %: leaks and
# false shadows; aliasing m: mean, p95, max) and timed (shadow-pass and frame GPU ms, on a software
# renderer the synchronous timers' wall time). shadowlab_bench writes per path a report
# (report.{csv,json,html}: the time-against-error scatter with its Pareto front, tables,
# thumbnails); then OUT_DIR/summary.md and OUT_DIR/index.html: per scene and budget the Pareto front
# and the "which technique when" lines, generated from the figures, and the error against the light
# direction per technique. Usage:
#   tools/showdown_bench.sh [--quick] [BUILD_DIR (build/default)] [OUT_DIR (out/bench/showdown)]
# --quick (CI's smoke test, a few minutes): 2048^2 only, 2 samples per orbit, 6 sweep directions,
# 240x135. The full run: 1024^2, 2048^2 and 4096^2, 8 samples per orbit, the forest, a
# 1M-triangle city, all 26 sweep directions, 320x180. Environment: SIZE, SAMPLES, SWEEP, REPEATS,
# RUNS (a subset of "city terrain sweep forest city_1m soft"; the summary reads every run's folder).
# Figures from a software renderer (llvmpipe) on a shared machine rank techniques; they do not
# predict a GPU's milliseconds. The error figures are deterministic; the timings are noisy.
set -euo pipefail
source "$(dirname "$0")/script_args.sh"
check_script_args --quick -- "$@"
quick=0
if [[ ${1:-} == --quick ]]; then
  quick=1
  shift
fi
build=${1:-build/default}
out=${2:-out/bench/showdown}
root=$(cd "$(dirname "$0")/.." && pwd)
lesson=$build/bin/lesson_10_showdown
bench=$build/bin/shadowlab_bench
for b in "$lesson" "$bench"; do
  [[ -x $b ]] || { echo "showdown_bench: $b not built (cmake --build $build)" >&2; exit 2; }
done
command -v python3 >/dev/null || { echo "showdown_bench: needs python3" >&2; exit 2; }
if ((quick)); then
  budgets=${BUDGETS:-2048}
  size=${SIZE:-240x135}
  samples=${SAMPLES:-2}
  sweep=${SWEEP:-6}
  triangles=${TRIANGLES:-30000}
else
  budgets=${BUDGETS:-1024 2048 4096}
  size=${SIZE:-320x180}
  samples=${SAMPLES:-8}
  sweep=${SWEEP:-26}
  triangles=${TRIANGLES:-60000}
fi
repeats=${REPEATS:-1}
# Which runs (RUNS, e.g. "forest city_1m" to add them to an earlier run's folder): all by default.
runs=${RUNS:-city terrain sweep forest city_1m soft}
for r in $runs; do
  case $r in city | terrain | sweep | forest | city_1m | soft) ;;
    *) echo "showdown_bench: RUNS: '$r' is not one of city terrain sweep forest city_1m soft" >&2; exit 2 ;;
  esac
done
[[ $size =~ ^[0-9]+x[0-9]+$ ]] || { echo "showdown_bench: SIZE '$size' is not WxH" >&2; exit 2; }
mkdir -p "$out"

# The configurations: each map technique at each budget (texels: the side of a light's total),
# the volumes once. (tests/gpu/registry_test.cpp: every technique of the showdown's registry has a
# configuration here, in this list or as technique=NAME.)
map_techniques="uniform psm lispsm csm sdsm hybrid"
configs=()
for b in $budgets; do
  for t in $map_techniques; do
    # (every map redrawn every frame, as on a moving path: a held pose's reuse would time nothing)
    extra=" $t.reuse_maps=false"
    configs+=(--config "$t $b: technique=$t texels=$b triangles=$triangles$extra")
  done
done
configs+=(--config "volumes -: technique=volumes triangles=$triangles")
# No shadows at all: the floor every row's error is read against (the summary never ranks it).
configs+=(--config "none -: technique=none triangles=$triangles")
# The comparison of Lloyd et al. 2006: the cascades with a LiSPSM warp inside each (csm.warp) at
# 2048^2 total against one LiSPSM map at 4096^2 (with --quick 4096^2 is not among the budgets).
configs+=(--config "csm+warp 2048: technique=csm csm.warp=true texels=2048 triangles=$triangles csm.reuse_maps=false")
# Sample distribution shadow maps with the same warp inside each cascade (sdsm 2048 is among the
# map techniques above): the summary's SDSM table sets them against the practical cascades.
configs+=(--config "sdsm+warp 2048: technique=sdsm sdsm.warp=true texels=2048 triangles=$triangles sdsm.reuse_maps=false")
# Texel snapping off (the fitted frusta follow the camera by fractions of a texel): the stability
# table sets each against its snapped self.
for t in uniform csm sdsm; do
  configs+=(--config "$t/nosnap 2048: technique=$t texels=2048 triangles=$triangles $t.reuse_maps=false $t.snap=false")
done
if ((quick)); then configs+=(--config "lispsm 4096: technique=lispsm texels=4096 triangles=$triangles lispsm.reuse_maps=false"); fi

# Shimmer (every configuration of the city, terrain and forest runs): 8 consecutive frame pairs of
# lesson 09's view of the city with the camera sliding 3 cm a frame, and with the sun turning 0.1
# degree a frame (bench/paths/city_drift.path, sun_turn.path: 1/60 s a frame), each frame measured
# against the one before; the soft run drifts along its own path (about 1.2 cm a frame).
shimmer=(--shimmer "camera=$root/bench/paths/city_drift.path@0..0.1333"
  --shimmer "sun=$root/bench/paths/sun_turn.path@0..0.1333" --shimmer-frames 9)

run() {  # run NAME SCENE PATH SAMPLES [EXTRA CONFIG ARGS...]
  local name=$1 scene=$2 path=$3 n=$4
  shift 4
  [[ " $runs " == *" $name "* ]] || return 0
  echo "showdown_bench: $name ($scene, $path, $n samples)" >&2
  "$bench" "$lesson" --out "$out/$name" --scenes "$scene" --path "$root/bench/paths/$path" --path-samples "$n" \
    --repeat "$repeats" --frames 2 --size "$size" --title "Lesson 10: $name, equal texels" "$@"
}
run city city psm_city_orbit.path "$samples" "${configs[@]}" "${shimmer[@]}"
run terrain terrain psm_terrain_orbit.path "$samples" "${configs[@]}" "${shimmer[@]}"
run sweep city psm_light_sweep.path "$sweep" "${configs[@]}"
if ((!quick)); then
  run forest forest soft_forest.path "$samples" "${configs[@]}" "${shimmer[@]}"
  big=()
  for c in "${configs[@]}"; do big+=("${c/triangles=$triangles/triangles=1000000}"); done
  run city_1m city psm_city_orbit.path 2 "${big[@]}"
fi
# The soft methods against the sphere-light reference (soft RMSE of visibility; the Embree reference
# traces measure.samples rays a pixel toward the sphere, and "many 16" also traces a second reference
# with another seed: their RMSE is the noise floor the others are read against). Lesson 05's
# spherical spot (light1, radius 0.5 m) over the showcase, the sun off, along lesson 05's committed
# path (the camera moves; light1 stays), each method at its own settings (the soft maps are 1024^2
# a sample; "uniform" is the hard map the soft methods replace).
soft_sets="scene=showcase triangles=$triangles light0.enabled=false light1.enabled=true measure.light=1"
soft_sets+=" measure.samples=${SOFT_RAYS:-64}"
soft=(--config "many 16: technique=many many.samples=16 measure.noise_floor=true $soft_sets"
  --config "pcf 16: technique=pcf pcf.filter_taps=16 $soft_sets"
  --config "pcss 16+16: technique=pcss pcss.search_taps=16 pcss.filter_taps=16 $soft_sets")
if ((!quick)); then
  soft+=(--config "uniform hard: technique=uniform texels=1024 uniform.reuse_maps=false $soft_sets"
    --config "many 4: technique=many many.samples=4 $soft_sets"
    --config "many 64: technique=many many.samples=64 $soft_sets"
    --config "pcss 32+32: technique=pcss pcss.search_taps=32 pcss.filter_taps=32 $soft_sets"
    --config "parker 32: technique=parker $soft_sets" --config "haines 32: technique=haines $soft_sets"
    --config "mesh 48: technique=mesh mesh.nodes=48 $soft_sets"
    --config "vsm blur 2: technique=vsm $soft_sets" --config "esm blur 2: technique=esm $soft_sets"
    --config "evsm2 blur 2: technique=evsm2 $soft_sets" --config "evsm4 blur 2: technique=evsm4 $soft_sets"
    --config "msm 16 blur 2: technique=msm $soft_sets")
fi
run soft showcase soft_showcase.path "$((quick ? 2 : 3))" "${soft[@]}" \
  --shimmer "camera=$root/bench/paths/soft_showcase.path@0.25..0.26" --shimmer-frames 9
python3 "$root/tools/showdown_summary.py" "$out" "$size" "$repeats"
echo "showdown_bench: $out/index.html, $out/summary.md" >&2
