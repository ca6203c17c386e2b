"""VecParkingEnv: n parking tasks stepped together in C++ threads, behind Gymnasium's vector API.

    envs = parksim.VecParkingEnv(8, fidelity="kinematic")
    obs, infos = envs.reset(seed=0)          # obs (8, 10) float32; sub-environment i seeded 0 + i
    obs, rewards, terminated, truncated, infos = envs.step(envs.action_space.sample())

Batched NumPy arrays throughout: observations (n, 10) float32, rewards (n,) float64, terminated
and truncated (n,) bool, infos a dict of arrays (each key with its "_key" mask, as Gymnasium's
vector environments give them). A sub-environment whose episode ended is reset at the next
step (its action ignored, reward 0; Gymnasium's default autoreset mode, "next step"), while
ParkingEnv itself refuses a step after the end. The tasks run in C++ (parksim/rl/TaskBatch.h)
with the GIL released; results do not depend on the number of threads. When gymnasium is
importable, VecParkingEnv is a gymnasium.vector.VectorEnv.
"""

import numpy as np

from . import _parksim
from .env import (OBSERVATIONS, checked_seed, fresh_seed, goal_dict_space, goal_observation,
                  goal_rewards, own_step_limit, pose_goal, task_options, task_spaces, world_from)

try:  # pragma: no cover - depends on what is installed
    import gymnasium as _gym
    from gymnasium.vector import VectorEnv as _Base

    try:
        from gymnasium.vector import AutoresetMode as _AutoresetMode

        _NEXT_STEP, _SAME_STEP = _AutoresetMode.NEXT_STEP, _AutoresetMode.SAME_STEP
    except ImportError:  # gymnasium 1.0: "next step" is the only mode
        _NEXT_STEP, _SAME_STEP = "next_step", "same_step"
except ImportError:
    _gym = None
    _Base = object
    _NEXT_STEP, _SAME_STEP = "next_step", "same_step"


def _autoreset_mode(mode):
    """The mode as metadata holds it (Gymnasium's AutoresetMode where importable), from a mode
    or its value ("next_step", "same_step"); ValueError otherwise."""
    for name, known in (("next_step", _NEXT_STEP), ("same_step", _SAME_STEP)):
        if mode in (name, known, getattr(known, "value", known)):
            return known
    raise ValueError(f"autoreset_mode must be 'next_step' or 'same_step', got {mode!r}")


