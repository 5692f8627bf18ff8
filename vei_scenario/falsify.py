"""``falsify``: search a box of scenario parameters for the failures of the system under test.

Why this shape: the failures of a collision-avoidance planner are thin sets. In the case study the
planner fails only where the rider's timing (TimeShift) lies in windows 0.007-0.08 s wide, windows that
move by about 2 s per m/s of the ego's cruise speed. Random or quasi-random points over the whole box
step over them, and so does a coarse scan (the old ``vei risk`` answered "none found"). The search
therefore treats one continuous parameter as the *primary* axis (TimeShift when it is searched) and:

1. **Slices.** The other continuous parameters are sampled (evenly spaced for one, a scrambled Sobol
   sample for several, ``--slices`` per parameter) and crossed with every value of the discrete ones.
2. **Line search on each slice.** A coarse scan along the primary axis, scored with a continuous
   robustness value (the minimum box gap, ``-(1 + impact speed)`` on contact with the ego moving, 0 on
   contact with the ego standing, or the margin of a metric target such as ``min_ttc_s<1``), finds failing
   points directly; then branch and bound on the lattice of ``--tol`` splits only the intervals where a
   failure can hide: where a dip could reach zero between two points (a bound from the scan's steepest
   slope), beside every local minimum below a margin (zooming into each dip, where a notch sits beside a
   jump), and at each window's edges, down to ``--tol``. Slices far from failing end after the scan.
3. **Regions.** Windows on neighbouring slices are one region when their intervals overlap, or when a
   probe on the slice half-way between them finds a window between them (a band that moves faster than
   its width). Each region's primary edges are the extreme window edges, refined along each other
   parameter around the slice that holds them.
4. **Worst case.** Each region's lowest-robustness run (the hardest impact) is written as a
   fully-resolved ``.xosc`` with a one-line ``vei run`` command that reproduces it.

Runs go through the compiled kernel for vei-compiled scenarios (thousands per second), else the
interpreter. The search spends a few percent of the runs of a grid of the same resolution
(``benchmarks/bench_falsify.py`` measures it against a dense grid).
"""

from __future__ import annotations

import itertools
import math
import re
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from vei_scenario.errors import VeiInputError
from vei_scenario.sut.contract import is_system_fault

#: The robustness below which a local minimum of the scan is zoomed into, down to --tol (the box gap, m).
CLIMB_BELOW = 2.0
#: What an edge search scores where it finds no window (finite: the minimiser does arithmetic on it).
NO_WINDOW = 1e9
#: Coarse scan points along the primary axis per slice.
COARSE_POINTS = 60
_TARGET = re.compile(r"^\s*([a-z_][a-z0-9_.]*)\s*(<=|>=|<|>)\s*([-+0-9.eE]+)\s*$")


@dataclass
class Axis:
    name: str
    low: float = math.nan
    high: float = math.nan
    values: list[str] = field(default_factory=list)  # a discrete axis when set

    @property
    def discrete(self) -> bool:
        return bool(self.values)


@dataclass
class Window:
    """A failure interval along the primary axis on one slice."""

    slice_values: dict[str, str]  # every other parameter of the slice
    slice_point: tuple[float, ...]  # the other continuous values (for neighbours)
    start: float
    end: float
    worst: tuple[float, dict[str, str]] | None = None  # (robustness, parameters) of its worst run


