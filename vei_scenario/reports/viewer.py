"""``vei view``: a run played back on its road: the boxes moving with time, their trails, the threat
coloured by its TTC zone (as the safety index counts it), the collision marked.

Written as an animated GIF (Pillow, which matplotlib brings) or MP4 (needs ffmpeg), or shown in a
window when there is a display. Frames are rendered by Agg without pyplot, so the same run gives the
same frames (and the same GIF bytes) on any machine; the tests render them headless.
"""

from __future__ import annotations

import csv
import json
import math
import shutil
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from vei_scenario.errors import VeiInputError
from vei_scenario.models.boxes import box_corners

ZONE_FACE = {0: "#4daf4a", 1: "#ffd92f", 2: "#e41a1c", 3: "#7f0000"}  # safe, attention, alert, collision
ZONE_NAMES = ("safe", "attention", "alert", "COLLISION")
TRAIL_S = 3.0  # seconds of trail behind each road user
VIEW_M = 50.0  # the least width of the view (m) around the ego and its threat


@dataclass
class View:
    """What is drawn: the run (a RunResult, or one read back from a run directory) and its zones."""

    run: object  # interpreter.engine.RunResult
    zones: np.ndarray | None  # per step: 0 safe .. 3 collision, for the ego and its threat
    ttc: np.ndarray | None  # the TTC the zones use, per step


def _zones(run) -> tuple[np.ndarray | None, np.ndarray | None]:
    if run.threat is None:
        return None, None
    from vei_scenario.metrics.series import MetricConfig, PairSeries

    cfg = MetricConfig()
    pair = PairSeries.from_run(run)
    return pair.zones(cfg), pair.zone_ttc(cfg)


def view_scenario(
    path: str | Path, parameters: dict[str, str] | None = None, dt: float = 0.01, controllers: tuple = ()
) -> View:
    """Run ``path`` with the built-in interpreter (``controllers``: the systems under test) and view the run."""
    from vei_scenario.interpreter import run_scenario

    run = run_scenario(path, parameters, dt, controllers=controllers)
    return View(run, *_zones(run))


#: The numeric columns of trajectories.csv the viewer reads.
COLUMNS = ("time_s", "x_m", "y_m", "heading_rad", "speed_mps", "acceleration_mps2")


def view_run_dir(run_dir: str | Path, scenario: str | Path | None = None) -> View:
    """View what ``vei run -o RUN_DIR`` wrote (trajectories.csv, metrics.json). Boxes and the road come
    from ``scenario`` when given (else from metrics.json's entities, without a road)."""
    from vei_scenario.interpreter.engine import EntityTrace, RunResult

    run_dir = Path(run_dir)
    csv_path, doc_path = run_dir / "trajectories.csv", run_dir / "metrics.json"
    for p in (csv_path, doc_path):
        if not p.is_file():
            raise VeiInputError(run_dir, p.name, "not found: give a run directory written by vei run -o")
    try:
        doc = json.loads(doc_path.read_text("utf-8"))
    except json.JSONDecodeError as exc:
        raise VeiInputError(doc_path, f"line {exc.lineno}", f"not JSON: {exc.msg}") from None
    rows: dict[str, list[list[float]]] = {}
    states: dict[str, list[str]] = {}
    with csv_path.open(newline="", encoding="utf-8") as fh:
        reader = csv.DictReader(fh)
        for line, r in enumerate(reader, start=2):
            try:  # (column names with units since 0.2; without them before)
                values = [float(r[k] if k in r else r[k.rsplit("_", 1)[0]]) for k in COLUMNS]
            except (KeyError, TypeError, ValueError):
                raise VeiInputError(
                    csv_path, f"line {line}", "expected time_s,entity,x_m,y_m,heading_rad,speed_mps,..."
                ) from None
            if not all(math.isfinite(v) for v in values):
                raise VeiInputError(csv_path, f"line {line}", "a value is not a finite number")
            rows.setdefault(r["entity"], []).append(values)
            states.setdefault(r["entity"], []).append(r.get("controller_state", ""))
    if not rows:
        raise VeiInputError(csv_path, "line 2", "no trajectory rows")
    boxes = {n: (e["category"], e["length_m"], e["width_m"], e["center_x_m"]) for n, e in doc["entities"].items()}
    from vei_scenario.interpreter.document import parameter_text

    # (metrics.json keeps the declared types: a run takes them back as OpenSCENARIO text)
    texts = {k: parameter_text(v) for k, v in (doc.get("parameters") or {}).items()}
    road_file = None
    if scenario is not None:
        from vei_scenario.interpreter import load_scenario

        road_file = load_scenario(scenario, texts).road_file
    traces = {}
    t = None
    for name, vals in rows.items():
        a = np.array(vals)
        t = a[:, 0] if t is None else t
        if a.shape[0] != t.size:
            raise VeiInputError(csv_path, name, "entities have different numbers of rows")
        cat, length, width, cx = boxes.get(name, ("vehicle", 4.5, 1.8, 0.0))
        traces[name] = EntityTrace(name, cat, length, width, t, *(a[:, k] for k in range(1, 6)), states[name], cx)
    collisions = [(c["time_s"], *c["entities"]) for c in doc.get("collisions", [])]
    run = RunResult(
        str(doc.get("scenario", run_dir)),
        float(doc.get("dt_s", np.median(np.diff(t)) if t.size > 1 else 0.01)),
        t,
        traces,
        collisions,
        texts,
        doc.get("ego") or next(iter(traces)),
        doc.get("threat"),
        doc.get("end_reason", ""),
        road_file,
    )
    return View(run, *_zones(run))