class VecParkingEnv(_Base):
    """num_envs parking tasks (ParkingEnv's, same options) stepped in C++ threads.

    threads: threads that step the batch, the calling one included (None or 0: one per
    hardware thread, at most num_envs). Trajectories do not depend on it.
    autoreset_mode: "next_step" (Gymnasium's default) or "same_step" (the sub-environment is
    reset within the step that ended its episode; infos["final_obs"] and infos["final_info"]
    hold the last step's, as Gymnasium's SyncVectorEnv gives them); an AutoresetMode too.
    max_episode_steps: as ParkingEnv's (300; None or -1: no limit of the environment's own),
    and what gymnasium.make_vec's max_episode_steps sets.
    world, realism, model and the ParkingTaskDef options: as ParkingEnv's; in particular
    fidelity="kinematic" (exact arcs against the collision checker, no Bullet dynamics: the
    pre-training fidelity) or "dynamics" (the default).

    reset(seed=s) seeds sub-environment i with s + i (a list gives each its own seed, None
    keeps a sub-environment's sequence); sub-environment i then runs exactly the episodes of
    ParkingEnv().reset(seed=s + i) followed by reset() after each end.

    observation="goal_dict": ParkingEnv's goal-conditioned dict, batched (observation (n, 6)
    float32, achieved_goal and desired_goal (n, 4) float64), infos["previous_achieved_goal"]
    (n, 4), masked off for a sub-environment reset at this step (its info is a reset's), and
    compute_reward(achieved_goal, desired_goal, info), ParkingEnv's own function.
    """

    metadata = {"render_modes": ["rgb_array"], "autoreset_mode": _NEXT_STEP}

    def __init__(self, num_envs, world=None, *, threads=None, render_mode=None, realism=None,
                 model=None, autoreset_mode=_NEXT_STEP, observation="array", **options):
        num_envs = int(num_envs)
        if num_envs < 1:
            raise ValueError(f"num_envs must be at least 1, got {num_envs}")
        if render_mode not in (None, "rgb_array"):
            raise ValueError(f"render_mode must be None or 'rgb_array', got {render_mode!r}")
        mode = _autoreset_mode(autoreset_mode)
        if observation not in OBSERVATIONS:
            raise ValueError(f"observation must be one of {OBSERVATIONS}, got {observation!r}")
        self.observation = observation
        self.world = world_from(world)
        self._batch = _parksim._TaskBatch(self.world, num_envs, threads=int(threads or 0),
                                          same_step=mode == _SAME_STEP,
                                          **task_options(dict(options, realism=realism,
                                                              model=model)))
        self.num_envs = num_envs
        self.render_mode = render_mode
        self.threads = self._batch.threads
        definition = self._batch.definition
        self.fidelity = definition.fidelity
        self.control_period_s = self._batch.control_period_s
        self.max_episode_steps = own_step_limit(definition)
        self.discount = definition.discount  # the shaping's gamma (docs/python.md, "Reward")
        self.metadata = dict(type(self).metadata, render_fps=1.0 / self.control_period_s,
                             autoreset_mode=mode)
        low, high = self._batch.observation_low, self._batch.observation_high
        self.single_action_space, self.single_observation_space = task_spaces(low, high)
        self.action_space, self.observation_space = task_spaces(low, high, num_envs)
        if observation == "goal_dict":
            self.single_observation_space = goal_dict_space(self.single_observation_space)
            self.observation_space = goal_dict_space(self.observation_space)
        self._desired_goal = pose_goal(self.world.goal["pose"])
        self._achieved_goal = None  # (n, 4): the last observations', for the next step's infos
        self._ended = np.zeros(num_envs, dtype=bool)  # the last step's ends (next-step autoreset)
        self.spec = None
        self.closed = False
        self._seeded = [False] * num_envs

    if _gym is None:
        @property
        def np_random(self):
            """The vector environment's generator: seeded by reset(seed=int), from entropy
            otherwise; it seeds sub-environments that were never given a seed."""
            if getattr(self, "_np_random", None) is None:
                self._np_random = np.random.default_rng()
            return self._np_random

    def reset(self, *, seed=None, options=None):
        if options:
            raise ValueError(f"reset: unknown options {sorted(options)}")
        n = self.num_envs
        if seed is None:
            seeds = [None] * n
        elif isinstance(seed, (list, tuple, np.ndarray)):
            if len(seed) != n:
                raise ValueError(f"reset: {len(seed)} seeds for {n} environments")
            seeds = [None if s is None else checked_seed(s) for s in seed]
        else:
            first = checked_seed(seed)
            seeds = [checked_seed(first + i) for i in range(n)]
        if isinstance(seed, (int, np.integer)) and not isinstance(seed, bool):
            if _gym is not None:
                super().reset(seed=int(seed))
            else:
                self._np_random = np.random.default_rng(int(seed))
        for i, s in enumerate(seeds):
            if s is None and not self._seeded[i]:
                seeds[i] = fresh_seed(self.np_random)
            self._seeded[i] = True
        obs, infos = self._batch.reset(seeds)
        self._ended[:] = False
        return self._observed(obs, infos), infos

    def step(self, actions):
        """actions: (num_envs, 2) wheel speed fractions; ValueError on another shape, anything
        but real numbers or a non-finite value (nothing steps then)."""
        if not all(self._seeded):
            raise RuntimeError("VecParkingEnv.step: call reset() before step()")
        last_obs, rewards, terminated, truncated, last_infos = self._batch.step(actions)
        ended = terminated | truncated
        if self.metadata["autoreset_mode"] != _SAME_STEP:
            # A sub-environment that ended at the last step was reset by this one.
            self._add_previous_goal(last_infos, ~self._ended)
            self._ended = ended
            return self._observed(last_obs, last_infos), rewards, terminated, truncated, last_infos
        self._add_previous_goal(last_infos, np.ones(self.num_envs, dtype=bool))
        last = self._observed(last_obs, last_infos)
        obs, infos = self._batch.started()
        self._add_previous_goal(infos, ~ended, last_infos.get("previous_achieved_goal"))
        obs = self._observed(obs, infos)
        if ended.any():
            # As Gymnasium's vector environments add them: an object array of the ended
            # sub-environments' last observations, and their last infos under masks.
            final_obs = np.full(self.num_envs, None, dtype=object)
            for i in np.flatnonzero(ended):
                final_obs[i] = (last[i] if self.observation == "array"
                                else {key: value[i] for key, value in last.items()})
            final_info = {}
            for key, value in last_infos.items():
                if not key.startswith("_"):
                    kept = np.zeros_like(value)
                    kept[ended] = value[ended]
                    final_info[key], final_info["_" + key] = kept, ended.copy()
            infos.update(final_obs=final_obs, _final_obs=ended.copy(), final_info=final_info,
                         _final_info=ended.copy())
        return obs, rewards, terminated, truncated, infos

    def _add_previous_goal(self, infos, mask, values=None):
        """goal_dict: infos["previous_achieved_goal"], the achieved goals before the step (or
        `values`), under `mask` (its entries elsewhere are zero, as Gymnasium masks them)."""
        if self.observation != "goal_dict":
            return
        previous = self._achieved_goal if values is None else values
        infos["previous_achieved_goal"] = np.where(mask[:, None], previous, 0.0)
        infos["_previous_achieved_goal"] = mask.copy()

    def _observed(self, obs, infos):
        """The batch's observations as this environment gives them (observation=...)."""
        if self.observation == "array":
            return obs
        observed = goal_observation(obs, infos["pose"], self._desired_goal)
        self._achieved_goal = observed["achieved_goal"].copy()
        return observed

    def compute_reward(self, achieved_goal, desired_goal, info):
        """ParkingEnv.compute_reward (the same function): goals (..., 4), info a dict or a
        sequence of dicts, one per goal, each with previous_achieved_goal and contacts (a
        sub-environment's row of infos)."""
        return goal_rewards(self._batch, achieved_goal, desired_goal, info)

    def render(self):
        if self.render_mode != "rgb_array" or not all(self._seeded):
            return None
        from . import render_frame
        return tuple(render_frame(self.world, pose=self._batch.pose(i),
                                  obstacle_poses=self._batch.obstacle_poses(i),
                                  contacts=self._batch.contacts(i))
                     for i in range(self.num_envs))

    def close(self, **kwargs):
        self.closed = True

    def __repr__(self):
        return (f"VecParkingEnv({self.num_envs}, world={self.world.name!r}, "
                f"fidelity={self.fidelity!r}, threads={self.threads})")


__all__ = ["VecParkingEnv"]
