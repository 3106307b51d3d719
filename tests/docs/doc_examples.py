#!/usr/bin/env python3
"""Every command and case example in README.md and docs/*.md runs as written.

Reads the fenced blocks from the text itself, so an example cannot rot unnoticed:

- ```sh blocks: each shaderbed command runs (a block's lines in order, in one folder, so
  `--save-images good` then `--against good` works); it must exit 0 or 1 (1: the
  example shows a failure or a regression), never 2 (bad input) or by a signal.
  `~/port/...` is tests/docs/port/, a user's folder with a Phong original in HLSL, its
  GLSL port and a DX9 effect; a case file a block uses before it writes it is written
  first by `shaderbed init --no-run`, as the user would have. Other programs (scripts/,
  ctest, the Google Benchmark binaries) are the test suite itself: they must exist.
- ```toml blocks: a complete case (it names a model or a reference, and its variants)
  runs against the files of tests/realworld/ and must pass; an abridged one says so in a
  comment (`# abridged: ...`) and must parse.

To keep the run short the commands change in three mechanical ways, never in what they
check: images are at most 32 px (`--size`) and timings take at most 3 repeats
(`--repeat`), a command over the whole library runs on one case (`--case lambert`; the
whole library runs in the suite.* tests), `bench` is `--quick`, and `view` draws two
frames under xvfb-run into a screenshot.

usage: doc_examples.py SOURCE_DIR SHADERBED_BINARY [DOC ...]
"""
import glob
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile
import time
import tomllib

SIZE = 32
SIZED = {"run", "view", "sweep", "hard", "init", "port", "bench", "explain"}
WHOLE_LIBRARY = {"run", "hard", "stats", "bench"}
failures = []


def blocks(path):
    text = open(path).read()
    for m in re.finditer(r"^```(\w*)[^\n]*\n(.*?)^```", text, re.S | re.M):
        yield m.group(1), m.group(2), text[: m.start()].count("\n") + 2


def commands(block):
    """(line offset, command) per command of a shell block, comments and prompts dropped."""
    joined, start = "", 0
    for i, line in enumerate(block.splitlines()):
        if not joined:
            start = i
        joined += line.rstrip("\\") + (" " if line.endswith("\\") else "")
        if line.endswith("\\"):
            continue
        words = shlex.split(joined, comments=True)
        if words:
            yield start, words
        joined = ""


def loop(words):
    """`for V in A B; do CMD; done` -> [CMD with $V = A, CMD with $V = B], else [words]."""
    text = " ".join(words)
    m = re.fullmatch(r"for (\w+) in (.*?) ; do (.*?) ; done", text.replace(";", " ;"))
    if not m:
        return [words]
    var, values, body = m.groups()
    return [shlex.split(body.replace("$" + var, v)) for v in values.split()]


def shaderbed_at(words):
    """Index of the shaderbed binary in a command's words, or None."""
    for i, w in enumerate(words):
        if w in ("shaderbed", "build/bin/shaderbed"):
            return i
    return None


def adapt(words, at):
    sub = words[at + 1] if len(words) > at + 1 else ""
    args = words[at + 2 :]
    if sub in SIZED:
        if "--size" in args:
            i = args.index("--size")
            args[i + 1] = str(min(int(args[i + 1]), SIZE))
        elif sub != "bench":
            args += ["--size", str(SIZE)]
    if "--repeat" in args:
        i = args.index("--repeat")
        args[i + 1] = str(min(int(args[i + 1]), 3))
    if sub in WHOLE_LIBRARY and not any(a in args for a in ("--case", "--cases-dir", "--from", "--compare")):
        args += ["--case", "lambert"]
    if sub == "bench" and "--quick" not in args:
        args.append("--quick")
    if sub == "view":
        if "--screenshot" not in args:
            args += ["--screenshot", "view.png", "--frames", "2"]
        if words[0] != "xvfb-run":
            words, at = ["xvfb-run", "-a"] + words, at + 2
    return words[: at + 2] + args


