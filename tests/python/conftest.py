"""Shared fixtures: the source tree, the parksim executable (PARKSIM_EXE, set by ctest) and the
study's worlds. Run through ctest, which puts the build's module on PYTHONPATH."""

import os
import pathlib
import subprocess

import pytest

import parksim

SOURCE_DIR = pathlib.Path(os.environ.get("PARKSIM_SOURCE_DIR",
                                         pathlib.Path(__file__).resolve().parents[2]))


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
