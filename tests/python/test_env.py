"""ParkingEnv's gymnasium contract: spaces, reset(seed) -> (obs, info), step -> five values,
determinism per seed, 1,000 random-policy steps."""

import numpy as np
import pytest

import parksim


@pytest.fixture(scope="module")
def env(head_in):
    return parksim.ParkingEnv(world=head_in, max_episode_steps=200)


def test_spaces_are_described(env):
    assert env.action_space.shape == (2,)
    assert env.action_space.dtype == np.float32
    assert np.all(env.action_space.low == -1.0) and np.all(env.action_space.high == 1.0)
    assert env.observation_space.shape == (10,)
    assert env.observation_space.dtype == np.float32


def test_a_thousand_random_steps_keep_the_contract(env):
    obs, info = env.reset(seed=7)
    assert obs.shape == (10,) and obs.dtype == np.float32
    assert env.observation_space.contains(obs)
    episodes, steps = 0, 0
    for _ in range(1000):
        steps += 1
        action = env.action_space.sample()
        assert env.action_space.contains(action)
        obs, reward, terminated, truncated, info = env.step(action)
        assert obs.shape == (10,) and np.all(np.isfinite(obs))
        assert isinstance(reward, float) and np.isfinite(reward)
        assert isinstance(terminated, bool) and isinstance(truncated, bool)
        assert truncated == (steps == 200)  # as Gymnasium's TimeLimit, also when terminated
        assert {"pose", "t", "goal_pos_err_m", "is_success", "contacts"} <= set(info)
        if terminated or truncated:
            episodes, steps = episodes + 1, 0
            obs, info = env.reset()
    assert episodes >= 1  # 200-step limit: at least one episode ended


def test_reset_with_a_seed_repeats_the_episode(env):
    def rollout(seed):
        obs, _ = env.reset(seed=seed)
        actions = np.random.default_rng(seed).uniform(-1.0, 1.0, size=(20, 2))
        out = [obs]
        for action in actions:
            out.append(env.step(action)[0])
        return np.array(out)

    a, b, c = rollout(3), rollout(3), rollout(4)
    assert np.array_equal(a, b)
    assert not np.array_equal(a, c)


def test_reward_is_the_documented_distance_and_success_terminates(head_in_path):
    import math

    import yaml

    def phi(info):  # the documented potential: -D, D parking-v0's goal distance
        return -math.sqrt(info["goal_pos_err_m"] / 0.1
                          + 0.3 * info["goal_heading_err_rad"] / math.pi)

    env = parksim.ParkingEnv(world=head_in_path, start_position_noise_m=0.0,
                             start_heading_noise_rad=0.0)
    assert env.discount == 1.0  # the shaping's gamma (issue 39)
    _, start = env.reset(seed=0)
    _, reward, terminated, _, info = env.step([0.5, 0.2])
    assert reward == pytest.approx(phi(info) - phi(start), rel=1e-12)
    assert not terminated and not info["is_success"]

    # The same lot with the robot starting on the goal: success at the first step.
    data = yaml.safe_load(head_in_path.read_text())
    data["start"] = data["goal"]["pose"]
    at_goal = parksim.ParkingEnv(world=parksim.load_world(data), start_position_noise_m=0.0,
                                 start_heading_noise_rad=0.0)
    _, start = at_goal.reset(seed=0)
    _, reward, terminated, truncated, info = at_goal.step([0.0, 0.0])
    assert info["is_success"] and terminated and not truncated
    assert reward == pytest.approx(10.0 - phi(start), rel=1e-12)  # phi(terminal) = 0


def test_render_returns_an_image(head_in):
    env = parksim.ParkingEnv(world=head_in, render_mode="rgb_array")
    env.reset(seed=1)
    image = env.render()
    assert image.shape == (480, 640, 3) and image.dtype == np.uint8


def test_box_space_stand_in_samples_reproducibly():
    box = parksim.spaces.Box(-1.0, 1.0, shape=(3,), seed=5)
    a = [box.sample() for _ in range(3)]
    box.seed(5)
    b = [box.sample() for _ in range(3)]
    assert np.array_equal(a, b)
    assert all(box.contains(s) for s in a)
    unbounded = parksim.spaces.Box(-np.inf, np.inf, shape=(4,), seed=1)
    assert np.all(np.isfinite(unbounded.sample()))
