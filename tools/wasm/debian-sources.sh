#!/usr/bin/env bash
# debian-sources.sh DIR
# The C and C++ sources the browser build compiles with emscripten, from Debian's own source
# packages (the versions the native build links): Dear ImGui, libspng and zlib. apt-get runs with
# its own source list, package lists and cache under DIR, so the system's apt configuration is not
# touched and no deb-src line is needed there (DEBIAN_MIRROR overrides deb.debian.org). Unpacked
# into DIR/imgui, DIR/spng, DIR/zlib; a second run with the sources in place does nothing.
set -euo pipefail
dir=${1:?usage: debian-sources.sh DIR}
mkdir -p "$dir"
dir=$(cd "$dir" && pwd)

# name in DIR, Debian source package, version (the binary packages' source version on Debian 12)
sources=(
  "imgui imgui 1.86+ds-1"
  "spng libspng 0.7.3-3"
  "zlib zlib 1:1.2.13.dfsg-1"
)
missing=0
for s in "${sources[@]}"; do read -r name _ _ <<<"$s"; [[ -f "$dir/$name/.unpacked" ]] || missing=1; done
[[ $missing -eq 0 ]] && exit 0

command -v apt-get >/dev/null || { echo "debian-sources: needs apt-get (Debian or Ubuntu)" >&2; exit 1; }
command -v dpkg-source >/dev/null || { echo "debian-sources: needs dpkg-source (package dpkg-dev)" >&2; exit 1; }
apt="$dir/apt"
mkdir -p "$apt/lists/partial" "$apt/parts" "$apt/cache/archives/partial" "$dir/download"
suite=$(. /etc/os-release && echo "${VERSION_CODENAME:-bookworm}")
echo "deb-src ${DEBIAN_MIRROR:-http://deb.debian.org/debian} $suite main" >"$apt/sources.list"
opts=(-o "Dir::Etc::SourceList=$apt/sources.list" -o "Dir::Etc::SourceParts=$apt/parts"
      -o "Dir::State::Lists=$apt/lists" -o "Dir::Cache=$apt/cache" -o Debug::NoLocking=1
      -o APT::Sandbox::User="$(id -un)")
echo "debian-sources: fetching Debian's source packages for the browser build into $dir"
apt-get "${opts[@]}" -qq update
for s in "${sources[@]}"; do
  read -r name package version <<<"$s"
  [[ -f "$dir/$name/.unpacked" ]] && continue
  rm -rf "$dir/$name" "$dir/download"/*
  (cd "$dir/download" && apt-get "${opts[@]}" -qq source --download-only "$package=$version")
  dpkg-source --no-check -x "$dir/download"/*.dsc "$dir/$name" >/dev/null
  touch "$dir/$name/.unpacked"
  echo "debian-sources: $package $version -> $dir/$name"
done
rm -rf "$dir/download" "$dir"/*.orig.tar.* "$dir"/*.debian.tar.* "$dir"/*.dsc
