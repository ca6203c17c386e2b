"""Environment steps per second from Python: ParkingEnv and VecParkingEnv, both fidelities.

A random policy (uniform wheel-speed fractions, drawn by NumPy in blocks: the Python thread's
cost is included) drives
  before   (with --baseline-env FILE) another ParkingEnv, e.g. the one of an earlier version,
           loaded from its env.py as a submodule of this parksim, one environment
  physics  DynamicsWorld.step() alone for as many physics steps (the same random wheel
           speeds, no observation, reward or Python per step beyond the call): the ceiling
           of the dynamics fidelity on one core
  single   ParkingEnv: one environment, reset() after each end
  vec-1    VecParkingEnv(n, threads=1): n sub-environments in one thread (autoreset)
  vec-2    VecParkingEnv(n, threads=2): the same in two threads
  sb3-2    parksim.sb3.SB3VecEnv(n, threads=2): vec-2 behind Stable-Baselines3's VecEnv
           interface (step_async + step_wait, a list of info dicts, same-step autoreset)
for the "dynamics" (Bullet, ideal robot) and "kinematic" fidelities, 0.1-s steps. Steps are
counted over all sub-environments. Configurations are interleaved over several rounds; the
table gives the median steps/s, CPU seconds per wall second (2 = both cores busy), steps per
CPU second (what a loaded machine still tells) and the load average before and after. vec-1 and vec-2 are checked to produce identical observations.
Usage, from the source tree:
  PYTHONPATH=build/python /usr/bin/python3 bench/python_vec_env.py [--rounds 5] [--envs 8]
Against the pure-Python ParkingEnv of version 0.3.0 (DynamicsWorld stepped from Python):
  git show 2b7e560:python/parksim/env.py > /tmp/env_0_3.py
  PYTHONPATH=build/python /usr/bin/python3 bench/python_vec_env.py --baseline-env /tmp/env_0_3.py
"""

import argparse
import importlib.util
import os
import sys
import statistics
import time

import numpy as np

import parksim


def load_env_class(path):
    """ParkingEnv from an env.py, imported as parksim._baseline_env (its relative imports then
    resolve to this parksim's module)."""
    spec = importlib.util.spec_from_file_location("parksim._baseline_env", path)
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module
    spec.loader.exec_module(module)
    return module.ParkingEnv


def run_single(world, fidelity, steps, seed, env_class=None):
    if env_class is None:
        env = parksim.ParkingEnv(world=world, fidelity=fidelity)
    else:
        env = env_class(world=world)
    rng = np.random.default_rng(seed)
    env.reset(seed=seed)
    actions = rng.uniform(-1.0, 1.0, size=(steps, 2)).astype(np.float32)
    start = time.perf_counter(), time.process_time()
    obs = None
    for a in actions:
        obs, _, terminated, truncated, _ = env.step(a)
        if terminated or truncated:
            obs, _ = env.reset()
    return steps, start, obs


def run_physics(world, fidelity, steps, seed):
    rng = np.random.default_rng(seed)
    sim = parksim.DynamicsWorld(world, start=world.start)
    per_action = round(0.1 / world.time_step_s)
    speed = world.robot.max_wheel_speed_radps
    actions = rng.uniform(-speed, speed, size=(steps, 2))
    start = time.perf_counter(), time.process_time()
    for left, right in actions:
        sim.set_wheel_targets(float(left), float(right))
        sim.step(per_action)
    return steps, start, None


def run_vec(world, fidelity, n, threads, vec_steps, seed):
    envs = parksim.VecParkingEnv(n, world=world, fidelity=fidelity, threads=threads)
    envs.reset(seed=seed)
    return run_batch(envs, n, vec_steps, seed)


def run_sb3(world, fidelity, n, threads, vec_steps, seed):
    from parksim.sb3 import SB3VecEnv

    envs = SB3VecEnv(n, world=world, fidelity=fidelity, threads=threads)
    envs.seed(seed)
    envs.reset()
    return run_batch(envs, n, vec_steps, seed)  # its step(): step_async, then step_wait


