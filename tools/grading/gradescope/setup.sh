#!/usr/bin/env bash
# Gradescope runs this once, as root, when it builds the autograder's image (this folder is
# /autograder/source): installs what grading needs from the distribution's packages
# (tools/install-deps.sh grading; SHADOWLAB_SKIP_APT=1 skips it where they are there already),
# then grades the untouched stubs once, which builds the course library, the graders and the
# lessons the GLSL graders render: a submission's run then compiles only the student's files.
set -euo pipefail
src=$(cd "$(dirname "$0")" && pwd)
root=${AUTOGRADER_ROOT:-$(dirname "$src")}
[ -n "${SHADOWLAB_SKIP_APT:-}" ] || bash "$src/shadowlab/tools/install-deps.sh" grading
chmod +x "$src/run_autograder"
rm -rf "$root/staged"
mkdir -p "$root/staged"  # empty: every file graded as the untouched stub
lessons=$(cat "$src/lessons.txt")
cd "$src/shadowlab"
LESSONS=$lessons bash tools/grading/grade_submission.sh "$root/staged" "$root/prebuild" \
  >"$root/prebuild.log" 2>&1 || { tail -n 60 "$root/prebuild.log"; echo "setup.sh: the prebuild failed" >&2; exit 1; }
tail -n 1 "$root/prebuild.log"
echo "shadowlab autograder ready: lessons ${lessons:-every lesson with exercises}"
