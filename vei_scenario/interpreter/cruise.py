"""Quiet steps handed to the core in one call: while every road user keeps its lane (shifting sideways
in a running lane change or lane offset), drives straight on or follows a path (an untimed one at its
speed or at the speed its running SynchronizeAction or SpeedAction transition sets; a timed one as its
time says; placed at the gap its continuous LongitudinalDistanceAction keeps and on at the speed of the
road user it keeps it to), and no trigger can fire, a step is only motion, and the core takes many at once.

The storyboard stays in charge. After a step's evaluation in which nothing started or ended, each
watched condition says for how many steps its value cannot change while the road users cruise within
:class:`QuietBounds` (``steady_steps``: a time still ahead, a distance that cannot be covered, a value
only an action sets; a comparison of a speed, an acceleration or a distance that changes is a guard the
core watches); the triggers say which of those evaluations would fire (delays and edges included); every
running action says whether the core carries it (``Action.carried``); the core (``_core.cruise``: the
same lane keeping, path following, timed playing, synchronisation profile and transition as a single
step's) moves everyone that many steps, and stops early before any step that leaves the bounds, a road,
a lane or a path, ends a synchronisation, a transition, a lane change or a timed path's action, changes
what a guard compares, starts or ends a standstill, or changes which boxes touch. The steps it took are
recorded as the interpreter records its own, bit for bit (tests/test_cruise*.py), and
the conditions and actions account for the evaluations that were not run.
"""

from __future__ import annotations

import array
import math
from dataclasses import dataclass, field

from vei_scenario.core import _core, layout
from vei_scenario.core import row as core_row
from vei_scenario.interpreter.clock import count_at_or_before, packed_step_times, step_time, step_times
from vei_scenario.interpreter.entities import SHAPE_CODES as _SHAPES  # (the core's numbers of the shapes)

#: Core columns of a road user (core_module.c: ROAD_USER_COLUMNS).
_ROAD_USER = layout("road_user")
_COLS = len(_ROAD_USER)
_MODE, _S, _LANE, _X, _Y, _YAW, _SPEED, _ODO, _PROFILE, _ACCEL = (
    _ROAD_USER[n] for n in ("MODE", "S", "LANE", "X", "Y", "YAW", "SPEED", "ODOMETER", "PROFILE", "ACCEL")
)
_OFFSET, _FRACTION, _PARAM, _PREV_X, _PREV_Y = (
    _ROAD_USER[n] for n in ("OFFSET", "LAT_FRACTION", "LAT_PARAM", "PREV_X", "PREV_Y")
)
#: A road user's mode in the core (core_module.c: MODE_*): straight on, its lane, its path, its timed
#: path in position or in follow mode, towed; and what the interpreter records it doing in each.
_STRAIGHT, _LANE_MODE, _PATH, _TIMED, _TIMED_FOLLOW, _TOWED = (
    float(layout("mode")[n]) for n in ("STRAIGHT", "LANE", "PATH", "TIMED", "TIMED_FOLLOW", "TOWED")
)
_STATUS = {_TIMED: "replay", _TIMED_FOLLOW: "follow", _TOWED: "towed"}
#: How many core columns a synchronisation and a kept distance have (core_module.c: SYNC_COLUMNS, KEEP_COLUMNS).
_SY_COLS = len(layout("sync"))
_KP_COLS = len(layout("keep"))
_AC_COLS = len(layout("acc"))
#: Most steps in one call of the core (the poses it returns for them are held in memory at once).
CHUNK = 2000
#: Fewest quiet steps worth a call (fewer: the ordinary step is as quick).
MIN_STEPS = 3
#: Steps the engine takes before offering the core a stretch again after the storyboard or the road
#: users' motion refused one.
RETRY_STEPS = 4
#: How many refusals in a row for road users starting or stopping are followed by an offer at once.
EDGE_RETRIES = 8
#: How fast (rad/s) a road user may turn in a quiet stretch watched by a condition that reads turning.
TURN_RATE = 0.3
#: How much faster (m/s) than now a road user whose speed a synchronisation sets may go in a quiet
#: stretch: the bound of its steps that the conditions reason with (the core stops before it is passed).
SPEED_MARGIN_MPS = 2.0


