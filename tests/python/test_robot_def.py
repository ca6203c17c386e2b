"""parksim.RobotDef for both drives (issue 38): every car key read and written, each field
checked as the world file's key with the reader's own message, the whole robot as the reader
checks it, and a car world built in Python that plans and drives an episode."""

import math
import pickle

import pytest

import parksim

CAR_FIELDS = ["length_m", "width_m", "front_overhang_m", "axle_distance_m", "track_m",
              "wheel_radius_m", "max_steer_rad", "max_steer_rate_radps", "max_speed_mps",
              "max_accel_mps2", "height_m", "ground_clearance_m"]


def world_text(robot_lines):
    return ("format: parksim-world/1\nname: w\n"
            "lot: {x_min: 0.0, y_min: 0.0, x_max: 40.0, y_max: 40.0}\n"
            "robot:\n" + "".join(f"  {line}\n" for line in robot_lines) +
            "start: [10.0, 10.0, 0]\ngoal:\n  pose: [30.0, 10.0, 0]\n")


def reader_message(robot_lines, tmp_path):
    """The world reader's message for a robot: section, without its file and line."""
    path = tmp_path / "w.yaml"
    path.write_text(world_text(robot_lines))
    with pytest.raises(parksim.Error) as e:
        parksim.load_world(str(path))
    located = str(e.value)
    assert located.startswith(f"{path}:")
    return located.split(": ", 1)[1]


def test_a_car_has_every_car_key_and_the_mid_size_cars_defaults():
    car = parksim.RobotDef(drive="car")
    assert car.drive == "car"
    assert sorted(car.to_dict()) == sorted(CAR_FIELDS + ["drive"])
    # docs/cars.md's mid-size car.
    assert (car.length_m, car.width_m, car.front_overhang_m) == (4.689, 1.942, 3.739)
    assert (car.axle_distance_m, car.track_m, car.wheel_radius_m) == (2.8, 1.6, 0.33)
    assert (car.max_steer_rad, car.max_steer_rate_radps) == (0.75, 0.5)
    assert (car.max_speed_mps, car.max_accel_mps2, car.height_m) == (2.5, 1.0, 1.5)
    assert car.ground_clearance_m == 0.15
    assert car.max_steer_deg == pytest.approx(math.degrees(0.75), rel=1e-15)
    assert car.min_turning_radius_m == pytest.approx(2.8 / math.tan(0.75), rel=1e-15)


def test_every_car_field_is_written_and_the_wheel_limits_follow():
    car = parksim.RobotDef(drive="car")
    car.axle_distance_m = 2.7
    car.track_m = 1.55
    car.max_steer_deg = 35.0
    car.max_steer_rate_degps = 40.0
    car.max_speed_mps = 2.0
    car.max_accel_mps2 = 1.5
    car.wheel_radius_m = 0.3
    car.length_m, car.width_m, car.front_overhang_m = 4.5, 1.9, 3.6
    car.height_m, car.ground_clearance_m = 1.4, 0.12
    car.check()
    assert car.max_steer_rad == pytest.approx(math.radians(35.0), rel=1e-15)
    assert car.max_steer_rate_radps == pytest.approx(math.radians(40.0), rel=1e-15)
    # RobotDef.h's setCarWheelLimits, written out: the outer rear wheel at the tightest turn.
    curvature = math.tan(math.radians(35.0)) / 2.7
    assert car.max_wheel_speed_radps == pytest.approx(2.0 * (1 + 0.5 * 1.55 * curvature) / 0.3,
                                                      rel=1e-12)
    assert car.max_wheel_accel_radps2 == pytest.approx(1.5 / 0.3, rel=1e-12)
    again = pickle.loads(pickle.dumps(car))
    assert again.to_dict() == car.to_dict()
    assert parksim.RobotDef(car.to_dict()).to_dict() == car.to_dict()


