"""Parameter variations: ``--vary`` specifications and OpenSCENARIO ParameterValueDistribution files.

Both produce a list of variants, each a full ``{parameter: value-string}`` assignment checked against
the scenario's declared parameters and their types. Stochastic distributions draw from a seeded
generator, so a catalog reproduces exactly.
"""

from __future__ import annotations

import itertools
import math
from pathlib import Path

import numpy as np

from vei_scenario.errors import VeiInputError
from vei_scenario.interpreter.document import check_type
from vei_scenario.openscenario.numeric_attributes import check_numbers
from vei_scenario.safe_xml import first_element, float_attribute, parse_xml

#: Cap on the variants one sweep may ask for (a typo in a step should not ask for billions).
MAX_VARIANTS = 2_000_000


def _fmt(v: float) -> str:
    r = round(float(v), 10)
    return repr(int(r)) if r.is_integer() else repr(r)


def parse_vary(spec: str, declared: dict[str, str]) -> tuple[str, list[str]]:
    """``Name=start:stop:step`` (inclusive) or ``Name=v1,v2,...`` against the declared types."""
    name, sep, values = spec.partition("=")
    name = name.strip()
    if not sep or not name or not values.strip():
        raise VeiInputError(None, "--vary", f"{spec!r} is not Name=start:stop:step or Name=v1,v2")
    if name not in declared:
        raise VeiInputError(None, "--vary", f"unknown parameter {name!r} (declared: {', '.join(sorted(declared))})")
    if values.count(":") == 2 and "," not in values:
        try:
            start, stop, step = (float(x) for x in values.split(":"))
        except ValueError:
            raise VeiInputError(None, "--vary", f"{spec!r}: start:stop:step must be numbers") from None
        if not all(math.isfinite(x) for x in (start, stop, step)) or step <= 0 or stop < start:
            raise VeiInputError(None, "--vary", f"{spec!r} is an empty range (need start <= stop and step > 0)")
        n = int(math.floor((stop - start) / step + 1e-9)) + 1
        if n > MAX_VARIANTS:
            raise VeiInputError(None, "--vary", f"{spec!r} gives {n} values")
        out = [_fmt(start + i * step) for i in range(n)]
    else:
        out = [v.strip() for v in values.split(",")]
        if any(not v for v in out):
            raise VeiInputError(None, "--vary", f"{spec!r} has an empty value")
    for v in out:
        problem = check_type(declared[name], v)
        if problem:
            raise VeiInputError(None, "--vary", f"{name}={v!r} {problem} ({declared[name]} parameter)")
    return name, out


def cartesian(axes: list[tuple[str, list[str]]], defaults: dict[str, str]) -> list[dict[str, str]]:
    names = [a[0] for a in axes]
    if len(set(names)) != len(names):
        raise VeiInputError(None, "--vary", "a parameter is varied twice")
    total = math.prod(len(a[1]) for a in axes) if axes else 1
    if total > MAX_VARIANTS:
        raise VeiInputError(None, "--vary", f"{total} variants exceed the limit of {MAX_VARIANTS}")
    out = []
    for combo in itertools.product(*(a[1] for a in axes)):
        v = dict(defaults)
        v.update(zip(names, combo))
        out.append(v)
    return out


def _range(path: Path, el) -> tuple[float, float] | None:
    r = el.find("Range")
    if r is None:
        return None
    lo, hi = float_attribute(path, r, "lowerLimit"), float_attribute(path, r, "upperLimit")
    if hi < lo:
        raise VeiInputError(path, f"line {r.sourceline}", "Range upperLimit is below lowerLimit")
    return lo, hi


def _value(path: Path, el) -> str:
    """The ``value`` of a distribution's element or parameter assignment; one line when it has none."""
    value = el.get("value")
    if value is None:
        raise VeiInputError(path, f"line {el.sourceline}", f"<{el.tag}> needs a value")
    return value


def _deterministic_single(path: Path, el) -> list[str]:
    kind = first_element(el)  # (comments may stand before it)
    if kind is not None and kind.tag == "DistributionSet":
        values = [_value(path, e) for e in kind.iterfind("Element")]
        if not values:  # (the product would have no variant at all)
            raise VeiInputError(path, f"line {kind.sourceline}", "a DistributionSet has no Element")
        return values
    if kind is not None and kind.tag == "DistributionRange":
        step = float_attribute(path, kind, "stepWidth")
        bounds = _range(path, kind)
        if bounds is None:
            raise VeiInputError(path, f"line {kind.sourceline}", "a DistributionRange needs a Range")
        lo, hi = bounds
        if step <= 0:
            raise VeiInputError(path, f"line {kind.sourceline}", "stepWidth must be positive")
        count = (hi - lo) / step
        if count >= MAX_VARIANTS:  # (before a list of 10^15 values is built)
            raise VeiInputError(
                path, f"line {kind.sourceline}", f"the range gives {count:.3g} values; at most {MAX_VARIANTS}"
            )
        n = int(math.floor(count + 1e-9)) + 1
        return [_fmt(lo + i * step) for i in range(n)]
    tag = kind.tag if kind is not None else "nothing"
    raise VeiInputError(path, f"line {el.sourceline}", f"<{tag}> distributions are not supported")


