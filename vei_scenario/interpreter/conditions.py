"""The conditions of OpenSCENARIO triggers, each one class with a ``test(ctx) -> bool`` of the current
state (edges and delays are the trigger's, :class:`~vei_scenario.interpreter.storyboard.ConditionRunner`).
A new condition is one class and one line in ``VALUE_CONDITIONS`` or ``ENTITY_CONDITIONS``.

Each condition also knows for how many steps its value cannot change while the road users cruise
(:mod:`vei_scenario.interpreter.cruise`: along its lane or path, each step bounded by
:class:`~vei_scenario.interpreter.cruise.QuietBounds`, whose ``varying`` names those whose speed
changes): ``steady_steps``, 0 where it cannot tell. A comparison the core can work out every step (a
speed, an acceleration, a distance between road users or to a fixed point) is handed to it as a guard
instead, and holds for as long as the core runs."""

from __future__ import annotations

import math
import operator
from functools import lru_cache

from vei_scenario.core import _core, layout
from vei_scenario.interpreter.context import Context
from vei_scenario.models.angles import wrap_angle
from vei_scenario.openscenario import STORYBOARD_ELEMENT_TYPES


def _equal(a: float, b: float) -> bool:
    return abs(a - b) <= 1e-9 * max(1.0, abs(b))


def _not_equal(a: float, b: float) -> bool:
    return abs(a - b) > 1e-9 * max(1.0, abs(b))


#: OpenSCENARIO's Rule as a comparison of (value, threshold); equality within 1e-9 (relative).
RULES = {
    "greaterThan": operator.gt,
    "lessThan": operator.lt,
    "greaterOrEqual": operator.ge,
    "lessOrEqual": operator.le,
    "equalTo": _equal,
    "notEqualTo": _not_equal,
}


#: Each comparison as the core numbers it (core_module.c: RULES), for the guards of a quiet stretch.
RULE_CODES = {
    cmp: layout("rule")[name]
    for cmp, name in ((operator.gt, "GT"), (operator.lt, "LT"), (operator.ge, "GE"), (operator.le, "LE"),
                      (_equal, "EQ"), (_not_equal, "NE"))
}  # fmt: skip
_GE = RULE_CODES[operator.ge]


def comparator(rule: str):
    """The comparison of ``rule``, looked up once when a condition is built (conditions test every
    step); an unknown rule raises ValueError when it is used, as :func:`compare` does."""
    found = RULES.get(rule)
    if found is not None:
        return found

    def unknown(a: float, b: float) -> bool:
        raise ValueError(rule)

    return unknown


def compare(rule: str, a: float, b: float) -> bool:
    return comparator(rule)(a, b)


@lru_cache(maxsize=1024)
def _number(text: str) -> float | None:
    """``float(text)``, or None where ``text`` is no number. Kept per text: a parameter condition tests a
    word such as "true" every step, and a failed conversion costs far more than a lookup."""
    try:
        return float(text)
    except ValueError:
        return None


#: ``steady_steps`` of a value that cannot change while the road users cruise.
STEADY = 1 << 30


def steps_before(gap: float, per_step: float) -> int:
    """Steps in which a quantity ``gap`` from its threshold, changing at most ``per_step`` a step,
    cannot reach it (one step short, to leave rounding no say)."""
    if not gap > 0.0:
        return 0
    if not per_step > 0.0 or math.isinf(gap):
        return STEADY
    return max(0, min(STEADY, int(gap / per_step) - 1))


def _threshold_gap(cmp, measured: float, value: float) -> float:
    """How far ``measured`` is from where the comparison with ``value`` can change (an equality's
    tolerance band counts as the threshold; NaN: nowhere to tell)."""
    if cmp is _equal or cmp is _not_equal:
        return abs(measured - value) - 2e-9 * max(1.0, abs(value)) if not _equal(measured, value) else 0.0
    return abs(measured - value)


# --- conditions -------------------------------------------------------------------------------------


class Condition:
    """Raw truth of a condition; edges and delays are applied by :class:`ConditionRunner`."""

    def test(self, ctx: Context) -> bool:  # pragma: no cover - interface
        raise NotImplementedError

    def steady_steps(self, ctx: Context, bounds) -> int:
        """Steps after this one in which :meth:`test` gives what it gives now while the road users
        cruise within ``bounds``; 0 (the default): it cannot tell."""
        return 0

    #: whether :meth:`steady_steps` reasons with how far road users turn in a step (``bounds.turn``);
    #: a quiet stretch watched by none of these does not bound the turning (its ``bounds.turn`` is then
    #: infinite, so a condition that reads it without saying so holds for no step: slower, not wrong)
    reads_turning = False

    def _threshold(self, el) -> None:
        """``value`` of ``el`` and ``cmp``, the comparison of its ``rule`` (looked up once)."""
        self.value, self.cmp = float(el.get("value")), comparator(el.get("rule"))


