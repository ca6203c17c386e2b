#!/usr/bin/env python3
"""A parksim planner in plain Python, run as a command (docs/your-code.md, "A planner as a
command"):

    parksim run worlds/head_in.yaml \
        --planner-command 'python3 examples/commands/waypoint_planner.py {problem} {out}' \
        --planner-param waypoints='0.1 0.5, 1.5 0.5'

It reads the problem file ({problem}, format parksim-planning-problem/1) and writes
{out}/trajectory.csv: through the waypoints (the planner parameter `waypoints`, "x y" pairs in
metres separated by commas; none: straight to the goal) to the goal, turning in place towards
each and then driving straight, and at the goal turning to its heading. Every move is a
rest-to-rest wheel speed profile within the problem's timing limits, one row per period, and
each row's wheel speeds held for a period lead exactly to the next row's pose: parksim checks
all of that, and the swept footprint against the obstacles, before it drives the plan.

It does not look at obstacles: the waypoints must keep the robot clear of them (parksim refuses
a plan that does not, plan_invalid, naming the obstacle). Standard library only.
"""

import json
import math
import os
import sys


def profile(amount, top, step, dt):
    """Speeds held for `dt` each that cover `amount` (wheel radians, >= 0) from rest to rest:
    changing by at most `step` a period, at most `top`, then scaled down so that they cover
    `amount` exactly."""
    if amount <= 0.0:
        return []
    n = 1
    while True:
        speeds = [min(top, (k + 1) * step, (n - k) * step) for k in range(n)]
        covered = sum(speeds) * dt
        if covered >= amount:
            return [s * amount / covered for s in speeds]
        n += 1


def plan(problem):
    world = problem["world"]
    robot = world["robot"]
    timing = problem["timing"]
    dt = timing["period_s"]
    r = robot["wheel_radius_m"]
    half_base = 0.5 * robot["wheel_base_m"]
    top = timing["max_wheel_speed_radps"]
    step = timing["max_wheel_accel_radps2"] * dt

    start, goal = world["start"], world["goal"]["pose"]
    x, y, theta = start["x_m"], start["y_m"], start["theta_rad"]
    rows = []  # (t, x, y, theta, omega_left, omega_right)

    def move(wheel_angle, left_sign, right_sign):
        """Appends a rest-to-rest move: each wheel turns `wheel_angle` radians, in its sign."""
        nonlocal x, y, theta
        for s in profile(wheel_angle, top, step, dt):
            left, right = left_sign * s, right_sign * s
            rows.append((len(rows) * dt, x, y, theta, left, right))
            v = r * 0.5 * (left + right)
            omega = r * (right - left) / (2.0 * half_base)
            # Straight or on the spot, so the exact motion over the period is this simple.
            x += v * dt * math.cos(theta)
            y += v * dt * math.sin(theta)
            theta += omega * dt
        if rows and (rows[-1][4] != 0.0 or rows[-1][5] != 0.0):
            rows.append((len(rows) * dt, x, y, theta, 0.0, 0.0))  # a period at rest

    def turn_to(heading):
        turn = math.remainder(heading - theta, 2.0 * math.pi)
        if abs(turn) < 1e-12:
            return
        sign = 1.0 if turn > 0.0 else -1.0
        move(abs(turn) * half_base / r, -sign, sign)

    def drive_to(tx, ty):
        distance = math.hypot(tx - x, ty - y)
        if distance < 1e-9:
            return
        turn_to(math.atan2(ty - y, tx - x))
        move(distance / r, 1.0, 1.0)

    text = problem["params"].get("waypoints", "").strip()
    for pair in filter(None, (p.strip() for p in text.split(","))):
        wx, wy = (float(v) for v in pair.split())
        drive_to(wx, wy)
    drive_to(goal["x_m"], goal["y_m"])
    turn_to(goal["theta_rad"])
    if not rows:
        rows.append((0.0, x, y, theta, 0.0, 0.0))
    return rows


def main():
    problem_path, out_dir = sys.argv[1], sys.argv[2]
    with open(problem_path, encoding="utf-8") as f:
        problem = json.load(f)
    if problem["format"] != "parksim-planning-problem/1":
        sys.exit(f"unknown problem format {problem['format']}")
    rows = plan(problem)
    # Written aside and renamed: parksim reads it only after the exit anyway, but a file that is
    # there is then always whole.
    path = os.path.join(out_dir, "trajectory.csv")
    with open(path + ".part", "w", encoding="utf-8") as f:
        f.write("t,x,y,theta,omega_left,omega_right\n")
        for row in rows:
            f.write(",".join(repr(v) for v in row) + "\n")
    os.replace(path + ".part", path)


if __name__ == "__main__":
    main()
