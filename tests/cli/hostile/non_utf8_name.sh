#!/bin/sh
# soma pose --json on a copy of POSE.json whose file name has the byte 0xFF (not UTF-8): the JSON
# answer carries the name with U+FFFD in its place (issue 24: nlohmann's type_error.316, exit 2).
# Usage: non_utf8_name.sh SOMA POSE.json DIR
set -e
name=$(printf '%s/pose_\377.json' "$3")
cp "$2" "$name"
"$1" pose "$name" --json
