"""One episode record (parksim/results/tables/EpisodeRecord.h) everywhere: one episode of the head-in
world under the `lab` realism, through `parksim run` (metrics.json), a sweep (its results.jsonl
and results.csv row, and the episode's own metrics.json) and Python's run().metrics. Every
field of the record agrees across them, and no field of the row is empty that metrics.json
fills (issue 31: the sweep left 11 realism columns empty that `run` filled).

Run through ctest (PARKSIM_EXE, PYTHONPATH and PARKSIM_SOURCE_DIR set)."""

import csv
import json
import os
import pathlib
import subprocess

import pytest

import parksim

SOURCE_DIR = pathlib.Path(os.environ.get("PARKSIM_SOURCE_DIR",
                                         pathlib.Path(__file__).resolve().parents[2]))
WORLD = SOURCE_DIR / "worlds" / "head_in.yaml"
NOISE_SEED = 3


def cli(*args):
    exe = os.environ.get("PARKSIM_EXE")
    if not exe:
        pytest.skip("PARKSIM_EXE is not set (run through ctest)")
    p = subprocess.run([exe, *map(str, args)], capture_output=True, text=True, timeout=600)
    return p.returncode, p.stderr


@pytest.fixture(scope="module")
def episode(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("record")
    code, err = cli("run", WORLD, "--realism", "lab", "--noise-seed", NOISE_SEED,
                    "--out", tmp / "run")
    assert code in (0, 4), err
    from_run = json.loads((tmp / "run" / "metrics.json").read_text())

    spec = tmp / "spec.yaml"
    spec.write_text(f"format: parksim-sweep/1\nname: record\nworlds: ['{WORLD}']\n"
                    f"realism: lab\nnoise_seeds: [{NOISE_SEED}]\n"
                    "record: {executed_csv: all}\n")
    code, err = cli("sweep", spec, "--out", tmp / "sweep", "--workers", 1)
    assert code in (0, 1), err
    (row,) = [json.loads(line) for line in (tmp / "sweep" / "results.jsonl").read_text()
              .splitlines()]
    with open(tmp / "sweep" / "results.csv", newline="") as f:
        (csv_row,) = list(csv.DictReader(f))
    from_sweep = json.loads(
        (tmp / "sweep" / "episodes" / row["episode_id"] / "metrics.json").read_text())

    from_python = parksim.run(parksim.load_world(WORLD), realism="lab",
                              noise_seed=NOISE_SEED).metrics
    return from_run, row, csv_row, from_sweep, from_python


FIELDS = parksim.episode_fields()


def varies(field):
    """Wall-clock fields differ between runs of one episode."""
    return field["group"] == "timing"


def csv_text(value):
    """A value as results.csv writes it."""
    if value is None:
        return ""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, list):
        return "|".join(v if isinstance(v, str) else json.dumps(v) for v in value)
    if isinstance(value, str):
        return value
    return json.dumps(value)


def test_the_record_covers_every_key_the_episode_part_of_metrics_json_has(episode):
    from_run = episode[0]
    metrics_keys = {f["metrics_key"] for f in FIELDS if f["metrics_key"] and f["read"]}
    # Every record field that a driven lab episode has is in metrics.json (plan_cost_m is
    # time-a-star's: it minimises duration, and leaves the path cost out everywhere).
    for key in metrics_keys - {"plan_cost_m", "parked_displacement_m"}:
        assert key in from_run, key
    # metrics.json's own keys beyond the record: the document (world, tolerance, provenance)
    # and plan.json's keys with a plan_ prefix.
    for key in from_run:
        known = key in metrics_keys or key.startswith(("plan_", "provenance.", "tolerance.",
                                                       "parked_displacement_m."))
        assert known or key in ("world", "scenario"), key


def test_every_field_agrees_between_run_sweep_and_python(episode):
    from_run, row, csv_row, from_sweep, from_python = episode
    checked = 0
    for f in FIELDS:
        key, metrics_key = f["key"], f["metrics_key"]
        if metrics_key and not varies(f):
            assert from_sweep.get(metrics_key) == from_run.get(metrics_key), metrics_key
            assert from_python.get(metrics_key) == from_run.get(metrics_key), metrics_key
        if key and metrics_key and f["read"] and not varies(f) and not f["per_name"]:
            # The row holds what metrics.json holds, under its own key.
            assert row.get(key) == from_run.get(metrics_key), (key, metrics_key)
            checked += 1
    assert checked >= 50  # every measurement, the verdict and the plan's statistics
    # Parked robots, per name, alike.
    parked = {k: v for k, v in from_run.items() if k.startswith("parked_displacement_m.")}
    assert parked and parked == {k: v for k, v in row.items() if k in parked}
    # The parameters the row states are those run ran with (metrics.json names them as
    # plan.json does).
    assert row["world"] == from_run["scenario"]
    for column, key in [("planner", "plan_planner"), ("steering", "plan_steering"),
                        ("smooth", "plan_smooth"), ("seed", "plan_seed"),
                        ("timing", "plan_timing"), ("realism", "realism"),
                        ("noise_seed", "noise_seed"), ("tracking", "tracking")]:
        assert row[column] == from_run[key], column


def test_no_column_is_empty_that_metrics_json_fills(episode):
    from_run, row, csv_row, _, _ = episode
    for f in FIELDS:
        key, metrics_key = f["key"], f["metrics_key"]
        if not key:
            continue
        if metrics_key and from_run.get(metrics_key) not in (None, "", []):
            assert row.get(key) is not None, key
            if f["csv"]:
                assert csv_row[key] != "", key
        if f["csv"]:
            # results.csv is the rendering of the results.jsonl row.
            assert csv_row[key] == csv_text(row.get(key)), key
    # The realism columns the issue found empty.
    for key in ("estimator", "max_est_pos_err_m", "rms_est_pos_err_m", "max_slip_mps",
                "max_motor_torque_nm", "pose_samples_dropped"):
        assert csv_row[key] != "", key
    assert row["estimator"] == from_run["estimator"] != "truth"
