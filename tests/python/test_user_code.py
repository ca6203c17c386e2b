"""Your planner and your controller in Python (docs/your-code.md): plan() and run() take objects
as well as names; they are checked as any user code is (plan_invalid, planner_error,
controller_error), and one that does exactly what a built-in does gives the built-in's rows."""

import math
import re
import warnings

import numpy as np
import pytest

import parksim
from conftest import SOURCE_DIR


class Straight:
    """Turn, drive, turn from the start to the goal with the problem's steering function: a plan
    that is valid only where nothing is in the way."""

    name = "straight"

    def __init__(self, check=True):
        self.check = check
        self.problems = []

    def solve(self, problem):
        self.problems.append((problem.start, problem.goal, problem.seed, problem.max_iterations))
        traj, reached = problem.steer(problem.start, problem.goal)
        if not reached or (self.check and not problem.is_valid(traj)):
            return None
        return traj


class Replay:
    """Returns a plan it was given: the default planner's, for comparisons."""

    def __init__(self, trajectory):
        self.trajectory = trajectory

    def solve(self, problem):
        return self.trajectory


class Tracking:
    """parksim's tracking law in Python, with the gains its built-in derives for the head-in plan
    at 240 Hz (sim/control/TrackingController.h)."""

    def __init__(self, robot, top_speed):
        self.robot = robot
        self.k_x, self.k_theta = 10.0, 10.0
        self.k_y = 100.0 / top_speed**2
        self.resets = 0

    def reset(self, setup):
        self.resets += 1
        assert setup["period_s"] == pytest.approx(1 / 240)

    def command(self, obs):
        x, y, th = obs.pose
        xr, yr, thr = obs.reference
        v_r, w_r = obs.reference_twist
        dx, dy = xr - x, yr - y
        ex = math.cos(th) * dx + math.sin(th) * dy
        ey = -math.sin(th) * dx + math.cos(th) * dy
        eth = math.remainder(thr - th, 2 * math.pi)
        v = v_r * math.cos(eth) + self.k_x * ex
        w = w_r + self.k_y * v_r * ey + self.k_theta * math.sin(eth)
        r, b = self.robot.wheel_radius_m, self.robot.wheel_base_m
        left, right = (v - 0.5 * b * w) / r, (v + 0.5 * b * w) / r
        limit = self.robot.max_wheel_speed_radps
        scale = max(1.0, abs(left) / limit, abs(right) / limit)
        return left / scale, right / scale


def test_a_python_planner_plans_and_its_plan_is_checked(head_in, tmp_path):
    planner = Straight(check=False)
    # Straight through the lot: planning alone, the one check finds what it hits, as run does.
    p = parksim.plan(head_in, planner=planner)
    assert not p.solved and p.status == "plan_invalid" and p.stats["planner"] == "straight"
    assert "the footprint overlaps" in p.message and p.verdict["status"] == "plan_invalid"
    assert p.stats["planner_origin"] == "Python object test_user_code.Straight"
    assert len(p.trajectory) > 0  # kept to be looked at
    assert planner.problems[0][0] == head_in.start
    with pytest.raises(parksim.Error, match="may not be driven \\(plan_invalid\\)"):
        parksim.run(head_in, plan=p)
    r = parksim.run(head_in, planner=Straight(check=False), out=tmp_path)
    assert r.status == "plan_invalid" and r.reason == p.message
    assert r.plan.status == "plan_invalid"
    assert r.executed is None or len(r.executed) == 0
    # Its metrics.json holds the verdict and whose code it was, and no measurement.
    assert r.metrics["status"] == "plan_invalid" and r.metrics["failure"] == r.reason
    assert r.metrics["plan_planner_origin"] == "Python object test_user_code.Straight"
    assert "max_pos_err_m" not in r.metrics
    assert (tmp_path / "metrics.json").exists() and not (tmp_path / "trajectory.csv").exists()
    # Checking its own plans, it reports that it found none.
    r = parksim.run(head_in, planner=Straight(check=True))
    assert r.status == "plan_failed" and "found no plan" in r.reason


