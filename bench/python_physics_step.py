"""The dynamics fidelity's physics alone, for an instruction count: DynamicsWorld.step() driven
by random wheel-speed targets held for 0.1 s each (24 physics steps of 1/240 s), as the
reinforcement-learning loop drives it (the "physics" loop of python_vec_env.py, one world).
Instruction counts do not depend on the machine's load; run it under callgrind and divide
DynamicsWorld::step()'s inclusive count by the physics steps (24 x ACTIONS):
  PYTHONPATH=build/python valgrind --tool=callgrind --callgrind-out-file=/tmp/phys.cg \\
      /usr/bin/python3 bench/python_physics_step.py worlds/head_in.yaml 300
  callgrind_annotate --inclusive=yes /tmp/phys.cg | grep 'DynamicsWorld::step()'
Usage: python_physics_step.py WORLD ACTIONS (docs/simulation.md, "A cheaper step, same bytes").
"""

import sys

import numpy as np

import parksim

world = parksim.load_world(sys.argv[1])
rng = np.random.default_rng(1)
sim = parksim.DynamicsWorld(world, start=world.start)
per_action = round(0.1 / world.time_step_s)
speed = world.robot.max_wheel_speed_radps
for left, right in rng.uniform(-speed, speed, size=(int(sys.argv[2]), 2)):
    sim.set_wheel_targets(float(left), float(right))
    sim.step(per_action)
