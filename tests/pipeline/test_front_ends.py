"""One pipeline, one verdict, one set of defaults: the same episode through `parksim run`,
`parksim run --realisations`, `parksim sweep` and Python's run() gives the same status, the same
one-line reason and (for the single-episode command) the exit code of that status; and every
front-end left at its defaults runs with the same settings, read back from what each recorded.

Run through ctest (PARKSIM_EXE, PYTHONPATH and PARKSIM_SOURCE_DIR set)."""

import json
import os
import pathlib
import re
import subprocess

import pytest

import parksim

SOURCE_DIR = pathlib.Path(os.environ.get("PARKSIM_SOURCE_DIR",
                                         pathlib.Path(__file__).resolve().parents[2]))
WORLDS = SOURCE_DIR / "tests" / "pipeline" / "worlds"
EXIT_CODE = {"met": 0, "plan_failed": 1, "contact": 4, "goal_missed": 4, "tolerance_missed": 4}


def parksim_exe():
    exe = os.environ.get("PARKSIM_EXE")
    if not exe:
        pytest.skip("PARKSIM_EXE is not set (run through ctest)")
    return exe


def cli(*args):
    p = subprocess.run([parksim_exe(), *map(str, args)], capture_output=True, text=True,
                       timeout=600)
    return p.returncode, p.stdout, p.stderr


# Each case: the world, its noise seed, its planning budget (None: the library's), and the
# status it must end in (None: whatever it is, as long as every front-end agrees).
CASES = [
    ("straight.yaml", 1, None, "met"),
    ("walled_goal.yaml", 1, 40, "plan_failed"),
    ("straight_wall.yaml", 1, None, "contact"),
    ("straight_drifting.yaml", 1, None, "goal_missed"),
    ("straight_strict.yaml", 1, None, "tolerance_missed"),
    # Issue 17's case: `run` said contact, a sweep said met, Python said nothing.
    ("head_in_lenient.yaml", 5, None, None),
]


def budget_args(budget):
    return [] if budget is None else ["--max-iterations", budget]


def verdict_line(stderr):
    lines = [line for line in stderr.splitlines() if line.startswith("parksim run: ")]
    return lines[-1][len("parksim run: "):] if lines else ""


def via_run(world, seed, budget, out):
    code, _, err = cli("run", world, "--noise-seed", seed, *budget_args(budget), "--out", out)
    status, reason = "plan_failed", verdict_line(err)
    metrics_path = out / "metrics.json"
    if metrics_path.exists():
        metrics = json.loads(metrics_path.read_text())
        status, recorded = metrics["status"], metrics["failure"]
        assert recorded == reason, (recorded, reason)
    return status, reason, code


def via_realisations(world, seed, budget, out):
    code, _, err = cli("run", world, "--noise-seed", seed, "--realisations", 3,
                       *budget_args(budget), "--out", out)
    line = verdict_line(err)
    # "N of 3 realisations failed; first (noise seed S): REASON"
    match = re.match(r"(\d) of 3 realisations failed; first \(noise seed (\d+)\): (.*)$", line)
    reason = match.group(3) if match else line
    metrics_path = out / "metrics.json"
    status = json.loads(metrics_path.read_text())["status"] if metrics_path.exists() \
        else "plan_failed"
    return status, reason, code


def via_sweep(world, seed, budget, out):
    spec = out.parent / (out.name + ".yaml")
    lines = ["format: parksim-sweep/1", "name: one", f"worlds: ['{world}']",
             f"noise_seeds: [{seed}]"]
    if budget is not None:
        lines.append(f"max_iterations: [{budget}]")
    spec.write_text("\n".join(lines) + "\n")
    code, _, err = cli("sweep", spec, "--out", out, "--workers", 1)
    assert code in (0, 1), err  # 1: some episode did not meet its tolerance
    rows = [json.loads(line) for line in (out / "results.jsonl").read_text().splitlines()]
    assert len(rows) == 1
    return rows[0]["status"], rows[0]["failure"], None


def via_python(world, seed, budget):
    options = {"noise_seed": seed}
    if budget is not None:
        options["max_iterations"] = budget
    run = parksim.run(parksim.load_world(world), **options)
    return run.status, run.reason, None


