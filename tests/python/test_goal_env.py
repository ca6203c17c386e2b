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


def same_dict(got, want, i=None):
    """The goal dict `got` (row i of a batched one) equals the single environment's `want`."""
    assert set(got) == set(want) == {"observation", "achieved_goal", "desired_goal"}
    for key, value in want.items():
        row = got[key] if i is None else got[key][i]
        assert row.dtype == value.dtype and np.array_equal(row, value), key


def row_info(infos, i):
    return {"previous_achieved_goal": infos["previous_achieved_goal"][i],
            "contacts": infos["contacts"][i]}


@pytest.mark.parametrize("mode", ["next_step", "same_step"])
@pytest.mark.parametrize("kind", ["differential", "car"])
def test_vector_goal_dicts_equal_the_single_environments(kind, mode, head_in, car_world):
    # Sub-environment i seeded s + i is ParkingEnv(seed=s + i), reset after each end: the same
    # dict entries, previous_achieved_goal and compute_reward, across autoresets.
    world = car_world if kind == "car" else head_in
    n, steps, seed = 2, 14, 30
    options = dict(fidelity="kinematic", observation="goal_dict", max_episode_steps=5)
    actions = np.random.default_rng(5).uniform(-1.0, 1.0, (steps, n, 2))
    envs = parksim.VecParkingEnv(n, world, autoreset_mode=mode, **options)
    singles = [parksim.ParkingEnv(world, **options) for _ in range(n)]
    assert envs.single_observation_space["observation"].shape == (6,)
    assert envs.observation_space["achieved_goal"].shape == (n, 4)
    obs, _ = envs.reset(seed=seed)
    assert obs in envs.observation_space
    for i, env in enumerate(singles):
        same_dict(obs, env.reset(seed=seed + i)[0], i)
    ended, resets = [False] * n, 0
    for k in range(steps):
        obs, rewards, terminated, truncated, infos = envs.step(actions[k])
        assert obs in envs.observation_space
        for i, env in enumerate(singles):
            if ended[i]:  # next_step: this step reset sub-environment i
                want, _ = env.reset()
                assert not infos["_previous_achieved_goal"][i] and rewards[i] == 0.0
                same_dict(obs, want, i)
                ended[i], resets = False, resets + 1
                continue
            want, reward, term, trunc, info = env.step(actions[k][i])
            assert rewards[i] == reward and terminated[i] == term and truncated[i] == trunc
            single_reward = env.compute_reward(want["achieved_goal"], want["desired_goal"], info)
            if mode == "same_step" and (term or trunc):
                same_dict(infos["final_obs"][i], want)
                final = infos["final_info"]
                assert np.array_equal(final["previous_achieved_goal"][i],
                                      info["previous_achieved_goal"])
                got = envs.compute_reward(want["achieved_goal"], want["desired_goal"],
                                          row_info(final, i))
                assert not infos["_previous_achieved_goal"][i]
                want, _ = env.reset()
                resets += 1
            else:
                assert infos["_previous_achieved_goal"][i]
                assert np.array_equal(infos["previous_achieved_goal"][i],
                                      info["previous_achieved_goal"])
                got = envs.compute_reward(obs["achieved_goal"][i], obs["desired_goal"][i],
                                          row_info(infos, i))
                ended[i] = term or trunc
            assert got == single_reward == pytest.approx(reward, rel=1e-12, abs=1e-12)
            same_dict(obs, want, i)
    assert resets >= n  # the episodes of 5 steps ended and restarted
    # Batched: one call for every sub-environment's step.
    batch = envs.compute_reward(obs["achieved_goal"], obs["desired_goal"],
                                [row_info(infos, i) for i in range(n)])
    assert batch.shape == (n,)


def test_sb3_vec_env_gives_the_goal_dicts_and_compute_reward(car_world):
    from parksim.sb3 import SB3VecEnv

    n, steps, seed = 2, 12, 7
    options = dict(fidelity="kinematic", observation="goal_dict", max_episode_steps=4)
    actions = np.random.default_rng(9).uniform(-1.0, 1.0, (steps, n, 2))
    venv = SB3VecEnv(n, car_world, **options)
    singles = [parksim.ParkingEnv(car_world, **options) for _ in range(n)]
    assert venv.observation_space["desired_goal"].shape == (4,)
    venv.seed(seed)
    obs = venv.reset()
    for i, env in enumerate(singles):
        same_dict(obs, env.reset(seed=seed + i)[0], i)
    dones_seen = 0
    for k in range(steps):
        obs, rewards, dones, infos = venv.step(actions[k])
        for i, env in enumerate(singles):
            want, reward, term, trunc, info = env.step(actions[k][i])
            assert rewards[i] == np.float32(reward) and dones[i] == (term or trunc)
            assert np.array_equal(infos[i]["previous_achieved_goal"],
                                  info["previous_achieved_goal"])
            achieved = want["achieved_goal"]
            if dones[i]:
                same_dict(infos[i]["terminal_observation"], want)
                want, _ = env.reset()
                dones_seen += 1
            else:
                assert np.array_equal(obs["achieved_goal"][i], achieved)
            # As HerReplayBuffer calls it: on sub-environment 0, infos an array of dicts.
            got = venv.env_method("compute_reward", achieved[None], want["desired_goal"][None],
                                  np.array([infos[i]], dtype=object), indices=[0])[0]
            assert got.shape == (1,) and got[0] == pytest.approx(reward, rel=1e-12, abs=1e-12)
            same_dict(obs, want, i)
    assert dones_seen >= n
