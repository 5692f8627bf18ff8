"""Distances along chains of roads (a synchronisation's distance to its goal): the per-pair shortcut
against the full search, and against lengths worked out by hand."""

from __future__ import annotations

import random

import pytest

from vei_scenario.interpreter.routes import _leg_between, _plan, plan_route, road_distance
from vei_scenario.roads.road_model import RoadNetwork

LANES = (
    '<lanes><laneSection s="0"><left><lane id="1" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/>'
    '</lane></left><center><lane id="0" type="none"/></center><right><lane id="-1" type="driving">'
    '<width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></right></laneSection></lanes>'
)


def _road(rid: str, length: float, pred: str = "", succ: str = "", junction: str = "-1") -> str:
    link = f"<link>{pred}{succ}</link>"
    return (
        f'<road id="{rid}" length="{length}" junction="{junction}">{link}<planView>'
        f'<geometry s="0" x="0" y="0" hdg="0" length="{length}"><line/></geometry></planView>{LANES}</road>'
    )


def _to(kind: str, element: str, other: str, contact: str = "") -> str:
    cp = f' contactPoint="{contact}"' if contact else ""
    return f'<{kind} elementType="{element}" elementId="{other}"{cp}/>'


@pytest.fixture
def net(tmp_path) -> RoadNetwork:
    """Road 1 (100 m) ends in junction 9, which leads on to road 2 (80 m) by connecting road 10
    (20 m) or 11 (35 m); road 2 meets road 3 (60 m, drawn the other way) end to end; road 4 (50 m)
    joins nothing."""
    roads = [
        _road("1", 100, succ=_to("successor", "junction", "9")),
        _road("10", 20, _to("predecessor", "road", "1", "end"), _to("successor", "road", "2", "start"), "9"),
        _road("11", 35, _to("predecessor", "road", "1", "end"), _to("successor", "road", "2", "start"), "9"),
        _road("2", 80, _to("predecessor", "junction", "9"), _to("successor", "road", "3", "end")),
        _road("3", 60, succ=_to("successor", "road", "2", "end")),
        _road("4", 50),
    ]
    junction = (
        '<junction id="9"><connection id="0" incomingRoad="1" connectingRoad="10" contactPoint="start"/>'
        '<connection id="1" incomingRoad="1" connectingRoad="11" contactPoint="start"/>'
        '<connection id="2" incomingRoad="2" connectingRoad="10" contactPoint="end"/>'
        '<connection id="3" incomingRoad="2" connectingRoad="11" contactPoint="end"/></junction>'
    )
    path = tmp_path / "chain.xodr"
    path.write_text(f'<OpenDRIVE><header revMajor="1" revMinor="6"/>{"".join(roads)}{junction}</OpenDRIVE>')
    return RoadNetwork.load(path)


def test_distances_along_a_chain_match_the_lengths(net):
    # road 1 to its end, the shorter connecting road, road 2 whole, road 3 from its end back to s
    assert road_distance(net, ("1", 30.0), ("3", 45.0)) == pytest.approx(70 + 20 + 80 + 15, abs=1e-9)
    assert road_distance(net, ("3", 45.0), ("1", 30.0)) == pytest.approx(15 + 80 + 20 + 70, abs=1e-9)
    assert road_distance(net, ("2", 10.0), ("10", 5.0)) == pytest.approx(10 + 15, abs=1e-9)
    assert road_distance(net, ("1", 30.0), ("1", 75.5)) == 45.5
    assert road_distance(net, ("1", 30.0), ("4", 1.0)) is None


