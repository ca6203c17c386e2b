"""ParkingEnv: the parking task with Gymnasium's interface, for reinforcement learning.

Used like highway-env's parking-v0:

    env = parksim.ParkingEnv()                      # the installed head_in world
    obs, info = env.reset(seed=0)
    obs, reward, terminated, truncated, info = env.step(env.action_space.sample())

The task itself (observation, action, reward, episode end, seeding) is C++
(parksim/rl/ParkingTask.h, options: parksim.ParkingTaskDef); this file adds Gymnasium's
interface. gymnasium is optional (Debian does not ship it). When it is importable, ParkingEnv is
a gymnasium.Env with gymnasium.spaces.Box spaces, registered as "parksim/Parking-v0" (with
max_episode_steps, and VecParkingEnv as its vector entry point); otherwise the spaces are
parksim.spaces.Box, with the same attributes.
"""

import math

import numpy as np

from . import _parksim

try:  # pragma: no cover - depends on what is installed
    import gymnasium as _gym
    from gymnasium.spaces import Box as _Box

    try:
        from gymnasium.spaces import Dict as _Dict
    except ImportError:  # a stand-in gymnasium with Box alone
        from .spaces import Dict as _Dict

    _Base = _gym.Env
except ImportError:
    _gym = None
    from .spaces import Box as _Box
    from .spaces import Dict as _Dict

    _Base = object

_MAX_SEED = 2**64 - 1


def task_options(options):
    """ParkingTaskDef options as the compiled task takes them: max_episode_steps=None or -1
    (Gymnasium's "no limit", which make_vec passes to a vector entry point) is 0, no limit of
    the environment's own."""
    steps = options.get("max_episode_steps", 0)
    if steps is None or (not isinstance(steps, bool) and steps == -1):
        options = dict(options, max_episode_steps=0)
    return options


def own_step_limit(definition):
    """The environment's own step limit, None where it has none (max_episode_steps 0)."""
    return definition.max_episode_steps or None


def task_spaces(observation_low, observation_high, num_envs=None):
    """(action_space, observation_space) of the parking task (rl/TaskSpaces.h): the action two
    fractions in [-1, 1] (wheel speeds, or a car's acceleration and steering), the observation
    10 values within the task's bounds; with num_envs, the batched spaces of that many. The one
    definition of both for ParkingEnv, VecParkingEnv, the Stable-Baselines3 adapter and
    anything that runs their policies."""
    low = np.asarray(observation_low, dtype=np.float32)
    high = np.asarray(observation_high, dtype=np.float32)
    action_shape = (2,)
    if num_envs is not None:
        low, high = np.tile(low, (num_envs, 1)), np.tile(high, (num_envs, 1))
        action_shape = (num_envs, 2)
    return (_Box(-1.0, 1.0, shape=action_shape, dtype=np.float32),
            _Box(low, high, dtype=np.float32))


OBSERVATIONS = ("array", "goal_dict")
ROBOT_PART = 6  # the observation's robot values: x, y, cos, sin, v, omega (a car's: steer)


def goal_dict_space(observation_space):
    """The goal-conditioned observation space of highway-env's parking-v0 (GoalEnv): the robot's
    part of the observation, and its pose and the goal as (x, y, cos theta, sin theta), in
    float64 so that compute_reward on them is the step's reward to rounding. From task_spaces'
    observation space, single or batched (each entry then has the leading num_envs axis)."""
    low, high = observation_space.low, observation_space.high
    goal_low = low[..., ROBOT_PART:].astype(np.float64)
    goal_high = high[..., ROBOT_PART:].astype(np.float64)
    return _Dict({
        "observation": _Box(low[..., :ROBOT_PART], high[..., :ROBOT_PART], dtype=np.float32),
        "achieved_goal": _Box(np.minimum(low[..., :4], goal_low),
                              np.maximum(high[..., :4], goal_high), dtype=np.float64),
        "desired_goal": _Box(goal_low, goal_high, dtype=np.float64),
    })


def goal_observation(obs, pose, desired_goal):
    """The goal_dict observation of flat observations obs (..., 10) whose true poses are pose
    (..., 3), towards desired_goal (4,): the one layout of ParkingEnv, VecParkingEnv and
    SB3VecEnv (batched, each entry has the leading num_envs axis)."""
    achieved = pose_goal(pose)
    return {"observation": np.array(obs[..., :ROBOT_PART], dtype=np.float32),
            "achieved_goal": achieved,
            "desired_goal": np.broadcast_to(desired_goal, achieved.shape).copy()}