def run_batch(envs, n, vec_steps, seed):
    """vec_steps steps of random actions (n per step, drawn in blocks)."""
    rng = np.random.default_rng(seed)
    block = 1000
    start = time.perf_counter(), time.process_time()
    obs = None
    for first in range(0, vec_steps, block):
        actions = rng.uniform(-1.0, 1.0, size=(min(block, vec_steps - first), n, 2))
        for a in actions.astype(np.float32):
            obs = envs.step(a)[0]
    return n * vec_steps, start, obs


def timed(run, *args):
    steps, (wall0, cpu0), obs = run(*args)
    wall = time.perf_counter() - wall0
    cpu = time.process_time() - cpu0
    return steps / wall, cpu / wall, obs


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--world", default="head_in")
    parser.add_argument("--envs", type=int, default=8)
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--dynamics-steps", type=int, default=300,
                        help="vector steps per dynamics run (x envs sub-environment steps)")
    parser.add_argument("--kinematic-steps", type=int, default=20000,
                        help="vector steps per kinematic run")
    parser.add_argument("--fidelity", choices=["dynamics", "kinematic", "both"], default="both")
    parser.add_argument("--baseline-env", metavar="FILE",
                        help="an env.py whose ParkingEnv (Bullet, ideal robot) is timed as 'before'")
    args = parser.parse_args()
    baseline = load_env_class(args.baseline_env) if args.baseline_env else None

    world = parksim.load_world(args.world)
    fidelities = ["dynamics", "kinematic"] if args.fidelity == "both" else [args.fidelity]
    load_before = os.getloadavg()
    results = {}
    for _ in range(args.rounds):
        for fidelity in fidelities:
            vec_steps = args.dynamics_steps if fidelity == "dynamics" else args.kinematic_steps
            configs = {}
            if baseline is not None and fidelity == "dynamics":
                configs["before"] = (run_single, world, fidelity, 4 * vec_steps, args.seed,
                                     baseline)
            if fidelity == "dynamics":
                configs["physics"] = (run_physics, world, fidelity, 4 * vec_steps, args.seed)
            configs |= {
                "single": (run_single, world, fidelity, min(vec_steps * args.envs, 4 * vec_steps),
                           args.seed),
                "vec-1": (run_vec, world, fidelity, args.envs, 1, vec_steps, args.seed),
                "vec-2": (run_vec, world, fidelity, args.envs, 2, vec_steps, args.seed),
                "sb3-2": (run_sb3, world, fidelity, args.envs, 2, vec_steps, args.seed),
            }
            finals = {}
            for name, (run, *rest) in configs.items():
                rate, cores, obs = timed(run, *rest)
                results.setdefault((fidelity, name), []).append((rate, cores))
                finals[name] = obs
            assert np.array_equal(finals["vec-1"], finals["vec-2"]), \
                f"{fidelity}: 1 and 2 threads differ"
    load_after = os.getloadavg()

    print(f"{world.name}, {args.envs} sub-environments, 0.1-s steps, random policy, "
          f"median of {args.rounds} rounds; load average {load_before[0]:.2f} before, "
          f"{load_after[0]:.2f} after; vec-1 and vec-2 observations identical")
    reference = "before" if baseline is not None else "single"
    print(f"{'fidelity':>10} {'loop':>7} {'steps/s':>10} {'cpu/wall':>9} {'steps/cpu-s':>12} "
          f"{'ratio':>7}  (steps/s against)")
    for fidelity in fidelities:
        key = (fidelity, reference) if (fidelity, reference) in results else (fidelity, "single")
        base = statistics.median(r for r, _ in results[key])
        for name in ("before", "physics", "single", "vec-1", "vec-2", "sb3-2"):
            rates = results.get((fidelity, name))
            if rates is None:
                continue
            rate = statistics.median(r for r, _ in rates)
            cores = statistics.median(c for _, c in rates)
            per_cpu = statistics.median(r / c for r, c in rates)
            print(f"{fidelity:>10} {name:>7} {rate:10.0f} {cores:9.2f} {per_cpu:12.0f} "
                  f"{rate / base:6.2f}x  {key[1]}")


if __name__ == "__main__":
    main()
