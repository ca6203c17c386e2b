"""The learning check (issue 34): a small learner, NumPy only, learns to park in the kinematic
fidelity from a fixed start region, stepping VecParkingEnv's C++ threads. Prints the success
rate of the deterministic policy over fresh starts against environment steps and wall time.

The task: head_in's slot (goal 1.5, 0.04, facing south), the robot starting anywhere in
x 1.5 +- 0.1 m, y 0.4 +- 0.1 m, heading south +- 0.5 rad (the task's own start noise around
a start moved there), ParkingEnv's reward with shaping and discount 1 (the undiscounted return
ranks episodes as the discounted one does: docs/python.md, "Reward"), 100-step episodes (10 s).

The learner: Augmented Random Search (Mania, Guy and Recht 2018, "Simple random search
provides a competitive approach to reinforcement learning"), V1-t: a deterministic policy, here
an 8-32-2 tanh network on features of the observation (the goal in the robot's frame, the
heading error, the speeds), perturbed along
`--directions` random directions both ways; each perturbed policy drives one episode from a
start shared by the pair (common random numbers); the parameters move along the directions of
the `--top` best pairs, weighted by their return differences over the standard deviation of
those returns. Every `--eval-every` iterations the unperturbed policy drives `--eval-episodes`
episodes from starts never used in training (their own seeds): the rates of success and of
crashes or exits (the rest timed out) are printed.

    PYTHONPATH=build/python /usr/bin/python3 bench/learn_parking.py [--iterations 400] [--seed 1]

Environment steps count every step of every training episode (evaluation steps excluded).
Nothing here is a test: the numbers are in docs/python.md with the command that made them.
"""

import argparse
import math
import time

import numpy as np

import parksim

START = (1.5, 0.4, -math.pi / 2)  # north of head_in's slot, facing it


def make_env(n, threads):
    """n sub-environments: head_in (as installed) with its start moved north of the slot."""
    import yaml

    with open(parksim.load_world("head_in").source_path) as f:
        data = yaml.safe_load(f)
    data.update(name="head_in_region", start=[START[0], START[1], math.degrees(START[2])])
    return parksim.VecParkingEnv(n, parksim.load_world(data), fidelity="kinematic",
                                 threads=threads, max_episode_steps=100, discount=1.0,
                                 start_position_noise_m=0.1, start_heading_noise_rad=0.5)


def features(obs):
    """What the policy reads of the observation: the goal in the robot's frame (/ 0.3 m, and
    tanh(/ 0.02 m) for the last centimetres), the heading error's cos and sin, v / 0.2 m/s and
    omega / 4.7 rad/s (the robot's limits)."""
    x, y, c, s, v, w, gx, gy, gc, gs = obs.T
    dx, dy = gx - x, gy - y
    ahead, left = c * dx + s * dy, c * dy - s * dx
    return np.stack([ahead / 0.3, left / 0.3, np.tanh(ahead / 0.02), np.tanh(left / 0.02),
                     c * gc + s * gs, c * gs - s * gc, v / 0.2, w / 4.7], axis=1)


class Policy:
    """An 8-32-2 tanh network on features(obs), its parameters one flat vector; evaluated for
    a batch of parameter vectors at once (one per sub-environment)."""

    def __init__(self, hidden=32, inputs=8):
        self.shapes = [(hidden, inputs), (hidden,), (2, hidden), (2,)]
        self.size = sum(int(np.prod(s)) for s in self.shapes)

    def unpack(self, params):
        """params (m, size) -> [W1 (m, h, 10), b1 (m, h), W2 (m, 2, h), b2 (m, 2)]."""
        out, k = [], 0
        for shape in self.shapes:
            n = int(np.prod(shape))
            out.append(params[:, k:k + n].reshape((params.shape[0],) + shape))
            k += n
        return out

    def __call__(self, layers, obs):
        w1, b1, w2, b2 = layers
        x = features(obs)
        h = np.tanh(np.einsum("mhi,mi->mh", w1, x) + b1)
        return np.tanh(np.einsum("moh,mh->mo", w2, h) + b2)

    def initial(self, rng):
        w1 = rng.normal(0, 1 / math.sqrt(self.shapes[0][1]), self.shapes[0])
        w2 = np.zeros(self.shapes[2])
        return np.concatenate([w1.ravel(), np.zeros(self.shapes[1]), w2.ravel(),
                               np.zeros(self.shapes[3])])


