"""Shared fixtures: the source tree, the parksim executable (PARKSIM_EXE, set by ctest), the
study's worlds and Gymnasium. Run through ctest, which puts the build's module on PYTHONPATH."""

import os
import pathlib
import subprocess
import sys

import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("PARKSIM_SOURCE_DIR",
                                         pathlib.Path(__file__).resolve().parents[2]))

# Gymnasium (Debian packages none, and no package index is reachable): Gymnasium 1.3.0's
# unchanged source and a stand-in for farama-notifications, from PARKSIM_THIRD_PARTY, by default
# ../shared/third_party beside the source tree, where the project's machines and CI have it
# (its README.md; Debian's python3-cloudpickle and python3-typing-extensions complete it). On
# the path before parksim is imported (parksim.env subclasses gymnasium.Env only when it can
# import it), and on PYTHONPATH for the tests' child processes.
THIRD_PARTY = pathlib.Path(os.environ.get("PARKSIM_THIRD_PARTY")
                           or SOURCE_DIR.parent / "shared" / "third_party")
GYMNASIUM_DIR = THIRD_PARTY / "gymnasium-1.3.0"
if GYMNASIUM_DIR.is_dir():
    _dirs = [str(GYMNASIUM_DIR), str(THIRD_PARTY / "stubs")]
    sys.path[:0] = _dirs
    os.environ["PYTHONPATH"] = os.pathsep.join(_dirs + [os.environ.get("PYTHONPATH", "")])

import parksim  # noqa: E402


def gymnasium_or_skip():
    """gymnasium, or a skip saying where it was looked for."""
    try:
        import gymnasium
    except ImportError as e:
        pytest.skip(f"Gymnasium not importable ({e}): looked for {GYMNASIUM_DIR} "
                    f"(PARKSIM_THIRD_PARTY, default ../shared/third_party beside the source tree)")
    return gymnasium


def pytest_report_header(config):
    try:
        import gymnasium
    except ImportError:
        return f"gymnasium: not importable (looked for {GYMNASIUM_DIR})"
    return f"gymnasium: {gymnasium.__version__} from {pathlib.Path(gymnasium.__file__).parent}"


@pytest.fixture(scope="session")
def source_dir():
    return SOURCE_DIR


@pytest.fixture(scope="session")
def head_in_path():
    return SOURCE_DIR / "worlds" / "head_in.yaml"


@pytest.fixture(scope="session")
def head_in(head_in_path):
    return parksim.load_world(head_in_path)


@pytest.fixture(scope="session")
def head_in_plan(head_in):
    plan = parksim.plan(head_in, seed=1)
    assert plan.solved, plan.message
    return plan


def run_cli(*args):
    """Runs the parksim executable; returns (exit code, stdout, stderr)."""
    exe = os.environ.get("PARKSIM_EXE")
    if not exe:
        pytest.skip("PARKSIM_EXE is not set (run through ctest)")
    p = subprocess.run([exe, *map(str, args)], capture_output=True, text=True, timeout=120)
    return p.returncode, p.stdout, p.stderr
