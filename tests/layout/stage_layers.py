#!/usr/bin/env python3
"""Checks the stage layering docs/development.md's Layout section states: every #include of a file in
harness/ names a stage its own stage may include, and harness/CMakeLists.txt links each
stage library to exactly what its includes need (no link runs up, no include goes unlinked).

usage: stage_layers.py SOURCE_DIR
"""
import os
import re
import sys

root = sys.argv[1]


def fail(message):
    print("stage_layers: " + message)
    sys.exit(1)


# docs/development.md's ```stages block: "stage: what it may include" per line, bottom to top.
development = open(os.path.join(root, "docs", "development.md"), encoding="utf-8").read()
block = re.search(r"```stages\n(.*?)```", development, re.S)
if not block:
    fail("docs/development.md has no ```stages block in its Layout section")
allowed = {}
for line in block.group(1).splitlines():
    line = line.split("#")[0].strip()
    if not line:
        continue
    stage, _, below = line.partition(":")
    names = below.split()
    unknown = [n for n in names if n not in allowed]
    if unknown:
        fail(f"docs/development.md stage '{stage}' may include {unknown}, which are not listed below it")
    allowed[stage.strip()] = set(names)


def stage_of(relative):
    """The stage of a path relative to harness/ (or of an include): the longest listed prefix."""
    parts = relative.split("/")
    for n in range(len(parts) - 1, 0, -1):
        candidate = "/".join(parts[:n])
        if candidate in allowed:
            return candidate
    return None


problems = []
includes = {}   # stage -> stages it includes
for top in ("harness",):
    for folder, _, files in os.walk(os.path.join(root, top)):
        for name in files:
            if not name.endswith((".h", ".cpp")):
                continue
            path = os.path.join(folder, name)
            relative = os.path.relpath(path, os.path.join(root, top))
            stage = stage_of(relative)
            if stage is None:
                problems.append(f"harness/{relative}: its folder is no stage of docs/development.md's ```stages block")
                continue
            with open(path, encoding="utf-8", errors="replace") as f:
                for number, line in enumerate(f, 1):
                    m = re.match(r'\s*#\s*include\s+"([^"]+)"', line)
                    if not m or "/" not in m.group(1):
                        continue
                    target = stage_of(m.group(1))
                    if target is None or target == stage:
                        continue   # a generated header or the stage's own
                    includes.setdefault(stage, set()).add(target)
                    if target not in allowed[stage]:
                        problems.append(f"harness/{relative}:{number}: {stage} includes {m.group(1)} ({target} is not below it)")

# The link graph: shaderbed_<name> libraries and what target_link_libraries gives them.
cmake = open(os.path.join(root, "harness", "CMakeLists.txt"), encoding="utf-8").read()
library_stage = {}
for m in re.finditer(r"shaderbed_stage\((shaderbed_\w+)\s+([\w/]+)\)", cmake):
    library_stage[m.group(1)] = m.group(2)
library_stage["shaderbed_reference"] = "reference"
library_stage["shaderbed_sh"] = "sh"
links = {}
for m in re.finditer(r"target_link_libraries\((shaderbed_\w+)\s+([^)]*)\)", cmake, re.S):
    stage = library_stage.get(m.group(1))
    if stage is None:
        continue
    for library in re.findall(r"shaderbed_\w+", m.group(2)):
        if library in library_stage:
            links.setdefault(stage, set()).add(library_stage[library])

def closure(stage, seen=None):
    seen = set() if seen is None else seen
    for below in links.get(stage, ()):
        if below not in seen:
            seen.add(below)
            closure(below, seen)
    return seen

for stage, linked in sorted(links.items()):
    if stage not in allowed:
        continue
    for below in sorted(linked - allowed[stage]):
        problems.append(f"harness/CMakeLists.txt: {stage} links {below}, which is not below it")
for stage, included in sorted(includes.items()):
    if stage not in library_stage.values():
        continue   # an executable's folder (the CLI, a tool): linked by hand
    for target in sorted(included - closure(stage)):
        if target in ("reference", "sh") or target in library_stage.values():
            problems.append(f"harness/CMakeLists.txt: {stage} includes {target} but does not link it")

if problems:
    print("\n".join(problems))
    sys.exit(1)
print(f"stage_layers: {len(allowed)} stages, {sum(len(v) for v in includes.values())} stage-to-stage includes, all downward and linked")
