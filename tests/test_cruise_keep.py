"""Quiet stretches through a continuous LongitudinalDistanceAction without dynamic constraints (Euro
NCAP CCFhol's obstruction vehicle, esmini's drop-bike): the core places the keeping road user at its gap
before everyone moves, gives it its reference's speed, and the run equals the interpreter's step by step,
bit for bit (tests/test_cruise.py's ``run_both``).

The cases vary what the action reads (a distance or a time gap; between boxes or reference points; in the
entity's frame or along the road; behind, ahead or on the side it starts), what the reference does (a
speed transition, a synchronisation, another lane, the other direction on a curve) and what ends it (a
SpeedAction of its own taking over, the road's end); a condition on the kept gap makes an event react.
Each case also checks that the gap is kept where the road is straight (the comparison is not of two
runs equally wrong) and that the core took most steps where it can."""

from __future__ import annotations

import math

import numpy as np
import pytest
from test_cruise import ROAD, _entity, _lane, assert_identical, on_arc, run_both
from test_cruise_lateral import _event
from xosc_parts import step_speed


def _keep(ref: str, attrs: str, constraints: str = "") -> str:
    """A continuous LongitudinalDistanceAction to ``ref``; ``constraints``: DynamicConstraints' attributes."""
    inner = f"<DynamicConstraints {constraints}/>" if constraints else ""
    return (
        f'<PrivateAction><LongitudinalAction><LongitudinalDistanceAction entityRef="{ref}" continuous="true" {attrs}>'
        f"{inner}</LongitudinalDistanceAction></LongitudinalAction></PrivateAction>"
    )


def _follow_speed(ref: str, value: float, kind: str, seconds: float = 0.0) -> str:
    """A SpeedAction to ``ref``'s speed plus (``kind`` delta) or times (factor) ``value``, kept continuously."""
    shape = "step" if seconds == 0.0 else "linear"
    return (
        "<PrivateAction><LongitudinalAction><SpeedAction>"
        f'<SpeedActionDynamics dynamicsShape="{shape}" value="{seconds}" dynamicsDimension="time"/><SpeedActionTarget>'
        f'<RelativeTargetSpeed entityRef="{ref}" value="{value}" speedTargetValueType="{kind}" continuous="true"/>'
        "</SpeedActionTarget></SpeedAction></LongitudinalAction></PrivateAction>"
    )


def _at_time(t: float) -> str:
    return f'<ByValueCondition><SimulationTimeCondition value="{t}" rule="greaterThan"/></ByValueCondition>'


def _speed_change(actor: str, speed: float, at: float, seconds: float) -> str:
    action = (
        "<PrivateAction><LongitudinalAction><SpeedAction>"
        f'<SpeedActionDynamics dynamicsShape="linear" value="{seconds}" dynamicsDimension="time"/>'
        f'<SpeedActionTarget><AbsoluteTargetSpeed value="{speed}"/></SpeedActionTarget></SpeedAction>'
        "</LongitudinalAction></PrivateAction>"
    )
    return _event(f"{actor}_speed", actor, action, _at_time(at))


def _reacts(condition: str) -> str:
    """Other slows to 5 m/s once ``condition`` holds."""
    return _event("react", "Other", step_speed(5.0), condition)


def scenario(tmp_path, keeper_lane: int, keeper_s: float, keep: str, events: str, end: float = 14.0):
    """Lead (12 m/s, lane -1 of test_cruise's arc road, from s = 60) and Other (lane -2) drive on; Keeper
    starts on ``keeper_lane`` at ``keeper_s`` and keeps its distance by ``keep`` from the start."""
    (tmp_path / "arc.xodr").write_text(ROAD)
    names = ("Lead", "Keeper", "Other")
    keeper = _lane("Keeper", keeper_lane, keeper_s, 10.0).replace("</Private>", keep + "</Private>")
    xosc = tmp_path / "k.xosc"
    xosc.write_text(on_arc(names, f"{_lane('Lead', -1, 60, 12)}{keeper}{_lane('Other', -2, 20, 11)}", events, end))
    return xosc


