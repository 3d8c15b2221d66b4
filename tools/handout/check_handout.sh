#!/usr/bin/env bash
# The student handout's properties, as the tests (tests/handout.cmake) check them:
#   check_handout.sh bodies HANDOUT_DIR      no line of a reference implementation is in the handout
#   check_handout.sh leak WORK_DIR           the check above can fail: a folder holding one
#                                            reference file of each kind must fail it
#   check_handout.sh build TARBALL WORK_DIR  the tarball, unpacked where the full tree is not,
#                                            builds with `make build`, points nowhere into the full
#                                            tree, runs every lesson with impl=reference, and
#                                            passes its own unit and grader-validity tests
#   check_handout.sh grade SUBMISSION OUT_DIR WANT
#                                            grades SUBMISSION with the instructor's grader
#                                            (grade_submission.sh) and checks the grade: WANT=zero
#                                            (every case fails) or WANT=full (every case passes),
#                                            hidden cases among them; SUBMISSION=reference grades
#                                            the reference solutions (exNN_reference.cpp and
#                                            exercises_reference.glsl in the student's places)
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
cd "$root"

# A line as compared: comments and surrounding space dropped, inner space collapsed.
normalize() { sed -E 's|//.*$||; s/^[[:space:]]+//; s/[[:space:]]+$//; s/[[:space:]]+/ /g'; }

