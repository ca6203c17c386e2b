"""ParkingEnv: the parking task with gymnasium's interface, for reinforcement learning.

Used like highway-env's parking-v0:

    env = parksim.ParkingEnv(world="worlds/head_in.yaml")
    obs, info = env.reset(seed=0)
    obs, reward, terminated, truncated, info = env.step(env.action_space.sample())

gymnasium is optional (Debian does not ship it). When it is importable, ParkingEnv is a
gymnasium.Env with gymnasium.spaces.Box spaces and is registered as "parksim/Parking-v0";
otherwise the spaces are parksim.spaces.Box, with the same attributes.
"""

import math

import numpy as np

from . import _parksim

try:  # pragma: no cover - depends on what is installed
    import gymnasium as _gym
    from gymnasium.spaces import Box as _Box

    _Base = _gym.Env
except ImportError:
    _gym = None
    from .spaces import Box as _Box

    _Base = object


def _wrap(angle):
    return (angle + math.pi) % (2.0 * math.pi) - math.pi


class ParkingEnv(_Base):
    """Drive the world's robot from (near) its start into the goal, by wheel speeds.

    Action: Box(-1, 1, (2,), float32), the left and right wheel speeds as fractions of the
    robot's maximum; each action is held for control_period_s (whole simulation steps).

    Observation: Box(-inf, inf, (10,), float32):
        x, y, cos(theta), sin(theta), v, omega, x_goal, y_goal, cos(theta_goal), sin(theta_goal)
    (m, m/s, rad/s; the true state of the Bullet simulation).

    Reward per step, as parking-v0's: -sqrt(d / distance_scale_m + heading_weight * e / pi),
    d the distance to the goal position and e the heading error (either heading when the goal
    allows it), plus contact_reward on every step the chassis penetrates an obstacle and
    success_reward on success.

    terminated: success (within success_position_m and success_heading_rad of the goal; the
    world's own tolerances, 1 mm / 0.5 deg in the study, are for planned trajectories), or a
    contact when terminate_on_contact. truncated: max_episode_steps actions, or the reference
    point left the lot.

    reset(seed=...) perturbs the start by up to start_position_noise_m and
    start_heading_noise_rad (uniform), keeping the footprint collision-free.
    """

    metadata = {"render_modes": ["rgb_array"], "render_fps": 10}

    def __init__(self, world="worlds/head_in.yaml", control_period_s=0.1, max_episode_steps=300,
                 start_position_noise_m=0.02, start_heading_noise_rad=0.2,
                 success_position_m=0.01, success_heading_rad=math.radians(5.0),
                 distance_scale_m=0.1, heading_weight=0.3, contact_reward=-1.0,
                 success_reward=10.0, terminate_on_contact=True, render_mode=None, model=None):
        if isinstance(world, _parksim.World):
            self.world = world
        else:
            from . import load_world
            self.world = load_world(world)
        if render_mode not in (None, "rgb_array"):
            raise ValueError(f"render_mode must be None or 'rgb_array', got {render_mode!r}")
        self.render_mode = render_mode
        self.model = model
        dt = self.world.time_step_s
        self.steps_per_action = max(1, round(control_period_s / dt))
        self.control_period_s = self.steps_per_action * dt
        self.max_episode_steps = int(max_episode_steps)
        self.start_position_noise_m = float(start_position_noise_m)
        self.start_heading_noise_rad = float(start_heading_noise_rad)
        self.success_position_m = float(success_position_m)
        self.success_heading_rad = float(success_heading_rad)
        self.distance_scale_m = float(distance_scale_m)
        self.heading_weight = float(heading_weight)
        self.contact_reward = float(contact_reward)
        self.success_reward = float(success_reward)
        self.terminate_on_contact = bool(terminate_on_contact)

        self._max_wheel = self.world.robot.max_wheel_speed_radps
        goal = self.world.goal
        self._goal = goal["pose"]
        self._either_heading = goal["either_heading"]
        self._lot = self.world.lot
        self._checker = _parksim.CollisionChecker(self.world)
        self.action_space = _Box(-1.0, 1.0, shape=(2,), dtype=np.float32)
        self.observation_space = _Box(-np.inf, np.inf, shape=(10,), dtype=np.float32)
        self.np_random = np.random.default_rng()
        self._sim = None
        self._steps = 0

    # -- gymnasium interface ---------------------------------------------------------------

    def reset(self, *, seed=None, options=None):
        if _gym is not None:
            super().reset(seed=seed)
        elif seed is not None:
            self.np_random = np.random.default_rng(seed)
        if seed is not None:
            self.action_space.seed(seed)
        start = self._sample_start()
        self._sim = _parksim.DynamicsWorld(self.world, start=start, model=self.model)
        self._steps = 0
        return self._observation(), self._info()

    def step(self, action):
        if self._sim is None:
            raise RuntimeError("call reset() before step()")
        a = np.clip(np.asarray(action, dtype=np.float64).reshape(2), -1.0, 1.0)
        self._sim.set_wheel_targets(float(a[0]) * self._max_wheel, float(a[1]) * self._max_wheel)
        self._sim.step(self.steps_per_action)
        self._steps += 1
        info = self._info()
        contact = bool(info["contacts"])
        reward = -math.sqrt(info["goal_pos_err_m"] / self.distance_scale_m
                            + self.heading_weight * info["goal_heading_err_rad"] / math.pi)
        if contact:
            reward += self.contact_reward
        if info["is_success"]:
            reward += self.success_reward
        terminated = info["is_success"] or (contact and self.terminate_on_contact)
        x, y, _ = info["pose"]
        outside = not (self._lot["x_min"] <= x <= self._lot["x_max"]
                       and self._lot["y_min"] <= y <= self._lot["y_max"])
        truncated = (not terminated) and (self._steps >= self.max_episode_steps or outside)
        return self._observation(), reward, terminated, truncated, info

    def render(self):
        if self.render_mode != "rgb_array" or self._sim is None:
            return None
        from . import render_frame
        return render_frame(self.world, pose=self._sim.pose,
                            obstacle_poses=self._sim.obstacle_poses,
                            contacts=self._sim.contacts)

    def close(self):
        self._sim = None

    # -- internals -------------------------------------------------------------------------

    def _sample_start(self):
        x0, y0, t0 = self.world.start
        for _ in range(100):
            dx, dy = self.np_random.uniform(-1.0, 1.0, size=2) * self.start_position_noise_m
            dt = self.np_random.uniform(-1.0, 1.0) * self.start_heading_noise_rad
            pose = (x0 + dx, y0 + dy, _wrap(t0 + dt))
            if self._checker.is_free(pose):
                return pose
        return (x0, y0, t0)

    def _heading_error(self, theta):
        err = abs(_wrap(theta - self._goal[2]))
        if self._either_heading:
            err = min(err, abs(_wrap(theta - self._goal[2] - math.pi)))
        return err

    def _observation(self):
        s = self._sim.robot_state()
        x, y, theta = s["pose"]
        v, omega = s["twist"]
        gx, gy, gt = self._goal
        return np.array([x, y, math.cos(theta), math.sin(theta), v, omega,
                         gx, gy, math.cos(gt), math.sin(gt)], dtype=np.float32)

    def _info(self):
        pose = self._sim.pose
        pos_err = math.hypot(pose[0] - self._goal[0], pose[1] - self._goal[1])
        heading_err = self._heading_error(pose[2])
        return {
            "pose": pose,
            "t": self._sim.time,
            "goal_pos_err_m": pos_err,
            "goal_heading_err_rad": heading_err,
            "is_success": pos_err <= self.success_position_m
            and heading_err <= self.success_heading_rad,
            "contacts": self._sim.contacts,
        }


if _gym is not None:  # pragma: no cover - depends on what is installed
    if "parksim/Parking-v0" not in _gym.registry:
        _gym.register(id="parksim/Parking-v0", entry_point="parksim.env:ParkingEnv")
