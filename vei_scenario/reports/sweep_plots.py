"""The sweep report's plots: each metric over the numeric varied parameter, one line per group of the
other parameters, drawn by matplotlib's Agg canvas into base64 PNGs. Imports numpy and the figure
helpers only, so that the plot worker (reports.plot_worker) can load it without the sweep."""

from __future__ import annotations

import base64

import numpy as np

from vei_scenario.reports import overlap
from vei_scenario.reports.figures import agg_figure, png_bytes


def _png(fig) -> str:
    return base64.b64encode(png_bytes(fig, 100)).decode()


def collision_runs(flags: np.ndarray) -> list[tuple[int, int]]:
    """(first, last) index of each run of consecutive True values (the report's collision regions)."""
    return _runs(flags)


def _runs(flags: np.ndarray) -> list[tuple[int, int]]:
    """(first, last) index of each run of consecutive True values."""
    edges = np.diff(np.concatenate(([0], flags.astype(np.int8), [0])))
    return list(zip(np.flatnonzero(edges == 1), np.flatnonzero(edges == -1) - 1))


#: Units of the parameters vei-compiled scenarios declare (labels say what a number means).
UNITS = {"TimeShift": "s", "ConflictTimeShift": "s", "EgoCruiseSpeed": "m/s", "SfmDesiredSpeed": "m/s"}


def param_label(param: str) -> str:
    return f"{param} ({UNITS[param]})" if param in UNITS else param


#: Above this many variants a line, points are not marked one by one (the lines, bands and top-edge
#: segments say the same and the report stays under a second at 100 000 variants).
MARKER_LIMIT = 5000
#: The plots of the report: (metric, axis label).
SERIES = (("safety_index", "safety index"), ("min_ttc_s", "minimum TTC (s)"), ("min_gap_m", "minimum gap (m)"))


def _series_plot(
    grouped: list[tuple[str, np.ndarray, dict, np.ndarray]],
    x_param: str,
    metric: str,
    label: str,
    xlim: tuple[float, float],
) -> tuple[str, int]:
    """The metric over ``x_param``, one line per group; (PNG, variants without a value)."""
    fig, missing = series_figure(grouped, x_param, metric, label, xlim)
    return _png(fig), missing


def series_figure(
    grouped: list[tuple[str, np.ndarray, dict, np.ndarray]],
    x_param: str,
    metric: str,
    label: str,
    xlim: tuple[float, float],
):
    """The metric over ``x_param``, one line per group; (figure, variants without a value). Variants
    with no value (no TTC: never on a collision course) are marked along the top edge, not dropped."""
    ncol = 1 if len(grouped) <= 6 else 2  # (legend entries carry notes: one a line while they fit)
    rows = -(-len(grouped) // ncol)
    height = 4.3 + 0.2 * rows  # the plot keeps its height; the legend below gets a line per row
    fig = agg_figure((11, height))
    ax = fig.add_subplot()
    missing = 0
    many = False
    count = len(grouped)
    # groups with equal values would hide each other: each its own dash, width and open marker (larger
    # for the earlier groups, so that markers on the same point nest), and a legend note
    notes = overlap.coincidence_notes([(name, x, values[metric]) for name, x, values, _ in grouped], partial=True)
    for k, ((name, x, values, coll), note) in enumerate(zip(grouped, notes)):
        y = values[metric]
        marked = x.size <= MARKER_LIMIT
        many |= not marked
        shape = {
            "marker": overlap.MARKERS[k % len(overlap.MARKERS)],
            "mfc": "none",
            "ms": 3 + 4 * (count - 1 - k) / max(count - 1, 1),
        }
        line = ax.plot(x, y, ls=overlap.LINE_STYLES[k % len(overlap.LINE_STYLES)],
                       lw=1.0 + 1.5 * (count - 1 - k) / max(count - 1, 1), label=name + note,
                       **(shape if marked else {}))  # fmt: skip
        colour = line[0].get_color()
        none = np.isnan(y)
        missing += int(none.sum())
        top = ax.get_xaxis_transform()
        if marked:
            ax.plot(x[coll], y[coll], "x", color=colour, ms=6)
            if none.any():  # at the top edge, in axes coordinates
                # (each group a little lower than the one before: the marks of one do not cover another's)
                ax.plot(x[none], np.full(none.sum(), 0.98 - 0.012 * k), "^", color=colour, ms=3, transform=top)
        elif none.any():  # one segment along the top edge per run of variants without a value
            for i, j in _runs(none):
                ax.plot([x[i], x[j]], [0.98, 0.98], color=colour, lw=3, transform=top, solid_capstyle="butt")
        if coll.any():  # shade this group's collision region: one band per run of colliding variants
            step = np.median(np.diff(x)) if x.size > 1 else 0.1
            runs = np.array(_runs(coll))
            left, right = x[runs[:, 0]] - step / 2, x[runs[:, 1]] + step / 2
            # all the bands as one collection (thousands of axvspan patches cost seconds to place)
            ax.broken_barh(list(zip(left, right - left)), (0, 1), transform=top, color="red", alpha=0.04, lw=0)
    ax.set_xlim(*xlim)
    ax.set_xlabel(param_label(x_param))
    ax.set_ylabel(label)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.14), ncol=ncol, frameon=False)  # off the data
    marks = "red band: collision region" if many else "× collision, red band: collision region"
    title = f"{label} over {param_label(x_param)}: {marks}"
    if missing:
        title += f"; {'bar' if many else '▲'} at the top: no value ({missing} variants)"
    ax.set_title(title, fontsize=10)
    fig.subplots_adjust(left=0.07, right=0.98, top=1 - 0.35 / height, bottom=(0.75 + 0.2 * rows) / height)
    return fig, missing


def render_plots(inputs: tuple | None, which: range | None = None) -> list[tuple[str, int]]:
    """The report's plots from :func:`plot_inputs`: (base64 PNG, variants without a value) per series
    (those of ``which``, default all)."""
    if inputs is None:
        return []
    numeric_x, grouped, xlim = inputs
    series = SERIES if which is None else [SERIES[i] for i in which]
    return [_series_plot(grouped, numeric_x, metric, label, xlim) for metric, label in series]