# A line's shape, for the GLSL answers: the line as compared, less a leading `return ` or
# declaration (`TYPE NAME = `) and the trailing `;`, with every name that is not called (variables,
# their members) one `_`. An answer copied with other variable names or into a declaration keeps
# its shape (`mat2 turn = mat2(cos(a), ...)` is `return mat2(cos(a), ...)`).
shape() {
  normalize | perl -pe 's/^return //; s/^(const )?[A-Za-z_][A-Za-z0-9_]* [A-Za-z_][A-Za-z0-9_]* = //; s/;$//;
    s/\b[A-Za-z_][A-Za-z0-9_]*\b(?!\s*\()/_/g; s/_(\._)+/_/g'
}
# Shapes specific enough to be an answer, not plumbing: 30 characters or more, four names or more.
answerShapes() { awk 'length($0) >= 30 && gsub(/_/, "_") >= 4'; }

# The reference implementations: the bodies of the functions the reference exercises call
# (tests/grading/exNN_reference.cpp -> common/algorithms), those files' own bodies, and the sealed
# shader files; every line of them long enough to be an answer rather than a brace or a loop head.
referenceFunctions() {
  grep -ohE '\b(lighting|shadow|volume|sampling|psm|soft|hybrid)::[A-Za-z_]+\(' tests/grading/ex*_reference.cpp |
    sed -E 's/.*::([A-Za-z_]+)\(/\1/' | sort -u
}
bodyOf() {  # bodyOf NAME FILE...: the lines inside the braces of NAME's definitions
  awk -v name="$1" '
    !inside && $0 ~ "^[A-Za-z].*[ :*&]" name "\\(" && $0 !~ /;[[:space:]]*$/ { start = 1 }
    start || inside {
      line = $0
      opens = gsub(/\{/, "{", line); closes = gsub(/\}/, "}", line)
      if (inside) print
      depth += opens - closes
      if (opens > 0 && !inside) { inside = 1; start = 0 }
      if (inside && depth <= 0) { inside = 0; depth = 0 }
    }' "${@:2}"
}
oneLinersOf() {  # oneLinersOf NAME FILE...: what is inside the braces of NAME's one-line definitions
  awk -v name="$1" '$0 ~ "^[A-Za-z].*[ :*&]" name "\\(.*\\{.*\\}[[:space:]]*(//.*)?$" {
    line = $0; sub(/[[:space:]]*\/\/.*$/, "", line); sub(/^[^{]*\{/, "", line); sub(/\}[^}]*$/, "", line); print line
  }' "${@:2}"
}
# The GLSL ports of exercises: "FILE NAME" for each shader function (in any tracked shader) named
# like a reference function, or marked as the mirror of one by a trailing `// ns::name` on its
# first line. Their bodies are answers wherever they are, so a shader that holds one must be sealed.
glslAnswers() {
  # shellcheck disable=SC2046
  awk -v names="$(referenceFunctions | tr '\n' ' ')" '
    BEGIN { n = split(names, a, " "); for (i = 1; i <= n; i++) ref[a[i]] = 1 }
    /^[A-Za-z]/ && $0 !~ /;[[:space:]]*$/ && match($0, /[A-Za-z_][A-Za-z0-9_]*\(/) {
      fn = substr($0, RSTART, RLENGTH - 1); mirror = ""
      if (match($0, /\/\/.*::[A-Za-z_]+/)) { mirror = substr($0, RSTART, RLENGTH); sub(/.*::/, "", mirror) }
      if ((fn in ref) || (mirror in ref)) print FILENAME, fn
    }' $(git ls-files 'shaders/*.glsl' 'shaders/*.frag' 'shaders/*.vert' 'shaders/*.geom')
}
fingerprints() {
  local sources sealed f file name
  sources=$(git ls-files 'common/algorithms/*.cpp')
  for f in $(referenceFunctions); do bodyOf "$f" $sources; done >"$work.bodies"
  bodyOf '[A-Za-z_]+' tests/grading/ex*_reference.cpp >>"$work.bodies"
  sealed=$(sed -E 's/#.*//; s/^withheld\s+//; s/^\s+|\s+$//g' tools/handout/sealed_shaders.txt | grep . | sed 's|^|shaders/|')
  # shellcheck disable=SC2086
  { bodyOf '[A-Za-z_]+' $sealed; oneLinersOf '[A-Za-z_]+' $sealed; } >>"$work.bodies"
  # shellcheck disable=SC2086
  { bodyOf '[A-Za-z_]+' $sealed; oneLinersOf '[A-Za-z_]+' $sealed; } >"$work.glsl_bodies"
  glslAnswers | while read -r file name; do
    bodyOf "$name" "$file"
    oneLinersOf "$name" "$file"
  done | tee -a "$work.glsl_bodies" >>"$work.bodies"
  normalize <"$work.bodies" | awk 'length($0) >= 24' | grep -vE '^(for \(|\}|if \(.*\) (continue|break);$)' |
    sort -u | comm -23 - <(allowedLines | normalize | sort -u)
}
allowedLines() { grep -vE '^\s*(#|$)' tools/handout/allowed_lines.txt | sed -E 's/[[:space:]]+#=.*$//'; }
# The GLSL answers' shapes (after fingerprints): found in a handout's text, an answer rewritten.
shapeFingerprints() {
  shape <"$work.glsl_bodies" | answerShapes | sort -u | comm -23 - <(allowedLines | shape | sort -u)
}

# Each line, and the inside of a one-line definition on it (`... { inner }`: what oneLinersOf
# fingerprints), so an answer written on one line is found too.
withInsides() { sed -nE 'p; s/^[^{]*\{ ?(.*[^ ]) ?\}[^{}]*$/\1/p'; }

bodies() {
  local handout=$1 found=0
  work=$handout
  fingerprints >"$handout.fingerprints"
  shapeFingerprints >"$handout.shapes"
  echo "$(wc -l <"$handout.fingerprints") lines of reference implementations and $(wc -l <"$handout.shapes") shapes of GLSL answers to look for"
  while IFS= read -r -d '' f; do
    if grep -qI . "$f" 2>/dev/null; then
      normalize <"$f" | withInsides | sort -u | comm -12 - "$handout.fingerprints" | sed "s|^|${f#"$handout"/}: |"
      shape <"$f" | sort -u | comm -12 - "$handout.shapes" | sed "s|^|${f#"$handout"/}: (shape) |"
    else strings -n 8 "$f" | normalize | withInsides | sort -u | comm -12 - "$handout.fingerprints" | sed "s|^|${f#"$handout"/}: |"; fi
  done < <(find "$handout" -type f -print0) >"$handout.matches"
  found=$(wc -l <"$handout.matches")
  if [ "$found" -gt 0 ]; then
    echo "FAIL: $found reference line(s) in the handout:"
    head -40 "$handout.matches"
    exit 1
  fi
  echo "no reference line in $(find "$handout" -type f | wc -l) files (libraries' strings included)"
}

build() {
  local tarball=$1 work=$2
  rm -rf "$work"
  mkdir -p "$work"
  tar -xzf "$tarball" -C "$work"
  local tree=$work/shadowlab
  [ ! -d "$tree/common/algorithms/psm" ] || [ -z "$(ls "$tree"/common/algorithms/*.cpp 2>/dev/null)" ] ||
    { echo "FAIL: algorithm sources in the handout"; exit 1; }
  (cd "$tree" && make build JOBS="${JOBS:-2}") >"$work/build.log" 2>&1 || { tail -30 "$work/build.log"; exit 1; }
  if grep -rlF "$root" "$tree/build/default" --include=CMakeCache.txt --include=build.ninja \
       --include=compile_commands.json >/dev/null; then
    echo "FAIL: the handout's build refers to the full tree ($root)"
    exit 1
  fi
  local bin=$tree/build/default/bin n=0
  for lesson in "$bin"/lesson_[0-9]*; do
    # impl=reference where the lesson has exercises (an impl parameter).
    local impl=()
    "$lesson" --list-params | grep -q '^impl ' && impl=(--set impl=reference)
    env -u SHADOWLAB_ROOT SHADOWLAB_STRICT_GL=1 "$lesson" --headless --frames 2 --size 320x180 \
      "${impl[@]}" --screenshot "$work/$(basename "$lesson").png" >/dev/null ||
      { echo "FAIL: $(basename "$lesson") does not run in the handout"; exit 1; }
    n=$((n + 1))
  done
  (cd "$tree/build/default" && ctest -L 'unit|validity' -j "${JOBS:-2}" --output-on-failure) >"$work/ctest.log" 2>&1 ||
    { tail -40 "$work/ctest.log"; exit 1; }
  # The student's README and make: no instructor section, and `make handout` says where it works.
  if grep -q '^## Grading a class' "$tree/README.md"; then echo "FAIL: the handout's README has the instructor's section"; exit 1; fi
  local target msg code
  for target in handout gradescope; do
    set +e
    msg=$(make -C "$tree" --no-print-directory $target 2>&1 >/dev/null)
    code=$?
    set -e
    [[ $code -ne 0 && "$msg" == *"the instructor's tree only"* ]] ||
      { echo "FAIL: make $target in the handout: exit $code, '$msg'"; exit 1; }
  done
  echo "the handout built from $tarball, ran $n lessons with impl=reference and passed its $(grep -o '[0-9]* tests passed\|out of [0-9]*' "$work/ctest.log" | tail -1) unit and validity tests"
}

score() {
  local out=$1 want=$2
  local json=$out/score.json
  [ -f "$json" ] || { echo "FAIL: no $json"; exit 1; }
  local points max cases failed hidden
  points=$(grep -m1 '"score"' "$json" | grep -oE '[0-9.]+')
  max=$(grep -m1 '"max_score"' "$json" | grep -oE '[0-9.]+')
  cases=$(grep -m1 '"cases"' "$json" | grep -oE '[0-9]+')
  failed=$(grep -m1 '"cases_failed"' "$json" | grep -oE '[0-9]+')
  hidden=$(grep -o '"hidden_passed": [0-9]*\|"hidden_failed": [0-9]*' "$json" | grep -oE '[0-9]+' | awk '{s += $1} END {print s + 0}')
  echo "score $points / $max, $failed of $cases cases failed, $hidden hidden"
  if [ -n "${LESSONS:-}" ]; then  # one week's assignment: exactly those lessons' exercises graded
    python3 - "$json" "$LESSONS" <<'PY' || { echo "FAIL: the grade is not exactly lessons $LESSONS"; exit 1; }
import json, sys
graded = sorted({e.split(".")[0] for e in json.load(open(sys.argv[1]))["exercises"]})
wanted = sorted({n.zfill(2) for n in sys.argv[2].split(",")})
print(f"lessons graded: {' '.join(graded)}")
sys.exit(graded != wanted)
PY
  fi
  [ "$hidden" -gt 0 ] || { echo "FAIL: no hidden case ran"; exit 1; }
  case $want in
    zero) [ "$failed" = "$cases" ] && awk -v p="$points" 'BEGIN {exit !(p == 0)}' || { explain "$out" true; echo "FAIL: expected 0 points"; exit 1; } ;;
    full) [ "$failed" = 0 ] && awk -v p="$points" -v m="$max" 'BEGIN {exit !(p == m && m > 0)}' || { explain "$out" false; echo "FAIL: expected full marks"; exit 1; } ;;
    *) echo "usage: score OUT_DIR zero|full" >&2; exit 2 ;;
  esac
}

