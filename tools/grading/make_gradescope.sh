#!/usr/bin/env bash
# make gradescope [LESSONS=03,05] [GRADESCOPE=OUT_DIR]
#
# Builds the Gradescope autograder: OUT_DIR (default out/gradescope)/shadowlab-autograder.zip, or
# shadowlab-autograder-03-05.zip for one assignment's lessons. Upload it as a "Zip file upload"
# autograder on an Ubuntu image. Inside: setup.sh (installs the packages, prebuilds the graders),
# run_autograder (places the student's files, grades them, writes results.json), autograder.py,
# lessons.txt and shadowlab/, this tree as git tracks it, hidden cases and references included (an
# autograder is the instructor's: students never see it).
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
out=${1:-$root/out/gradescope}
[[ "$out" = /* ]] || out=$PWD/$out
lessons=$(bash "$root/tools/grading/grade_submission.sh" --lessons)  # checked: a bad list stops here
name=shadowlab-autograder${lessons:+-${lessons//,/-}}
pkg=$out/$name
rm -rf "$pkg" "$pkg.zip"
mkdir -p "$pkg/shadowlab"
cp "$root"/tools/grading/gradescope/{setup.sh,run_autograder,autograder.py} "$pkg/"
echo "$lessons" >"$pkg/lessons.txt"
(cd "$root" && git ls-files -z | while IFS= read -r -d '' f; do [ -e "$f" ] && printf '%s\0' "$f"; done |
  tar --null -T - -cf -) | tar -xf - -C "$pkg/shadowlab"
(cd "$pkg" && zip -qr "../$name.zip" .)
echo "gradescope: $pkg.zip ($(du -h "$pkg.zip" | cut -f1), lessons ${lessons:-every lesson with exercises})"