GAP_CONDITION = _entity(
    '<RelativeDistanceCondition entityRef="Lead" relativeDistanceType="cartesianDistance" value="9.87" '
    'freespace="true" rule="lessThan"/>',
    who="Other",
)
#: (keeper's lane, its start s, the action's attributes, the gap expected on the straight: "d" a distance
#: between boxes, "ref" between reference points, "time" 1.5 s of the reference's speed, None: not checked)
CASES = {
    "behind_freespace_road": (-1, 40, 'distance="8" freespace="true" coordinateSystem="road"', ("box", 8.0)),
    "behind_points_road": (-1, 40, 'distance="8" freespace="false" coordinateSystem="road"', ("s", 8.0)),
    "behind_points_entity": (-1, 40, 'distance="8" freespace="false" coordinateSystem="entity"', None),
    "time_gap": (-1, 40, 'timeGap="1.5" freespace="true" coordinateSystem="entity"', ("box_time", 1.5)),
    "leading": (
        -1, 90, 'distance="6" freespace="true" displacement="leadingReferencedEntity" coordinateSystem="road"',
        ("box", -6.0),
    ),
    "any_side_ahead": (-2, 85, 'distance="5" freespace="false" displacement="any" coordinateSystem="road"', None),
    "other_lane": (-2, 45, 'distance="10" freespace="true" coordinateSystem="road"', None),
}  # fmt: skip


def _box_gap(a, b, i: int) -> float:
    """The free gap from a to b along a's heading at sample i (both cars: 4.5 m, centre 1.4 m ahead)."""
    c, s = math.cos(a.yaw[i]), math.sin(a.yaw[i])
    ax, ay = a.x[i] + 1.4 * c, a.y[i] + 1.4 * s
    bx, by = b.x[i] + 1.4 * math.cos(b.yaw[i]), b.y[i] + 1.4 * math.sin(b.yaw[i])
    d = c * (bx - ax) + s * (by - ay)
    return d - 4.5 if d > 0 else d + 4.5


@pytest.mark.parametrize("lead_moves", ["transition", "steady"])
@pytest.mark.parametrize("case", sorted(CASES))
def test_kept_distances_in_quiet_steps_equal_the_stepped_run(tmp_path, monkeypatch, case, lead_moves):
    lane, s0, attrs, expect = CASES[case]
    events = _reacts(GAP_CONDITION)
    if lead_moves == "transition":
        events += _speed_change("Lead", 16.0, 2.0, 3.0)
    fast, cruised, slow = run_both(scenario(tmp_path, lane, s0, _keep("Lead", attrs), events), monkeypatch)
    assert_identical(fast, slow)
    keeper, lead = fast.traces["Keeper"], fast.traces["Lead"]
    assert np.array_equal(keeper.speed[1:], lead.speed[:-1])  # (each step at the speed the reference had)
    straight = np.flatnonzero((lead.x < 95.0) & (keeper.x < 95.0) & (fast.t > 0.5))
    assert straight.size > 20
    if expect is not None:
        kind, value = expect
        for i in straight[::7]:
            if kind == "s":
                gap = lead.x[i] - keeper.x[i]  # (along the straight: s is x)
            else:
                gap = _box_gap(keeper, lead, i)
            want = value * lead.speed[i - 1] if kind == "box_time" else value
            # placed before the move, then both move a step at the speeds they had
            assert gap == pytest.approx(want, abs=abs(lead.speed[i] - lead.speed[i - 1]) * 0.01 + 1e-9), (case, i)
    assert cruised > 0.6 * len(fast.t), f"{case}: only {cruised} of {len(fast.t)} steps cruised"


def test_a_keeper_taken_over_or_at_the_road_end_steps_as_the_interpreter_does(tmp_path, monkeypatch):
    """A SpeedAction of the keeper's own ends the action in a stretch's middle; the reference drives on
    to the road's end and stands there while the keeper closes in."""
    events = _speed_change("Keeper", 3.0, 5.55, 1.0) + _reacts(GAP_CONDITION)
    keep = _keep("Lead", 'distance="8" freespace="true" coordinateSystem="road"')
    fast, cruised, slow = run_both(scenario(tmp_path, -1, 40, keep, events), monkeypatch)
    assert_identical(fast, slow)
    assert fast.traces["Keeper"].speed[-1] == 3.0 and cruised > 0.6 * len(fast.t)
    keep = _keep("Lead", 'distance="3" freespace="false" coordinateSystem="road"')
    fast, cruised, slow = run_both(scenario(tmp_path, -1, 40, keep, "", end=40.0), monkeypatch)
    assert_identical(fast, slow)
    assert fast.traces["Lead"].speed[-1] == 0.0 and cruised > 0.5 * len(fast.t)


