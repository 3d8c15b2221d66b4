#!/usr/bin/env bash
# Lesson 07's measurements against the paper's claims (its README: Theory, "The paper's claims, measured"): hybrid maps against
# standard maps of the same source resolution and of equal memory, on the city, the forest and a
# 1M-triangle showcase, at 1024^2, 2048^2 and 4096^2, along the committed camera path
# bench/paths/walk.path. Usage:
#   tools/hybrid_bench.sh [BUILD_DIR (build/default)] [OUT_DIR (out/hybrid_bench)] [SIZE (960x540)]
# Environment: SCENES ("city forest showcase"), MAPS ("1024 2048 4096"), SAMPLES (path poses, 3),
# ROUNDS (of the interleaved timing runs, 3), FRAMES (timed frames a run, 6), PHASES ("errors timing").
#   errors  through shadowlab_bench, one report per scene (OUT_DIR/errors_SCENE/report.html): the
#           standard map (lesson 03's uniform map, nearest, 16 bits), the hybrid map as the paper
#           sets it (eps0 = 0.25) and at eps0 = 0.01, each per map size and path pose; then standard
#           maps of equal memory (levels 0 at the side whose bytes equal the hybrid map's mean
#           stored bytes along the path: 2 bytes a texel at 16 bits, and 4 for a 24-bit map), judged
#           on the same edge band (2 texels of the source map). Error figures are deterministic.
#   timing  the same three and the hybrid technique at levels 0 (a standard map through the hybrid
#           map's own, leaner lit shader: the lookup without the index) per scene and map size at
#           the path's middle pose, both maps redrawn every frame (uniform.reuse_maps=false and reuse_maps=false: a held
#           pose would otherwise reuse either map and time no depth pass), interleaved (every
#           configuration once per round), ROUNDS rounds; per pass the median of the frames after
#           the first two, CPU ms of synchronous timer scopes (a software renderer does its work at
#           flush time; lesson.hpp's GpuTimers). Ratios are taken within a round, then the median
#           over rounds. The machine's load is logged with every round.
# Writes OUT_DIR/errors.csv, OUT_DIR/timing.csv and OUT_DIR/summary.txt.
set -euo pipefail
source "$(dirname "$0")/script_args.sh"
check_script_args -- "$@"
build=${1:-build/default}
out=${2:-out/hybrid_bench}
size=${3:-960x540}
scenes=${SCENES:-city forest showcase}
maps=${MAPS:-1024 2048 4096}
samples=${SAMPLES:-3}
rounds=${ROUNDS:-3}
frames=${FRAMES:-6}
phases=${PHASES:-errors timing}
root=$(cd "$(dirname "$0")/.." && pwd)
path=$root/bench/paths/walk.path
lesson=$build/bin/lesson_07_hybrid_maps
bench=$build/bin/shadowlab_bench
for bin in "$lesson" "$bench"; do
  [[ -x $bin ]] || { echo "hybrid_bench: $bin not built (cmake --build $build)" >&2; exit 2; }
done
[[ $size =~ ^[0-9]+x[0-9]+$ ]] || { echo "hybrid_bench: size '$size' is not WxH" >&2; exit 2; }
command -v python3 >/dev/null || { echo "hybrid_bench: needs python3" >&2; exit 2; }
mkdir -p "$out"

triangles() { case $1 in showcase) echo 1000000 ;; forest) echo 200000 ;; *) echo 60000 ;; esac; }
common() {  # the settings every run shares: 16-bit maps, one comparison, the scene's size
  echo "triangles=$(triangles "$1") format=16 uniform.format=16 uniform.filter=nearest filter=nearest"
}

