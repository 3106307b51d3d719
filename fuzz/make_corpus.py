#!/usr/bin/env python3
"""Writes the seed corpora from the project's own shaders, case files and expectations into
OUT/<target>/ (the build tree: the library is the seed, so it is not copied into the
repository). The checked-in fuzz/corpus/<target>/ holds only what the library does not:
hand-written seeds (hand_*), crash regressions (crash_*) and results JSON cut from a real
run (with `--results RUN.json`, written into fuzz/corpus/json_report_fuzzer/).

  make_corpus.py OUT [--results RUN.json] [--glslang GLSLANGVALIDATOR]

With --glslang, twin_fuzzer's seeds are the library's fragment shaders compiled to SPIR-V
for Vulkan (the GLSL ones that compile alone: legacy and ES shaders need the project's
dialect passes first, so they are left out), and fuzz/twin_shaders/: hand-written ones for
what the library's shaders do not use (loops, every image instruction, integers)."""
import hashlib
import json
import pathlib
import re
import subprocess
import sys
import tempfile
import tomllib

ROOT = pathlib.Path(__file__).resolve().parent.parent
CHECKED_IN = ROOT / "fuzz" / "corpus"
CORPUS = CHECKED_IN   # set in main() for the generated seeds
CASE_DIRS = ["shaders/cases", "tests/realworld/cases", "tests/differential/cases", "tests/mutants/cases"]
TWIN_SHADERS = ["shaders/glsl/*.frag", "tests/realworld/**/*.frag", "tests/differential/glsl/*.frag",
                "fuzz/twin_shaders/*.frag"]


def reset(target):
    folder = CORPUS / target
    folder.mkdir(parents=True, exist_ok=True)
    for f in folder.iterdir():
        if not f.name.startswith(("hand_", "crash_")):
            f.unlink()
    return folder


def put(folder, name, text):
    (folder / name).write_bytes(text.encode() if isinstance(text, str) else text)


def inline_includes(path, seen=None):
    # glslang's preprocessor resolves includes before translate_cg; the seed inlines them.
    seen = seen or set()
    out = []
    for line in path.read_text().splitlines(keepends=True):
        m = re.match(r'\s*#include\s+"([^"]+)"', line)
        target = path.parent / m.group(1) if m else None
        if target and target.exists() and target not in seen:
            seen.add(target)
            out.append(inline_includes(target, seen))
        else:
            out.append(line)
    return "".join(out)


def cases():
    for d in CASE_DIRS:
        for case in sorted((ROOT / d).glob("*.toml")):
            data = tomllib.loads(case.read_text())
            root = case.parent.parent
            for vname, variant in data.get("variants", {}).items():
                yield case, root, vname, variant


def twin_seeds(glslang):
    folder = reset("twin_fuzzer")
    with tempfile.TemporaryDirectory() as scratch:
        out = pathlib.Path(scratch) / "frag.spv"
        for pattern in TWIN_SHADERS:
            for src in sorted(ROOT.glob(pattern)):
                done = subprocess.run([glslang, "-V", "-o", str(out), str(src)], stdout=subprocess.DEVNULL,
                                      stderr=subprocess.DEVNULL)
                if done.returncode == 0:
                    name = "_".join(src.relative_to(ROOT).with_suffix("").parts[1:])
                    put(folder, f"{name}.spv", out.read_bytes())


def option(args, name):
    if name not in args:
        return None
    i = args.index(name)
    value = args[i + 1]
    del args[i:i + 2]
    return value


def main():
    global CORPUS
    args = sys.argv[1:]
    results = option(args, "--results")
    glslang = option(args, "--glslang")
    if len(args) != 1:
        sys.exit("usage: make_corpus.py OUT [--results RUN.json] [--glslang GLSLANGVALIDATOR]")
    CORPUS = pathlib.Path(args[0])
    folder = reset("case_file_fuzzer")
    for d in CASE_DIRS:
        for case in sorted((ROOT / d).glob("*.toml")):
            put(folder, f"{pathlib.Path(d).parts[-2]}_{case.name}", case.read_text())

    cg = reset("cg_dialect_fuzzer")
    glsl = reset("legacy_glsl_fuzzer")
    fx = reset("effect_file_fuzzer")
    seen = set()
    for case, root, vname, variant in cases():
        if "cg" in variant:
            for stage in ("vertex", "fragment"):
                src = root / variant["cg"][stage]
                entry = variant["cg"].get(f"{stage}_entry", "main")
                key = ("cg", src, stage, entry)
                if src.exists() and key not in seen:
                    seen.add(key)
                    put(cg, f"{src.stem}_{stage}.cg", f"//fuzz {stage} {entry}\n" + inline_includes(src))
        if "glsl" in variant:
            v, f = root / variant["glsl"]["vertex"], root / variant["glsl"]["fragment"]
            key = ("glsl", v, f)
            if v.exists() and f.exists() and key not in seen:
                seen.add(key)
                put(glsl, f"{root.name}_{v.stem}_{f.stem}.glsl",
                    v.read_text() + "\n//fuzz fragment\n" + f.read_text())
        if "hlsl" in variant:
            for stage in ("vertex", "fragment"):
                src = root / variant["hlsl"][stage]
                if src.exists() and src not in seen:
                    seen.add(src)
                    put(fx, f"{root.name}_{src.name}", src.read_text())

    exp = reset("expectations_fuzzer")
    for f in [ROOT / "shaders/expectations.toml", ROOT / "tests/realworld/planted_bugs.toml",
              ROOT / "tests/mutants/expectations.toml"]:
        put(exp, f"{f.parent.name}_{f.name}", f.read_text())

    if glslang:
        twin_seeds(glslang)

    if results:
        # A real results file, cut into small ones: each status once, and a file of a few cells.
        CORPUS = CHECKED_IN
        js = reset("json_report_fuzzer")
        report = json.loads(pathlib.Path(results).read_text())
        results = report["results"]
        picked = {}
        for r in results:
            picked.setdefault((r["status"], r["backend"], r["language"]), r)
        for i, r in enumerate(picked.values()):
            one = dict(report, results=[r])
            put(js, f"results_{i}.json", json.dumps(one, indent=1))
        put(js, "results_empty.json", json.dumps(dict(report, results=[])))
        for f in js.iterdir():
            assert f.stat().st_size < 20000, f


main()
