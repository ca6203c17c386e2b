#!/usr/bin/env python3
"""A parksim controller in plain Python, a process speaking the line protocol
parksim-controller/1 on its standard input and output (docs/your-code.md, "A controller as a
process"):

    parksim run worlds/head_in.yaml --controller-command 'python3 examples/commands/tracking_controller.py'

The law is parksim's own tracking controller's (docs/simulation.md): the plan's wheel speeds as
feed-forward, plus feedback on the error of the plan's pose seen from the robot,

    v     = v_r cos(e_theta) + k_x e_x
    omega = omega_r + k_y v_r e_y + k_theta sin(e_theta)

with one bandwidth w for all errors: k_x = w, k_y = w^2 / v_top^2, k_theta = 2 zeta w, and w at
most 10 rad/s, 2 pi / 25 of the control rate and 0.25 / latency. Its parameters (`--controller-param
bandwidth_radps=5`) come in the reset message. Standard library only.
"""

import json
import math
import sys


class Tracker:
    def __init__(self, reset):
        robot = reset["world"]["robot"]
        self.r = robot["wheel_radius_m"]
        self.b = robot["wheel_base_m"]
        self.w_max = robot["max_wheel_speed_radps"]
        self.fields = reset["tick_fields"]
        columns = reset["plan"]["columns"]
        left, right = columns.index("omega_left"), columns.index("omega_right")
        v_top = max(abs(0.5 * self.r * (row[left] + row[right])) for row in reset["plan"]["rows"])
        v_top = max(v_top, 0.05 * self.w_max * self.r)
        params = reset["params"]
        w = float(params.get("bandwidth_radps", 0.0))
        if w <= 0.0:
            w = 10.0
            if reset["period_s"] > 0.0:
                w = min(w, 2.0 * math.pi / (25.0 * reset["period_s"]))
            if reset["latency_s"] > 0.0:
                w = min(w, 0.25 / reset["latency_s"])
        damping = float(params.get("damping", 0.5))
        self.k_x, self.k_y, self.k_theta = w, w * w / (v_top * v_top), 2.0 * damping * w

    def command(self, tick):
        x, y, theta = tick["x_m"], tick["y_m"], tick["theta_rad"]
        dx, dy = tick["ref_x_m"] - x, tick["ref_y_m"] - y
        c, s = math.cos(theta), math.sin(theta)
        e_x, e_y = c * dx + s * dy, -s * dx + c * dy
        e_theta = math.remainder(tick["ref_theta_rad"] - theta, 2.0 * math.pi)
        v_r = tick["ref_v_mps"]
        v = v_r * math.cos(e_theta) + self.k_x * e_x
        omega = tick["ref_omega_radps"] + self.k_y * v_r * e_y + self.k_theta * math.sin(e_theta)
        left = (v - 0.5 * self.b * omega) / self.r
        right = (v + 0.5 * self.b * omega) / self.r
        # Both scaled down together when one is beyond the limit: the curvature is kept.
        largest = max(abs(left), abs(right))
        if largest > self.w_max:
            left, right = left * self.w_max / largest, right * self.w_max / largest
        return left, right


def main():
    tracker = None
    for line in iter(sys.stdin.readline, ""):
        kind, _, rest = line.partition(" ")
        if kind == "reset":
            reset = json.loads(rest)
            if reset["format"] != "parksim-controller/1":
                sys.exit(f"unknown protocol {reset['format']}")
            tracker = Tracker(reset)
            answer = "ready"
        else:
            tick = dict(zip(tracker.fields, map(float, rest.split())))
            answer = "%r %r" % tracker.command(tick)
        sys.stdout.write(answer + "\n")
        sys.stdout.flush()  # a pipe is block-buffered: without this parksim waits in vain


if __name__ == "__main__":
    main()