def goal_rewards(task, achieved_goal, desired_goal, info):
    """compute_reward of ParkingEnv, VecParkingEnv and SB3VecEnv (ParkingEnv.compute_reward's
    documentation); `task` is the compiled task or batch, whose transition_rewards is the C++
    task's own reward (rl/TaskReward.h)."""
    achieved = np.asarray(achieved_goal, dtype=np.float64)
    desired = np.asarray(desired_goal, dtype=np.float64)
    infos = [info] if isinstance(info, dict) else list(np.asarray(info, dtype=object).ravel())
    shape = np.broadcast_shapes(achieved.shape[:-1], desired.shape[:-1])
    n = int(np.prod(shape))
    if len(infos) != n:
        raise ValueError(f"compute_reward: {len(infos)} infos for {n} goals")
    if any(not isinstance(i, dict) or "previous_achieved_goal" not in i or "contacts" not in i
           for i in infos):
        raise ValueError(
            "compute_reward: info must be the step's info (previous_achieved_goal, "
            "contacts): the reward's shaping starts at the previous pose; with "
            "Stable-Baselines3's HerReplayBuffer pass "
            "replay_buffer_kwargs=dict(copy_info_dict=True)")
    before = np.stack([np.asarray(i["previous_achieved_goal"], dtype=np.float64)
                       for i in infos])
    contact = np.array([bool(np.any(i["contacts"])) for i in infos])
    rewards = task.transition_rewards(
        goal_pose(before), goal_pose(np.broadcast_to(achieved, shape + (4,)).reshape(n, 4)),
        goal_pose(np.broadcast_to(desired, shape + (4,)).reshape(n, 4)), contact)
    return float(rewards[0]) if shape == () else rewards.reshape(shape)


def pose_goal(pose):
    """(x, y, theta) poses, shape (..., 3), as goals (x, y, cos theta, sin theta). The cosine
    and sine are math's, one pose at a time: NumPy's vectorised ones may differ in the last bit
    with the array's length and alignment, and a batch's goals must be a single pose's."""
    pose = np.asarray(pose, dtype=np.float64)
    goal = np.empty(pose.shape[:-1] + (4,))
    goal[..., :2] = pose[..., :2]
    flat_goal, theta = goal.reshape(-1, 4), pose[..., 2].ravel()
    for i, t in enumerate(theta.tolist()):
        flat_goal[i, 2], flat_goal[i, 3] = math.cos(t), math.sin(t)
    return goal


def goal_pose(goal):
    """Goals (x, y, cos theta, sin theta), shape (..., 4), as (x, y, theta) poses."""
    goal = np.asarray(goal, dtype=np.float64)
    return np.stack([goal[..., 0], goal[..., 1], np.arctan2(goal[..., 3], goal[..., 2])],
                    axis=-1)


def world_from(world):
    """A World from a World, a path, an installed world's name, or None (head_in)."""
    if isinstance(world, _parksim.World):
        return world
    from . import load_world
    return load_world("head_in" if world is None else world)


def checked_seed(seed, what="seed"):
    """`seed` as a non-negative int (a ValueError names it otherwise)."""
    if isinstance(seed, (bool, np.bool_)) or not isinstance(seed, (int, np.integer)):
        raise ValueError(f"{what} must be a non-negative integer or None, got {seed!r}")
    if not 0 <= int(seed) <= _MAX_SEED:
        raise ValueError(f"{what} must be a non-negative integer below 2**64, got {seed}")
    return int(seed)


def fresh_seed(rng):
    """A task seed drawn from a NumPy generator (seeded by the user or from entropy)."""
    return int(rng.integers(0, 2**63))