#: What a guard compares (core_module.c: GUARD_QUANTITIES), by the names the conditions use.
_GUARDED = {name.lower(): float(code) for name, code in layout("guard_quantity").items()}
#: The distances the core works out (conditions._relative's kinds; OpenSCENARIO 1.0 spelt one euclidian).
_DISTANCES = {"cartesianDistance": "cartesian", "euclidianDistance": "cartesian", "euclideanDistance": "cartesian",
              "longitudinal": "longitudinal", "lateral": "lateral"}  # fmt: skip
#: The comparisons (conditions.RULE_CODES) a distance guard takes: an order, not an equality.
_ORDERS = frozenset(layout("rule")[n] for n in ("GT", "LT", "GE", "LE"))
_GT = layout("rule")["GT"]


@dataclass
class Offers:
    """When a run next offers the core a quiet stretch (the engine keeps one per run; :func:`cruise`
    sets it from why each offer ended)."""

    wait: int = 0  # quiet steps to let pass first
    refusals: int = 0  # the core's refusals in a row (it would not take even the first step offered)

    def due(self) -> bool:
        """Whether this quiet step is offered (else one of the steps to let pass has passed)."""
        if self.wait:
            self.wait -= 1
            return False
        return True


@dataclass(frozen=True)
class QuietBounds:
    """The most a quiet step changes: the core stops before a step that would exceed any of these, or
    that would change what a guard compares."""

    move: dict[str, float]  # metres a road user's reference point moves in a step
    along: dict[str, float]  # metres of its road's s (or its path's) it passes in a step
    turn: float  # radians it turns in a step
    reach: float = 10.0  # metres a distance's lever arm may grow before a condition looks again
    varying: frozenset = frozenset()  # road users whose speed changes (a synchronisation sets it)
    index: dict = field(default_factory=dict)  # each road user's row in the core
    guards: list = field(default_factory=list)  # the core's columns of what guard() was asked

    def guard(self, quantity: str, name: str, rule: int | None, value: float, other: str | None = None) -> bool:
        """Have the core stop before a step after which ``quantity`` ("speed", "accel" or "odometer")
        of road user ``name`` (less ``other``'s) compares with ``value`` by ``rule`` (core_module.c:
        RULE_*, the conditions' comparisons) otherwise than it does now: how a condition on a quantity
        that changes every step holds through a quiet stretch. False when the core cannot watch it."""
        if quantity not in ("speed", "accel", "odometer") or rule is None:
            return False
        return self._add(quantity, name, other, rule, value, {})

    def guard_distance(self, kind: str, freespace: bool, name: str, other: str | None, rule: int | None,
                       value: float, point=None) -> bool:  # fmt: skip
        """Have the core stop before a step after which the distance of ``kind`` (conditions._relative's:
        cartesian, longitudinal or lateral in ``name``'s frame; ``freespace``: between the boxes) from
        road user ``name`` to road user ``other`` (or to the fixed ``point``, with x, y, yaw) compares
        with ``value`` by ``rule`` otherwise than it does now. The core works the distance out again, so
        it also stops before a step that leaves it within a micrometre of ``value``, where the last bits
        of its arithmetic and the interpreter's could disagree. False when the core cannot watch it."""
        quantity = _DISTANCES.get(kind)
        if quantity is None or rule not in _ORDERS or (other is None and point is None):
            return False
        extra = {"FREESPACE": 1.0 if freespace else 0.0}
        if point is not None:
            extra |= {"POINT_X": point.x, "POINT_Y": point.y, "POINT_YAW": point.yaw}
        return self._add(quantity, name, other, rule, value, extra)

    def guard_ahead(self, name: str, other: str) -> bool:
        """Have the core stop before a step after which road user ``other``'s reference point is ahead of
        ``name``'s (along its heading) where it was behind, or behind where it was ahead, or within a
        micrometre of abeam. False when the core cannot watch it."""
        return self._add("ahead", name, other, _GT, 0.0, {})

    def _add(self, quantity: str, name: str, other: str | None, rule: int, value: float, extra: dict) -> bool:
        index = self.index
        if name not in index or (other is not None and other not in index):
            return False
        values = {"ENTITY": index[name], "OTHER": -1.0 if other is None else index[other]}
        values |= {"QUANTITY": _GUARDED[quantity], "RULE": rule, "VALUE": value}
        self.guards.extend(core_row("guard", values | extra))
        return True