def test_a_python_planners_failures_are_planner_errors(head_in):
    class Broken:
        def solve(self, problem):
            raise RuntimeError("lost my map")

    r = parksim.run(head_in, planner=Broken())
    assert r.status == "planner_error"
    assert r.reason == "planner Broken threw: RuntimeError: lost my map"

    class Garbage:
        def solve(self, problem):
            return np.zeros(3)

    r = parksim.run(head_in, planner=Garbage())
    assert r.status == "planner_error" and "structured array" in r.reason


def test_a_python_controller_equal_to_the_built_in_drives_the_same_rows(head_in):
    plan = parksim.plan(head_in)
    top = float(np.max(np.abs(plan.trajectory["v"])))
    ours = Tracking(head_in.robot, top)
    a = parksim.run(head_in, plan=plan)
    b = parksim.run(head_in, plan=plan, controller=ours)
    assert ours.resets == 1
    assert b.metrics["controller"] == "Tracking"
    assert a.status == b.status == "met"
    # The same law in double precision: the same rows to a few ulps of the pose.
    np.testing.assert_allclose(b.executed["x"], a.executed["x"], rtol=0, atol=1e-12)
    np.testing.assert_allclose(b.executed["theta"], a.executed["theta"], rtol=0, atol=1e-12)
    # A planner object replaying the default plan is checked and then drives like the original.
    c = parksim.run(head_in, planner=Replay(plan.trajectory))
    assert c.status == "met"
    np.testing.assert_array_equal(c.executed["x"], a.executed["x"])


@pytest.mark.parametrize("answer,reason", [
    (lambda obs: (float("nan"), 0.0), "not a number"),
    (lambda obs: (50.0, 50.0), "beyond robot.max_wheel_speed_radps 10"),
    (lambda obs: ("0.1", "0.2"), "not two real numbers"),
    (lambda obs: (1 + 2j, 0.0), "not two real numbers"),
    (lambda obs: 1 / 0, "ZeroDivisionError"),
])
def test_a_python_controllers_failures_are_controller_errors(head_in, answer, reason):
    def faulty(obs):
        return obs.feedforward if obs.t_s < 0.5 else answer(obs)

    r = parksim.run(head_in, controller=faulty)
    assert r.status == "controller_error"
    assert r.reason.startswith("controller faulty ") and reason in r.reason
    # The plan was fine: its own verdict is met.
    assert r.plan.solved and r.plan.status == "solved" and r.plan.verdict["met"]
    assert r.executed["t"][-1] == pytest.approx(0.5, abs=0.005)


def test_a_python_controller_under_lab_realism_sees_the_estimate_at_its_rate(head_in):
    ticks = []

    def hold(obs):
        ticks.append((obs.t_s, obs.pose, obs.encoders_rad))
        return obs.feedforward

    r = parksim.run(head_in, controller=hold, realism="lab")
    times = np.array([t for t, _, _ in ticks])
    # 50 Hz on 240 Hz physics: tick k at the first step at or after k / 50 s.
    k = np.arange(50)
    np.testing.assert_allclose(times[:50], np.ceil(k * 240 / 50 - 1e-9) / 240, atol=1e-12)
    assert r.metrics["realism"] == "lab"


def test_bad_components_are_input_errors(head_in):
    with pytest.raises(TypeError, match="solve"):
        parksim.plan(head_in, planner=object())
    with pytest.raises(ValueError, match="name"):
        parksim.run(head_in, controller=type("X", (), {"name": "bad name!", "command": None})())
    with pytest.raises(parksim.Error, match="takes no controller_params"):
        parksim.run(head_in, controller=lambda o: o.feedforward, controller_params={"k": 1})


