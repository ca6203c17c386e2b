"""`parksim compare BASELINE CANDIDATE` end to end on real small sweeps (issue 20, item 2):
the same spec twice is paired and passes; the same code under other noise seeds is unpaired
and passes; a candidate whose tracking errors grew by a fifth fails with exit 4, in Markdown
and in JUnit (read by junitparser when installed); bad input exits 2 and writes nothing.
"""

import json
import os
import pathlib
import shutil
import subprocess
import sys

import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("PARKSIM_SOURCE_DIR",
                                         pathlib.Path(__file__).resolve().parents[2]))
sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1] / "support"))
from sealed_rows import write_sealed  # noqa: E402  (tests/support/sealed_rows.py)


def parksim(*args, ok=(0,)):
    exe = os.environ.get("PARKSIM_EXE")
    if not exe:
        pytest.skip("PARKSIM_EXE is not set (run through ctest)")
    p = subprocess.run([exe, *map(str, args)], capture_output=True, text=True, timeout=600)
    assert p.returncode in ok, f"exit {p.returncode}: {p.stdout}{p.stderr}"
    return p


def spec(tmp, name, noise_from, noise_to):
    path = tmp / f"{name}.yaml"
    path.write_text(
        f"format: parksim-sweep/1\nname: {name}\nworlds: [head_in.yaml, parallel.yaml]\n"
        "planners: [hybrid-a-star]\nrealism: lab\n"
        f"noise_seeds: {{from: {noise_from}, to: {noise_to}}}\n", encoding="utf-8")
    return path


@pytest.fixture(scope="module")
def sweeps(tmp_path_factory):
    """Baseline: noise seeds 1..8; again: the same spec; other: noise seeds 9..16."""
    tmp = tmp_path_factory.mktemp("compare")
    for world in ("head_in", "parallel"):
        shutil.copy(SOURCE_DIR / "worlds" / f"{world}.yaml", tmp / f"{world}.yaml")
    runs = {"base": (1, 8), "again": (1, 8), "other": (9, 16)}
    for name, (a, b) in runs.items():
        parksim("sweep", spec(tmp, "ci", a, b) if name != "other" else spec(tmp, "ci2", a, b),
                "--out", tmp / name, "--workers", "2", ok=(0, 1))
    return tmp


def rows(path):
    return [json.loads(line) for line in path.read_text(encoding="utf-8").splitlines()]


def write_rows(path, table):
    write_sealed(path, table)


def test_the_same_spec_twice_is_paired_and_passes(sweeps):
    p = parksim("compare", sweeps / "base", sweeps / "again", "--markdown", sweeps / "same.md")
    md = (sweeps / "same.md").read_text(encoding="utf-8")
    assert md == p.stdout
    assert md.startswith("## parksim compare: no regression")
    assert md.count("8 paired") == 2  # one row per group says how it was compared


def test_other_noise_seeds_are_unpaired_and_pass(sweeps):
    p = parksim("compare", sweeps / "base", sweeps / "other" / "results.jsonl")
    assert "8 / 8 unpaired" in p.stdout
    assert p.stdout.startswith("## parksim compare: no regression")


def test_tracking_errors_a_fifth_larger_are_a_regression(sweeps):
    table = rows(sweeps / "again" / "results.jsonl")
    for row in table:
        if row["world"] == "head_in":
            row["max_pos_err_m"] *= 1.2
    write_rows(sweeps / "worse.jsonl", table)
    p = parksim("compare", sweeps / "base", sweeps / "worse.jsonl", "--junit",
                sweeps / "worse.xml", "--markdown", sweeps / "worse.md", ok=(4,))
    assert p.stdout.startswith("## parksim compare: regression")
    lines = [line for line in p.stdout.splitlines() if "**regression**" in line]
    assert lines and all("max tracking error" in line for line in lines)
    junitparser = pytest.importorskip("junitparser")
    xml = junitparser.JUnitXml.fromfile(str(sweeps / "worse.xml"))
    failed = [(suite.name, case.name) for suite in xml for case in suite
              if any(isinstance(r, junitparser.Failure) for r in case.result)]
    assert failed and all(s.startswith("head_in /") for s, _ in failed)
    assert {c for _, c in failed} <= {"max tracking error median", "max tracking error p95"}


def test_a_stricter_confidence_and_margin_are_honoured(sweeps):
    table = rows(sweeps / "again" / "results.jsonl")
    for row in table:
        row["max_pos_err_m"] *= 1.2
    write_rows(sweeps / "worse_all.jsonl", table)
    # A 30 % margin lets a 20 % growth pass.
    parksim("compare", sweeps / "base", sweeps / "worse_all.jsonl", "--max-increase-percent",
            "30")
    parksim("compare", sweeps / "base", sweeps / "worse_all.jsonl", "--confidence", "0.99",
            ok=(4,))


@pytest.mark.parametrize("args,message", [
    (["{tmp}/none", "{tmp}/base"], "no such file"),
    (["{tmp}/base", "{tmp}/base", "--confidence", "1.5"], "--confidence"),
    (["{tmp}/base", "{tmp}/base", "--junit", "{tmp}/no/such/r.xml"], "does not exist"),
])
def test_bad_input_exits_2_and_writes_nothing(sweeps, args, message):
    md = sweeps / "bad.md"
    args = [a.format(tmp=sweeps) for a in args]
    p = parksim("compare", *args, "--markdown", md, ok=(2,))
    assert message in p.stderr
    assert not md.exists()


def test_tables_without_a_common_group_are_bad_input(sweeps):
    table = rows(sweeps / "base" / "results.jsonl")
    for row in table:
        row["world"] = "elsewhere"
    write_rows(sweeps / "elsewhere.jsonl", table)
    p = parksim("compare", sweeps / "base", sweeps / "elsewhere.jsonl", ok=(2,))
    assert "no world / planner / realism group is in both" in p.stderr


def test_rows_of_another_world_content_are_flagged(sweeps):
    # As report does: a table whose rows come from two versions of a world is compared, but
    # not silently; the warning names the row.
    table = rows(sweeps / "again" / "results.jsonl")
    table[-1]["world_hash"] = "0" * 16
    write_rows(sweeps / "mixed.jsonl", table)
    p = parksim("compare", sweeps / "base", sweeps / "mixed.jsonl")
    assert "warning: " in p.stderr and "mixed.jsonl:%d" % len(table) in p.stderr
    clean = parksim("compare", sweeps / "base", sweeps / "again")
    assert "warning" not in clean.stderr