def run_block(doc, line, block, source, binary, fixture):
    home = tempfile.mkdtemp(prefix="shaderbed-doc-")
    shutil.copytree(fixture, os.path.join(home, "port"))
    work = os.path.join(home, "work")
    os.makedirs(os.path.join(work, "build/bin"))
    os.symlink(binary, os.path.join(work, "build/bin/shaderbed"))
    for entry in ("shaders", "tests", "scripts", "docs"):
        os.symlink(os.path.join(source, entry), os.path.join(work, entry))
    env = dict(os.environ, HOME=home)
    prepared = set()   # case files the test wrote with init, for lines that use them
    for offset, words in (c for o, w in commands(block) for c in ((o, x) for x in loop(w))):
        where = f"{doc}:{line + offset}"
        text = " ".join(words)
        at = shaderbed_at(words)
        if at is None:
            program = words[0]
            if not (shutil.which(program) or os.path.exists(os.path.join(source, program))
                    or os.path.exists(os.path.join(os.path.dirname(binary), os.path.basename(program)))):
                failures.append(f"{where}: `{text}`: no program {program}")
            continue
        words = [os.path.expanduser(w).replace(os.path.expanduser("~"), home) for w in words]
        if words[at + 1 : at + 2] == ["init"]:
            # The case this init writes: one the test wrote for an earlier line goes first.
            shaders = [w for w in words[at + 2 :] if w.startswith(home) and not w.endswith(".toml")]
            target = words[words.index("--out") + 1] if "--out" in words else os.path.splitext(shaders[0])[0] + ".toml"
            if target in prepared:
                os.remove(target)
                prepared.discard(target)
        else:
            for w in words:
                stem, ext = os.path.splitext(w)
                if ext == ".toml" and w.startswith(home) and not os.path.exists(w):
                    originals = sorted(glob.glob(stem + ".*"), key=lambda p: (not p.endswith((".hlsl", ".fx")), p))
                    if originals:
                        subprocess.run([binary, "init", *originals, "--no-run"], cwd=work, env=env,
                                       capture_output=True, check=True)
                        prepared.add(w)
        words[at] = binary   # `shaderbed` in the docs is the binary under test
        command = adapt(words, at)
        started = time.monotonic()
        done = subprocess.run(command, cwd=work, env=env, capture_output=True, text=True, timeout=600)
        seconds = time.monotonic() - started
        if done.returncode not in (0, 1):
            tail = "\n".join((done.stdout + done.stderr).strip().splitlines()[-8:])
            failures.append(f"{where}: `{text}` exited {done.returncode}:\n{tail}")
        else:
            print(f"ok   {where}: {text}  ({seconds:.1f} s)")
    shutil.rmtree(home)


def check_case(doc, line, block, source, binary):
    where = f"{doc}:{line}"
    try:
        case = tomllib.loads(block)
    except tomllib.TOMLDecodeError as e:
        failures.append(f"{where}: the case example does not parse: {e}")
        return
    if re.search(r"^#.*\babridged\b", block, re.M):
        print(f"ok   {where}: abridged case parses")
        return
    if not (("model" in case or "reference" in case) and "variants" in case):
        failures.append(f"{where}: the case example names no model or reference and no variants, "
                        "and is not marked `# abridged: ...`")
        return
    # Its shader paths are the library's (shaders/) or the real-world corpus's.
    files = [v for variant in case["variants"].values() for lang in variant.values() if isinstance(lang, dict)
             for k, v in lang.items() if k in ("vertex", "fragment")]
    corpus = next((os.path.join(source, d) for d in ("tests/realworld", "shaders")
                   if all(os.path.exists(os.path.join(source, d, f)) for f in files)), None)
    if corpus is None:
        failures.append(f"{where}: the case example's shaders {files} are neither in tests/realworld/ nor in shaders/")
        return
    root = tempfile.mkdtemp(prefix="shaderbed-doc-case-")
    for entry in os.listdir(corpus):
        if entry != "cases":
            os.symlink(os.path.join(corpus, entry), os.path.join(root, entry))
    os.makedirs(os.path.join(root, "cases"))
    path = os.path.join(root, "cases", f"example_{line}.toml")
    with open(path, "w") as f:
        f.write(block)
    done = subprocess.run([binary, "run", "--case", path, "--size", str(SIZE), "-q"], capture_output=True, text=True)
    if done.returncode != 0:
        tail = "\n".join((done.stdout + done.stderr).strip().splitlines()[-8:])
        failures.append(f"{where}: the case example exited {done.returncode}:\n{tail}")
    else:
        print(f"ok   {where}: case example runs and passes")
    shutil.rmtree(root)


def main():
    source, binary = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    docs = sys.argv[3:] or ["README.md"] + sorted(os.path.relpath(p, source) for p in glob.glob(f"{source}/docs/*.md"))
    fixture = os.path.join(source, "tests/docs/port")
    for doc in docs:
        for kind, block, line in blocks(os.path.join(source, doc)):
            if kind == "sh":
                run_block(doc, line, block, source, binary, fixture)
            elif kind == "toml":
                check_case(doc, line, block, source, binary)
    if failures:
        print("\n".join(["", f"{len(failures)} documented example(s) do not run as written:"] + failures))
        sys.exit(1)


if __name__ == "__main__":
    main()