def frame_steps(view: View, fps: float, speed: float = 1.0) -> np.ndarray:
    """Indices of the run's steps shown as frames: ``fps`` frames per second of film, the run played
    ``speed`` times as fast as real time; the last step is always shown."""
    if fps <= 0 or speed <= 0:
        raise VeiInputError(None, "--fps/--speed", "must be positive")
    t = view.run.t
    wanted = np.arange(t[0], t[-1] + 1e-9, speed / fps)
    steps = np.unique(np.clip(np.searchsorted(t, wanted - 1e-9), 0, t.size - 1))
    return np.unique(np.append(steps, t.size - 1))


def _corners(x: float, y: float, yaw: float, length: float, width: float, cx: float) -> np.ndarray:
    """The box's corners: its centre lies ``cx`` ahead of the logged reference point (x, y)."""
    return box_corners(x + cx * math.cos(yaw), y + cx * math.sin(yaw), yaw, length, width)


def render_frames(view: View, steps: np.ndarray, size_px: int = 640) -> Iterator[np.ndarray]:
    """RGB frames (H, W, 3 uint8) of the given steps."""
    from matplotlib.patches import Polygon

    from vei_scenario.reports.figures import agg_figure
    from vei_scenario.reports.run_plots import _road

    run = view.run
    dpi = 100
    fig = agg_figure((size_px / dpi, size_px / dpi), dpi)
    canvas = fig.canvas
    ax = fig.add_axes((0.08, 0.07, 0.9, 0.86))
    xs = np.concatenate([tr.x for tr in run.traces.values()])
    ys = np.concatenate([tr.y for tr in run.traces.values()])
    pad = 10.0
    bbox = (xs.min() - pad, ys.min() - pad, xs.max() + pad, ys.max() + pad)
    _road(ax, run.road_file, bbox)
    ax.set_aspect("equal", adjustable="box")
    ax.set_xlabel("x east (m)", fontsize=8)
    ax.set_ylabel("y north (m)", fontsize=8)
    ax.tick_params(labelsize=7)
    colours = {n: ("tab:blue" if n == run.ego else "tab:gray") for n in run.traces}
    artists = {}
    for name in run.traces:
        (trail,) = ax.plot([], [], color=colours[name], lw=1.2, alpha=0.7)
        box = Polygon(np.zeros((4, 2)), closed=True, fc=colours[name], ec="k", lw=0.6, zorder=5)
        ax.add_patch(box)
        label = ax.text(0, 0, name, fontsize=7, zorder=6)
        artists[name] = (trail, box, label)
    status = ax.text(0.01, 0.99, "", transform=ax.transAxes, va="top", fontsize=8, family="monospace", zorder=7)
    (hit,) = ax.plot([], [], "x", color="k", ms=9, mew=2, alpha=0.6, zorder=8)
    focus = [n for n in (run.ego, run.threat) if n is not None]
    first = min(run.collisions, default=None)  # the first contact between any two
    trail_steps = max(1, int(round(TRAIL_S / run.dt)))
    for k in steps:
        for name, tr in run.traces.items():
            trail, box, label = artists[name]
            lo = max(0, k - trail_steps)
            trail.set_data(tr.x[lo : k + 1], tr.y[lo : k + 1])
            box.set_xy(_corners(tr.x[k], tr.y[k], tr.yaw[k], tr.length, tr.width, tr.center_x))
            if name == run.threat and view.zones is not None:
                box.set_facecolor(ZONE_FACE[int(view.zones[k])])
            label.set_position((tr.x[k] + 1.5, tr.y[k] + 1.5))
        text = f"t = {run.t[k]:6.2f} s"
        if view.zones is not None:
            ttc = view.ttc[k]
            ttc_text = f"{ttc:5.2f} s" if math.isfinite(ttc) else "  none"
            text += f"\nTTC {ttc_text}  zone {ZONE_NAMES[int(view.zones[k])]}"
        status.set_text(text)
        if first is not None and run.t[k] >= first[0] - 1e-9:
            i = int(np.searchsorted(run.t, first[0] - 1e-9))
            a = run.traces[first[1]]
            hit.set_data([a.x[i]], [a.y[i]])
        else:
            hit.set_data([], [])
        # the camera frames the ego and its threat (at least VIEW_M across), so their boxes are visible
        fx = [run.traces[n].x[k] for n in focus]
        fy = [run.traces[n].y[k] for n in focus]
        half = max(0.5 * VIEW_M, 0.5 * max(np.ptp(fx), np.ptp(fy)) + 10.0)
        cx, cy = float(np.mean(fx)), float(np.mean(fy))
        ax.set_xlim(cx - half, cx + half)
        ax.set_ylim(cy - half, cy + half)
        ax.set_title(f"{Path(run.scenario).name}: ego blue, {run.threat or 'others'} coloured by TTC zone", fontsize=9)
        canvas.draw()
        yield np.asarray(canvas.buffer_rgba())[:, :, :3].copy()