@dataclass
class Region:
    number: int
    discrete: dict[str, str]
    windows: list[Window]
    primary: str
    low: float
    high: float
    worst_robustness: float
    worst: dict[str, str]
    dt: float = 0.01
    #: the options that plug the system under test in again (sut.reproduce_options)
    options: str = ""

    def reproduce(self, scenario: str) -> str:
        params = " ".join(f"--param {k}={v}" for k, v in self.worst.items())
        step = f" --dt {self.dt:g}" if self.dt != 0.01 else ""
        return f"vei run {scenario} {params}{step}{self.options}"

    def as_dict(self, scenario: str) -> dict:
        return {
            "region": self.number,
            "discrete": self.discrete,
            "primary": self.primary,
            "edges": [self.low, self.high],
            "slices": len(self.windows),
            "windows": [
                {"at": w.slice_values, "interval": [w.start, w.end]}
                for w in sorted(self.windows, key=lambda w: w.slice_point)
            ],
            "worst": {"parameters": self.worst, "robustness": self.worst_robustness},
            "reproduce": self.reproduce(scenario),
        }


@dataclass
class FalsifyResult:
    scenario: str
    target: str
    regions: list[Region]
    runs: int
    axes: list[Axis]
    written: list[Path] = field(default_factory=list)
    system_under_test: list[dict] = field(default_factory=list)
    #: runs the system under test failed (raised, crashed, hung, returned no command): (values, error)
    failed_runs: list[tuple[dict[str, str], str]] = field(default_factory=list)


#: The robustness of a run the system under test failed: the worst failure there is (finite, so the
#: search's interval bounds stay numbers).
SYSTEM_FAULT = -1e9


#: The target that counts every contact, the ego standing or not (``collision`` counts the ego moving).
COLLISION_ANY = "collision_any"
_NOT_NUMERIC = ("collision", "collision_entities", "ttc_zones_s", "near_miss", "collision_ego_moving")


def parse_target(text: str) -> tuple[str, str, float] | str | None:
    """``collision`` (None: a collision with the ego moving, a failure of the system that drives it),
    ``collision_any`` (every contact) or ``METRIC<VALUE`` (``<``, ``<=``, ``>``, ``>=``) as
    (metric, op, value)."""
    from vei_scenario.metrics import METRICS

    if text == "collision":
        return None
    if text == COLLISION_ANY:
        return COLLISION_ANY
    m = _TARGET.match(text)
    if not m:
        raise VeiInputError(
            None, "--target", f"{text!r} is not collision, collision_any or METRIC<VALUE (e.g. min_ttc_s<1.0)"
        )
    metric, op, value = m.group(1), m.group(2), float(m.group(3))
    if metric not in METRICS or metric in _NOT_NUMERIC:
        numeric = [k for k in METRICS if k not in _NOT_NUMERIC]
        raise VeiInputError(None, "--target", f"unknown numeric metric {metric!r} (known: {', '.join(numeric)})")
    if not math.isfinite(value):
        raise VeiInputError(None, "--target", f"{text!r}: the value is not finite")
    return metric, op, value


def robustness(metrics: dict, target: tuple[str, str, float] | str | None) -> float:
    """Continuous failure margin: negative where the target holds (a failure), lower is worse. A
    collision with the ego standing (speed ≤ 0.1 m/s at the first contact) is no failure of the system
    that drives it: 0, on the edge, unless the target is ``collision_any``."""
    moving = metrics.get("collision_ego_moving") if target != COLLISION_ANY else metrics.get("collision")
    if moving:
        return -(1.0 + float(metrics.get("impact_speed_mps") or 0.0))
    if target is None or target == COLLISION_ANY:
        return 0.0 if metrics.get("collision") else float(metrics["min_gap_m"])
    metric, op, value = target
    v = metrics.get(metric)
    if v is None:  # (never defined: e.g. no TTC when the boxes never approach) far from failing
        return 1e6
    margin = float(v) - value if op in ("<", "<=") else value - float(v)
    if margin == 0:  # on the threshold: a failure only for <= and >=
        return -1e-12 if op in ("<=", ">=") else 1e-12
    return margin


