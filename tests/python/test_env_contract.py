"""ParkingEnv refuses what it cannot use (issue 20, item 4): one test per item of the contract.
Gymnasium is not packaged in Debian, so these assert what its checker and wrappers rely on;
registration is checked against a stand-in gymnasium module in a child process."""

import copy
import importlib.util
import math
import os
import pickle
import re
import subprocess
import sys
import textwrap

import re

import numpy as np
import pytest

import parksim


@pytest.fixture
def env(head_in):
    e = parksim.ParkingEnv(world=head_in)
    e.reset(seed=3)
    return e


def actions(seed, n, scale=1.0):
    """n random actions (seeded); scale < 1 keeps the robot near its start."""
    rng = np.random.default_rng(seed)
    return (scale * rng.uniform(-1.0, 1.0, size=(n, 2))).astype(np.float32)


EXPECTED = r"^action: expected two finite numbers \(left, right wheel speed fractions\), got "


def test_non_finite_actions_raise_and_move_nothing(head_in, env):
    for bad in ([np.nan, 0.0], [0.0, np.inf], [-np.inf, 0.5]):
        with pytest.raises(ValueError, match=EXPECTED + r"\(.*\)$"):
            env.step(bad)
    # The refused actions left no trace: the episode continues as an untouched one does.
    fresh = parksim.ParkingEnv(world=head_in)
    fresh.reset(seed=3)
    for action in actions(1, 3):
        assert np.array_equal(env.step(action)[0], fresh.step(action)[0])


def test_wrong_action_shapes_raise(env):
    for bad, shape in (([[0.1, 0.2]], r"\(1, 2\)"), ([0.1, 0.2, 0.3], r"\(3,\)"),
                       (0.5, r"\(\)"), (np.zeros((2, 1)), r"\(2, 1\)")):
        with pytest.raises(ValueError, match=EXPECTED + "shape " + shape + "$"):
            env.step(bad)
    assert env.step(np.array([0.1, 0.2], dtype=np.float32))[0].shape == (10,)


def test_actions_are_numbers_only(head_in, env):
    # NumPy would parse the strings and drop the imaginary part (with a ComplexWarning): each
    # is refused with the message every bad action gets, in one line, and nothing moves.
    import decimal
    import warnings

    refused = {"strings": ["0.1", "0.2"], "complex numbers": [0.1 + 0.5j, 0.2],
               "booleans": [True, False], "Python objects": [decimal.Decimal("0.1"), 0.2]}
    vec = parksim.VecParkingEnv(2, world=head_in, fidelity="kinematic")
    vec.reset(seed=0)
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # no ComplexWarning either
        for kind, bad in refused.items():
            with pytest.raises(ValueError, match=EXPECTED + kind + "$") as single:
                env.step(bad)
            assert "\n" not in str(single.value)
            with pytest.raises(ValueError, match=r"^actions: expected shape \(2, 2\) of finite "
                                                 r"numbers .*, got " + kind + "$"):
                vec.step([bad, bad])
        with pytest.raises(ValueError, match=EXPECTED + "strings$"):
            env.step("left")  # NumPy makes a 0-d array of it
        with pytest.raises(ValueError, match=EXPECTED + r"\[\[0.1\], \[0.2, 0.3\]\]$"):
            env.step([[0.1], [0.2, 0.3]])  # no array at all: its repr
        # A repr of many lines (a list of arrays of NumPy's wrapped repr) is one line too.
        ragged = [np.linspace(0.0, 1.0, 30), np.zeros(2)]
        assert "\n" in repr(ragged)
        for step, bad in ((env.step, ragged), (vec.step, [ragged, ragged])):
            with pytest.raises(ValueError) as refused:
                step(bad)
            assert "\n" not in str(refused.value) and "  " not in str(refused.value)
            assert str(refused.value).endswith("...")
        with pytest.raises(ValueError, match=EXPECTED + re.escape(
                "[array([0. , 0.03448276, 0.06896552, 0.10344828, 0.137931...") + "$"):
            env.step(ragged)
    # Integers and floats of any width are numbers: the same step as the float64 pair.
    fresh = parksim.ParkingEnv(world=head_in)
    fresh.reset(seed=3)
    for action in ([1, 0], np.array([1, 0], dtype=np.int8), np.array([1.0, 0.0], np.float16)):
        assert np.array_equal(env.step(action)[0], fresh.step([1.0, 0.0])[0])


