"""Loading worlds from files and dicts; every reader error arrives as parksim.Error with the
command line's located message."""

import math

import pytest
import yaml

import parksim
from conftest import run_cli


def test_load_world_reads_the_study_lot(head_in, head_in_path):
    assert head_in.name == "head_in"
    assert head_in.source_path == str(head_in_path)
    assert len(head_in.obstacles) > 0
    assert {"name", "kind", "center", "size", "yaw", "height", "corners"} <= set(
        head_in.obstacles[0])
    assert head_in.obstacles[0]["corners"].shape == (4, 2)
    assert head_in.robot.length_m == pytest.approx(0.080)
    x, y, theta = head_in.start
    assert head_in.lot["x_min"] <= x <= head_in.lot["x_max"]
    assert head_in.time_step_s == pytest.approx(1.0 / 240.0)


def test_a_dict_with_the_files_structure_gives_the_same_world(head_in, head_in_path):
    data = yaml.safe_load(head_in_path.read_text())
    world = parksim.load_world(data)
    assert world.source_path == "<dict>"
    assert world.start == head_in.start
    assert world.goal == head_in.goal
    assert [o["name"] for o in world.obstacles] == [o["name"] for o in head_in.obstacles]
    for a, b in zip(world.obstacles, head_in.obstacles):
        assert a["center"] == b["center"] and a["size"] == b["size"] and a["yaw"] == b["yaw"]
    # Same world, same plan, to the bit.
    pa = parksim.plan(world, seed=3).trajectory
    pb = parksim.plan(head_in, seed=3).trajectory
    assert pa.tobytes() == pb.tobytes()


def bad_world(tmp_path, head_in_path, edit):
    text = head_in_path.read_text()
    bad = edit(text)
    assert bad != text
    path = tmp_path / "bad.yaml"
    path.write_text(bad)
    return path


@pytest.mark.parametrize("edit", [
    lambda t: t.replace("format: parksim-world/1", "format: parksim-world/9"),
    lambda t: t + "\nunknown_key: 1\n",
    lambda t: t.replace("obstacles:", "obstacles: 3\nold_obstacles:", 1),
])
def test_bad_files_raise_the_command_lines_message(tmp_path, head_in_path, edit):
    path = bad_world(tmp_path, head_in_path, edit)
    with pytest.raises(parksim.Error) as raised:
        parksim.load_world(path)
    message = str(raised.value)
    assert message.startswith(str(path) + ":")
    assert isinstance(raised.value, ValueError)
    code, _, err = run_cli("plan", path, "--out", tmp_path / "out")
    assert code == 2
    assert err.strip() == "parksim: error: " + message


def test_a_missing_file_names_the_file(tmp_path):
    with pytest.raises(parksim.Error, match="nope.yaml"):
        parksim.load_world(tmp_path / "nope.yaml")


def test_a_bad_dict_names_the_field_and_line(head_in_path):
    data = yaml.safe_load(head_in_path.read_text())
    data["robot"] = dict(data.get("robot", {}), length=-0.1)
    with pytest.raises(parksim.Error, match=r"^<dict>:\d+: robot\.length"):
        parksim.load_world(data)


def test_collision_checker_and_cspace_agree(head_in):
    checker = parksim.CollisionChecker(head_in)
    assert checker.is_free(head_in.start)
    obstacle = head_in.obstacles[0]
    cx, cy = obstacle["center"]
    assert not checker.is_free((cx, cy, 0.0))
    assert obstacle["name"] in checker.overlapping((cx, cy, 0.0))
    # The C-space slice at a heading contains exactly the colliding reference points.
    slices = parksim.cspace_slice(head_in, 0.3)
    assert len(slices) == len(head_in.obstacles)
    poly = slices[0]
    assert poly.shape[1] == 2 and 4 <= poly.shape[0] <= 8
    centroid = poly.mean(axis=0)
    assert not checker.is_free((centroid[0], centroid[1], 0.3))
    assert math.isfinite(checker.clearance(head_in.start))


def test_a_dict_may_hold_numpy_values(head_in_path):
    import numpy as np

    data = yaml.safe_load(head_in_path.read_text())
    data["start"] = np.array(data["start"], dtype=np.float64)
    data["goal"]["position_tolerance"] = np.float64(data["goal"]["position_tolerance"])
    assert parksim.load_world(data).start == parksim.load_world(head_in_path).start


def test_a_map_key_map_server_ignores_is_a_warning_not_an_error(tmp_path, source_dir):
    """Issue 39: a ROS map YAML's `centerline` (nav2's map_server ignores it) was refused."""
    (tmp_path / "maps").mkdir()
    (tmp_path / "maps" / "lab.pgm").write_bytes((source_dir / "worlds/maps/lab.pgm").read_bytes())
    (tmp_path / "maps" / "lab.yaml").write_text(
        (source_dir / "worlds/maps/lab.yaml").read_text() + "centerline: [[0, 0], [1, 0]]\n")
    (tmp_path / "w.yaml").write_text((source_dir / "worlds/ros_lab.yaml").read_text())
    with pytest.warns(UserWarning, match=r"lab\.yaml:8: centerline: not a key nav2's map_server"):
        world = parksim.load_world(tmp_path / "w.yaml")
    assert world.name == "ros_lab"
