#!/usr/bin/env python3
"""Every case file in the repository (the library, the test corpora, the users' examples)
validates against docs/schema/case.schema.json, so the published schema says what the
reader (harness/scene/CaseFile.cpp) takes. Usage: validate_cases.py SOURCE_DIR"""
import json
import pathlib
import sys
import tomllib

import jsonschema

# Case folders, relative to the source tree; every *.toml in them is a case.
CASE_FOLDERS = ["shaders/cases", "tests/realworld/cases", "tests/realworld/precision", "tests/mutants/cases",
                "tests/differential/cases", "tests/divergence/cases", "tests/twin/cases", "tests/hard/cases",
                "tests/hard/user", "tests/viewer/one_draw/cases"]


def main():
    root = pathlib.Path(sys.argv[1])
    schema = json.loads((root / "docs/schema/case.schema.json").read_text())
    jsonschema.Draft202012Validator.check_schema(schema)
    validator = jsonschema.Draft202012Validator(schema)
    files = [f for folder in CASE_FOLDERS for f in sorted((root / folder).glob("*.toml"))]
    if len(files) < 50:
        sys.exit(f"found only {len(files)} case files: has a folder moved?")
    bad = 0
    for f in files:
        with open(f, "rb") as stream:
            document = tomllib.load(stream)
        for e in validator.iter_errors(document):
            bad += 1
            print(f"{f.relative_to(root)}: /{'/'.join(map(str, e.absolute_path))}: {e.message}")
    # The schema refuses what the reader refuses: a few broken cases must fail.
    broken = [{"model": "phong"},                                              # no variants
              {"model": "phong", "reference": {"language": "hlsl"}, "variants": {"p": {"glsl": {"vertex": "a", "fragment": "b"}}}},
              {"model": "phong", "colour": 1, "variants": {"p": {"glsl": {"vertex": "a", "fragment": "b"}}}},
              {"model": "phong", "variants": {"p": {"glsl": {"vertex": "a"}}}},
              {"model": "phong", "variants": {"p": {"glsl": {"vertex": "a", "fragment": "b"}}},
               "tolerance": {"interior": {"max_abs": 1e-3}, "silhouette": {"max_abs": 1e-3, "reason": "x"}}},
              {"reference": {"language": "hlsl", "twin": "double", "backend": "gl"},
               "variants": {"p": {"hlsl": {"vertex": "a", "fragment": "b"}}}}]
    for i, document in enumerate(broken):
        if validator.is_valid(document):
            bad += 1
            print(f"broken case {i} validates: the schema is looser than the reader")
    print(f"{len(files)} case files, {len(broken)} broken cases checked: {bad} problems")
    sys.exit(1 if bad else 0)


if __name__ == "__main__":
    main()