def test_stepping_after_the_end_raises(head_in):
    env = parksim.ParkingEnv(world=head_in, max_episode_steps=3)
    with pytest.raises(RuntimeError, match="reset"):
        env.step([0.0, 0.0])  # before the first reset
    env.reset(seed=1)
    for _ in range(2):
        assert not any(env.step([0.1, 0.1])[2:4])
    _, _, terminated, truncated, _ = env.step([0.1, 0.1])
    assert truncated and not terminated
    with pytest.raises(RuntimeError, match="ended"):
        env.step([0.1, 0.1])
    env.reset()
    env.step([0.1, 0.1])


def test_observation_bounds_are_finite_from_the_lot_and_the_robots_limits(head_in):
    env = parksim.ParkingEnv(world=head_in)
    low, high = env.observation_space.low, env.observation_space.high
    assert np.all(np.isfinite(low)) and np.all(np.isfinite(high))
    robot, lot = head_in.robot, head_in.lot
    v_max = robot.max_wheel_speed_radps * robot.wheel_radius_m
    margin = 2 * v_max * env.control_period_s  # one action past the lot, doubled
    assert low[0] == pytest.approx(lot["x_min"] - margin) and high[0] == pytest.approx(
        lot["x_max"] + margin)
    assert low[1] == pytest.approx(lot["y_min"] - margin) and high[1] == pytest.approx(
        lot["y_max"] + margin)
    assert list(low[2:4]) == [-1, -1] and list(high[2:4]) == [1, 1]
    assert high[4] == pytest.approx(1.5 * v_max)
    assert high[5] == pytest.approx(1.5 * 2 * v_max / robot.wheel_base_m)
    # The goal's part: the same position bounds, cos and sin in [-1, 1]; no low == high
    # (Gymnasium's checker warns of those).
    assert np.array_equal(low[6:], [low[0], low[1], -1, -1])
    assert np.array_equal(high[6:], [high[0], high[1], 1, 1])
    assert np.all(low < high)
    obs, _ = env.reset(seed=0)
    assert env.observation_space.contains(obs)
    for action in actions(0, 300):
        obs, _, terminated, truncated, _ = env.step(action)
        assert env.observation_space.contains(obs)
        if terminated or truncated:
            env.reset()


def test_the_default_world_comes_from_the_installed_package(tmp_path):
    code = textwrap.dedent("""
        import os, parksim
        env = parksim.ParkingEnv()
        print(env.world.name)
        print(os.path.dirname(env.world.source_path) == parksim.worlds_dir())
        print(parksim.load_world("parallel").name, "head_in" in parksim.world_names())
    """)
    out = subprocess.run([sys.executable, "-c", code], cwd=tmp_path, capture_output=True,
                         text=True, env=dict(os.environ), timeout=60)
    assert out.returncode == 0, out.stderr
    assert out.stdout.split() == ["head_in", "True", "parallel", "True"]
    assert not (tmp_path / "worlds").exists()


# A stand-in for gymnasium: what the registration and the environment use of it.
FAKE_GYMNASIUM = {
    "gymnasium/__init__.py": """
        import numpy as np
        registry = {}
        calls = []
        def register(id, entry_point, max_episode_steps=None, vector_entry_point=None, **kw):
            calls.append(dict(id=id, entry_point=entry_point, max_episode_steps=max_episode_steps,
                              vector_entry_point=vector_entry_point))
            registry[id] = calls[-1]
        class Env:
            _np_random = None
            @property
            def np_random(self):
                if self._np_random is None:
                    self._np_random = np.random.default_rng()
                return self._np_random
            def reset(self, *, seed=None, options=None):
                if seed is not None:
                    self._np_random = np.random.default_rng(seed)
    """,
    "gymnasium/spaces.py": """
        from parksim.spaces import Box
    """,
    "gymnasium/vector/__init__.py": """
        import enum
        class AutoresetMode(enum.Enum):
            NEXT_STEP = "NextStep"
            SAME_STEP = "SameStep"
        class VectorEnv:
            _np_random = None
            def reset(self, *, seed=None, options=None):
                import numpy as np
                if seed is not None:
                    self._np_random = np.random.default_rng(seed)
            @property
            def np_random(self):
                import numpy as np
                if self._np_random is None:
                    self._np_random = np.random.default_rng()
                return self._np_random
    """,
}