if [[ " $phases " == *" errors "* ]]; then
  for scene in $scenes; do
    configs=()
    for m in $maps; do
      configs+=(--config "standard $m: $(common "$scene") technique=standard uniform.map_size=$m")
      configs+=(--config "hybrid paper $m: $(common "$scene") map_size=$m eps0=0.25")
      configs+=(--config "hybrid eps0 0.01 $m: $(common "$scene") map_size=$m eps0=0.01")
    done
    echo "hybrid_bench: errors, $scene (source resolution)" >&2
    "$bench" "$lesson" --out "$out/errors_$scene" --scenes "$scene" "${configs[@]}" --path "$path" \
      --path-samples "$samples" --repeat 1 --frames 2 --size "$size" --title "lesson 07: $scene, source resolution"
    # Standard maps of the hybrid maps' memory: each hybrid run's stored bytes, averaged along the path.
    configs=()
    while IFS='|' read -r label m bytes; do
      for per in 2 4; do
        side=$(python3 -c "import math; print(int(math.sqrt($bytes / $per)))")
        format=$([[ $per == 2 ]] && echo 16 || echo 24)
        configs+=(--config "standard = $label memory ($format bit ${side}^2) $m: $(common "$scene") levels=0 map_size=$side format=$format edge_band.map_size=$m")
      done
    done < <(python3 - "$out/errors_$scene" <<'PY'
import json, sys, collections, os
rows = json.load(open(os.path.join(sys.argv[1], "report.json")))["rows"]
runs = collections.defaultdict(list)
for i, r in enumerate(rows):
    if not r["technique"].startswith("hybrid"): continue
    j = json.load(open(os.path.join(sys.argv[1], r["imageThumbnail"].replace(".png", ".json"))))
    label, m = r["technique"].rsplit(" ", 1)
    runs[(label.replace("hybrid ", ""), m)].append(int(j["counters"]["light0 hybrid bytes"].split()[0]))
for (label, m), b in sorted(runs.items()):
    print(f"{label}|{m}|{sum(b) // len(b)}")
PY
)
    echo "hybrid_bench: errors, $scene (equal memory)" >&2
    "$bench" "$lesson" --out "$out/equal_$scene" --scenes "$scene" "${configs[@]}" --path "$path" \
      --path-samples "$samples" --repeat 1 --frames 2 --size "$size" --title "lesson 07: $scene, equal memory"
  done
  python3 - "$out" $scenes > "$out/errors.csv" <<'PY'
import json, sys, os
out, scenes = sys.argv[1], sys.argv[2:]
print("scene,configuration,map,pose,misclassified_pct,edge_misclassified_pct,edge_pixels,m_mean,edge_m_mean,edge_m_p95,stored_bytes,stored_texels")
for scene in scenes:
    for part in ("errors", "equal"):
        folder = os.path.join(out, f"{part}_{scene}")
        for r in json.load(open(os.path.join(folder, "report.json")))["rows"]:
            j = json.load(open(os.path.join(folder, r["imageThumbnail"].replace(".png", ".json"))))
            label, m = r["technique"].rsplit(" ", 1)
            b, c = j["edge_band"], j["counters"]
            stored = c.get("light0 hybrid bytes", "").split(" ")[0]
            texels = c.get("light0 stored texels", "").split(" ")[0]
            if label == "standard":  # lesson 03's map: 16 bits a texel
                stored, texels = str(int(m) * int(m) * 2), str(int(m) * int(m))
            elif label.startswith("standard ="):  # levels 0 at the equal-memory side: its format's bytes
                stored = str(int(texels) * (2 if "16 bit" in label else 4))
            print(",".join(str(x) for x in [scene, label, m, r["frame"], j["hard"]["misclassified_pct"],
                  b["misclassified_pct"], b["pixels"], j["aliasing"]["mean"], b["aliasing"]["mean"], b["aliasing"]["p95"],
                  stored, texels]))
PY
fi

if [[ " $phases " == *" timing "* ]]; then
  csv=$out/timing.csv
  echo "round,scene,map,configuration,load,shadow_ms,merge_ms,index_ms,records_ms,scene_ms,total_ms,frame_ms" > "$csv"
  for round in $(seq 1 "$rounds"); do
    for scene in $scenes; do
      for m in $maps; do
        for config in standard levels0 paper tuned; do
          case $config in
            standard) sets="technique=standard uniform.map_size=$m uniform.reuse_maps=false" ;;  # redrawn every frame, as the hybrid map is
            levels0) sets="map_size=$m levels=0 reuse_maps=false" ;;
            paper) sets="map_size=$m eps0=0.25 reuse_maps=false" ;;
            tuned) sets="map_size=$m eps0=0.01 reuse_maps=false" ;;
          esac
          args=(--headless --size "$size" --frames "$frames" --replay "$path@1" --set "scene=$scene")
          for kv in $(common "$scene") $sets; do args+=(--set "$kv"); done
          tag=$out/timing/${scene}_${m}_${config}_$round
          mkdir -p "$out/timing"
          load=$(cut -d' ' -f1 /proc/loadavg)
          printf '\rhybrid_bench: timing round %d/%d %s %s %s (load %s)   ' "$round" "$rounds" "$scene" "$m" "$config" "$load" >&2
          "$lesson" "${args[@]}" --bench "$tag.csv" >/dev/null
          python3 - "$tag.csv" "$round" "$scene" "$m" "$config" "$load" >> "$csv" <<'PY'
