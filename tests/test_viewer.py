"""`vei view`: frames rendered headless, checked by their pixels; the GIF; a run directory read back."""

from __future__ import annotations

import numpy as np
import pytest
from matplotlib.colors import to_rgb

from vei_scenario.reports import viewer
from vei_scenario.reports.viewer import ZONE_FACE, frame_steps, render_frames, view_run_dir, view_scenario


def _has(frame: np.ndarray, colour: str, at_least: int = 10) -> bool:
    rgb = np.round(np.array(to_rgb(colour)) * 255).astype(int)
    return int(np.all(np.abs(frame.astype(int) - rgb) <= 2, axis=-1).sum()) >= at_least


@pytest.fixture(scope="module")
def collision_view(compiled):
    from vei_scenario.interpreter import load_scenario

    xosc = compiled["case_study"].written[0]
    shift = load_scenario(xosc).parameters["ConflictTimeShift"]
    return xosc, {"TimeShift": shift, "RiderType": "replay", "CapEnabled": "false"}


def test_the_threat_is_drawn_in_its_zone_colour_and_the_collision_shows(collision_view):
    xosc, params = collision_view
    view = view_scenario(xosc, params)
    run = view.run
    t_hit = run.collisions[0][0]
    hit = int(np.searchsorted(run.t, t_hit - 1e-9))
    safe = int(np.flatnonzero(view.zones[:hit] == 0)[-1])  # the last safe moment before the contact
    before, during = render_frames(view, np.array([safe, hit]))
    assert view.zones[hit] == 3
    assert _has(before, ZONE_FACE[0]) and not _has(before, ZONE_FACE[3])
    assert _has(during, ZONE_FACE[3]) and not _has(during, ZONE_FACE[0])
    assert _has(before, "tab:blue") and _has(during, "tab:blue")  # the ego


def test_frames_follow_the_clock_and_the_gif_is_reproducible(collision_view, tmp_path):
    from PIL import Image

    xosc, params = collision_view
    view = view_scenario(xosc, params)
    t = view.run.t
    for fps, speed in ((10, 1), (10, 2)):
        shown = t[frame_steps(view, fps, speed)]
        assert np.allclose(np.diff(shown[:-1]), speed / fps) and shown[-1] == t[-1]
    steps = frame_steps(view, 2, 1)
    assert view.run.t[steps][1] == pytest.approx(0.5) and steps[-1] == view.run.t.size - 1
    a = viewer.write_animation(view, tmp_path / "a.gif", fps=2, size_px=320)
    b = viewer.write_animation(view, tmp_path / "b.gif", fps=2, size_px=320)
    assert a.read_bytes() == b.read_bytes()
    with Image.open(a) as im:
        assert im.n_frames == steps.size and im.size == (320, 320)


def test_a_run_directory_plays_like_its_scenario(collision_view, tmp_path):
    from vei_scenario.runner import run_to

    xosc, params = collision_view
    run_to(xosc, tmp_path / "run", params, 0.01, plots=False)
    from_dir = view_run_dir(tmp_path / "run", xosc)
    direct = view_scenario(xosc, params)
    assert np.array_equal(from_dir.zones, direct.zones)
    k = np.array([int(np.searchsorted(direct.run.t, direct.run.collisions[0][0] - 1e-9))])
    f1, f2 = next(render_frames(from_dir, k)), next(render_frames(direct, k))
    assert np.mean(np.all(f1 == f2, axis=-1)) > 0.99  # (the CSV keeps 0.1 mm: a few edge pixels move)


def test_view_refuses_what_it_cannot_do_in_one_line(collision_view, tmp_path, monkeypatch, capsys):
    from vei_scenario.cli import main

    xosc, params = collision_view
    monkeypatch.setattr(viewer.shutil, "which", lambda name: None)
    assert main(["view", str(xosc), "-o", str(tmp_path / "v.mp4"), "--fps", "1"]) == 2
    assert "MP4 needs ffmpeg" in capsys.readouterr().err
    monkeypatch.delenv("DISPLAY", raising=False)
    monkeypatch.delenv("WAYLAND_DISPLAY", raising=False)
    assert main(["view", str(xosc)]) == 2
    assert "no display here" in capsys.readouterr().err
    assert main(["view", str(tmp_path / "missing")]) == 2
    assert not (tmp_path / "v.mp4").exists()
