#!/usr/bin/env bash
# Build the library, CLI and tests, run the test suite with CTest, then compile the benchmarks
# (they run in scripts/bench.sh, not here: timing goals live in bench/, never in tests).
set -euo pipefail
cd "$(dirname "$0")/.."
start=$(date +%s)
bash scripts/build.sh
ctest --preset release "$@"
tests_done=$(date +%s)
echo "soma tests: built and ran in $(( tests_done - start )) s"
cmake --build --preset release --target soma_benchmarks
echo "soma benchmarks: compiled in $(( $(date +%s) - tests_done )) s"
