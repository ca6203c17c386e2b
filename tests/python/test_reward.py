"""The reward teaches parking (issue 34): from each start, scripted park, crash, exit and idle
episodes return what the potential-based shaping predicts (-phi(s_0) plus the discounted
outcome) and rank the park first, for discounts 0.9 to 1, in both fidelities and under every
realism. And the reward changes no state: the same actions give the same states, bit for bit,
whatever the reward's options."""

import math

import numpy as np
import pytest

import parksim

GOAL = (1.5, 0.04, -math.pi / 2)  # head_in's: head-in between robot_5 and robot_6
ROBOT_5 = (1.3425, 0.045)         # the middle of its footprint
# North of the slot, on and off its axis, and west of it facing east.
STARTS = [(1.5, 0.35, -math.pi / 2), (1.45, 0.45, -1.4), (1.56, 0.42, -1.75), (1.2, 0.4, 0.0)]
GAMMAS = (0.9, 0.95, 0.99, 1.0)
STEPS = 150  # the idle episode's length; the others end sooner


def wrap(a):
    return (a + math.pi) % (2 * math.pi) - math.pi


def drive(obs, target, heading=None, v_max=0.2, b=0.085):
    """Wheel speed fractions towards `target` from the observation (what the controller knows):
    the polar move-to-pose law into `heading`, or turn-then-drive at full speed without one."""
    x, y, c, s = obs[:4]
    theta = math.atan2(s, c)
    rho = math.hypot(target[0] - x, target[1] - y)
    alpha = wrap(math.atan2(target[1] - y, target[0] - x) - theta)
    if heading is None:
        v, w = (v_max if abs(alpha) < 0.2 else 0.0), 3.0 * alpha
    else:
        v, w = rho, 3.0 * alpha - wrap(heading - theta - alpha)
    left, right = v - w * b / 2, v + w * b / 2
    scale = max(abs(left), abs(right), v_max)
    return [left / scale, right / scale]


POLICIES = {
    "park": lambda obs: drive(obs, GOAL[:2], GOAL[2]),
    "crash": lambda obs: drive(obs, ROBOT_5),           # into the parked robot_5
    "exit": lambda obs: drive(obs, (2.2, obs[1])),      # east, out of the lot
    "idle": lambda obs: [0.0, 0.0],                     # until the step limit
}


def episode(env, start, policy):
    """(discounted return at env.discount, steps, last info, terminated, truncated, trace)."""
    obs, info = env.reset(options={"start": start, "noise_seed": 7})
    phi0 = potential(env, info)
    ret, weight, steps, trace = 0.0, 1.0, 0, [obs]
    while True:
        obs, reward, terminated, truncated, info = env.step(policy(obs))
        ret += weight * reward
        weight *= env.discount
        steps += 1
        trace.append(np.concatenate([obs, info["pose"]]))
        if terminated or truncated:
            return dict(ret=ret, steps=steps, info=info, terminated=terminated,
                        truncated=truncated, phi0=phi0, trace=np.array(trace[1:]))


def potential(env, info):
    """The documented potential: -D, D parking-v0's goal distance (weight 1)."""
    return -math.sqrt(info["goal_pos_err_m"] / 0.1 + 0.3 * info["goal_heading_err_rad"] / math.pi)


CONFIGS = {
    "kinematic": dict(fidelity="kinematic"),
    "dynamics": dict(realism="ideal"),
    "dynamics-lab": dict(realism="lab"),
    "dynamics-odometry": dict(realism="odometry"),
}


