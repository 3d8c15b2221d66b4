#!/usr/bin/env bash
# make grade-submission SUBMISSION=DIR [SEED=N] [GRADES=OUT] [LESSONS=03,05] [REFERENCE_CALLS=report]
#
# LESSONS: grade only these lessons (one week's assignment); default every lesson with exercises.
# GRADE_TIMEOUT: seconds each C++ exercise may run (default 60). GRADE_BUILD: the build folder
# (default build/grade-submission; make grade-class gives each submission its own).
# REFERENCE_CALLS: zero (default: an exercise that reaches the reference answer scores 0, with the
# reason) or report (listed in logs/reference_calls.txt only, for an instructor who reads them).
# Grades a student's submission against this (the instructor's) tree: DIR holds the student's
# files where the handout has them, lessons/NN_name/exercises.cpp and shaders/NN_name/
# exercises.glsl (a whole handout tree will do; a missing file is graded as the untouched stub).
# Each grader is built from the student's file (build/grade-submission, -DSHADOWLAB_SUBMISSION)
# and runs its public AND hidden cases: the hidden ones (and the GLSL graders' random cases) with
# the assignment's seed (SEED, else fixed by its lessons; written into every report), the public
# C++ cases with the seed the student's own `make grade` used; the GLSL graders render the lessons with the student's shaders. A file that
# does not compile scores 0 on its lesson's cases, with the compiler's errors in the report.
# Writes OUT (default out/grades/submission): score.json, junit.xml, results.json (Gradescope),
# runs/ (each grader's results), logs/ (builds, graders, and reference_calls.txt: the exercises
# whose code reaches the reference answer, which score 0).
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
usage="usage: grade_submission.sh SUBMISSION_DIR [OUT_DIR]  (or --lessons: print LESSONS checked, as NN,NN)"
[ $# -ge 1 ] || { echo "$usage" >&2; exit 2; }
caller=$PWD  # relative paths are the caller's
cd "$root"
# The lessons that have exercises, and the ones asked for.
available=$( (ls tests/grading/ex*_reference.cpp tests/grading/glsl/ex*_glsl.cpp 2>/dev/null || true) |
  sed -E 's#.*/ex([0-9]+)_(reference\.cpp|glsl\.cpp)$#\1#' | sort -u | paste -sd ' ' -)
wanted=" $available "
if [ -n "${LESSONS:-}" ]; then
  wanted=" "
  for nn in ${LESSONS//,/ }; do
    [ ${#nn} -eq 1 ] && nn=0$nn
    case " $available " in
      *" $nn "*) wanted="$wanted$nn " ;;
      *) echo "grade_submission.sh: LESSONS: '$nn' is not a lesson with exercises; valid: $available" >&2; exit 2 ;;
    esac
  done
  [ "$1" = --lessons ] || echo "grade: lessons$wanted(LESSONS=$LESSONS)"
fi
if [ "$1" = --lessons ]; then
  [ -z "${LESSONS:-}" ] || { echo "$wanted" | xargs | tr ' ' ','; }
  exit 0
fi
sub=$1 out=${2:-$root/out/grades/submission}
[[ "$sub" = /* ]] || sub=$caller/$sub
[[ "$out" = /* ]] || out=$caller/$out
[ -d "$sub" ] || { echo "grade_submission.sh: no submission directory '$1'; $usage" >&2; exit 2; }
sub=$(cd "$sub" && pwd)
# The same code scores the same: the hidden cases' seed is fixed per assignment (SEED, else drawn
# from its lessons), the public cases, C++ and GLSL, keep the seed `make grade` ran them with for the
# student (the default: the handout's GLSL reference values were recorded at it).
seed=${SEED:-$(printf 'shadowlab assignment%s' "$wanted" | cksum | cut -d' ' -f1)}
build=${GRADE_BUILD:-$root/build/grade-submission}  # make grade-class: one per submission
jobs=${JOBS:-$(nproc 2>/dev/null || echo 2)}
reference_calls=${REFERENCE_CALLS:-zero}
case $reference_calls in
  zero | report) ;;
  *) echo "grade_submission.sh: REFERENCE_CALLS='$reference_calls'; valid: zero, report" >&2; exit 2 ;;
esac
# The object file a target compiled from a source (compile_commands.json knows; stale objects of
# earlier submissions share the folder).
object_of() {
  python3 - "$build/compile_commands.json" "$1" "$2" <<'PY'
import json, os, shlex, sys
for e in json.load(open(sys.argv[1])):
    args = e["arguments"] if "arguments" in e else shlex.split(e["command"])
    out = args[args.index("-o") + 1] if "-o" in args else ""
    if os.path.realpath(e["file"]) == os.path.realpath(sys.argv[3]) and f"/{sys.argv[2]}/" in f"/{out}":
        print(os.path.join(e["directory"], out))
        break
PY
}
graded() { case "$wanted" in *" $1 "*) return 0 ;; *) return 1 ;; esac; }
rm -rf "$out"
mkdir -p "$out/runs" "$out/logs"
echo "grade: $sub, seed $seed (the assignment's hidden cases; public C++ cases as the student ran them)"
# -ffunction-sections: one section per function, so the reference-call check can link a student's
# function alone and see exactly which library functions it reaches.
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSHADOWLAB_SUBMISSION="$sub" \
  -DCMAKE_CXX_FLAGS=-ffunction-sections -DCMAKE_EXPORT_COMPILE_COMMANDS=ON >"$out/logs/configure.log"
cmake --build "$build" -j "$jobs" --target grade_report grade_isolated >"$out/logs/build_report.log"

reports=()
for ref in tests/grading/ex*_reference.cpp; do
  nn=$(basename "$ref" | sed -E 's/ex([0-9]+)_reference.cpp/\1/')
  graded "$nn" || continue
  lesson=$(basename "$(ls -d lessons/${nn}_*)")
  [ -f "$sub/lessons/$lesson/exercises.cpp" ] ||
    echo "grade: no lessons/$lesson/exercises.cpp in the submission: graded as the untouched stub"
  student_cpp=$sub/lessons/$lesson/exercises.cpp
  [ -f "$student_cpp" ] || student_cpp=$root/lessons/$lesson/exercises.cpp
  if cmake --build "$build" -j "$jobs" --target "grade_ex$nn" "grade_ex${nn}_reference" >"$out/logs/build_ex$nn.log" 2>&1; then
    # One exercise per process, with limits: a crash or an endless loop costs that exercise only.
    "$build/bin/grade_isolated" --reference="$build/bin/grade_ex${nn}_reference" --results-json="$out/runs/ex$nn.json" \
      --timeout="${GRADE_TIMEOUT:-60}" \
      -- "$build/bin/grade_ex$nn" --hidden-seed="$seed" >"$out/logs/ex$nn.log" 2>&1 || true
    reports+=("$out/runs/ex$nn.json")
    # An exercise whose function reaches, directly or through any library function, what the
    # reference answer calls borrowed the answer: decided by the linker (reference_reach.sh), it
    # scores 0 with the reason in the student's report.
    mine=$(object_of "grade_ex$nn.dir" "$student_cpp")
    theirs=$(object_of "shadowlab_ex${nn}_reference.dir" "$root/tests/grading/ex${nn}_reference.cpp")
    if [ -n "$mine" ] && [ -n "$theirs" ]; then
      bash tools/grading/reference_reach.sh "$mine" "$theirs" "lessons/$lesson/exercises.cpp" \
        "$build/libshadowlab_algorithms.a" "$build/libshadowlab_core.a" >>"$out/logs/reference_calls.txt" \
        2>>"$out/logs/reference_reach.log" || echo "grade: the reference-call check of lesson $nn failed (logs/reference_reach.log)"
    fi
  else
    echo "grade: lessons/$lesson/exercises.cpp does not compile: its cases score 0 (logs/build_ex$nn.log)"
    cmake --build "$build" -j "$jobs" --target "grade_ex${nn}_reference" >>"$out/logs/build_ex$nn.log" 2>&1
    "$build/bin/grade_ex${nn}_reference" --hidden-seed="$seed" --results-json="$out/runs/ex$nn.json" >/dev/null 2>&1 || true
    reports+=("--build-failed=$out/logs/build_ex$nn.log" "$out/runs/ex$nn.json")
  fi
done

for cases in tests/grading/glsl/ex*_glsl.cpp; do
  nn=$(basename "$cases" | sed -E 's/ex([0-9]+)_glsl.cpp/\1/')
  graded "$nn" || continue
  lesson=$(basename "$(ls -d lessons/${nn}_*)")
  student=$sub
  if [ ! -f "$sub/shaders/$lesson/exercises.glsl" ]; then
    echo "grade: no shaders/$lesson/exercises.glsl in the submission: graded as the untouched stub"
    student=tree
  fi
  cmake --build "$build" -j "$jobs" --target "grade_ex${nn}_glsl" >"$out/logs/build_ex${nn}_glsl.log" 2>&1
  "$build/bin/grade_ex${nn}_glsl" --lesson-binary="$build/bin/glsl_lesson_$lesson" --student="$student" \
    --hidden-seed="$seed" --images="$out/images/ex$nn" --results-json="$out/runs/ex${nn}_glsl.json" \
    >"$out/logs/ex${nn}_glsl.log" 2>&1 || true
  reports+=("$out/runs/ex${nn}_glsl.json")
done

touch "$out/logs/reference_calls.txt"
zeroed=()
if [ -s "$out/logs/reference_calls.txt" ]; then
  if [ "$reference_calls" = zero ]; then
    echo "grade: these exercises reach the reference answer and score 0:"
    zeroed=(--reference-calls="$out/logs/reference_calls.txt")
  else
    echo "grade: these exercises reach the reference answer (REFERENCE_CALLS=report: listed, not scored):"
  fi
  cut -f1 "$out/logs/reference_calls.txt" | sed 's/^/  /'
fi
"$build/bin/grade_report" --out "$out" "${zeroed[@]}" "${reports[@]}"
