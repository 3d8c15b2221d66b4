#!/usr/bin/env bash
# Lesson 04's closing note, measured: stencil shadow volumes against lesson 03's shadow map on the
# city scene, in one run on one machine: fill (samples passed), GPU ms per pass, frame time and the
# misclassified share against ground truth. Usage:
#   tools/volume_bench.sh [BUILD_DIR (build/default)] [OUT_DIR (out/volume_bench)] [SIZE (1280x720)]
# Lesson 03 is compared only when its binary exists; otherwise lesson 04's figures alone are printed
# and the script says so. Figures from a software renderer (llvmpipe) rank techniques, they do not
# predict a GPU's milliseconds.
set -euo pipefail
source "$(dirname "$0")/script_args.sh"
check_script_args -- "$@"
build=${1:-build/default}
out=${2:-out/volume_bench}
size=${3:-1280x720}
bin=$build/bin
l04=$bin/lesson_04_shadow_volumes
l03=$bin/lesson_03_shadow_quality
[[ -x $l04 ]] || { echo "volume_bench: $l04 not built (cmake --build $build --target lesson_04_shadow_volumes)" >&2; exit 2; }
mkdir -p "$out"

summary() {  # name json csv
  python3 - "$1" "$2" "$3" <<'PY'
import json, sys, csv, collections
name, js, cs = sys.argv[1:4]
m = json.load(open(js))
h = m["hard"]
gpu = collections.defaultdict(list); frame = {}
for row in csv.reader(open(cs)):
    if not row or row[0] == "frame": continue
    f, p, g = int(row[0]), row[1], float(row[2])
    if f >= 5: gpu[p].append(g)          # skip warm-up frames
    frame[f] = float(row[4]) if len(row) > 4 and row[4] else 0.0
fill = {k: v for k, v in m["counters"].items() if k.startswith("fill") or "samples" in k}
ft = [v for f, v in frame.items() if f >= 5 and v > 0]
print(f"== {name}")
print(f"  misclassified {h['misclassified_pct']:.3f} %  (edge-tolerant {h['edge_tolerant_pct']:.3f} %, leaks {h['leak_pct']:.3f} %, false shadows {h['false_shadow_pct']:.3f} %)")
print(f"  samples passed: " + (", ".join(f"{k} {v}" for k, v in fill.items()) or "(none reported)"))
for p, v in gpu.items():
    print(f"  gpu {p:24s} {sum(v)/len(v):8.3f} ms")
print(f"  gpu total {sum(sum(v)/len(v) for v in gpu.values()):.3f} ms; frame {sum(ft)/max(len(ft),1):.1f} ms (mean of {len(ft)} frames)")
PY
}

run() {  # name binary args...
  local name=$1 b=$2; shift 2
  "$b" --headless --size "$size" --frames 30 "$@" --bench "$out/$name.csv" --measure "$out/$name.json" >/dev/null
  summary "$name" "$out/$name.json" "$out/$name.csv" | tee -a "$out/summary.txt"
}

: > "$out/summary.txt"
echo "volume_bench: city scene, $size, $(nproc) cores, $(date -u +%FT%TZ)" | tee -a "$out/summary.txt"
run lesson04_auto "$l04" --preset city
run lesson04_gpu_silhouettes "$l04" --preset city --set silhouettes=gpu
if [[ -x $l03 ]]; then
  run lesson03_shadow_map "$l03" --set scene=city --set triangles=100000 --set camera.distance=60 --set camera.pitch=0.6
else
  echo "lesson 03 ($l03) is not built in $build: lesson 04's figures only" | tee -a "$out/summary.txt"
fi
