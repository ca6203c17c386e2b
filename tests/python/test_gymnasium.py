"""Gymnasium's own checker, wrappers and vector environments against ParkingEnv and
VecParkingEnv, with the real Gymnasium: 1.3.0 from PARKSIM_THIRD_PARTY (conftest.py). Skipped,
saying where it was looked for, where Gymnasium is not importable (ctest then reports the test
as skipped, not passed)."""

import warnings

import numpy as np
import pytest

import parksim
from conftest import gymnasium_or_skip


@pytest.fixture
def gym():
    # Per test, not for the module: a module skipped whole collects nothing, which fails ctest.
    return gymnasium_or_skip()


def test_the_gymnasium_found_is_the_third_party_copy(gym):
    # Where the folder is, these tests ran against its Gymnasium 1.3.0, not another one.
    import pathlib

    from conftest import GYMNASIUM_DIR

    if not GYMNASIUM_DIR.is_dir():
        pytest.skip(f"no {GYMNASIUM_DIR}: testing the installed Gymnasium {gym.__version__}")
    assert gym.__version__ == "1.3.0"
    assert pathlib.Path(gym.__file__).resolve().is_relative_to(GYMNASIUM_DIR.resolve())
    assert "parksim/Parking-v0" in gym.registry


@pytest.mark.parametrize("options", [{}, {"fidelity": "kinematic"}, {"realism": "lab"}],
                         ids=["dynamics", "kinematic", "lab"])
def test_check_env_passes_without_warnings(gym, options):
    from gymnasium.utils.env_checker import check_env

    env = gym.make("parksim/Parking-v0", **options)
    assert env.spec.max_episode_steps == parksim.ParkingTaskDef().max_episode_steps == 300
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        check_env(env.unwrapped)


def idle_episode_length(env, vector=False):
    """Steps of an episode of zero actions (nothing ends it but a time limit)."""
    env.reset(seed=0)
    action = np.zeros((env.num_envs, 2) if vector else 2, dtype=np.float32)
    for steps in range(1, 2000):
        _, _, terminated, truncated, _ = env.step(action)
        assert not np.any(terminated)
        if np.any(truncated):
            assert np.all(truncated)
            return steps
    return None


def test_max_episode_steps_means_gymnasiums_in_every_way_of_making_the_environment(gym):
    # gymnasium.make: the registered 300, or its argument; -1 (no TimeLimit): none of ours.
    assert idle_episode_length(gym.make("parksim/Parking-v0")) == 300
    assert idle_episode_length(gym.make("parksim/Parking-v0", max_episode_steps=500)) == 500
    assert idle_episode_length(gym.make("parksim/Parking-v0", max_episode_steps=50,
                                        fidelity="kinematic")) == 50
    unlimited = gym.make("parksim/Parking-v0", max_episode_steps=-1, fidelity="kinematic")
    assert unlimited.unwrapped.max_episode_steps is None
    assert idle_episode_length(unlimited) is None  # 2,000 steps and no end
    for mode in ("sync", "async", "vector_entry_point"):
        made = gym.make_vec("parksim/Parking-v0", num_envs=2, vectorization_mode=mode,
                            max_episode_steps=500, fidelity="kinematic")
        assert idle_episode_length(made, vector=True) == 500, mode
        made.close()
        default = gym.make_vec("parksim/Parking-v0", num_envs=2, vectorization_mode=mode,
                               fidelity="kinematic")
        assert idle_episode_length(default, vector=True) == 300, mode
        default.close()
        # -1: no limit in every mode (issue 39: the vector entry point refused it).
        unlimited = gym.make_vec("parksim/Parking-v0", num_envs=2, vectorization_mode=mode,
                                 max_episode_steps=-1, fidelity="kinematic")
        assert idle_episode_length(unlimited, vector=True) is None, mode
        unlimited.close()
    # And where the environment is made directly, -1 is None too.
    assert parksim.VecParkingEnv(2, max_episode_steps=-1).max_episode_steps is None
    assert parksim.ParkingEnv(max_episode_steps=-1).max_episode_steps is None


def test_time_limit_around_an_unlimited_env_is_the_envs_own_limit(gym):
    # TimeLimit(ParkingEnv without a limit, 40) and ParkingEnv(max_episode_steps=40): the same
    # steps, flags included (truncated also on a step that terminated).
    from gymnasium.wrappers import TimeLimit

    wrapped = TimeLimit(parksim.ParkingEnv(max_episode_steps=None), 40)
    own = parksim.ParkingEnv(max_episode_steps=40)
    actions = np.random.default_rng(1).uniform(-1, 1, size=(200, 2))
    for env in (wrapped, own):
        env.reset(seed=5)
    ends = 0
    for action in actions:
        a, b = wrapped.step(action), own.step(action)
        assert np.array_equal(a[0], b[0]) and a[1:4] == b[1:4]
        if a[2] or a[3]:
            ends += 1
            assert np.array_equal(wrapped.reset()[0], own.reset()[0])
    assert ends >= 4


@pytest.mark.parametrize("autoreset", ["next_step", "same_step"])
def test_a_sync_vector_env_of_parking_envs_matches_vec_parking_env(gym, autoreset):
    mode = {"next_step": gym.vector.AutoresetMode.NEXT_STEP,
            "same_step": gym.vector.AutoresetMode.SAME_STEP}[autoreset]
    sync = gym.make_vec("parksim/Parking-v0", num_envs=3, vectorization_mode="sync",
                        vector_kwargs={"autoreset_mode": mode}, max_episode_steps=12)
    vec = parksim.VecParkingEnv(3, autoreset_mode=autoreset, max_episode_steps=12)
    assert vec.metadata["autoreset_mode"] == mode
    a, _ = sync.reset(seed=10)
    b, _ = vec.reset(seed=10)
    assert np.array_equal(a, b)
    actions = np.random.default_rng(3).uniform(-1, 1, size=(30, 3, 2)).astype(np.float32)
    ends = 0
    for action in actions:
        x, y = sync.step(action), vec.step(action)
        for k in range(4):
            assert np.array_equal(x[k], y[k])
        assert np.array_equal(x[4]["pose"], y[4]["pose"])
        ended = x[2] | x[3]
        ends += ended.sum()
        if autoreset == "same_step" and ended.any():
            for key in ("final_obs", "final_info"):
                assert np.array_equal(x[4]["_" + key], y[4]["_" + key])
            for i in np.flatnonzero(ended):
                assert np.array_equal(x[4]["final_obs"][i], y[4]["final_obs"][i])
                for key in ("pose", "t", "is_success", "contacts"):
                    assert np.array_equal(x[4]["final_info"][key][i],
                                          y[4]["final_info"][key][i]), key
    assert ends >= 6


def test_async_vector_env_with_spawned_workers_matches(gym):
    # Workers that import parksim afresh (spawn) step the same episodes.
    spawned = gym.make_vec("parksim/Parking-v0", num_envs=2, vectorization_mode="async",
                           vector_kwargs={"context": "spawn"}, fidelity="kinematic")
    vec = parksim.VecParkingEnv(2, fidelity="kinematic")
    assert np.array_equal(spawned.reset(seed=2)[0], vec.reset(seed=2)[0])
    for action in np.random.default_rng(2).uniform(-1, 1, size=(20, 2, 2)):
        assert np.array_equal(spawned.step(action)[0], vec.step(action)[0])
    spawned.close()
