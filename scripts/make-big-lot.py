#!/usr/bin/env python3
"""Writes worlds/big_lot.yaml: a 10 x 10 m lot with 300 rotated boxes (issue 9).

Deterministic (Python's Mersenne Twister with a fixed seed), so the committed file can be
re-made bit for bit: scripts/make-big-lot.py > worlds/big_lot.yaml
Boxes keep 0.35 m from the start and the goal, so both stay free with room to turn.
"""
import math
import random

rng = random.Random(9)
start = (0.3, 0.3, 0.0)
goal = (9.6, 9.6, 90.0)
print("format: parksim-world/1")
print("name: big_lot")
print()
print("# A 10 x 10 m lot with 300 rotated boxes between the start (south-west) and the goal")
print("# (north-east), made by scripts/make-big-lot.py (seeded; do not edit by hand).")
print("# Units: m, degrees in keys ending in _deg.")
print()
print("lot: {x_min: 0.0, y_min: 0.0, x_max: 10.0, y_max: 10.0}")
print()
print("obstacles:")
n = 0
while n < 300:
    x = rng.uniform(0.2, 9.8)
    y = rng.uniform(0.2, 9.8)
    w = rng.uniform(0.1, 0.4)
    h = rng.uniform(0.1, 0.4)
    yaw = rng.uniform(-90.0, 90.0)
    if min(math.hypot(x - start[0], y - start[1]), math.hypot(x - goal[0], y - goal[1])) < 0.6:
        continue
    n += 1
    print(f"  - {{name: box_{n}, kind: box, center: [{x:.3f}, {y:.3f}], "
          f"size: [{w:.3f}, {h:.3f}], yaw_deg: {yaw:.1f}}}")
print()
print(f"start: [{start[0]}, {start[1]}, {start[2]:g}]")
print()
print("goal:")
print(f"  pose: [{goal[0]}, {goal[1]}, {goal[2]:g}]")
print("  position_tolerance: 0.001")
print("  heading_tolerance_deg: 0.5")
print("  either_heading: false")
