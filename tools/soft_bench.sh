#!/usr/bin/env bash
# Lesson 05's closing note, measured: every soft-shadow technique and setting against the Embree
# sphere-light reference on the showcase and the forest, along each scene's committed camera path
# (bench/paths/soft_*.path), at two light radii; then the techniques' frame times as ratios to the
# hard shadow, interleaved and repeated in one run. Usage:
#   tools/soft_bench.sh [BUILD_DIR (build/default)] [OUT_DIR (out/soft_bench)] [SIZE (320x180)]
# Environment: SCENES ("showcase forest"), SAMPLES (rays per pixel of the reference, 64), POSES (path
# samples, 3), TIMING_SIZE (640x360), TIMING_ROUNDS (3; 0: no timing runs), SWEEP (0: only the timing
# runs), ONLY (an extended regular expression: only the configurations whose label matches it).
# Writes OUT_DIR/<scene>_r<R>/report.{csv,json,html} (shadowlab_bench: RMSE, max error, umbra over-
# and under-estimate, the reference's noise floor, ms per pass, the Pareto front; on the showcase the
# shimmer under its sphere sliding 1 cm a frame, bench/paths/showcase_light_drift.path), OUT_DIR/timing.csv
# and OUT_DIR/summary.txt. The soft reference costs seconds a frame at full size: the sweep runs at
# a reduced size on purpose. Figures from a software renderer (llvmpipe) rank techniques; they do not
# predict a GPU's milliseconds.
set -euo pipefail
source "$(dirname "$0")/script_args.sh"
check_script_args -- "$@"
build=${1:-build/default}
out=${2:-out/soft_bench}
size=${3:-320x180}
scenes=${SCENES:-showcase forest}
samples=${SAMPLES:-64}
poses=${POSES:-3}
timing_size=${TIMING_SIZE:-640x360}
rounds=${TIMING_ROUNDS:-3}
bin=$build/bin/lesson_05_soft_shadows
bench=$build/bin/shadowlab_bench
root=$(cd "$(dirname "$0")/.." && pwd)
[[ -x $bin && -x $bench ]] || { echo "soft_bench: $bin or $bench not built (make build)" >&2; exit 2; }
[[ $size =~ ^[0-9]+x[0-9]+$ && $timing_size =~ ^[0-9]+x[0-9]+$ ]] || { echo "soft_bench: sizes must be WxH" >&2; exit 2; }
command -v python3 >/dev/null || { echo "soft_bench: needs python3" >&2; exit 2; }
mkdir -p "$out"

# Each scene's light (the path sets light0's position and direction) and its two radii.
scene_sets() {
  case $1 in
    showcase) echo "scene=showcase" ;;
    forest) echo "scene=forest light0.spot_inner=0.55 light0.spot_outer=0.65" ;;
  esac
}
radii() { case $1 in showcase) echo "0.3 0.6" ;; forest) echo "0.6 1.2" ;; esac; }

