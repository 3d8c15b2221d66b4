#!/usr/bin/env bash
# check_grade_class.sh WORK_DIR  (grading.grade_class)
#
# make grade-class on a class of three, LESSONS=01, each entry a different shape:
#   alice/        a folder with the crash fixture as a flat exercises.cpp: 10 of 40 (01.1 right)
#   bob.zip       a handout tree, nested, with lesson 01's reference forwarders: 0, every exercise
#                 reported as borrowing the reference answer
#   carol.tar.gz  an exercises.cpp that does not compile: 0, reported as not compiling
# class.csv must hold exactly those rows and class.html the three problems and the cases most
# students fail.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
work=$1
rm -rf "$work"
mkdir -p "$work/subs/alice" "$work/bob/shadowlab-student/lessons/01_lighting" "$work/carol"
cp "$root/tests/grading/fixtures/faulty_ex01/exercises.cpp" "$work/subs/alice/"
cp "$root/tests/grading/ex01_reference.cpp" "$work/bob/shadowlab-student/lessons/01_lighting/exercises.cpp"
(cd "$work/bob" && zip -qr ../subs/bob.zip .)
printf '#include "exercises.hpp"\nnamespace shadowlab::ex01 {\nfloat attenuation(const glm::vec3& c, float d) { return c.x + ; }\n}\n' \
  >"$work/carol/exercises.cpp"
tar -czf "$work/subs/carol.tar.gz" -C "$work/carol" .
LESSONS=01 GRADE_TIMEOUT=5 bash "$root/tools/grading/grade_class.sh" "$work/subs" "$work/out"

expected='student,score,max_score,01.1,01.2,01.3,01.4,problems
alice,10,40,10,0,0,0,
bob,0,40,0,0,0,0,01.1 borrowed the reference answer; 01.2 borrowed the reference answer; 01.3 borrowed the reference answer; 01.4 borrowed the reference answer
carol,0,40,0,0,0,0,lesson 01'"'"'s exercises.cpp did not compile'
got=$(tr -d '\r' <"$work/out/class.csv")
[ "$got" = "$expected" ] || { printf 'FAIL: class.csv is\n%s\nexpected\n%s\n' "$got" "$expected"; exit 1; }
for text in "Class grades: 3 submissions" "carol: lesson 01&#x27;s exercises.cpp did not compile" \
  "bob: 01.1 borrowed the reference answer" "did not finish within 5 s (the time limit)"; do
  grep -qF "$text" "$work/out/class.html" || { echo "FAIL: class.html does not say '$text'"; exit 1; }
done
[ ! -e "$work/out/.build" ] || { echo "FAIL: the per-student build folders were left behind"; exit 1; }
echo "grade-class: three submissions of three shapes graded, class.csv and class.html as expected"