def _columns(
    ctx, entities, synced: dict[str, float], turn: float, kept: dict[str, str] | None = None,
    cruising: dict[str, float] | None = None,
) -> tuple[tuple, list[float], QuietBounds] | None:  # fmt: skip
    """The core's columns of every road user and the bounds of their steps, or None when one moves
    otherwise than by cruising along its lane or path (or straight on) at its speed, the speed a
    synchronisation (``synced``: road user -> the speed it heads for) or a SpeedAction's transition
    gives it, the speed of the road user it keeps its distance to (``kept``: road user -> that one),
    the speed its adaptive cruise gives it (``cruising``: road user -> the fastest it may command), or
    along a timed path."""
    ways, cols, dt = [], [], ctx.dt
    kept, cruising = kept or {}, cruising or {}
    # (a trailer's speed is its tow's, a keeper's its reference's, a cruise's its own: taken as changing)
    varying = synced.keys() | kept.keys() | cruising.keys()
    varying |= {e.name for e in entities if not e.deleted and (e.speed_profile is not None or _timed(e) or e.towed_by)}
    index = {e.name: i for i, e in enumerate(entities)}
    bounds = QuietBounds({}, {}, turn, varying=frozenset(varying), index=index)
    for e in entities:
        if e.deleted:
            ways.append(None)
            cols += _absent(e)
            continue
        f = e.follower
        # (a kept one's speed is the core's, a cruising one's its cruise's: a transition left is not read)
        p = e.speed_profile if e.name not in kept and e.name not in cruising else None
        row = {"X": e.x, "Y": e.y, "YAW": e.yaw, "CENTER_X": e.center_x, "LENGTH": e.length, "WIDTH": e.width}
        row |= {"ODOMETER": e.odometer, "SPEED": e.speed, "LAST_MOVED": e.last_step_m, "ACCEL": e.accel}
        row |= {"PROFILE": -1.0, "TOW": -1.0}
        if e.towed_by is not None:  # (pulled after everyone has moved, front to back)
            chain = _chain(ctx.entities, e)
            if chain is None or e.placed or p is not None or ctx.entities[e.towed_by].hitch_dx is None:
                return None
            tow = ctx.entities[e.towed_by]
            reach = (abs(e.speed) + SPEED_MARGIN_MPS) * dt + abs(tow.hitch_dx) * min(turn, math.pi)
            move = bounds.move[e.name] = reach * 1.05 + 1e-9
            bounds.along[e.name] = 0.0
            ways.append(None)
            row |= {"MODE": _TOWED, "MAX_MOVE": move, "TOW": index[tow.name], "HITCH": tow.hitch_dx}
            cols += _row(row | {"COUPLER": e.coupler_dx, "CHAIN": chain})
            continue
        timed = _timed(e)
        lateral = _lateral(ctx, e) if e.lateral is not None else {}
        if (
            e.placed or lateral is None or e.find_lane or (any(e.active.values()) and e.name not in cruising)
            or (f is not None and f.polyline.xs is None)
            or (p is not None and (e.name in synced or p.shape not in _SHAPES or timed))
        ):  # fmt: skip
            return None
        st = e.lane
        if timed:  # along its timed path (its time moves it)
            ways.append(f.polyline.core)
            domain, scale, offset = f.timing
            row |= {"MODE": _TIMED if f.mode == "position" else _TIMED_FOLLOW, "S": f.s, "TIME_SCALE": scale}
            row["TIME_BASE"], row["TIME_OFFSET"] = 0.0 if domain == "absolute" else f.t_start, offset
            row["TIME_END"] = f.polyline.ts[-1] if not f.finished(ctx.t, dt) else math.nan  # (NaN: action over)
            row["MAX_ACCEL"], row["MAX_DECEL"] = e.limits.max_accel_mps2, e.limits.max_decel_mps2
        elif f is not None:  # along its path (an untimed one: the speed moves it)
            ways.append(f.polyline.core)
            row |= {"MODE": _PATH, "S": f.s, "FORWARD": 1.0 if f.reverse else 0.0}
            row["PAST_END"] = 0.0 if e.modelled else 1.0  # (engine._motion: on past its end without a model)
        elif st is not None:
            ways.append(ctx.roads.road(st.road).core)
            row |= {"MODE": _LANE_MODE, "S": st.s, "LANE": st.lane, "OFFSET": st.offset, "HEADING": st.heading}
            row["FORWARD"] = 1.0 if st.forward else 0.0
        else:
            ways.append(None)
            row["MODE"] = _STRAIGHT
        if e.name in kept:  # (placed at its gap, then on at the other's speed: about as far as that one)
            ref = ctx.entities[kept[e.name]]
            q = ref.speed_profile
            fastest = max(abs(e.speed), abs(ref.speed), *((abs(q.v0), abs(q.v1)) if q is not None else ()))
            reach = (fastest + SPEED_MARGIN_MPS) * dt
        elif e.name in cruising:  # (its cruise's speed: at most the fastest it may command)
            reach = (max(abs(e.speed), cruising[e.name]) + SPEED_MARGIN_MPS) * dt
        elif e.name in synced:
            # (a synchronisation's speed: heading for its final speed, bounded by the margin beyond
            # it; the core stops before a step past the bound)
            reach = (max(abs(e.speed), synced[e.name]) + SPEED_MARGIN_MPS) * dt
        elif timed:  # (a timed path's speed: bounded by the margin, the core stops past it)
            reach = (abs(e.speed) + SPEED_MARGIN_MPS) * dt
        elif p is not None:  # (a transition's speed lies between where it is and where it ends)
            reach = max(abs(e.speed), abs(p.v0), abs(p.v1)) * dt
        else:
            reach = abs(e.speed * dt)
        if lateral:  # (and sideways: the offset's change, at the steepest a shape has, and lanes widening)
            step = dt if lateral["LAT_BY_TIME"] else reach
            reach += (abs(lateral["LAT_START_REL"] - lateral["LAT_TARGET_OFFSET"]) * 1.6 + 0.1) * step / e.lateral.value
            row |= lateral
        row["MAX_MOVE"] = bounds.move[e.name] = reach * 1.05 + 1e-9
        row["MAX_DS"] = bounds.along[e.name] = reach * 1.3 + 1e-9
        if p is not None:
            row |= {"PROFILE": _SHAPES[p.shape], "PROFILE_V0": p.v0, "PROFILE_V1": p.v1}
            row["PROFILE_T0"], row["PROFILE_DURATION"] = p.t0, p.duration
        cols += _row(row)
    return tuple(ways), cols, bounds


