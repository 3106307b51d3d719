#!/usr/bin/env python3
"""Slow probe (about 35 s): a shader whose compile never ends in reasonable time (a
preprocessor bomb, 2^33 tokens) stops `shaderbed init` after the compile child's 30 s
timeout with one `shaderbed:` line naming the file, exit 2 (the child is killed).
Usage: compile_timeout_probe.py BUILD/bin/shaderbed"""
import os
import subprocess
import sys
import tempfile
import time

SOURCE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "shaders", "hlsl", "setup_vs.hlsl")


def main() -> int:
    binary = sys.argv[1]
    with tempfile.TemporaryDirectory(prefix="shaderbed_timeout_") as d:
        lines = ["#define X0 n.x"] + [f"#define X{i} (X{i - 1} + X{i - 1})" for i in range(1, 34)]
        lines.append("float4 main(float3 n : TEXCOORD0) : COLOR0 { return float4(X33, 0, 0, 1); }")
        bomb = os.path.join(d, "bomb_ps.hlsl")
        with open(bomb, "w") as f:
            f.write("\n".join(lines) + "\n")
        vertex = os.path.join(d, "vs.hlsl")
        with open(SOURCE) as src, open(vertex, "w") as f:
            f.write(src.read())
        start = time.monotonic()
        run = subprocess.run([binary, "init", vertex, bomb, "--no-run", "--out", os.path.join(d, "c.toml")],
                             capture_output=True, text=True, timeout=120)
        seconds = time.monotonic() - start
        line = next((l for l in run.stderr.splitlines() if l.startswith("shaderbed: ")), "")
        ok = (run.returncode == 2 and "bomb_ps.hlsl" in line and "took longer than 30 s" in line and seconds < 60)
        print(f"exit {run.returncode} after {seconds:.1f} s: {line or run.stderr.strip()}")
        print("compile timeout probe:", "ok" if ok else "FAILED")
        return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
