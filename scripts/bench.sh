#!/usr/bin/env bash
# Build and run soma's Google Benchmark executables (bench/*.cpp) and regenerate the table in
# papers/benchmarks/se3.md (scripts/bench_table.py keeps the notes outside its markers).
#
#   scripts/bench.sh [--wait-load L [--max-wait S]] [--no-table] [-- extra benchmark flags]
#
#   --wait-load L   before running, wait until the 1-minute load average is below L
#                   (checked every 15 s, for at most --max-wait seconds, default 1800)
#   --no-table      run and keep the JSON, but do not touch papers/benchmarks/se3.md
# Environment: SOMA_BENCH_BUILD (build directory, default build/bench), SOMA_BENCH_JOBS
# (build parallelism, default 2). Results: $SOMA_BENCH_BUILD/bench-results/<name>.json.
set -euo pipefail
cd "$(dirname "$0")/.."

build=${SOMA_BENCH_BUILD:-build/bench}
jobs=${SOMA_BENCH_JOBS:-2}
wait_load=""
max_wait=1800
table=1
extra=()
while [ $# -gt 0 ]; do
  case "$1" in
    --wait-load) wait_load=$2; shift 2 ;;
    --max-wait) max_wait=$2; shift 2 ;;
    --no-table) table=0; shift ;;
    --) shift; extra=("$@"); break ;;
    *) echo "bench.sh: unknown option $1 (see the header of $0)" >&2; exit 2 ;;
  esac
done

load1() { cut -d' ' -f1 /proc/loadavg; }
loadavg() { cut -d' ' -f1-3 /proc/loadavg | sed 's/ /, /g'; }

cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DSOMA_BUILD_BENCH=ON -DSOMA_LADDER_OPT=-O3 >/dev/null
targets=()
for src in bench/*.cpp; do targets+=("bench_$(basename "$src" .cpp)"); done
cmake --build "$build" --target "${targets[@]}" -j "$jobs"

if [ -n "$wait_load" ]; then
  waited=0
  while awk -v l="$(load1)" -v t="$wait_load" 'BEGIN { exit !(l >= t) }'; do
    if [ "$waited" -ge "$max_wait" ]; then
      echo "bench.sh: load still $(load1) after ${waited}s; running anyway" >&2
      break
    fi
    echo "bench.sh: load $(load1) >= $wait_load, waiting..." >&2
    sleep 15
    waited=$((waited + 15))
  done
fi

out="$build/bench-results"
mkdir -p "$out"
before=$(loadavg)
jsons=()
flags=(--benchmark_repetitions=5 --benchmark_report_aggregates_only=true "${extra[@]}")
for t in "${targets[@]}"; do
  echo "== $t (load $(loadavg))" >&2
  "$build/bench/$t" "${flags[@]}" --benchmark_out="$out/$t.json" --benchmark_out_format=json
  jsons+=("$out/$t.json")
done
after=$(loadavg)

if [ "$table" -eq 1 ]; then
  python3 scripts/bench_table.py --out papers/benchmarks/se3.md \
    --title "SE(3) and SO(3): soma's scalar ladder beside Orocos KDL" \
    --load "before: $before; after: $after" --flags "${flags[*]}" "${jsons[@]}"
  echo "bench.sh: wrote papers/benchmarks/se3.md" >&2
fi
