"""The built-in OpenSCENARIO interpreter: runs the compiled XML (or any file in the supported subset).

``document`` loads and resolves parameters, ``storyboard`` holds element states, triggers and
conditions, ``actions`` and ``controllers`` set what moves the entities, ``engine`` steps everything.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

from vei_scenario.interpreter.document import load_scenario
from vei_scenario.interpreter.engine import DEFAULT_MAX_TIME_S, RunResult, Simulation
from vei_scenario.interpreter.malformed import refused_when_malformed


def run_scenario(
    path: str | Path,
    parameters: dict[str, object] | None = None,
    dt: float = 0.01,
    max_time_s: float = DEFAULT_MAX_TIME_S,
    coupling: str = "sequential",
    controllers: tuple = (),
    on_start: Callable[[Simulation], Callable[[float], None] | None] | None = None,
) -> RunResult:
    """Load ``path``, apply parameter overrides (strings as in the file, or Python booleans and
    numbers), run at the fixed step ``dt`` (``coupling``: see
    :data:`~vei_scenario.interpreter.engine.COUPLINGS`); ``controllers``: the systems under test
    (:class:`~vei_scenario.sut.ControllerSpec`), each driving its entity's speed throughout.

    A file the interpreter cannot read because it breaks the ASAM schema is refused with the schema's
    first complaint (file, line, reason), not with the place where reading it failed
    (:mod:`~vei_scenario.interpreter.malformed`).

    ``on_start``: called with the simulation once it is set up, before the first step; what it
    returns (if not None) is called with the simulated time now and then as the run goes on (a
    caller's announcement of a long run and its progress bar)."""
    doc = None
    with refused_when_malformed(path, lambda: doc.root if doc is not None else None):
        doc = load_scenario(path, parameters)
        sim = Simulation(doc, dt, max_time_s, coupling, controllers)
        return sim.run(on_start(sim) if on_start is not None else None)


__all__ = ["RunResult", "Simulation", "load_scenario", "run_scenario"]


def clear_file_caches() -> None:
    """Forget the catalogs and road networks built so far in this process (they are kept per file
    content, so that a sweep's variants share them): the next run reads them as a fresh process does."""
    from vei_scenario.interpreter import document, shapes
    from vei_scenario.roads.road_model import _network
    from vei_scenario.safe_xml import _digest

    for cache in (
        document._template,
        document._listing,
        document._catalog_tree,
        document._catalog_index,
        document._directory,
        document._road_network_problem,
        _network,
        _digest,
    ):
        cache.cache_clear()
    document._RESOLVED.clear()
    document._NAMES.clear()
    shapes._BUILT.clear()
