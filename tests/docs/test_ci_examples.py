"""The CI recipe (issue 20, item 3): examples/ci/'s GitLab job and GitHub workflow parse and
call the recipe's script, docs/ci.md shows them as they are, and the script itself runs: a
small sweep stored as the baseline, checked against it (no regression, exit 0), then against a
baseline that was better than the code is now (a regression, exit 4), with JUnit and Markdown
written for the CI page.
"""

import json
import os
import pathlib
import re
import shutil
import subprocess
import sys

import pytest

yaml = pytest.importorskip("yaml")

SOURCE_DIR = pathlib.Path(os.environ.get("PARKSIM_SOURCE_DIR",
                                         pathlib.Path(__file__).resolve().parents[2]))
sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1] / "support"))
from sealed_rows import write_sealed  # noqa: E402  (tests/support/sealed_rows.py)
CI = SOURCE_DIR / "examples" / "ci"
SCRIPT = CI / "parksim-ci.sh"


def load(path):
    return yaml.safe_load(path.read_text(encoding="utf-8"))


def doc_yaml_blocks():
    """The yaml blocks of docs/ci.md, parsed."""
    text = (SOURCE_DIR / "docs" / "ci.md").read_text(encoding="utf-8")
    return [yaml.safe_load(b) for b in re.findall(r"^```yaml\n(.*?)^```", text, re.S | re.M)]


def test_gitlab_job_parses_and_publishes_junit():
    doc = load(CI / "gitlab-ci.yml")
    job = doc["parksim-regression"]
    assert job["extends"] == ".parksim"
    assert "examples/ci/parksim-ci.sh check" in job["script"]
    assert set(job["artifacts"]["reports"]["junit"]) == {"parksim-ci/sweep.xml",
                                                        "parksim-ci/compare.xml"}
    assert job["artifacts"]["when"] == "always"
    base = doc[".parksim"]
    assert any("build.sh" in line for line in base["before_script"])
    assert doc["parksim-refresh-baseline"]["when"] == "manual"
    assert "examples/ci/parksim-ci.sh refresh" in doc["parksim-refresh-baseline"]["script"]


def test_github_workflow_parses_checks_and_publishes_junit():
    doc = load(CI / "github-workflow.yml")
    triggers = doc.get("on", doc.get(True))  # YAML 1.1 reads a bare `on` as true
    assert {"push", "pull_request", "workflow_dispatch"} <= set(triggers)
    steps = doc["jobs"]["parksim"]["steps"]
    runs = " ".join(s.get("run", "") for s in steps)
    assert "examples/ci/parksim-ci.sh check" in runs
    assert "examples/ci/parksim-ci.sh refresh" in runs
    uses = [s.get("uses", "") for s in steps]
    assert any(u.startswith("actions/checkout@") for u in uses)
    assert any(u.startswith("mikepenz/action-junit-report@") for u in uses)


def test_docs_show_the_example_jobs_as_they_are():
    blocks = doc_yaml_blocks()
    assert load(CI / "gitlab-ci.yml") in blocks
    assert load(CI / "github-workflow.yml") in blocks


def parksim_exe():
    exe = os.environ.get("PARKSIM_EXE")
    if not exe:
        pytest.skip("PARKSIM_EXE is not set (run through ctest)")
    return exe


def test_the_example_sweep_expands(tmp_path):
    p = subprocess.run([parksim_exe(), "sweep", CI / "sweep.yaml", "--slurm", "--out",
                        tmp_path / "out"], capture_output=True, text=True, timeout=120)
    assert p.returncode == 0, p.stderr
    assert "20 episodes" in p.stdout + p.stderr


def run_script(mode, env, cwd):
    return subprocess.run(["sh", SCRIPT, mode], env=env, cwd=cwd, capture_output=True,
                          text=True, timeout=600)


@pytest.fixture(scope="module")
def job(tmp_path_factory):
    """The script's environment as a CI job sets it, with a small sweep (one world, five noise
    seeds of the lab robot) so the test stays short."""
    tmp = tmp_path_factory.mktemp("ci")
    shutil.copy(SOURCE_DIR / "worlds" / "head_in.yaml", tmp / "head_in.yaml")
    (tmp / "small.yaml").write_text(
        "format: parksim-sweep/1\nname: ci-small\nworlds: [head_in.yaml]\n"
        "planners: [hybrid-a-star]\nrealism: lab\nnoise_seeds: {from: 1, to: 6}\n",
        encoding="utf-8")
    env = dict(os.environ, PARKSIM=parksim_exe(), SPEC=str(tmp / "small.yaml"),
               BASELINE=str(tmp / "ci" / "baseline" / "results.jsonl"), OUT=str(tmp / "job"),
               GITHUB_STEP_SUMMARY=str(tmp / "summary.md"))
    p = run_script("refresh", env, tmp)
    assert p.returncode == 0, p.stderr
    return tmp, env


def test_refresh_stores_the_sweeps_table_as_the_baseline(job):
    tmp, env = job
    baseline = pathlib.Path(env["BASELINE"])
    assert baseline.read_bytes() == (tmp / "job" / "sweep" / "results.jsonl").read_bytes()
    assert len(baseline.read_text().splitlines()) == 6


def test_check_against_the_same_code_passes_with_reports(job):
    tmp, env = job
    summary = tmp / "summary.md"
    summary.unlink(missing_ok=True)
    p = run_script("check", env, tmp)
    assert p.returncode == 0, p.stdout + p.stderr
    for name in ("sweep.xml", "compare.xml", "compare.md", "compare.html",
                 "sweep/report/index.html"):
        assert (tmp / "job" / name).is_file(), name
    xml = (tmp / "job" / "sweep.xml").read_text(encoding="utf-8")
    assert 'name="html_report" value="sweep/report/index.html"' in xml
    md = (tmp / "job" / "compare.md").read_text(encoding="utf-8")
    assert md.startswith("## parksim compare: no regression")
    assert "6 paired" in md
    assert summary.read_text(encoding="utf-8") == md


def test_check_fails_with_exit_4_when_the_code_got_worse(job):
    tmp, env = job
    # A baseline from better code: every tracking error two thirds of today's.
    rows = [json.loads(line) for line in pathlib.Path(env["BASELINE"]).read_text().splitlines()]
    for row in rows:
        row["max_pos_err_m"] *= 2.0 / 3.0
    better = tmp / "better.jsonl"
    write_sealed(better, rows)
    p = run_script("check", dict(env, BASELINE=str(better)), tmp)
    assert p.returncode == 4, p.stdout + p.stderr
    md = (tmp / "job" / "compare.md").read_text(encoding="utf-8")
    assert md.startswith("## parksim compare: regression")
    assert "**regression**" in md
    xml = (tmp / "job" / "compare.xml").read_text(encoding="utf-8")
    assert re.search(r'<testsuites [^>]*failures="[1-9]', xml)


def test_a_missing_baseline_is_bad_input(job):
    tmp, env = job
    p = run_script("check", dict(env, BASELINE=str(tmp / "none.jsonl")), tmp)
    assert p.returncode == 2
    assert "none.jsonl" in p.stderr
