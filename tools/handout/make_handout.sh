#!/usr/bin/env bash
# make handout [HANDOUT=DIR]: the student tree, DIR/shadowlab and DIR/shadowlab-student.tar.gz
# (default DIR: out/handout). It builds and runs with the same two commands as this tree (make run,
# make test), every lesson works with impl=reference, and no reference implementation is there
# as source:
#   - the taught algorithms (common/algorithms), the reference exercises (tests/grading/exNN_
#     reference.cpp) and the sealed shader files (tools/handout/sealed_shaders.txt) are compiled
#     into lib/*.a (optimised as make build, debug information stripped; the shaders obscured, see
#     core/sealed_files.hpp), their source left out;
#   - the reference GLSL of the GLSL exercises is withheld (`withheld` in sealed_shaders.txt): in
#     no form in the handout; the reference's side of their public cases and renders is recorded
#     here instead (grade_exNN_glsl --record-reference, into tests/grading/glsl/reference/), and
#     in the lessons the student's exercises.glsl stands in for it, which the banner says;
#   - tools/handout/exclude.txt lists what else stays in the instructor's tree: the hidden cases,
#     the references' own unit tests, this script and the submission grader.
# The GLSL recordings use this tree's build (SHADOWLAB_BUILD, else build/default), built first.
# Only files git tracks go in (no build folders, no node_modules).
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
out=${1:-$root/out/handout}
mkdir -p "$out"
out=$(cd "$out" && pwd)
tree=$out/shadowlab
libbuild=$root/build/handout-lib
cd "$root"

# ---- 1. the libraries ---------------------------------------------------------------------------
echo "handout: building the prebuilt libraries in $libbuild"
# RelWithDebInfo as make build (the debug information is stripped below): the same compiles as
# build/default, so with ccache (CMakeLists.txt) these are cache hits.
cmake -S "$root" -B "$libbuild" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSHADOWLAB_UNIT_ONLY=ON >/dev/null
refs=$(ls tests/grading/ex*_reference.cpp | sed -E 's|.*/ex([0-9]+)_reference\.cpp|shadowlab_ex\1_reference|')
# shellcheck disable=SC2086
cmake --build "$libbuild" --target shadowlab_algorithms shadowlab_sealed $refs >/dev/null

# ---- 2. the tree: tracked files minus the exclusions ------------------------------------------
patterns=()
while IFS= read -r line; do
  line=${line%%#*}
  line=$(echo "$line" | xargs)
  [ -n "$line" ] && patterns+=("$line")
done < tools/handout/exclude.txt
while IFS= read -r line; do
  line=${line%%#*}
  line=$(echo "$line" | xargs)
  line=${line#withheld }
  [ -n "$line" ] && patterns+=("shaders/$(echo "$line" | xargs)")
done < tools/handout/sealed_shaders.txt

excluded() {
  local f=$1 p
  for p in "${patterns[@]}"; do
    # shellcheck disable=SC2053
    [[ $f == $p ]] && return 0
  done
  return 1
}

rm -rf "$tree"
mkdir -p "$tree/lib"
kept=0 left=0
while IFS= read -r -d '' f; do
  [ -e "$f" ] || continue  # deleted in the working tree
  if excluded "$f"; then
    left=$((left + 1))
    continue
  fi
  mkdir -p "$tree/$(dirname "$f")"
  cp -p "$f" "$tree/$f"
  kept=$((kept + 1))
done < <(git ls-files -z)

# The README is the student's: the instructor's section (grading a class) stays in this tree.
awk '/^## Grading a class/ {skip = 1; next} /^## / {skip = 0} !skip' README.md >"$tree/README.md"
grep -q '^## Grading a class' "$tree/README.md" && { echo "handout: the README kept its instructor section" >&2; exit 1; }

# ---- 3. the libraries into lib/, without debug information ------------------------------------
for t in shadowlab_algorithms shadowlab_sealed $refs; do
  a=$(find "$libbuild" -name "lib$t.a" | head -1)
  [ -n "$a" ] || { echo "handout: lib$t.a was not built" >&2; exit 1; }
  cp "$a" "$tree/lib/"
  strip --strip-debug "$tree/lib/lib$t.a"
done
cat > "$tree/lib/README.md" <<'TXT'
# Prebuilt libraries of the student handout

The course's reference implementations, compiled: `libshadowlab_algorithms.a` (common/algorithms:
the lighting model, shadow-map maths, shadow volumes, texture sampling, PSM), the reference
exercises `libshadowlab_exNN_reference.a` (the graders' proof of validity and the GLSL graders'
lesson builds) and `libshadowlab_sealed.a` (the reference GLSL, which the shader preprocessor finds
when the file is absent). CMake links them instead of the sources, which this handout leaves out.
Built for Debian 12 / Ubuntu 22.04+ (x86-64, GCC's libstdc++).
TXT

# ---- 3b. the reference's side of the GLSL exercises, which the handout withholds ----------------
build=${SHADOWLAB_BUILD:-$root/build/default}
recorded=$tree/tests/grading/glsl/reference
glsl_targets=()
for cases in tests/grading/glsl/ex*_glsl.cpp; do
  nn=$(basename "$cases" | sed -E 's/ex([0-9]+)_glsl.cpp/\1/')
  glsl_targets+=("grade_ex${nn}_glsl")
done
echo "handout: recording the reference GLSL's values and renders with $build"
cmake --build "$build" --target "${glsl_targets[@]}" >/dev/null
for target in "${glsl_targets[@]}"; do
  nn=${target#grade_ex}
  nn=${nn%_glsl}
  lesson=$(basename "$(ls -d lessons/"${nn}"_*)")
  env -u SHADOWLAB_ROOT -u SHADOWLAB_SEED "$build/bin/$target" --lesson-binary="$build/bin/glsl_lesson_$lesson" \
    --record-reference="$recorded" >/dev/null
done
cat > "$recorded/README.md" <<'TXT'
# The reference side of the GLSL exercises, precomputed

This handout does not contain the reference GLSL of the exercises. The instructor's tree recorded
what it computes for every public case and render (`make handout`): `NN_name.json` (the values, and
which render is which) and `NN_name/render_K.png` with its ground-truth figures (`render_K.json`).
`make grade LESSON=NN` and the lesson's exercises panel compare your exercises.glsl with these. They
were recorded at the default seed: grade without `--seed` or `SHADOWLAB_SEED`.
TXT

# ---- 4. the tarball ---------------------------------------------------------------------------
tar -czf "$out/shadowlab-student.tar.gz" -C "$out" shadowlab
echo "handout: $tree ($kept files, $left left out, $(du -sh "$tree" | cut -f1)); $out/shadowlab-student.tar.gz ($(du -h "$out/shadowlab-student.tar.gz" | cut -f1))"
