#!/usr/bin/env python3
"""Slow probe (scripts/test --reliability): ROUNDS rounds of RUNS concurrent `shaderbed run
--save-images` into one folder, each run a different case (one tiny cell); every run's
entry must be in the manifest and its image in the folder afterwards, and no staging
folder may be left. The fast check is StoredImages.ConcurrentSavesIntoOneFolderKeepEveryEntry.

  concurrent_save_images.py SHADERBED [--rounds 10] [--runs 8]
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CASES = ["lambert", "phong", "blinn_phong", "minnaert", "oren_nayar", "ward_iso", "ward_aniso", "cook_torrance",
         "schlick", "spot", "point_attenuated", "ambient"]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("shaderbed")
    ap.add_argument("--rounds", type=int, default=10)
    ap.add_argument("--runs", type=int, default=8)
    a = ap.parse_args()
    cases = CASES[: a.runs]
    lost_rounds = 0
    for round_ in range(a.rounds):
        with tempfile.TemporaryDirectory(prefix="shaderbed_concurrent_") as tmp:
            shared = os.path.join(tmp, "shared")
            runs = [subprocess.Popen([a.shaderbed, "run", "--case", c, "--cases-dir", os.path.join(ROOT, "shaders/cases"),
                                      "--variant", "pixel", "--lang", "glsl", "--backend", "vulkan", "--shape", "sphere",
                                      "--size", "16", "--repeat", "0", "-q", "--jobs", "1", "--save-images", shared],
                                     stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True) for c in cases]
            for c, p in zip(cases, runs):
                _, err = p.communicate()
                if p.returncode != 0:
                    print(f"round {round_}: {c} exited {p.returncode}: {err.strip()}")
            with open(os.path.join(shared, "manifest.json")) as f:
                images = json.load(f)["images"]
            lost = [c for c in cases if f"{c}/pixel/glsl/vulkan/spirv/sphere" not in images]
            lost += [c for c in cases if f"{c}/pixel/glsl/vulkan/spirv/sphere" in images and not os.path.exists(
                os.path.join(shared, images[f"{c}/pixel/glsl/vulkan/spirv/sphere"]["file"]))]
            staging = [n for n in os.listdir(shared) if n.startswith(".staging")]
            if lost or staging:
                lost_rounds += 1
                print(f"round {round_}: lost {lost}, staging left {staging}")
    print(f"{lost_rounds} of {a.rounds} rounds lost entries")
    return 1 if lost_rounds else 0


if __name__ == "__main__":
    sys.exit(main())