#: Lead (lane -1) synchronised to reach s = 200 when Other (lane -2) does, at 9 m/s.
SYNCHRONISE_LEAD = (
    '<PrivateAction><SynchronizeAction masterEntityRef="Other"><TargetPositionMaster>'
    '<LanePosition roadId="1" laneId="-2" s="200"/></TargetPositionMaster><TargetPosition>'
    '<LanePosition roadId="1" laneId="-1" s="200"/></TargetPosition><FinalSpeed><AbsoluteSpeed value="9"/>'
    "</FinalSpeed></SynchronizeAction></PrivateAction>"
)


def test_a_keeper_of_a_synchronised_reference_and_one_started_after_it(tmp_path, monkeypatch):
    """Lead is synchronised to reach s = 200 when Other does; Keeper keeps its gap to Lead from the start
    (the core places it before the synchronisation steps, as the interpreter does) — and, in the second
    run, only from 1 s on, after the synchronisation (the interpreter steps it, the run is the same)."""
    sync = _event("sync", "Lead", SYNCHRONISE_LEAD, _at_time(0.2))
    keep = _keep("Lead", 'distance="8" freespace="true" coordinateSystem="road"')
    fast, cruised, slow = run_both(scenario(tmp_path, -1, 40, keep, sync), monkeypatch)
    assert_identical(fast, slow)
    lead = fast.traces["Lead"]
    assert np.ptp(lead.speed) > 1.0 and cruised > 0.6 * len(fast.t)  # (the synchronisation set its speeds)
    late = keep.replace("<PrivateAction>", "", 1).replace("</PrivateAction>", "", 1)
    later = _event("keep_late", "Keeper", f"<PrivateAction>{late}</PrivateAction>", _at_time(1))
    path = scenario(tmp_path, -1, 40, "", sync + later)
    fast, _, slow = run_both(path, monkeypatch)
    assert_identical(fast, slow)
    keeper, lead = fast.traces["Keeper"], fast.traces["Lead"]
    # (stepped after the synchronisation, it reads the speed that step gives the reference)
    assert np.array_equal(keeper.speed[-50:], lead.speed[-50:])
    assert abs(_box_gap(keeper, lead, 150) - 8.0) < 0.5


@pytest.mark.parametrize(
    "keep, why",
    [
        ({"ENTITY": 0.0, "REF": 2.0}, "not there"),
        ({"ENTITY": 1.0, "REF": 1.0}, "not there"),
        ({"ENTITY": 0.0, "REF": 1.0}, "keeps its lane"),  # (road user 0 drives straight on, off any lane)
    ],
)
def test_the_core_refuses_a_keep_it_cannot_place(keep, why):
    from test_cruise_distances import _straight

    from vei_scenario.core import _core, layout

    columns = layout("keep")
    row = [0.0] * len(columns)
    for name, v in ({"VALUE": 5.0, "SIDE": 1.0} | keep).items():
        row[columns[name]] = v
    state = np.asarray(_straight(0.0, 0.0, 0.0, 8.0) + _straight(50.0, 0.0, 0.0, 8.0), float).tobytes()
    clock = np.arange(10, dtype=float).tobytes()
    with pytest.raises(ValueError, match=why):
        _core.cruise((None, None), state, b"", np.asarray(row, float).tobytes(), b"", b"", b"", clock, math.inf, 0.1)


SPRINGS = {
    "distance": ('distance="12" freespace="true" coordinateSystem="entity"', 'maxAcceleration="3" maxDeceleration="5"'),
    "time_gap_rates": (
        'timeGap="1.2" freespace="true" coordinateSystem="entity" displacement="any"',
        'maxAcceleration="2.5" maxDeceleration="4" maxAccelerationRate="1.5" maxDecelerationRate="3" maxSpeed="14"',
    ),
    "along_road": (
        'distance="15" freespace="false" coordinateSystem="road"', 'maxAcceleration="2" maxDeceleration="6"'
    ),
}  # fmt: skip