class _Runner:
    def __init__(
        self, scenario: str, fixed: dict[str, str], target, dt: float, workers: int | None, controllers: tuple = ()
    ) -> None:
        self.scenario, self.fixed, self.target, self.dt, self.workers = scenario, fixed, target, dt, workers
        self.controllers = controllers
        self.runs = 0
        self.cache: dict[tuple, float] = {}
        self.failed: list[tuple[dict[str, str], str]] = []

    def __call__(self, variants: list[dict[str, str]]) -> list[float]:
        from vei_scenario.sweep.evaluate import evaluate_local

        keys = [tuple(sorted(v.items())) for v in variants]
        todo = [(k, v) for k, v in zip(keys, variants) if k not in self.cache]
        if todo:
            rows = evaluate_local(
                self.scenario, [{**self.fixed, **v} for _, v in todo], self.dt, self.workers,
                controllers=self.controllers,
            )  # fmt: skip
            self.runs += len(rows)
            for (k, v), r in zip(todo, rows):
                if r["status"] == "ok":
                    self.cache[k] = robustness(r["metrics"], self.target)
                elif self.controllers and is_system_fault(r["error"]):
                    self.failed.append((v, str(r["error"])))
                    self.cache[k] = SYSTEM_FAULT
                else:
                    shown = ", ".join(f"{n}={x}" for n, x in v.items())
                    raise VeiInputError(self.scenario, "variant", f"{shown} failed: {r['error']}")
        return [self.cache[k] for k in keys]


def _fmt(x: float) -> str:
    return repr(round(float(x), 6))