class SimulationTime(Condition):
    def __init__(self, el, ctx: Context) -> None:
        self._threshold(el)

    def test(self, ctx: Context) -> bool:
        return self.cmp(ctx.t, self.value)

    def steady_steps(self, ctx: Context, bounds) -> int:
        if ctx.t > self.value + 1e-6:  # past it: no rule changes its answer again
            return STEADY
        return steps_before(self.value - ctx.t, ctx.dt)


class ParameterCondition(Condition):
    store, ref, what = "parameters", "parameterRef", "parameter"

    def __init__(self, el, ctx: Context) -> None:
        self.name, self.value, self.rule = (el.get(self.ref) or "").lstrip("$"), el.get("value"), el.get("rule")
        self.cmp = comparator(self.rule)
        if self.name not in getattr(ctx, self.store):
            raise ctx.error(el, f"{el.tag} on undeclared {self.what} {self.name!r}")

    def test(self, ctx: Context) -> bool:
        current = getattr(ctx, self.store)[self.name]
        a, b = _number(current), _number(self.value)
        if a is not None and b is not None:
            try:
                return self.cmp(a, b)
            except ValueError:  # (a rule no comparison has)
                pass
        # (a word: "true", "aggressive")
        if self.rule == "equalTo":
            return current == self.value
        if self.rule == "notEqualTo":
            return current != self.value
        return False

    def steady_steps(self, ctx: Context, bounds) -> int:  # only an action sets one
        return STEADY


class VariableCondition(ParameterCondition):
    """VariableCondition (OpenSCENARIO 1.2): a variable's current value against ``value`` (numbers
    compared as numbers, text and booleans by equality)."""

    store, ref, what = "variables", "variableRef", "variable"


class StoryboardElementState(Condition):
    def __init__(self, el, ctx: Context) -> None:
        self.key = (STORYBOARD_ELEMENT_TYPES.get(el.get("storyboardElementType"), ""), el.get("storyboardElementRef"))
        self.state = el.get("state")
        self.el = el
        if not self.state:
            raise ctx.error(el, "StoryboardElementStateCondition needs a state")
        #: a state (standbyState ...: the element is in it) or else a transition (Element.mark: when and where)
        self.in_state = self.state[: -len("State")] if self.state.endswith("State") else None
        self.target = None  # the element, found on the first test (the storyboard is built by then)

    def test(self, ctx: Context) -> bool:
        target = self.target
        if target is None:
            target = self.target = ctx.elements.get(self.key)
            if target is None:
                raise ctx.error(self.el, f"StoryboardElementStateCondition: no {self.key[0]} named {self.key[1]!r}")
        if self.in_state is not None:
            return target.state == self.in_state
        seen = target.transitions.get(self.state)
        if seen is None:
            return False
        # seen once (esmini steps the storyboard in document order): in the step it happened by the
        # triggers after the element, in the next step by those before it (an end found after the
        # entities moved stands after every trigger: all see it in the next step)
        step, where = seen
        return (step == ctx.step and where < ctx.position) or (step == ctx.step - 1 and ctx.position <= where)

    def steady_steps(self, ctx: Context, bounds) -> int:
        """A state holds while nothing starts or ends; a transition is seen for one step only."""
        return STEADY if self.in_state is not None or not self.test(ctx) else 0


class _EntityCondition(Condition):
    """Base for conditions evaluated for triggering entities (any/all)."""

    def __init__(self, el, ctx: Context, triggering: list[str], rule: str) -> None:
        self.el, self.triggering, self.rule_any = el, triggering, rule == "any"

    def for_entity(self, ctx: Context, name: str) -> bool:  # pragma: no cover - interface
        raise NotImplementedError

    def test(self, ctx: Context) -> bool:
        if len(self.triggering) == 1:  # (the common case, without a generator)
            return self.for_entity(ctx, self.triggering[0])
        results = (self.for_entity(ctx, n) for n in self.triggering)
        return any(results) if self.rule_any else all(results)

    def steady_steps(self, ctx: Context, bounds) -> int:
        return min(self.steady_for(ctx, n, bounds) for n in self.triggering)

    def steady_for(self, ctx: Context, name: str, bounds) -> int:
        """:meth:`steady_steps` for one triggering entity (0: it cannot tell)."""
        return 0


def known_entity(ctx: Context, el, name: str):
    """Entity ``name``; one line naming ``el``'s line when there is none."""
    if name not in ctx.entities:
        raise ctx.error(el, f"no entity named {name!r}")
    return ctx.entities[name]


class Collision(_EntityCondition):
    def __init__(self, el, ctx, triggering, rule) -> None:
        super().__init__(el, ctx, triggering, rule)
        ref = el.find("EntityRef")
        by_type = el.find("ByType")
        if ref is not None:
            self.targets = [ref.get("entityRef")]
            known_entity(ctx, el, self.targets[0])
        elif by_type is not None:
            kind = by_type.get("type") or by_type.get("objectType")
            self.targets = [n for n, e in ctx.entities.items() if e.category == kind or kind == "vehicle"]
        else:
            raise ctx.error(el, "CollisionCondition needs EntityRef or ByType")

    def for_entity(self, ctx: Context, name: str) -> bool:
        return any(frozenset((name, t)) in ctx.colliding for t in self.targets if t != name)

    def steady_for(self, ctx: Context, name: str, bounds) -> int:  # (a cruise ends where contacts change)
        return STEADY


