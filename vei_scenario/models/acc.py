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

The law and the geometry it reads are the compiled core's (``vei_models.c``): the interpreter's own
steps call them here, and the core's quiet stretches (interpreter/cruise.py) step them in C.
"""

from __future__ import annotations

from array import array
from dataclasses import astuple, dataclass
from functools import cached_property

from vei_scenario.core import _core


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
        return _core.acc_lookahead(self.packed, v_mps, max_decel_mps2)

    @cached_property
    def packed(self) -> bytes:
        """The parameters as the core's ``VeiAccParams`` (its field order is this class's)."""
        return array("d", astuple(self)).tobytes()


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
    gap, v_lead = lead if lead is not None else (0.0, 0.0)
    return _core.acc_speed(p.packed, v_mps, set_speed_mps, lead is not None, gap, v_lead, max_accel_mps2,
                           max_decel_mps2, dt)  # fmt: skip


def bumper_gap(
    ds_m: float, own_length: float, own_center_x: float, other_length: float, other_center_x: float, same_way: bool
) -> float:
    """The gap between the ego's front and the other's near end, from the distance ``ds_m`` between
    their reference points along the lane: the other's rear when both head the same way, its front
    when it comes towards the ego."""
    return _core.bumper_gap(ds_m, own_length, own_center_x, other_length, other_center_x, same_way)


def close_ahead(x_gap: float, y_gap: float, other_length: float, closing_mps: float) -> bool:
    """An entity just ahead of the ego's box that the lane test may miss (half in the lane, or on
    another road): its box within ``1 + its length + half the closing speed`` metres in front, and
    laterally within 0.2 m to the left or 0.5 m to the right of the ego's box (esmini yields more on
    the right, for right-hand traffic). ``x_gap``/``y_gap``: the gaps between the boxes along and
    across the ego's heading (0 where they overlap in that direction; y positive to the left)."""
    return _core.close_ahead(x_gap, y_gap, other_length, closing_mps)


def box_gaps(
    own: tuple[float, float, float, float, float], other: tuple[float, float, float, float, float]
) -> tuple[float, float]:
    """The gaps between two boxes (centre x, centre y, yaw, length, width) along and across the first
    one's heading: signed (positive ahead / to the left), 0 where their extents overlap. The other box
    is measured by its extent along those axes (as the distance conditions measure freespace)."""
    return _core.box_gaps(own, other)
