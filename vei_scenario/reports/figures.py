"""Figures drawn by matplotlib's Agg canvas without pyplot: no global state, no GUI backend imported,
and PNG bytes without timestamps (the same figure gives the same bytes)."""

from __future__ import annotations

import io


def agg_figure(figsize: tuple[float, float], dpi: float | None = None):
    """A Figure with an Agg canvas attached (``fig.canvas.draw()`` and ``savefig`` work)."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=figsize, dpi=dpi)
    FigureCanvasAgg(fig)
    return fig


def png_bytes(fig, dpi: float) -> bytes:
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=dpi, metadata={"Software": None})
    return buf.getvalue()
