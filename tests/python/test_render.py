"""Images as NumPy arrays: frames of the lot, an episode instant, the study's figures, PNG."""

import pathlib

import numpy as np
import pytest

import parksim


def test_a_frame_of_the_lot_is_an_rgb_array(head_in):
    image = parksim.render_frame(head_in, width=320, height=240)
    assert image.shape == (240, 320, 3) and image.dtype == np.uint8
    assert len(np.unique(image.reshape(-1, 3), axis=0)) > 3  # ground, obstacles, markers


def test_the_robot_and_the_plan_change_the_frame(head_in, head_in_plan):
    lot = parksim.render_frame(head_in, width=320, height=240, msaa=1)
    with_robot = parksim.render_frame(head_in, pose=(0.9, 0.4, 0.0), width=320, height=240,
                                      msaa=1)
    with_plan = parksim.render_frame(head_in, plan=head_in_plan, width=320, height=240, msaa=1)
    assert not np.array_equal(lot, with_robot)
    assert not np.array_equal(lot, with_plan)
    # Top view: the lot spans 1.8 m across ~314 pixels. The robot at x 0.9 lies near the
    # image's middle column; the rest of the image is unchanged.
    changed = np.any(lot != with_robot, axis=2)
    cols = np.nonzero(changed.any(axis=0))[0]
    assert 130 < cols.mean() < 190
    # Same inputs, same pixels.
    again = parksim.render_frame(head_in, pose=(0.9, 0.4, 0.0), width=320, height=240, msaa=1)
    assert np.array_equal(with_robot, again)


def test_an_episode_instant_and_the_3d_view(head_in, head_in_plan):
    ep = parksim.Episode(head_in, head_in_plan)
    ep.step(240)
    top = parksim.render_frame(head_in, episode=ep, width=320, height=240)
    view3d = parksim.render_frame(head_in, episode=ep, width=320, height=240, view="3d")
    assert top.shape == view3d.shape == (240, 320, 3)
    assert not np.array_equal(top, view3d)
    with pytest.raises(ValueError, match="view"):
        parksim.render_frame(head_in, view="side")


@pytest.mark.parametrize("name", ["lot_map", "cspace_slice", "plan", "tracking_error"])
def test_figures(head_in, head_in_plan, name):
    run = parksim.run(head_in, plan=head_in_plan) if name == "tracking_error" else None
    image = parksim.render_figure(head_in, name, plan=head_in_plan,
                                  executed=None if run is None else run.executed,
                                  width=300, height=200, msaa=1)
    assert image.shape == (200, 300, 3) and image.dtype == np.uint8
    assert image.std() > 0


def test_write_figures_writes_the_chosen_figures(tmp_path, head_in, head_in_plan):
    assert parksim.FIGURE_NAMES == ("lot_map", "steering", "cspace_slice", "cspace_stack",
                                    "plan", "tracking_error", "lot_3d")
    out = tmp_path / "some"
    written = parksim.write_figures(head_in, str(out), figures="plan, lot_map,plan",
                                    plans=[head_in_plan], width=240, height=160, msaa=1)
    assert written == [str(out / "lot_map.png"), str(out / "plan_time-a-star.png")]
    assert sorted(p.name for p in out.iterdir()) == ["lot_map.png", "plan_time-a-star.png"]
    assert parksim.read_png(written[0]).shape == (160, 240, 3)
    assert parksim.write_figures(head_in, str(tmp_path / "none"), figures="none") == []
    assert not (tmp_path / "none").exists()
    with pytest.raises(parksim.Error, match="unknown figure 'lotmap'.*lot_3d"):
        parksim.write_figures(head_in, str(tmp_path / "bad"), figures="lot_map,lotmap")
    assert not (tmp_path / "bad").exists()


def test_png_round_trip(tmp_path, head_in):
    image = parksim.render_frame(head_in, width=64, height=48, msaa=1)
    data = parksim.encode_png(image)
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    path = tmp_path / "frame.png"
    parksim.write_png(str(path), image)
    assert path.read_bytes()[:8] == data[:8]
    assert np.array_equal(parksim.read_png(str(path)), image)


def test_frame_recorder_writes_frames(tmp_path, head_in, head_in_plan):
    rec = parksim.FrameRecorder(head_in, out_dir=str(tmp_path), fps=10, width_px=64, height_px=48)
    rec.set_plan(head_in_plan)
    ep = parksim.Episode(head_in, head_in_plan)
    for _ in range(5):
        obs = ep.observation()
        rec.add_frame(obs["t"], obs["pose"], reference=obs["reference"])
        ep.step(24)  # 0.1 s
    result = rec.finish()
    assert result["frames"] == 5
    assert sorted(p.name for p in (tmp_path / "frames").iterdir())[0] == "000000.png"


def test_frame_recorder_refuses_a_film_over_the_memory_bound(tmp_path, head_in):
    # Stored frames of 8192x8192, both views, would hold their whole file besides the
    # framebuffers and the frame (docs/limits.md): refused before anything is written.
    out = tmp_path / "never"
    with pytest.raises(ValueError, match=r"png_compression stored, msaa_samples 1, "
                       r"encode_threads 1 would hold \d+ bytes, more than the bound of 1700000000"):
        parksim.FrameRecorder(head_in, out_dir=str(out), width_px=8192, height_px=8192,
                              view="both", png_compression="stored")
    assert not out.exists()
    with pytest.raises(ValueError, match="msaa_samples 4"):
        parksim.FrameRecorder(head_in, out_dir=str(out), width_px=8192, height_px=8192,
                              view="both", msaa_samples=4)
    assert not out.exists()


def test_frames_choose_their_gl_backend(tmp_path, head_in):
    d = parksim.FrameDef()
    assert d.gl_backend == "auto"  # PARKSIM_GL_BACKEND, else egl, then osmesa
    d.gl_backend = "egl"
    assert d.gl_backend == "egl"
    with pytest.raises(parksim.Error, match="unknown OpenGL backend 'vulkan'"):
        d.gl_backend = "vulkan"
    rec = parksim.FrameRecorder(head_in, out_dir=str(tmp_path), width_px=64, height_px=48,
                                gl_backend="egl")
    rec.add_frame(0.0, (0.3, 0.3, 0.0))
    assert rec.finish()["frames"] == 1
    paths = parksim.write_figures(head_in, str(tmp_path / "figures"), figures="lot_map",
                                  width=120, height=80, gl_backend="egl")
    assert [pathlib.Path(p).name for p in paths] == ["lot_map.png"]
    with pytest.raises(parksim.Error, match="unknown OpenGL backend"):
        parksim.write_figures(head_in, str(tmp_path / "never"), gl_backend="gles")
