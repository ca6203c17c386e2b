"""A controller written in Python against parksim's own, under `lab` realism (a 50 Hz control
loop, issue 30's target: at least 100x real time).

Three ways to drive the same head_in plan to its end, interleaved over several rounds (median
wall time of each), each printed with its factor over real time (simulated / wall time):
  built-in   parksim.run(world, plan=plan, realism="lab"): the tracking controller in C++
  callable   controller=a Python function returning the feed-forward
  tracking   controller=the tracking law written in Python (tests/python/test_user_code.py's)
Usage, from the source tree:
  PYTHONPATH=build/python /usr/bin/python3 bench/python_controller.py [--rounds 7]
"""

import argparse
import math
import statistics
import time

import numpy as np

import parksim


def feedforward(obs):
    return obs.feedforward


class Tracking:
    """The tracking law (sim/control/TrackingController.h) in Python, gains as the built-in derives them
    at 50 Hz (bandwidth 10 rad/s)."""

    def __init__(self, robot, top_speed):
        self.robot = robot
        self.k_x = self.k_theta = 10.0
        self.k_y = 100.0 / top_speed**2

    def command(self, obs):
        x, y, th = obs.pose
        xr, yr, thr = obs.reference
        v_r, w_r = obs.reference_twist
        c, s = math.cos(th), math.sin(th)
        ex = c * (xr - x) + s * (yr - y)
        ey = -s * (xr - x) + c * (yr - y)
        eth = math.remainder(thr - th, 2 * math.pi)
        v = v_r * math.cos(eth) + self.k_x * ex
        w = w_r + self.k_y * v_r * ey + self.k_theta * math.sin(eth)
        r, b = self.robot.wheel_radius_m, self.robot.wheel_base_m
        left, right = (v - 0.5 * b * w) / r, (v + 0.5 * b * w) / r
        scale = max(1.0, abs(left) / self.robot.max_wheel_speed_radps,
                    abs(right) / self.robot.max_wheel_speed_radps)
        return left / scale, right / scale


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--rounds", type=int, default=7)
    ap.add_argument("--world", default="worlds/head_in.yaml")
    args = ap.parse_args()
    world = parksim.load_world(args.world)
    plan = parksim.plan(world)
    top = float(np.max(np.abs(plan.trajectory["v"])))
    ways = {"built-in": None, "callable": feedforward, "tracking": Tracking(world.robot, top)}
    times = {name: [] for name in ways}
    sim = {}
    for _ in range(args.rounds):
        for name, controller in ways.items():
            kw = {} if controller is None else {"controller": controller}
            t0 = time.perf_counter()
            r = parksim.run(world, plan=plan, realism="lab", **kw)
            times[name].append(time.perf_counter() - t0)
            sim[name] = (r.metrics["sim_time_s"], r.status, r.metrics["max_pos_err_m"])
    base = statistics.median(times["built-in"])
    print(f"{args.world}, lab realism (50 Hz control), median of {args.rounds} rounds:")
    for name in ways:
        wall = statistics.median(times[name])
        t_sim, status, err = sim[name]
        print(f"  {name:9s} {wall * 1e3:8.2f} ms  {t_sim / wall:6.0f}x real time  "
              f"{wall / base:5.2f} of built-in  ({status}, max error {err * 1e3:.3f} mm)")


if __name__ == "__main__":
    main()