@pytest.mark.parametrize("realism", ["ideal", "lab"])
def test_a_parking_policy_drives_as_in_its_environment(head_in, realism):
    """PolicyController observes and acts exactly as ParkingEnv does: replaying the actions an
    episode of the environment took, from the same start, it sees the same observations."""
    env = parksim.ParkingEnv(head_in, fidelity="dynamics", realism=realism)
    obs, _ = env.reset(seed=3, options={"start": head_in.start, "noise_seed": 1})
    rng = np.random.default_rng(5)
    actions, seen = [], [obs]
    for _ in range(30):
        action = rng.uniform(-0.3, 0.6, size=2).astype(np.float32)
        obs, _, terminated, truncated, _ = env.step(action)
        actions.append(action)
        seen.append(obs)
        if terminated or truncated:
            break
    received = []

    def replay(observation):
        received.append(observation.copy())
        return actions[min(len(received) - 1, len(actions) - 1)]

    parksim.run(head_in, controller=parksim.PolicyController(replay, env.control_period_s),
                realism=realism, noise_seed=1, max_stop_time_s=0.0)
    n = min(len(received), len(seen))
    assert n >= 20
    assert received[0].dtype == np.float32 and received[0].shape == (10,)
    np.testing.assert_array_equal(np.array(received[:n]), np.array(seen[:n]))


def _rows(path):
    import json
    with open(path) as f:
        return [json.loads(line) for line in f if line.strip()]


def test_a_sweep_runs_python_components_in_workers_and_resumes(head_in, tmp_path):
    """parksim.sweep(): Python objects by the names the spec lists, beside parksim's own; a
    controller that kills its process is that episode's controller_error; a second call runs
    nothing again; the built-in episodes' rows are the CLI's."""
    import os
    import signal
    import subprocess

    plan = parksim.plan(head_in)
    top = float(np.max(np.abs(plan.trajectory["v"])))

    def crashing(obs):
        if obs.t > 0.5:
            os.kill(os.getpid(), signal.SIGSEGV)
        return obs.feedforward

    spec = tmp_path / "spec.yaml"
    world = os.path.join(parksim.worlds_dir(), "head_in.yaml")
    spec.write_text("format: parksim-sweep/1\nname: py\nworlds: [%s]\n"
                    "planners: [time-a-star, straight]\n"
                    "controllers: [tracking, mine, crashing]\n" % world)
    out = tmp_path / "out"
    kwargs = dict(out=str(out), planners={"straight": Straight(check=True)},
                  controllers={"mine": Tracking(head_in.robot, top), "crashing": crashing},
                  workers=2)
    r = parksim.sweep(str(spec), **kwargs)
    assert (r["episodes"], r["ran"]) == (6, 6)
    rows = {(x["planner"], x["controller"]): x for x in _rows(out / "results.jsonl")}
    assert len(rows) == 6
    assert rows[("time-a-star", "tracking")]["status"] == "met"
    assert rows[("time-a-star", "mine")]["status"] == "met"
    assert rows[("time-a-star", "crashing")]["status"] == "controller_error"
    assert rows[("time-a-star", "crashing")]["failure"] == \
        "controller crashing crashed (SIGSEGV, Segmentation fault)"
    # The straight planner checks its plans: it finds none through the head-in lot.
    for c in ("tracking", "mine", "crashing"):
        assert rows[("straight", c)]["status"] == "plan_failed"
    # Resumed: nothing with a verdict runs again.
    again = parksim.sweep(str(spec), **kwargs)
    assert (again["episodes"], again["ran"], again["failed"]) == (6, 0, r["failed"])
    # parksim's own episodes give the rows the command line gives, to the bit.
    cli_spec = tmp_path / "cli.yaml"
    cli_spec.write_text("format: parksim-sweep/1\nname: py\nworlds: [%s]\n" % world)
    exe = os.path.join(os.path.dirname(parksim.__file__), "..", "..", "app", "parksim")
    if not os.path.exists(exe):
        pytest.skip("the parksim program is not beside this module")
    subprocess.run([exe, "sweep", str(cli_spec), "--out", str(tmp_path / "cli")], check=True,
                   capture_output=True)
    cli = _rows(tmp_path / "cli" / "results.jsonl")[0]
    ours = rows[("time-a-star", "tracking")]
    assert cli["episode_id"] == ours["episode_id"]
    for key in ("max_pos_err_m", "final_x_m", "final_y_m", "final_theta_rad", "steps"):
        assert cli[key] == ours[key], key


