#!/usr/bin/env bash
# The GL-free libraries (core, algorithms, grading, measure) cross-compiled for Windows with
# MinGW-w64 (Debian's g++-mingw-w64-x86-64-posix): no POSIX-only header or call, no glibc-only
# habit may be left in them. Compile-only: Debian ships no Windows builds of spng, assimp or
# embree to link against, so the objects are archived into static libraries (which proves they
# compiled as a whole) but no program is linked or run.
#   mingw.sh SOURCE_ROOT OUT_DIR
# Third-party headers come from a folder of links to Debian's header-only packages, never from
# /usr/include itself (that would pull in glibc's headers). Warnings in our code are errors.
set -euo pipefail
shopt -s nullglob
root=$1
out=$2
cxx=$(command -v x86_64-w64-mingw32-g++-posix || true)
ar=$(command -v x86_64-w64-mingw32-ar || true)
if [[ -z "$cxx" || -z "$ar" ]]; then
  echo "mingw: x86_64-w64-mingw32-g++-posix not installed (make deps installs g++-mingw-w64-x86-64-posix)" >&2
  exit 1
fi
launcher=""
if command -v ccache >/dev/null; then
  launcher=ccache
  export CCACHE_BASEDIR="$root" CCACHE_NOHASHDIR=1
fi

rm -rf "$out"
mkdir -p "$out/include" "$out/obj"
# The header-only parts of the dependencies, as a Windows install (vcpkg) lays them out.
for dir in glm nlohmann doctest assimp embree3; do ln -s "/usr/include/$dir" "$out/include/$dir"; done
ln -s /usr/include/stb/stb_image_write.h "$out/include/stb_image_write.h"
ln -s /usr/include/spng.h "$out/include/spng.h"

flags=(-std=c++20 -O1 -Wall -Wextra -Wno-unused-parameter -Wno-missing-field-initializers -Werror
       -DGLM_FORCE_XYZW_ONLY "-DSHADOWLAB_SOURCE_ROOT=\"C:/shadowlab\"" -I"$root/common" -isystem "$out/include")
declare -A libs=([core]="common/core" [algorithms]="common/algorithms common/algorithms/psm"
                 [grading]="common/grading" [measure]="common/measure")
order=(core algorithms grading measure)

# MinGW brings some POSIX headers MSVC lacks (unistd.h): a file of these libraries that includes
# one must choose it under #ifdef _WIN32 ... #else, or Visual C++ would fail where MinGW passed.
posix_only='^#include <(unistd|spawn|fcntl|dlfcn|pthread|sys/[a-z_]+)\.h>'
unguarded=0
for lib in "${order[@]}"; do
  for dir in ${libs[$lib]}; do
    for src in "$root/$dir"/*.cpp "$root/$dir"/*.hpp; do
      [[ -f "$src" ]] || continue
      if grep -Eq "$posix_only" "$src" && ! grep -q '_WIN32' "$src"; then
        echo "mingw: FAIL ${src#"$root"/} includes a POSIX-only header without a Windows branch:" >&2
        grep -En "$posix_only" "$src" >&2
        unguarded=$((unguarded + 1))
      fi
    done
  done
done

# The flags as a response file, one quoted flag a line, so paths with spaces survive xargs.
for f in "${flags[@]}"; do
  f=${f//\\/\\\\}
  printf '"%s"\n' "${f//\"/\\\"}"
done >"$out/flags.rsp"
export root cxx launcher rsp="$out/flags.rsp"
jobs=()
for lib in "${order[@]}"; do
  for dir in ${libs[$lib]}; do
    for src in "$root/$dir"/*.cpp; do jobs+=("$src" "$out/obj/${lib}__${dir//\//_}_$(basename "${src%.cpp}").o"); done
  done
done
count=$((${#jobs[@]} / 2))
failed=0
# Two at a time (this machine's cores).
printf '%s\0' "${jobs[@]}" | xargs -0 -n 2 -P "${JOBS:-2}" bash -c '
  if ! $launcher "$cxx" "@$rsp" -c "$0" -o "$1" 2>"$1.log"; then
    echo "mingw: FAIL ${0#"$root"/}:" >&2; head -20 "$1.log" >&2; exit 1; fi' || failed=1
if [[ $failed -ne 0 || $unguarded -ne 0 ]]; then
  echo "mingw: not every source of core, algorithms, grading and measure compiles for Windows" >&2
  exit 1
fi
for lib in "${order[@]}"; do "$ar" rcs "$out/libshadowlab_$lib.a" "$out/obj/${lib}__"*.o; done
echo "mingw: $count sources of core, algorithms, grading and measure compile for Windows (x86_64-w64-mingw32, -Werror); libraries in $out"
