"""User code that fails, through plan() and run(): a verdict with its reason, never a corrupt
result or a lost interpreter; with isolate=True one that crashes or hangs past its time limit
too. Each case runs in a fresh interpreter, so that a crash or a hang is this test's failure
(its exit status and stderr shown, or its timeout), not the end of every test after it."""

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
import json, os, signal, sys
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

class Hangs:
    def solve(self, problem):
        while True:
            pass

class Crashes:
    def solve(self, problem):
        os.kill(os.getpid(), signal.SIGSEGV)

def hangs_on(obs):
    while obs.t > 0.5:
        pass
    return obs.feedforward

def verdict(result):
    if hasattr(result, "verdict"):  # a PlanResult
        return {"status": result.status, "reason": result.message}
    return {"status": result.status, "reason": result.reason}

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


@pytest.mark.skipif(not PLUGIN, reason="PARKSIM_TEST_PLUGIN is not set (run through ctest)")
def test_a_plugin_that_crashes_while_loaded_is_an_error_not_the_end_of_the_interpreter():
    crashing = os.path.join(os.path.dirname(PLUGIN), "libparksim_broken_plugin_5.so")
    r = in_child(f"""
        try:
            parksim.plan(world, plugins=[{crashing!r}])
            error = None
        except parksim.Error as e:
            error = str(e)
        print(json.dumps([error, parksim.plan(world).solved]))
    """)
    assert r == [crashing + ": the plugin crashed while it was loaded (SIGSEGV, Segmentation "
                 "fault: in its static initializers, entry point or registration); not loaded",
                 True]


@pytest.mark.parametrize("call,status,reason", [
    ("parksim.plan(world, planner=Hangs(), isolate=True, planner_timeout=1)", "planner_error",
     "planner Hangs ran past its time limit of 1 s (its process was killed)"),
    ("parksim.plan(world, planner=Crashes(), isolate=True)", "planner_error",
     "planner Crashes crashed (SIGSEGV, Segmentation fault)"),
    ("parksim.run(world, planner=Hangs(), isolate=True, planner_timeout=1)", "planner_error",
     "planner Hangs ran past its time limit of 1 s (its process was killed)"),
    ("parksim.run(world, controller=hangs_on, isolate=True, controller_timeout=1)",
     "controller_error",
     "controller hangs_on gave no command within its time limit of 1 s (its process was killed)"),
])
def test_isolated_python_code_that_crashes_or_hangs_is_a_verdict(call, status, reason):
    r = in_child(f"""
        r = {call}
        # The interpreter goes on: the next episode runs as ever.
        print(json.dumps([verdict(r), parksim.plan(world).solved]))
    """)
    assert r == [{"status": status, "reason": reason}, True]


@pytest.mark.skipif(not PLUGIN, reason="PARKSIM_TEST_PLUGIN is not set (run through ctest)")
@pytest.mark.parametrize("options,status,reason", [
    ("planner='segfault-planner'", "planner_error",
     "planner segfault-planner crashed (SIGSEGV, Segmentation fault)"),
    ("controller='hanging-controller', controller_timeout=0.5", "controller_error",
     "controller hanging-controller gave no command within its time limit of 0.5 s (its process "
     "was killed)"),
])
def test_an_isolated_plugins_crash_or_hang_is_a_verdict(options, status, reason):
    r = in_child(f"""
        r = parksim.run(world, plugins=[{PLUGIN!r}], {options}, isolate=True)
        print(json.dumps([verdict(r), r.metrics["status"]]))
    """)
    assert r == [{"status": status, "reason": reason}, status]


def test_an_isolated_run_gives_what_the_run_in_process_gives():
    r = in_child("""
        def ff(obs):
            return obs.feedforward
        a = parksim.run(world, controller=ff, realism="lab", realisations=2)
        b = parksim.run(world, controller=ff, realism="lab", realisations=2, isolate=True)
        # Wall-clock measurements differ from run to run; everything else is the same.
        clocks = ("wall_time_s", "real_time_factor", "plan_planning_time_s",
                  "plan_first_solution_s", "plan_phase_times_s.")
        differ = [k for k in a.metrics if not k.startswith(clocks) and a.metrics[k] != b.metrics[k]]
        print(json.dumps([a.status, b.status, a.executed.tobytes() == b.executed.tobytes(),
                          a.executed.dtype == b.executed.dtype, differ == [],
                          sorted(a.metrics) == sorted(b.metrics),
                          [x["status"] for x in a.realisations] ==
                          [x["status"] for x in b.realisations],
                          a.plan.stats["path_length_m"] == b.plan.stats["path_length_m"]]))
    """)
    assert r[0] == r[1] and all(r[2:]), r


def test_a_time_limit_that_cannot_hold_is_refused_and_a_commands_holds():
    r = in_child("""
        try:
            parksim.plan(world, planner=Hangs(), planner_timeout=1)
            refused = ""
        except TypeError as e:
            refused = str(e)
        p = parksim.plan(world, planner="command", planner_timeout=1,
                         planner_params={"command": "sh -c 'sleep 60' sh {out}"})
        print(json.dumps([refused, verdict(p)]))
    """)
    refused, command = r
    assert "isolate=True" in refused, refused
    assert command == {"status": "planner_error", "reason":
                       "planner command `sh -c 'sleep 60' sh {out}` gave no answer within the "
                       "planner time limit of 1 s and was killed"}