def test_registration_has_max_episode_steps_and_only_with_gymnasium(tmp_path):
    for name, text in FAKE_GYMNASIUM.items():
        (tmp_path / name).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / name).write_text(textwrap.dedent(text))
    code = textwrap.dedent("""
        import gymnasium, parksim
        print(gymnasium.calls)
        env = parksim.ParkingEnv()
        assert isinstance(env, gymnasium.Env)
        a = env.reset(seed=4)[0]; b = env.reset(seed=4)[0]
        assert (a == b).all()
        vec = parksim.VecParkingEnv(2, fidelity="kinematic")
        assert vec.metadata["autoreset_mode"] == gymnasium.vector.AutoresetMode.NEXT_STEP
        vec.reset(seed=1)
    """)
    environ = dict(os.environ)
    environ["PYTHONPATH"] = os.pathsep.join([str(tmp_path), environ.get("PYTHONPATH", "")])
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         env=environ, timeout=60)
    assert out.returncode == 0, out.stderr
    calls = eval(out.stdout)  # the stand-in's record of register() calls
    assert calls == [{"id": "parksim/Parking-v0", "entry_point": "parksim.env:registered_env",
                      "max_episode_steps": parksim.ParkingTaskDef().max_episode_steps,
                      "vector_entry_point": "parksim.vector:VecParkingEnv"}]
    assert calls[0]["max_episode_steps"] == 300
    # Without gymnasium (Debian's interpreter): nothing to register with, and nothing breaks.
    if importlib.util.find_spec("gymnasium") is None:
        assert "gymnasium" not in sys.modules


def test_without_gymnasium_the_stand_in_spaces_serve(tmp_path):
    # Debian's interpreter has no Gymnasium: the stand-ins, with the same behaviour.
    code = textwrap.dedent("""
        import sys
        sys.modules["gymnasium"] = None  # import gymnasium fails
        import numpy as np, parksim
        env = parksim.ParkingEnv(fidelity="kinematic")
        assert type(env.action_space) is parksim.spaces.Box
        assert type(env).__mro__[1] is object
        first = env.reset(seed=4)[0]
        assert np.array_equal(first, env.reset(seed=4)[0])
        assert env.observation_space.contains(env.step(env.action_space.sample())[0])
        vec = parksim.VecParkingEnv(2, fidelity="kinematic", autoreset_mode="same_step")
        assert vec.metadata["autoreset_mode"] == "same_step"
        assert np.array_equal(vec.reset(seed=4)[0][0], first)
        print("ok")
    """)
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         env=dict(os.environ), timeout=60, cwd=tmp_path)
    assert out.returncode == 0, out.stderr
    assert out.stdout.split() == ["ok"]


def test_render_fps_follows_the_control_period(head_in):
    fast = parksim.ParkingEnv(world=head_in, control_period_s=0.05)
    default = parksim.ParkingEnv(world=head_in)
    assert fast.metadata["render_fps"] == pytest.approx(20.0)
    assert default.metadata["render_fps"] == pytest.approx(10.0)
    assert parksim.ParkingEnv.metadata["render_fps"] == 10
    # Rounded to whole physics steps: 0.03 s is 7 steps at 240 Hz.
    odd = parksim.ParkingEnv(world=head_in, control_period_s=0.03)
    assert odd.control_period_s == pytest.approx(7 / 240)
    assert odd.metadata["render_fps"] == pytest.approx(240 / 7)


def test_info_is_array_valued(head_in, env):
    obs, info = env.reset(seed=2)
    _, _, _, _, step_info = env.step([0.3, 0.2])
    for i in (info, step_info):
        assert not any(isinstance(v, (tuple, list)) for v in i.values()), i
        assert i["pose"].shape == (3,) and i["pose"].dtype == np.float64
        assert i["estimated_pose"].shape == (3,)
        assert i["contacts"].shape == (len(head_in.obstacles),) and i["contacts"].dtype == bool
        assert isinstance(i["t"], float) and isinstance(i["is_success"], bool)
    assert step_info["t"] == pytest.approx(env.control_period_s)