@pytest.mark.parametrize("field, value, key, written", [
    ("axle_distance_m", 25.0, "axle_distance", "25"),
    ("max_steer_deg", 85.0, "max_steer_deg", "85"),
    ("max_steer_rate_degps", 0.01, "max_steer_rate_degps", "0.01"),
    ("max_speed_mps", 200.0, "max_speed_mps", "200"),
    ("max_accel_mps2", 0.001, "max_accel_mps2", "0.001"),
    ("track_m", 30.0, "track", "30"),
])
def test_a_field_out_of_range_is_refused_with_the_readers_range(field, value, key, written,
                                                                tmp_path):
    file_message = reader_message(["drive: car", f"{key}: {written}"], tmp_path)
    car = parksim.RobotDef(drive="car")
    with pytest.raises(ValueError) as e:
        setattr(car, field, value)
    # The same range and reason as the file's ("must be in [lo, hi] unit (why), got ...").
    ours = str(e.value)
    assert ours.startswith(f"RobotDef.{field}: ")
    assert ours.split(", got")[0].split(": ", 1)[1] == file_message.split(", got")[0].split(
        ": ", 1)[1]
    assert car.to_dict() == parksim.RobotDef(drive="car").to_dict()  # unchanged


@pytest.mark.parametrize("fields, lines", [
    ({"axle_distance_m": 4.0}, ["axle_distance: 4.0"]),
    ({"max_steer_deg": 75.0, "axle_distance_m": 0.2}, ["max_steer_deg: 75", "axle_distance: 0.2"]),
    ({"track_m": 2.0}, ["track: 2.0"]),
    ({"ground_clearance_m": 1.6}, ["ground_clearance: 1.6"]),
])
def test_a_car_the_reader_refuses_is_refused_with_its_message(fields, lines, tmp_path):
    file_message = reader_message(["drive: car"] + lines, tmp_path)
    with pytest.raises(parksim.Error) as e:
        parksim.RobotDef(drive="car", **fields)
    assert str(e.value).split(", got")[0] == file_message.split(", got")[0]


def test_the_other_drives_fields_are_refused_by_name():
    with pytest.raises(ValueError, match=r"RobotDef.axle_distance_m: a car's field"):
        parksim.RobotDef(axle_distance_m=2.0)
    with pytest.raises(ValueError, match=r"RobotDef.max_wheel_speed_radps: a differential"):
        parksim.RobotDef(drive="car", max_wheel_speed_radps=5.0)
    with pytest.raises(ValueError, match=r"unknown drive \"boat\""):
        parksim.RobotDef(drive="boat")
    with pytest.raises(TypeError, match="unknown option steer"):
        parksim.RobotDef(drive="car", steer=1.0)


def test_a_differential_drive_is_unchanged(head_in):
    robot = parksim.RobotDef()
    assert robot.drive == "differential"
    assert robot.to_dict() == head_in.robot.to_dict()
    assert head_in.robot.wheel_base_m == 0.085


def test_a_car_world_built_in_python_plans_and_drives_an_episode():
    car = parksim.RobotDef(drive="car", max_steer_deg=38.0, max_steer_rate_degps=35.0,
                           max_speed_mps=2.0, axle_distance_m=2.7)
    world = parksim.load_world({
        "format": "parksim-world/1", "name": "python_car",
        "lot": {"x_min": 0.0, "y_min": 0.0, "x_max": 40.0, "y_max": 30.0},
        "robot": car,
        "physics": {"chassis_mass_kg": 1500, "wheel_mass_kg": 75, "max_wheel_torque_nm": 1500},
        "start": [8.0, 10.0, 0], "goal": {"pose": [28.0, 18.0, 90], "position_tolerance": 0.05,
                                          "heading_tolerance_deg": 1.0},
    })
    assert world.robot.drive == "car"
    for field, value in car.to_dict().items():
        assert getattr(world.robot, field) == pytest.approx(value, rel=1e-14), field
    run = parksim.run(world)
    assert run.status == "met", run.reason
    # A car's plan: it never turns in place nor tighter than tan(38 deg) / 2.7 m.
    plan = run.plan.trajectory
    assert (abs(plan["omega"]) <= abs(plan["v"]) * math.tan(math.radians(38.0)) / 2.7 * (1 + 1e-6)
            + 1e-12).all()
    assert abs(plan["v"]).max() > 1.0