# The configurations: label, then the technique's settings.
configs=(
  "many 1:technique=many many.samples=1"
  "many 2:technique=many many.samples=2"
  "many 4:technique=many many.samples=4"
  "many 8:technique=many many.samples=8"
  "many 16:technique=many many.samples=16 measure.noise_floor=true"
  "many 16 disk:technique=many many.samples=16 many.layout=disk"
  "many 32:technique=many many.samples=32"
  "many 64:technique=many many.samples=64"
  "pcf 8 r2:technique=pcf pcf.filter_taps=8 pcf.radius=2"
  "pcf 8 r4:technique=pcf pcf.filter_taps=8 pcf.radius=4"
  "pcf 8 r8:technique=pcf pcf.filter_taps=8 pcf.radius=8"
  "pcf 16 r2:technique=pcf pcf.filter_taps=16 pcf.radius=2"
  "pcf 16 r4:technique=pcf pcf.filter_taps=16 pcf.radius=4"
  "pcf 16 r8:technique=pcf pcf.filter_taps=16 pcf.radius=8"
  "pcf 32 r2:technique=pcf pcf.filter_taps=32 pcf.radius=2"
  "pcf 32 r4:technique=pcf pcf.filter_taps=32 pcf.radius=4"
  "pcf 32 r8:technique=pcf pcf.filter_taps=32 pcf.radius=8"
  "pcss 8+8:technique=pcss pcss.search_taps=8 pcss.filter_taps=8"
  "pcss 16+16:technique=pcss pcss.search_taps=16 pcss.filter_taps=16"
  "pcss 16+16 pixel:technique=pcss pcss.search_taps=16 pcss.filter_taps=16 pcss.quad_search=false"
  "pcss 32+32:technique=pcss pcss.search_taps=32 pcss.filter_taps=32"
  "parker 32:technique=parker"
  "parker 32 linear:technique=parker parker.profile=linear"
  "haines 32:technique=haines"
  "mesh 24:technique=mesh mesh.nodes=24"
  "mesh 48:technique=mesh mesh.nodes=48"
  "mesh 96:technique=mesh mesh.nodes=96"
  "vsm blur 2:technique=vsm vsm.blur=2 vsm.map_size=1024"
  "vsm blur 4:technique=vsm vsm.blur=4 vsm.map_size=1024"
  "esm blur 2:technique=esm esm.blur=2 esm.map_size=1024"
  "esm blur 4:technique=esm esm.blur=4 esm.map_size=1024"
  "evsm2 blur 2:technique=evsm2 evsm2.blur=2 evsm2.map_size=1024"
  "evsm4 blur 2:technique=evsm4 evsm4.blur=2 evsm4.map_size=1024"
  "evsm4 blur 4:technique=evsm4 evsm4.blur=4 evsm4.map_size=1024"
  "msm 16 blur 2:technique=msm msm.blur=2 msm.map_size=1024"
  "msm 16 blur 4:technique=msm msm.blur=4 msm.map_size=1024"
  "msm 32 blur 2:technique=msm msm.blur=2 msm.map_size=1024 msm.format=32f msm.bias=3e-7"
)

if [[ ${SWEEP:-1} != 0 ]]; then
  for scene in $scenes; do
    for r in $(radii "$scene"); do
      args=()
      for c in "${configs[@]}"; do
        [[ -z ${ONLY:-} || ${c%%:*} =~ $ONLY ]] || continue
        args+=(--config "${c%%:*}: ${c#*:} $(scene_sets "$scene") light0.radius=$r measure.samples=$samples")
      done
      # Shimmer on the showcase: its sphere sliding 1 cm a frame over 9 frames, the camera still
      # (the mean change of visibility a frame beyond the reference's: shimmer_change:light).
      shimmer=()
      [[ $scene == showcase ]] &&
        shimmer=(--shimmer "light=$root/bench/paths/showcase_light_drift.path@0..0.1333" --shimmer-frames 9)
      echo "soft_bench: $scene, R = $r m, $(( ${#args[@]} / 2 )) configurations x $poses poses at $size" >&2
      "$bench" "$bin" --out "$out/${scene}_r$r" --title "lesson 05: $scene, sphere of radius $r m, $size" \
        --path "$root/bench/paths/soft_$scene.path" --path-samples "$poses" --repeat 1 --frames 2 --size "$size" \
        "${args[@]}" "${shimmer[@]}" >/dev/null
    done
  done
fi

# Timing: the default view of the showcase, every technique once per round, the rounds interleaved,
# the median frame, scene pass and shadow passes of frames 2..7 (the first frames build programs).
timing=$out/timing.csv
echo "round,technique,frame_ms,scene_ms,shadow_ms" > "$timing"
techniques="many,technique=many many.samples=1
many16,technique=many many.samples=16
pcf16,technique=pcf
pcss16,technique=pcss
pcss16pixel,technique=pcss pcss.quad_search=false
parker,technique=parker
haines,technique=haines
mesh,technique=mesh
vsm,technique=vsm
esm,technique=esm
evsm4,technique=evsm4
msm,technique=msm"
for round in $(seq "$rounds"); do
  while IFS=, read -r name sets; do
    set_args=()
    for kv in $sets; do set_args+=(--set "$kv"); done
    "$bin" --headless --frames 8 --size "$timing_size" "${set_args[@]}" --bench "$out/t.csv" >/dev/null
    python3 - "$out/t.csv" "$round" "$name" >> "$timing" <<'PY'