def test_reset_with_a_seed_leaves_the_users_action_space_alone(head_in):
    env = parksim.ParkingEnv(world=head_in)
    env.action_space.seed(9)
    expected = copy.deepcopy(env.action_space)  # the same generator, in the same state
    first = env.action_space.sample()
    assert np.array_equal(first, expected.sample())
    env.reset(seed=123)
    assert np.array_equal(env.action_space.sample(), expected.sample())
    env.reset(seed=123)
    assert np.array_equal(env.action_space.sample(), expected.sample())


def test_world_pickles_and_deep_copies(head_in):
    for copied in (pickle.loads(pickle.dumps(head_in)), copy.deepcopy(head_in),
                   copy.copy(head_in)):
        assert copied.name == head_in.name and copied.source_path == head_in.source_path
        assert [o["name"] for o in copied.obstacles] == [o["name"] for o in head_in.obstacles]
        assert copied.start == head_in.start
    from_dict = parksim.load_world({"format": "parksim-world/1", "name": "d",
                                    "lot": {"x_min": 0, "y_min": 0, "x_max": 2, "y_max": 2},
                                    "start": [0.1, 0.1, 0], "goal": {"pose": [1, 1, 0]}})
    assert pickle.loads(pickle.dumps(from_dict)).goal == from_dict.goal
    plan = parksim.plan(pickle.loads(pickle.dumps(head_in)), seed=1)
    assert plan.trajectory.tobytes() == parksim.plan(head_in, seed=1).trajectory.tobytes()


def test_environment_pickles_and_deep_copies_mid_episode(head_in):
    env = parksim.ParkingEnv(world=head_in, model={"solver": "fast"}, realism="lab")
    env.reset(seed=5)
    for action in actions(5, 7, scale=0.3):
        env.step(action)
    for twin in (pickle.loads(pickle.dumps(env)), copy.deepcopy(env)):
        for action in actions(6, 5, scale=0.3):
            a, b = env.step(action), twin.step(action)
            assert np.array_equal(a[0], b[0]) and a[1:4] == b[1:4]
            assert np.array_equal(a[4]["pose"], b[4]["pose"])
        env.reset(seed=5)
        for action in actions(5, 7, scale=0.3):
            env.step(action)
    # The seed sequence goes on as well: the next reset() draws the same start.
    twin = pickle.loads(pickle.dumps(env))
    assert np.array_equal(env.reset()[0], twin.reset()[0])
    assert pickle.loads(pickle.dumps(parksim.ParkingEnv(world=head_in))).world.name == "head_in"


def test_a_realism_preset_is_selectable_and_observed_through_the_estimate(head_in):
    lab = parksim.ParkingEnv(world=head_in, realism="lab")
    obs, info = lab.reset(seed=1)
    gap = 0.0
    for action in actions(1, 20):
        obs, _, terminated, truncated, info = lab.step(action)
        estimate, truth = info["estimated_pose"], info["pose"]
        assert np.array_equal(obs[:2], estimate[:2].astype(np.float32))
        assert obs[2] == np.float32(math.cos(estimate[2]))
        gap = max(gap, float(np.hypot(*(estimate[:2] - truth[:2]))))
        if terminated or truncated:
            break
    assert 0.0 < gap < 0.01  # an estimate (motion capture: sub-millimetre to millimetres)
    ideal = parksim.ParkingEnv(world=head_in, realism="ideal")
    obs, info = ideal.reset(seed=1)
    obs, *_, info = ideal.step([0.5, 0.5])
    assert np.array_equal(info["estimated_pose"], info["pose"])
    assert np.array_equal(obs[:2], info["pose"][:2].astype(np.float32))
    with pytest.raises(ValueError, match="realism"):
        parksim.ParkingEnv(world=head_in, realism="lab", fidelity="kinematic")
    with pytest.raises(ValueError, match="unknown"):
        parksim.ParkingEnv(world=head_in, realism="lunar")
