"""SB3VecEnv: VecParkingEnv as a Stable-Baselines3 VecEnv, so that SB3's algorithms step the
parking tasks in VecParkingEnv's C++ threads (not one Python environment after another in a
DummyVecEnv, nor one process each in a SubprocVecEnv).

    from parksim.sb3 import SB3VecEnv
    from stable_baselines3 import SAC
    env = SB3VecEnv(8, fidelity="kinematic")        # VecParkingEnv's arguments
    model = SAC("MlpPolicy", env).learn(100_000)  # any gamma (docs/python.md, "Reward")

SB3's VecEnv contract (stable_baselines3.common.vec_env.VecEnv, its documentation "Vectorized
Environments"), as DummyVecEnv keeps it:
  reset() -> observations (num_envs, 10) (observation="goal_dict": VecParkingEnv's dict of
      batched arrays, terminal_observation a dict, compute_reward through env_method); seeds
      set by seed() and options by set_options() are used by this reset only; reset_infos[i]
      holds sub-environment i's reset info.
  step_async(actions); step_wait() -> (observations, rewards float32, dones bool, infos), infos a
      list of dicts, one per sub-environment (ParkingEnv's info). A sub-environment whose episode
      ended is reset within the step: observations holds its new episode's first observation,
      infos[i]["terminal_observation"] its last one, infos[i]["TimeLimit.truncated"] is
      truncated and not terminated, and reset_infos[i] the new episode's info.
  seed(seed) -> [seed + i]: sub-environment i is seeded seed + i at the next reset (None: a
      seed drawn from entropy), as ParkingEnv().reset(seed=seed + i).
  get_attr, set_attr, env_method, env_is_wrapped: on the sub-environments, each a view of one
      task of the batch: ParkingEnv's attributes (world, fidelity, control_period_s,
      max_episode_steps, discount, render_mode, observation_space, action_space, metadata,
      spec) read-only, render() and get_wrapper_attr(); other attributes may be set (and are
      read back), as on any object. No sub-environment is wrapped.
When stable_baselines3 is importable, SB3VecEnv is a subclass of its VecEnv, so its algorithms,
VecNormalize and VecMonitor take it as it is; without it, _VecEnvBase stands in for the methods
SB3's base class gives (step, seed, set_options, render, ...), with the same behaviour.
"""

import numpy as np

from .vector import VecParkingEnv


class _VecEnvBase:
    """What SB3's VecEnv base class provides around the methods it leaves to subclasses, for
    when stable_baselines3 is not importable (SB3VecEnv behaves the same either way)."""

    def __init__(self, num_envs, observation_space, action_space):
        self.num_envs = num_envs
        self.observation_space = observation_space
        self.action_space = action_space
        self.reset_infos = [{} for _ in range(num_envs)]
        self._seeds = [None] * num_envs
        self._options = [{} for _ in range(num_envs)]
        self.render_mode = self.get_attr("render_mode")[0]
        self.metadata = {"render_modes": [] if self.render_mode is None
                         else ["human", "rgb_array"]}

    def _reset_seeds(self):
        self._seeds = [None] * self.num_envs

    def _reset_options(self):
        self._options = [{} for _ in range(self.num_envs)]

    def step(self, actions):
        self.step_async(actions)
        return self.step_wait()

    def seed(self, seed=None):
        if seed is None:
            seed = int(np.random.default_rng().integers(0, 2**32 - 1))
        self._seeds = [seed + i for i in range(self.num_envs)]
        return self._seeds

    def set_options(self, options=None):
        import copy

        options = {} if options is None else options
        self._options = copy.deepcopy([options] * self.num_envs if isinstance(options, dict)
                                      else list(options))

    def has_attr(self, attr_name):
        try:
            self.get_attr(attr_name)
            return True
        except AttributeError:
            return False

    def render(self, mode=None):
        """The sub-environments' images tiled into one (rgb_array), or None."""
        if (mode or self.render_mode) != "rgb_array" or self.render_mode != "rgb_array":
            return None
        images = np.asarray(self.get_images())
        n, h, w, c = images.shape
        rows = int(np.ceil(np.sqrt(n)))
        cols = int(np.ceil(n / rows))
        grid = np.zeros((rows * cols, h, w, c), dtype=images.dtype)
        grid[:n] = images
        return grid.reshape(rows, cols, h, w, c).transpose(0, 2, 1, 3, 4).reshape(
            rows * h, cols * w, c)

    @property
    def unwrapped(self):
        return self

    def getattr_depth_check(self, name, already_found):
        if hasattr(self, name) and already_found:
            return f"{type(self).__module__}.{type(self).__name__}"
        return None

    def _get_indices(self, indices):
        if indices is None:
            return range(self.num_envs)
        if isinstance(indices, (int, np.integer)):
            return [int(indices)]
        return indices


try:  # pragma: no cover - depends on what is installed
    from stable_baselines3.common.vec_env import VecEnv as _Base
except ImportError:
    _Base = _VecEnvBase