# A failed score names what to replay: the seed (grade_submission.sh's, fixed per assignment), every
# case whose "passed" is not what was wanted, with its grader's output, and a copy of the run that
# the next run of the test does not overwrite.
explain() {
  local out=$1 wrong=$2 keep
  grep -m1 -o 'seed [0-9]*' "$out.log" | sed 's/^seed /replay with SEED=/' || true
  python3 - "$out/runs" "$wrong" <<'PY' || true
import json, pathlib, sys
wrong = sys.argv[2] == "true"
for f in sorted(pathlib.Path(sys.argv[1]).glob("*.json")):
    for run in json.loads(f.read_text()).get("runs", []):
        for c in run.get("cases", []):
            if c.get("passed") == wrong:
                print(f"{f.stem} (seed {run.get('seed')}): {'passed' if wrong else 'failed'}: {c['name']}"
                      f"{' [hidden]' if c.get('hidden') else ''}\n  {c.get('output', '')[:600]}")
PY
  keep=$out.failed-$(date +%Y%m%d-%H%M%S)
  cp -r "$out" "$keep" && cp "$out.log" "$keep/grade.log" && echo "the failing run is kept in $keep"
}

reference_submission() {
  local dir=$1 ref nn lesson
  rm -rf "$dir"
  for ref in tests/grading/ex*_reference.cpp; do
    nn=$(basename "$ref" | sed -E 's/ex([0-9]+)_reference.cpp/\1/')
    lesson=$(basename "$(ls -d lessons/${nn}_*)")
    mkdir -p "$dir/lessons/$lesson"
    cp "$ref" "$dir/lessons/$lesson/exercises.cpp"
  done
  for ref in shaders/*/exercises_reference.glsl; do
    lesson=$(basename "$(dirname "$ref")")
    mkdir -p "$dir/shaders/$lesson"
    cp "$ref" "$dir/shaders/$lesson/exercises.glsl"
  done
}

grade() {
  local submission=$1 out=$2 want=$3
  if [ "$submission" = reference ]; then
    submission=$out.submission
    reference_submission "$submission"
  fi
  # The reference exercises forward to the library's answers: every one of them must be found
  # reaching it (REFERENCE_CALLS=report lists them without scoring them 0); the stubs reach none.
  local calls=zero
  [ "$want" = full ] && calls=report
  REFERENCE_CALLS=$calls bash tools/grading/grade_submission.sh "$submission" "$out" >"$out.log" 2>&1 ||
    { cat "$out.log"; exit 1; }
  grep -m1 '^grade: .*, seed [0-9]*' "$out.log" || true
  tail -3 "$out.log"
  score "$out" "$want"
  reference_calls "$out" "$want"
}

# Exactly the C++ exercises of the graded lessons (full: the reference) or none (zero: the stubs)
# are found reaching the reference answer.
reference_calls() {
  local out=$1 want=$2 expected found nn
  expected=$(for nn in $(sed -nE 's/^ *"([0-9]+)\.[0-9]+": \{$/\1/p' "$out/score.json" | sort -u); do
    grep -ho 'SHADOWLAB_STUB("[0-9.]*")' lessons/${nn}_*/exercises.cpp | grep -o '[0-9][0-9.]*'
  done | sort -u | paste -sd ' ' -)
  found=$(cut -f1 "$out/logs/reference_calls.txt" | sort -u | paste -sd ' ' -)
  [ "$want" = zero ] && expected=""
  [ "$found" = "$expected" ] ||
    { echo "FAIL: exercises found reaching the reference answer: '$found', expected '$expected'"; exit 1; }
  echo "reference calls found: ${found:-none}"
}

