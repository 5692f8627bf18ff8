"""Routes (AssignRouteAction, RoutePosition): waypoints joined by the shortest chain of roads.

A route is planned once, as esmini does for ``routeStrategy="shortest"``: from each waypoint to the
next, the chain of roads (through junctions' connecting roads) of least length, each road driven
towards increasing or decreasing s. An entity on a route takes, at a junction, the connecting road
its route goes on with; a RoutePosition lies ``pathS`` metres along the route from its first waypoint.
"""

from __future__ import annotations

import heapq
from dataclasses import dataclass

from vei_scenario.roads.road_model import RoadNetwork

#: (road id, s, driven towards increasing s there — None when either way will do)
Waypoint = tuple[str, float, "bool | None"]


@dataclass(frozen=True)
class Leg:
    road: str
    forward: bool  # driven towards increasing s
    s_from: float
    s_to: float

    @property
    def length(self) -> float:
        return abs(self.s_to - self.s_from)


def _exits(net: RoadNetwork, road_id: str, forward: bool) -> list[tuple[str, bool]]:
    """Roads reachable on leaving ``road_id`` at its end (forward) or start, with the direction they
    are then driven in."""
    road = net.road(road_id)
    link = road.successor if forward else road.predecessor
    if link is None:
        return []
    if link.kind == "road":
        nxt = (link.id, link.contact != "end")
        return [nxt] if link.id in net.roads and _drivable(net, *nxt) else []
    out = []
    for conn in net.junctions.get(link.id, []):
        if (
            conn.incoming == road_id
            and conn.connecting in net.roads
            and _drivable(net, conn.connecting, conn.contact != "end")
        ):
            out.append((conn.connecting, conn.contact != "end"))
    return out


def _drivable(net: RoadNetwork, road_id: str, forward: bool) -> bool:
    """Whether road ``road_id`` has a lane driven towards increasing s (``forward``) or decreasing s where
    it is entered: right lanes go with s in right-hand traffic, left lanes in left-hand traffic. A
    one-way road (a roundabout's ring, a connecting road of a junction) is not planned against its
    lanes (esmini's shortest route goes round a roundabout, not back through it)."""
    road = net.road(road_id)
    if not road.sections:
        return True
    lanes = (road.sections[0] if forward else road.sections[-1]).lanes
    return any(road.drives_forward(lane_id) == forward for lane_id in lanes if lane_id != 0)


def _leg_between(net: RoadNetwork, a: Waypoint, b: Waypoint) -> list[Leg] | None:
    """Shortest chain of legs from road position ``a`` to ``b``, arriving in the driving direction of
    ``b``'s lane when it has one (None when unreachable)."""
    (ra, sa, a_forward), (rb, sb, b_forward) = a, b
    if ra == rb:
        return [Leg(ra, sb >= sa, sa, sb)]
    best: list[Leg] | None = None
    best_cost = float("inf")
    heap: list = []
    n = 0
    for forward in (True, False) if a_forward is None else (a_forward,):
        road = net.road(ra)
        first = Leg(ra, forward, sa, road.length if forward else 0.0)
        heapq.heappush(heap, (first.length, n, [first]))
        n += 1
    seen: set[tuple[str, bool]] = set()
    while heap:
        cost, _, legs = heapq.heappop(heap)
        if cost >= best_cost:
            break
        last = legs[-1]
        if (last.road, last.forward) in seen:
            continue
        seen.add((last.road, last.forward))
        for nxt, fwd in _exits(net, last.road, last.forward):
            road = net.road(nxt)
            start = 0.0 if fwd else road.length
            if nxt == rb:
                end = Leg(nxt, fwd, start, sb)
                if b_forward is not None and fwd != b_forward:
                    continue
                if (sb >= start) == fwd or abs(sb - start) < 1e-9:
                    total = cost + end.length
                    if total < best_cost:
                        best, best_cost = [*legs, end], total
                continue
            leg = Leg(nxt, fwd, start, road.length if fwd else 0.0)
            heapq.heappush(heap, (cost + leg.length, n, [*legs, leg]))
            n += 1
    return best


