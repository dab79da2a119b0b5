#!/usr/bin/env bash
# Keep the output of every `soma` CLI test (tests/CMakeLists.txt, soma_cli_test) in DIR, with the
# run-to-run varying parts masked (times, the checkout's path), so that a refactoring can show the
# CLI output unchanged:   scripts/cli_snapshot.sh before/ && (change) && scripts/cli_snapshot.sh after/
#                         diff -r before/ after/
#   scripts/cli_snapshot.sh DIR [BUILD_DIR]     (BUILD_DIR default build/release; the report test is skipped)
set -euo pipefail
cd "$(dirname "$0")/.."
out=$(realpath -m "$1")
build=${2:-build/release}
rm -rf "$out" && mkdir -p "$out"
SOMA_CLI_SNAPSHOT="$out" ctest --test-dir "$build" -R '^cli: ' -E 'report' -j 2 --timeout 600 >"$out.ctest.log" || true
root=$(pwd)
for f in "$out"/*.txt; do
  sed -E -i \
    -e "s#${root}#<root>#g" \
    -e 's#"([a-z_]*seconds)": [-0-9.e+]+#"\1": <t>#g' \
    -e 's#[0-9][0-9.]*(e[-+]?[0-9]+)? ?(s|ms|µs|ns|min)\b#<t>#g' \
    -e 's# +<t>#  <t>#g' \
    "$f"
done
echo "cli_snapshot: $(ls "$out" | wc -l) outputs in $out ($(grep -c 'Passed' "$out.ctest.log" || true) tests passed)"
