"""Trailers (OpenSCENARIO 1.3): a trailer's coupler rides on its tow vehicle's hitch.

A vehicle may carry a ``TrailerHitch`` (dx ahead of its reference point, negative behind it) and a
``TrailerCoupler`` (dx ahead of the trailer's reference point, its rear axle), and name the trailer it
tows (``Trailer/TrailerRef``; ``ConnectTrailerAction`` / ``DisconnectTrailerAction`` change that at
run time). A towed trailer does not move by itself: after its tow vehicle has moved it is pulled like
a rod from the hitch — its axle moves towards the new hitch position, keeping the coupler-to-axle
length. That is the no-slip kinematics of a trailer on an axle (its axle moves along its heading only)
taken over one step, and in a steady turn it tracks inside the tow vehicle's path as a real trailer
does. Chains (a truck with two trailers) are pulled front to back.
"""

from __future__ import annotations

import math

from vei_scenario.core import _core


def hitch_point(tow) -> tuple[float, float]:
    """World position of ``tow``'s trailer hitch."""
    return tow.x + tow.hitch_dx * math.cos(tow.yaw), tow.y + tow.hitch_dx * math.sin(tow.yaw)


def place_behind(trailer, tow) -> None:
    """Put ``trailer`` in line behind ``tow``, its coupler on the hitch (a trailer connected in Init,
    or one connected during the run)."""
    hx, hy = hitch_point(tow)
    trailer.yaw = tow.yaw
    trailer.x = hx - trailer.coupler_dx * math.cos(tow.yaw)
    trailer.y = hy - trailer.coupler_dx * math.sin(tow.yaw)
    trailer.speed = tow.speed
    trailer.lane, trailer.follower, trailer.find_lane = None, None, False


def pull(trailer, tow, dt: float) -> None:
    """Move ``trailer`` after ``tow`` has moved: its axle towards the hitch, at the coupler distance
    (the core's towed_pose, the one its quiet steps take)."""
    x0, y0 = trailer.x, trailer.y
    trailer.x, trailer.y, trailer.yaw = _core.towed_pose(
        tow.x, tow.y, tow.yaw, tow.hitch_dx, trailer.coupler_dx, x0, y0, trailer.yaw
    )
    moved = _core.hypot(trailer.x - x0, trailer.y - y0)  # (as the core measures a step)
    trailer.last_step_m = moved
    trailer.odometer += moved
    trailer.accel = (tow.speed - trailer.speed) / dt if dt > 0 else 0.0
    trailer.speed = tow.speed
    trailer.status = "towed"


def hitches(entities: dict) -> list[tuple]:
    """Every (tow vehicle, trailer) pair, each chain from its front (a tow vehicle that is not towed
    itself) to its back, so that a trailer is moved after what pulls it."""
    out = []
    for e in entities.values():
        if e.trailer is None or e.towed_by is not None:
            continue
        tow, seen = e, {e.name}
        nxt = entities.get(e.trailer)
        while nxt is not None and nxt.name not in seen:
            out.append((tow, nxt))
            seen.add(nxt.name)
            tow, nxt = nxt, entities.get(nxt.trailer) if nxt.trailer else None
    return out


def connect(entities: dict, tow_name: str, trailer_name: str) -> None:
    """Hitch ``trailer_name`` to ``tow_name`` (where it stands; it is placed in line)."""
    tow, trailer = entities[tow_name], entities[trailer_name]
    if tow.trailer is not None:
        entities[tow.trailer].towed_by = None
    tow.trailer, trailer.towed_by = trailer_name, tow_name
    place_behind(trailer, tow)


def disconnect(entities: dict, tow_name: str) -> None:
    """Unhitch whatever ``tow_name`` pulls: the trailer stands where it is."""
    tow = entities[tow_name]
    if tow.trailer is None:
        return
    trailer = entities[tow.trailer]
    trailer.towed_by, tow.trailer = None, None
    trailer.speed, trailer.accel, trailer.speed_profile = 0.0, 0.0, None
    trailer.status = "default"
