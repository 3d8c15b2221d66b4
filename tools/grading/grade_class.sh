#!/usr/bin/env bash
# make grade-class SUBMISSIONS=DIR [LESSONS=03,05] [GRADES=OUT] [PARALLEL=2]
#
# Grades a class: every entry of DIR is one student's submission, a folder or an archive (.zip,
# .tar.gz, .tgz, .tar), named after the student. Each is placed as the Gradescope autograder
# places files (a handout tree at any depth, or flat exercise files: gradescope/autograder.py),
# graded by grade_submission.sh in a build folder of its own (ccache makes the second and later
# cheap), PARALLEL at a time (default 2, this machine's cores), each C++ exercise with the time
# limit. Writes OUT (default out/grades/class): STUDENT/ (each grade: score.json, results.json,
# logs/, placement.txt), class.csv (points per exercise per student) and class.html (the same, the
# cases most students fail with their messages, and the submissions that did not compile).
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
usage="usage: grade_class.sh SUBMISSIONS_DIR [OUT_DIR]"
[ $# -ge 1 ] || { echo "$usage" >&2; exit 2; }
subs=$1 out=${2:-$root/out/grades/class}
[[ "$subs" = /* ]] || subs=$PWD/$subs
[[ "$out" = /* ]] || out=$PWD/$out
[ -d "$subs" ] || { echo "grade_class.sh: no folder of submissions '$1'; $usage" >&2; exit 2; }
lessons=$(bash "$root/tools/grading/grade_submission.sh" --lessons)  # checked here, once
parallel=${PARALLEL:-2}
rm -rf "$out"
mkdir -p "$out"

# One student: unpack, place, grade. Never fails the class run: a failure is that student's row.
grade_one() {
  local entry=$1 name dir raw
  name=$(basename "$entry")
  name=${name%.zip} name=${name%.tar.gz} name=${name%.tgz} name=${name%.tar}
  dir=$out/$name
  raw=$dir/submission
  mkdir -p "$raw" "$dir/staged"
  case $entry in
    *.zip) unzip -q "$entry" -d "$raw" ;;
    *.tar.gz | *.tgz | *.tar) tar -xf "$entry" -C "$raw" ;;
    *) [ -d "$entry" ] && cp -r "$entry/." "$raw/" ;;
  esac || echo "could not unpack $(basename "$entry")" >"$dir/unpack_failed"
  python3 "$root/tools/grading/gradescope/autograder.py" place "$raw" "$dir/staged" "$root" "$lessons" >"$dir/placement.txt"
  if GRADE_BUILD=$out/.build/$name JOBS=1 LESSONS=$lessons SEED=${SEED:-} \
    bash "$root/tools/grading/grade_submission.sh" "$dir/staged" "$dir/grade" >"$dir/grade.log" 2>&1; then
    echo "graded $name: $(tail -n 1 "$dir/grade.log" | cut -d';' -f1)"
  else
    echo "FAILED to grade $name (see $dir/grade.log)"
  fi
  rm -rf "$out/.build/$name"  # hundreds of MB each; ccache keeps what the next one reuses
}
export -f grade_one
export root out lessons

n=$(find "$subs" -mindepth 1 -maxdepth 1 ! -name '.*' | wc -l)
[ "$n" -gt 0 ] || { echo "grade_class.sh: $subs holds no submissions" >&2; exit 2; }
echo "grade-class: $n submissions, lessons ${lessons:-every lesson with exercises}, $parallel at a time"
find "$subs" -mindepth 1 -maxdepth 1 ! -name '.*' -print0 | sort -z |
  xargs -0 -n 1 -P "$parallel" bash -c 'grade_one "$0"'
rm -rf "$out/.build"
python3 "$root/tools/grading/class_report.py" "$out"