def _lateral(ctx, e) -> dict[str, float] | None:
    """The core columns of ``e``'s running lane change or lane offset (actions.LaneChangeRuntime), or
    None when the core does not take it: off a lane, a step shape, already complete."""
    rt, st, p = e.lateral, e.lane, e.speed_profile
    if st is None or e.follower is not None or rt.shape not in _SHAPES or not rt.value > 0:
        return None
    if rt.start_rel is None or rt.fraction >= 1.0 or rt.dimension not in ("time", "distance"):
        return None
    road = ctx.roads.road(st.road)
    # (LaneChangeRuntime._t: the target's centre held within its section; the core leaves a step where
    # that puts it in another section, whose lanes the interpreter maps, to the interpreter)
    lo, hi, section = -math.inf, math.inf, -1.0
    where = rt.target_where
    if where is not None and where[0] == road.id and where[1] < len(road.sections):
        (lo, hi), section = road.section_span(where[1]), float(where[1])
    prev = rt.prev_xy if rt.prev_xy is not None else (math.nan, math.nan)
    return {
        "LATERAL": 1.0, "LAT_SHAPE": _SHAPES[rt.shape], "LAT_BY_TIME": 1.0 if rt.dimension == "time" else 0.0,
        "LAT_VALUE": rt.value, "LAT_T0": rt.t0, "LAT_ODO0": rt.odo0, "LAT_AHEAD": float(rt.steps_ahead),
        "LAT_PROJECTS": 1.0 if rt.projects_step else 0.0, "LAT_TARGET_LANE": float(rt.target_lane),
        "LAT_TARGET_OFFSET": rt.target_offset, "LAT_START_REL": rt.start_rel, "LAT_LO": lo, "LAT_HI": hi,
        "LAT_SECTION": section, "LAT_FRACTION": rt.fraction, "LAT_PARAM": rt.param,
        "LAT_OLD_SPEED": float(rt.projects_step and p is not None and p.order > rt.order),
        "PREV_X": prev[0], "PREV_Y": prev[1],
    }  # fmt: skip


def _chain(entities: dict, trailer) -> int | None:
    """Where ``trailer`` is in its chain (1: behind a tow that is not towed itself), or None when a
    link is not one the interpreter pulls (a deleted one, a tow that names another trailer)."""
    depth, e = 0, trailer
    while e.towed_by is not None:
        tow = entities[e.towed_by]
        if e.deleted or tow.deleted or tow.trailer != e.name or depth > len(entities):
            return None
        depth, e = depth + 1, tow
    return depth