@pytest.mark.parametrize("case", sorted(SPRINGS))
def test_a_kept_distance_with_dynamic_constraints_in_quiet_steps_equals_the_stepped_run(tmp_path, monkeypatch, case):
    """The spring (its acceleration limited, and the change of it where rates are given) drives Keeper
    to its gap behind Lead while Lead changes speed; Other keeps its own gap to Keeper with the same
    spring, stepped after it (it sees the speed Keeper's step set, as in the interpreter)."""
    attrs, constraints = SPRINGS[case]
    events = _reacts(GAP_CONDITION) + _speed_change("Lead", 16.0, 4.0, 3.0)
    second = _keep("Keeper", 'distance="9" freespace="true" coordinateSystem="entity"', "maxAcceleration=\"4\" "
                   'maxDeceleration="8"')  # fmt: skip
    path = scenario(tmp_path, -1, 20, _keep("Lead", attrs, constraints), events, end=16.0)
    text = path.read_text().replace(
        _lane("Other", -2, 20, 11), _lane("Other", -1, 2, 11).replace("</Private>", second + "</Private>")
    )
    path.write_text(text)
    fast, cruised, slow = run_both(path, monkeypatch)
    assert_identical(fast, slow)
    keeper, lead = fast.traces["Keeper"], fast.traces["Lead"]
    limits = [float(v) for v in (constraints.split('"')[1], constraints.split('"')[3])]
    assert np.all(np.diff(keeper.speed) <= limits[0] * 0.01 + 1e-9) and np.all(
        np.diff(keeper.speed) >= -limits[1] * 0.01 - 1e-9
    )
    assert np.ptp(keeper.speed) > 1.0  # (it did accelerate and brake)
    assert _box_gap(keeper, lead, -1) > 0.0  # (behind Lead)
    if "maxSpeed" in constraints:  # (held below Lead's 16 m/s: it falls back)
        assert keeper.speed.max() == 14.0 and _box_gap(keeper, lead, -1) > 30.0
    assert cruised > 0.5 * len(fast.t), f"{case}: only {cruised} of {len(fast.t)} steps cruised"


@pytest.mark.parametrize("where", ["init", "storyboard"])
@pytest.mark.parametrize("kind, value", [("delta", -1.5), ("factor", 0.8)])
def test_a_continuous_relative_speed_in_quiet_steps_equals_the_stepped_run(tmp_path, monkeypatch, where, kind, value):
    """Keeper takes Lead's speed (less 1.5 m/s, or 80 % of it) every step, from Init or from an event
    after a transition of its own, while Lead changes speed: the core gives it that speed each step."""
    follow = _follow_speed("Lead", value, kind, 0.0 if where == "init" else 1.0)
    events = _reacts(GAP_CONDITION) + _speed_change("Lead", 16.0, 4.0, 3.0)
    if where == "init":  # (its only longitudinal action: an Init step speed before it would keep it)
        path = scenario(tmp_path, -2, 40, follow, events)
        path.write_text(path.read_text().replace(step_speed(10.0) + follow, follow))
    else:
        start = _event("follow", "Keeper", follow, _at_time(0.5))
        path = scenario(tmp_path, -2, 40, "", events + start)
    fast, cruised, slow = run_both(path, monkeypatch)
    assert_identical(fast, slow)
    keeper, lead = fast.traces["Keeper"], fast.traces["Lead"]
    want = lead.speed[-101:-1] + value if kind == "delta" else lead.speed[-101:-1] * value
    assert np.array_equal(keeper.speed[-100:], want)  # (each step: the reference's speed at its start)
    assert cruised > 0.6 * len(fast.t), f"only {cruised} of {len(fast.t)} steps cruised"


@pytest.mark.parametrize("table", ["syncs", "keeps", "guards"])
def test_the_core_refuses_a_table_that_is_not_whole_rows(table):
    from test_cruise_distances import _straight

    from vei_scenario.core import _core

    state = np.asarray(_straight(0.0, 0.0, 0.0, 8.0), float).tobytes()
    tables = {"syncs": b"", "keeps": b"", "guards": b""} | {table: np.zeros(3).tobytes()}
    clock = np.arange(10, dtype=float).tobytes()
    with pytest.raises(ValueError, match=f"the {table} need their columns each"):
        _core.cruise((None,), state, tables["syncs"], tables["keeps"], b"", b"", tables["guards"], clock, math.inf, 0.1)


