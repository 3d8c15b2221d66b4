#!/usr/bin/env bash
# build.sh [BUILD_DIR]   (make web)
# The browser build: the lessons of SHADOWLAB_WEB_LESSONS (cmake/web.cmake) as WebGL2 pages in
# BUILD_DIR/site (default build/web/site), with an index page, the READMEs and the slide decks;
# plain static files for any web host.
# Debian's emscripten compiles them; its system libraries are built once into a cache outside the
# build folder (SHADOWLAB_EM_CACHE, default ~/.cache/shadowlab/emscripten: 5-20 minutes the first
# time), so fresh clones and CI reuse it.
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build/web}
mkdir -p "$build"
build=$(cd "$build" && pwd)
command -v emcmake >/dev/null || { echo "make web: emscripten missing; make deps installs it (Debian's package)" >&2; exit 1; }
export EM_FROZEN_CACHE=  # Debian's emscripten freezes its cache in /usr; ours is writable
export EM_CACHE=${SHADOWLAB_EM_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/shadowlab/emscripten}
export NODE_PATH=${NODE_PATH:-/usr/share/nodejs}  # Debian's acorn, for emscripten's JS optimiser
mkdir -p "$EM_CACHE"
[[ -f "$EM_CACHE/sysroot/lib/wasm32-emscripten/libc.a" ]] ||
  echo "make web: building emscripten's system libraries into $EM_CACHE once (5-20 minutes)"
bash tools/wasm/debian-sources.sh "$build/debian-src"
if [[ ! -f "$build/CMakeCache.txt" ]]; then
  emcmake cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DSHADOWLAB_WEB_SOURCES="$build/debian-src" >/dev/null
fi
cmake --build "$build" -j "${JOBS:-$(nproc)}"
# The decks beside the pages (the index links each lesson's): a set already built (SHADOWLAB_SLIDES:
# the tests' own, PDFs included) copied, or built here without the PDFs (figures by the native lessons).
rm -rf "$build/site/slides"
if [[ -n "${SHADOWLAB_SLIDES:-}" ]]; then
  cp -r "$SHADOWLAB_SLIDES" "$build/site/slides"
else
  node tools/slides/build.mjs --bin "${SHADOWLAB_BIN:-build/default/bin}" --out "$build/site/slides" --no-pdf
fi
node tools/wasm/site.mjs --build "$build" --bin "${SHADOWLAB_BIN:-build/default/bin}"
