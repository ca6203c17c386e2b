"""parksim from Python: load a world, plan, run episodes, step your own controller, render.

    import parksim
    world = parksim.load_world("worlds/head_in.yaml")
    plan = parksim.plan(world, planner="rrt-goal-connect", seed=1)
    run = parksim.run(world, plan=plan, tracking="closed")
    run.executed["pos_err"].max(), run.metrics["goal_reached"]

Arrays are NumPy structured arrays with the columns of the command line's CSV files, metrics
are metrics.json's keys, and results are bit-identical to `parksim run` for the same options.
See docs/python.md.
"""

import importlib as _importlib
import json as _json
import os as _os
import sys as _sys


def _interpreter_problem():
    """Why the compiled module cannot load in this interpreter, as one line, or None."""
    try:
        from . import _build_info as built  # written by the build beside the module
    except ImportError:
        return None
    import importlib.machinery

    here = _sys.executable or "this interpreter"
    if built.MODULE_FILE[len("_parksim"):] not in importlib.machinery.EXTENSION_SUFFIXES:
        return (f"parksim: the compiled module is for {built.PYTHON} (Python {built.PYTHON_VERSION}),"
                f" not {here} (Python {_sys.version_info[0]}.{_sys.version_info[1]}): run it with"
                f" {built.PYTHON}, or build for this one (cmake -DPython_EXECUTABLE={here})")
    try:
        import numpy  # noqa: F401
    except ImportError:
        return (f"parksim: NumPy is missing for {here}; the module was built for {built.PYTHON},"
                f" which has it: run it with {built.PYTHON} (or install NumPy for {here})")
    return None


def _fail_in_one_line(message):
    """ImportError(message); uncaught, it prints as that one line, not as a traceback."""
    error = ImportError(message)
    previous = _sys.excepthook

    def hook(kind, value, traceback):
        if value is error:
            print(f"ImportError: {message}", file=_sys.stderr)
        else:
            previous(kind, value, traceback)

    _sys.excepthook = hook
    raise error from None


if (_problem := _interpreter_problem()) is not None:
    _fail_in_one_line(_problem)

try:
    _parksim = _importlib.import_module(__name__ + "._parksim")
except ModuleNotFoundError as _missing:
    if _missing.name != __name__ + "._parksim":
        raise
    # The sources without the compiled module (python/parksim/, or a build that stopped).
    _fail_in_one_line("parksim: the compiled module is not built; from the repository's top "
                      "folder: scripts/build.sh build, then run with "
                      "PYTHONPATH=$PWD/build/python /usr/bin/python3")

from ._parksim import (  # noqa: F401,E402  (re-exported)
    CollisionChecker,
    DynamicsWorld,
    Episode,
    Error,
    ExecutionDef,
    FIGURE_NAMES,
    FrameDef,
    FrameRecorder,
    MotionValidatorDef,
    MoveToPoseDef,
    SearchDef,
    ParkingTaskDef,
    PlanResult,
    PlanningProblem,
    PolicyController,
    ControllerInput,
    CarCommand,
    PlanSetup,
    ReedsSheppDef,
    RobotDef,
    RotateTranslateRotateDef,
    RunResult,
    SimModelDef,
    World,
    cspace_slice,
    encode_png,
    plan,
    read_png,
    read_trajectory,
    render_figure,
    run,
    sweep,
    write_figures,
    write_png,
)

__version__ = "0.3.0"


def _plain(value):
    """NumPy scalars and arrays in a world dict, as JSON numbers and lists; a RobotDef as the
    world file's robot: section (RobotDef.to_world())."""
    if isinstance(value, RobotDef):
        return value.to_world()
    if hasattr(value, "tolist"):
        return value.tolist()
    raise TypeError(f"a world dict holds numbers, strings, lists, dicts and RobotDefs, not "
                    f"{type(value)}")


def episode_fields():
    """The episode record's fields (parksim/results/tables/EpisodeRecord.h), one dict each: key (its
    column in a sweep's results table), metrics_key (its key in run().metrics and
    metrics.json), group, type, unit, meaning."""
    return _parksim._episode_fields()


