#!/usr/bin/env python3
"""A run whose --out fills up keeps every verdict and says what it lost (issue 30, item 4).

--out (keeping every image) and --html go to a 1 MiB tmpfs (mounted here when this runs as root and may mount;
else each file is capped with RLIMIT_FSIZE, the same ENOSPC-like failure for every write
past the cap). The JSON goes to a normal disk. Checked: the run finishes with its summary
and a JSON of every cell, no cell becomes an error for want of space, every cell that lost
an image says so in its warnings and names no artefact that is missing, and no image, JSON
or HTML file is left empty or cut short at its final name. Then --save-images into a
known-good set on a full disk: the set stays byte for byte as it was, and the run keeps
its summary and JSON (exit 1).

usage: full_disk.py SOURCE_DIR SHADERBED [--size N] [--cases a,b] [--slow]
--slow (scripts/test --reliability): more cases, on disks of 256 KiB, 1 MiB and 4 MiB.
"""
import argparse
import json
import os
import resource
import signal
import subprocess
import sys
import tempfile


def mount_small_tmpfs(path, kib):
    if os.geteuid() != 0:
        return False
    r = subprocess.run(["mount", "-t", "tmpfs", "-o", f"size={kib}k", "tmpfs", path], capture_output=True)
    return r.returncode == 0


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("source")
    ap.add_argument("shaderbed")
    ap.add_argument("--size", default="64")
    ap.add_argument("--cases", default="lambert")
    ap.add_argument("--slow", action="store_true")
    a = ap.parse_args()
    if a.slow:
        return max([probe(a.shaderbed, "lambert,phong,ward_iso,cook_torrance", a.size, kib) for kib in (256, 1024, 4096)]
                   + [probe_stored_set(a.shaderbed, "lambert,phong", a.size)])
    return max(probe(a.shaderbed, a.cases, a.size, 1024), probe_stored_set(a.shaderbed, a.cases, a.size))


def verdict(problems, out):
    for p in problems[:10]:
        print("FAIL:", p)
    if problems:
        print(out[-3000:])
    return 1 if problems else 0


def fill(folder):
    """Writes a filler file until the disk (or the file size cap) says no."""
    try:
        with open(os.path.join(folder, "filler"), "wb") as f:
            while True:
                f.write(b"\0" * 65536)
                f.flush()
    except OSError:
        pass


def probe_stored_set(shaderbed, cases, size):
    """--save-images into a known-good set on a full disk: the set stays byte for byte as
    it was, and the run keeps its verdicts (a summary, a JSON of every cell, exit 1)."""
    with tempfile.TemporaryDirectory(prefix="shaderbed_full_set_") as tmp:
        full = os.path.join(tmp, "full")
        os.mkdir(full)
        mounted = mount_small_tmpfs(full, 1024)
        try:
            good = os.path.join(full, "good")
            base = [shaderbed, "run", "--case", cases, "--shape", "sphere", "--backend", "vulkan", "--size", size,
                    "--repeat", "0", "-q"]
            first = subprocess.run(base + ["--save-images", good], capture_output=True, text=True, timeout=600)
            if first.returncode != 0:
                print("FAIL: the known-good set could not be saved:", first.stdout[-2000:], first.stderr[-2000:])
                return 1
            before = {}
            for root, _, files in os.walk(good):
                for f in files:
                    with open(os.path.join(root, f), "rb") as h:
                        before[os.path.join(root, f)] = h.read()
            if mounted:
                fill(full)
            results = os.path.join(tmp, "results.json")
            cap = None if mounted else (lambda: (signal.signal(signal.SIGXFSZ, signal.SIG_IGN),
                                                 resource.setrlimit(resource.RLIMIT_FSIZE, (16 << 10, 16 << 10))))
            run = subprocess.run(base + ["--save-images", good, "--json", results], capture_output=True, text=True,
                                 timeout=600, preexec_fn=cap)
            out = run.stdout + run.stderr
            problems = []
            if run.returncode != 1:
                problems.append(f"exit {run.returncode}, not 1")
            if " cells: " not in out:
                problems.append("no summary line")
            if not os.path.exists(results):
                problems.append("no JSON: the run's results were discarded")
            after = {}
            for root, _, files in os.walk(good):
                for f in files:
                    if not f.startswith("."):
                        with open(os.path.join(root, f), "rb") as h:
                            after[os.path.join(root, f)] = h.read()
            if after != {k: v for k, v in before.items() if not os.path.basename(k).startswith(".")}:
                problems.append("the known-good set changed")
            print(f"--save-images on a full {'1 MiB tmpfs' if mounted else 'RLIMIT_FSIZE 16 KiB'}: exit "
                  f"{run.returncode}, set {'unchanged' if 'the known-good set changed' not in problems else 'CHANGED'}")
            return verdict(problems, out)
        finally:
            if mounted:
                subprocess.run(["umount", full])


def probe(shaderbed, cases, size, kib):
    with tempfile.TemporaryDirectory(prefix="shaderbed_full_disk_") as tmp:
        full = os.path.join(tmp, "full")
        os.mkdir(full)
        mounted = mount_small_tmpfs(full, kib)

        def cap_file_size():
            # Writes past 64 KiB fail with EFBIG (SIGXFSZ ignored, as the workers inherit it).
            signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
            resource.setrlimit(resource.RLIMIT_FSIZE, (64 << 10, 64 << 10))

        results = os.path.join(tmp, "results.json")
        try:
            cmd = [shaderbed, "run", "--case", cases, "--size", size, "--repeat", "0", "-q", "--keep-images", "all",
                   "--out", os.path.join(full, "out"), "--html", os.path.join(full, "html"), "--json", results]
            run = subprocess.run(cmd, capture_output=True, text=True, timeout=600,
                                 preexec_fn=None if mounted else cap_file_size)
            out = run.stdout + run.stderr
            print(f"{f'{kib} KiB tmpfs' if mounted else 'RLIMIT_FSIZE 64 KiB'}, {cases}: exit {run.returncode}")
            problems = []
            if " cells: " not in out:
                problems.append("no summary line")
            if not os.path.exists(results):
                problems.append("no JSON")
                report = {"results": []}
            else:
                with open(results) as f:
                    report = json.load(f)
            cells = report["results"]
            lost = [c for c in cells if any("not written" in w for w in c.get("warnings", []))]
            errors = [c for c in cells if c["status"] == "error"]
            if errors:
                problems.append(f"{len(errors)} cells became errors: {errors[0].get('message', '')}")
            if not lost:
                problems.append("no cell says an image was lost (the disk did not fill?)")
            for c in cells:
                for key, path in c.get("artefacts", {}).items():
                    if not isinstance(path, str):
                        continue   # error_scale: the error map's numbers, not a file
                    if path and (not os.path.exists(path) or os.path.getsize(path) == 0):
                        problems.append(f"{c['id']}: artefact {key} names {path}, which is "
                                        "missing or empty")
                        break
            empty = []
            for root, _, files in os.walk(full):
                empty += [os.path.join(root, f) for f in files if os.path.getsize(os.path.join(root, f)) == 0]
            if empty:
                problems.append(f"{len(empty)} empty files at their final names, e.g. {empty[0]}")
            print(f"{len(cells)} cells, {len(lost)} say what they lost, {len(errors)} errors")
            return verdict(problems, out)
        finally:
            if mounted:
                subprocess.run(["umount", full])


if __name__ == "__main__":
    sys.exit(main())