class _StaticPoint:
    """A position as the other party of a distance or time-to-collision: no size, no motion."""

    length = width = speed = center_x = 0.0
    name = None  # (not a road user: it does not move)

    def __init__(self, pose) -> None:
        self.x, self.y, self.yaw, self.lane = pose.x, pose.y, pose.h, pose.lane

    def box(self) -> tuple[float, float, float, float, float]:
        return self.x, self.y, self.yaw, 0.0, 0.0

    def velocity(self) -> tuple[float, float]:
        return 0.0, 0.0


#: relativeDistanceType values that mean the straight distance (OpenSCENARIO 1.0 spelt it euclidian)
CARTESIAN = frozenset(("cartesianDistance", "euclidianDistance", "euclideanDistance"))


def _relative(ctx, el, a, b, kind: str, freespace: bool) -> tuple[float, float]:
    """Distance and its rate of change between entities a and b (``kind``: cartesian/euclidian,
    longitudinal or lateral in a's frame; ``freespace``: between the boxes)."""
    ax, ay, ayaw, al, aw = a.box()
    bx, by, byaw, bl, bw = b.box()
    if not freespace:  # between reference points (esmini), not box centres
        ax, ay, bx, by = a.x, a.y, b.x, b.y
    (avx, avy), (bvx, bvy) = a.velocity(), b.velocity()
    rx, ry, vx, vy = bx - ax, by - ay, bvx - avx, bvy - avy
    if kind in CARTESIAN:
        if freespace:  # (the core's box distance, the one its guards measure)
            d = _core.box_distance((ax, ay, ayaw, al, aw), (bx, by, byaw, bl, bw))
            later = (ax + avx * 1e-3, ay + avy * 1e-3, ayaw, al, aw), (bx + bvx * 1e-3, by + bvy * 1e-3, byaw, bl, bw)
            return d, (_core.box_distance(*later) - d) / 1e-3
        d = _core.hypot(rx, ry)
        return d, (rx * vx + ry * vy) / d if d > 1e-12 else 0.0
    c, s = math.cos(a.yaw), math.sin(a.yaw)
    if kind == "alongRoad":
        la, lb = a.lane, b.lane
        if la is not None and lb is not None and la.road == lb.road:  # s difference, a's driving sense
            sign = 1.0 if la.forward else -1.0
            d = sign * (_box_s(b) - _box_s(a)) if freespace else sign * (lb.s - la.s)
            rate = b.speed * math.cos(byaw - ayaw) - a.speed
            half = 0.5 * (al + bl) if freespace else 0.0
            direction = 1.0 if d >= 0 else -1.0
            return max(abs(d) - half, 0.0), direction * rate
        kind = "longitudinal"  # not on one road: along a's heading
    if kind == "longitudinal":
        d, rate = c * rx + s * ry, c * vx + s * vy
        half = 0.5 * (al + bl * abs(math.cos(byaw - ayaw)) + bw * abs(math.sin(byaw - ayaw))) if freespace else 0.0
    elif kind == "lateral":
        d, rate = -s * rx + c * ry, -s * vx + c * vy
        half = 0.5 * (aw + bw * abs(math.cos(byaw - ayaw)) + bl * abs(math.sin(byaw - ayaw))) if freespace else 0.0
    else:
        raise ctx.error(el, f"relativeDistanceType {kind!r} is not supported")
    sign = 1.0 if d >= 0 else -1.0
    return max(abs(d) - half, 0.0), sign * rate


def _box_s(e) -> float:
    """Where ``e``'s box centre is along its road (its reference point on its lane, moved by the box's
    offset along the way it drives): a distance between boxes along the road is measured from there."""
    return e.lane.s + (e.center_x if e.lane.forward else -e.center_x)


def _distance_rate(kind: str, freespace: bool, a, b, bounds) -> float:
    """The most a distance of ``kind`` between ``a`` and ``b`` (road users or points) changes in a
    quiet step: their moves, and where boxes or a frame turn, the turn times the lever arm (the
    distance itself counted with ``bounds.reach`` more, which the caller caps the steps to)."""
    move = bounds.move.get(a.name, 0.0) + bounds.move.get(b.name, 0.0)
    turn_a = bounds.turn if a.name is not None else 0.0
    turn_b = bounds.turn if b.name is not None else 0.0

    def arm(e) -> float:
        return abs(e.center_x) + 0.5 * math.hypot(e.length, e.width) if freespace else 0.0

    if kind in CARTESIAN:
        return move + turn_a * arm(a) + turn_b * arm(b)
    if kind == "alongRoad" and a.lane is not None and b.lane is not None and a.lane.road == b.lane.road:
        return bounds.along.get(a.name, 0.0) + bounds.along.get(b.name, 0.0)
    lever = math.hypot(b.x - a.x, b.y - a.y) + bounds.reach + arm(a) + arm(b)
    return move + (turn_a + turn_b) * lever


