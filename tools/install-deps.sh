#!/usr/bin/env bash
# Installs the Debian/Ubuntu packages shadowlab builds and tests with, and only the missing ones.
# Prints what it installs. Uses sudo when not root. Safe to run on every `make`.
#   tools/install-deps.sh            build + test packages
#   tools/install-deps.sh --slides   also what `make slides` needs (Chromium, Node.js/npm)
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config
  libglfw3-dev libglm-dev libimgui-dev libstb-dev doctest-dev libepoxy-dev
  libegl-dev libgl-dev libegl-mesa0 libgl1-mesa-dri libgles-dev
  libembree-dev libtinyobjloader-dev nlohmann-json3-dev
  glslang-tools xvfb xauth
)
if [[ "${1:-}" == "--slides" ]]; then packages+=(chromium nodejs npm); fi

if ! command -v dpkg-query >/dev/null || ! command -v apt-get >/dev/null; then
  echo "install-deps: no apt-get here; install these yourself (see vcpkg.json): ${packages[*]}" >&2
  exit 0
fi

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$p")
done
# nodejs ships npm on some distributions; a working npm is what matters.
if [[ " ${missing[*]} " == *" npm "* ]] && command -v npm >/dev/null; then
  missing=("${missing[@]/npm}")
fi
missing=($(printf '%s\n' "${missing[@]}" | grep -v '^$' || true))
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