def _with_bar(render):
    """``render`` (view, steps, size) whose frames tick a terminal bar as they are drawn."""

    def frames(view, steps, size_px):
        from vei_scenario.reports.run_progress import terminal_bar

        bar = terminal_bar(len(steps), "frame", "drawing")
        try:
            for f in render(view, steps, size_px):
                yield f
                if bar is not None:
                    bar.update(1)
        finally:
            if bar is not None:
                bar.close()

    return frames


def write_animation(
    view: View, out: str | Path, fps: float = 10.0, speed: float = 1.0, size_px: int = 640, progress: bool = False
) -> Path:
    """An animated GIF (``.gif``) or MP4 (``.mp4``, needs ffmpeg) of the run, written atomically. With
    ``progress``, the frames drawn show as a bar where stderr is a terminal (a film takes seconds)."""
    from vei_scenario.atomic_io import write_bytes_atomic

    out = Path(out)
    steps = frame_steps(view, fps, speed)
    draw = _with_bar(render_frames) if progress else render_frames
    suffix = out.suffix.lower()
    if suffix == ".gif":
        import io

        from matplotlib.colors import to_rgb
        from PIL import Image

        rgb = list(draw(view, steps, size_px))
        # one palette for the film, from two frames and swatches of the colours that must survive (a box
        # of a few pixels would otherwise lose its zone colour to the road's greys)
        keys = [*ZONE_FACE.values(), "tab:blue", "tab:gray", "black", "white"]
        swatch = np.repeat(np.array([[np.round(np.array(to_rgb(c)) * 255) for c in keys]], np.uint8), 64, axis=0)
        sample = np.concatenate([rgb[0][:64], rgb[len(rgb) // 2][:64], np.repeat(swatch, size_px // len(keys) + 1,
                                 axis=1)[:, :size_px]], axis=0)  # fmt: skip
        palette = Image.fromarray(sample).quantize(colors=255, method=Image.Quantize.MEDIANCUT)
        frames = [Image.fromarray(f).quantize(palette=palette, dither=Image.Dither.NONE) for f in rgb]
        buf = io.BytesIO()
        frames[0].save(buf, format="GIF", save_all=True, append_images=frames[1:], duration=int(1000 / fps), loop=0)
        write_bytes_atomic(out, buf.getvalue())
        return out
    if suffix == ".mp4":
        ffmpeg = shutil.which("ffmpeg")
        if ffmpeg is None:
            raise VeiInputError(out, "-o", "MP4 needs ffmpeg on PATH; write a .gif instead")
        import subprocess
        import tempfile

        frames = list(draw(view, steps, size_px))
        h, w = frames[0].shape[:2]
        with tempfile.TemporaryDirectory(dir=out.parent if out.parent.exists() else None) as tmp:
            part = Path(tmp) / "view.mp4"
            cmd = [ffmpeg, "-loglevel", "error", "-y", "-f", "rawvideo", "-pix_fmt", "rgb24", "-s", f"{w}x{h}"]
            cmd += [
                "-r",
                repr(fps),
                "-i",
                "-",
                "-pix_fmt",
                "yuv420p",
                "-vf",
                "pad=ceil(iw/2)*2:ceil(ih/2)*2",
                str(part),
            ]
            subprocess.run(cmd, input=b"".join(f.tobytes() for f in frames), check=True)
            write_bytes_atomic(out, part.read_bytes())
        return out
    raise VeiInputError(out, "-o", "write a .gif or .mp4")


def show(view: View, fps: float = 10.0, speed: float = 1.0) -> None:
    """Play the run in a window (needs a display)."""
    import os

    if not (os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY")) and os.name != "nt":
        raise VeiInputError(None, "vei view", "no display here: write the animation with -o view.gif")
    import matplotlib.pyplot as plt
    from matplotlib.animation import FuncAnimation

    steps = frame_steps(view, fps, speed)
    frames = render_frames(view, steps)
    fig, ax = plt.subplots(figsize=(7, 7))
    ax.axis("off")
    image = ax.imshow(next(frames))

    def update(_):
        image.set_data(next(frames, image.get_array()))
        return (image,)

    fig.animation = FuncAnimation(fig, update, frames=len(steps) - 1, interval=1000 / fps, repeat=False)
    plt.show()
