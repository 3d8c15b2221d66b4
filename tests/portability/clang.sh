#!/usr/bin/env bash
# The whole tree (libraries, lessons, tools, tests) compiled and linked by clang with warnings as
# errors: no GCC-only habit (clang 14 cannot capture a structured binding in a lambda, which
# doctest's INFO does). Unoptimised and without debug information: clang's warnings come from its
# front end, so that costs no check and keeps a cold build to a few minutes.
#   clang.sh SOURCE_ROOT BUILD_DIR
set -euo pipefail
root=$1
build=$2
command -v clang++ >/dev/null || { echo "clang: clang++ is not installed (make deps)" >&2; exit 1; }
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE= -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
  "-DCMAKE_CXX_FLAGS=-O0 -g0 -Werror" >"$build.configure.log" 2>&1 || { cat "$build.configure.log" >&2; exit 1; }
if ! cmake --build "$build" -j "${JOBS:-2}" -- -k 0 >"$build.build.log" 2>&1; then
  grep -E "error:|FAILED:" "$build.build.log" | head -40 >&2
  echo "clang: the tree does not compile with clang -Werror (the whole log: $build.build.log)" >&2
  exit 1
fi
echo "clang: $(grep -c 'Building CXX' "$build.build.log" || true) sources compiled by $(clang++ --version | head -1), -Wall -Wextra -Werror"
