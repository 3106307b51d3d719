#!/usr/bin/env python3
"""The CI matrix of .github/workflows/shaderbed.yml runs and merges as written.

Reads the suite job's matrix and run command and the report job's merge command from the
workflow file itself, so the test and the workflow cannot drift apart. Every job of the
matrix runs in its own folder at a small size on a few cases (the only change to the
command), its `out` folder is laid out as actions/download-artifact lays out artifacts
(results/<artifact name>/...), then the merge command runs and its totals are checked.

usage: ci_matrix.py SOURCE_DIR SHADERBED_BINARY
"""
import itertools
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

import yaml

SMALL = ["--size", "24", "--case", "lambert,blinn_phong"]


def expand(text, values):
    """Replaces ${{ matrix.x }} by the job's value; other expressions are not expected."""
    def one(m):
        key = m.group(1).strip()
        if not key.startswith("matrix."):
            raise SystemExit(f"unexpected expression ${{{{ {key} }}}} in a run step")
        return values[key[len("matrix."):]]
    return re.sub(r"\$\{\{(.*?)\}\}", one, text)


def step_running(job, word):
    for step in job["steps"]:
        if "run" in step and f"shaderbed {word}" in step["run"]:
            return step["run"]
    raise SystemExit(f"no step runs 'shaderbed {word}'")


def artifact_name(job, values):
    for step in job["steps"]:
        if step.get("uses", "").startswith("actions/upload-artifact"):
            return expand(step["with"]["name"], values), step["with"]["path"]
    raise SystemExit("the suite job uploads no artifact")


def shell(command, cwd):
    done = subprocess.run(["bash", "-c", command], cwd=cwd, capture_output=True, text=True)
    return done.returncode, done.stdout + done.stderr


def main():
    source, binary = sys.argv[1], os.path.abspath(sys.argv[2])
    with open(os.path.join(source, ".github/workflows/shaderbed.yml")) as f:
        workflow = yaml.safe_load(f)
    suite, report = workflow["jobs"]["suite"], workflow["jobs"]["report"]
    matrix = suite["strategy"]["matrix"]
    keys = list(matrix)
    run_command = step_running(suite, "run")
    merge_command = step_running(report, "merge")

    root = tempfile.mkdtemp(prefix="shaderbed-ci-matrix-")
    results = os.path.join(root, "results")
    jobs = []
    for combo in itertools.product(*(matrix[k] for k in keys)):
        values = dict(zip(keys, combo))
        work = os.path.join(root, "job-" + "-".join(combo))
        os.makedirs(os.path.join(work, "build/bin"))
        os.symlink(binary, os.path.join(work, "build/bin/shaderbed"))
        os.symlink(os.path.join(source, "shaders"), os.path.join(work, "shaders"))
        command = expand(run_command, values).strip() + " " + " ".join(SMALL)
        status, output = shell(command, work)
        if status != 0:
            raise SystemExit(f"job {values} exited {status}: {command}\n{output}")
        name, path = artifact_name(suite, values)
        shutil.copytree(os.path.join(work, path), os.path.join(results, name))
        json_files = [f for f in os.listdir(os.path.join(results, name)) if f.endswith(".json")]
        if len(json_files) != 1:
            raise SystemExit(f"job {values} left {json_files} in its artifact, expected one results file")
        with open(os.path.join(results, name, json_files[0])) as f:
            cells = json.load(f)["results"]
        if not cells:
            raise SystemExit(f"job {values} ran no cells")
        jobs.append((values, len(cells)))

    os.makedirs(os.path.join(root, "build/bin"))
    os.symlink(binary, os.path.join(root, "build/bin/shaderbed"))
    status, output = shell(merge_command, root)
    if status != 0:
        raise SystemExit(f"merge exited {status}: {merge_command}\n{output}")
    expected = sum(n for _, n in jobs)
    with open(os.path.join(root, "report/junit.xml")) as f:
        junit = f.read()
    total = re.search(r'<testsuites[^>]*\btests="(\d+)"', junit)
    if not total or int(total.group(1)) != expected:
        raise SystemExit(f"the merged JUnit counts {total and total.group(1)} cells, the {len(jobs)} jobs ran {expected}")
    if f"merged {len(jobs)} files: {expected} cells" not in output or "no cells for" in output:
        raise SystemExit(f"merge did not report the union of {len(jobs)} jobs' {expected} cells:\n{output}")
    if not os.path.isfile(os.path.join(root, "report/index.html")):
        raise SystemExit("merge wrote no HTML report")
    print(f"{len(jobs)} jobs ({', '.join(keys)}) ran {expected} cells; merge joined them:")
    print(output.split("\n\n")[0])
    shutil.rmtree(root)


if __name__ == "__main__":
    main()
