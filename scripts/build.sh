#!/usr/bin/env bash
# Configure and build soma (Release, Ninja, ccache) into build/release.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake --preset release >/dev/null
cmake --build --preset release "$@"