def _keeping(name: str, s: float, action: str) -> str:
    """Init: ``name`` standing on lane -1 at ``s``, given ``action``."""
    return _lane(name, -1, s, 0.0).replace("</Private>", action + "</Private>")


#: The chains of kept distances: (Keeper's to Lead, Other's to Keeper), by placing ("") or by the spring.
CHAINS = {
    "placed_placed": ("", ""),
    "spring_placed": ('maxAcceleration="3" maxDeceleration="5" maxSpeed="30"', ""),
    "placed_spring": ("", 'maxAcceleration="3" maxDeceleration="5" maxSpeed="30"'),
}


@pytest.mark.parametrize("order", ["lead_first", "lead_last"])
@pytest.mark.parametrize("chain", sorted(CHAINS))
def test_a_chain_of_kept_distances_in_quiet_steps_equals_the_stepped_run(tmp_path, monkeypatch, chain, order):
    """Other keeps its distance to Keeper, which keeps its own to Lead (a platoon set going from a
    standstill): the core places or springs them one after the other in the interpreter's order, each
    from where the one before it put its reference, and carries nearly the whole run."""
    (tmp_path / "arc.xodr").write_text(ROAD)
    first, second = CHAINS[chain]
    keeper = _keeping("Keeper", 40, _keep("Lead", 'distance="8" freespace="true"', first))
    other = _keeping("Other", 20, _keep("Keeper", 'timeGap="0.8" freespace="true"', second))
    inits = [_lane("Lead", -1, 60, 0.0), keeper, other]
    if order == "lead_last":
        inits.reverse()
    xosc = tmp_path / "k.xosc"
    xosc.write_text(on_arc(("Lead", "Keeper", "Other"), "".join(inits), _speed_change("Lead", 14.0, 1.0, 3.0), 14.0))
    fast, cruised, slow = run_both(xosc, monkeypatch)
    assert_identical(fast, slow)
    assert fast.traces["Other"].speed[-1] > 13.0  # (the chain followed Lead up to its speed)
    assert cruised > 0.95 * len(fast.t), (cruised, len(fast.t))


def test_road_users_setting_off_one_after_the_other_are_offered_to_the_core_at_once(tmp_path, monkeypatch):
    """Lead, standing, is synchronised from the start and Keeper, standing, keeps its distance to it
    (placed before the synchronisation steps: it sets off one step after Lead). The core
    refuses both steps, each a road user setting off (its ``edge``), and the engine offers the next step
    each time at once rather than waiting RETRY_STEPS after the second refusal in a row."""
    from vei_scenario.interpreter import engine

    (tmp_path / "arc.xodr").write_text(ROAD)
    keeper = _keeping("Keeper", 40, _keep("Lead", 'distance="8" freespace="true"'))
    lead = _keeping("Lead", 60, SYNCHRONISE_LEAD)
    xosc = tmp_path / "k.xosc"
    xosc.write_text(on_arc(("Lead", "Keeper", "Other"), keeper + lead + _lane("Other", -2, 20, 11.0), "", 6.0))
    offers: list[tuple[int, int]] = []
    original = engine.cruise

    def watching(ctx, *args):
        step = ctx.step
        n = original(ctx, *args)
        offers.append((step, n))
        return n

    monkeypatch.setattr(engine, "cruise", watching)
    fast, _, slow = run_both(xosc, monkeypatch)
    assert_identical(fast, slow)
    lead_off, keeper_off = (int(np.argmax(fast.traces[n].speed > 0.0)) for n in ("Lead", "Keeper"))
    assert 0 < lead_off and keeper_off == lead_off + 1  # (one, then the other)
    # (the steps they set off in refused in a row, then the next one offered and taken with most of the run)
    assert offers[:3] == [(lead_off - 1, 0), (keeper_off - 1, 0), (keeper_off, offers[2][1])], offers
    assert offers[2][1] > 0.8 * len(fast.t), offers
