#!/usr/bin/env python3
"""Slow probe of the isolated run's supervisor at random times (issue 30, items 5 and 13).

Each trial starts `shaderbed run` on a few library cases and, after a random delay, does
one of: SIGKILL a random worker (repeatedly, so replacements die too, some before their
hello), SIGSTOP a random worker (the step deadline must end it), SIGHUP the run, or SIGINT
it twice in quick succession. Whatever happens, the run must end by itself (no hang) and
write its JSON report: complete, or marked incomplete after a signal to the run.

  tests/reliability/supervisor_signals.py SOURCE BINARY [--slow] [--trials N] [--seed S]

(as scripts/test --reliability calls it: 40 trials with --slow, 4 without).
"""
import argparse
import json
import os
import random
import signal
import subprocess
import sys
import tempfile
import time


def workers_of(pid):
    """The run's worker processes: children of `pid` started as `__cell-worker`."""
    found = []
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open(f"/proc/{entry}/stat") as f:
                fields = f.read().rsplit(")", 1)[1].split()
            with open(f"/proc/{entry}/cmdline", "rb") as f:
                cmdline = f.read()
        except OSError:
            continue
        if int(fields[1]) == pid and b"__cell-worker" in cmdline:
            found.append(int(entry))
    return found


def trial(binary, rng, folder):
    report = os.path.join(folder, "r.json")
    if os.path.exists(report):
        os.remove(report)
    command = [binary, "run", "--case", "lambert,phong,blinn_phong", "--size", "64", "--repeat", "0", "-j2", "-q",
               "--step-timeout", "3", "--json", report]
    run = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    action = rng.choice(["kill-workers", "stop-worker", "hup", "int-twice"])
    time.sleep(rng.uniform(0.05, 3.0))
    if action == "kill-workers":
        for _ in range(rng.randint(1, 6)):
            for pid in workers_of(run.pid)[:1]:
                os.kill(pid, signal.SIGKILL)
            time.sleep(rng.uniform(0.0, 0.3))
    elif action == "stop-worker":
        for pid in workers_of(run.pid)[:1]:
            os.kill(pid, signal.SIGSTOP)
    elif action == "hup":
        run.send_signal(signal.SIGHUP)
    else:
        run.send_signal(signal.SIGINT)
        time.sleep(rng.uniform(0.0, 0.05))
        run.send_signal(signal.SIGINT)
    try:
        _, err = run.communicate(timeout=300)
    except subprocess.TimeoutExpired:
        run.kill()
        return f"{action}: hung"
    if run.returncode < 0:
        return f"{action}: ended by signal {-run.returncode} ({err.decode(errors='replace')[-300:]})"
    if not os.path.exists(report):
        return f"{action}: exit {run.returncode} and no report ({err.decode(errors='replace')[-300:]})"
    with open(report) as f:
        j = json.load(f)
    if action in ("hup", "int-twice") and run.returncode in (129, 130) and "incomplete" not in j:
        return f"{action}: interrupted (exit {run.returncode}) but the report is not marked incomplete"
    return None


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("source", help="the source folder (unused: the library's cases are the binary's)")
    parser.add_argument("binary")
    parser.add_argument("--slow", action="store_true", help="40 trials rather than 4")
    parser.add_argument("--trials", type=int)
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()
    args.trials = args.trials or (40 if args.slow else 4)
    rng = random.Random(args.seed)
    failures = []
    with tempfile.TemporaryDirectory(prefix="supervisor-signals-") as folder:
        for i in range(args.trials):
            problem = trial(args.binary, rng, folder)
            print(f"trial {i + 1}/{args.trials}: {problem or 'ok'}", flush=True)
            if problem:
                failures.append(problem)
    print(f"{len(failures)} of {args.trials} trials lost a report or hung")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
