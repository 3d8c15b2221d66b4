#!/usr/bin/env bash
# install-deps.sh [grading]
# Installs the Debian/Ubuntu packages shadowlab builds and tests with, and only the missing ones.
# Prints what it installs. Uses sudo when not root. Safe to run on every `make`.
# grading: only what grading submissions needs (the Gradescope autograder's setup.sh): the build,
# the libraries, Mesa's software renderer for the GLSL graders, binutils and python3.
set -euo pipefail

grading=(
  build-essential cmake ninja-build pkg-config binutils python3 ccache
  libglfw3-dev libglm-dev libimgui-dev libstb-dev libspng-dev doctest-dev libepoxy-dev
  libegl-dev libgl-dev libegl-mesa0 libgl1-mesa-dri libgles-dev
  libembree-dev nlohmann-json3-dev libassimp-dev
)
packages=(
  build-essential cmake ninja-build pkg-config
  libglfw3-dev libglm-dev libimgui-dev libstb-dev libspng-dev doctest-dev libepoxy-dev
  libegl-dev libgl-dev libegl-mesa0 libgl1-mesa-dri libgles-dev
  libembree-dev nlohmann-json3-dev
  ccache  # compiler cache: the handout and grading tests compile the tree again (CMakeLists.txt)
  libassimp-dev  # model files (OBJ + MTL, glTF 2.0): --model, scene=model
  glslang-tools xvfb xauth
  clang-format  # the tree's one C++ style, checked by the test format.check
  clang libclang-rt-dev  # libFuzzer targets (tests/fuzz): make fuzz, and a short run in make test
  chromium nodejs npm  # slides and HTML reports, tested in headless Chromium
  g++-mingw-w64-x86-64-posix  # the GL-free libraries cross-compiled for Windows (portability.mingw)
  emscripten dpkg-dev  # the lessons in the browser (make web); dpkg-source unpacks Debian's sources for it
)

case ${1:-} in
  "") ;;
  grading) packages=("${grading[@]}") ;;
  *) echo "install-deps: unknown profile '$1'; valid: grading (or none: everything)" >&2; exit 2 ;;
esac

if ! command -v dpkg-query >/dev/null || ! command -v apt-get >/dev/null; then
  echo "install-deps: no apt-get here; install these yourself (see vcpkg.json): ${packages[*]}" >&2
  exit 0
fi

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$p")
done
# A working node and npm is what matters, wherever they came from (nodesource, nvm, Debian).
if command -v node >/dev/null && command -v npm >/dev/null; then
  missing=($(printf '%s\n' "${missing[@]}" | grep -vx -e nodejs -e npm || true))
fi
[[ ${#missing[@]} -eq 0 ]] && exit 0

sudo=""
if [[ $(id -u) -ne 0 ]]; then
  command -v sudo >/dev/null || { echo "install-deps: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
  sudo="sudo"
fi
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
