"""With Gymnasium installed (not in Debian: skipped here), its own checker and vector
environments against ParkingEnv and VecParkingEnv. Verified by hand with Gymnasium 1.4.0."""

import warnings

import numpy as np
import pytest

import parksim


@pytest.fixture
def gym():
    # Per test, not for the module: a module skipped whole collects nothing, which fails ctest.
    return pytest.importorskip("gymnasium")


def test_check_env_passes_without_warnings(gym):
    from gymnasium.utils.env_checker import check_env

    env = gym.make("parksim/Parking-v0")
    assert env.spec.max_episode_steps == parksim.ParkingTaskDef().max_episode_steps
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        check_env(env.unwrapped)


def test_a_sync_vector_env_of_parking_envs_matches_vec_parking_env(gym):
    sync = gym.make_vec("parksim/Parking-v0", num_envs=3, vectorization_mode="sync")
    vec = gym.make_vec("parksim/Parking-v0", num_envs=3, vectorization_mode="vector_entry_point")
    assert isinstance(vec, parksim.VecParkingEnv)
    a, _ = sync.reset(seed=10)
    b, _ = vec.reset(seed=10)
    assert np.array_equal(a, b)
    actions = np.random.default_rng(3).uniform(-1, 1, size=(30, 3, 2)).astype(np.float32)
    for action in actions:
        x, y = sync.step(action), vec.step(action)
        for k in range(4):
            assert np.array_equal(x[k], y[k])
        assert np.array_equal(x[4]["pose"], y[4]["pose"])
