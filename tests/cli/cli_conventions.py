#!/usr/bin/env python3
"""The command line as a Unix user expects it (issue 29): one-line refusals with the nearest
name, `help CMD`, colour only where it is wanted, help that fits the terminal, '-' for
standard output, --path like --backend, and a bash completion made from the options.

usage: cli_conventions.py CHECK SHADERBED   (CHECK: one of the functions below)
"""
import json
import os
import subprocess
import sys

SHADERBED = sys.argv[2] if len(sys.argv) > 2 else "shaderbed"
# One small cell: enough for a summary, a totals line and a verdict to colour.
ONE_CELL = ["run", "--case", "lambert", "--variant", "pixel", "--lang", "hlsl", "--backend", "vulkan",
            "--shape", "sphere", "--size", "16"]


def cli(args, env=None, merged=True):
    environment = dict(os.environ, **(env or {}))
    p = subprocess.run([SHADERBED] + args, stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT if merged else subprocess.PIPE, env=environment, timeout=120)
    out = p.stdout.decode()
    return (p.returncode, out) if merged else (p.returncode, out, p.stderr.decode())


def check(condition, what):
    if not condition:
        print("FAILED:", what)
        sys.exit(1)


def lines_of(text):
    return [l for l in text.split("\n") if l]


def parse_errors():
    for args, says in [("run --sise 16", "(did you mean '--size'?)"), ("runn", "(did you mean 'run'?)"),
                       ("run --twin duble", "(did you mean 'double'?)"),
                       ("run --keep-images al", "(did you mean 'all'?)"), ("run --size", "--size")]:
        status, out = cli(args.split())
        check(status == 2, f"{args}: exit {status}\n{out}")
        check(len(lines_of(out)) == 1, f"{args}: one line\n{out}")
        check(out.startswith("shaderbed: "), f"{args}: shaderbed: prefix\n{out}")
        check(says in out, f"{args}: says {says}\n{out}")


def help_command():
    status, out = cli(["help", "run"])
    check(status == 0, out)
    check(out == cli(["run", "--help"])[1], "help run == run --help\n" + out)
    status, top = cli(["help"])
    check(status == 0 and top == cli(["--help"])[1], "help == --help\n" + top)
    status, bad = cli(["help", "runn"])
    check(status == 2 and len(lines_of(bad)) == 1, bad)
    check("shaderbed: help: unknown command 'runn' (did you mean 'run'?)" in bad, bad)


def colour():
    status, out = cli(ONE_CELL + ["--color", "always"])
    check(status == 0, out)
    check("\033[32m" in out, "a pass is green with --color always:\n" + out)
    # --table: the verdict word is tinted, and the columns after it stay where the header has them.
    status, out = cli(ONE_CELL + ["--table", "--color", "always"])
    rows = [l for l in out.split("\n") if l.startswith("lambert ") or l.startswith("case ")]
    check(status == 0 and len(rows) >= 2 and "\033[32mpass\033[0m" in rows[1], "--table tints pass:\n" + out)
    plain = [l.replace("\033[32m", "").replace("\033[0m", "") for l in rows]
    check(plain[1].index("pass") == plain[0].index("verdict"), "--table columns stay aligned:\n" + "\n".join(plain))
    # A pipe, --color never, or NO_COLOR with auto: no escape codes at all.
    for args, env in [(["--color", "never"], None), ([], None), (["--color", "auto"], {"NO_COLOR": "1"})]:
        status, out = cli(ONE_CELL + args, env)
        check(status == 0, out)
        check("\033" not in out, f"{args} {env}: no escape codes\n{out}")
    status, out = cli(["--color", "sometimes"] + ONE_CELL)
    check(status == 2 and out.startswith("shaderbed: "), out)


def help_format():
    status, out = cli(["run", "--help"], {"COLUMNS": "100"})
    check(status == 0, out)
    long_lines = [l for l in out.split("\n") if len(l) > 100]
    check(not long_lines, "lines over 100 columns:\n" + "\n".join(long_lines))
    check(" TEXT" not in out, "a TEXT placeholder:\n" + out)
    check(" FILE" in out and " DIR" in out and " LIST" in out, "typed placeholders:\n" + out)
    check(os.path.dirname(os.path.abspath(__file__)).split("/tests")[0] not in out,
          "an absolute source path:\n" + out)
    status, narrow = cli(["run", "--help"], {"COLUMNS": "80"})
    check(all(len(l) <= 80 for l in narrow.split("\n") if not l.lstrip().startswith("-")),
          "descriptions wrapped to 80:\n" + narrow)


def json_stdout():
    status, out, err = cli(ONE_CELL + ["--json", "-", "-q"], merged=False)
    check(status == 0, out + err)
    report = json.loads(out)
    check(len(report["results"]) == 1, out)
    check("1 cells: 1 passed" in err, "the totals go to stderr:\n" + err)


def json_stdout_for_tables():
    """stats, sweep and hard print a table as they go: with --json - it moves to stderr and
    stdout is the JSON alone, with no file named '-' left behind."""
    for args, key in [(["stats", "--case", "lambert", "--variant", "pixel", "--no-nir"], "entries"),
                      (["sweep", "lambert", "--variant", "pixel", "--size", "16", "--repeat", "1", "--warmup", "0"],
                       "points"),
                      (["hard", "--case", "lambert", "--backend", "vulkan", "--size", "16"], "rows")]:
        status, out, err = cli(args + ["--json", "-"], merged=False)
        check(status in (0, 1), f"{args[0]}: exit {status}\n" + out + err)
        try:
            report = json.loads(out)
        except json.JSONDecodeError as e:
            check(False, f"{args[0]}: stdout is not JSON ({e}):\n{out[:2000]}")
        check(isinstance(report, dict) and report.get(key), f"{args[0]}: the JSON has its {key}:\n{out[:2000]}")
        check("lambert" in err, f"{args[0]}: the table went to stderr:\n{err}")
        check(not os.path.exists("-"), f"{args[0]}: wrote a file named '-'")


def path_filter():
    status, out, err = cli(["run", "--case", "lambert", "--path", "cross", "--size", "16", "--shape", "sphere",
                            "--variant", "pixel", "--json", "-", "-q"], merged=False)
    check(status == 0, out + err)
    paths = {r["path"] for r in json.loads(out)["results"]}
    check(paths == {"cross"}, f"only cross cells: {paths}")
    status, out = cli(["run", "--case", "lambert", "--path", "crosss", "--size", "16"])
    check(status == 2 and "did you mean 'cross'" in out and len(lines_of(out)) == 1, out)


def bash_completion():
    status, script = cli(["completion", "bash"], merged=False)[:2]
    check(status == 0 and "-F _shaderbed shaderbed" in script, script)
    def complete(words):
        line = " ".join(words)
        program = (script + f"\nCOMP_WORDS=({line}); COMP_CWORD={len(words) - 1}; COMP_LINE='{line}'; "
                   f"COMP_POINT={len(line)}; _shaderbed; printf '%s\\n' \"${{COMPREPLY[@]}}\"\n")
        p = subprocess.run(["bash", "-c", program], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=30)
        return p.stdout.decode().split()
    check(complete(["shaderbed", "ru"]) == ["run"], complete(["shaderbed", "ru"]))
    check(complete(["shaderbed", "run", "--ba"]) == ["--backend"], complete(["shaderbed", "run", "--ba"]))
    check(complete(["shaderbed", "run", "--twin", "d"]) == ["double"], "IsMember values complete")


if __name__ == "__main__":
    globals()[sys.argv[1]]()
    print("ok")
