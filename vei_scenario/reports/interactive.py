"""Interactive plots of a sweep for report.html (Plotly): zoom, pan, and hover that names the variant and
its parameters, so a reader can go from a point to the command that reproduces it.

Why Plotly: a well-kept library whose HTML output is self-contained (the library is embedded once, no
network when the report is opened) and deterministic (fixed element ids; the data are the catalog's
values). WebGL scatter traces keep 100 000 variants interactive and the page is written in a fraction
of a second. The static PNG plots stay above these for print and quick reading.
"""

from __future__ import annotations

import base64

import numpy as np

from vei_scenario.reports.sweep_plots import SERIES, param_label


def _typed(a: np.ndarray, dtype: str) -> dict:
    """A numeric array as plotly.js's typed-array JSON (``f8``, ``f4`` or ``i4`` and base64 bytes),
    written in a fraction of the time of a list of decimal numbers."""
    data = np.ascontiguousarray(a, "<" + dtype).tobytes()
    return {"dtype": dtype, "bdata": base64.b64encode(data).decode()}


def interactive_html(inputs: tuple | None) -> str:
    """The report's interactive section from :func:`~vei_scenario.sweep.report_html.plot_inputs`
    (x parameter, groups, limits): one figure per plotted metric, one trace per group of the other
    varied parameters, collisions as crosses. '' without a numeric x."""
    if inputs is None:
        return ""
    import plotly.io as pio

    x_param, grouped, xlim = inputs
    parts = ["<h2>Interactive plots</h2><p class='note'>Zoom with the mouse, double-click to reset; hovering a "
             "point shows its variant number and parameters (the catalog's row and the values to reproduce it). "
             "Crosses are collisions.</p>"]  # fmt: skip
    for n, (metric, label) in enumerate(SERIES):
        traces = []
        for k, (name, x, values, hit) in enumerate(grouped):
            y, number = values[metric], values["variant"]
            fixed = "".join(f"<br>{part}" for part in name.split(", ")) if name != "all" else ""
            hover = f"variant %{{customdata}}<br>{x_param} %{{x}}{fixed}<br>{label} %{{y}}<extra></extra>"
            colour = PALETTE[k % len(PALETTE)]
            # groups with equal values must not hide each other: own symbol (open, larger for the earlier
            # groups, so markers on one point nest), own dash, wider lines below (as the PNG plots)
            below = (len(grouped) - 1 - k) / max(len(grouped) - 1, 1)
            marker = {"size": 4 + 5 * below, "color": colour, "symbol": SYMBOLS[k % len(SYMBOLS)]}
            line = {"width": 1 + 1.5 * below, "color": colour, "dash": DASHES[k % len(DASHES)]}
            traces.append({"type": "scattergl", "x": _typed(x, "f8"), "y": _typed(y, "f4"),
                           "mode": "lines+markers", "name": name, "customdata": _typed(number, "i4"),
                           "hovertemplate": hover, "legendgroup": name, "marker": marker, "line": line})  # fmt: skip
            if hit.any():
                traces.append({"type": "scattergl", "x": _typed(x[hit], "f8"), "y": _typed(y[hit], "f4"),
                               "mode": "markers", "name": name, "customdata": _typed(number[hit], "i4"),
                               "legendgroup": name,
                               "hovertemplate": hover.replace("<extra>", " (collision)<extra>"), "showlegend": False,
                               "marker": {"size": 7, "symbol": "x", "color": colour}})  # fmt: skip
        layout = {
            "title": {"text": label}, "height": 420, "plot_bgcolor": "white",
            "xaxis": {"title": {"text": param_label(x_param)}, "range": list(xlim), "gridcolor": "#e5e5e5"},
            "yaxis": {"title": {"text": label}, "gridcolor": "#e5e5e5"},
            "margin": {"l": 60, "r": 20, "t": 50, "b": 50}, "legend": {"orientation": "h", "y": -0.2},
        }  # fmt: skip
        # a plain figure dict, not validated trace by trace (100 000 points in a fraction of a second)
        parts.append(pio.to_html({"data": traces, "layout": layout}, full_html=False, include_plotlyjs=(n == 0),
                                 div_id=f"vei-plot-{metric}", validate=False))  # fmt: skip
    return "".join(parts)


#: Marker symbols and line dashes per group, in drawing order (as reports.overlap for the PNG plots).
SYMBOLS = ("circle-open", "square-open", "triangle-up-open", "diamond-open", "triangle-down-open", "star-open")
DASHES = ("solid", "dash", "dashdot", "dot", "longdash", "longdashdot")
#: Trace colours (matplotlib's default cycle, as in the PNG plots).
PALETTE = ("#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22",
           "#17becf")  # fmt: skip