def run_episodes(env, policy, params, seeds):
    """One episode per sub-environment (params[i] drives sub-environment i from its seed's
    start): (undiscounted returns, successes, failures (a crash or an exit), environment
    steps); the rest timed out."""
    layers = policy.unpack(params)
    obs, _ = env.reset(seed=[int(s) for s in seeds])
    n = env.num_envs
    returns = np.zeros(n)
    success = np.zeros(n, dtype=bool)
    failure = np.zeros(n, dtype=bool)
    running = np.ones(n, dtype=bool)
    steps = 0
    while running.any():
        obs, rewards, terminated, truncated, infos = env.step(policy(layers, obs))
        steps += int(running.sum())
        returns += np.where(running, rewards, 0.0)
        success |= running & infos["is_success"]
        failure |= running & terminated & ~infos["is_success"]
        running &= ~(terminated | truncated)
    return returns, success, failure, steps


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--iterations", type=int, default=400)
    parser.add_argument("--directions", type=int, default=64)
    parser.add_argument("--top", type=int, default=32)
    parser.add_argument("--noise", type=float, default=0.05, help="perturbation scale")
    parser.add_argument("--step-size", type=float, default=0.02)
    parser.add_argument("--eval-every", type=int, default=25)
    parser.add_argument("--eval-episodes", type=int, default=200)
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--save", metavar="FILE.npy", help="write the learnt parameters there")
    args = parser.parse_args()

    rng = np.random.default_rng(args.seed)
    p = args.directions
    train = make_env(2 * p, args.threads)
    evaluate = make_env(args.eval_episodes, args.threads)
    policy = Policy()
    theta = policy.initial(rng)
    eval_seeds = 10**9 + np.arange(args.eval_episodes)  # starts training never sees
    env_steps = 0
    began = time.perf_counter()
    print(f"ARS V1-t, {policy.size} parameters, {p} directions (top {args.top}), "
          f"noise {args.noise}, step {args.step_size}, seed {args.seed}")
    print("iteration  env_steps  wall_s  success_rate  crash_or_exit  mean_return")

    def report(iteration):
        returns, success, failure, _ = run_episodes(
            evaluate, policy, np.tile(theta, (args.eval_episodes, 1)), eval_seeds)
        print(f"{iteration:9d}  {env_steps:9d}  {time.perf_counter() - began:6.1f}  "
              f"{success.mean():12.3f}  {failure.mean():13.3f}  {returns.mean():11.3f}",
              flush=True)

    report(0)
    for iteration in range(1, args.iterations + 1):
        deltas = rng.normal(size=(p, policy.size))
        params = np.concatenate([theta + args.noise * deltas, theta - args.noise * deltas])
        starts = rng.integers(0, 10**9, size=p)
        returns, _, _, steps = run_episodes(train, policy, params,
                                            np.concatenate([starts, starts]))
        env_steps += steps
        plus, minus = returns[:p], returns[p:]
        best = np.argsort(-np.maximum(plus, minus))[:args.top]
        spread = np.concatenate([plus[best], minus[best]]).std() + 1e-8
        theta = theta + args.step_size / (args.top * spread) * (
            (plus[best] - minus[best]) @ deltas[best])
        if iteration % args.eval_every == 0:
            report(iteration)
    if args.save:
        np.save(args.save, theta)


if __name__ == "__main__":
    main()
