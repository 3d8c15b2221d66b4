#!/usr/bin/env bash
# check_gradescope.sh WORK_DIR  (grading.gradescope)
#
# The Gradescope autograder as shipped: make gradescope LESSONS=01,03 builds the zip; it is unpacked
# into WORK_DIR/autograder/source, standing for /autograder (AUTOGRADER_ROOT), setup.sh prebuilds
# (SHADOWLAB_SKIP_APT=1: the packages are here), and run_autograder grades four submissions:
#   reference  a handout tree, nested one folder deep, with the reference solutions
#              (REFERENCE_CALLS=report: they forward to the library): full marks
#   untouched  the stubs at the top level: 0
#   flat       exercises.cpp (lesson 03: 03.1 borrowed through hybrid::levelBias, 03.2 by hand),
#              notes.txt and mystery.cpp: 03.2 full, 03.1 0 with the reason, and the two other
#              files named with why they were not graded
#   crash      lesson 01's faulty fixture as a flat exercises.cpp: 01.1 full, 01.2 over the time
#              limit and 01.3 crashed, each 0 with its reason, the grade written
# Each time only the student's files compile (the build log's compile lines are counted).
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
work=$1
rm -rf "$work"
mkdir -p "$work/autograder/source"
LESSONS=01,03 bash "$root/tools/grading/make_gradescope.sh" "$work/zip" | tail -1
unzip -q "$work/zip/shadowlab-autograder-01-03.zip" -d "$work/autograder/source"
export AUTOGRADER_ROOT=$work/autograder
SHADOWLAB_SKIP_APT=1 bash "$AUTOGRADER_ROOT/source/setup.sh" | tail -2
sub=$AUTOGRADER_ROOT/submission

grade() {
  local name=$1
  shift
  echo "== $name"
  env "$@" GRADE_TIMEOUT=5 bash "$AUTOGRADER_ROOT/source/run_autograder" >"$work/$name.log" 2>&1 ||
    { cat "$work/$name.log"; echo "FAIL: run_autograder exited non-zero for $name"; exit 1; }
  cp "$AUTOGRADER_ROOT/results/results.json" "$work/$name.results.json"
  # Only the student's files compiled (at most: two exercises.cpp per grader, the GLSL is not compiled).
  local compiled
  compiled=$(grep -c 'Building CXX object' "$AUTOGRADER_ROOT/work/grade/logs/"build_*.log | awk -F: '{s += $2} END {print s}')
  echo "compiled $compiled C++ files"
  [ "$compiled" -le 4 ] || { echo "FAIL: $compiled files compiled for $name: the prebuild did not hold"; exit 1; }
}
put() { mkdir -p "$(dirname "$sub/$2")"; cp "$root/$1" "$sub/$2"; }

rm -rf "$sub"
put tests/grading/ex01_reference.cpp shadowlab-student/lessons/01_lighting/exercises.cpp
put tests/grading/ex03_reference.cpp shadowlab-student/lessons/03_shadow_quality/exercises.cpp
put shaders/03_shadow_quality/exercises_reference.glsl shadowlab-student/shaders/03_shadow_quality/exercises.glsl
grade reference REFERENCE_CALLS=report

rm -rf "$sub"
put lessons/01_lighting/exercises.cpp lessons/01_lighting/exercises.cpp
put lessons/03_shadow_quality/exercises.cpp lessons/03_shadow_quality/exercises.cpp
put shaders/03_shadow_quality/exercises.glsl shaders/03_shadow_quality/exercises.glsl
grade untouched

rm -rf "$sub"
put tests/grading/fixtures/borrowed/lessons/03_shadow_quality/exercises.cpp exercises.cpp
echo "my notes" >"$sub/notes.txt"
echo "int main() { return 0; }" >"$sub/mystery.cpp"
grade flat

rm -rf "$sub"
put tests/grading/fixtures/faulty_ex01/exercises.cpp exercises.cpp
grade crash

python3 - "$work" <<'PY'
import json, re, sys
from collections import defaultdict
work = sys.argv[1]
failures = []
def load(name):
    d = json.load(open(f"{work}/{name}.results.json"))
    per = defaultdict(lambda: [0.0, 0.0, []])
    for t in d["tests"]:
        e = per[t["number"]]
        e[0] += t["score"]; e[1] += t["max_score"]; e[2].append(t.get("output", ""))
    return d, per
def expect(cond, what):
    if not cond: failures.append(what)

d, per = load("reference")
total = sum(v[1] for v in per.values())
expect(total > 0 and abs(d["score"] - total) < 1e-6, f"reference: {d['score']} of {total}")
expect(sorted(per) == ["01.1", "01.2", "01.3", "01.4", "03.1", "03.2", "03.3", "03.4", "03.5", "03.6"],
       f"reference: exercises graded {sorted(per)}")
expect("shadowlab-student/lessons/01_lighting/exercises.cpp: graded as lessons/01_lighting/exercises.cpp (by its path)" in d["output"],
       "reference: the nested tree was not placed by its paths")
d, per = load("untouched")
expect(d["score"] == 0, f"untouched: {d['score']} points")
d, per = load("flat")
expect(per["03.2"][0] == per["03.2"][1] > 0, f"flat: 03.2 {per['03.2'][:2]}")
expect(per["03.1"][0] == 0 and any("reaches shadowlab::shadow::slopeScaledBias" in o for o in per["03.1"][2]),
       "flat: 03.1 not zeroed with the reason")
for line in ["exercises.cpp: graded as lessons/03_shadow_quality/exercises.cpp (by its namespace)",
             "mystery.cpp: cannot tell which lesson it is for",
             "notes.txt: not graded (only exercises.cpp and exercises.glsl are)",
             "no lessons/01_lighting/exercises.cpp in the submission: graded as the untouched stub"]:
    expect(line in d["output"], f"flat: the output does not say '{line}'")
d, per = load("crash")
expect(per["01.1"][0] == per["01.1"][1] > 0, f"crash: 01.1 {per['01.1'][:2]}")
for ex, why in [("01.2", "did not finish within 5 s"), ("01.3", "crashed with SIGSEGV")]:
    expect(per[ex][0] == 0 and any(why in o for o in per[ex][2]), f"crash: {ex} not 0 with '{why}'")
if failures:
    print("FAIL:\n  " + "\n  ".join(failures))
    sys.exit(1)
print("gradescope: reference full marks, untouched 0, flat placed (03.2 full, 03.1 borrowed 0), crash graded exercise by exercise")
PY
