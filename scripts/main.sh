#!/usr/bin/env bash
# The main job: build soma, run every study, write out/report/index.html (+ report.json, figures).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh --target soma
./build/release/cli/soma report --out out/report
echo "report: $(pwd)/out/report/index.html"
