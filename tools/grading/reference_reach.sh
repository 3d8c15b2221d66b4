#!/usr/bin/env bash
# reference_reach.sh STUDENT_OBJECT REFERENCE_OBJECT STUB_SOURCE LIBRARY...
#
# Which of a student's exercise functions reach the reference answer: prints one line per such
# exercise, "NN.k<TAB>why", nothing when none does. Decided by the linker, not by grepping
# names: for each exercise function the student's object is linked alone against the course's
# libraries (LIBRARY..., built with -ffunction-sections) with that function as the only root and
# --gc-sections, so the link map keeps exactly the library functions it can reach, directly or
# through any function it calls. If that includes a function the reference implementation of the
# same exercise calls (read from REFERENCE_OBJECT's relocations, shadowlab:: functions outside the
# exNN and grading namespaces), the exercise borrowed its answer. STUB_SOURCE (the untouched
# exercises.cpp) says which function is which exercise (its SHADOWLAB_STUB("NN.k") markers).
# GNU toolchains (binutils' readelf and nm, ld's -Map); the grading machines are Linux.
# Exit 0 (whatever it found), 1 when a link failed (its exercise was not checked), 2 on bad usage or
# a missing file.
set -euo pipefail
[ $# -ge 4 ] || { echo "usage: reference_reach.sh STUDENT_OBJECT REFERENCE_OBJECT STUB_SOURCE LIBRARY..." >&2; exit 2; }
student=$1 reference=$2 stubs=$3
shift 3
for f in "$student" "$reference" "$stubs" "$@"; do
  [ -f "$f" ] || { echo "reference_reach.sh: no file '$f'" >&2; exit 2; }
done
cxx=${CXX:-c++}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# Exercise of each function name, from the stubs: "slopeScaledBias 03.1".
awk '/^[A-Za-z].*[A-Za-z_0-9]+\(/ { line = $0; sub(/\(.*/, "", line); n = split(line, w, /[^A-Za-z_0-9]+/); name = w[n] }
     /SHADOWLAB_STUB\("/ { match($0, /SHADOWLAB_STUB\("[0-9]+\.[0-9]+"/); print name, substr($0, RSTART + 16, RLENGTH - 17) }' \
  "$stubs" >"$work/exercises"

# The functions each reference exercise function calls: "mangled_exercise_function mangled_callee".
readelf -rW "$reference" | awk '
  /^Relocation section / { sec = $3; gsub(/\047/, "", sec); sub(/^\.rela\.text\./, "", sec); fn = (sec ~ /^_ZN9shadowlab4ex[0-9]+/) ? sec : ""; next }
  fn != "" && $5 ~ /^_ZN9shadowlab/ && $5 !~ /^_ZN9shadowlab4ex[0-9]+/ && $5 !~ /^_ZN9shadowlab7grading/ { print fn, $5 }' |
  sort -u >"$work/answers"

name_of() { c++filt "$1" | sed -E 's/\(.*//; s/.*:://'; }

nm --defined-only "$student" | awk '$2 == "T" && $3 ~ /^_ZN9shadowlab4ex[0-9]+/ { print $3 }' | sort -u |
  while read -r fn; do
    name=$(name_of "$fn")
    id=$(awk -v n="$name" '$1 == n { print $2; exit }' "$work/exercises")
    [ -n "$id" ] || continue
    callees=$(awk -v f="$fn" '$1 == f { print $2 }' "$work/answers")
    [ -n "$callees" ] || continue
    map=$work/$id.map
    # The usual start files (they define what static objects need, such as __dso_handle) but the
    # exercise function as the entry: main is never linked, so nothing else is a root.
    "$cxx" -o "$work/$id.out" "$student" "$@" -Wl,--gc-sections -Wl,-e,"$fn" \
      -Wl,--unresolved-symbols=ignore-all -Wl,-Map,"$map" >"$work/$id.log" 2>&1 || {
      echo "reference_reach.sh: the link for $id failed: $(head -c 600 "$work/$id.log")" >&2
      touch "$work/failed"
      continue
    }
    # The map lists the discarded sections first, then the kept ones ("Linker script and memory map").
    kept=$(sed -n '/^Linker script and memory map/,$p' "$map")
    for callee in $callees; do
      if grep -qF ".text.$callee" <<<"$kept"; then
        printf '%s\tyour %s reaches %s, which the reference answer of exercise %s calls: borrowing the answer scores the exercise 0 (write it yourself; found by linking your function alone against the course library)\n' \
          "$id" "$name" "$(c++filt "$callee")" "$id"
        break
      fi
    done
  done
# A link that failed decided nothing: say so (the caller reports it) rather than pass in silence.
[ ! -e "$work/failed" ] || exit 1
