#!/usr/bin/env bash
# Light bleeding, measured (issue 41; lesson 05's README table "Light bleeding"): every filterable
# map (VSM, ESM, EVSM2, EVSM4, MSM in 16 and 32 bits) against the Embree sphere-light reference, with
# no bleeding reduction (NAME.bleed = 0), on three set-ups: lesson 05's vsm_bleeding view of the
# knot (its loops overlap in the kernel) at its blur 8 and 512^2 maps, the same at the defaults
# (blur 2, 1024^2), and the forest preset at blur 2 and at blur 8. For each: the share of the
# reference's umbra brightened by more than 0.1 (bleeding), the RMSE of the visibility, and the
# bytes a texel of the moments. Usage:
#   tools/bleeding_bench.sh [BUILD_DIR (build/default)] [OUT_DIR (out/bleeding_bench)] [SIZE (640x360)]
# Environment: SAMPLES (rays a pixel of the reference, 64). Writes OUT_DIR/*.json (--measure) and
# OUT_DIR/table.md, the README's table. One frame a run: ranks techniques, times nothing.
set -euo pipefail
source "$(dirname "$0")/script_args.sh"
check_script_args -- "$@"
build=${1:-build/default}
out=${2:-out/bleeding_bench}
size=${3:-640x360}
samples=${SAMPLES:-64}
bin=$build/bin/lesson_05_soft_shadows
[[ -x $bin ]] || { echo "bleeding_bench: $bin not built (make build)" >&2; exit 2; }
[[ $size =~ ^[0-9]+x[0-9]+$ ]] || { echo "bleeding_bench: SIZE must be WxH" >&2; exit 2; }
command -v python3 >/dev/null || { echo "bleeding_bench: needs python3" >&2; exit 2; }
mkdir -p "$out"

# set-up: label | preset | blur | map size
setups=("knot, blur 8, 512^2|vsm_bleeding|8|512" "knot, blur 2, 1024^2|vsm_bleeding|2|1024"
  "forest, blur 2, 1024^2|forest|2|1024" "forest, blur 8, 512^2|forest|8|512")
# technique: label | technique | bytes a texel | extra settings
techniques=("vsm|vsm|8|" "esm|esm|4|" "evsm2|evsm2|8|" "evsm4|evsm4|16|" "msm 16|msm|8|msm.format=16"
  "msm 32|msm|16|msm.format=32f msm.bias=3e-7")
for s in "${!setups[@]}"; do
  IFS='|' read -r _ preset blur map <<< "${setups[$s]}"
  for t in "${!techniques[@]}"; do
    IFS='|' read -r _ tech _ extra <<< "${techniques[$t]}"
    sets=(--set "technique=$tech" --set "$tech.blur=$blur" --set "$tech.map_size=$map" --set measure.overlay=none
      --set "measure.samples=$samples")
    [[ $tech == esm ]] || sets+=(--set "$tech.bleed=0")
    for kv in $extra; do sets+=(--set "$kv"); done
    "$bin" --headless --strict-gl --frames 3 --size "$size" --preset "$preset" "${sets[@]}" \
      --measure "$out/s${s}_t$t.json" >/dev/null
  done
done
python3 - "$out" "${#setups[@]}" "${setups[@]}" "${techniques[@]}" > "$out/table.md" <<'PY'
import json, sys
out, n = sys.argv[1], int(sys.argv[2])
setups = [s.split("|")[0] for s in sys.argv[3:3 + n]]
techniques = [t.split("|") for t in sys.argv[3 + n:]]
print("| technique | bytes a texel | " + " | ".join(setups) + " |")
print("|---|---|" + "---|" * len(setups))
for t, (label, _, size, _) in enumerate(techniques):
    cells = []
    for s in range(n):
        d = json.load(open(f"{out}/s{s}_t{t}.json"))["soft"]
        cells.append(f"{d['bleed_pct']:.1f} % ({d['rmse']:.3f})")
    print(f"| `{label}` | {size} | " + " | ".join(cells) + " |")
PY
cat "$out/table.md"