def road_distance(net: RoadNetwork, a: tuple[str, float], b: tuple[str, float]) -> float | None:
    """Length of the shortest chain of roads from (road, s) ``a`` to ``b``, either way along each
    (None when none joins them): what ``_leg_between`` finds, summed in its order.

    Asked every step by a synchronisation, so the search runs once per pair of roads: the roads in
    between are driven whole, so only the first and last pieces depend on where ``a`` and ``b`` lie."""
    (ra, sa), (rb, sb) = a, b
    if ra == rb:
        return abs(sb - sa)
    la, lb = net.road(ra).length, net.road(rb).length
    if not (0.0 <= sa <= la and 0.0 <= sb <= lb):  # off a road's ends: the search itself
        legs = _leg_between(net, (ra, sa, None), (rb, sb, None))
        return sum(leg.length for leg in legs) if legs else None
    best = None
    for leave_forward, arrive_forward, middle in road_chains(net, ra, rb):  # (each piece >= 0, as Leg.length has it)
        total = la - sa if leave_forward else sa
        for length in middle:
            total += length
        total += sb if arrive_forward else lb - sb
        if best is None or total < best:
            best = total
    return best


def road_chains(net: RoadNetwork, ra: str, rb: str) -> list[tuple[bool, bool, tuple[float, ...]]]:
    """:func:`_chains_between` ``ra`` and ``rb``, searched once per network (kept in ``net.memo``)."""
    key = ("chains", ra, rb)
    chains = net.memo.get(key)
    if chains is None:
        chains = net.memo[key] = _chains_between(net, ra, rb)
    return chains


def _chains_between(net: RoadNetwork, ra: str, rb: str) -> list[tuple[bool, bool, tuple[float, ...]]]:
    """For each way of leaving ``ra`` and entering ``rb``: the lengths of the roads driven whole in
    between on the shortest such chain (absent when there is none)."""
    out = []
    for leave_forward in (True, False):
        best: dict[bool, tuple[float, tuple[float, ...]]] = {}
        heap: list = [(0.0, 0, ra, leave_forward, ())]
        seen: set[tuple[str, bool]] = set()
        n = 1
        while heap:
            cost, _, road_id, forward, middle = heapq.heappop(heap)
            if (road_id, forward) in seen:
                continue
            seen.add((road_id, forward))
            for nxt, fwd in _exits(net, road_id, forward):
                if nxt == rb:
                    if fwd not in best or cost < best[fwd][0]:
                        best[fwd] = (cost, middle)
                    continue
                length = net.road(nxt).length
                heapq.heappush(heap, (cost + length, n, nxt, fwd, (*middle, length)))
                n += 1
        out += [(leave_forward, arrive, middle) for arrive, (_, middle) in sorted(best.items(), reverse=True)]
    return out


@dataclass
class Route:
    legs: list[Leg]

    @property
    def roads(self) -> list[str]:
        return [leg.road for leg in self.legs]

    def at(self, path_s: float) -> tuple[Leg, float]:
        """The leg and the road s ``path_s`` metres along the route (clamped to its ends)."""
        left = max(path_s, 0.0)
        for leg in self.legs:
            if left <= leg.length or leg is self.legs[-1]:
                left = min(left, leg.length)
                return leg, leg.s_from + (left if leg.forward else -left)
            left -= leg.length
        raise ValueError("empty route")

    def next_road(self, current: str) -> str | None:
        """The road the route takes after ``current`` (None off the route or at its end)."""
        for a, b in zip(self.legs, self.legs[1:]):
            if a.road == current and b.road != current:
                return b.road
        return None


def plan_route(net: RoadNetwork, waypoints: list[Waypoint]) -> Route | None:
    """The route through ``waypoints`` (None when no chain of roads joins two of them), planned once
    per network and waypoints (kept in ``net.memo``: a sweep places the same route positions in every
    variant); each call gets its own Route of the same legs."""
    planned = net.memo.setdefault("routes", {})
    key = tuple(waypoints)
    if key not in planned:
        if len(planned) >= 4096:
            planned.clear()
        route = _plan(net, waypoints)
        planned[key] = None if route is None else tuple(route.legs)
    legs = planned[key]
    return None if legs is None else Route(list(legs))


def _plan(net: RoadNetwork, waypoints: list[Waypoint]) -> Route | None:
    legs: list[Leg] = []
    for a, b in zip(waypoints, waypoints[1:]):
        part = _leg_between(net, a, b)
        if part is None:
            return None
        if legs and legs[-1].road == part[0].road:  # join the legs on the waypoint's road
            legs[-1] = Leg(legs[-1].road, legs[-1].forward, legs[-1].s_from, part[0].s_to)
            part = part[1:]
        legs += part
    return Route(legs)
