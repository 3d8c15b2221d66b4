#!/usr/bin/env bash
# Lessons 08 and 09 measured (issue 12's goals): the uniform fitted map, the original PSM, PSM with
# every fix and LiSPSM at EQUAL total texels (a face set counts all its faces), through lesson 09's
# parameters, over the committed camera paths (bench/paths/psm_city_orbit, psm_terrain_orbit:
# the light behind, along, beside and facing the view; psm_caster_leaves: the original's slide
# changing) and a sweep of 26 light directions over the whole sphere (psm_light_sweep; again at
# street level and from high above: psm_light_sweep_street, psm_light_sweep_high). Each run is
# measured against ground truth (misclassified %, leaks and false shadows apart, aliasing m), and
# its shadow-pass GPU ms timed; repeats go round-robin over the configurations so their timings
# share the machine's load. Then the goals, met or not, with their figures. Usage:
#   tools/psm_bench.sh [BUILD_DIR (build/default)] [OUT_DIR (out/psm_bench)] [SIZE (320x180)]
# Environment: SAMPLES (samples of the orbit paths, 8), TRIANGLES (30000), FRAMES (per run, 2),
# REPEATS (of the timing runs, 3: four sweep directions per technique, round-robin).
# Writes OUT_DIR/{city,terrain,caster_leaves,sweep,sweep_street,sweep_high}/report.{csv,json,html} (tables and plots along
# the frames) and OUT_DIR/goals.md. Figures from a software renderer (llvmpipe) rank techniques;
# they do not predict a GPU's milliseconds. The error figures are deterministic.
set -euo pipefail
source "$(dirname "$0")/script_args.sh"
check_script_args -- "$@"
build=${1:-build/default}
out=${2:-out/psm_bench}
size=${3:-320x180}
repeats=${REPEATS:-3}
samples=${SAMPLES:-8}
triangles=${TRIANGLES:-30000}
frames=${FRAMES:-2}
lesson=$build/bin/lesson_09_psm_fixes
bench=$build/bin/shadowlab_bench
root=$(cd "$(dirname "$0")/.." && pwd)
for b in "$lesson" "$bench"; do
  [[ -x $b ]] || { echo "psm_bench: $b not built (cmake --build $build)" >&2; exit 2; }
done
[[ $size =~ ^[0-9]+x[0-9]+$ ]] || { echo "psm_bench: size '$size' is not WxH" >&2; exit 2; }
command -v python3 >/dev/null || { echo "psm_bench: needs python3" >&2; exit 2; }
mkdir -p "$out"

# The four techniques at 2048^2 texels per light (equal_texels gives LiSPSM and the uniform map
# the PSM's map_size); the original is lesson 08's parameters in lesson 09. Every map is redrawn
# every frame (reuse_maps=false): a sample's held pose would otherwise keep its maps and time none.
redraw="reuse_maps=false lispsm.reuse_maps=false uniform.reuse_maps=false"
common="triangles=$triangles map_size=2048 $redraw"
uniform="uniform 2048: technique=uniform $common"
original="original PSM 2048: technique=psm fix.inverse=false fix.clip=false fix.faces=never fix.fallback=false bias=constant bias.normal_offset=0 $common"
fixed="PSM all fixes 2048: technique=psm $common"
lispsm="LiSPSM 2048: technique=lispsm $common"
# The second goal: PSM with the fixes at 1024^2 against the uniform map at 4096^2.
fixed1k="PSM all fixes 1024: technique=psm triangles=$triangles map_size=1024 $redraw"
uniform4k="uniform 4096: technique=uniform triangles=$triangles map_size=4096 $redraw"

