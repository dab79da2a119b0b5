#!/usr/bin/env python3
"""The scene JSON Schema (io/schema/scene.schema.json) against the scene files: every example scene
(examples/scenes/*.json) is valid, every bad scene of tests/io/scenes/bad_*.json is rejected (the
reader rejects each too: tests/io/scene_file.cpp). A repeated key is rejected while loading (a
schema cannot see it: a JSON parser keeps the last one). Run by CTest: `scene schema: ...`."""
import json
import pathlib
import sys

import jsonschema

root = pathlib.Path(sys.argv[1])
schema = json.loads((root / "io/schema/scene.schema.json").read_text())
jsonschema.Draft202012Validator.check_schema(schema)
validator = jsonschema.Draft202012Validator(schema)


def unique(pairs):
    keys = [k for k, _ in pairs]
    for k in keys:
        if keys.count(k) > 1:
            raise ValueError(f'the key "{k}" is given twice')
    return dict(pairs)


def load(path):
    return json.loads(path.read_text(), object_pairs_hook=unique)


failures = 0
examples = sorted((root / "examples/scenes").glob("*.json"))
bad = sorted((root / "tests/io/scenes").glob("bad_*.json"))
if len(examples) < 12 or not bad:
    print(f"expected at least 12 example scenes and some bad ones, found {len(examples)} and {len(bad)}")
    sys.exit(1)
for path in examples:
    errors = list(validator.iter_errors(load(path)))
    if errors:
        failures += 1
        print(f"FAIL {path.name}: {errors[0].message} at {list(errors[0].absolute_path)}")
    else:
        print(f"ok   {path.name}: valid")
for path in bad:
    if validator.is_valid(load(path)):
        failures += 1
        print(f"FAIL {path.name}: the schema accepts a bad scene")
    else:
        print(f"ok   {path.name}: rejected ({next(validator.iter_errors(load(path))).message[:80]})")
dup = root / "tests/io/scenes/semantic/duplicate_name.json"
try:
    load(dup)
    failures += 1
    print(f"FAIL {dup.name}: a repeated key is not rejected")
except ValueError as e:
    print(f"ok   {dup.name}: rejected ({e})")
print(f"{len(examples)} example scenes, {len(bad) + 1} bad scenes, {failures} failed")
sys.exit(1 if failures else 0)
