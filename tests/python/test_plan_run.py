"""plan() and run() against the command line: the same trajectory and executed rows, to the bit,
for the same seeds; metrics as metrics.json; episodes in parallel threads."""

import concurrent.futures
import json

import numpy as np
import pytest

import parksim
from conftest import run_cli

TRAJECTORY_FIELDS = ("t", "x", "y", "theta", "omega_left", "omega_right", "v", "omega")
EXECUTED_FIELDS = ("t", "x", "y", "theta", "x_ref", "y_ref", "theta_ref", "omega_left_cmd",
                   "omega_right_cmd", "omega_left", "omega_right", "pos_err", "heading_err")


def read_csv(path):
    """A CSV file of numbers with a header, parsed with full precision (%.17g round-trips)."""
    lines = path.read_text().splitlines()
    header = lines[0].split(",")
    rows = [[float(v) for v in line.split(",")] for line in lines[1:]]
    return header, np.array(rows, dtype=np.float64).reshape(len(rows), len(header))


def assert_bit_identical(array, path, fields):
    header, values = read_csv(path)
    assert tuple(header) == fields
    assert array.dtype.names == fields
    assert len(array) == len(values)
    for i, name in enumerate(fields):
        # Bitwise, not approximately: compare the float64 bit patterns.
        np.testing.assert_array_equal(array[name].view(np.uint64), values[:, i].view(np.uint64),
                                      err_msg=name)


def test_plan_result_has_status_stats_and_a_structured_trajectory(head_in_plan):
    assert head_in_plan.solved
    assert head_in_plan.status == "solved"
    traj = head_in_plan.trajectory
    assert traj.dtype.names == TRAJECTORY_FIELDS
    assert traj["t"][0] == 0.0 and np.all(np.diff(traj["t"]) > 0)
    stats = head_in_plan.stats
    assert stats["planner"] == parksim.PlanSetup().planner and stats["seed"] == 1
    assert stats["iterations"] > 0 and stats["path_length_m"] > 0
    assert set(stats["phase_times_s"]) >= {"sampling", "steering", "collision_checking"}


@pytest.mark.parametrize("tracking,extra", [("closed", {}), ("open", {"smooth": True})])
def test_run_is_bit_identical_to_parksim_run(tmp_path, head_in, head_in_path, tracking, extra):
    seed = 2
    result = parksim.run(head_in, seed=seed, tracking=tracking, **extra)
    assert result.solved
    out = tmp_path / "cli"
    args = ["run", head_in_path, "--seed", seed, "--tracking", tracking, "--out", out]
    if extra.get("smooth"):
        args.append("--smooth")
    run_cli(*args)  # exit 1 (tolerance not met) is an outcome, not a failure here
    assert_bit_identical(result.trajectory, out / "trajectory.csv", TRAJECTORY_FIELDS)
    assert_bit_identical(result.executed, out / "executed.csv", EXECUTED_FIELDS)
    cli = json.loads((out / "metrics.json").read_text())
    # Wall-clock measurements differ from run to run; everything else must match.
    timing = {k for k in cli if k in ("wall_time_s", "real_time_factor", "plan_planning_time_s",
                                       "plan_first_solution_s") or k.startswith("plan_phase")}
    # metrics.json also has the tolerance it checked (tolerance.*); every key run() reports is
    # one of its keys, with the same value.
    assert set(result.metrics) <= set(cli)
    assert {"max_pos_err_m", "goal_reached", "steps", "plan_path_length_m"} <= set(result.metrics)
    for key in set(result.metrics) - timing:
        assert result.metrics[key] == cli[key], key


def test_run_with_a_given_plan_drives_that_plan(head_in, head_in_plan):
    a = parksim.run(head_in, plan=head_in_plan)
    b = parksim.run(head_in, plan=head_in_plan.trajectory)
    assert a.plan is None
    np.testing.assert_array_equal(a.executed, b.executed)
    assert a.metrics["goal_reached"] and a.metrics["contacts"] == 0
    # The planned run with the same seed drives the same plan.
    c = parksim.run(head_in, seed=1)
    assert c.executed.tobytes() == a.executed.tobytes()


def test_options_reach_the_definitions_and_unknown_ones_are_refused(head_in):
    p = parksim.plan(head_in, planner="rrt-star", seed=4, max_iterations=300, record_tree=False,
                     steering="rotate-translate-rotate", validation={"resolution_m": 0.002})
    assert p.setup.planner == "rrt-star" and p.setup.search.max_iterations == 300
    assert p.setup.steering == "rotate-translate-rotate"
    assert p.setup.validation.resolution_m == 0.002
    assert p.stats["motion_check_resolution_m"] == 0.002
    assert p.tree_edges == []
    with pytest.raises(TypeError, match="max_iteration"):
        parksim.plan(head_in, max_iteration=3)
    with pytest.raises(parksim.Error, match="rrt-nope"):
        parksim.plan(head_in, planner="rrt-nope")
    # A planner's own parameters go by name; a typo is an error, not a default.
    q = parksim.plan(head_in, planner="rrt-star", max_iterations=50,
                     planner_params={"goal_bias": 0.2, "informed_sampling": False})
    assert q.setup.planner_params == {"goal_bias": "0.2", "informed_sampling": "false"}
    assert q.stats["planner_params"] == {"goal_bias": "0.2", "informed_sampling": "false"}
    with pytest.raises(parksim.Error, match="unknown parameter 'goal_biass'"):
        parksim.plan(head_in, planner="rrt-star", planner_params={"goal_biass": 0.2})
    with pytest.raises(TypeError, match="gain"):
        parksim.run(head_in, plan=head_in.start, gain=3)


def test_an_unsolved_plan_is_a_status_and_run_does_not_drive(head_in):
    p = parksim.plan(head_in, seed=1, max_iterations=1)
    assert not p.solved and p.status == "iteration_limit"
    assert len(p.trajectory) == 0
    r = parksim.run(head_in, seed=1, max_iterations=1)
    assert not r.solved and r.plan.status == "iteration_limit"
    # Nothing driven: metrics.json holds the verdict and the plan's keys, no measurement.
    assert len(r.executed) == 0 and r.metrics["status"] == "plan_failed"
    assert r.metrics["plan_status"] == "iteration_limit" and "max_pos_err_m" not in r.metrics


def test_episodes_run_in_parallel_threads_with_the_same_results(head_in, head_in_plan):
    seeds = [1, 2, 3]
    sequential = [parksim.run(head_in, seed=s).executed.tobytes() for s in seeds]
    with concurrent.futures.ThreadPoolExecutor(max_workers=3) as pool:
        parallel = list(pool.map(lambda s: parksim.run(head_in, seed=s).executed.tobytes(), seeds))
    assert parallel == sequential


@pytest.mark.parametrize("planner", ["rrt", "rrt-goal-connect", "rrt-star", "rrt-connect"])
def test_every_planner_plans_as_the_command_line(tmp_path, head_in, head_in_path, planner):
    p = parksim.plan(head_in, planner=planner, seed=5, max_iterations=400)
    out = tmp_path / "cli"
    code, _, _ = run_cli("plan", head_in_path, "--planner", planner, "--seed", 5,
                         "--max-iterations", 400, "--out", out)
    cli = json.loads((out / "plan.json").read_text())
    assert p.status == cli["status"] and code == (0 if p.solved else 1)
    assert p.stats["iterations"] == cli["iterations"]
    if p.solved:
        assert_bit_identical(p.trajectory, out / "trajectory.csv", TRAJECTORY_FIELDS)