class ParkingEnv(_Base):
    """Drive the world's robot from (near) its start into the goal, by wheel speeds.

    world: a World, a world file's path, an installed world's name (parksim.world_names()), or
    None for "head_in" (installed with the package: no working directory needed).
    realism: None (the library's default, "world": the world's realism: section, else the ideal
    robot), or a preset ("ideal", "lab", "odometry"); it needs fidelity="dynamics".
    Other options are parksim.ParkingTaskDef's fields (help(parksim.ParkingTaskDef)):
    fidelity ("dynamics": Bullet; "kinematic": exact arcs against the collision checker, no
    dynamics, for pre-training), control_period_s, max_episode_steps (None or -1: no limit of
    the environment's own), start noise, success thresholds, reward (discount: the shaping's, 1
    by default), terminate_on_contact, model (a SimModelDef or dict).

    Action: Box(-1, 1, (2,), float32), the left and right wheel speeds as fractions of the
    robot's maximum, held for control_period_s (whole physics steps). Exactly two finite real
    numbers; anything else (another shape, strings, complex numbers, booleans, objects, NaN)
    raises ValueError "action: expected two finite numbers ..., got ...", and values outside
    [-1, 1] are clipped. A car's world (robot.drive: car) reads the action as
    [acceleration, steering], parking-v0's: fractions of max_accel_mps2 and of max_steer_rad
    (the front wheels' target, reached at max_steer_rate), within max_speed_mps, on a kinematic
    bicycle (fidelity="kinematic") or the car's body in Bullet (docs/python.md, "A car").

    Observation: Box(low, high, (10,), float32), bounds from the lot and the robot's limits:
        x, y, cos(theta), sin(theta), v, omega, x_goal, y_goal, cos(theta_goal), sin(theta_goal)
    (m, m/s, rad/s); for a car the sixth value is the steering angle (rad) instead of omega.
    The robot's part is what its controller knows: the true state for the ideal robot, the
    realism's estimate (and encoder speeds) otherwise.

    Reward (docs/python.md, "Reward"): success_reward (10) on success, contact_reward (-10) on
    a step with a contact, exit_reward (-10) on leaving the lot, nothing per step; plus
    potential-based shaping discount * phi(s') - phi(s), phi = -shaping_weight * D (0 once
    terminated), D = sqrt(d / distance_scale_m + heading_weight * e / pi) of the true distance
    d and heading error e to the goal. Discounted by `discount` (1 by default: the undiscounted
    return that episode statistics log), every successful park returns more than every crash,
    exit and time-out from the same start; a learner's gamma < 1 still ranks a prompt park
    above idling.

    terminated: success (no contact during the step), leaving the lot, or a contact when
    terminate_on_contact. truncated: max_episode_steps actions, as Gymnasium's TimeLimit (also
    on a step that terminated). A step after either raises RuntimeError: call reset().

    info: pose and estimated_pose (arrays x, y, theta), t, goal_pos_err_m,
    goal_heading_err_rad, is_success, contacts (bool array, one per obstacle of world.obstacles).

    reset(seed=s) seeds the episodes (the action space is the user's: it is never re-seeded);
    episode k after seed s starts from a start drawn from (s, k), as sub-environment i of
    VecParkingEnv(seed=s - i) does. reset(options={"start": (x, y, theta)}) starts there.
    The environment pickles and deep-copies, an episode in progress included (it is replayed).

    observation="goal_dict" makes it a goal-conditioned environment as highway-env's parking-v0
    is, for hindsight experience replay (Stable-Baselines3's HerReplayBuffer), either drive:
    the observation is a dict of "observation" (the robot's six values above), "achieved_goal"
    (the true pose, which the reward judges, as x, y, cos theta, sin theta) and "desired_goal"
    (the goal's, the same way); info adds "previous_achieved_goal" (before the step) and
    compute_reward(achieved_goal, desired_goal, info) gives the step's reward for any goal,
    vectorised over leading axes (info a dict or a sequence of them): for the goal the step had,
    exactly the reward step() returned (docs/python.md, "Goal-conditioned observations").
    """

    metadata = {"render_modes": ["rgb_array"], "render_fps": 10}

    def __init__(self, world=None, *, render_mode=None, realism=None, model=None,
                 observation="array", **options):
        if render_mode not in (None, "rgb_array"):
            raise ValueError(f"render_mode must be None or 'rgb_array', got {render_mode!r}")
        if observation not in OBSERVATIONS:
            raise ValueError(f"observation must be one of {OBSERVATIONS}, got {observation!r}")
        self.observation = observation
        self.world = world_from(world)
        self._options = task_options(dict(options, realism=realism, model=model))
        self._task = _parksim._ParkingTask(self.world, **self._options)
        self.render_mode = render_mode
        definition = self._task.definition
        self.fidelity = definition.fidelity
        self.control_period_s = self._task.control_period_s
        self.max_episode_steps = own_step_limit(definition)
        self.discount = definition.discount  # the shaping's gamma (docs/python.md, "Reward")
        # Per instance: the class's metadata describes the default period only.
        self.metadata = dict(type(self).metadata, render_fps=1.0 / self.control_period_s)
        self.action_space, self.observation_space = task_spaces(self._task.observation_low,
                                                                self._task.observation_high)
        if observation == "goal_dict":
            self.observation_space = goal_dict_space(self.observation_space)
        goal = self.world.goal["pose"]
        self._desired_goal = pose_goal(goal)
        self._achieved_goal = None  # the last observation's, for the next step's info
        self._seeded = False
        self._actions = []  # this episode's actions, to replay it when unpickled

    # -- gymnasium interface ---------------------------------------------------------------

    if _gym is None:
        @property
        def np_random(self):
            """The environment's generator (gymnasium.Env's attribute): seeded by
            reset(seed=...), from entropy otherwise."""
            if getattr(self, "_np_random", None) is None:
                self._np_random = np.random.default_rng()
            return self._np_random

    def reset(self, *, seed=None, options=None):
        if seed is not None:
            seed = checked_seed(seed)
        if _gym is not None:
            super().reset(seed=seed)
        elif seed is not None:
            self._np_random = np.random.default_rng(seed)
        if seed is not None:
            self._task.seed(seed)
        elif not self._seeded:
            self._task.seed(fresh_seed(self.np_random))
        self._seeded = True
        options = dict(options or {})
        start = options.pop("start", None)
        noise_seed = options.pop("noise_seed", None)
        if options:
            raise ValueError(f"reset: unknown options {sorted(options)} (start, noise_seed)")
        self._actions = []
        if start is None:
            if noise_seed is not None:
                raise ValueError("reset: options noise_seed needs start")
            obs, info = self._task.reset()
        else:
            obs, info = self._task.reset_at(start, checked_seed(noise_seed or 0, "noise_seed"))
        return self._observed(obs, info), info

    def step(self, action):
        if not self._task.running:
            raise RuntimeError(
                "ParkingEnv.step: the episode has ended (terminated or truncated); call reset()"
                if self._seeded else "ParkingEnv.step: call reset() before step()")
        # ValueError on anything but two finite numbers
        obs, reward, terminated, truncated, info = self._task.step(action)
        self._actions.append(np.asarray(action, dtype=np.float64).reshape(2))
        if self.observation == "goal_dict":
            info["previous_achieved_goal"] = self._achieved_goal
        return self._observed(obs, info), reward, terminated, truncated, info

    def _observed(self, obs, info):
        """The task's observation as this environment gives it (observation=...)."""
        if self.observation == "array":
            return obs
        observed = goal_observation(obs, info["pose"], self._desired_goal)
        self._achieved_goal = observed["achieved_goal"].copy()
        return observed

    def compute_reward(self, achieved_goal, desired_goal, info):
        """The reward of the steps that reached achieved_goal, had desired_goal been the goal
        (observation="goal_dict"): goals (x, y, cos theta, sin theta), shape (..., 4); info the
        steps' info, a dict or a sequence (or array) of them, with previous_achieved_goal and
        contacts. The task's own reward (rl/TaskReward.h's taskTransitionReward): success within
        the success thresholds without a contact, contact, leaving the lot, and the shaping from
        the previous to the achieved pose; an array of the leading shape (a float for one)."""
        return goal_rewards(self._task, achieved_goal, desired_goal, info)

    def render(self):
        if self.render_mode != "rgb_array" or not self._seeded:
            return None
        from . import render_frame
        return render_frame(self.world, pose=self._task.pose,
                            obstacle_poses=self._task.obstacle_poses(),
                            contacts=self._task.contacts)

    def close(self):
        pass

    # -- pickling: the task is rebuilt and its episode replayed (the simulation is
    # deterministic, so the copy continues bit for bit) ------------------------------------

    def __getstate__(self):
        state = self.__dict__.copy()
        task = state.pop("_task")
        state["_task_state"] = (task.seed_state, task.episode if self._seeded else None,
                                task.steps, list(self._actions))
        return state

    def __setstate__(self, state):
        seed_state, episode, steps, actions = state.pop("_task_state")
        self.__dict__.update(state)
        self._task = _parksim._ParkingTask(self.world, **self._options)
        if episode is not None:
            start, noise_seed = episode
            self._task.reset_at(start, noise_seed)
            for action in actions:
                self._task.step(action)
            assert self._task.steps == steps
        self._task.seed_state = seed_state


def registered_env(**kwargs):
    """gymnasium.make's entry point for "parksim/Parking-v0": a ParkingEnv without a step limit
    of its own, as make() wraps it in TimeLimit(max_episode_steps) (the registered 300, or
    make's own argument; -1: no TimeLimit, then kMaxTaskEpisodeSteps ends an episode). The
    vector entry point, VecParkingEnv, takes make_vec's max_episode_steps itself."""
    kwargs.setdefault("max_episode_steps", None)
    return ParkingEnv(**kwargs)


registered_env.metadata = ParkingEnv.metadata  # make() reads the render modes from it


def _register():  # pragma: no cover - depends on what is installed
    if "parksim/Parking-v0" in _gym.registry:
        return
    import inspect

    kwargs = {"max_episode_steps": _parksim.ParkingTaskDef().max_episode_steps}
    if "vector_entry_point" in inspect.signature(_gym.register).parameters:
        kwargs["vector_entry_point"] = "parksim.vector:VecParkingEnv"
    _gym.register(id="parksim/Parking-v0", entry_point="parksim.env:registered_env", **kwargs)


if _gym is not None:
    _register()

__all__ = ["ParkingEnv"]