@pytest.mark.parametrize("name,seed,budget,expected", CASES, ids=[c[0] for c in CASES])
def test_every_front_end_gives_the_same_verdict(tmp_path, name, seed, budget, expected):
    world = WORLDS / name
    single = via_run(world, seed, budget, tmp_path / "run")
    if expected is not None:
        assert single[0] == expected, single
    assert single[2] == EXIT_CODE[single[0]], single
    assert (single[1] == "") == (single[0] == "met"), single
    # The same episode through the three other doors.
    assert via_sweep(world, seed, budget, tmp_path / "sweep")[:2] == single[:2]
    assert via_python(world, seed, budget)[:2] == single[:2]
    if name != "head_in_lenient.yaml":  # its realisations draw other calibrations
        assert via_realisations(world, seed, budget, tmp_path / "many") == single


SETTING_KEYS = [
    "plan_planner", "plan_steering", "plan_timing", "plan_max_iterations", "plan_seed",
    "plan_smooth", "plan_feedback_headroom", "plan_time_limit_s",
    "plan_motion_check_resolution_m", "tracking", "realism", "noise_seed", "estimator",
    "tolerance.max_pos_err_m", "tolerance.goal_pos_err_m", "tolerance.goal_heading_err_deg",
    "tolerance.max_contacts", "tolerance.max_parked_displacement_m",
]
# Measured in wall-clock time, or naming the machine, the build or the file it was read from.
VARYING = re.compile(r"^(provenance\.|plan_planning_time_s|plan_phase_times_s\.|"
                     r"plan_first_solution_s|wall_time_s|real_time_factor|world$)")


def comparable(metrics):
    return {k: v for k, v in metrics.items() if not VARYING.match(k)}


def test_defaults_are_the_same_everywhere(tmp_path):
    world = SOURCE_DIR / "worlds" / "head_in.yaml"
    code, _, err = cli("run", world, "--out", tmp_path / "run")
    assert code == 0, err
    from_run = json.loads((tmp_path / "run" / "metrics.json").read_text())

    spec = tmp_path / "defaults.yaml"
    spec.write_text(f"format: parksim-sweep/1\nname: defaults\nworlds: ['{world}']\n"
                    "record: {executed_csv: all}\n")
    code, _, err = cli("sweep", spec, "--out", tmp_path / "sweep", "--workers", 1)
    assert code == 0, err
    row = json.loads((tmp_path / "sweep" / "results.jsonl").read_text().splitlines()[0])
    from_sweep = json.loads(
        (tmp_path / "sweep" / "episodes" / row["episode_id"] / "metrics.json").read_text())

    from_python = parksim.run(parksim.load_world(world)).metrics

    for key in SETTING_KEYS:
        assert key in from_run, key
        assert from_sweep[key] == from_run[key], key
        assert from_python[key] == from_run[key], key
    # Not only the settings: the whole episode is the same, number for number.
    assert comparable(from_sweep) == comparable(from_run)
    assert comparable(from_python) == comparable(from_run)
    # The row states the same settings.
    assert row["planner"] == from_run["plan_planner"]
    assert row["steering"] == from_run["plan_steering"]
    assert row["timing"] == from_run["plan_timing"]
    assert row["plan_max_iterations"] == from_run["plan_max_iterations"]

    # What `parksim run --help` states as its defaults is what it ran.
    _, help_text, _ = cli("run", "--help")
    for option, key in [("--planner", "plan_planner"), ("--steering", "plan_steering"),
                        ("--timing", "plan_timing"), ("--seed", "plan_seed"),
                        ("--noise-seed", "noise_seed"), ("--tracking", "tracking")]:
        # CLI11 writes "--planner TEXT=hybrid-a-star", "--timing TEXT:{...}=time-optimal".
        match = re.search(re.escape(option) + r" (\S+)", help_text)
        assert match and "=" in match.group(1), option
        shown = match.group(1).rsplit("=", 1)[1]
        assert shown == str(from_run[key]), (option, shown, from_run[key])
