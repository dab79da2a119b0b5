#!/usr/bin/env bash
# Run each libFuzzer harness of the fuzz build (tests/fuzz/README.md) for SECONDS (default 60) on a
# copy of its corpus (tests/fuzz/corpus/<harness>/, which stays untouched), SOMA_FUZZ_JOBS harnesses
# at a time (default 2: the CI machine's cores). Fails on a finding — a crash, a sanitizer report, an
# exception other than soma::InvalidInput, a differential disagreement, a hang (-timeout) or memory
# beyond -rss_limit_mb — and prints the input's path; add it to the corpus as a regression test
# (README.md). Needs the fuzz build: cmake --preset fuzz && cmake --build --preset fuzz --target soma_fuzz
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
jobs=${SOMA_FUZZ_JOBS:-2}
build=build/fuzz/tests/fuzz
harnesses=(robot urdf pose platform planar_scene scene sweep differential)
work=$(mktemp -d "${TMPDIR:-/tmp}/soma-fuzz.XXXXXX")
for h in "${harnesses[@]}"; do
  if [ ! -x "$build/fuzz_$h" ]; then
    echo "fuzz.sh: $build/fuzz_$h is not built (cmake --preset fuzz && cmake --build --preset fuzz --target soma_fuzz)" >&2
    exit 1
  fi
done

# One harness: its corpus copied, its findings in $work/<harness>/findings/, its log in $work/<harness>/log.
run() {
  local h=$1 dir=$work/$1
  mkdir -p "$dir/corpus" "$dir/findings"
  cp tests/fuzz/corpus/"$h"/* "$dir/corpus/"
  # stdin from /dev/null: a scene naming /dev/stdin as a file must not wait for a terminal.
  if "$build/fuzz_$h" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=16384 \
      -print_final_stats=1 -artifact_prefix="$dir/findings/" "$dir/corpus" </dev/null >"$dir/log" 2>&1; then
    echo ok >"$dir/status"
  else
    echo finding >"$dir/status"
  fi
}

running=0
for h in "${harnesses[@]}"; do
  run "$h" &
  running=$((running + 1))
  if [ "$running" -ge "$jobs" ]; then
    wait -n || true
    running=$((running - 1))
  fi
done
wait

failed=0
for h in "${harnesses[@]}"; do
  dir=$work/$h
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$dir/log" | tail -1)
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$dir/log" | tail -1)
  files=$(find "$dir/corpus" -type f | wc -l)
  if [ "$(cat "$dir/status")" = ok ]; then
    echo "fuzz: $h: ${execs:-?} executions in ${seconds} s (${rate:-?}/s), corpus ${files} files, no finding"
  else
    failed=1
    echo "fuzz: $h: FINDING after ${execs:-?} executions (log: $dir/log)"
    grep -E "^(==[0-9]+==ERROR|SUMMARY|fuzz [a-z_]+:|.*runtime error:)" "$dir/log" | head -5 | sed 's/^/  /' || true
    for f in "$dir"/findings/*; do
      [ -e "$f" ] && echo "  input: $f"
    done
  fi
done
exit $failed
