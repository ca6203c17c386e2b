"""The step API: an Episode stepped from Python against runEpisode, commanded wheel speeds,
observations, contacts and metrics; the bare DynamicsWorld."""

import math

import numpy as np
import pytest

import parksim


def test_stepping_to_the_end_is_run(head_in, head_in_plan):
    reference = parksim.run(head_in, plan=head_in_plan)
    ep = parksim.Episode(head_in, head_in_plan)
    steps = 0
    while not ep.finished:
        ep.step()
        steps += 1
    assert ep.executed.tobytes() == reference.executed.tobytes()
    assert steps == reference.metrics["steps"] == ep.steps
    m = ep.metrics
    for key in ("max_pos_err_m", "rms_pos_err_m", "goal_pos_err_m", "goal_reached", "contacts"):
        assert m[key] == reference.metrics[key], key


def test_stepping_in_blocks_is_stepping_one_at_a_time(head_in, head_in_plan):
    a = parksim.Episode(head_in, head_in_plan, tracking="open")
    b = parksim.Episode(head_in, head_in_plan, tracking="open")
    a.step(500)
    for _ in range(500):
        b.step()
    assert a.executed.tobytes() == b.executed.tobytes()
    assert a.steps == 500


def test_a_python_controller_commanding_the_controllers_command_is_the_controller(
        head_in, head_in_plan):
    reference = parksim.run(head_in, plan=head_in_plan)
    ep = parksim.Episode(head_in, head_in_plan)
    while not ep.finished:
        ep.set_wheel_speeds(*ep.controller_command())
        ep.step()
    assert ep.executed.tobytes() == reference.executed.tobytes()


def test_held_wheel_speeds_drive_the_robot_and_observation_reports_it(head_in, head_in_plan):
    ep = parksim.Episode(head_in, head_in_plan)
    obs = ep.observation()
    assert obs["t"] == 0.0 and obs["pose"] == pytest.approx(head_in.start)
    assert set(obs) >= {"pose", "estimated_pose", "wheel_speeds", "twist", "reference",
                        "contacts"}
    # Straight ahead at 4 rad/s on 20 mm wheels for 0.5 s: 40 mm along the start heading
    # (north), less what the motors need to reach speed.
    ep.set_wheel_speeds(4.0, 4.0)
    ep.step(round(0.5 / ep.time_step))
    obs = ep.observation()
    x0, y0, _ = head_in.start
    x, y, theta = obs["pose"]
    assert y - y0 == pytest.approx(0.5 * 4.0 * head_in.robot.wheel_radius_m, abs=0.003)
    assert x == pytest.approx(x0, abs=1e-3)
    assert obs["wheel_speeds"] == pytest.approx((4.0, 4.0), abs=0.05)
    assert obs["wheel_speeds_cmd"] == (4.0, 4.0)
    assert obs["twist"][0] == pytest.approx(0.08, abs=0.002)
    ep.use_controller()
    ep.step()
    assert ep.observation()["wheel_speeds_cmd"] != (4.0, 4.0)


def test_driving_into_the_wall_is_a_contact_event(head_in, head_in_plan):
    # From the start (0.1, 0.1) facing north, turn east and drive into wall_2 (x 0.5..0.6).
    ep = parksim.Episode(head_in, head_in_plan)
    ep.set_wheel_speeds(3.0, -3.0)  # turn right in place
    quarter = round((math.pi / 2) / (2 * 3.0 * 0.02 / 0.085) / ep.time_step)
    ep.step(quarter)
    ep.set_wheel_speeds(8.0, 8.0)
    for _ in range(600):
        ep.step(4)
        if ep.contacts:
            break
    wall = [o["name"] for o in head_in.obstacles].index("wall_2")
    assert wall in ep.contacts
    events = ep.contact_events
    assert events and events[0]["body"] == "wall_2" and events[0]["obstacle_index"] == wall
    assert ep.metrics["contacts"] == len(events)
    assert ep.obstacle_poses.shape == (len(head_in.obstacles), 3)


def test_dynamics_world_holds_targets_and_starts_where_asked(head_in):
    start = (0.3, 0.3, 0.0)
    sim = parksim.DynamicsWorld(head_in, start=start)
    assert sim.pose == pytest.approx(start, abs=1e-6)
    sim.set_wheel_targets(5.0, 5.0)
    sim.step(240)
    assert sim.time == pytest.approx(1.0)
    state = sim.robot_state()
    assert state["wheel_speeds"] == pytest.approx((5.0, 5.0), abs=0.05)
    assert sim.pose[0] - start[0] == pytest.approx(0.1, abs=0.004)
    assert sim.contacts == []


def test_model_and_execution_options_are_taken(head_in, head_in_plan):
    ep = parksim.Episode(head_in, head_in_plan, tracking="open", csv_stride_steps=10,
                         model={"solver": "exact"})
    ep.step(100)
    assert len(ep.executed) == 11  # rows at steps 0, 10, ..., 100
    with pytest.raises(TypeError, match="tracknig"):
        parksim.Episode(head_in, head_in_plan, tracknig="open")
    with pytest.raises(ValueError, match="solver"):
        parksim.Episode(head_in, head_in_plan, model={"solver": "nope"})
    assert np.all(np.diff(ep.executed["t"]) > 0)


def test_a_realism_preset_gives_an_estimate_and_matches_the_command_line(
        tmp_path, head_in, head_in_path, head_in_plan):
    from conftest import run_cli
    from test_plan_run import read_csv

    ep = parksim.Episode(head_in, head_in_plan, realism="lab", noise_seed=2)
    ep.step(240)
    obs = ep.observation()
    assert obs["estimated_pose"] != obs["pose"]  # the estimator's pose, not the truth
    assert obs["estimated_pose"] == pytest.approx(obs["pose"], abs=0.01)
    # run() with the same realism and seeds drives the robot as `parksim run` does.
    run = parksim.run(head_in, seed=1, realism="lab", noise_seed=2)
    out = tmp_path / "cli"
    run_cli("run", head_in_path, "--seed", 1, "--realism", "lab", "--noise-seed", 2,
            "--out", out)
    header, values = read_csv(out / "executed.csv")
    assert run.executed.dtype.names == tuple(header)  # the realism columns too
    for name in header:
        column = values[:, header.index(name)]
        np.testing.assert_array_equal(run.executed[name].view(np.uint64),
                                      column.view(np.uint64), err_msg=name)