def _sample(path: Path, el, rng: np.random.Generator, n: int) -> list[str]:
    kind = first_element(el)  # (comments may stand before it)
    tag = kind.tag if kind is not None else "nothing"
    if tag == "ProbabilityDistributionSet":
        elems = list(kind.iterfind("Element"))
        w = np.array([float_attribute(path, e, "weight") for e in elems])
        if np.any(w < 0) or w.sum() <= 0:
            raise VeiInputError(path, f"line {kind.sourceline}", "weights must be non-negative and not all zero")
        idx = rng.choice(len(elems), size=n, p=w / w.sum())
        values = [_value(path, e) for e in elems]
        return [values[i] for i in idx]
    if tag == "Histogram":
        bins = list(kind.iterfind("Bin"))
        if not bins:
            raise VeiInputError(path, f"line {kind.sourceline}", "a Histogram needs Bin elements")
        w = np.array([float_attribute(path, b, "weight") for b in bins])
        if np.any(w < 0) or w.sum() <= 0:
            raise VeiInputError(path, f"line {kind.sourceline}", "bin weights must be non-negative and not all zero")
        ranges = [_range(path, b) for b in bins]
        for b, r in zip(bins, ranges):
            if r is None:
                raise VeiInputError(path, f"line {b.sourceline}", "a Bin needs a Range")
        idx = rng.choice(len(bins), size=n, p=w / w.sum())
        return [_fmt(rng.uniform(*ranges[i])) for i in idx]
    rng_range = _range(path, kind) if kind is not None else None
    if tag == "UniformDistribution":
        if rng_range is None:
            raise VeiInputError(path, f"line {kind.sourceline}", "a UniformDistribution needs a Range")
        return [_fmt(v) for v in rng.uniform(*rng_range, size=n)]
    if tag == "LogNormalDistribution" and float_attribute(path, kind, "expectedValue") <= 0:
        raise VeiInputError(path, f"line {kind.sourceline}", "a log-normal expectedValue must be positive")
    if tag in ("NormalDistribution", "LogNormalDistribution") and float_attribute(path, kind, "variance") < 0:
        raise VeiInputError(path, f"line {kind.sourceline}", "variance must not be negative")
    if tag == "LogNormalDistribution":  # (its spread is log(1 + variance / expectedValue²): finite)
        mean, var = float_attribute(path, kind, "expectedValue"), float_attribute(path, kind, "variance")
        if mean * mean == 0.0 or not math.isfinite(var / (mean * mean)):
            raise VeiInputError(
                path,
                f"line {kind.sourceline}",
                f"a log-normal needs variance / expectedValue² finite (expectedValue {mean:g}, variance {var:g})",
            )
    if tag == "PoissonDistribution" and not (0 <= float_attribute(path, kind, "expectedValue") <= 1e9):
        raise VeiInputError(path, f"line {kind.sourceline}", "a Poisson expectedValue must be in 0..1e9")

    def draw() -> float:
        if tag == "NormalDistribution":
            return rng.normal(
                float_attribute(path, kind, "expectedValue"), math.sqrt(float_attribute(path, kind, "variance"))
            )
        if tag == "LogNormalDistribution":
            # expectedValue and variance are those of the log-normal variable itself.
            mean, var = float_attribute(path, kind, "expectedValue"), float_attribute(path, kind, "variance")
            s2 = math.log(1 + var / (mean * mean))
            return rng.lognormal(math.log(mean) - s2 / 2, math.sqrt(s2))
        if tag == "PoissonDistribution":
            return float(rng.poisson(float_attribute(path, kind, "expectedValue")))
        raise VeiInputError(path, f"line {el.sourceline}", f"<{tag}> distributions are not supported")

    out = []
    for _ in range(n):
        for _attempt in range(10_000):  # truncation to the Range by rejection
            v = draw()
            if rng_range is None or rng_range[0] <= v <= rng_range[1]:
                break
        else:
            raise VeiInputError(path, f"line {kind.sourceline}", "the Range excludes almost every sample")
        out.append(_fmt(v))
    return out


