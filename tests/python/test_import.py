"""`import parksim` as README's Python line runs it: from the repository's top folder, whose
C++ folder `parksim/` comes first on the path. With the built module on PYTHONPATH it is the
module; without it, the import fails with one line saying how to build it (issue 31: it was
an empty namespace package, and `parksim.load_world` an AttributeError)."""

import os
import pathlib
import subprocess
import sys

SOURCE_DIR = pathlib.Path(os.environ.get("PARKSIM_SOURCE_DIR",
                                         pathlib.Path(__file__).resolve().parents[2]))
BUILT = os.environ.get("PYTHONPATH", "")
# The entry of PYTHONPATH that holds the built package (conftest.py may put Gymnasium's first).
BUILT_DIR = next((p for p in BUILT.split(os.pathsep) if (pathlib.Path(p) / "parksim").is_dir()),
                 BUILT.split(os.pathsep)[0])


def python(code, cwd, pythonpath, *flags):
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    if pythonpath is not None:
        env["PYTHONPATH"] = pythonpath
    return subprocess.run([sys.executable, *flags, "-c", code], cwd=cwd, env=env,
                          capture_output=True, text=True, timeout=120)


def assert_one_line_how_to_build(p):
    assert p.returncode == 1, p
    lines = p.stderr.strip().splitlines()
    assert len(lines) == 1, p.stderr
    assert lines[0].startswith("ImportError: parksim: the compiled module is not built")
    assert "scripts/build.sh build" in lines[0] and "PYTHONPATH=" in lines[0]


def test_the_repository_root_with_the_built_module_imports_the_module():
    p = python("import parksim; print(parksim.__file__); "
               "print(parksim.load_world('worlds/head_in.yaml').name)", SOURCE_DIR, BUILT)
    assert p.returncode == 0, p.stderr
    module_file, world = p.stdout.split()
    assert pathlib.Path(module_file).parent == pathlib.Path(BUILT_DIR) / "parksim"
    assert world == "head_in"


def test_the_repository_root_without_the_module_says_how_to_build_it():
    # -S: no site directories, where an installed parksim would be found instead.
    assert_one_line_how_to_build(python("import parksim", SOURCE_DIR, None, "-S"))


def test_the_sources_without_the_compiled_module_say_how_to_build_it(tmp_path):
    assert_one_line_how_to_build(
        python("import parksim", tmp_path, str(SOURCE_DIR / "python"), "-S"))
