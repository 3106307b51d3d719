#!/usr/bin/env python3
"""The reports of a few real runs validate against the published schemas: the JSON of
`run --json` and `merge --json` against docs/schema/results.schema.json, the JUnit of
`run --junit` and `merge --junit` against the junit-10 schema CI systems check
(tests/schema/junit-10.xsd, with xmllint). The runs: a differential case whose buggy port
fails, a case whose shader does not compile (an error cell), and two shards of a model case
with its twin, and their merge, and a GL cell drawn on an EGL device (its tools.gl_platform
must say so). Each is one shape on one backend at 16 px.

Also: a failing cell's JUnit names its images as [[ATTACHMENT|path]] lines (GitLab and
Jenkins show them) and the paths exist relative to the directory the run started in; the
run's JSON names no folder of the user's home (the default caches are written "~/...").

usage: validate_reports.py SOURCE_DIR SHADERBED_BINARY"""
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

import jsonschema

SMALL = ["--size", "16", "--shape", "sphere", "--backend", "vulkan"]


def run(binary, cwd, args, env, allowed=(0, 1)):
    done = subprocess.run([binary, *args], cwd=cwd, env=env, capture_output=True, text=True, timeout=300)
    if done.returncode not in allowed:
        sys.exit(f"shaderbed {' '.join(args)} exited {done.returncode}:\n{done.stdout}{done.stderr}")
    return done


def main():
    source, binary = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    with open(os.path.join(source, "docs/schema/results.schema.json")) as f:
        schema = json.load(f)
    jsonschema.Draft202012Validator.check_schema(schema)
    validator = jsonschema.Draft202012Validator(schema)
    xsd = os.path.join(source, "tests/schema/junit-10.xsd")
    work = tempfile.mkdtemp(prefix="shaderbed-schema-")
    home = os.path.join(work, "home")
    os.makedirs(home)
    env = dict(os.environ, SHADERBED_ROOT=source)
    # The error run (no draw, so a cold cache costs nothing) uses the default caches under
    # $HOME, so its report's cache folders are the user's own.
    home_env = {k: v for k, v in env.items() if k not in ("SHADERBED_CACHE_DIR", "XDG_CACHE_HOME")}
    home_env["HOME"] = home

    # An error cell: a case next to its own shader, which does not compile.
    user = os.path.join(work, "user")
    os.makedirs(user)
    shutil.copy(os.path.join(source, "shaders/glsl/setup.vert"), user)
    with open(os.path.join(user, "broken.frag"), "w") as f:
        f.write("#version 450\nlayout(location = 0) out vec4 color;\nvoid main() { color = vec4(oops); }\n")
    with open(os.path.join(user, "broken.toml"), "w") as f:
        f.write('model = "lambert"\n[params]\ndiffuse = [1.0, 1.0, 1.0]\n'
                '[variants.pixel]\nglsl = { vertex = "setup.vert", fragment = "broken.frag" }\n'
                '[bindings.glsl]\nmodelViewProjection = "transform"\nlightDirection = "light_vector"\n'
                'diffuseColor = "diffuse"\n')

    runs = {
        "differential": ["run", "--cases-dir", os.path.join(source, "tests/divergence/cases"), "--case", "blinn_point",
                         "--variant", "half_average"],
        "error": ["run", "--case", os.path.join(user, "broken.toml")],
        "shard1": ["run", "--case", "lambert", "--variant", "vertex,pixel", "--lang", "glsl", "--twin", "float", "--shard", "1/2"],
        "shard2": ["run", "--case", "lambert", "--variant", "vertex,pixel", "--lang", "glsl", "--twin", "float", "--shard", "2/2"],
        # GL on an EGL device (docs/gl-platforms.md): tools.gl_platform in its longest form.
        "egl": ["run", "--case", "lambert", "--variant", "pixel", "--lang", "glsl", "--backend", "gl", "--gl-device", "0"],
    }
    statuses = {}
    for name, args in runs.items():
        run(binary, work, args + SMALL + ["--out", f"out/{name}", "--json", f"{name}.json", "--junit", f"{name}.xml"],
            home_env if name == "error" else env)
    run(binary, work, ["merge", "shard1.json", "shard2.json", "--json", "merged.json", "--junit", "merged.xml"], env)

    problems = []
    for name in list(runs) + ["merged"]:
        with open(os.path.join(work, f"{name}.json")) as f:
            text = f.read()
        report = json.loads(text)
        for e in validator.iter_errors(report):
            problems.append(f"{name}.json /{'/'.join(map(str, e.absolute_path))}: {e.message[:300]}")
        statuses[name] = sorted({r["status"] for r in report["results"]})
        if home in text:
            problems.append(f"{name}.json names the user's home folder {home}")
        lint = subprocess.run(["xmllint", "--noout", "--schema", xsd, f"{name}.xml"], cwd=work, capture_output=True,
                              text=True)
        if lint.returncode != 0:
            problems.append(f"{name}.xml does not validate against junit-10:\n{lint.stderr}")
    # The runs cover what they are meant to.
    for name, wanted in {"merged": "pass", "differential": "fail", "error": "error"}.items():
        if wanted not in statuses[name]:
            problems.append(f"{name}: expected a '{wanted}' cell, found {statuses[name]}")
    with open(os.path.join(work, "egl.json")) as f:
        platform = json.load(f)["tools"]["gl_platform"]
    if not platform.startswith("egl device 0: "):
        problems.append(f"egl.json: tools.gl_platform is {platform!r}, expected 'egl device 0: ...'")
    with open(os.path.join(work, "error.json")) as f:
        cache = json.load(f).get("cache", {})
    if cache.get("compile", {}).get("dir") != "~/.cache/shaderbed/compile":
        problems.append(f"error.json: compile cache written as {cache}, expected ~/.cache/shaderbed/compile")
    with open(os.path.join(work, "merged.json")) as f:
        merged = json.load(f)
    if len(merged["results"]) != 2:
        problems.append(f"merged.json holds {len(merged['results'])} cells, the shards ran 2")
    if not all("twin" in r for r in merged["results"]):
        problems.append("merged.json: a cell without its twin figures (--twin float)")
    # A failing cell's images as attachments, each an existing file.
    with open(os.path.join(work, "differential.xml")) as f:
        junit = f.read()
    attachments = re.findall(r"\[\[ATTACHMENT\|([^\]]+)\]\]", junit)
    if not any(a.endswith("error.png") or "error" in os.path.basename(a) for a in attachments):
        problems.append(f"differential.xml: no error image among the attachments {attachments}")
    for a in attachments:
        if not os.path.isfile(os.path.join(work, a)):
            problems.append(f"differential.xml: attachment {a} is no file")

    for p in problems:
        print(p)
    print(f"{len(runs) + 1} reports: {len(problems)} problems")
    if problems:
        print(f"(kept {work})")
        sys.exit(1)
    shutil.rmtree(work)


if __name__ == "__main__":
    main()
