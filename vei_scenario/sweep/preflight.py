"""What a sweep refuses before any variant runs, in one line and with nothing written.

Why: a defect of the file (an action vei cannot play, a trajectory it cannot follow, a road network
that is not one) fails every variant alike, and a value a parameter cannot take (a misspelt rider
type, a value outside the declaration's ValueConstraints) fails every variant that has it; both are
known before the first run, so a catalog of identical failures would only hide them. What depends on a
variant's combination of values stays a row of the catalog.
"""

from __future__ import annotations

import math
from pathlib import Path

from vei_scenario.errors import VeiError, VeiInputError
from vei_scenario.interpreter.document import load_scenario

#: Distinct values of one string parameter tried on their own before the sweep (each a build of the
#: scenario, a few milliseconds; a longer list is left to the rows).
MAX_PROBED_VALUES = 64


def _build_error(scenario: Path, values: dict[str, str], dt: float, controllers: tuple = ()) -> str | None:
    """Why the scenario cannot be set up with ``values`` and the systems under test ``controllers`` (None
    when it can; nothing is run)."""
    from vei_scenario.interpreter import Simulation

    try:
        Simulation(load_scenario(scenario, values), dt, controllers=controllers)
    except VeiInputError as exc:
        return str(exc)
    except (VeiError, ValueError, ArithmeticError):
        return None  # (not the file's defect as such: the rows say what it is)
    return None


#: "Not built yet", for the defaults' build error a caller may already know (None: it builds).
_UNKNOWN = object()


def preflight(
    scenario: Path,
    variants: list[dict[str, str]],
    varied: list[str],
    dt: float,
    controllers: tuple = (),
    where: str = "--vary",
) -> None:
    """Both checks before a sweep (:func:`check_playable`, :func:`check_values`), building the scenario
    with its defaults once for the two."""
    if not variants:
        return
    defaults = _build_error(scenario, {}, dt, controllers)
    check_playable(scenario, variants, dt, controllers, defaults)
    check_values(scenario, variants, varied, dt, where, defaults if not controllers else _UNKNOWN)


def check_playable(
    scenario: Path, variants: list[dict[str, str]], dt: float, controllers: tuple = (), defaults=_UNKNOWN
) -> None:
    """Refuse a scenario that cannot be set up at all: with its defaults, the first variant and the last
    alike (so the defect does not depend on the values varied); ``controllers``: the systems under test
    (an entity they name that the scenario lacks is such a defect); ``defaults``: the defaults' build
    error with those controllers, when the caller has it."""
    if not variants:
        return
    base = _build_error(scenario, {}, dt, controllers) if defaults is _UNKNOWN else defaults
    if base is None:
        return
    for v in (variants[0], variants[-1]):
        if _build_error(scenario, v, dt, controllers) != base:
            return
    raise VeiInputError(None, "", f"{base} (the base scenario cannot be played: no variant was run)")


def satisfies(value: str, rule: str, bound: str) -> bool:
    """One ValueConstraint: numbers compare as numbers, other text only by equalTo / notEqualTo (a rule
    the value's type cannot have is not the value's fault, so it holds)."""
    try:
        x, b = float(value), float(bound)
    except ValueError:
        x, b = value, bound  # (strings: equalTo / notEqualTo only)
        if rule not in ("equalTo", "notEqualTo"):
            return True
    if isinstance(x, float) and not (math.isfinite(x) and math.isfinite(b)):
        return True
    return {
        "equalTo": x == b,
        "notEqualTo": x != b,
        "greaterThan": x > b,
        "greaterOrEqual": x >= b,
        "lessThan": x < b,
        "lessOrEqual": x <= b,
    }.get(rule, True)


def declared_constraints(doc) -> dict[str, list[list[tuple[str, str]]]]:
    """{parameter: its ConstraintGroups, each a list of (rule, value)} (OpenSCENARIO 1.2): a value must
    satisfy every constraint of at least one group."""
    out: dict[str, list[list[tuple[str, str]]]] = {}
    for d in doc.root.iterfind("ParameterDeclarations/ParameterDeclaration"):
        groups = [
            [(c.get("rule", ""), c.get("value", "")) for c in g.iterfind("ValueConstraint")]
            for g in d.iterfind("ConstraintGroup")
        ]
        if any(groups):
            out[(d.get("name") or "").lstrip("$")] = [g for g in groups if g]
    return out


def describe_allowed(groups: list[list[tuple[str, str]]]) -> str:
    """The ConstraintGroups in words, for a refusal: "one of a, b" or "rule v and rule w or ..."."""
    if all(len(g) == 1 and g[0][0] == "equalTo" for g in groups):
        return "one of " + ", ".join(g[0][1] for g in groups)
    return " or ".join(" and ".join(f"{rule} {value}" for rule, value in g) for g in groups)


def check_values(
    scenario: Path,
    variants: list[dict[str, str]],
    varied: list[str],
    dt: float,
    where: str = "--vary",
    defaults=_UNKNOWN,
) -> None:
    """Refuse a varied value outside its declaration's ValueConstraints, or a string value that the
    scenario refuses on its own (tried with every other parameter at its default): one line naming the
    parameter, the value and what it may be. ``defaults``: the defaults' build error (no controllers),
    when the caller has it."""
    doc = load_scenario(scenario)
    constraints = declared_constraints(doc)
    distinct: dict[str, list[str]] = {}
    for v in variants:
        for name in varied:
            if name in v and v[name] not in distinct.setdefault(name, []):
                distinct[name].append(v[name])
    for name, values in distinct.items():
        groups = constraints.get(name)
        for value in values if groups else ():
            if not any(all(satisfies(value, rule, bound) for rule, bound in g) for g in groups):
                raise VeiInputError(
                    scenario, where, f"{name}={value!r} is outside its declared values ({describe_allowed(groups)})"
                )
    probed = {
        n: vs for n, vs in distinct.items() if doc.parameter_types.get(n) == "string" and len(vs) <= MAX_PROBED_VALUES
    }
    if not probed:
        return
    if (_build_error(scenario, {}, dt) if defaults is _UNKNOWN else defaults) is not None:
        return
    for name, values in probed.items():
        for value in values:
            if value == doc.parameters.get(name):
                continue
            problem = _build_error(scenario, {name: value}, dt)
            if problem is not None:
                raise VeiInputError(None, where, f"{name}={value!r}: {problem}")