def _row(values: dict[str, float]) -> list[float]:
    """A road user's core columns from their values by name (the others 0)."""
    return core_row("road_user", values)


def _absent(e) -> list[float]:
    """The columns of a road user that is not there (deleted): it neither moves nor has a transition,
    and the core's poses repeat where it was left."""
    return _row({"MODE": -1.0, "PROFILE": -1.0, "X": e.x, "Y": e.y, "YAW": e.yaw, "SPEED": e.speed, "ACCEL": e.accel})


def _timed(e) -> bool:
    """Whether ``e`` follows a timed path (its trajectory's time, not its speed, moves it)."""
    f = e.follower
    return f is not None and f.plays_time


@dataclass
class _Stepped:
    """The actions stepping before the moves as the core takes them: the synchronisations, their
    columns and their distances' road programs; the distance keepers and their columns."""

    syncs: list = field(default_factory=list)
    sync_cols: list = field(default_factory=list)
    programs: list = field(default_factory=list)
    keeps: list = field(default_factory=list)
    keep_cols: list = field(default_factory=list)
    follows: list = field(default_factory=list)  # (a continuous relative speed, whether it had a profile)


def _stepped(ctx, entities: list) -> _Stepped | None:
    """The actions setting speeds or places before the moves in the core's columns, or None when one
    does it as the core does not (or a synchronisation's distances are not along the path or roads its
    parties keep). The core places the distance keepers before the synchronisations step, so they must
    come first here too, and none sets a master's speed. Keepers are placed in the interpreter's order,
    each from where the ones before it were put, so one may keep its distance to another (a platoon:
    tests/test_cruise_keep.py). A continuous relative speed reads its reference's speed at the step's
    start, as the core."""
    from vei_scenario.interpreter.actions import Speed
    from vei_scenario.interpreter.longitudinal import LongitudinalDistance
    from vei_scenario.interpreter.synchronize import Synchronize

    out = _Stepped()
    index = {n: i for i, n in enumerate(ctx.entities)}
    for e in entities:
        a = e.longitudinal
        if type(a) is Speed and a.continuous and not a.done and not e.deleted:
            c = a.core_columns(ctx, index)
            if c is None:
                return None
            out.keeps.append(a)
            out.keep_cols += c
            out.follows.append((a, e.speed_profile is not None))
    for a in ctx.stepping:
        if type(a) is LongitudinalDistance and not out.syncs:
            c = a.core_columns(ctx, index)
            if c is None:
                return None
            out.keeps.append(a)
            out.keep_cols += c
            continue
        c = a.core_columns(ctx, index, out.programs) if type(a) is Synchronize else None
        if c is None:
            return None
        out.syncs.append(a)
        out.sync_cols += c
    actions = out.syncs
    synced = {a.entity for a in actions}
    if len(synced) < len(actions) or any(a.master in synced for a in actions):
        return None
    kept = {a.entity for a in out.keeps}
    if len(kept) < len(out.keeps) or kept & (synced | {a.master for a in actions}):
        return None
    if any(a.final is not None and a.final[0] == "relative" and ctx.entities[a.master].speed_profile for a in actions):
        return None  # (a final speed relative to a master whose speed changes: worked out each step)
    return out


@dataclass
class _Cruises:
    """The controllers in charge of road users that the core steps (the adaptive cruises) and their columns."""

    controllers: list = field(default_factory=list)
    cols: list = field(default_factory=list)
    fastest: dict = field(default_factory=dict)  # road user -> the fastest speed its cruise may command


def _cruises(ctx, entities: list, stepped: _Stepped, sequential: bool) -> _Cruises | None:
    """The controllers in charge of road users, as the core steps them, or None when one is not a
    controller the core steps (``core_columns``), shares its road user with another, or the road users
    are where it would not know whom an adaptive cruise follows: every other one keeps its lane without
    changing lanes (the core reads road points from lane states), and no action places a road user or sets
    its speed before the moves (the core's order would differ from the interpreter's)."""
    out = _Cruises()
    index = None
    for e in entities:
        if e.deleted or not any(e.active.values()):
            continue
        ctrls = {id(c): c for c in e.active.values() if c is not None}
        if len(ctrls) != 1 or stepped.keeps or stepped.syncs:
            return None
        (ctrl,) = ctrls.values()
        if not _core_stepped(ctrl):
            return None
        if index is None:
            index = {o.name: i for i, o in enumerate(entities)}
            if not all(o.deleted or (o.lane is not None and o.follower is None and o.lateral is None
                                     and o.towed_by is None) for o in entities if o is not e):  # fmt: skip
                return None
        cols = ctrl.core_columns(e, ctx, index, sequential)
        if cols is None:
            return None
        out.controllers.append(ctrl)
        out.cols += cols
        out.fastest[e.name] = max(abs(ctrl.current), abs(ctrl.set_speed))
    return out


