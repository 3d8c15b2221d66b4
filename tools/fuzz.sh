#!/usr/bin/env bash
# Runs every libFuzzer target of build/fuzz for a fixed number of executions (make fuzz) and prints,
# per target: executions, seconds, executions a second, the corpus it ended with (units/size, as
# libFuzzer counts it), and whether it found anything. New inputs land in build/fuzz/fuzz-corpus/NAME; a crash, leak, timeout or broken
# invariant is kept as build/fuzz/findings/NAME/crash-* (add it to tests/fuzz/NAME/regressions
# once fixed). Exit 1 on any finding.
#   tools/fuzz.sh BUILD_DIR RUNS [TARGET...]
set -uo pipefail
source "$(dirname "$0")/script_args.sh"
check_script_args -- "$@"
build=${1:?usage: tools/fuzz.sh BUILD_DIR RUNS [TARGET...]}
runs=${2:?usage: tools/fuzz.sh BUILD_DIR RUNS [TARGET...]}
shift 2
root=$(cd "$(dirname "$0")/.." && pwd)
targets=("$@")
if [[ ${#targets[@]} -eq 0 ]]; then
  for t in "$build"/bin/fuzz_*; do targets+=("$(basename "$t" | sed 's/^fuzz_//')"); done
fi
failed=0
printf '%-14s %12s %9s %8s %14s  %s\n' target executions seconds exec/s "corpus (units)" result
for name in "${targets[@]}"; do
  work="$build/fuzz-corpus/$name"
  findings="$build/findings/$name"
  mkdir -p "$work" "$findings"
  corpus=("$root/tests/fuzz/$name/seeds")
  [[ -d "$root/tests/fuzz/$name/regressions" ]] && corpus+=("$root/tests/fuzz/$name/regressions")
  log="$build/findings/$name.log"
  start=$(date +%s.%N)
  ASAN_OPTIONS=detect_leaks=1 LSAN_OPTIONS=suppressions="$root/tests/lsan.supp" "$build/bin/fuzz_$name" -runs="$runs" -seed=1 -timeout=10 -rss_limit_mb=2048 \
    -print_final_stats=1 -artifact_prefix="$findings/" "$work" "${corpus[@]}" >"$log" 2>&1
  status=$?
  seconds=$(echo "$(date +%s.%N) - $start" | bc)
  executions=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$')
  corpus_size=$(grep -o 'DONE .*corp: [0-9]*/[0-9]*[a-zA-Z]*' "$log" | tail -1 | grep -o '[0-9]*/[0-9]*[a-zA-Z]*$')
  result=ok
  if [[ $status -ne 0 ]] || grep -qE 'ERROR: libFuzzer|SUMMARY: .*Sanitizer|FUZZ_CHECK failed' "$log"; then
    result="FINDING (see $log)"
    failed=1
  fi
  rate=$(echo "${executions:-0} / $seconds" | bc)
  printf '%-14s %12s %9.1f %8s %14s  %s\n' "$name" "${executions:-?}" "$seconds" "$rate" "${corpus_size:-?}" "$result"
done
exit $failed
