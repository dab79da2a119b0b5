#!/usr/bin/env bash
# The main job: build soma, run every study, write out/report/index.html (+ report.json, figures).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh --target soma
# The Python module (README "Python"): built and installed into Debian's python3 (dist-packages).
if grep -q '^SOMA_PYTHON:BOOL=ON' build/release/CMakeCache.txt; then
  cmake --build --preset release --target soma_python
  cmake --install build/release --component python
fi
./build/release/cli/soma report --out out/report
echo "report: $(pwd)/out/report/index.html"