def _distance_steps(cmp, measured: float, value: float, rate: float, bounds) -> int:
    """Quiet steps before a distance ``measured`` (changing at most ``rate`` a step) can cross the
    comparison with ``value``, no more than it takes to move ``bounds.reach`` (the lever's margin)."""
    cap = steps_before(bounds.reach, rate) if rate > 0 else STEADY
    return min(steps_before(_threshold_gap(cmp, measured, value), rate), cap)


def _distance_kind(ctx, el) -> str:
    system = el.get("coordinateSystem", "entity")
    if system not in ("entity", "road", "lane"):
        raise ctx.error(el, f"coordinateSystem {system!r} is not supported (entity, road, lane)")
    if system != "entity" and el.get("relativeDistanceType") == "longitudinal":
        return "alongRoad"
    if el.get("routingAlgorithm") not in (None, "undefined"):
        raise ctx.error(el, f"routingAlgorithm {el.get('routingAlgorithm')!r} is not supported")
    if el.get("alongRoute") == "true":  # OpenSCENARIO 1.0: along the road (s), see _relative
        return "alongRoad"
    return el.get("relativeDistanceType", "cartesianDistance")


class TimeToCollision(_EntityCondition):
    def __init__(self, el, ctx, triggering, rule) -> None:
        super().__init__(el, ctx, triggering, rule)
        self._threshold(el)
        self.freespace = el.get("freespace", "false") == "true"
        self.kind = _distance_kind(ctx, el)
        target = el.find("TimeToCollisionConditionTarget")
        ref = target.find("EntityRef") if target is not None else None
        position = target.find("Position") if target is not None else None
        self.position = _PositionTarget(position) if position is not None else None
        if ref is None and self.position is None:
            raise ctx.error(el, "TimeToCollisionCondition needs an EntityRef or a Position target")
        self.target = ref.get("entityRef") if ref is not None else None
        if self.target is not None:
            known_entity(ctx, el, self.target)

    def _target(self, ctx: Context):
        if self.target is not None:
            return ctx.entities[self.target]
        return self.position(ctx)

    def ttc(self, ctx: Context, name: str) -> float:
        a, b = ctx.entities[name], self._target(ctx)
        if self.freespace and self.kind in CARTESIAN:
            (avx, avy), (bvx, bvy) = a.velocity(), b.velocity()
            return _core.time_to_contact(a.box(), avx, avy, b.box(), bvx, bvy)
        d, rate = _relative(ctx, self.el, a, b, self.kind, self.freespace)
        return d / -rate if rate < -1e-9 else math.inf

    def for_entity(self, ctx: Context, name: str) -> bool:
        ttc = self.ttc(ctx, name)
        return math.isfinite(ttc) and self.cmp(ttc, self.value)


class RelativeDistance(_EntityCondition):
    reads_turning = True  # (_distance_rate: boxes and frames that turn)

    def __init__(self, el, ctx, triggering, rule) -> None:
        super().__init__(el, ctx, triggering, rule)
        self._threshold(el)
        self.freespace = el.get("freespace", "false") == "true"
        self.kind = _distance_kind(ctx, el)
        self.target = el.get("entityRef")
        known_entity(ctx, el, self.target)

    def measure(self, ctx: Context, a, b) -> float:
        return _relative(ctx, self.el, a, b, self.kind, self.freespace)[0]

    def for_entity(self, ctx: Context, name: str) -> bool:
        return self.cmp(self.measure(ctx, ctx.entities[name], ctx.entities[self.target]), self.value)

    def steady_for(self, ctx: Context, name: str, bounds) -> int:
        # the core works the distance out every step (not alongRoad: lanes and roads are the interpreter's)
        if bounds.guard_distance(self.kind, self.freespace, name, self.target, RULE_CODES.get(self.cmp), self.value):
            return STEADY
        a, b = ctx.entities[name], ctx.entities[self.target]
        rate = _distance_rate(self.kind, self.freespace, a, b, bounds)
        return _distance_steps(self.cmp, self.measure(ctx, a, b), self.value, rate, bounds)


class _PositionTarget:
    """A condition's ``<Position>``: resolved when first needed (after Init placed the entities), and
    again every time when it is relative to an entity (it moves with it, as in esmini)."""

    def __init__(self, el) -> None:
        self.el = el
        self.moving = any(x.get("entityRef") for x in el.iter() if isinstance(x.tag, str))
        self.point: _StaticPoint | None = None

    def __call__(self, ctx: Context) -> _StaticPoint:
        if self.point is None or self.moving:
            from vei_scenario.interpreter.positions import resolve

            self.point = _StaticPoint(resolve(ctx, self.el))
        return self.point