def distributed_scenario(path: str | Path) -> Path | None:
    """The scenario a ParameterValueDistribution file varies (its ``ScenarioFile``, relative to the
    distribution's folder), or None when ``path`` is a scenario itself: a distribution names the scenario
    it is for, so ``vei run`` and ``vei sweep`` take it alone (the Euro NCAP pack ships its variations so)."""
    path = Path(path)
    root = parse_xml(path).getroot()
    pvd = root.find("ParameterValueDistribution")
    if root.tag != "OpenSCENARIO" or pvd is None:
        return None
    ref = pvd.find("ScenarioFile")
    if ref is None or not (ref.get("filepath") or "").strip():
        raise VeiInputError(path, f"line {pvd.sourceline}", "the distribution names no ScenarioFile filepath")
    scenario = (path.parent / ref.get("filepath")).resolve()
    if not scenario.is_file():
        raise VeiInputError(path, f"line {ref.sourceline}", f"ScenarioFile {ref.get('filepath')!r} not found")
    return scenario


def read_distribution(path: str | Path, declared: dict[str, str], seed: int | None = None) -> list[dict[str, str]]:
    """Variants of a ParameterValueDistribution file (values not yet merged with defaults)."""
    path = Path(path)
    root = parse_xml(path).getroot()
    pvd = root.find("ParameterValueDistribution")
    if root.tag != "OpenSCENARIO" or pvd is None:
        raise VeiInputError(path, f"line {root.sourceline}", "not an OpenSCENARIO ParameterValueDistribution file")
    check_numbers(path, root)
    variants: list[dict[str, str]]
    det, sto = pvd.find("Deterministic"), pvd.find("Stochastic")
    if det is not None:
        # the cartesian product of every distribution, in file order, the first varying slowest (the
        # standard; esmini's --param_permutation counts so): a single parameter's values, or a multi-
        # parameter distribution's value sets (one factor each)
        factors: list[list[dict[str, str]]] = []
        named = []
        for d in det:
            if d.tag == "DeterministicSingleParameterDistribution":
                name = d.get("parameterName")
                factors.append([{name: v} for v in _deterministic_single(path, d)])
                named.append((name, d))
            elif d.tag == "DeterministicMultiParameterDistribution":
                sets = [
                    {a.get("parameterRef"): _value(path, a) for a in vs.iterfind("ParameterAssignment")}
                    for vs in d.iterfind("ValueSetDistribution/ParameterValueSet")
                ]
                if not sets:
                    raise VeiInputError(
                        path, f"line {d.sourceline}", "a multi-parameter distribution without value sets"
                    )
                factors.append(sets)
                named += [(k, d) for vs in sets for k in vs]
        total = math.prod(len(f) for f in factors)
        if total > MAX_VARIANTS:
            raise VeiInputError(path, f"line {det.sourceline}", f"{total} variants exceed the limit of {MAX_VARIANTS}")
        variants = [{k: v for part in combo for k, v in part.items()} for combo in itertools.product(*factors)]
    elif sto is not None:
        runs = float_attribute(path, sto, "numberOfTestRuns")
        if not (1 <= runs <= MAX_VARIANTS) or not runs.is_integer():
            raise VeiInputError(
                path, f"line {sto.sourceline}", f"numberOfTestRuns must be a whole number in 1..{MAX_VARIANTS}"
            )
        n = int(runs)
        seed_value = (
            seed if seed is not None else int(float_attribute(path, sto, "randomSeed")) if sto.get("randomSeed") else 0
        )
        if seed_value < 0 or seed_value >= 2**63:
            raise VeiInputError(path, f"line {sto.sourceline}", "the random seed must be a non-negative integer")
        rng = np.random.default_rng(seed_value)
        columns = {}
        named = []
        for d in sto.iterfind("StochasticDistribution"):
            columns[d.get("parameterName")] = _sample(path, d, rng, n)
            named.append((d.get("parameterName"), d))
        variants = [{k: v[i] for k, v in columns.items()} for i in range(n)]
    else:
        raise VeiInputError(path, f"line {pvd.sourceline}", "neither Deterministic nor Stochastic")
    for name, el in named:
        if name not in declared:
            raise VeiInputError(path, f"line {el.sourceline}", f"varies {name!r}, which the scenario does not declare")
    for v in variants:
        for k, value in v.items():
            if value.startswith("${") and value.endswith("}"):  # an expression (esmini evaluates them too)
                from vei_scenario.interpreter.expressions import ExpressionError, evaluate

                try:
                    result = evaluate(value[2:-1], {n: x for n, x in v.items() if not x.startswith("${")})
                except ExpressionError as exc:
                    raise VeiInputError(path, "", f"{k}={value!r}: {exc}") from None
                value = v[k] = _fmt(result) if math.isfinite(result) else value
            problem = check_type(declared[k], value)
            if problem:
                raise VeiInputError(path, "", f"{k}={value!r} {problem} ({declared[k]} parameter)")
    return variants
