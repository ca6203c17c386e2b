"""VecParkingEnv (issue 21, item 4): Gymnasium's vector API with batched arrays, autoreset at
the next step, per-sub-environment seeds, the same trajectories with 1 and 2 threads, the GIL
released while stepping, and the kinematic fidelity selectable for both environments."""

import math
import sys
import threading
import time

import numpy as np
import pytest

import parksim


def batch_actions(seed, steps, n, scale=1.0):
    rng = np.random.default_rng(seed)
    return (scale * rng.uniform(-1.0, 1.0, size=(steps, n, 2))).astype(np.float32)


def rollout(envs, seed, actions):
    obs, infos = envs.reset(seed=seed)
    out = [(obs, None, None, None, infos)]
    for a in actions:
        out.append(envs.step(a))
    return out


def test_batched_arrays_with_gymnasiums_shapes(head_in):
    envs = parksim.VecParkingEnv(3, world=head_in)
    assert envs.num_envs == 3
    assert envs.single_observation_space.shape == (10,)
    assert envs.observation_space.shape == (3, 10) and envs.action_space.shape == (3, 2)
    obs, infos = envs.reset(seed=0)
    assert obs.shape == (3, 10) and obs.dtype == np.float32
    obs, rewards, terminated, truncated, infos = envs.step(envs.action_space.sample())
    assert obs.shape == (3, 10) and obs.dtype == np.float32
    assert rewards.shape == (3,) and rewards.dtype == np.float64
    assert terminated.shape == (3,) and terminated.dtype == bool
    assert truncated.shape == (3,) and truncated.dtype == bool
    assert infos["pose"].shape == (3, 3) and infos["estimated_pose"].shape == (3, 3)
    assert infos["contacts"].shape == (3, len(head_in.obstacles))
    for key in ("t", "goal_pos_err_m", "goal_heading_err_rad", "is_success"):
        assert infos[key].shape == (3,), key
    for key in list(infos):
        if not key.startswith("_"):
            assert infos["_" + key].dtype == bool and infos["_" + key].all()
    assert envs.observation_space.contains(obs)
    assert envs.metadata["render_fps"] == pytest.approx(10.0)


def test_sub_environment_i_is_a_single_environment_seeded_s_plus_i(head_in):
    steps, n = 12, 2
    a = batch_actions(1, steps, n, scale=0.5)
    envs = parksim.VecParkingEnv(n, world=head_in, max_episode_steps=5)
    batch = rollout(envs, 40, a)
    for i in range(n):
        env = parksim.ParkingEnv(world=head_in, max_episode_steps=5)
        obs, _ = env.reset(seed=40 + i)
        assert np.array_equal(batch[0][0][i], obs)
        ended = False
        for k in range(steps):
            if ended:  # the vector environment resets at the next step; the single one is told
                obs, info = env.reset()
                reward, terminated, truncated = 0.0, False, False
            else:
                obs, reward, terminated, truncated, info = env.step(a[k][i])
            got = batch[k + 1]
            assert np.array_equal(got[0][i], obs), (i, k)
            assert got[1][i] == reward and got[2][i] == terminated and got[3][i] == truncated
            assert np.array_equal(got[4]["pose"][i], info["pose"])
            ended = terminated or truncated


def test_autoreset_happens_at_the_next_step(head_in):
    envs = parksim.VecParkingEnv(2, world=head_in, fidelity="kinematic", max_episode_steps=3)
    first, _ = envs.reset(seed=8)
    for _ in range(3):
        _, rewards, terminated, truncated, _ = envs.step(np.zeros((2, 2)))
    assert truncated.all() and not terminated.any()
    obs, rewards, terminated, truncated, infos = envs.step(np.ones((2, 2)))  # actions ignored
    assert not terminated.any() and not truncated.any()
    assert np.array_equal(rewards, [0.0, 0.0])
    assert np.array_equal(infos["t"], [0.0, 0.0])
    single = parksim.ParkingEnv(world=head_in, fidelity="kinematic")
    single.reset(seed=8)
    assert np.array_equal(obs[0], single.reset()[0])  # the seed's second episode
    assert not np.array_equal(obs[0], first[0])


def test_one_and_two_threads_give_identical_trajectories(head_in):
    for fidelity in ("dynamics", "kinematic"):
        a = batch_actions(2, 40, 4)
        runs = []
        for threads in (1, 2):
            envs = parksim.VecParkingEnv(4, world=head_in, threads=threads, fidelity=fidelity,
                                         max_episode_steps=15)
            assert envs.threads == threads
            runs.append(rollout(envs, 11, a))
        ends = 0
        for one, two in zip(*runs):
            assert np.array_equal(one[0], two[0]), fidelity
            for k in (1, 2, 3):
                if one[k] is not None:
                    assert np.array_equal(one[k], two[k]), fidelity
            assert np.array_equal(one[4]["pose"], two[4]["pose"])
            if one[2] is not None:
                ends += int(one[2].sum() + one[3].sum())
        assert ends >= 8, fidelity  # autoresets happened within the run