@pytest.mark.parametrize("config", CONFIGS)
def test_parking_returns_more_than_crashing_leaving_or_idling(head_in, config):
    # Odometry drifts: from the west start its estimate misses the slot (a time-out).
    starts = STARTS[:3] if config == "dynamics-odometry" else STARTS
    for gamma in GAMMAS:
        env = parksim.ParkingEnv(world=head_in, max_episode_steps=STEPS, discount=gamma,
                                 **CONFIGS[config])
        for start in starts:
            at = f"{config}, gamma {gamma}, start {start}"
            runs = {name: episode(env, start, policy) for name, policy in POLICIES.items()}
            park, crash, exit_, idle = (runs[k] for k in ("park", "crash", "exit", "idle"))
            assert park["terminated"] and park["info"]["is_success"], at
            assert crash["terminated"] and park["info"]["contacts"].sum() == 0, at
            assert crash["info"]["contacts"].any(), at
            assert exit_["terminated"] and exit_["info"]["pose"][0] > head_in.lot["x_max"], at
            assert idle["truncated"] and not idle["terminated"] and idle["steps"] == STEPS, at

            # The shaping telescopes: -phi(s_0), plus the outcome discounted to the last step,
            # or at the time-out gamma^T phi(s_T).
            start_value = -park["phi0"]
            for run, outcome in ((park, 10.0), (crash, -10.0), (exit_, -10.0)):
                predicted = start_value + gamma ** (run["steps"] - 1) * outcome
                assert run["ret"] == pytest.approx(predicted, abs=1e-9), at
            assert idle["ret"] == pytest.approx(
                start_value + gamma ** STEPS * potential(env, idle["info"]), abs=1e-9), at

            assert park["ret"] > idle["ret"] > max(crash["ret"], exit_["ret"]), at


def test_without_shaping_one_reward_ranks_the_episodes_for_every_discount(head_in):
    # shaping_weight 0: the outcome alone (10, -10, -10, 0 at a time-out), which no discount
    # reorders; the returns are computed here at each discount from one run.
    env = parksim.ParkingEnv(world=head_in, fidelity="kinematic", max_episode_steps=STEPS,
                             shaping_weight=0.0, discount=1.0)
    for start in STARTS:
        runs = {name: episode(env, start, policy) for name, policy in POLICIES.items()}
        for gamma in GAMMAS:
            ret = {name: gamma ** (r["steps"] - 1) * r["ret"] for name, r in runs.items()}
            assert ret["park"] > ret["idle"] == 0.0 > max(ret["crash"], ret["exit"])


def test_the_reward_changes_no_state(head_in):
    # The same actions under other reward options: the same observations and true poses.
    options = dict(discount=0.9, shaping_weight=3.0, success_reward=1.0, contact_reward=-0.5,
                   exit_reward=0.0, distance_scale_m=0.3, heading_weight=1.0)
    for config in ("kinematic", "dynamics-lab"):
        actions = np.random.default_rng(4).uniform(-1, 1, size=(60, 2))
        traces = []
        for reward_options in ({}, options):
            env = parksim.ParkingEnv(world=head_in, max_episode_steps=STEPS,
                                     **CONFIGS[config], **reward_options)
            obs, info = env.reset(seed=12)
            trace = [np.concatenate([obs, info["pose"]])]
            for action in actions:
                obs, _, terminated, truncated, info = env.step(action)
                trace.append(np.concatenate([obs, info["pose"]]))
                if terminated or truncated:
                    obs, info = env.reset()
            traces.append(np.array(trace))
        assert traces[0].tobytes() == traces[1].tobytes(), config


@pytest.mark.parametrize("config", ["kinematic", "dynamics"])
def test_with_the_default_reward_a_prompt_park_wins_with_and_without_discounting(head_in, config):
    # What RecordEpisodeStatistics and SB3's Monitor log is the undiscounted return; a learner
    # maximises the discounted one (gamma 0.99, SB3's default). Idling for 500 steps in the
    # lot's south-west corner (head_in's start) or next to the slot must return less than a
    # prompt park (STARTS[0], 34 steps) under both. With the shaping's discount at 0.99 the
    # idler collected (1 - 0.99) * D a step: 17.56 undiscounted against the park's 12.12.
    env = parksim.ParkingEnv(world=head_in, max_episode_steps=500, **CONFIGS[config])
    gamma = 0.99

    def returns(start, policy):
        obs, info = env.reset(options={"start": start, "noise_seed": 7})
        rewards = []
        while True:
            obs, reward, terminated, truncated, info = env.step(policy(obs))
            rewards.append(reward)
            if terminated or truncated:
                return (sum(rewards), sum(gamma ** k * r for k, r in enumerate(rewards)),
                        info["is_success"], len(rewards))

    park = returns(STARTS[0], POLICIES["park"])
    assert park[2] and park[3] < 60, park
    for start in ((0.1, 0.1, math.pi / 2), (0.1, 1.1, 0.0), STARTS[0]):
        idle = returns(start, POLICIES["idle"])
        assert idle[3] == 500 and not idle[2]
        assert park[0] > idle[0], (start, park, idle)  # undiscounted: as logged
        assert park[1] > idle[1], (start, park, idle)  # discounted by the learner's gamma
