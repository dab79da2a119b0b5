#!/usr/bin/env bash
# Build everything (library, CLI, tests, benchmarks) and run the test suite with CTest.
set -euo pipefail
cd "$(dirname "$0")/.."
start=$(date +%s)
bash scripts/build.sh
ctest --preset release "$@"
echo "soma tests: built and ran in $(( $(date +%s) - start )) s"
