"""Plots of runs (the seed paper's Figs. 5–8): trajectories on the road map, speed profiles, gap and
TTC over time with the TTC zones shaded. PNG bytes, deterministic (no timestamps in the metadata)."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from vei_scenario.metrics.series import MetricConfig, PairSeries
from vei_scenario.reports import overlap
from vei_scenario.reports.figures import agg_figure, png_bytes
from vei_scenario.roads.opendrive_lanes import lane_areas
from vei_scenario.safe_xml import parse_xml

ZONE_COLOURS = {"safe": "#d9f0d3", "attention": "#fff3b0", "alert": "#f8c9c4", "collision": "#b30000"}
#: One colour per run (configuration); within a run the ego is solid, the threat dashed, others dotted.
RUN_COLOURS = ("tab:blue", "tab:orange", "tab:green", "tab:red", "tab:purple", "tab:brown", "tab:pink")
#: Time marks on the paths: a dot every MARK_S, labelled every LABEL_S (same times on every path).
MARK_S, LABEL_S = 1.0, 4.0


def _figure(figsize: tuple[float, float], rows: int = 1, sharex: bool = False):
    fig = agg_figure(figsize)
    return fig, fig.subplots(rows, 1, sharex=sharex)


def _png(fig) -> bytes:
    return png_bytes(fig, 110)


def _road(ax, road_file: Path | None, bbox) -> None:
    """The lanes within ``bbox`` as one collection of polygons (driving lanes grey, the others sand):
    a map holds hundreds of lane pieces, and one artist draws them many times faster than a patch each."""
    from matplotlib.collections import PolyCollection

    if road_file is None:
        return
    outlines, colours = [], []
    for area in lane_areas(parse_xml(road_file).getroot(), 1.0, bbox):
        for poly in getattr(area.polygon, "geoms", [area.polygon]):
            if poly.geom_type == "Polygon":
                outlines.append(np.asarray(poly.exterior.coords))
                colours.append("#e4e4e4" if area.lane_type == "driving" else "#f2efe6")
    if outlines:
        lanes = PolyCollection(outlines, facecolors=colours, edgecolors="#bbbbbb", linewidths=0.3, zorder=0)
        lanes.set_joinstyle("miter")  # (a patch's corners, as each piece had)
        ax.add_collection(lanes)


def _style(r, name: str) -> tuple[str, float]:
    return ("-", 1.6) if name == r.ego else ("--", 1.4) if name == r.threat else (":", 1.1)


def _colour(k: int, r, name: str, several: bool) -> str:
    if several:  # one colour per run: its ego and threat belong together
        return RUN_COLOURS[k % len(RUN_COLOURS)]
    return "tab:blue" if name == r.ego else ("tab:red" if name == r.threat else "tab:gray")


def _legend(ax, several: bool) -> None:
    if not ax.get_legend_handles_labels()[0]:  # nothing labelled (a run without a second entity)
        return
    if several:  # below the axes, never over the data
        ax.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.1), ncol=2, frameon=False)
    else:
        ax.legend(fontsize=7, loc="best")


def trajectories_png(results: list[tuple[str, object]], road_file: Path | None) -> bytes:
    """Paths of every entity on the road network, with time marks (a dot every second, labelled every
    4 s, on every path: where each was at the same moment) and the first collision of each run."""
    several = len(results) > 1
    fig, ax = _figure((7.5, 8.5 if several else 7.5))
    xs = np.concatenate([tr.x for _, r in results for tr in r.traces.values()])
    ys = np.concatenate([tr.y for _, r in results for tr in r.traces.values()])
    pad = 15.0
    bbox = (xs.min() - pad, ys.min() - pad, xs.max() + pad, ys.max() + pad)
    _road(ax, road_file, bbox)
    any_collision = False
    for k, (label, r) in enumerate(results):
        marks = np.flatnonzero(np.isclose(np.mod(r.t + 1e-9, MARK_S), 0.0, atol=1e-6))
        for name, tr in r.traces.items():
            ls, lw = _style(r, name)
            colour = _colour(k, r, name, several)
            ax.plot(tr.x, tr.y, ls=ls, color=colour, lw=lw, label=f"{label}: {name}" if several else name)
            ax.plot(tr.x[marks], tr.y[marks], "o", color=colour, ms=2.5)
            if k == 0:  # labels once: the runs share the clock
                for i in marks:
                    if abs(r.t[i] / LABEL_S - round(r.t[i] / LABEL_S)) < 1e-6:
                        ax.annotate(f"{r.t[i]:g} s", (tr.x[i], tr.y[i]), fontsize=6, xytext=(3, 3),
                                    textcoords="offset points", color=colour)  # fmt: skip
        for t, a, _b in r.collisions[:1]:
            any_collision = True
            i = int(np.searchsorted(r.t, t))
            ax.plot(r.traces[a].x[i], r.traces[a].y[i], "kx", ms=10, mew=2)
    ax.set_xlim(bbox[0], bbox[2])
    ax.set_ylim(bbox[1], bbox[3])
    ax.set_aspect("equal")
    ax.set_xlabel("x east (m)")
    ax.set_ylabel("y north (m)")
    marks_text = f"dots every {MARK_S:g} s, labels every {LABEL_S:g} s"
    ax.set_title(f"Trajectories ({marks_text}; " + ("× first collision)" if any_collision else "no collision)"))
    _legend(ax, several)
    fig.tight_layout()
    return _png(fig)


def _run_style(k: int, count: int, r, several: bool, base_width: float) -> dict:
    """With several runs, each its own marker (staggered) and width, so that coinciding runs stay
    visible (:mod:`overlap`); a single run keeps its plain line."""
    return overlap.style(k, count, r.t.size, base_width) if several else {"lw": base_width}


def _noted(labels: list[str], series: list[np.ndarray], t: list[np.ndarray]) -> list[str]:
    """Legend labels, each with a note naming the earlier series it lies on."""
    notes = overlap.coincidence_notes([(lab, x, y) for lab, x, y in zip(labels, t, series)])
    return [lab + n for lab, n in zip(labels, notes)]


def speeds_figure(results: list[tuple[str, object]]):
    """Speeds of the ego and its threat, the ego's acceleration, and the ego's controller mode (the
    planner's cruise / brake, or default) over time: what the planner did and when."""
    several = len(results) > 1
    count = len(results)
    fig, (ax, acc, mode) = _figure((10, 11 if several else 7.5) if several else (8, 7.5), rows=3, sharex=True)
    for axis in (ax, acc, mode):
        axis.grid(alpha=0.3)
    labels, series, times, kw = [], [], [], []
    for k, (label, r) in enumerate(results):
        for name in (r.ego, r.threat):
            if name is None:
                continue
            ls, lw = _style(r, name)
            labels.append(f"{label}: {name}" if several else name)
            series.append(r.traces[name].speed)
            times.append(r.t)
            kw.append({"ls": ls, "color": _colour(k, r, name, several), **_run_style(k, count, r, several, lw)})
    for lab, y, t, style in zip(_noted(labels, series, times) if several else labels, series, times, kw):
        ax.plot(t, y, label=lab, **style)
    ax.set_ylabel("speed (m/s)")
    ax.set_title(
        "Speed profiles" + (" (one colour and marker per configuration; ego solid, threat dashed)" if several else "")
    )
    # the ego's acceleration (the threat's, differentiated from a replayed track, spikes at its start)
    accel = [r.traces[r.ego].accel for _, r in results]
    for k, ((_, r), a) in enumerate(zip(results, accel)):
        acc.plot(r.t, a, color=_colour(k, r, r.ego, several), **_run_style(k, count, r, several, 1.4))
    acc.axhline(0.0, color="#888888", lw=0.6)
    acc.set_ylabel("acceleration (m/s²)")
    title = "Ego acceleration"
    if several:  # which runs draw over each other here (their legend entries are the speeds')
        names = [label for label, _ in results]
        notes = overlap.coincidence_notes([(n, r.t, a) for n, (_, r), a in zip(names, results, accel)])
        same = [f"{n}{note}" for n, note in zip(names, notes) if note]
        title += ("\n" + "; ".join(same)) if same else ""
    acc.set_title(title, fontsize=9)
    # the ego's controller mode, one level per state (in order of first appearance), runs offset
    states = list(dict.fromkeys(s for _, r in results for s in r.traces[r.ego].status))
    level = {s: i for i, s in enumerate(states)}
    spread = 0.3 / max(count - 1, 1) if several else 0.0
    for k, (_, r) in enumerate(results):
        y = np.array([level[s] for s in r.traces[r.ego].status], float) + (k * spread - 0.15 if several else 0.0)
        mode.plot(r.t, y, drawstyle="steps-post", color=_colour(k, r, r.ego, several),
                  **_run_style(k, count, r, several, 1.6))  # fmt: skip
    mode.set_yticks(range(len(states)), states, fontsize=8)
    mode.set_ylim(-0.6, len(states) - 0.4)
    mode.set_ylabel("ego controller")
    mode.set_xlabel("time (s)")
    mode.set_title("Ego controller mode (the planner's cruise / brake; default: no controller assigned)"
                   + ("; configurations offset" if several else ""), fontsize=9)  # fmt: skip
    if several:  # the series once, under the figure, never over the data
        handles, names = ax.get_legend_handles_labels()
        rows = (len(names) + 1) // 2
        fig.legend(handles, names, fontsize=7, loc="lower center", ncol=2, frameon=False)
        fig.tight_layout(rect=(0, 0.01 + 0.016 * rows, 1, 1))
    else:
        _legend(ax, several)
        fig.tight_layout()
    return fig


def speeds_png(results: list[tuple[str, object]]) -> bytes:
    return _png(speeds_figure(results))


def gap_ttc_png(results: list[tuple[str, object]], cfg: MetricConfig) -> bytes:
    return _png(gap_ttc_figure(results, cfg))


def gap_ttc_figure(results: list[tuple[str, object]], cfg: MetricConfig):
    """Gap between the boxes and TTC over time. The background bands are the TTC zones; the solid line
    is the TTC the zones and the safety index use (``cfg.zone_ttc``), and a strip per run above the
    curves shows the zone of every step exactly as the metrics count it. The other TTC is dotted."""
    from matplotlib.lines import Line2D

    several = len(results) > 1
    fig, (ax1, ax2) = _figure((9, 8 if several else 6.5), rows=2, sharex=True)
    used = "headway TTC ≈ gap/v in the ego's path" if cfg.zone_ttc == "approx" else "2-D TTC"
    other = "2-D TTC" if cfg.zone_ttc == "approx" else "headway TTC"
    top = 8.0
    ax2.axhspan(cfg.safe_ttc_s, top, color=ZONE_COLOURS["safe"], zorder=0)
    ax2.axhspan(cfg.alert_ttc_s, cfg.safe_ttc_s, color=ZONE_COLOURS["attention"], zorder=0)
    ax2.axhspan(0, cfg.alert_ttc_s, color=ZONE_COLOURS["alert"], zorder=0)
    runs = [(k, label, r) for k, (label, r) in enumerate(results) if r.threat is not None]
    strip = 0.6  # height (on the TTC axis) of each run's zone strip, above the zone bands
    pairs = [PairSeries.from_run(r) for _, _, r in runs]
    labels = [label if several else r.threat for _, label, r in runs]
    if several:  # a run whose gap lies on another's says so (it is drawn, but may not be seen)
        labels = _noted(labels, [p.gap for p in pairs], [r.t for _, _, r in runs])
    for n, ((k, _, r), pair) in enumerate(zip(runs, pairs)):
        colour = RUN_COLOURS[k % len(RUN_COLOURS)] if several else "tab:blue"
        style = _run_style(n, len(runs), r, several, 1.3)
        ax1.plot(r.t, pair.gap, color=colour, label=labels[n], **style)
        zone_ttc = pair.zone_ttc(cfg)
        other_ttc = pair.ttc_2d if cfg.zone_ttc == "approx" else pair.ttc_approx
        # below the strips only, with a dot on every step (a TTC defined for single steps shows too)
        ttc_style = {**style, "lw": style["lw"] + 0.3} if several else {"lw": 1.6, "marker": ".", "ms": 1.5}
        ax2.plot(r.t, np.where(zone_ttc <= top, zone_ttc, np.nan), color=colour, **ttc_style)
        ax2.plot(r.t, np.where(other_ttc <= top, other_ttc, np.nan), lw=1.0, ls=":", color=colour)
        zones = pair.zones(cfg)
        base = top + n * strip
        for z, zname in enumerate(("safe", "attention", "alert", "collision")):
            on = zones == z
            if on.any():
                ax2.fill_between(r.t, base + 0.1 * strip, base + 0.9 * strip, where=on, color=ZONE_COLOURS[zname],
                                 lw=0, step="mid")  # fmt: skip
        if several:  # whose strip this is: the run's colour and marker at its left end
            ax2.plot([r.t[0]], [base + 0.5 * strip], style["marker"], color=colour, ms=5)
    ax2.set_ylim(0, top + max(1, len(runs)) * strip)
    ax2.set_yticks([t for t in ax2.get_yticks() if t <= top])
    ax1.set_ylabel("gap between boxes (m)")
    ax2.set_ylabel("TTC (s)")
    ax2.set_xlabel("time (s)")
    ax1.set_title("Gap between the boxes", fontsize=10)
    ax2.set_title(
        f"TTC; zones (safe ≥ {cfg.safe_ttc_s:g} s, attention, alert < {cfg.alert_ttc_s:g} s) on the {used}."
        "\nStrip above: each step's zone as the safety index counts it (dark red: contact)"
        + ("; one strip per configuration, its marker at the left" if several else ""),
        fontsize=9,
    )
    for ax in (ax1, ax2):
        ax.grid(alpha=0.3)
    styles = [
        Line2D([], [], color="k", lw=1.6, label=f"{used} (zones)"),
        Line2D([], [], color="k", lw=1.0, ls=":", label=f"{other} (not used for zones)"),
    ]
    ax2.legend(handles=styles, fontsize=7, loc="lower right")
    if several:  # the runs, once, under the figure
        fig.legend(*ax1.get_legend_handles_labels(), fontsize=8, loc="lower center", ncol=3, frameon=False)
        fig.tight_layout(rect=(0, 0.07, 1, 1))
    else:
        if ax1.get_legend_handles_labels()[0]:
            ax1.legend(fontsize=7)
        fig.tight_layout()
    return fig
