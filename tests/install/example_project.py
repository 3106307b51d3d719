#!/usr/bin/env python3
"""shaderbed installed and called from a project of its own (issue 29, item 4).

`cmake --install BUILD --prefix TMP/prefix` (no rebuild: it copies what `shaderbed` built),
then, from a folder that is neither the source nor the build tree:
  - the installed files are where docs/install.md says;
  - the installed binary reads its cases from the installed tree (a case that exists only
    there runs, with no --cases-dir) and dlopens the installed image module;
  - SHADERBED_ROOT overrides that (its case runs, a library case is then unknown);
  - tests/install/example, configured with -DCMAKE_PREFIX_PATH=TMP/prefix, registers its
    case through shaderbed_add_cases(): one test per backend for its GLSL-only case and
    none for HLSL, labelled, and its ctest passes.

usage: example_project.py SOURCE_DIR BUILD_DIR CMAKE CTEST GENERATOR SHADERBED
"""
import os
import shutil
import subprocess
import sys
import tempfile

source, build, cmake, ctest, generator, built_binary = sys.argv[1:7]
example = os.path.join(source, "tests", "install", "example")


def fail(message, result=None):
    print("install.example_project: " + message)
    if result is not None:
        print("--- stdout\n" + result.stdout + "\n--- stderr\n" + result.stderr[-6000:])
    sys.exit(1)


def run(args, cwd, env=None, expect=0):
    r = subprocess.run(args, cwd=cwd, env=env, capture_output=True, text=True, timeout=300)
    if expect is not None and r.returncode != expect:
        fail(f"{' '.join(args)} exited {r.returncode}, expected {expect}", r)
    return r


def copy_example_case(shaders, case_name):
    """The example's case and its GLSL under SHADERS (a shaders/ folder), named CASE_NAME."""
    os.makedirs(os.path.join(shaders, "cases"), exist_ok=True)
    os.makedirs(os.path.join(shaders, "glsl"), exist_ok=True)
    shutil.copy(os.path.join(example, "cases", "matte.toml"), os.path.join(shaders, "cases", case_name + ".toml"))
    for name in ("matte.vert", "matte.frag"):
        shutil.copy(os.path.join(example, "glsl", name), os.path.join(shaders, "glsl", name))


with tempfile.TemporaryDirectory(prefix="shaderbed-install-") as tmp:
    prefix = os.path.join(tmp, "prefix")
    elsewhere = os.path.join(tmp, "elsewhere")
    os.makedirs(elsewhere)
    env = {k: v for k, v in os.environ.items() if k != "SHADERBED_ROOT"}

    if not os.path.isfile(built_binary):
        fail(f"{built_binary} is not built: the install copies what `shaderbed` built")
    built_at = os.stat(built_binary).st_mtime_ns
    run([cmake, "--install", build, "--prefix", prefix], cwd=elsewhere, env=env)
    if os.stat(built_binary).st_mtime_ns != built_at:
        fail("installing rebuilt the program")
    binary = os.path.join(prefix, "bin", "shaderbed")
    for relative in ("bin/shaderbed", "bin/shaderbed-nir-dump", "lib/shaderbed/libshaderbed_imageio.so",
                     "share/shaderbed/shaders/cases/lambert.toml", "share/shaderbed/shaders/glsl/lambert.frag",
                     "share/shaderbed/shaders/expectations.toml", "share/doc/shaderbed/README.md",
                     "share/doc/shaderbed/install.md", "lib/cmake/shaderbed/shaderbedConfig.cmake",
                     "lib/cmake/shaderbed/shaderbedConfigVersion.cmake", "lib/cmake/shaderbed/ShaderbedCases.cmake"):
        if not os.path.isfile(os.path.join(prefix, relative)):
            fail(f"the install has no {relative}")

    # The installed tree's own cases are the default: a case only the install holds runs.
    copy_example_case(os.path.join(prefix, "share", "shaderbed", "shaders"), "installed_only")
    cell = ["--backend", "vulkan", "--lang", "glsl", "--shape", "sphere", "--size", "16", "--repeat", "0", "-q"]
    out = os.path.join(tmp, "out")
    # The dynamic loader's own log (of the supervisor and its workers) names the module opened.
    loader_log = os.path.join(tmp, "loader")
    os.makedirs(loader_log)
    r = run([binary, "run", "--case", "installed_only", *cell, "--out", out, "--keep-images", "all"], cwd=elsewhere,
            env={**env, "LD_DEBUG": "files", "LD_DEBUG_OUTPUT": os.path.join(loader_log, "ld")})
    module = os.path.join(prefix, "lib", "shaderbed", "libshaderbed_imageio.so")
    opened = "".join(open(os.path.join(loader_log, name), errors="replace").read() for name in os.listdir(loader_log))
    if f"file={module}" not in opened:
        fail("the installed binary did not dlopen the installed image module " + module, r)
    if not any(name.endswith(".png") for _, _, files in os.walk(out) for name in files):
        fail("the installed binary wrote no image into --out", r)

    # SHADERBED_ROOT wins over the installed tree.
    root = os.path.join(tmp, "root")
    copy_example_case(os.path.join(root, "shaders"), "only_in_root")
    run([binary, "run", "--case", "only_in_root", *cell], cwd=elsewhere, env={**env, "SHADERBED_ROOT": root})
    r = run([binary, "run", "--case", "lambert", *cell], cwd=elsewhere, env={**env, "SHADERBED_ROOT": root}, expect=None)
    if r.returncode == 0:
        fail("with SHADERBED_ROOT set, the installed library's lambert case still ran", r)

    # The example project against the installed package.
    example_build = os.path.join(tmp, "example-build")
    run([cmake, "-S", example, "-B", example_build, "-G", generator, "-DCMAKE_PREFIX_PATH=" + prefix],
        cwd=elsewhere, env=env)
    run([cmake, "--build", example_build], cwd=elsewhere, env=env)
    listed = run([ctest, "--test-dir", example_build, "-N"], cwd=elsewhere, env=env).stdout
    names = sorted(line.split(": ", 1)[1].strip() for line in listed.splitlines() if ": example." in line)
    if names != ["example.matte.gl.glsl", "example.matte.vulkan.glsl"]:
        fail(f"the example registered {names}, expected one GLSL test per backend and no HLSL test:\n{listed}")
    for label, expected in (("^vulkan$", 1), ("^gl$", 1), ("^glsl$", 2), ("^shaderbed$", 2), ("^hlsl$", 0)):
        listed = run([ctest, "--test-dir", example_build, "-N", "-L", label], cwd=elsewhere, env=env).stdout
        if f"Total Tests: {expected}" not in listed:
            fail(f"ctest -N -L '{label}' should list {expected} tests:\n{listed}")
    r = run([ctest, "--test-dir", example_build, "--output-on-failure"], cwd=elsewhere, env=env)
    if "100% tests passed, 0 tests failed out of 2" not in r.stdout:
        fail("the example's ctest did not run and pass its 2 tests", r)
    print("install.example_project: installed, ran from elsewhere, and the example's 2 tests passed")