class Distance(_EntityCondition):
    reads_turning = True  # (_distance_rate: boxes and frames that turn)

    def __init__(self, el, ctx, triggering, rule) -> None:
        super().__init__(el, ctx, triggering, rule)
        self._threshold(el)
        self.freespace = el.get("freespace", "false") == "true"
        self.kind = _distance_kind(ctx, el)
        if el.find("Position") is None:
            raise ctx.error(el, "DistanceCondition needs a Position")
        self.target = _PositionTarget(el.find("Position"))

    def measure(self, ctx: Context, e, p) -> tuple[float, str]:
        """The distance from ``e`` to the position ``p``, and the kind it was measured as."""
        if self.kind == "alongRoad" and p.lane is not None and e.lane is not None and e.lane.road == p.lane.road:
            d = abs(p.lane.s - _box_s(e)) - 0.5 * e.length if self.freespace else abs(p.lane.s - e.lane.s)
            return max(d, 0.0), "alongRoad"
        kind = "longitudinal" if self.kind == "alongRoad" else self.kind
        return _relative(ctx, self.el, e, p, kind, self.freespace)[0], kind

    def for_entity(self, ctx: Context, name: str) -> bool:
        return self.cmp(self.measure(ctx, ctx.entities[name], self.target(ctx))[0], self.value)

    def steady_for(self, ctx: Context, name: str, bounds) -> int:
        if self.target.moving:  # (a position relative to a road user: it moves too)
            return 0
        e, p = ctx.entities[name], self.target(ctx)
        d, kind = self.measure(ctx, e, p)
        if kind != "alongRoad" and bounds.guard_distance(
            kind, self.freespace, name, None, RULE_CODES.get(self.cmp), self.value, point=p
        ):
            return STEADY
        return _distance_steps(self.cmp, d, self.value, _distance_rate(kind, self.freespace, e, p, bounds), bounds)


class Speed(_EntityCondition):
    """Compares the entity's ``quantity`` (an Entity attribute) with the condition's value."""

    quantity = "speed"

    def __init__(self, el, ctx, triggering, rule) -> None:
        super().__init__(el, ctx, triggering, rule)
        self._threshold(el)
        if len(triggering) == 1:  # the common case, tested every step: one call (rising edges add one)
            name, quantity, cmp, value = triggering[0], self.quantity, self.cmp, self.value
            self.test = lambda ctx: cmp(getattr(ctx.entities[name], quantity), value)

    def for_entity(self, ctx: Context, name: str) -> bool:
        return self.cmp(getattr(ctx.entities[name], self.quantity), self.value)

    def steady_for(self, ctx: Context, name: str, bounds) -> int:
        # a cruise keeps the speed; one that changes (a synchronisation, a transition, a timed path)
        # the core watches, stopping before the step that would change the comparison
        if name not in bounds.varying or self._guard(name, bounds):
            return STEADY
        return 0

    def _guard(self, name: str, bounds) -> bool:
        return bounds.guard(self.quantity, name, RULE_CODES.get(self.cmp), self.value)


class ReachPosition(_EntityCondition):
    def __init__(self, el, ctx, triggering, rule) -> None:
        super().__init__(el, ctx, triggering, rule)
        self.tolerance = float(el.get("tolerance"))
        if el.find("Position") is None:
            raise ctx.error(el, "ReachPositionCondition needs a Position")
        self.target = _PositionTarget(el.find("Position"))

    def measure(self, ctx: Context, name: str) -> float:
        e, p = ctx.entities[name], self.target(ctx)
        return math.hypot(e.x - p.x, e.y - p.y)

    def for_entity(self, ctx: Context, name: str) -> bool:
        return self.measure(ctx, name) <= self.tolerance

    def steady_for(self, ctx: Context, name: str, bounds) -> int:
        if self.target.moving:
            return 0
        return steps_before(abs(self.measure(ctx, name) - self.tolerance), bounds.move.get(name, 0.0))


class TraveledDistance(_EntityCondition):
    def __init__(self, el, ctx, triggering, rule) -> None:
        super().__init__(el, ctx, triggering, rule)
        self.value = float(el.get("value"))

    def for_entity(self, ctx: Context, name: str) -> bool:
        return ctx.entities[name].odometer >= self.value

    def steady_for(self, ctx: Context, name: str, bounds) -> int:  # (an odometer only grows)
        odometer = ctx.entities[name].odometer
        if odometer >= self.value or bounds.guard("odometer", name, _GE, self.value):
            return STEADY  # (reached; or the core stops before the step that reaches it)
        return steps_before(self.value - odometer, bounds.move.get(name, 0.0))


class StandStill(_EntityCondition):
    def __init__(self, el, ctx, triggering, rule) -> None:
        super().__init__(el, ctx, triggering, rule)
        self.duration = float(el.get("duration"))

    def for_entity(self, ctx: Context, name: str) -> bool:
        since = ctx.entities[name].standing_since
        return since is not None and ctx.t - since >= self.duration - 1e-9

    def steady_for(self, ctx: Context, name: str, bounds) -> int:
        e = ctx.entities[name]
        if self.for_entity(ctx, name):  # standing long enough: moving again ends it at the next step
            return STEADY if abs(e.speed) < 1e-9 else 0
        if abs(e.speed) >= 1e-9:
            return STEADY
        since = e.standing_since if e.standing_since is not None else ctx.t + ctx.dt
        return steps_before(since + self.duration - ctx.t, ctx.dt)


