"""Plots of runs (the seed paper's Figs. 5–8): trajectories on the road map, speed profiles, gap and
TTC over time with the TTC zones shaded. PNG bytes, deterministic (no timestamps in the metadata)."""

from __future__ import annotations

import io
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from vei_scenario.metrics.series import MetricConfig, PairSeries  # noqa: E402
from vei_scenario.roads.opendrive_lanes import lane_areas  # noqa: E402
from vei_scenario.safe_xml import parse_xml  # noqa: E402

ZONE_COLOURS = {"safe": "#d9f0d3", "attention": "#fff3b0", "alert": "#f8c9c4"}


def _png(fig) -> bytes:
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=110, metadata={"Software": None})
    plt.close(fig)
    return buf.getvalue()


def _road(ax, road_file: Path | None, bbox) -> None:
    if road_file is None:
        return
    for area in lane_areas(parse_xml(road_file).getroot(), 1.0, bbox):
        polys = getattr(area.polygon, "geoms", [area.polygon])
        for poly in polys:
            if poly.geom_type != "Polygon":
                continue
            x, y = poly.exterior.xy
            ax.fill(x, y, color="#e4e4e4" if area.lane_type == "driving" else "#f2efe6", lw=0.3, ec="#bbbbbb", zorder=0)


def trajectories_png(results: list[tuple[str, object]], road_file: Path | None) -> bytes:
    """Paths of every entity on the road network; one style per run (label, RunResult)."""
    fig, ax = plt.subplots(figsize=(7.5, 7.5))
    xs = np.concatenate([tr.x for _, r in results for tr in r.traces.values()])
    ys = np.concatenate([tr.y for _, r in results for tr in r.traces.values()])
    pad = 15.0
    bbox = (xs.min() - pad, ys.min() - pad, xs.max() + pad, ys.max() + pad)
    _road(ax, road_file, bbox)
    styles = ["-", "--", ":", "-.", (0, (5, 1))]
    for k, (label, r) in enumerate(results):
        for name, tr in r.traces.items():
            colour = "tab:blue" if name == r.ego else ("tab:red" if name == r.threat else "tab:gray")
            ax.plot(
                tr.x,
                tr.y,
                ls=styles[k % len(styles)],
                color=colour,
                lw=1.4,
                label=f"{label}: {name}" if len(results) > 1 else name,
            )
        for t, a, _b in r.collisions[:1]:
            i = int(np.searchsorted(r.t, t))
            ax.plot(r.traces[a].x[i], r.traces[a].y[i], "kx", ms=10, mew=2)
    ax.set_xlim(bbox[0], bbox[2])
    ax.set_ylim(bbox[1], bbox[3])
    ax.set_aspect("equal")
    ax.set_xlabel("x east (m)")
    ax.set_ylabel("y north (m)")
    ax.set_title("Trajectories (× first collision)")
    ax.legend(fontsize=7, loc="best")
    return _png(fig)


def speeds_png(results: list[tuple[str, object]]) -> bytes:
    fig, ax = plt.subplots(figsize=(8, 4))
    for label, r in results:
        for name in (r.ego, r.threat):
            if name is None:
                continue
            tr = r.traces[name]
            ax.plot(r.t, tr.speed, lw=1.3, label=f"{label}: {name}" if len(results) > 1 else name)
    ax.set_xlabel("time (s)")
    ax.set_ylabel("speed (m/s)")
    ax.set_title("Speed profiles")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    return _png(fig)


def gap_ttc_png(results: list[tuple[str, object]], cfg: MetricConfig) -> bytes:
    """Gap between the boxes and TTC over time, TTC zones shaded (safe ≥ 3 s, attention 2–3 s, alert)."""
    fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(8, 6), sharex=True)
    for label, r in results:
        if r.threat is None:
            continue
        pair = PairSeries.from_run(r)
        name = label if len(results) > 1 else r.threat
        ax1.plot(r.t, pair.gap, lw=1.3, label=name)
        ttc = pair.zone_ttc(cfg)
        line = ax2.plot(r.t, np.where(np.isfinite(ttc), ttc, np.nan), lw=1.6, label=f"{name}: TTC {cfg.zone_ttc}")
        ttc2 = pair.ttc_2d
        ax2.plot(
            r.t,
            np.where(np.isfinite(ttc2), ttc2, np.nan),
            lw=1.0,
            ls=":",
            color=line[0].get_color(),
            label=f"{name}: TTC 2-D",
        )
    top = 8.0
    ax2.axhspan(cfg.safe_ttc_s, top, color=ZONE_COLOURS["safe"], zorder=0)
    ax2.axhspan(cfg.alert_ttc_s, cfg.safe_ttc_s, color=ZONE_COLOURS["attention"], zorder=0)
    ax2.axhspan(0, cfg.alert_ttc_s, color=ZONE_COLOURS["alert"], zorder=0)
    ax2.set_ylim(0, top)
    ax1.set_ylabel("gap between boxes (m)")
    ax2.set_ylabel("TTC (s)")
    ax2.set_xlabel("time (s)")
    ax1.set_title("Gap and TTC (zones on the headway TTC ≈ gap/v: safe ≥ 3 s, attention 2–3 s, alert < 2 s)")
    for ax in (ax1, ax2):
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
    return _png(fig)
