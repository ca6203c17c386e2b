"""User code that fails, through plan() and run(): a verdict with its reason, never a corrupt
result or a lost interpreter. Each case runs in a fresh interpreter, so that a crash is this
test's failure (its exit status and stderr shown), not the end of every test after it."""

import json
import os
import subprocess
import sys
import textwrap

import pytest

from conftest import SOURCE_DIR

# The faulty planners, each named for its fault (tests/plugin/FaultyPlugin.cpp).
PLUGIN = os.environ.get("PARKSIM_TEST_PLUGIN", "")

PRELUDE = """
import json, sys
import numpy as np
import parksim
world = parksim.load_world(%r)

class Raises:
    def solve(self, problem):
        raise RuntimeError("lost my map")

class ReturnsNan:
    def solve(self, problem):
        traj, reached = problem.steer(problem.start, problem.goal)
        traj["x"][len(traj) // 2] = float("nan")
        return traj

class WrongShape:
    def solve(self, problem):
        return np.zeros((4, 3))

def report(result):
    # Every property, read: a corrupt result raises or crashes here.
    return {"status": result.status, "message": result.message, "solved": result.solved,
            "verdict": result.verdict, "rows": len(result.trajectory),
            "waypoints": len(result.waypoints), "cost": result.cost, "repr": repr(result),
            "stats": result.stats}
""" % str(SOURCE_DIR / "worlds" / "head_in.yaml")


def in_child(code):
    """The JSON `code` prints last, run after PRELUDE in a new interpreter."""
    p = subprocess.run([sys.executable, "-c", PRELUDE + textwrap.dedent(code)],
                       capture_output=True, text=True, timeout=600)
    assert p.returncode == 0, f"exit status {p.returncode}: {p.stderr[-3000:]}"
    return json.loads(p.stdout.strip().splitlines()[-1])


@pytest.mark.parametrize("planner,reason", [
    ("Raises()", "planner Raises threw: RuntimeError: lost my map"),
    ("ReturnsNan()", "planner ReturnsNan returned an unusable plan: row "),
    ("WrongShape()", "structured array"),
])
def test_a_failing_python_planner_is_a_planner_error_from_plan(planner, reason):
    r = in_child(f"print(json.dumps(report(parksim.plan(world, planner={planner}))))")
    assert r["status"] == "planner_error" and not r["solved"], r
    assert reason in r["message"], r
    assert r["verdict"] == {"status": "planner_error", "met": False, "reason": r["message"]}
    assert r["rows"] == 0 and r["waypoints"] == 0 and r["cost"] == 0.0
    assert r["repr"] == "<parksim.PlanResult planner_error: " + r["message"] + ">"


def test_a_failing_python_planner_is_the_same_verdict_from_plan_and_run():
    r = in_child("""
        p, q = parksim.plan(world, planner=Raises()), parksim.run(world, planner=Raises())
        print(json.dumps([report(p), q.status, q.reason, report(q.plan)]))
    """)
    plan, status, reason, run_plan = r
    assert status == plan["status"] == run_plan["status"] == "planner_error"
    assert reason == plan["message"] == run_plan["message"]


@pytest.mark.skipif(not PLUGIN, reason="PARKSIM_TEST_PLUGIN is not set (run through ctest)")
@pytest.mark.parametrize("planner,reason", [
    ("throwing-planner", "planner throwing-planner threw: no idea how to park"),
    ("nan-planner", "planner nan-planner returned an unusable plan: row "),
])
def test_a_plugins_failing_planner_is_a_planner_error_from_plan(planner, reason):
    r = in_child(f"""
        print(json.dumps(report(parksim.plan(world, plugins=[{PLUGIN!r}], planner={planner!r}))))
    """)
    assert r["status"] == "planner_error" and not r["solved"], r
    assert r["message"].startswith(reason), r