class RelativeSpeed(_EntityCondition):
    def __init__(self, el, ctx, triggering, rule) -> None:
        super().__init__(el, ctx, triggering, rule)
        self._threshold(el)
        self.target = el.get("entityRef")
        known_entity(ctx, el, self.target)

    def for_entity(self, ctx: Context, name: str) -> bool:
        return self.cmp(ctx.entities[name].speed - ctx.entities[self.target].speed, self.value)

    def steady_for(self, ctx: Context, name: str, bounds) -> int:  # (as Speed's, on the difference)
        if not (name in bounds.varying or self.target in bounds.varying):
            return STEADY
        return STEADY if bounds.guard("speed", name, RULE_CODES.get(self.cmp), self.value, self.target) else 0


class Acceleration(Speed):
    quantity = "accel"

    def steady_for(self, ctx: Context, name: str, bounds) -> int:  # a cruise step's acceleration is 0
        if (ctx.entities[name].accel == 0.0 and name not in bounds.varying) or self._guard(name, bounds):
            return STEADY
        return 0


class TimeHeadway(_EntityCondition):
    """Headway time: distance to the target divided by the triggering entity's speed (inf standing)."""

    def __init__(self, el, ctx, triggering, rule) -> None:
        super().__init__(el, ctx, triggering, rule)
        self._threshold(el)
        self.target = el.get("entityRef")
        self.freespace = el.get("freespace", "false") == "true"
        # OpenSCENARIO 1.1 coordinateSystem and relativeDistanceType as the distance conditions read them;
        # without them the euclidean distance (the standard's distance where none is said), whatever 1.0's
        # deprecated alongRoute says, as esmini 3.6 reads it (measured: its cut-in examples play within
        # 2 mm so; "along the route" put them 0.25 m away, and "along the heading" a step apart)
        if el.get("coordinateSystem") is not None or el.get("relativeDistanceType") is not None:
            self.kind = _distance_kind(ctx, el)
        else:
            self.kind = "euclidianDistance"
        known_entity(ctx, el, self.target)

    def for_entity(self, ctx: Context, name: str) -> bool:
        e = ctx.entities[name]
        t = ctx.entities[self.target]
        d, _ = _relative(ctx, self.el, e, t, self.kind, self.freespace)
        if self._behind(e, t, d):  # the target is behind: no headway
            return False
        if e.speed <= 1e-9:
            return False
        return self.cmp(d / e.speed, self.value)

    def _behind(self, e, t, d: float) -> bool:
        """No headway to a target behind: its reference point behind along the road user's heading;
        between boxes (``freespace``), a box behind with a gap (as esmini 3.6: overlapping boxes have a
        headway of 0)."""
        return _behind_boxes(e, t, self.kind, d) if self.freespace else _ahead(e, t) <= 0

    def steady_for(self, ctx: Context, name: str, bounds) -> int:
        """Whether the target is ahead (along the road user's heading; behind: no headway, whatever the
        speed) is a guard the core works out every step. Ahead, while the road user's speed holds (not
        ``bounds.varying``), the headway compares as the distance does with ``value`` times that speed:
        a distance guard too (or, where the core cannot work the distance out, how fast it can change).
        An equality compares the quotient within a tolerance of its own: not watched."""
        if self.cmp is _equal or self.cmp is _not_equal:
            return 0
        e, t = ctx.entities[name], ctx.entities[self.target]
        varying = name in bounds.varying
        if e.speed <= 1e-9 and not varying:  # (no headway while it stands, or backs, at a speed that holds)
            return STEADY
        if not bounds.guard_ahead(name, self.target):
            return 0
        if _ahead(e, t) <= 0:  # (behind: no headway; between boxes, until they overlap: stepped)
            return 0 if self.freespace else STEADY
        if varying:
            return 0
        threshold = self.value * e.speed
        if bounds.guard_distance(self.kind, self.freespace, name, self.target, RULE_CODES.get(self.cmp), threshold):
            return STEADY
        d = _relative(ctx, self.el, e, t, self.kind, self.freespace)[0]
        return _distance_steps(self.cmp, d, threshold, _distance_rate(self.kind, self.freespace, e, t, bounds), bounds)


def _behind_boxes(e, t, kind: str, d_free: float) -> bool:
    """Whether ``t``'s box is behind ``e``'s with a gap between them (``d_free`` > 0): along the road
    when both are on one (the distance's ``alongRoad``), else along ``e``'s heading between box centres.
    Boxes overlapping along the way have no gap, hence a headway of 0 (esmini 3.6's signed free-space
    distance: measured on a car closing from behind in the next lane, it fires as their boxes meet)."""
    if d_free <= 0.0:
        return False
    la, lb = e.lane, t.lane
    if kind == "alongRoad" and la is not None and lb is not None and la.road == lb.road:
        return (1.0 if la.forward else -1.0) * (_box_s(t) - _box_s(e)) < 0.0
    ax, ay, ayaw, _, _ = e.box()
    bx, by, _, _, _ = t.box()
    return math.cos(ayaw) * (bx - ax) + math.sin(ayaw) * (by - ay) < 0.0