import csv, sys, statistics, collections
passes = collections.defaultdict(lambda: collections.defaultdict(float)); frame = {}
for r in csv.reader(open(sys.argv[1])):
    if not r or r[0] == "frame" or int(r[0]) < 2: continue
    f, name = int(r[0]), r[1]
    key = ("shadow" if name.startswith("shadow") else "merge" if name.startswith("hybrid merge") else
           "index" if name.startswith("hybrid index") else "records" if name.startswith("hybrid records") else
           "scene" if name == "scene" else None)
    if key: passes[key][f] += float(r[3])
    frame[f] = float(r[4])
med = lambda k: statistics.median(passes[k].values()) if passes[k] else 0.0
parts = [med(k) for k in ("shadow", "merge", "index", "records", "scene")]
print(",".join([*sys.argv[2:7], *(f"{p:.2f}" for p in parts), f"{sum(parts):.2f}", f"{statistics.median(frame.values()):.1f}"]))
PY
        done
      done
    done
  done
  echo >&2
fi

python3 - "$out" <<'PY' | tee "$out/summary.txt"
import csv, os, sys, statistics, collections
out = sys.argv[1]
if os.path.exists(os.path.join(out, "errors.csv")):
    rows = list(csv.DictReader(open(os.path.join(out, "errors.csv"))))
    g = collections.defaultdict(list)
    for r in rows: g[(r["scene"], int(r["map"]), r["configuration"])].append(r)
    print("errors: mean over the path's poses; edge = within 2 source texels of a shadow edge; m on edge pixels")
    for k in sorted(g):
        rs = g[k]; avg = lambda f: sum(float(r[f]) for r in rs) / len(rs)
        print(f"  {k[0]:9s} {k[1]:5d} {k[2]:42s} misclassified {avg('misclassified_pct'):7.3f} %  edge {avg('edge_misclassified_pct'):7.3f} %"
              f"  m edge {avg('edge_m_mean'):6.2f}  stored {avg('stored_bytes') / 1048576:7.2f} MiB")
if os.path.exists(os.path.join(out, "timing.csv")):
    rows = list(csv.DictReader(open(os.path.join(out, "timing.csv"))))
    t = {(r["round"], r["scene"], r["map"], r["configuration"]): r for r in rows}
    print("timing: CPU ms of synchronous passes (llvmpipe), median of frames 2+, ratio to lesson 03's standard map within a round,")
    print("        median and range over the rounds; loads " + ", ".join(sorted({r["load"] for r in rows})))
    for scene, m in sorted({(r["scene"], r["map"]) for r in rows}, key=lambda x: (x[0], int(x[1]))):
        for config in ("levels0", "paper", "tuned"):
            ratios, parts = [], collections.defaultdict(list)
            for rnd in sorted({r["round"] for r in rows}):
                s, h = t.get((rnd, scene, m, "standard")), t.get((rnd, scene, m, config))
                if not s or not h: continue
                ratios.append(float(h["total_ms"]) / float(s["total_ms"]))
                for f in ("shadow_ms", "merge_ms", "index_ms", "records_ms", "scene_ms"):
                    parts[f + "_h"].append(float(h[f])); parts[f + "_s"].append(float(s[f]))
            if not ratios: continue
            md = lambda f: statistics.median(parts[f])
            print(f"  {scene:9s} {m:5s} {config:6s}: total x{statistics.median(ratios):.2f} ({min(ratios):.2f}..{max(ratios):.2f});"
                  f" standard depth {md('shadow_ms_s'):.0f} + scene {md('scene_ms_s'):.0f} ms;"
                  f" hybrid depth {md('shadow_ms_h'):.0f} + merge {md('merge_ms_h'):.0f} + index {md('index_ms_h'):.0f}"
                  f" + records {md('records_ms_h'):.0f} + scene {md('scene_ms_h'):.0f} ms")
PY
