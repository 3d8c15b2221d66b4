#!/usr/bin/env bash
# make grade-submission SUBMISSION=DIR [SEED=N] [GRADES=OUT] [LESSONS=03,05]
#
# LESSONS: grade only these lessons (one week's assignment); default every lesson with exercises.
# Grades a student's submission against this (the instructor's) tree: DIR holds the student's
# files where the handout has them, lessons/NN_name/exercises.cpp and shaders/NN_name/
# exercises.glsl (a whole handout tree will do; a missing file is graded as the untouched stub).
# Each grader is built from the student's file (build/grade-submission, -DSHADOWLAB_SUBMISSION)
# and runs its public AND hidden cases with a seed the grader chooses (SEED, else random, written
# into every report); the GLSL graders render the lessons with the student's shaders. A file that
# does not compile scores 0 on its lesson's cases, with the compiler's errors in the report.
# Writes OUT (default out/grades/submission): score.json, junit.xml, results.json (Gradescope),
# runs/ (each grader's results), logs/ (builds, graders, and calls into the reference library).
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
usage="usage: grade_submission.sh SUBMISSION_DIR [OUT_DIR]"
[ $# -ge 1 ] || { echo "$usage" >&2; exit 2; }
[ -d "$1" ] || { echo "grade_submission.sh: no submission directory '$1'; $usage" >&2; exit 2; }
sub=$(cd "$1" && pwd)
out=${2:-$root/out/grades/submission}
seed=${SEED:-$(od -An -N4 -tu4 /dev/urandom | tr -d ' ')}
build=$root/build/grade-submission
jobs=${JOBS:-$(nproc 2>/dev/null || echo 2)}
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
  echo "grade: lessons$wanted(LESSONS=$LESSONS)"
fi
graded() { case "$wanted" in *" $1 "*) return 0 ;; *) return 1 ;; esac; }
rm -rf "$out"
mkdir -p "$out/runs" "$out/logs"
echo "grade: $sub, seed $seed"
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSHADOWLAB_SUBMISSION="$sub" >"$out/logs/configure.log"
cmake --build "$build" -j "$jobs" --target grade_report grade_isolated >"$out/logs/build_report.log"

reports=()
for ref in tests/grading/ex*_reference.cpp; do
  nn=$(basename "$ref" | sed -E 's/ex([0-9]+)_reference.cpp/\1/')
  graded "$nn" || continue
  lesson=$(basename "$(ls -d lessons/${nn}_*)")
  [ -f "$sub/lessons/$lesson/exercises.cpp" ] ||
    echo "grade: no lessons/$lesson/exercises.cpp in the submission: graded as the untouched stub"
  if cmake --build "$build" -j "$jobs" --target "grade_ex$nn" "grade_ex${nn}_reference" >"$out/logs/build_ex$nn.log" 2>&1; then
    # One exercise per process, with limits: a crash or an endless loop costs that exercise only.
    "$build/bin/grade_isolated" --reference="$build/bin/grade_ex${nn}_reference" --results-json="$out/runs/ex$nn.json" \
      -- "$build/bin/grade_ex$nn" --seed="$seed" >"$out/logs/ex$nn.log" 2>&1 || true
    reports+=("$out/runs/ex$nn.json")
    # Calls from the student's file into what the reference calls: the answer borrowed, perhaps.
    mine=$(find "$build/tests/CMakeFiles/grade_ex$nn.dir" -path "*$sub/lessons/$lesson/exercises.cpp.o" | head -1)
    theirs=$(find "$build" -path "*shadowlab_ex${nn}_reference.dir*" -name "ex${nn}_reference.cpp.o" | head -1)
    if [ -n "$mine" ] && [ -n "$theirs" ]; then
      comm -12 <(nm -C -u "$mine" | grep -o 'shadowlab::[a-z]*::[a-z][A-Za-z_]*' | grep -v '::grading::' | sort -u) \
               <(nm -C -u "$theirs" | grep -o 'shadowlab::[a-z]*::[a-z][A-Za-z_]*' | sort -u) |
        sed "s|^|ex$nn: exercises.cpp calls the reference library's |" >>"$out/logs/reference_calls.txt" || true
    fi
  else
    echo "grade: lessons/$lesson/exercises.cpp does not compile: its cases score 0 (logs/build_ex$nn.log)"
    cmake --build "$build" -j "$jobs" --target "grade_ex${nn}_reference" >>"$out/logs/build_ex$nn.log" 2>&1
    "$build/bin/grade_ex${nn}_reference" --seed="$seed" --results-json="$out/runs/ex$nn.json" >/dev/null 2>&1 || true
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
    --seed="$seed" --images="$out/images/ex$nn" --results-json="$out/runs/ex${nn}_glsl.json" \
    >"$out/logs/ex${nn}_glsl.log" 2>&1 || true
  reports+=("$out/runs/ex${nn}_glsl.json")
done

[ -s "$out/logs/reference_calls.txt" ] && { echo "grade: look at these calls:"; cat "$out/logs/reference_calls.txt"; }
"$build/bin/grade_report" --out "$out" "${reports[@]}"