def test_a_car_command_holds_a_speed_or_an_acceleration_and_a_steering_angle():
    c = parksim.CarCommand(speed=1.5, steer=-0.25)
    assert (c.speed, c.accel, c.steer) == (1.5, None, -0.25)
    a = parksim.CarCommand(accel=-0.5, steer=0.1)
    assert (a.speed, a.accel, a.steer) == (None, -0.5, 0.1)
    for bad in ({}, {"speed": 1.0, "accel": 1.0}):
        with pytest.raises(ValueError):
            parksim.CarCommand(**bad)


def test_a_differential_robots_observation_has_no_steering(head_in):
    seen = []

    def feedforward(obs):
        seen.append((obs.steer_rad, obs.reference_steer_rad, obs.commanded_speed_mps))
        return obs.feedforward

    assert parksim.run(head_in, controller=feedforward).status == "met"
    assert seen and all(s == (0.0, 0.0, 0.0) for s in seen)


# docs/your-code.md's table of a controller's inputs and its car sentence, the names a Python
# controller reads: the same names (unit suffix included) as ControllerInput's C++ fields.
DOCUMENTED_INPUTS = ["t_s", "pose", "encoders_rad", "wheel_speeds_radps", "twist", "reference",
                     "reference_twist", "feedforward", "plan_ended", "steer_rad",
                     "reference_steer_rad", "commanded_speed_mps"]
RENAMED_INPUTS = {"t": "t_s", "encoders": "encoders_rad", "wheel_speeds": "wheel_speeds_radps",
                  "steer": "steer_rad", "reference_steer": "reference_steer_rad",
                  "commanded_speed": "commanded_speed_mps"}


def test_a_python_controller_reads_its_inputs_under_the_documented_names(head_in):
    docs = (SOURCE_DIR / "docs" / "your-code.md").read_text()
    for name in DOCUMENTED_INPUTS:
        assert f"`{name}`" in docs, name
    seen = []

    def record(obs):
        seen.append({name: getattr(obs, name) for name in DOCUMENTED_INPUTS})
        return obs.feedforward

    assert parksim.run(head_in, controller=record).status == "met"
    assert len(seen) > 100
    assert [s["t_s"] for s in seen[:3]] == pytest.approx([0.0, 1 / 240, 2 / 240])
    assert seen[-1]["encoders_rad"][0] > 1.0 and len(seen[-1]["wheel_speeds_radps"]) == 2


def test_a_controllers_inputs_of_before_still_read_with_a_deprecation_warning(head_in):
    seen = []

    def record(obs):
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            old = {o: getattr(obs, o) for o in RENAMED_INPUTS}
        seen.append((old, {o: getattr(obs, n) for o, n in RENAMED_INPUTS.items()},
                     [str(w.message) for w in caught if w.category is DeprecationWarning]))
        return obs.feedforward

    assert parksim.run(head_in, controller=record).status == "met"
    for old, new, messages in seen[:5]:
        assert old == new
        assert messages == [f"ControllerInput.{o} is deprecated: read .{n} (the same value)"
                            for o, n in RENAMED_INPUTS.items()]


@pytest.mark.parametrize("answer,type_name", [
    ("solved", "str"), ("", "str"), (b"plan.csv", "bytes"), ({"t": [0.0]}, "dict"),
])
def test_a_python_planner_returning_no_trajectory_is_a_planner_error_naming_the_type(
        head_in, answer, type_name):
    class Answers:
        def solve(self, problem):
            return answer

    r = parksim.plan(head_in, planner=Answers())
    assert r.status == "planner_error"
    assert r.message == (f"planner Answers threw: solve() returned a {type_name}, not a "
                         "trajectory (a structured array with fields t, x, y, theta, "
                         "omega_left, omega_right) or None")
    assert "cannot open" not in r.message


@pytest.mark.parametrize("path,message", [
    ("no/such/plan.csv", "no/such/plan.csv: cannot open plan file: No such file or directory"),
    ("", "cannot open plan file: the path is empty"),
])
def test_a_plan_file_that_cannot_be_opened_is_named(head_in, path, message):
    with pytest.raises(parksim.Error, match="^" + re.escape(message) + "$"):
        parksim.run(head_in, plan=path)
