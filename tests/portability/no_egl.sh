#!/usr/bin/env bash
# The build macOS and Windows get: no EGL (headless runs render from a hidden GLFW window) and no
# pkg-config (every dependency found as a CMake package or as a header and a library, as vcpkg
# provides them). Configures this tree that way into BUILD_DIR, builds lessons 01 and 03, the GL
# layer's tests and lesson_check, then under Xvfb (the hidden window needs a display):
#   - gpu_tests, all of them, on the hidden window's context;
#   - every preset of lessons 01 and 03 against the images the EGL build recorded (tests/data/golden);
#   - without a display, a headless run fails with one line saying what to do.
#   no_egl.sh SOURCE_ROOT BUILD_DIR
set -euo pipefail
root=$1
build=$2
command -v xvfb-run >/dev/null || { echo "no_egl: xvfb-run is not installed (make deps)" >&2; exit 1; }

cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSHADOWLAB_EGL=OFF \
  -DSHADOWLAB_PKG_CONFIG=OFF >"$build.configure.log" 2>&1 || { cat "$build.configure.log" >&2; exit 1; }
grep '^-- shadowlab:' "$build.configure.log"
grep -q 'headless runs through a hidden GLFW window' "$build.configure.log" ||
  { echo "no_egl: FAIL the build did not choose the hidden window" >&2; exit 1; }
if grep -q 'from pkg-config' "$build.configure.log"; then
  echo "no_egl: FAIL a dependency still came from pkg-config" >&2
  exit 1
fi
cmake --build "$build" -j "${JOBS:-2}" --target lesson_01_lighting lesson_03_shadow_quality gpu_tests lesson_check \
  >"$build.build.log" 2>&1 || { tail -40 "$build.build.log" >&2; exit 1; }

bin=$build/bin
xvfb-run -a env SHADOWLAB_EXPECT_PLATFORM="GLFW hidden window" "$bin/gpu_tests"
for lesson in 01_lighting 03_shadow_quality; do
  xvfb-run -a "$bin/lesson_check" "$bin/lesson_$lesson" --all-presets --png "$build/$lesson.png" \
    --golden "$root/tests/data/golden/$lesson" -- --headless --frames 2 --size 320x180 --screenshot "$build/$lesson.png"
done

set +e
err=$(env -u DISPLAY -u WAYLAND_DISPLAY "$bin/lesson_01_lighting" --headless --frames 1 2>&1 >/dev/null)
code=$?
set -e
if [[ $code -ne 1 || "$err" != *"headless runs need a display too"*"xvfb-run"* ]]; then
  echo "no_egl: FAIL without a display: exit $code, expected 1 with what to do; stderr: $err" >&2
  exit 1
fi
echo "no_egl: without a display: exit 1, '$(tail -1 <<<"$err")'"
echo "no_egl: the build without EGL and pkg-config renders lessons 01 and 03 as the EGL build does"