def worlds_dir():
    """The folder of the worlds installed with the package (the project's worlds/*.yaml)."""
    return _os.path.join(_os.path.dirname(_os.path.abspath(__file__)), "worlds")


def world_names():
    """Names of the installed worlds, as load_world() takes them ("head_in", ...)."""
    folder = worlds_dir()
    if not _os.path.isdir(folder):
        return []
    return sorted(f[:-len(".yaml")] for f in _os.listdir(folder) if f.endswith(".yaml"))


def _world_path(source):
    """A world file's path: `source` itself, or for a bare name that is not a file here
    ("head_in"), the installed world of that name."""
    path = _os.fspath(source)
    bare = _os.sep not in path and "/" not in path and not path.endswith((".yaml", ".yml"))
    if bare and not _os.path.exists(path):
        installed = _os.path.join(worlds_dir(), path + ".yaml")
        if _os.path.isfile(installed):
            return installed
    return path


def load_world(source, name="<dict>"):
    """A World from a world file (path), an installed world's name ("head_in": world_names()),
    or a dict with the file's structure.

    Errors are parksim.Error (a ValueError) with the world reader's one-line message,
    "<file>:<line>: <field>: <what is wrong>". A dict is read as the YAML text json.dumps
    makes of it (one key per line), named `name` in messages. Worlds pickle as their text.
    """
    if isinstance(source, dict):
        text = _json.dumps(source, indent=1, default=_plain)
        return _parksim._parse_world(text, name)
    return _parksim._load_world(_world_path(source))


def render_frame(world, pose=None, plan=None, reference=None, episode=None,
                 obstacle_poses=None, contacts=(), executed=None, overlay=None,
                 width=640, height=480, view="top", msaa=4):
    """An H x W x 3 uint8 image of the lot, as the film's frames are drawn.

    pose: robot (x, y, theta) to draw; plan: PlanResult, structured array or trajectory.csv
    path, drawn as the planned path; reference: planned pose drawn as an outline;
    episode: an Episode, whose current instant supplies pose, reference, obstacle poses,
    contacts, the path driven so far and the plan (explicit arguments win);
    executed: driven path (structured array with x, y, theta or (x, y, theta) rows);
    overlay: dict with title, t, pos_err, heading_err for the corner text;
    view: "top" or "3d" (follows the robot).
    """
    if episode is not None:
        obs = episode.observation()
        pose = obs["pose"] if pose is None else pose
        reference = obs["reference"] if reference is None else reference
        obstacle_poses = episode.obstacle_poses if obstacle_poses is None else obstacle_poses
        contacts = obs["contacts"] if not contacts else contacts
        executed = episode.executed if executed is None else executed
        plan = episode.plan if plan is None else plan
        if overlay is None:
            overlay = {"title": world.name, "t": obs["t"], "pos_err": obs["pos_err"],
                       "heading_err": obs["heading_err"]}
    return _parksim._render_frame(world, pose, plan, reference, obstacle_poses, list(contacts),
                                  executed, overlay, width, height, view, msaa)


from .env import ParkingEnv  # noqa: E402
from .vector import VecParkingEnv  # noqa: E402
from . import spaces  # noqa: E402
from .records import read_record  # noqa: E402

__all__ = [
    "CollisionChecker", "DynamicsWorld", "Episode", "Error", "ExecutionDef", "FIGURE_NAMES",
    "FrameDef", "FrameRecorder", "MotionValidatorDef", "MoveToPoseDef", "ParkingEnv",
    "ParkingTaskDef", "SearchDef", "PlanResult", "PlanningProblem", "PolicyController",
    "ControllerInput", "CarCommand", "PlanSetup", "ReedsSheppDef", "RobotDef",
    "RotateTranslateRotateDef",
    "RunResult", "SimModelDef", "World", "cspace_slice", "encode_png", "episode_fields",
    "load_world", "plan",
    "read_png", "read_record", "read_trajectory", "render_figure", "render_frame", "run", "spaces",
    "sweep",
    "write_figures", "write_png", "VecParkingEnv", "world_names", "worlds_dir",
]
