"""Adaptive cruise control as esmini 3.6 plays its ``ACCController`` (and ``ALKSController``, which is
the same longitudinal control keeping the lane offset it has).

Why it is here: the ALKS test scenarios (UN R157, the openMSL set) and esmini's own ACC examples put
the system under test on the ego as such a controller. Playing them the way the reference player does
needs its control law, measured against esmini's runs: ``benchmarks/conformance_esmini.py`` and
tests/test_acc.py. The law, in speed per step (no actuator lag, esmini's default controller then moves
the vehicle at the new speed):

* with nobody to follow, the speed approaches the set speed at ``approach_gain`` × max acceleration
  per m/s of error (capped at that fraction of the maximum, and at the maximum deceleration), without
  overshooting it;
* behind a leader at a bumper-to-bumper ``gap``, the wanted distance is
  ``follow = min_gap + time_gap · max(v, v_lead)``; with ``f = min(1, (gap − follow) / follow)`` the
  acceleration is ``2.5·f − f·(v − v_set) − (1 − f)·(v − min(v_set, v_lead))``, clamped to the
  vehicle's limits: far away it cruises, close in it matches the slower of leader and set speed, and
  too close it falls back; following never takes it above the set speed;
* a gap under ``stop_gap_m`` stops the vehicle at once (esmini's last resort, not physical).
"""

from __future__ import annotations

import math
from dataclasses import dataclass


@dataclass(frozen=True)
class AccParameters:
    #: Time gap to the leader (s), esmini's property ``timeGap``.
    time_gap_s: float = 1.5
    #: Half-width of the corridor (m) in which an entity in the ego's lane counts as a leader
    #: (esmini's ``lateralDist``: the lateral distance between reference points along the road).
    lateral_dist_m: float = 5.0
    #: Standstill distance kept to the leader (m).
    min_gap_m: float = 3.0
    #: Speed-error gain without a leader, as a fraction of the maximum acceleration per m/s.
    approach_gain: float = 0.7
    #: Gain of the distance term (m/s² at full distance factor).
    distance_gain_mps2: float = 2.5
    #: Below this bumper-to-bumper gap (m) the speed is set to zero at once.
    stop_gap_m: float = 1.0

    def lookahead_m(self, v_mps: float, max_decel_mps2: float) -> float:
        """How far ahead along the lane a leader is looked for: at least 50 m, else twice the
        standstill distance plus the distance to stop from ``v_mps``, twice over (esmini's horizon)."""
        return max(50.0, 2 * self.min_gap_m + v_mps * v_mps / max(max_decel_mps2, 1e-9))


def acc_speed(
    p: AccParameters,
    v_mps: float,
    set_speed_mps: float,
    lead: tuple[float, float] | None,
    max_accel_mps2: float,
    max_decel_mps2: float,
    dt: float,
) -> float:
    """The speed after one step of ``dt`` from ``v_mps``; ``lead`` is (bumper-to-bumper gap m, leader
    speed m/s), or None with nobody to follow."""
    if lead is None:
        a = (set_speed_mps - v_mps) * p.approach_gain * max_accel_mps2
        a = min(max(a, -max_decel_mps2), p.approach_gain * max_accel_mps2)
        v = v_mps + a * dt
        if abs(v - set_speed_mps) > abs(v_mps - set_speed_mps):  # (it would pass the set speed)
            return set_speed_mps
        return v
    gap, v_lead = lead
    if gap < p.stop_gap_m:
        return 0.0
    follow = p.min_gap_m + p.time_gap_s * abs(max(v_mps, v_lead))
    f = min(1.0, (gap - follow) / follow)
    dv_set = v_mps - set_speed_mps
    dv_min = v_mps - min(set_speed_mps, v_lead)
    a = p.distance_gain_mps2 * f - f * dv_set - (1.0 - f) * dv_min
    a = min(max(a, -max_decel_mps2), max_accel_mps2)
    return min(max(0.0, v_mps + a * dt), set_speed_mps)


def bumper_gap(
    ds_m: float, own_length: float, own_center_x: float, other_length: float, other_center_x: float, same_way: bool
) -> float:
    """The gap between the ego's front and the other's near end, from the distance ``ds_m`` between
    their reference points along the lane: the other's rear when both head the same way, its front
    when it comes towards the ego."""
    own_front = 0.5 * own_length + own_center_x
    other_near = 0.5 * other_length - other_center_x if same_way else 0.5 * other_length + other_center_x
    return ds_m - own_front - other_near


def close_ahead(x_gap: float, y_gap: float, other_length: float, closing_mps: float) -> bool:
    """An entity just ahead of the ego's box that the lane test may miss (half in the lane, or on
    another road): its box within ``1 + its length + half the closing speed`` metres in front, and
    laterally within 0.2 m to the left or 0.5 m to the right of the ego's box (esmini yields more on
    the right, for right-hand traffic). ``x_gap``/``y_gap``: the gaps between the boxes along and
    across the ego's heading (0 where they overlap in that direction; y positive to the left)."""
    return 0.0 < x_gap < 1.0 + other_length + 0.5 * max(0.0, closing_mps) and -0.5 < y_gap < 0.2


def box_gaps(own: tuple[float, float, float, float, float], other: tuple[float, float, float, float, float]):
    """The gaps between two boxes (centre x, centre y, yaw, length, width) along and across the first
    one's heading: signed (positive ahead / to the left), 0 where their extents overlap. The other box
    is measured by its extent along those axes (as the distance conditions measure freespace)."""
    x0, y0, yaw, length, width = own
    ox, oy, oyaw, ol, ow = other
    c, s = math.cos(yaw), math.sin(yaw)
    dx, dy = ox - x0, oy - y0
    along, across = c * dx + s * dy, -s * dx + c * dy
    cd, sd = abs(math.cos(oyaw - yaw)), abs(math.sin(oyaw - yaw))
    return (
        _gap(along, 0.5 * (ol * cd + ow * sd), 0.5 * length),
        _gap(across, 0.5 * (ol * sd + ow * cd), 0.5 * width),
    )


def _gap(centre: float, extent: float, half: float) -> float:
    """Signed gap between [-half, half] and [centre - extent, centre + extent], 0 where they overlap."""
    if centre - extent > half:
        return centre - extent - half
    if centre + extent < -half:
        return centre + extent + half
    return 0.0
