"""``find_risk``: the TimeShift intervals where an interaction becomes a collision or a near miss.

The seed method's dynamic risk generation. With the compiled kernel (vei-compiled scenarios) the window
is scanned at the tolerance itself, so no interval as wide as ``--tol`` is missed, and each edge is then
bisected to a quarter of it; otherwise the conflict shift found by the compiler and a coarse scan give
points on both sides of every edge, each bisected to the tolerance (intervals narrower than the coarse
step can then be missed, and the output says which way was used). With other varied parameters
(``--vary``), each combination is searched separately.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

from vei_scenario.atomic_io import OutputSet, json_text
from vei_scenario.errors import VeiInputError
from vei_scenario.interpreter.document import load_scenario
from vei_scenario.sut.contract import is_system_fault
from vei_scenario.sweep.catalog import variant_xosc
from vei_scenario.sweep.evaluate import evaluate_local, evaluate_variant
from vei_scenario.variation import cartesian, parse_vary

#: collision: with the ego moving at the first contact (a failure of the system that drives it);
#: collision_any: every contact; near-miss: no contact and the minimum TTC within the band.
TARGETS = ("collision", "collision_any", "near-miss")
#: Points of a scan at --tol that the compiled kernel runs without asking (~0.3 s per combination).
MAX_FINE_SCAN = 50_000


@dataclass
class RiskSearch:
    parameters: dict[str, str]  # the fixed values of this combination
    intervals: list[tuple[float, float]]  # TimeShift intervals where the target holds
    open_edges: list[str] = field(default_factory=list)  # edges that touch the search window
    evaluations: int = 0
    #: TimeShifts where the system under test failed (raised, crashed, hung), with the error: in a
    #: collision search they count as the target holding, in a near-miss band as not
    failed: list[tuple[float, str]] = field(default_factory=list)


def _holds(metrics: dict, target: str, band: tuple[float, float]) -> bool:
    if target == "collision":
        return bool(metrics.get("collision_ego_moving"))
    if target == "collision_any":
        return bool(metrics.get("collision"))
    ttc = metrics.get("min_ttc_s")
    return not metrics.get("collision") and ttc is not None and band[0] <= ttc <= band[1]


def search_combination(
    scenario: str,
    base: dict[str, str],
    target: str,
    band: tuple[float, float],
    window: tuple[float, float],
    coarse: float,
    tol: float,
    dt: float,
    seeds: list[float],
    workers: int | None,
    controllers: tuple = (),
) -> RiskSearch:
    cache: dict[float, bool] = {}
    failed: list[tuple[float, str]] = []

    def values(shift: float) -> dict[str, str]:
        return {**base, "TimeShift": repr(round(shift, 9))}

    def check(outcome: dict, shift: float) -> bool:
        if outcome["status"] == "ok":
            return _holds(outcome["metrics"], target, band)
        if controllers and is_system_fault(outcome["error"]):
            failed.append((shift, str(outcome["error"])))
            return target in ("collision", "collision_any")
        raise VeiInputError(scenario, "TimeShift", f"variant at TimeShift {shift:g} failed: {outcome['error']}")

    lo, hi = window
    n = int((hi - lo) / coarse + 1e-9) + 1
    grid = sorted({round(lo + i * coarse, 9) for i in range(n)} | {round(s, 9) for s in seeds if lo <= s <= hi})
    outcomes = evaluate_local(scenario, [values(s) for s in grid], dt, workers, controllers=controllers)
    for s, o in zip(grid, outcomes):
        cache[s] = check(o, s)

    def holds(shift: float) -> bool:
        if shift not in cache:
            cache[shift] = check(evaluate_variant(scenario, values(shift), dt, controllers=controllers), shift)
        return cache[shift]

    edges: list[tuple[float, bool]] = []  # (edge position, True if the target starts there)
    for a, b in zip(grid, grid[1:]):
        if cache[a] == cache[b]:
            continue
        x0, x1 = a, b
        while x1 - x0 > tol:
            mid = round(0.5 * (x0 + x1), 9)
            if holds(mid) == cache[a]:
                x0 = mid
            else:
                x1 = mid
        # The edge lies in (x0, x1]: report the last point inside the target set.
        edges.append((x1 if not cache[a] else x0, not cache[a]))
    intervals, open_edges = [], []
    start = grid[0] if cache[grid[0]] else None
    if start is not None:
        open_edges.append(f"target holds at the window's lower end {grid[0]:g}")
    for pos, rising in edges:
        if rising:
            start = pos
        elif start is not None:
            intervals.append((start, pos))
            start = None
    if start is not None:
        intervals.append((start, grid[-1]))
        open_edges.append(f"target holds at the window's upper end {grid[-1]:g}")
    return RiskSearch(base, intervals, open_edges, len(cache), sorted(failed))


def find_risk(
    scenario: str | Path,
    out_dir: str | Path | None,
    target: str = "collision",
    vary: list[str] | None = None,
    band: tuple[float, float] = (0.5, 1.5),
    window: tuple[float, float] | None = None,
    coarse: float = 0.5,
    tol: float = 0.01,
    dt: float = 0.01,
    workers: int | None = None,
    controllers: tuple = (),
) -> list[RiskSearch]:
    """The target's TimeShift intervals for each combination of ``vary`` (``controllers``: the systems
    under test, :class:`~vei_scenario.sut.ControllerSpec`)."""
    from vei_scenario.checks import check_dt, finite

    scenario = Path(scenario)
    check_dt(dt)
    for name, v in (("--coarse", coarse), ("--tol", tol), *(("--band", b) for b in band)):
        finite(v, name)
    if window is not None:
        for w in window:
            finite(w, "--window", -3600, 3600)
    if target not in TARGETS:
        raise VeiInputError(None, "--target", f"{target!r} is not one of {', '.join(TARGETS)}")
    if not (0 < tol < coarse):
        raise VeiInputError(None, "--tol", "need 0 < tol < coarse step")
    doc = load_scenario(scenario)
    if "TimeShift" not in doc.parameters:
        raise VeiInputError(scenario, "ParameterDeclarations", "risk search varies TimeShift, which is not declared")
    axes = [parse_vary(v, doc.parameter_types) for v in (vary or [])]
    if any(a[0] == "TimeShift" for a in axes):
        raise VeiInputError(None, "--vary", "TimeShift is what the risk search varies; vary other parameters")
    conflict = float(doc.parameters.get("ConflictTimeShift", "0"))
    window = window or (round(conflict - 6.0, 3), round(conflict + 6.0, 3))
    if window[1] <= window[0]:
        raise VeiInputError(None, "--window", "empty TimeShift window")
    combos = cartesian(axes, dict(doc.parameters)) if axes else [dict(doc.parameters)]
    # exhaustive where the compiled kernel makes it cheap: a scan at the tolerance itself misses no
    # window as wide as --tol (a coarse scan stepped over the planner's 0.03 s failure windows)
    from vei_scenario.sweep.evaluate import _native_engine

    step = coarse
    native = _native_engine(str(scenario.resolve()), dt, controllers=controllers)
    if native is not None and (window[1] - window[0]) / tol <= MAX_FINE_SCAN:
        step = tol
    results = [
        search_combination(str(scenario.resolve()), c, target, band, window, step, tol / 4 if step == tol else tol, dt,
                           [conflict], workers, controllers)
        for c in combos
    ]  # fmt: skip
    if out_dir is not None:
        out = Path(out_dir)
        files = OutputSet()
        doc_out = {
            "scenario": str(scenario),
            "target": target,
            "band_s": list(band),
            "window_s": list(window),
            "tolerance_s": tol,
            "searches": [],
        }
        if controllers:
            from vei_scenario.sut import sut_document

            doc_out["system_under_test"] = sut_document(controllers)
        for k, r in enumerate(results):
            entry = {
                "parameters": {a[0]: r.parameters[a[0]] for a in axes},
                "intervals": [],
                "open_edges": r.open_edges,
                "evaluations": r.evaluations,
            }
            if r.failed:
                entry["failed_runs"] = [{"time_shift_s": t, "error": e} for t, e in r.failed]
            for j, (a, b) in enumerate(r.intervals):
                files_rel = {}
                for label, shift in (("start", a), ("mid", 0.5 * (a + b)), ("end", b)):
                    rel = f"critical/search{k:02d}_interval{j}_{label}.xosc"
                    files.add(
                        out / rel,
                        variant_xosc(scenario, {**r.parameters, "TimeShift": repr(round(shift, 4))}, out / "critical"),
                    )
                    files_rel[label] = rel
                entry["intervals"].append({"time_shift_s": [round(a, 4), round(b, 4)], "scenarios": files_rel})
            doc_out["searches"].append(entry)
        files.add(out / "risk.json", json_text(doc_out, indent=2) + "\n")
        files.commit()
    return results
