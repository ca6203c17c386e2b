#!/usr/bin/env python3
"""Fuzzes Python's dict-to-world path, parksim.load_world(dict), from the Python side.

Seeded random mutations of the shipped worlds as dicts (values replaced by other types, huge,
tiny, non-finite and negative numbers, huge integers, NumPy scalars and arrays, nested
containers, strings with control and non-UTF-8-able characters, keys removed, added and
renamed) are loaded one by one. Every outcome must be a World, or parksim.Error (a ValueError)
with one line naming "<dict>", or TypeError for a type JSON cannot hold; anything else (another
exception, a crash of the interpreter, a message of several lines) fails. The C++ half is
fuzzed by WorldDictFuzz.cpp (scripts/fuzz.sh).

Usage: world_dict_fuzz.py BUILD_PYTHON_DIR WORLDS_DIR [RUNS] [SEED]
"""
import copy
import glob
import math
import os
import random
import sys

sys.path.insert(0, sys.argv[1])
import numpy as np  # noqa: E402
import yaml  # noqa: E402

import parksim  # noqa: E402

WORLDS = sorted(glob.glob(os.path.join(sys.argv[2], "*.yaml")))
RUNS = int(sys.argv[3]) if len(sys.argv) > 3 else 2000
SEED = int(sys.argv[4]) if len(sys.argv) > 4 else 1
rng = random.Random(SEED)

WEIRD = [
    0, -1, 1e-300, -1e-300, 1e300, -1e300, math.inf, -math.inf, math.nan, 10**30, -(10**30),
    2**63, 2**64 + 1, True, False, None, "", "abc", "0.5", "\x00", "\x1b[31m", "é",
    "a" * 5000, [], {}, [1, 2], [1, 2, 3], [[1, 2], [3, 4]], {"x": 1}, {"x": 1, "y": 2, "yaw_deg": 3},
    np.float64(0.02), np.float32(1e-40), np.int64(-5), np.array([0.1, 0.2, 45.0]),
    np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]), np.bool_(True),
]
KEYS = ["format", "name", "lot", "robot", "physics", "obstacles", "parked_robots", "start", "goal",
        "wheel_base", "time_step_s", "mass_kg", "<<", "x", "", "\x07"]


def paths(node, prefix=()):
    """Every (container, key) in a nested dict/list."""
    if isinstance(node, dict):
        for k in list(node):
            yield node, k
            yield from paths(node[k], prefix + (k,))
    elif isinstance(node, list):
        for i in range(len(node)):
            yield node, i
            yield from paths(node[i], prefix + (i,))


def weird():
    """A fresh copy of one of WEIRD's values: the lists and dicts among them are mutated in
    place by later steps, and a shared one could end up inside itself."""
    return copy.deepcopy(rng.choice(WEIRD))


def mutate(world):
    w = copy.deepcopy(world)
    for _ in range(rng.randint(1, 4)):
        spots = list(paths(w))
        if not spots:
            break
        container, key = rng.choice(spots)
        action = rng.random()
        if action < 0.55:
            container[key] = weird()
        elif action < 0.7 and isinstance(container, dict):
            del container[key]
        elif action < 0.8 and isinstance(container, dict):
            container[rng.choice(KEYS)] = weird()
        elif action < 0.9 and isinstance(container[key], (int, float)) and not isinstance(
                container[key], bool):
            container[key] = container[key] * rng.choice([-1, 0, 1e-9, 1e9, 1e308])
        else:
            container[key] = [copy.deepcopy(container[key]) for _ in range(rng.randint(0, 3))]
    return w


def main():
    worlds = []
    for path in WORLDS:
        with open(path) as f:
            worlds.append(yaml.safe_load(f))
    outcomes = {"world": 0, "error": 0, "type": 0}
    for run in range(RUNS):
        w = mutate(rng.choice(worlds))
        try:
            parksim.load_world(w, name="<dict>")
            outcomes["world"] += 1
        except parksim.Error as e:
            message = str(e)
            if "\n" in message or not message.startswith("<dict>"):
                sys.exit(f"run {run}: parksim.Error not one line naming <dict>: {message!r}")
            outcomes["error"] += 1
        except TypeError:
            outcomes["type"] += 1
        except RecursionError:
            outcomes["type"] += 1  # a dict nested deeper than json.dumps goes
        except Exception as e:  # noqa: BLE001 - anything else is the finding
            sys.exit(f"run {run}: {type(e).__name__}: {e!r} for {w!r}"[:2000])
    print(f"world_dict_fuzz: {RUNS} mutated worlds (seed {SEED}) -> {outcomes['world']} worlds, "
          f"{outcomes['error']} parksim.Error, {outcomes['type']} TypeError; nothing else")


if __name__ == "__main__":
    main()
