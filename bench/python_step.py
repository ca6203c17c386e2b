"""The step API's cost from Python against runEpisode in C++, for whole episodes.

Three ways to drive the same head_in plan to its end, interleaved over several rounds (median
wall time of each):
  cpp      parksim.run(world, plan=plan): runEpisode's loop in C++ (one call)
  step     Episode.step() once per simulation step from a Python loop
  control  per step: observation(), controller_command(), set_wheel_speeds(), step() -- what a
           user's own controller in Python costs
All three produce the same executed rows (checked). Usage, from the source tree:
  PYTHONPATH=build/python python3 bench/python_step.py [--rounds 7] [--world worlds/head_in.yaml]
"""

import argparse
import statistics
import time

import parksim


def drive_cpp(world, plan):
    return parksim.run(world, plan=plan).executed


def drive_step(world, plan):
    ep = parksim.Episode(world, plan)
    step = ep.step
    while not step():
        pass
    return ep.executed


def drive_control(world, plan):
    ep = parksim.Episode(world, plan)
    while not ep.finished:
        ep.observation()
        ep.set_wheel_speeds(*ep.controller_command())
        ep.step()
    return ep.executed


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--world", default="worlds/head_in.yaml")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--rounds", type=int, default=7)
    args = parser.parse_args()

    world = parksim.load_world(args.world)
    plan = parksim.plan(world, seed=args.seed)
    reference = drive_cpp(world, plan)
    steps = len(reference) - 1
    ways = {"cpp": drive_cpp, "step": drive_step, "control": drive_control}
    times = {name: [] for name in ways}
    for _ in range(args.rounds):
        for name, drive in ways.items():
            start = time.perf_counter()
            executed = drive(world, plan)
            times[name].append(time.perf_counter() - start)
            assert executed.tobytes() == reference.tobytes(), name
    base = statistics.median(times["cpp"])
    print(f"{world.name}, seed {args.seed}: {steps} simulation steps per episode, "
          f"median of {args.rounds} rounds")
    print(f"{'loop':>8} {'episode [ms]':>13} {'per step [us]':>14} {'vs C++':>7}")
    for name in ways:
        t = statistics.median(times[name])
        print(f"{name:>8} {1e3 * t:13.1f} {1e6 * t / steps:14.2f} {t / base:7.3f}x")


if __name__ == "__main__":
    main()