def _line_search(run: _Runner, base: dict[str, str], primary: Axis, lo: float, hi: float, points: int,
                 tol: float) -> list[Window]:  # fmt: skip
    """Failure windows along the primary axis on one slice, between ``lo`` and ``hi``, resolved as a
    grid at ``tol`` would resolve them, with the runs spent only where a failure can hide.

    A first scan of about ``points / 4`` runs, then branch and bound: an interval between two
    non-failing points is split while a dip reaching zero could fit between them, i.e. while
    ``(ρa + ρb) / 2 - L (b - a) / 2 <= 0``, with ``L`` twice the steepest slope of the robustness
    between the first scan's non-failing points, or while one of its ends is a local minimum of the
    robustness below :data:`CLIMB_BELOW` (the search zooms into every dip: a notch sits beside a jump
    the slope does not bound); an interval with a failing end is split down to ``tol`` (the window's
    edge). Slices whose robustness stays far from zero end after the first scan. Every probe lies on
    the lattice ``primary.low + k tol`` (a grid at ``tol`` holds the same points, and the probes of
    neighbouring searches are shared). (A planner's failure is often a notch at the bottom of a dip of
    the gap, a discontinuity: the search splits down to ``tol`` wherever the gap comes near zero, while
    a minimiser would stall on the plateau beside it.)"""

    def snap(x: float) -> float:  # (as the parameter is written: the edges are the values run)
        return float(_fmt(min(hi, max(lo, primary.low + round((x - primary.low) / tol) * tol))))

    first = np.linspace(lo, hi, max(3, points // 4 + 1))
    xs = sorted({float(lo), float(hi), *(snap(x) for x in first[1:-1])})
    rho: dict[float, float] = {}

    def evaluate(new: list[float]) -> None:
        for x, r in zip(new, run([{**base, primary.name: _fmt(x)} for x in new])):
            rho[x] = r

    evaluate(xs)
    slopes = [abs(rho[b] - rho[a]) / (b - a) for a, b in zip(xs, xs[1:]) if rho[a] >= 0 and rho[b] >= 0]
    lipschitz = 2.0 * max(slopes, default=0.0)  # (the first scan's: a jump seen closer would inflate it)
    while True:
        v = [rho[x] for x in xs]
        dip = {
            xs[i]
            for i in range(len(xs))
            if 0 <= v[i] < CLIMB_BELOW and v[i] <= min(v[max(i - 1, 0)], v[min(i + 1, len(v) - 1)])
        }
        mids = []
        for a, b in zip(xs, xs[1:]):
            ra, rb = rho[a], rho[b]
            if (ra < 0 and rb < 0) or b - a <= tol * (1 + 1e-9):
                continue
            if ra < 0 or rb < 0 or a in dip or b in dip or 0.5 * (ra + rb) - 0.5 * lipschitz * (b - a) <= 0:
                m = snap(0.5 * (a + b))
                if a < m < b:
                    mids.append(m)
        if not mids:
            break
        evaluate(mids)
        xs = sorted(rho)
    windows: list[Window] = []
    current: list[float] = []
    for x in xs + [math.inf]:
        if x != math.inf and rho[x] < 0:
            current.append(x)
            continue
        if current:
            worst = min(current, key=lambda v: rho[v])
            windows.append(Window(dict(base), (), current[0], current[-1],
                                  (rho[worst], {**base, primary.name: _fmt(worst)})))  # fmt: skip
            current = []
    return windows


def _slices(cont: list[Axis], per_axis: int, seed: int) -> list[tuple[float, ...]]:
    if not cont:
        return [()]
    if len(cont) == 1:
        a = cont[0]
        return [(float(v),) for v in np.linspace(a.low, a.high, per_axis)]
    from scipy.stats import qmc

    n = per_axis * len(cont)
    u = qmc.Sobol(len(cont), scramble=True, seed=seed).random(int(2 ** math.ceil(math.log2(n))))[:n]
    lows, highs = np.array([a.low for a in cont]), np.array([a.high for a in cont])
    return [tuple(float(v) for v in row) for row in qmc.scale(u, lows, highs)]


class _Union:
    def __init__(self, n: int) -> None:
        self.parent = list(range(n))

    def find(self, i: int) -> int:
        while self.parent[i] != i:
            self.parent[i] = self.parent[self.parent[i]]
            i = self.parent[i]
        return i

    def join(self, a: int, b: int) -> None:
        self.parent[self.find(a)] = self.find(b)


def falsify(
    scenario: str | Path,
    axes: list[Axis],
    fixed: dict[str, str] | None = None,
    target: str = "collision",
    slices: int = 7,
    tol: float = 0.005,
    coarse_points: int = COARSE_POINTS,
    seed: int = 0,
    dt: float = 0.01,
    workers: int | None = None,
    out_dir: str | Path | None = None,
    controllers: tuple = (),
    allow_default_controller: bool = False,
) -> FalsifyResult:
    """Search the box ``axes`` (others at ``fixed`` or their defaults) for failures (``target``) of the
    systems under test ``controllers`` (:class:`~vei_scenario.sut.ControllerSpec`; none: the scenario's
    own controllers). A controller the scenario names that vei has no model of is refused unless
    ``allow_default_controller``: the search would find the failures of an ego without its system."""
    from vei_scenario.checks import check_dt, finite
    from vei_scenario.interpreter.document import load_scenario

    check_dt(dt)
    finite(tol, "--tol", 1e-5, 10)
    if not (isinstance(slices, int) and 2 <= slices <= 200):
        raise VeiInputError(None, "--slices", f"{slices!r} is not a number of slices in 2..200")
    crit = parse_target(target)
    scenario = Path(scenario)
    doc = load_scenario(scenario)
    fixed = dict(fixed or {})
    check_axes(scenario, doc, axes, fixed)
    from vei_scenario.sweep.evaluate import refuse_default_controllers

    refuse_default_controllers(scenario, fixed, dt, tuple(controllers), allow_default_controller)
    cont = [a for a in axes if not a.discrete]
    if not cont:
        raise VeiInputError(None, "--bounds", "give at least one continuous range (NAME=LOW:HIGH) to search along")
    primary = next((a for a in cont if a.name == "TimeShift"), cont[0])
    others = [a for a in cont if a is not primary]
    discrete = [a for a in axes if a.discrete]
    run = _Runner(str(scenario.resolve()), fixed, crit, dt, workers, tuple(controllers))
    points = _slices(others, slices, seed)
    combos = [dict(zip([a.name for a in discrete], c)) for c in itertools.product(*(a.values for a in discrete))]
    regions: list[Region] = []
    spacing = [(a.high - a.low) / max(slices - 1, 1) for a in others]
    for combo in combos:
        windows: list[Window] = []
        for p in points:
            base = {**combo, **{a.name: _fmt(v) for a, v in zip(others, p)}}
            for w in _line_search(run, base, primary, primary.low, primary.high, coarse_points, tol):
                w.slice_point = p
                windows.append(w)
        regions += _regions(run, windows, combo, primary, others, spacing, tol, len(regions))
    from vei_scenario.sut import reproduce_options, sut_document

    sut = sut_document(tuple(controllers))
    for r in regions:
        r.dt, r.options = dt, reproduce_options(sut)
        _refine_edges(run, r, primary, others, spacing, tol)
        _worst(run, r, primary)
    result = FalsifyResult(str(scenario), target, regions, run.runs, axes)
    result.system_under_test, result.failed_runs = sut, run.failed
    if out_dir is not None:
        result.written = _write(result, scenario, Path(out_dir), fixed)
    return result


def _regions(run, windows: list[Window], combo, primary: Axis, others: list[Axis], spacing, tol,
             first: int) -> list[Region]:  # fmt: skip
    if not windows:
        return []
    u = _Union(len(windows))

    def neighbours(a: Window, b: Window) -> bool:
        if not others:
            return False
        d = [abs(x - y) / s if s > 0 else 0.0 for x, y, s in zip(a.slice_point, b.slice_point, spacing)]
        return 0 < max(d) <= 1.0 + 1e-9 if len(others) == 1 else 0 < math.hypot(*d) <= 1.5

    for i, a in enumerate(windows):
        for j in range(i + 1, len(windows)):
            b = windows[j]
            if not neighbours(a, b):
                continue
            if a.start <= b.end + tol and b.start <= a.end + tol:
                u.join(i, j)
                continue
            # not overlapping: a band moving faster than its width? probe the slice half-way between
            mid = tuple(0.5 * (x + y) for x, y in zip(a.slice_point, b.slice_point))
            base = {**combo, **{ax.name: _fmt(v) for ax, v in zip(others, mid)}}
            lo, hi = min(a.start, b.start), max(a.end, b.end)
            width = max(hi - lo, tol)
            found = _line_search(run, base, primary, max(primary.low, lo - 0.1 * width),
                                 min(primary.high, hi + 0.1 * width), 16, tol)  # fmt: skip
            if any(w.start <= hi and w.end >= lo for w in found):
                u.join(i, j)
    groups: dict[int, list[Window]] = {}
    for i, w in enumerate(windows):
        groups.setdefault(u.find(i), []).append(w)
    out = []
    for k, ws in enumerate(sorted(groups.values(), key=lambda ws: min(w.start for w in ws))):
        out.append(Region(first + k + 1, dict(combo), ws, primary.name, min(w.start for w in ws),
                          max(w.end for w in ws), 0.0, {}))  # fmt: skip
    return out


def _window_at(run, base, primary: Axis, near: Window, tol) -> Window | None:
    width = max(near.end - near.start, tol)
    lo, hi = max(primary.low, near.start - 2 * width), min(primary.high, near.end + 2 * width)
    found = _line_search(run, base, primary, lo, hi, 12, tol)
    return min(found, key=lambda w: abs(0.5 * (w.start + w.end) - 0.5 * (near.start + near.end)), default=None)


def _refine_edges(run, r: Region, primary: Axis, others: list[Axis], spacing, tol) -> None:
    """The region's extreme primary edges between the slices: a bounded Brent search (SciPy) along
    each other parameter around the slice that holds the extreme (a band's extreme may lie between)."""
    from scipy.optimize import minimize_scalar

    if not others:
        return
    for side in ("low", "high"):
        best = min(r.windows, key=lambda w: w.start) if side == "low" else max(r.windows, key=lambda w: w.end)
        for k, ax in enumerate(others):
            a = max(ax.low, best.slice_point[k] - spacing[k])
            b = min(ax.high, best.slice_point[k] + spacing[k])
            cache: dict[float, float] = {}

            def edge(v: float, k=k, best=best, side=side, cache=cache) -> float:
                if v not in cache:
                    point = list(best.slice_point)
                    point[k] = v
                    base = {**r.discrete, **{o.name: _fmt(x) for o, x in zip(others, point)}}
                    w = _window_at(run, base, primary, best, tol)
                    cache[v] = NO_WINDOW if w is None else (w.start if side == "low" else -w.end)
                return cache[v]

            edge(best.slice_point[k])  # (the slice's own edge: the search can only improve on it)
            if b > a:
                minimize_scalar(edge, bounds=(a, b), method="bounded", options={"maxiter": 10, "xatol": 1e-3 * (b - a)})
            value = min(cache.values(), default=NO_WINDOW)
            if value < NO_WINDOW:
                if side == "low":
                    r.low = min(r.low, value)
                else:
                    r.high = max(r.high, -value)


def _worst(run, r: Region, primary: Axis) -> None:
    """The region's hardest failure: the lowest robustness among its windows' runs."""
    best = min((w.worst for w in r.windows if w.worst is not None), key=lambda b: b[0], default=(math.inf, {}))
    r.worst_robustness, r.worst = best[0], {**run.fixed, **best[1]}


def check_axes(path: Path, doc, axes: list[Axis], fixed: dict[str, str]) -> None:
    """Bounds against the declared parameters: known names, finite and non-empty ranges of numeric
    parameters, values of the declared type, within the declaration's value constraints."""
    from vei_scenario.interpreter.document import check_type, check_values
    from vei_scenario.sweep.preflight import declared_constraints, describe_allowed, satisfies

    constraints = declared_constraints(doc)
    seen = set()
    for a in axes:
        if a.name not in doc.parameter_types:
            known = ", ".join(sorted(doc.parameter_types)) or "none"
            raise VeiInputError(None, "--bounds", f"unknown parameter {a.name!r} (declared: {known})")
        if a.name in seen or a.name in fixed:
            raise VeiInputError(None, "--bounds", f"{a.name} is given twice")
        seen.add(a.name)
        kind = doc.parameter_types[a.name]
        if a.discrete:
            for v in a.values:
                problem = check_type(kind, v)
                if problem:
                    raise VeiInputError(None, "--values", f"{a.name}={v!r} {problem} ({kind} parameter)")
                groups = constraints.get(a.name)
                if groups and not any(all(satisfies(v, rule, b) for rule, b in g) for g in groups):
                    raise VeiInputError(
                        None, "--values", f"{a.name}={v!r} is outside its declared values ({describe_allowed(groups)})"
                    )
            continue
        if kind not in ("double", "int", "integer", "unsignedInt", "unsignedShort"):
            raise VeiInputError(None, "--bounds", f"{a.name} is a {kind} parameter: give --values, not a range")
        if not (math.isfinite(a.low) and math.isfinite(a.high)):
            raise VeiInputError(None, "--bounds", f"{a.name}: bounds must be finite numbers")
        if not a.low < a.high:
            raise VeiInputError(None, "--bounds", f"{a.name}={a.low:g}:{a.high:g} is an empty box")
        groups = constraints.get(a.name)
        ends = (repr(a.low), repr(a.high))
        if groups and not any(all(satisfies(b, rule, v) for b in ends for rule, v in g) for g in groups):
            raise VeiInputError(
                None,
                "--bounds",
                f"{a.name}={a.low:g}:{a.high:g} is not within one of its declared ranges ({describe_allowed(groups)})",
            )
    check_values(doc.parameter_types, fixed)


def parse_bounds(specs: list[str], values: list[str]) -> list[Axis]:
    axes = []
    for spec in specs:
        name, sep, rng = spec.partition("=")
        parts = rng.split(":")
        try:
            low, high = float(parts[0]), float(parts[1])
        except (IndexError, ValueError):
            raise VeiInputError(None, "--bounds", f"{spec!r} is not NAME=LOW:HIGH") from None
        if not sep or len(parts) != 2 or not name.strip():
            raise VeiInputError(None, "--bounds", f"{spec!r} is not NAME=LOW:HIGH")
        axes.append(Axis(name.strip(), low, high))
    for spec in values:
        name, sep, vals = spec.partition("=")
        items = [v.strip() for v in vals.split(",")]
        if not sep or not name.strip() or not all(items):
            raise VeiInputError(None, "--values", f"{spec!r} is not NAME=V1,V2")
        axes.append(Axis(name.strip(), values=items))
    if not axes:
        raise VeiInputError(None, "--bounds", "nothing to search: give --bounds NAME=LOW:HIGH (and --values)")
    return axes


def bounds_from_distribution(path: str | Path) -> list[Axis]:
    """The box a ParameterValueDistribution spans: a range (deterministic DistributionRange, or the
    Range of a stochastic distribution) is a continuous axis, a set of values a discrete one."""
    from vei_scenario.safe_xml import float_attribute, parse_xml

    path = Path(path)
    root = parse_xml(path).getroot()
    pvd = root.find("ParameterValueDistribution")
    if root.tag != "OpenSCENARIO" or pvd is None:
        raise VeiInputError(path, f"line {root.sourceline}", "not an OpenSCENARIO ParameterValueDistribution file")
    axes: list[Axis] = []
    for d in pvd.iter("DeterministicSingleParameterDistribution", "StochasticDistribution"):
        name = d.get("parameterName")
        kind = next((c for c in d if isinstance(c.tag, str)), None)
        if kind is None:
            continue
        rng = kind.find("Range")
        if kind.tag in ("DistributionSet", "ProbabilityDistributionSet"):
            axes.append(Axis(name, values=[e.get("value") for e in kind.iterfind("Element")]))
        elif rng is not None:
            axes.append(Axis(name, float_attribute(path, rng, "lowerLimit"), float_attribute(path, rng, "upperLimit")))
        else:
            raise VeiInputError(
                path, f"line {kind.sourceline}", f"<{kind.tag}> of {name} has no Range: give --bounds {name}=LOW:HIGH"
            )
    if not axes:
        raise VeiInputError(path, f"line {pvd.sourceline}", "no parameter distributions to take bounds from")
    return axes


def _write(result: FalsifyResult, scenario: Path, out: Path, fixed: dict[str, str]) -> list[Path]:
    from vei_scenario.atomic_io import OutputSet, json_text
    from vei_scenario.sweep.catalog import variant_xosc

    files = OutputSet()
    doc = {
        "scenario": str(scenario),
        "target": result.target,
        "runs": result.runs,
        "fixed": fixed,
        "box": [
            {"name": a.name, "values": a.values} if a.discrete else {"name": a.name, "bounds": [a.low, a.high]}
            for a in result.axes
        ],
        "regions": [],
    }
    if result.system_under_test:
        doc["system_under_test"] = result.system_under_test
    if result.failed_runs:
        doc["failed_runs"] = [{"values": v, "error": e} for v, e in result.failed_runs]
    for r in result.regions:
        rel = f"regions/region_{r.number:02d}_worst.xosc"
        files.add(out / rel, variant_xosc(scenario, r.worst, out / "regions"))
        entry = r.as_dict(str(scenario))
        entry["worst"]["xosc"] = rel
        doc["regions"].append(entry)
    files.add(out / "falsify.json", json_text(doc, indent=2) + "\n")
    files.commit()
    return files.paths
