"""ParkingEnv(observation="goal_dict"): highway-env parking-v0's goal-conditioned observation
(observation, achieved_goal, desired_goal) and compute_reward(achieved, desired, info) for
hindsight experience replay, for a differential drive and a car. compute_reward must be the
step's own reward for the step's goal, vectorised, and for another goal the reward
docs/python.md's formula gives, computed here."""

import math

import numpy as np
import pytest

import parksim

CAR_WORLD = """format: parksim-world/1
name: open_car
lot: {x_min: 0.0, y_min: 0.0, x_max: 30.0, y_max: 20.0}
robot: {drive: car}
obstacles:
  - {name: block, kind: wall, center: [20.0, 10.0], size: [1.0, 6.0], height: 1.0}
start: [10.0, 10.0, 0]
goal:
  pose: [12.0, 14.0, 90]
"""


@pytest.fixture(scope="module")
def car_world(tmp_path_factory):
    path = tmp_path_factory.mktemp("goal") / "open_car.yaml"
    path.write_text(CAR_WORLD)
    return parksim.load_world(str(path))


def episodes(env, actions, starts):
    """Every transition (obs, reward, info) of one episode per start, each driven by `actions`
    (a function of the step) until it terminates or 200 steps."""
    out = []
    for start in starts:
        obs, _ = env.reset(seed=0, options={"start": start})
        assert obs in env.observation_space
        for k in range(200):
            obs, reward, terminated, truncated, info = env.step(actions(k))
            assert obs in env.observation_space
            out.append((obs, reward, terminated, info))
            if terminated or truncated:
                break
    return out


def goal_distance(defn, pose, goal):
    """docs/python.md's D: sqrt(d / distance_scale_m + heading_weight * e / pi)."""
    d = math.hypot(pose[0] - goal[0], pose[1] - goal[1])
    e = abs(math.remainder(pose[2] - goal[2], 2 * math.pi))
    return math.sqrt(d / defn.distance_scale_m + defn.heading_weight * e / math.pi)


def check_transitions(env, transitions):
    rewards = np.array([r for _, r, _, _ in transitions])
    achieved = np.array([o["achieved_goal"] for o, *_ in transitions])
    desired = np.array([o["desired_goal"] for o, *_ in transitions])
    infos = np.array([i for *_, i in transitions], dtype=object)
    # One at a time, and all at once (SB3's HerReplayBuffer passes an array of infos).
    for (obs, reward, _, info) in transitions:
        assert env.compute_reward(obs["achieved_goal"], obs["desired_goal"], info) == \
            pytest.approx(reward, rel=1e-12, abs=1e-12)
    batch = env.compute_reward(achieved, desired, infos)
    assert batch.shape == rewards.shape
    np.testing.assert_allclose(batch, rewards, rtol=1e-12, atol=1e-12)
    return rewards, achieved, infos


@pytest.mark.parametrize("kind", ["differential", "car"])
def test_compute_reward_is_the_steps_reward(kind, head_in, car_world):
    if kind == "car":
        env = parksim.ParkingEnv(car_world, fidelity="kinematic", observation="goal_dict",
                                 max_episode_steps=None)
        # Forward into the block (a contact), reverse out of the lot (an exit), and a turn.
        transitions = episodes(env, lambda k: [1.0, 0.0], [(12.0, 10.0, 0.0)])
        transitions += episodes(env, lambda k: [-1.0, 0.3], [(3.0, 10.0, 0.0)])
        transitions += episodes(env, lambda k: [0.5, 1.0], [(10.0, 10.0, 0.0)])
    else:
        env = parksim.ParkingEnv(head_in, fidelity="kinematic", observation="goal_dict",
                                 max_episode_steps=None)
        rng = np.random.default_rng(3)
        transitions = episodes(env, lambda k: rng.uniform(-1, 1, 2), [head_in.start] * 3)
        transitions += episodes(env, lambda k: [1.0, 1.0], [head_in.start])
    assert env.observation_space["observation"].shape == (6,)
    obs0 = transitions[0][0]
    assert obs0["desired_goal"] == pytest.approx(
        [*env.world.goal["pose"][:2], math.cos(env.world.goal["pose"][2]),
         math.sin(env.world.goal["pose"][2])], abs=1e-15)
    _, _, infos = check_transitions(env, transitions)
    # The steps include the outcomes the reward adds to the shaping.
    assert any(np.any(i["contacts"]) for i in infos) or kind == "differential"
    ended = [t for *_, t, _ in transitions]
    assert any(ended)


def test_compute_reward_for_a_relabelled_goal_follows_the_documented_formula(car_world):
    env = parksim.ParkingEnv(car_world, fidelity="kinematic", observation="goal_dict",
                             max_episode_steps=None)
    defn = env._task.definition
    transitions = episodes(env, lambda k: [0.6, 0.5], [(10.0, 10.0, 0.0)])
    for obs, _, _, info in transitions[5:40:7]:
        before = info["previous_achieved_goal"]
        before_pose = (before[0], before[1], math.atan2(before[3], before[2]))
        pose = tuple(info["pose"])
        # Reached: this step's pose as the goal (hindsight): success, no shaping after it.
        expected = defn.success_reward + defn.shaping_weight * goal_distance(
            defn, before_pose, pose)
        assert env.compute_reward(obs["achieved_goal"], obs["achieved_goal"], info) == \
            pytest.approx(expected, rel=1e-9)
        # Another goal 3 m away, not reached: the shaping alone.
        goal = (pose[0] + 3.0, pose[1], 0.5)
        phi = lambda p: -defn.shaping_weight * goal_distance(defn, p, goal)  # noqa: E731
        desired = [goal[0], goal[1], math.cos(goal[2]), math.sin(goal[2])]
        assert env.compute_reward(obs["achieved_goal"], desired, info) == pytest.approx(
            defn.discount * phi(pose) - phi(before_pose), rel=1e-9)


def test_the_array_observation_stays_the_default(head_in):
    env = parksim.ParkingEnv(head_in, fidelity="kinematic")
    obs, _ = env.reset(seed=0)
    assert obs.shape == (10,)
    with pytest.raises(ValueError, match="observation must be one of"):
        parksim.ParkingEnv(head_in, observation="dict")


def test_compute_reward_without_the_steps_info_names_what_it_needs(car_world):
    # Stable-Baselines3's HerReplayBuffer passes empty dicts unless copy_info_dict=True.
    env = parksim.ParkingEnv(car_world, fidelity="kinematic", observation="goal_dict")
    obs, _ = env.reset(seed=0)
    with pytest.raises(ValueError, match=r"copy_info_dict=True"):
        env.compute_reward(obs["achieved_goal"][None], obs["desired_goal"][None], np.array([{}]))