import csv, statistics, sys, collections
rows = [r for r in csv.DictReader(open(sys.argv[1])) if int(r["frame"]) >= 2]
frame = {r["frame"]: float(r["frame_ms"]) for r in rows}
scene = [float(r["cpu_ms"]) for r in rows if r["pass"] == "scene"]
shadow = collections.defaultdict(float)
for r in rows:
    if r["pass"].startswith("shadow") or r["pass"] == "light mesh bake": shadow[r["frame"]] += float(r["cpu_ms"])
print(f"{sys.argv[2]},{sys.argv[3]},{statistics.median(frame.values()):.1f},{statistics.median(scene):.1f},"
      f"{statistics.median(list(shadow.values()) + [0.0] * (len(frame) - len(shadow))):.1f}")
PY
  done <<< "$techniques"
done
rm -f "$out/t.csv"

python3 - "$out" "$timing" > "$out/summary.txt" <<'PY'
import csv, glob, os, statistics, sys, collections
out, timing = sys.argv[1], sys.argv[2]
print("Lesson 05 soft-shadow benchmark (tools/soft_bench.sh). Error figures: deterministic renders against")
print("the Embree sphere-light reference, mean over the path's poses. Noise floor: RMSE between two references")
print("of different seeds (the 'many 16' rows).\n")
for report in sorted(glob.glob(os.path.join(out, "*_r*", "report.csv"))):
    rows = list(csv.DictReader(open(report)))
    by = collections.defaultdict(list)
    for r in rows:
        if r["soft_rmse"]: by[r["technique"]].append(r)
    noise = [float(r["reference_noise_rmse"]) for r in rows if r["reference_noise_rmse"]]
    floor = statistics.mean(noise) if noise else float("nan")
    print(f"== {os.path.basename(os.path.dirname(report))}: noise floor {floor:.4f}")
    print(f"{'technique':18} {'RMSE':>7} {'x floor':>7} {'max':>6} {'over%':>6} {'under%':>6} {'gpu ms':>8}")
    for name, rs in by.items():
        m = lambda k: statistics.mean(float(r[k]) for r in rs)
        print(f"{name:18} {m('soft_rmse'):7.4f} {m('soft_rmse') / floor:7.2f} {m('soft_max_abs'):6.3f} "
              f"{m('umbra_over_pct'):6.2f} {m('umbra_under_pct'):6.2f} {m('gpu_total_ms'):8.1f}")
    for taps in ("8", "16", "32"):
        pcss = statistics.mean(float(r["soft_rmse"]) for r in by.get(f"pcss {taps}+{taps}", [{"soft_rmse": "nan"}]))
        pcfs = {n: statistics.mean(float(r["soft_rmse"]) for r in rs) for n, rs in by.items() if n.startswith(f"pcf {taps} ")}
        if pcfs:
            best = min(pcfs, key=pcfs.get)
            print(f"  {taps} filter taps: PCSS {pcss:.4f} against the best fixed PCF ({best}) {pcfs[best]:.4f}:"
                  f" {'below' if pcss < pcfs[best] else 'NOT below'}")
    print()
t = list(csv.DictReader(open(timing)))
base = {r["round"]: float(r["frame_ms"]) for r in t if r["technique"] == "many"}
print("== frame time against the hard shadow (one point light), same round, median over rounds")
for name in dict.fromkeys(r["technique"] for r in t):
    rs = [r for r in t if r["technique"] == name]
    ratio = statistics.median(float(r["frame_ms"]) / base[r["round"]] for r in rs)
    print(f"{name:10} frame {statistics.median(float(r['frame_ms']) for r in rs):8.1f} ms"
          f"  scene {statistics.median(float(r['scene_ms']) for r in rs):8.1f}"
          f"  shadow {statistics.median(float(r['shadow_ms']) for r in rs):7.1f}  x{ratio:.2f}")
PY
cat "$out/summary.txt"