run() {  # run NAME SCENE PATH SAMPLES REPEATS CONFIG...
  local name=$1 scene=$2 path=$3 n=$4 r=$5
  shift 5
  local args=()
  for c in "$@"; do args+=(--config "$c"); done
  "$bench" "$lesson" --out "$out/$name" --scenes "$scene" --path "$root/bench/paths/$path" --path-samples "$n" \
    --repeat "$r" --frames "$frames" --size "$size" --title "Lesson 09: $name, equal texels" "${args[@]}"
}
# The error figures are deterministic: one run each. The timings come from their own runs.
run city city psm_city_orbit.path "$samples" 1 "$uniform" "$original" "$fixed" "$lispsm" "$fixed1k" "$uniform4k"
run terrain terrain psm_terrain_orbit.path "$samples" 1 "$uniform" "$original" "$fixed" "$lispsm" "$fixed1k" "$uniform4k"
run caster_leaves city psm_caster_leaves.path 21 1 "$original" "$fixed"
run sweep city psm_light_sweep.path 26 1 "$uniform" "$original" "$fixed" "$lispsm"
# Issue 39's sweeps of the camera too: the same 26 directions at street level (a 30-degree lens
# among the blocks) and from high above; the fall-back must keep PSM from losing to the uniform map.
street="camera.fov=0.5235988 camera.near=1 camera.far=1000"
run sweep_street city psm_light_sweep_street.path 26 1 "$uniform $street" "$fixed $street" "$lispsm $street"
run sweep_high city psm_light_sweep_high.path 26 1 "$uniform" "$fixed" "$lispsm"
run timing city psm_light_sweep.path 4 "$repeats" "$uniform" "$original" "$fixed" "$lispsm"
"$build/bin/bench_psm_setup" "$out/psm_setup.csv" > "$out/psm_setup.txt"

python3 - "$out" "$size" "$repeats" "$triangles" <<'PY' | tee "$out/goals.md"
import json, sys, statistics as st
out, size, repeats, triangles = sys.argv[1:5]
def load(name):
    rows = json.load(open(f"{out}/{name}/report.json"))["rows"]
    by = {}
    for r in rows:
        by.setdefault(r["technique"].split(":")[0], []).append(r)
    for v in by.values(): v.sort(key=lambda r: r["frame"])
    return by
def m(r): return r["aliasing"]["mean"] if r.get("aliasing") else float("nan")
def mis(r): return r["hard"]["misclassifiedPct"]
def shadow_ms(r): return sum(v for k, v in r["gpuMs"].items() if k.startswith("shadow") and v is not None)
def mean(xs): return sum(xs) / len(xs)
def met(ok): return "**met**" if ok else "**not met**"
print(f"# PSM goals, measured ({size}, {triangles} triangles; llvmpipe on a 2-core machine shared with other "
      f"engineers' builds, load 10-14: the error figures are exact, the milliseconds are the median of {repeats} "
      "round-robin repeats over four sweep directions, for ratios only)\n")
print("Per path: mean over its samples. m: aliasing factor (screen pixels per texel, lower is better); "
      "misclassified % of the pixels facing the light (leaks, false shadows).\n")
print("| path | technique | texels | m mean | m p95 | m > 1 | misclassified % | leaks % | false % | shadow ms |")
# (shadow ms of the "timing" rows: the median over their repeats and directions; elsewhere one run)
print("|---|---|---|---|---|---|---|---|---|---|")
paths = {n: load(n) for n in ("city", "terrain", "caster_leaves", "sweep", "sweep_street", "sweep_high", "timing")}
for name, by in paths.items():
    for t, rs in by.items():
        print(f"| {name} | {t} | {rs[0]['shadowTexels']} | {mean([m(r) for r in rs]):.3g} | "
              f"{mean([r['aliasing']['p95'] for r in rs]):.3g} | {mean([r['aliasing']['shareAbove1'] for r in rs]):.2f} | "
              f"{mean([mis(r) for r in rs]):.3f} | {mean([r['hard']['leakPct'] for r in rs]):.3f} | "
              f"{mean([r['hard']['falseShadowPct'] for r in rs]):.3f} | {st.median([shadow_ms(r) for r in rs]):.1f} |")
print("\n## The goals\n")
# 1a: mean m at least 2x lower than uniform over the paths (equal texels).
for name in ("city", "terrain"):
    by = paths[name]
    u, f = mean([m(r) for r in by["uniform 2048"]]), mean([m(r) for r in by["PSM all fixes 2048"]])
    print(f"- PSM with the fixes, mean m over the {name} path at 2048^2: {f:.3g} against uniform {u:.3g} "
          f"(ratio {u / f:.2f}; goal >= 2): {met(u / f >= 2)}")
