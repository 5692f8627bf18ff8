"""The rider agent's set-up from its recorded track: the waypoints the social force model steers at and
the speed it starts at. One definition for every engine: the interpreter's SocialForceController, the
sweep kernel's scene and the e-scooter FMUs' parameters all take them from here.

The track is any polyline with ``length``, ``at_s(s) -> (x, y, heading)``, the vertices' arc lengths
``s`` and times ``ts`` (:class:`vei_scenario.interpreter.entities.Polyline`).
"""

from __future__ import annotations

import math

#: Spacing of the route waypoints the social force model steers at (m). Closer waypoints would keep
#: the destination within ~σ of the rider and slow it below v0.
WAYPOINT_SPACING_M = 6.0
#: The recorded route ends where the camera lost the scooter, not where the rider stopped: the model
#: rider carries on straight for this far (m) instead of braking onto the last recorded point.
ROUTE_EXTENSION_M = 100.0


def rider_route(polyline) -> list[tuple[float, float]]:
    """The waypoints the rider steers at: every ~``WAYPOINT_SPACING_M`` along its recorded path, plus
    one ``ROUTE_EXTENSION_M`` beyond its end along the last heading."""
    n = max(1, int(polyline.length // WAYPOINT_SPACING_M))
    route = [polyline.at_s(polyline.length * (i + 1) / n)[:2] for i in range(n)]
    ex, ey, eh = polyline.at_s(polyline.length)
    route.append((ex + ROUTE_EXTENSION_M * math.cos(eh), ey + ROUTE_EXTENSION_M * math.sin(eh)))
    return route


def recorded_start_speed(polyline) -> float:
    """The speed of the recording's first segment: the model rider starts at it."""
    if len(polyline.ts) < 2:
        return 0.0
    return (polyline.s[1] - polyline.s[0]) / (polyline.ts[1] - polyline.ts[0])
