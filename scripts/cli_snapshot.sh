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
    -e 's#"seconds": [-0-9.e+]+#"seconds": <t>#g' \
    -e 's#(time|seconds|in|took|after)( ?[:=]?) [0-9][-0-9.e+]* ?(s|ms|µs)\b#\1\2 <t> \3#g' \
    -e 's#\(([0-9][-0-9.e+]*) ?(s|ms)\)#(<t> \2)#g' \
    -e 's#: [0-9][-0-9.e+]* s, not included#: <t> s, not included#g' \
    "$f"
done
echo "cli_snapshot: $(ls "$out" | wc -l) outputs in $out ($(grep -c 'Passed' "$out.ctest.log" || true) tests passed)"