def test_seeds_per_sub_environment(head_in):
    envs = parksim.VecParkingEnv(3, world=head_in, fidelity="kinematic")
    obs, _ = envs.reset(seed=[5, None, 7])
    lone = parksim.VecParkingEnv(3, world=head_in, fidelity="kinematic")
    obs2, _ = lone.reset(seed=5)  # sub-environments 5, 6, 7
    assert np.array_equal(obs[0], obs2[0]) and np.array_equal(obs[2], obs2[2])
    with pytest.raises(ValueError, match="3 environments"):
        envs.reset(seed=[1, 2])
    with pytest.raises(ValueError, match="non-negative"):
        envs.reset(seed=-1)


def test_bad_actions_are_refused_before_anything_steps(head_in):
    envs = parksim.VecParkingEnv(2, world=head_in, fidelity="kinematic")
    obs, _ = envs.reset(seed=1)
    with pytest.raises(ValueError, match="action 1.*finite"):
        envs.step([[0.5, 0.5], [np.nan, 0.0]])
    with pytest.raises(ValueError, match=r"shape \(2, 2\)"):
        envs.step([0.5, 0.5])
    obs2, _, _, _, infos = envs.step(np.zeros((2, 2)))
    assert np.array_equal(infos["t"], [envs.control_period_s] * 2)  # the first step taken
    assert np.array_equal(obs2[:, :4], obs[:, :4])


def test_the_gil_is_released_while_stepping(head_in):
    # A Python thread appends ticks while the main thread is inside step() (8 Bullet worlds,
    # 1 s each). The switch interval is made far longer than a step, so a step that held the
    # GIL would let no tick in: ticks inside a step come only from a released GIL, whatever
    # the machine's load. A thread the OS has not scheduled during one step gets more steps
    # (a count, not a time limit); holding the GIL gives 0 ticks in all of them.
    envs = parksim.VecParkingEnv(8, world=head_in, threads=1, control_period_s=1.0)
    envs.reset(seed=0)
    ticks, stop = [], threading.Event()

    def count():
        while not stop.is_set():
            ticks.append(time.perf_counter())
            time.sleep(0)  # hands the GIL back at once, so the main thread never waits for it

    interval = sys.getswitchinterval()
    sys.setswitchinterval(1000.0)
    counter = threading.Thread(target=count)
    try:
        counter.start()
        time.sleep(0.01)
        inside = 0
        for _ in range(10):
            begin = time.perf_counter()
            envs.step(np.full((8, 2), 0.3))
            end = time.perf_counter()
            inside = sum(1 for t in list(ticks) if begin < t < end)
            if inside > 0:
                break
    finally:
        stop.set()
        counter.join()
        sys.setswitchinterval(interval)
    assert inside > 0  # the other thread ran while step() was in C++


def test_kinematic_fidelity_is_exact_arcs_in_both_environments(head_in):
    env = parksim.ParkingEnv(world=head_in, fidelity="kinematic")
    assert env.fidelity == "kinematic"
    start = (0.3, 0.3, 0.4)
    obs, info = env.reset(options={"start": start})
    assert np.array_equal(info["pose"], start)
    _, _, _, _, info = env.step([0.25, 0.75])
    robot, dt = head_in.robot, env.control_period_s
    wl, wr = 0.25 * robot.max_wheel_speed_radps, 0.75 * robot.max_wheel_speed_radps
    v = robot.wheel_radius_m * (wl + wr) / 2
    w = robot.wheel_radius_m * (wr - wl) / robot.wheel_base_m
    x, y, th = start
    expected = (x + v / w * (math.sin(th + w * dt) - math.sin(th)),
                y - v / w * (math.cos(th + w * dt) - math.cos(th)), th + w * dt)
    assert np.allclose(info["pose"], expected, rtol=0, atol=1e-12)
    envs = parksim.VecParkingEnv(2, world=head_in, fidelity="kinematic")
    assert envs.fidelity == "kinematic" and "kinematic" in repr(envs)
    assert parksim.ParkingEnv(world=head_in).fidelity == "dynamics"
    with pytest.raises(ValueError, match="dynamics or kinematic"):
        parksim.ParkingEnv(world=head_in, fidelity="mujoco")
