"""The compiled core: the per-step numerics that every engine shares, in C, built with the package.

What is here (``src/``): one OpenDRIVE road's geometry — reference-line poses of every geometry kind,
lane offsets and widths, lane borders and centres, the heading of a lane, the world point of road
coordinates and the projection of a world point onto a road (``road.c``, exposed as
:class:`_core.Road`). Every question a lane-keeping entity asks of its road each step is one C call;
``vei_scenario.roads.road_model`` parses the file (vei's hardened XML reader) and hands each road's
records over once.
The models and agents (``vei_models.c``: polyline, boxes, social force rider, planner, vehicle; the
rider and ego agents of the closed loop) serve the interpreter through this module, and the sweep kernel
(``vei_batch.c``, in the same shared object, called through ctypes: :mod:`vei_scenario.core.kernel`;
its scoring also scores every ``vei run``) and the
FMUs (compiled into each FMU's binary) run the same sources.

What stays in Python, and why: parsing and checking (error messages naming the line), the road
network's topology (links, junctions, routes: asked once per road end, not per step), the
storyboard (triggers, conditions, actions: event logic, not numerics), and the arc-length tables of
poly3/paramPoly3 geometries (numpy, built once per geometry at load).

Measured before writing it (``benchmarks/bench_core.py`` prints the figures): the compiled OpenDRIVE
libraries on the package index. CARLA 0.9.16's ``carla.Map`` (34 MB wheel) reads a road offline and
answers a projection in 2 µs, but places lane centres up to 0.65 mm from the geometry on esmini's
spiral roads and 3.75 m off on the superelevated velodrome (no banking), has no (s, t) query off the
lane centres, and prints to stdout; pyxodr is pure Python; libOpenDRIVE, maliput-malidrive and
pyopendrive have no package on PyPI.
"""

import functools

from vei_scenario.core import _core


@functools.cache
def layout(table: str) -> dict[str, int]:
    """Where each column of one of the core's tables (``road_user``, ``sync``, ``keep`` or ``guard`` of
    the quiet stretches) is, or the number of each of its codes (``guard_quantity``, ``mode``,
    ``shape``, ``rule``, ``sync_mode``), by the names core_module.c gives them: Python builds and reads the rows by
    name, and the order is written in the C alone. (One dict per table, only read.)"""
    return {name: i for i, name in enumerate(_core.CRUISE_LAYOUT[table])}


def row(table: str, values: dict[str, float]) -> list[float]:
    """A row of the core's ``table`` from its ``values`` by column name (the other columns 0)."""
    columns = layout(table)
    out = [0.0] * len(columns)
    for name, value in values.items():
        out[columns[name]] = value
    return out


__all__ = ["_core", "layout", "row"]
