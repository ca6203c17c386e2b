"""SB3VecEnv against Stable-Baselines3's documented VecEnv contract (stable_baselines3 is not
installable here): what its documentation and its DummyVecEnv do, written out below as
ReferenceVecEnv over n ParkingEnvs stepped one after another, must be what SB3VecEnv does over
one VecParkingEnv's C++ threads, bit for bit; and the rest of the interface (seed, options,
get_attr, set_attr, env_method, env_is_wrapped, render) as documented."""

import numpy as np
import pytest

import parksim
from parksim.sb3 import SB3VecEnv


class ReferenceVecEnv:
    """SB3's VecEnv contract as DummyVecEnv keeps it, over ParkingEnvs: reset(seed s + i) ->
    stacked observations and reset_infos; step -> observations, float32 rewards, dones
    (terminated or truncated), and per-sub-environment infos in which an ended episode's last
    observation is "terminal_observation" (the sub-environment reset at once, its new
    observation returned), and "TimeLimit.truncated" is truncated and not terminated."""

    def __init__(self, n, **options):
        self.envs = [parksim.ParkingEnv(**options) for _ in range(n)]
        self.reset_infos = [{} for _ in range(n)]

    def reset(self, seed):
        obs = []
        for i, env in enumerate(self.envs):
            o, self.reset_infos[i] = env.reset(seed=seed + i)
            obs.append(o)
        return np.stack(obs)

    def step(self, actions):
        obs, rewards, dones, infos = [], [], [], []
        for i, env in enumerate(self.envs):
            o, reward, terminated, truncated, info = env.step(actions[i])
            info["TimeLimit.truncated"] = truncated and not terminated
            if terminated or truncated:
                info["terminal_observation"] = o
                o, self.reset_infos[i] = env.reset()
            obs.append(o)
            rewards.append(reward)
            dones.append(terminated or truncated)
            infos.append(info)
        return (np.stack(obs), np.array(rewards, dtype=np.float32), np.array(dones), infos)


def same_info(a, b):
    assert a.keys() == b.keys()
    for key in a:
        assert type(a[key]) is type(b[key]), key
        assert np.array_equal(a[key], b[key]), key


@pytest.mark.parametrize("fidelity", ["dynamics", "kinematic"])
def test_steps_as_the_documented_contract_over_parking_envs(head_in, fidelity):
    options = dict(world=head_in, fidelity=fidelity, max_episode_steps=8)
    env = SB3VecEnv(3, threads=2, **options)
    reference = ReferenceVecEnv(3, **options)
    assert env.num_envs == 3 and env.venv.threads == 2
    assert env.observation_space.shape == (10,) and env.action_space.shape == (2,)
    assert env.seed(20) == [20, 21, 22]
    obs = env.reset()
    assert obs.dtype == np.float32 and obs.shape == (3, 10)
    assert np.array_equal(obs, reference.reset(20))
    for a, b in zip(env.reset_infos, reference.reset_infos):
        same_info(a, b)
    actions = np.random.default_rng(6).uniform(-1, 1, size=(30, 3, 2)).astype(np.float32)
    ends = {"terminated": 0, "truncated": 0}
    for action in actions:
        env.step_async(action)
        got = env.step_wait()
        expected = reference.step(action)
        for k in range(3):
            assert got[k].dtype == expected[k].dtype
            assert np.array_equal(got[k], expected[k]), k
        for a, b in zip(got[3], expected[3]):
            same_info(a, b)
            if "terminal_observation" in a:
                ends["truncated" if a["TimeLimit.truncated"] else "terminated"] += 1
        for a, b in zip(env.reset_infos, reference.reset_infos):
            same_info(a, b)
    assert ends["truncated"] >= 3  # 8-step episodes: time-outs, bootstrapped by SB3
    # step() is step_async + step_wait.
    assert np.array_equal(env.step(actions[0])[0], reference.step(actions[0])[0])


def test_seeds_and_options_are_used_by_the_next_reset_only(head_in):
    env = SB3VecEnv(2, world=head_in, fidelity="kinematic")
    env.seed(7)
    first = env.reset()
    second = env.reset()  # no seed: the sequences go on
    assert not np.array_equal(first, second)
    env.seed(7)
    assert np.array_equal(env.reset(), first)
    seeds = env.seed()  # from entropy, consecutive
    assert seeds[1] == seeds[0] + 1
    env.set_options({"start": (0.3, 0.3, 0.0)})
    with pytest.raises(ValueError, match="options"):
        env.reset()


def test_attributes_and_methods_of_the_sub_environments(head_in):
    env = SB3VecEnv(3, world=head_in, fidelity="kinematic", render_mode="rgb_array")
    env.reset()
    assert env.render_mode == "rgb_array" and env.get_attr("render_mode") == ["rgb_array"] * 3
    assert env.get_attr("fidelity", indices=1) == ["kinematic"]
    assert env.get_attr("max_episode_steps", [0, 2]) == [300, 300]
    assert env.get_attr("discount") == [1.0] * 3
    assert env.get_attr("observation_space")[0].shape == (10,)
    assert env.has_attr("control_period_s") and not env.has_attr("no_such_attribute")
    with pytest.raises(AttributeError):
        env.get_attr("no_such_attribute")
    # The task's definition is read-only; other attributes are the user's.
    with pytest.raises(AttributeError):
        env.set_attr("max_episode_steps", 10)
    env.set_attr("note", "mine", indices=[0, 2])
    assert env.get_attr("note", [0, 2]) == ["mine", "mine"]
    assert not env.has_attr("note")  # sub-environment 1 has none
    images = env.env_method("render", indices=[1])
    assert len(images) == 1 and images[0].shape == (480, 640, 3)
    assert env.env_method("get_wrapper_attr", "fidelity") == ["kinematic"] * 3
    assert env.env_is_wrapped(object) == [False] * 3
    tiled = env.render("rgb_array")
    assert tiled.shape == (2 * 480, 2 * 640, 3)  # 3 images in a 2 x 2 grid
    assert np.array_equal(tiled[:480, 640:], images[0])
    assert env.unwrapped is env and env.getattr_depth_check("num_envs", True)
    env.close()


def test_misuse_is_refused(head_in):
    env = SB3VecEnv(2, world=head_in, fidelity="kinematic")
    with pytest.raises(RuntimeError, match="reset"):
        env.step(np.zeros((2, 2)))
    env.reset()
    with pytest.raises(RuntimeError, match="step_async"):
        env.step_wait()
    with pytest.raises(ValueError, match=r"actions: expected shape \(2, 2\).*got strings"):
        env.step([["0", "1"], ["0", "1"]])
    with pytest.raises(TypeError, match="autoreset_mode"):
        SB3VecEnv(2, world=head_in, autoreset_mode="next_step")