def offered(entities: list) -> bool:
    """Whether the controllers in charge of road users leave a quiet stretch to the core at all: none,
    or only ones the core steps (their ``core_columns``)."""
    return all(_core_stepped(c) for e in entities for c in e.active.values() if c is not None)


def _core_stepped(ctrl) -> bool:
    """Whether the core steps controller ``ctrl`` in its quiet stretches (it gives the core its columns)."""
    return hasattr(ctrl, "core_columns")


class StepTimes:
    """The simulation times of the ``n`` steps after step ``step0`` (as the engine rounds them),
    computed when asked for."""

    def __init__(self, step0: int, dt: float, n: int) -> None:
        self.step0, self.dt, self.n = step0, dt, n

    def __len__(self) -> int:
        return self.n

    def __getitem__(self, i: int) -> float:
        if i < 0:
            i += self.n
        if not 0 <= i < self.n:
            raise IndexError(i)
        return step_time(self.step0 + 1 + i, self.dt)

    def between(self, i: int, j: int) -> list[float]:
        """Times ``i`` to ``j`` (exclusive), at once."""
        return step_times(self.step0 + 1 + i, self.step0 + 1 + j, self.dt)

    def count_at_or_before(self, limit: float) -> int:
        """How many of the times are at or before ``limit``."""
        return count_at_or_before(self.step0 + 1, self.step0 + 1 + self.n, self.dt, limit)

    def __iter__(self):
        return iter(self.between(0, self.n))


def steps_left(ctx, max_time: float) -> int:
    """Steps the run still takes before its time limit (the engine loops while t < max_time), at most
    CHUNK."""
    step, dt = ctx.step, ctx.dt
    n = max(0, min(CHUNK, int((max_time - 1e-9) / dt) - step + 2))
    while n > 0 and step_time(step + n - 1, dt) >= max_time - 1e-9:
        n -= 1
    while n < CHUNK and step_time(step + n, dt) < max_time - 1e-9:
        n += 1
    return n