def test_distances_equal_the_full_search_everywhere(net):
    rng = random.Random(7)
    ids = list(net.roads)
    for _ in range(2000):
        a, b = rng.choice(ids), rng.choice(ids)
        sa, sb = rng.uniform(0, net.road(a).length), rng.uniform(0, net.road(b).length)
        sa = rng.choice([sa, 0.0, net.road(a).length])
        legs = _leg_between(net, (a, sa, None), (b, sb, None))
        expected = sum(leg.length for leg in legs) if legs else None
        assert road_distance(net, (a, sa), (b, sb)) == expected, (a, sa, b, sb)
    # a position beyond a road's end takes the full search
    legs = _leg_between(net, ("1", 120.0, None), ("2", 5.0, None))
    assert road_distance(net, ("1", 120.0), ("2", 5.0)) == sum(leg.length for leg in legs)


def test_routes_planned_once_are_the_routes_planned_afresh(net):
    """plan_route keeps what it planned per network; every call still gets the route a fresh search
    gives, as its own object (a caller changing its legs changes no later route)."""
    rng = random.Random(3)
    ids = list(net.roads)
    for _ in range(300):
        points = [(r, rng.uniform(0, net.road(r).length), rng.choice([None, True, False]))
                  for r in (rng.choice(ids) for _ in range(rng.randint(2, 3)))]  # fmt: skip
        fresh = _plan(net, points)
        for _ in range(2):
            route = plan_route(net, points)
            assert (route is None) == (fresh is None)
            if route is not None:
                assert route.legs == fresh.legs
                route.legs.clear()  # (the next call's legs are its own)
    assert plan_route(net, [("1", 30.0, True), ("4", 1.0, None)]) is None


def _roundabout(tmp_path) -> RoadNetwork:
    """The language module's roundabout: four two-way arms (two lanes each way) joined to a one-lane,
    one-way ring (anticlockwise: its arcs 11-14 have right lanes only)."""
    from vei_scenario.language.maps import build_map

    odr, _ = build_map({"kind": "roundabout", "lanes_per_direction": 2})
    path = tmp_path / "roundabout.xodr"
    odr.write_xml(str(path))
    return RoadNetwork.load(path)


def test_a_route_goes_round_a_one_way_ring_with_its_lanes(tmp_path):
    """From the arm on the ego's left (4) to the one ahead (3) the short way is a quarter of the ring
    against its lanes; esmini drives three quarters with them, and so does the plan now (before: the
    quarter backwards, 100-160 m from esmini's trajectories in tests/test_describe.py)."""
    net = _roundabout(tmp_path)
    ring = {"11", "12", "13", "14"}
    arm4 = net.road("4")
    route = plan_route(net, [("4", arm4.length - 1.0, True), ("3", 40.0, False)])
    assert route is not None
    on_ring = [leg for leg in route.legs if leg.road in ring]
    assert len(on_ring) == 3 and all(leg.forward for leg in on_ring)
    for leg in route.legs:  # every road is driven the way one of its lanes goes
        road = net.road(leg.road)
        lanes = (road.sections[0] if leg.forward else road.sections[-1]).lanes
        assert any((k < 0) == leg.forward for k in lanes if k != 0), leg


def test_a_road_user_in_an_unlinked_lane_stops_at_the_junction_as_in_esmini(tmp_path, monkeypatch):
    """A route's connecting road that is not linked from the road user's lane does not take it: it stops
    at the end of its road, as in esmini (before: it crossed into the linked lane nearest its own,
    whatever that lane's direction, and drove the exit lane back into the ring: 100-160 m from esmini).
    The map: the language module's roundabout with only the arms' lanes next to the centre line joined
    to the ring (as it was built before its outer lanes were joined too)."""
    from vei_scenario.language import maps

    monkeypatch.setattr(maps, "_outer_arm_lanes_to_ring", lambda *args: None)
    net = _roundabout(tmp_path)
    road = net.road("1")
    conns = [c for c in net.junctions[road.successor.id] if c.incoming == "1"]
    assert conns and all(-2 not in c.lane_links for c in conns)
    for c in conns:
        assert net.next_road(road, -2, True, prefer=c.connecting) is None
    entry = next(c for c in conns if -1 in c.lane_links)
    assert net.next_road(road, -1, True, prefer=entry.connecting)[:2] == (net.road(entry.connecting), -1)