def _ahead(e, t) -> float:
    """How far ``t``'s reference point is ahead of ``e``'s along ``e``'s heading (negative: behind); the
    core's guard quantity AHEAD."""
    return math.cos(e.yaw) * (t.x - e.x) + math.sin(e.yaw) * (t.y - e.y)


class _HeldCondition(_EntityCondition):
    """True once the entity's :meth:`holds` has been true without a break for ``duration`` (``past``:
    for longer than it, a step later where it has held exactly that long)."""

    past = False

    def __init__(self, el, ctx, triggering, rule) -> None:
        super().__init__(el, ctx, triggering, rule)
        self.duration = float(el.get("duration"))
        self.since: dict[str, float] = {}

    def holds(self, ctx: Context, e) -> bool:  # pragma: no cover - interface
        raise NotImplementedError

    def for_entity(self, ctx: Context, name: str) -> bool:
        if not self.holds(ctx, ctx.entities[name]):
            self.since.pop(name, None)
            return False
        start = self.since.setdefault(name, ctx.t)
        if self.past:
            return ctx.t - start > self.duration + 1e-9
        return ctx.t - start >= self.duration - 1e-9


class EndOfRoad(_HeldCondition):
    """EndOfRoadCondition: stuck at a road end with nothing linked beyond it."""

    def holds(self, ctx: Context, e) -> bool:
        if e.lane is None:
            return False
        road = ctx.roads.road(e.lane.road)
        forward = e.lane.forward
        edge = e.lane.s >= road.length - 1e-6 if forward else e.lane.s <= 1e-6
        return edge and ctx.roads.next_road(road, e.lane.lane, forward) is None

    def steady_for(self, ctx: Context, name: str, bounds) -> int:
        """Short of the edge of its road, a cruise (which stays on the road) cannot reach it sooner
        than the s still to go allows."""
        e = ctx.entities[name]
        if e.lane is None:
            return STEADY
        if self.holds(ctx, e):
            return 0
        road = ctx.roads.road(e.lane.road)
        to_go = road.length - 1e-6 - e.lane.s if e.lane.forward else e.lane.s - 1e-6
        return steps_before(to_go, bounds.along.get(name, 0.0))


class TrafficSignal(Condition):
    """TrafficSignalCondition: the signal's state, as the last TrafficSignalStateAction set it."""

    def __init__(self, el, ctx: Context) -> None:
        self.name, self.state = el.get("name"), el.get("state")

    def test(self, ctx: Context) -> bool:
        return ctx.signals.get(self.name) == self.state

    def steady_steps(self, ctx: Context, bounds) -> int:  # only an action sets one
        return STEADY


VALUE_CONDITIONS = {
    "TrafficSignalCondition": TrafficSignal,
    "SimulationTimeCondition": SimulationTime,
    "ParameterCondition": ParameterCondition,
    "VariableCondition": VariableCondition,
    "StoryboardElementStateCondition": StoryboardElementState,
}


class RelativeClearance(_EntityCondition):
    """RelativeClearanceCondition: the lanes ``RelativeLaneRange`` away from the entity's (left
    positive, as it drives) exist where it is, run its way (unless ``oppositeLanes``), and hold no
    other entity (or none of the listed ones) from ``distanceBackward`` behind to ``distanceForward``
    ahead along the road."""

    def __init__(self, el, ctx, triggering, rule) -> None:
        super().__init__(el, ctx, triggering, rule)
        self.forward_m = float(el.get("distanceForward", "0") or 0)
        self.backward_m = float(el.get("distanceBackward", "0") or 0)
        self.opposite = el.get("oppositeLanes", "false") == "true"
        self.freespace = el.get("freeSpace", el.get("freespace", "false")) == "true"
        from vei_scenario.interpreter.positions import lane_id

        # (a range without a limit is open on that side)
        ranges = [
            (lane_id(ctx, r, "from", -1000), lane_id(ctx, r, "to", 1000)) for r in el.iterfind("RelativeLaneRange")
        ]
        self.ranges = ranges or [(-100, 100)]
        self.only = [r.get("entityRef") for r in el.iterfind("EntityRef")]

    def for_entity(self, ctx: Context, name: str) -> bool:
        from vei_scenario.interpreter.positions import lane_shift

        e = ctx.entities[name]
        if e.lane is None:
            return False
        road = ctx.roads.road(e.lane.road)
        lanes = road.section(e.lane.s).lanes
        wanted: set[int] = set()
        reach = len(lanes) + 1  # (no lane is further away than the section has lanes: a range of a
        for lo, hi in self.ranges:  # million lanes is looked through as far as there are any)
            for k in range(max(lo, -reach), min(hi, reach) + 1):
                lane = lane_shift(e.lane.lane, k, e.lane.forward) if k else e.lane.lane
                if lane not in lanes or lanes[lane].type not in DRIVABLE_LANE_TYPES:
                    continue
                if not self.opposite and road.drives_forward(lane) != road.drives_forward(e.lane.lane):
                    continue
                wanted.add(lane)
        if not wanted:
            return False
        sign = 1.0 if e.lane.forward else -1.0
        for other_name, o in ctx.entities.items():
            if other_name == name or (self.only and other_name not in self.only):
                continue
            if o.lane is None or o.lane.road != e.lane.road or o.lane.lane not in wanted:
                continue
            ds = sign * (o.lane.s - e.lane.s)
            half = 0.5 * (e.length + o.length) if self.freespace else 0.0
            if -self.backward_m - half <= ds <= self.forward_m + half:
                return False
        return True


