#!/usr/bin/env python3
"""Scores divergence localisation (issue 28) on a corpus of port bugs with known planted lines.

usage: divergence_corpus.py SOURCE_DIR SHADERBED_BINARY [--results FILE] [--keep FILE]
                            [--shape SHAPE] [--size N] [--min-rate R]

Runs `shaderbed run` on tests/divergence/cases (vulkan only, one shape, small images) with
--json, or reads the results of such a run with --results FILE (what a run with the lead's
own options wrote), and checks, against tests/divergence/planted.toml:

  - every case loads and draws: no error cell, every variant of every case is the original,
    a [[correct]] port or a [[bug]];
  - the originals and the correct ports pass, and carry no `divergence` entry;
  - every cell of a buggy variant fails;
  - each bug's first failing cell has a `divergence` entry naming a file and a line: the bug
    is hit when the file is the bug's file (compared by resolved path, or by suffix) and the
    line is one of its accepted `lines`; a line in any other file is a miss;
  - the hit rate is at least --min-rate (0.8).

It prints one row per bug (bug, planted lines, named line, hit or miss), the rate as
"N of M (P %)" and the rate among the bugs that are not of a convention kind. Exit status
0 when every check holds, 1 otherwise.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile
import tomllib


def load_corpus(root):
    planted = tomllib.load(open(os.path.join(root, "planted.toml"), "rb"))
    bugs = planted.get("bug", [])
    correct = planted.get("correct", [])
    problems = []
    cases = {}
    for path in sorted(os.listdir(os.path.join(root, "cases"))):
        if path.endswith(".toml"):
            cases[path[:-5]] = tomllib.load(open(os.path.join(root, "cases", path), "rb"))
    for bug in bugs:
        where = f"bug {bug.get('case')}/{bug.get('variant')}"
        for key in ("case", "variant", "language", "file", "lines", "convention", "what"):
            if key not in bug:
                problems.append(f"{where}: planted.toml has no '{key}'")
        case = cases.get(bug["case"])
        if case is None:
            problems.append(f"{where}: no case file cases/{bug['case']}.toml")
            continue
        variant = case.get("variants", {}).get(bug["variant"])
        if variant is None or bug["language"] not in variant:
            problems.append(f"{where}: the case has no {bug['language']} variant '{bug['variant']}'")
            continue
        files = variant[bug["language"]]
        if bug["file"] not in (files.get("vertex"), files.get("fragment")):
            problems.append(f"{where}: {bug['file']} is not one of the variant's files")
        path = os.path.join(root, bug["file"])
        if not os.path.exists(path):
            problems.append(f"{where}: {bug['file']} does not exist")
            continue
        count = len(open(path).read().split("\n"))
        for line in bug["lines"]:
            if not 1 <= line <= count:
                problems.append(f"{where}: line {line} is outside {bug['file']} ({count} lines)")
    known = {(b["case"], b["variant"]) for b in bugs} | {(c["case"], c["variant"]) for c in correct}
    for name, case in cases.items():
        original = case.get("reference", {}).get("variant")
        for variant in case.get("variants", {}):
            if variant != original and (name, variant) not in known:
                problems.append(f"{name}/{variant}: a variant planted.toml does not list as [[bug]] or [[correct]]")
    return bugs, correct, cases, problems


def run_corpus(root, binary, shape, size, out):
    args = [binary, "run", "--cases-dir", os.path.join(root, "cases"), "--backend", "vulkan",
            "--shape", shape, "--size", str(size), "--repeat", "0", "--warmup", "0",
            "--json", out, "--quiet"]
    print("$ " + " ".join(args), flush=True)
    done = subprocess.run(args, capture_output=True, text=True)
    if not os.path.exists(out):
        raise SystemExit(f"shaderbed wrote no results (exit {done.returncode}):\n{done.stderr[-3000:]}")
    return json.load(open(out))["results"]


def same_file(named, bug_file, root):
    """Whether a divergence's `file` is the bug's file: by resolved path (relative to
    tests/divergence, as the case names it, or absolute), else by path suffix."""
    if not named:
        return False
    candidates = [named] if os.path.isabs(named) else [os.path.join(root, named), os.path.join(os.getcwd(), named)]
    target = os.path.realpath(os.path.join(root, bug_file))
    if any(os.path.exists(c) and os.path.realpath(c) == target for c in candidates):
        return True
    a = named.replace("\\", "/").split("/")
    b = bug_file.split("/")
    n = min(len(a), len(b))
    return a[-n:] == b[-n:] and a[-1] == b[-1] and n >= min(2, len(b))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("source")
    parser.add_argument("binary", nargs="?")
    parser.add_argument("--results", help="score these results (a run's --json) instead of running shaderbed")
    parser.add_argument("--keep", help="also write the run's results JSON here")
    parser.add_argument("--shape", default="sphere")
    parser.add_argument("--size", type=int, default=48)
    parser.add_argument("--min-rate", type=float, default=0.8)
    options = parser.parse_args()

    root = os.path.join(options.source, "tests", "divergence")
    bugs, correct, cases, problems = load_corpus(root)
    if options.results:
        cells = json.load(open(options.results))["results"]
    else:
        if not options.binary:
            raise SystemExit("give the shaderbed binary, or --results FILE")
        with tempfile.TemporaryDirectory() as scratch:
            out = options.keep or os.path.join(scratch, "divergence.json")
            cells = run_corpus(root, options.binary, options.shape, options.size, out)

    by_variant = {}
    for cell in cells:
        by_variant.setdefault((cell["case"], cell["variant"]), []).append(cell)

    # The corpus itself: no error cells, originals and correct ports pass without a
    # divergence, every buggy cell fails.
    for cell in cells:
        if cell["status"] not in ("pass", "fail"):
            problems.append(f"{cell['id']}: {cell['status']}: {cell.get('message', '')[:300]}")
    for name, case in cases.items():
        original = case.get("reference", {}).get("variant")
        if original:
            for cell in by_variant.get((name, original), []):
                if cell["status"] != "pass":
                    problems.append(f"{cell['id']}: the original does not pass against itself ({cell['status']})")
    for c in correct:
        drawn = by_variant.get((c["case"], c["variant"]), [])
        if not drawn:
            problems.append(f"{c['case']}/{c['variant']}: the correct port drew no cell")
        for cell in drawn:
            if cell["status"] != "pass":
                problems.append(f"{cell['id']}: the correct port fails ({cell.get('message', '')[:200]})")
            if "divergence" in cell:
                d = cell["divergence"]
                problems.append(f"{cell['id']}: the correct port carries a divergence: "
                                f"{d.get('file')}:{d.get('line')} {d.get('error', '')}")
        # Localised although it passes (explain does for any cell): its twin must compute the
        # original's values at every traced pixel, so no line of it is named.
        if drawn and options.binary and not options.results:
            cell = drawn[0]
            case_file = os.path.join(root, "cases", c["case"] + ".toml")
            args = [options.binary, "explain", case_file, "--cell", cell["id"], "--size", str(options.size), "--json", "-"]
            done = subprocess.run(args, capture_output=True, text=True)
            try:
                d = json.loads(done.stdout).get("divergence", {})
            except json.JSONDecodeError:
                d = {"kind": f"(explain exited {done.returncode}: {done.stderr.strip()[:200]})"}
            if d.get("kind") != "output_matches":
                problems.append(f"{cell['id']}: explain names a line of the correct port: {d.get('kind')} "
                                f"{d.get('file', '')}:{d.get('line', '')} {d.get('text', '')[:200]}")
            else:
                print(f"correct port {cell['id']}: {d['text']}")

    rows = []
    missing_entries = []
    for bug in bugs:
        key = (bug["case"], bug["variant"])
        drawn = by_variant.get(key, [])
        label = f"{bug['case']}/{bug['variant']}"
        planted = f"{bug['file']}:{','.join(str(l) for l in bug['lines'])}"
        if not drawn:
            problems.append(f"{label}: no cell drawn")
            rows.append((bug, planted, "(not drawn)", False))
            continue
        for cell in drawn:
            if cell["status"] != "fail":
                problems.append(f"{cell['id']}: the planted bug does not fail ({cell['status']})")
        failing = [cell for cell in drawn if cell["status"] == "fail"]
        if not failing:
            rows.append((bug, planted, "(passes)", False))
            continue
        cell = failing[0]
        d = cell.get("divergence")
        if d is None:
            print(f"no divergence entry for {cell['id']}")
            missing_entries.append(cell["id"])
            rows.append((bug, planted, "(no divergence entry)", False))
            continue
        if d.get("error"):
            rows.append((bug, planted, f"(not localised: {d['error'][:60]})", False))
            continue
        named_file, named_line = d.get("file", ""), d.get("line")
        hit = same_file(named_file, bug["file"], root) and named_line in bug["lines"]
        rows.append((bug, planted, f"{named_file}:{named_line}", hit))

    width = max([len(f"{b['case']}/{b['variant']}") for b, *_ in rows] + [3])
    pwidth = max([len(p) for _, p, _, _ in rows] + [7])
    print()
    nwidth = max([len(n) for _, _, n, _ in rows] + [5])
    print(f"{'bug':<{width}}  conv  {'planted':<{pwidth}}  {'named':<{nwidth}}  result")
    for bug, planted, named, hit in rows:
        conv = "yes" if bug["convention"] else "no"
        print(f"{bug['case'] + '/' + bug['variant']:<{width}}  {conv:<4}  {planted:<{pwidth}}  {named:<{nwidth}}  {'hit' if hit else 'miss'}")
    hits = sum(1 for *_, hit in rows if hit)
    total = len(rows)
    other = [(b, hit) for b, _, _, hit in rows if not b["convention"]]
    other_hits = sum(1 for _, hit in other if hit)
    rate = hits / total if total else 0.0
    print()
    print(f"named the planted line: {hits} of {total} ({100.0 * rate:.0f} %)")
    if other:
        print(f"among the bugs off the convention list: {other_hits} of {len(other)} "
              f"({100.0 * other_hits / len(other):.0f} %)")

    if missing_entries:
        problems.append(f"no divergence entry for {len(missing_entries)} failing cell(s) "
                        f"(divergence localisation, issue 28, not in this build?)")
    if rate < options.min_rate:
        problems.append(f"hit rate {rate:.2f} below {options.min_rate}")
    if problems:
        print()
        print("FAILED:")
        for p in problems:
            print("  " + p)
        return 1
    print("OK")
    return 0


if __name__ == "__main__":
    sys.exit(main())