leak() {
  local dir=$1/leaky f
  # One reference file of each kind: C++ algorithm, GLSL exercise, C++ reference exercise, sealed
  # shaders (a geometry shader, an include file, a one-line port).
  for f in common/algorithms/lighting.cpp shaders/02_shadow_maps/exercises_reference.glsl \
    shaders/03_shadow_quality/exercises_reference.glsl tests/grading/ex09_reference.cpp \
    shaders/04_shadow_volumes/exercises_reference.glsl shaders/07_hybrid_maps/exercises_reference.glsl \
    shaders/05_soft_shadows/exercises_reference.glsl shaders/08_psm/exercises_reference.glsl \
    shaders/09_psm_fixes/exercises_reference.glsl shaders/10_showdown/exercises_reference.glsl \
    shaders/04_shadow_volumes/volume.geom \
    shaders/common/shadow_bias_slope.glsl shaders/common/soft_answers.glsl; do
    rm -rf "$dir"
    mkdir -p "$dir"
    cp "$f" "$dir/"
    if (bodies "$dir" >/dev/null); then
      echo "FAIL: a handout holding $f passed the check"
      exit 1
    fi
    echo "a handout holding $f fails the check ($(wc -l <"$dir.matches") reference lines found)"
  done
  # An answer written as a one-line definition: exercise 04.5's reference, joined onto one line.
  rm -rf "$dir"
  mkdir -p "$dir"
  grep -vE '^\s*(//|$)' shaders/04_shadow_volumes/exercises_reference.glsl | tr -s '\n ' ' ' >"$dir/one_line.glsl"
  if (bodies "$dir" >/dev/null); then
    echo "FAIL: a handout holding a one-line definition of an answer passed the check: $(cat "$dir/one_line.glsl")"
    exit 1
  fi
  echo "a handout holding an answer on one line fails the check ($(wc -l <"$dir.matches") reference lines found)"
  # Answers rewritten, as shipped shaders once held them readable: exercise 05.4's rotation in a
  # declaration, 05.3's radius for a blocker on the near plane (the search region, operands
  # reordered) and at the mean blocker (the single-sample hull), other variable names each time.
  local line
  while IFS= read -r line; do
    rm -rf "$dir"
    mkdir -p "$dir"
    printf 'float f(float a) {\n%s\n}\n' "$line" >"$dir/rewritten.frag"
    if (bodies "$dir" >/dev/null); then
      echo "FAIL: a handout holding \`$line\` passed the check"
      exit 1
    fi
    echo "a handout holding \`$line\` fails the check"
  done <<'GLSL'
  mat2 turn = mat2(cos(a), sin(a), -sin(a), cos(a));
  float search = min(R * max(r.z - near, 0.0) / (2.0 * tanHalf * near * r.z), uMaxSearch);
  float hull = R * max(r.z - zMean, 0.0) / (zMean * 2.0 * r.z * tanHalf);
GLSL
}

cmd=${1:-}
shift || true
case $cmd in
  bodies) bodies "$@" ;;
  leak) leak "$@" ;;
  build) build "$@" ;;
  grade) grade "$@" ;;
  *) echo "usage: check_handout.sh bodies DIR | build TARBALL WORK | grade SUBMISSION|reference OUT zero|full" >&2; exit 2 ;;
esac