# 1b: at no sweep direction worse than uniform by more than 10 %.
sw = paths["sweep"]
worst = max(((m(f) / m(u)), f["frame"]) for u, f in zip(sw["uniform 2048"], sw["PSM all fixes 2048"]))
print(f"- PSM with the fixes over the 26 sweep directions: worst m ratio to uniform {worst[0]:.2f} at direction "
      f"{worst[1]} (goal <= 1.10): {met(worst[0] <= 1.10)}")
# Issue 39: over the sweeps at street level and from high above too, never worse than uniform by more
# than 10 % in mean m, nor by more than 0.2 percentage points misclassified (the fall-back included).
for name in ("sweep", "sweep_street", "sweep_high"):
    by = paths[name]
    pairs = list(zip(by["uniform 2048"], by["PSM all fixes 2048"]))
    wm = max((m(f) / m(u), f["frame"]) for u, f in pairs if m(u) > 0)
    wd = max((mis(f) - mis(u), f["frame"]) for u, f in pairs)
    print(f"- {name}: PSM with the fixes against uniform, worst m ratio {wm[0]:.2f} (direction {wm[1]}), worst "
          f"misclassified difference {wd[0]:+.2f} points (direction {wd[1]}) (goals <= 1.10 and <= +0.20): "
          f"{met(wm[0] <= 1.10 and wd[0] <= 0.20)}")
# 2: PSM fixes at 1024^2 misclassified on the path no worse than uniform at 4096^2.
for name in ("city", "terrain"):
    by = paths[name]
    a, b = mean([mis(r) for r in by["PSM all fixes 1024"]]), mean([mis(r) for r in by["uniform 4096"]])
    print(f"- {name} path: PSM with the fixes at 1024^2 misclassifies {a:.3f} % against uniform at 4096^2 {b:.3f} % "
          f"(goal: no worse): {met(a <= b)}")
# 3: the original's quality jump at least 3x smaller with fix 2 (here: every fix, since fix 2 without
#    fix 1 keeps the slide that jumps).
cl = paths["caster_leaves"]
def jump(rs): return max(abs(m(b) - m(a)) for a, b in zip(rs, rs[1:]))
jo, jf = jump(cl["original PSM 2048"]), jump(cl["PSM all fixes 2048"])
print(f"- The caster-leaves path: largest frame-to-frame change of mean m, original {jo:.3g}, with the fixes "
      f"{jf:.3g} (ratio {jo / jf:.2f}; goal >= 3): {met(jo / jf >= 3)}")
# 4: no frame where a shadow vanishes (leaks above 5 % of the truly shadowed pixels).
bad = []
for name, by in paths.items():
    for t, rs in by.items():
        for r in rs:
            h = r["hard"]
            if h.get("referenceShadowed", 0) > 1000 and h["leaks"] > 0.05 * h["referenceShadowed"]:
                bad.append(f"{name}/{t}/frame {r['frame']} ({100 * h['leaks'] / h['referenceShadowed']:.1f} %)")
fixed_bad = [b for b in bad if "PSM all fixes" in b]
print(f"- Frames where a shadow vanishes (leaks > 5 % of the truly shadowed pixels, over 1,000 of them): "
      f"PSM with the fixes {len(fixed_bad)}, all techniques {len(bad)}: {met(not fixed_bad)}"
      + ("" if not bad else "; " + ", ".join(bad[:12]) + (" ..." if len(bad) > 12 else "")))
# 5: the light-camera set-up for 1,000 receiver boxes.
for line in open(f"{out}/psm_setup.csv"):
    if line.startswith("1000,"):
        f = line.split(",")
        print(f"- Light-camera set-up, 1,000 receiver boxes (bench_psm_setup): median {float(f[1]):.0f} us, least "
              f"{float(f[2]):.0f} us of thread CPU time (goal < 100 us): {met(float(f[2]) < 100)}")
PY