class _SubEnv:
    """Sub-environment `index` of an SB3VecEnv, as get_attr, set_attr and env_method see it:
    ParkingEnv's attributes of the batch (read-only), render(), and attributes of its own."""

    def __init__(self, venv, index):
        self._venv = venv
        self.index = index
        self.spec = None

    world = property(lambda self: self._venv.world)
    fidelity = property(lambda self: self._venv.fidelity)
    control_period_s = property(lambda self: self._venv.control_period_s)
    max_episode_steps = property(lambda self: self._venv.max_episode_steps)
    discount = property(lambda self: self._venv.discount)
    render_mode = property(lambda self: self._venv.render_mode)
    observation_space = property(lambda self: self._venv.single_observation_space)
    action_space = property(lambda self: self._venv.single_action_space)
    metadata = property(lambda self: self._venv.metadata)

    def get_wrapper_attr(self, name):
        return getattr(self, name)

    def compute_reward(self, achieved_goal, desired_goal, info):
        """ParkingEnv.compute_reward (observation="goal_dict"), as HerReplayBuffer calls it
        through env_method."""
        return self._venv.compute_reward(achieved_goal, desired_goal, info)

    def render(self):
        """This task's frame (H x W x 3 uint8) with render_mode="rgb_array", else None."""
        if self.render_mode != "rgb_array":
            return None
        from . import render_frame

        batch, i = self._venv._batch, self.index
        return render_frame(self._venv.world, pose=batch.pose(i),
                            obstacle_poses=batch.obstacle_poses(i), contacts=batch.contacts(i))


def _info_dicts(infos, n):
    """A batch's dict of arrays as n dicts with ParkingEnv's info types (Python scalars, arrays
    of one sub-environment)."""
    columns = {key: (value.tolist() if value.ndim == 1 else value)
               for key, value in infos.items() if not key.startswith("_")}
    return [{key: value[i] for key, value in columns.items()} for i in range(n)]


class SB3VecEnv(_Base):
    """VecParkingEnv(num_envs, world, **options) behind SB3's VecEnv interface (see the
    module's documentation); `venv` is that VecParkingEnv (autoreset_mode "same_step")."""

    def __init__(self, num_envs, world=None, **options):
        if "autoreset_mode" in options:
            raise TypeError("SB3VecEnv: autoreset_mode is SB3's (same step), not an option")
        self.venv = VecParkingEnv(num_envs, world, autoreset_mode="same_step", **options)
        self._sub_envs = [_SubEnv(self.venv, i) for i in range(num_envs)]
        self._actions = None
        super().__init__(num_envs, self.venv.single_observation_space,
                         self.venv.single_action_space)

    def reset(self):
        if any(self._options):
            raise ValueError("SB3VecEnv.reset: reset options are not supported (set_options);"
                             " a VecParkingEnv sub-environment starts from its seed's draws")
        obs, infos = self.venv.reset(seed=list(self._seeds))  # goal_dict: dict observations
        self.reset_infos = _info_dicts(infos, self.num_envs)
        self._reset_seeds()
        self._reset_options()
        return obs

    def step_async(self, actions):
        self._actions = actions

    def step_wait(self):
        actions, self._actions = self._actions, None  # one step per step_async
        if actions is None:
            raise RuntimeError("SB3VecEnv.step_wait: call step_async(actions) first")
        if not all(self.venv._seeded):
            raise RuntimeError("SB3VecEnv.step_wait: call reset() before stepping")
        venv, batch = self.venv, self.venv._batch  # its arrays: VecParkingEnv's infos
        last_obs, rewards, terminated, truncated, last_infos = batch.step(actions)
        venv._add_previous_goal(last_infos, np.ones(self.num_envs, dtype=bool))
        last_obs = venv._observed(last_obs, last_infos)
        obs, started_infos = batch.started()
        obs = venv._observed(obs, started_infos)
        dones = terminated | truncated
        infos = _info_dicts(last_infos, self.num_envs)
        if dones.any():
            started = _info_dicts(started_infos, self.num_envs)
            for i in np.flatnonzero(dones):
                infos[i]["terminal_observation"] = (
                    last_obs[i] if venv.observation == "array"
                    else {key: value[i] for key, value in last_obs.items()})
                self.reset_infos[i] = started[i]
        for i, info in enumerate(infos):
            info["TimeLimit.truncated"] = bool(truncated[i] and not terminated[i])
        return obs, rewards.astype(np.float32), dones, infos

    def close(self):
        self.venv.close()

    def get_attr(self, attr_name, indices=None):
        return [getattr(self._sub_envs[i], attr_name) for i in self._get_indices(indices)]

    def set_attr(self, attr_name, value, indices=None):
        for i in self._get_indices(indices):
            setattr(self._sub_envs[i], attr_name, value)

    def env_method(self, method_name, *method_args, indices=None, **method_kwargs):
        return [getattr(self._sub_envs[i], method_name)(*method_args, **method_kwargs)
                for i in self._get_indices(indices)]

    def env_is_wrapped(self, wrapper_class, indices=None):
        return [False for _ in self._get_indices(indices)]

    def get_images(self):
        return [sub.render() for sub in self._sub_envs]

    def __repr__(self):
        return f"SB3VecEnv({self.venv!r})"


__all__ = ["SB3VecEnv"]
