"""Map worlds (issue 32) from Python: load_world with a ROS, SVG or Moving AI map (by name, by
path, as a dict), their obstacles' convex parts, plan() and run() as the command line does them,
and the parking task (ParkingEnv, the Gymnasium environment) on a map lot, in both fidelities."""

import numpy as np
import pytest

import parksim
from conftest import SOURCE_DIR, run_cli


@pytest.mark.parametrize("name", ["ros_lab", "svg_lot", "warehouse"])
def test_installed_map_worlds_load_by_name_and_by_path(name):
    by_name = parksim.load_world(name)
    by_path = parksim.load_world(SOURCE_DIR / "worlds" / f"{name}.yaml")
    assert [o["name"] for o in by_name.obstacles] == [o["name"] for o in by_path.obstacles]
    assert by_name.obstacles


def test_a_maps_obstacle_carries_its_convex_parts():
    lab = parksim.load_world("ros_lab")
    (wall,) = lab.obstacles
    assert wall["shape"] == "compound" and wall["rings"] == []
    parts = wall["parts"]
    assert len(parts) > 10 and all(p.shape == (4, 2) for p in parts)
    # The parts lie within the obstacle's bounding rectangle, which spans the 6 x 4 m map.
    lo = np.min([p.min(axis=0) for p in parts], axis=0)
    hi = np.max([p.max(axis=0) for p in parts], axis=0)
    assert np.allclose(lo, [-1.0, -0.5]) and np.allclose(hi, [5.0, 3.5])
    ring = {o["name"]: o for o in parksim.load_world("svg_lot").obstacles}["lot/planter_ring"]
    assert ring["shape"] == "compound" and len(ring["rings"]) == 2


def test_a_dict_world_may_name_a_map():
    maps = SOURCE_DIR / "worlds" / "maps"
    world = parksim.load_world({
        "format": "parksim-world/1", "name": "d",
        "map": [{"movingai": str(maps / "warehouse.map"), "cell": 0.05, "inflation": 0.1}],
        "start": [1.0, 1.0, 0], "goal": {"pose": [2.0, 1.0, 0]}})
    assert world.obstacles[0]["name"] == "warehouse"
    with pytest.raises(parksim.Error, match=r"map\[0\]\.movingai: .*nothere\.map: cannot open"):
        parksim.load_world({"format": "parksim-world/1", "name": "d",
                            "map": [{"movingai": str(maps / "nothere.map"), "cell": 0.05}],
                            "start": [1.0, 1.0, 0], "goal": {"pose": [2.0, 1.0, 0]}})


def test_run_on_a_map_world_matches_the_command_line(tmp_path):
    path = SOURCE_DIR / "worlds" / "svg_lot.yaml"
    result = parksim.run(parksim.load_world(path))
    assert result.met
    out = tmp_path / "cli"
    run_cli("run", path, "--out", out)
    executed = np.loadtxt(out / "executed.csv", delimiter=",", skiprows=1)
    assert np.array_equal(result.executed["x"].view(np.uint64), executed[:, 1].view(np.uint64))


@pytest.mark.parametrize("fidelity", ["dynamics", "kinematic"])
def test_the_parking_task_runs_on_a_map_lot(fidelity):
    env = parksim.ParkingEnv("ros_lab", fidelity=fidelity, max_episode_steps=200)
    obs, info = env.reset(seed=4)
    assert obs.shape == (10,) and np.all(np.isfinite(obs))
    assert info["contacts"].shape == (len(env.world.obstacles),)
    rng = np.random.default_rng(1)
    steps = 0
    while True:
        obs, reward, terminated, truncated, info = env.step(rng.uniform(-1, 1, 2).astype(np.float32))
        steps += 1
        assert np.all(np.isfinite(obs)) and np.isfinite(reward)
        if terminated or truncated:
            break
    assert steps <= 200
    # The start was drawn where the map leaves room.
    assert not parksim.CollisionChecker(env.world).overlapping(tuple(env.reset(seed=5)[1]["pose"]))