def cruise(ctx, storyboard, entities: list, recording, max_time: float, offers: Offers, sequential: bool = True) -> int:
    """Take this step's move and as many quiet steps after it as nothing can happen in, in the core;
    record them. The number of steps taken (0: none, the step goes on as usual); ``offers``: when to
    offer again; ``sequential``: the coupling (False: Jacobi, an adaptive cruise sees everyone as the
    step began)."""
    offers.wait = RETRY_STEPS  # (not quiet now: a few steps later it may be)
    triggers = storyboard.watching()
    if triggers is None:
        return 0
    stepped = _stepped(ctx, entities)
    if stepped is None:
        return 0
    actions = stepped.syncs
    cruises = _cruises(ctx, entities, stepped, sequential)
    if cruises is None:
        return 0
    dt = ctx.dt
    runners = [c for t in triggers for c in t.conditions()]
    turn = TURN_RATE * dt if any(c.condition.reads_turning for c in runners) else math.inf
    kept = {a.entity: a.ref for a in stepped.keeps}
    columns = _columns(ctx, entities, {a.entity: a.speed_heading(ctx) for a in actions}, turn, kept, cruises.fastest)
    if columns is None:
        return 0
    ways, cols, bounds = columns
    skipped = steps_left(ctx, max_time) - 1  # evaluations after this step's that the cruise replaces
    for c in runners:
        if skipped < MIN_STEPS:
            return 0
        skipped = min(skipped, c.condition.steady_steps(ctx, bounds))
    if skipped < MIN_STEPS:
        return 0
    step0 = ctx.step
    held = {c: c.held(ctx) for c in runners}
    for t in triggers:
        skipped = min(skipped, t.first_firing(held, StepTimes(step0, dt, skipped)))
    if skipped < MIN_STEPS:
        return 0
    f64 = array.array
    tables = (cols, stepped.sync_cols, stepped.keep_cols, cruises.cols, stepped.programs, bounds.guards)
    columns = tuple(f64("d", table).tobytes() for table in tables)
    clock = packed_step_times(step0, step0 + skipped + 1, dt)  # (each step's start)
    n, poses, state, sync_state, keep_state, acc_state, edge = _core.cruise(ways, *columns, clock, bounds.turn, dt)
    # The core stops before a step that is not quiet (an action ending, a guard's comparison turning):
    # the interpreter takes that one, and the steps after it are offered again at once, unless the
    # core has refused the first step before (a state that lasts, such as a distance on its threshold).
    # A road user starting or stopping (``edge``) is an event of one step, and a few may come in a row
    # (a synchronisation starts one road user, a kept distance its follower the step after): offered
    # again at once up to EDGE_RETRIES times (a speed flickering about zero would otherwise be offered
    # every step).
    if n == 0:
        offers.refusals += 1
        offers.wait = 0 if offers.refusals == 1 or (edge and offers.refusals <= EDGE_RETRIES) else RETRY_STEPS
        return 0
    offers.refusals = 0
    offers.wait = 1 if n < skipped + 1 else 0  # (stopped early: the next step is the one it stopped before)
    for c in runners:
        c.skip(StepTimes(step0, dt, n - 1), held[c])
    sync_state = memoryview(sync_state).cast("d")
    for k, a in enumerate(actions):
        a.take_core_columns(sync_state[k * _SY_COLS : (k + 1) * _SY_COLS])
    keep_state = memoryview(keep_state).cast("d")
    follows = len(stepped.follows)
    for k, a in enumerate(stepped.keeps[follows:], follows):
        a.take_core_columns(keep_state[k * _KP_COLS : (k + 1) * _KP_COLS])
    acc_state = memoryview(acc_state).cast("d")
    for k, ctrl in enumerate(cruises.controllers):
        ctrl.take_core_columns(acc_state[k * _AC_COLS : (k + 1) * _AC_COLS])
    state = memoryview(state).cast("d")
    statuses = [_STATUS.get(state[i * _COLS + _MODE], "default") if not e.deleted else "deleted"
                for i, e in enumerate(entities)]  # fmt: skip
    for i, e in enumerate(entities):
        if e.name in cruises.fastest:
            statuses[i] = "acc"
    recording.record_core(step_times(step0 + 1, step0 + 1 + n, dt), poses, statuses)
    _commit(ctx, entities, memoryview(poses).cast("d"), state, statuses, n)
    ctx.step = step0 + n
    ctx.t = step_time(ctx.step, dt)
    for a, stepped_before in stepped.follows:
        a.after_core(ctx, stepped_before)
    return n


def _commit(ctx, entities: list, poses, state, statuses: list[str], n: int) -> None:
    """The road users as the core left them after ``n`` steps (``statuses``: what each was doing)."""
    k = len(entities)
    for i, e in enumerate(entities):
        col = state[i * _COLS : (i + 1) * _COLS]
        e.status = statuses[i]
        if e.deleted:
            e.last_step_m = 0.0
            continue
        last = 6 * (n - 1) * k + 6 * i
        e.step_speed = poses[last - 6 * k + 4] if n > 1 else e.speed  # (the speed the last step began at)
        e.x, e.y, e.yaw, e.speed = col[_X], col[_Y], col[_YAW], col[_SPEED]
        e.accel = poses[last + 5]
        e.last_step_m, e.odometer = poses[last + 3], col[_ODO]
        if e.follower is not None:
            e.follower.s = col[_S]
        elif e.lane is not None:
            e.lane.s, e.lane.lane = col[_S], int(col[_LANE])
            if e.lateral is not None:  # (a lane change or offset under way)
                e.lane.offset, e.lateral.fraction, e.lateral.param = col[_OFFSET], col[_FRACTION], col[_PARAM]
                e.lateral.prev_xy = None if math.isnan(col[_PREV_X]) else (col[_PREV_X], col[_PREV_Y])
        if e.towed_by is not None:  # (trailers.pull: a trailer's standstill is not counted)
            continue
        if abs(e.speed) < 1e-9:
            if e.standing_since is None:
                e.standing_since = ctx.t + ctx.dt
        else:
            e.standing_since = None
