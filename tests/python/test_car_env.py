"""ParkingEnv with a car (issue 38): actions [acceleration, steering] as highway-env's
parking-v0 has them, on a kinematic bicycle within the world's steering-rate, speed and
acceleration limits; the observation's speed and steering; gymnasium.make, Gymnasium's checker
and VecParkingEnv. The expected numbers come from the world file's own keys, written here."""

import math

import numpy as np
import pytest

import parksim
from conftest import gymnasium_or_skip

AXLE_M = 2.8
MAX_STEER_RAD = math.radians(40.0)
MAX_STEER_RATE_RADPS = math.radians(30.0)
MAX_SPEED_MPS = 2.0
MAX_ACCEL_MPS2 = 1.5
DT_S = 1.0 / 240.0  # the world's physics step (the default)

WORLD = f"""format: parksim-world/1
name: open_car
lot: {{x_min: 0.0, y_min: 0.0, x_max: 60.0, y_max: 60.0}}
robot:
  drive: car
  axle_distance: {AXLE_M}
  max_steer_deg: 40
  max_steer_rate_degps: 30
  max_speed_mps: {MAX_SPEED_MPS}
  max_accel_mps2: {MAX_ACCEL_MPS2}
start: [30.0, 30.0, 0]
goal:
  pose: [50.0, 50.0, 90]
"""


@pytest.fixture(scope="module")
def car_world(tmp_path_factory):
    path = tmp_path_factory.mktemp("car") / "open_car.yaml"
    path.write_text(WORLD)
    return parksim.load_world(str(path))


def car_env(world, **options):
    return parksim.ParkingEnv(world, fidelity="kinematic", max_episode_steps=None, **options)


def test_the_steering_angle_moves_at_most_at_the_rate_limit(car_world):
    env = car_env(car_world)
    obs, _ = env.reset(options={"start": (30.0, 30.0, 0.0)})
    assert obs[5] == 0.0  # straight wheels at the start
    period = env.control_period_s
    target = 0.9 * MAX_STEER_RAD
    for k in range(1, 25):
        obs, *_, info = env.step([0.0, 0.9])
        assert obs[5] == pytest.approx(min(target, MAX_STEER_RATE_RADPS * k * period), abs=1e-6)
        # Standing, the car neither moves nor turns.
        assert list(info["pose"]) == [30.0, 30.0, 0.0]


def test_a_constant_steering_angle_drives_a_circle_of_radius_axle_over_tan_steer(car_world):
    env = car_env(car_world)
    env.reset(options={"start": (30.0, 30.0, 0.0)})
    steer = -0.6 * MAX_STEER_RAD  # right
    for _ in range(30):  # steer while standing until the wheels are there (at most 1.7 s)
        obs, *_ = env.step([0.0, -0.6])
    assert obs[5] == pytest.approx(steer, abs=1e-6)
    radius = AXLE_M / math.tan(abs(steer))
    centre = np.array([30.0, 30.0 - radius])  # right of the heading (east)
    for k in range(150):
        obs, reward, terminated, truncated, info = env.step([0.5 if k < 10 else 0.0, -0.6])
        assert not terminated
        assert np.hypot(*(info["pose"][:2] - centre)) == pytest.approx(radius, abs=1e-9)
    assert obs[4] == pytest.approx(10 * 24 * 0.5 * MAX_ACCEL_MPS2 * DT_S, abs=1e-6)


@pytest.mark.parametrize("sign", [1.0, -1.0])
def test_speed_changes_at_the_acceleration_limit_up_to_the_speed_limit(car_world, sign):
    env = car_env(car_world)
    env.reset(options={"start": (30.0, 30.0, 0.0)})
    period = env.control_period_s
    speeds = [0.0]
    for k in range(1, 30):
        obs, *_ = env.step([2.0 * sign, 0.0])  # clipped to full acceleration
        expected = sign * min(MAX_SPEED_MPS, MAX_ACCEL_MPS2 * k * period)
        assert obs[4] == pytest.approx(expected, abs=1e-6)
        speeds.append(float(obs[4]))
    assert max(abs(v) for v in speeds) <= MAX_SPEED_MPS
    assert np.all(np.abs(np.diff(speeds)) <= MAX_ACCEL_MPS2 * period + 1e-6)


def test_spaces_are_the_cars(car_world):
    env = car_env(car_world)
    assert env.action_space.shape == (2,)
    assert env.observation_space.shape == (10,)
    assert env.observation_space.low[4] == np.float32(-MAX_SPEED_MPS)
    assert env.observation_space.high[5] == np.float32(MAX_STEER_RAD)


def test_the_dynamics_fidelity_drives_the_car_in_bullet(car_world):
    # The default fidelity: the car's body in Bullet, the kinematic task's actions. At a constant
    # acceleration fraction f the speed ramps at f * max_accel (within a physics step's change)
    # and the steering turns at max_steer_rate toward its target.
    env = parksim.ParkingEnv(car_world, max_episode_steps=None)
    assert env.fidelity == "dynamics"
    obs, _ = env.reset(options={"start": (30.0, 30.0, 0.0)})
    for _ in range(10):
        obs, _, terminated, _, info = env.step([0.5, 0.0])
        assert not terminated
    accel = 0.5 * MAX_ACCEL_MPS2
    assert obs[4] == pytest.approx(accel * info["t"], abs=accel * DT_S)
    assert info["pose"][1] == pytest.approx(30.0, abs=1e-3)
    steer_s = 0.5
    for _ in range(round(steer_s / env.control_period_s)):
        obs, *_ = env.step([0.0, 1.0])
    assert obs[5] == pytest.approx(MAX_STEER_RATE_RADPS * steer_s, abs=0.02)


def test_gymnasium_make_and_its_checker_take_a_car(car_world):
    gym = gymnasium_or_skip()
    from gymnasium.utils.env_checker import check_env

    env = gym.make("parksim/Parking-v0", world=car_world, fidelity="kinematic")
    check_env(env.unwrapped)
    obs, _ = env.reset(seed=3)
    assert env.observation_space.contains(obs)
    obs, *_ = env.step(np.array([1.0, 1.0], dtype=np.float32))
    assert obs[4] > 0.0 and obs[5] > 0.0


def test_vector_environments_step_cars_as_single_ones(car_world):
    actions = np.random.default_rng(0).uniform(-1.0, 1.0, (20, 3, 2))
    venv = parksim.VecParkingEnv(3, car_world, fidelity="kinematic", threads=2)
    vobs, _ = venv.reset(seed=5)
    singles = [car_env(car_world) for _ in range(3)]
    sobs = [env.reset(seed=5 + i)[0] for i, env in enumerate(singles)]
    assert np.array_equal(vobs, np.stack(sobs))
    for a in actions:
        vobs, *_ = venv.step(a)
        for i, env in enumerate(singles):
            obs, _, terminated, truncated, _ = env.step(a[i])
            assert not (terminated or truncated)
            assert np.array_equal(vobs[i], obs)