#: Lane types a vehicle may be on without being "off road" (OffroadCondition).
DRIVABLE_LANE_TYPES = {
    "driving", "entry", "exit", "onRamp", "offRamp", "connectingRamp", "bidirectional", "stop", "border", "shoulder",
}  # fmt: skip


class Offroad(_HeldCondition):
    """OffroadCondition: the entity has been off every drivable lane for longer than ``duration`` (esmini
    3.6 counts it so: its lane_change example's car steers back on a step after it has been off 2.5 s)."""

    past = True

    def holds(self, ctx: Context, e) -> bool:
        rp = ctx.roads.project(e.x, e.y) if ctx.roads is not None else None
        lane = rp.road.section(rp.s).lanes.get(rp.lane) if rp is not None and rp.lane is not None else None
        return lane is None or lane.type not in DRIVABLE_LANE_TYPES


def _heading_in(ctx: Context, e, system: str) -> float:
    """The entity's heading in ``system``: absolute (entity, world; what esmini measures), or relative
    to the direction of increasing s of the road it is on (road, lane)."""
    if system in ("road", "lane") and ctx.roads is not None:
        rp = ctx.roads.project(e.x, e.y, e.lane.road if e.lane is not None else None)
        if rp is not None:
            return e.yaw - rp.road.ref_pose(rp.s)[2]
    return e.yaw


class Angle(_EntityCondition):
    """AngleCondition (OpenSCENARIO 1.2): the entity's heading (pitch, roll: 0, vei's entities stay
    level) within ``angleTolerance`` of ``angle`` (rad), measured in ``coordinateSystem``."""

    reads_turning = True

    def __init__(self, el, ctx, triggering, rule) -> None:
        from vei_scenario.safe_xml import float_attribute

        super().__init__(el, ctx, triggering, rule)
        self.angle = float_attribute(ctx.path, el, "angle")
        self.tolerance = float_attribute(ctx.path, el, "angleTolerance")
        if self.tolerance < 0:
            raise ctx.error(el, "angleTolerance must not be negative")
        self.kind = el.get("angleType", "heading")
        if self.kind not in ("heading", "pitch", "roll"):
            raise ctx.error(el, f"angleType {self.kind!r} is not one of heading, pitch, roll")
        self.system = el.get("coordinateSystem", "entity")
        if self.system not in ("entity", "world", "road", "lane", "trajectory"):
            raise ctx.error(el, f"coordinateSystem {self.system!r} is not one of OpenSCENARIO's")

    def measured(self, ctx: Context, name: str) -> float:
        e = ctx.entities[name]
        return _heading_in(ctx, e, self.system) if self.kind == "heading" else 0.0

    def for_entity(self, ctx: Context, name: str) -> bool:
        diff = wrap_angle(self.measured(ctx, name) - self.angle)
        return abs(diff) <= self.tolerance + 1e-12

    #: road users whose headings it measures (turning at most ``bounds.turn`` a step each)
    turners = 1

    def steady_for(self, ctx: Context, name: str, bounds) -> int:
        if self.kind != "heading" or self.system not in ("entity", "world"):
            return 0 if self.kind == "heading" else STEADY  # (pitch and roll stay 0)
        diff = abs(wrap_angle(self.measured(ctx, name) - self.angle))
        return steps_before(abs(diff - self.tolerance) - 1e-12, self.turners * bounds.turn)


class RelativeAngle(Angle):
    """RelativeAngleCondition: the triggering entity's angle minus that of ``entityRef``."""

    def __init__(self, el, ctx, triggering, rule) -> None:
        super().__init__(el, ctx, triggering, rule)
        self.ref = el.get("entityRef")
        known_entity(ctx, el, self.ref)

    def measured(self, ctx: Context, name: str) -> float:
        return super().measured(ctx, name) - super().measured(ctx, self.ref)

    turners = 2


ENTITY_CONDITIONS = {
    "AngleCondition": Angle,
    "RelativeAngleCondition": RelativeAngle,
    "OffroadCondition": Offroad,
    "RelativeClearanceCondition": RelativeClearance,
    "CollisionCondition": Collision,
    "TimeToCollisionCondition": TimeToCollision,
    "DistanceCondition": Distance,
    "RelativeDistanceCondition": RelativeDistance,
    "SpeedCondition": Speed,
    "ReachPositionCondition": ReachPosition,
    "TraveledDistanceCondition": TraveledDistance,
    "StandStillCondition": StandStill,
    "RelativeSpeedCondition": RelativeSpeed,
    "AccelerationCondition": Acceleration,
    "TimeHeadwayCondition": TimeHeadway,
    "EndOfRoadCondition": EndOfRoad,
}
