"""The e-scooter social force model (SFM): parameters and dynamics.

m·a = F_dest + F_rep, with F_dest = k (v_des − v), v_des = v0 (p_dest − p) / sqrt(|p_dest − p|² + σ²)
and F_rep = A·exp(−d/B)·n (d: distance from the ego's closest box point to the scooter; n: unit vector
from that point to the scooter). The step is the compiled core's (``vei_models.c``: the interpreter,
the sweep kernel and the FMUs run the same code). The compiler writes the parameters into the
scenario's controller properties.
"""

from __future__ import annotations

from array import array
from dataclasses import asdict, astuple, dataclass
from functools import cached_property

from vei_scenario.core import _core
from vei_scenario.models.properties import from_properties

RIDER_TYPES = ("replay", "normal", "aggressive")


@dataclass(frozen=True)
class SfmParameters:
    #: Desired cruising speed (m/s): shared e-scooters cruise at 4–5 m/s (the seed paper's range).
    v0_mps: float = 4.5
    #: Scooter plus rider mass (kg): ~15 kg scooter and an ~80 kg adult rider.
    mass_kg: float = 95.0
    #: Relaxation time towards the desired velocity (s); k = mass / tau. 0.5 s is the usual social-force
    #: value for cyclists and pedestrians (Helbing & Molnár 1995 use 0.5 s).
    tau_s: float = 0.5
    #: Smoothing length of the destination term (m): v_des fades out within ~σ of the destination.
    sigma_m: float = 1.0
    #: Repulsion strength A (N) and range B (m) from the ego's influential point.
    repulsion_n: float = 600.0
    repulsion_range_m: float = 2.0
    #: Switch to the next route waypoint within this distance (m).
    waypoint_radius_m: float = 2.0
    #: E-scooter limits: 25 km/h (EU cap), 2.0 m/s² acceleration, 3.5 m/s² braking.
    max_speed_mps: float = 6.94
    max_accel_mps2: float = 2.0
    max_decel_mps2: float = 3.5

    @property
    def k_n_s_per_m(self) -> float:
        return self.mass_kg / self.tau_s

    def properties(self) -> dict[str, float]:
        return asdict(self)

    @cached_property
    def packed(self) -> bytes:
        """The parameters as the core's ``VeiSfmParams`` (its field order is this class's)."""
        return array("d", astuple(self)).tobytes()

    @classmethod
    def from_properties(cls, props: dict[str, str]) -> SfmParameters:
        return from_properties(cls, props)


@dataclass
class SfmState:
    """Point-mass state of a scooter in the scenario frame (m, m/s) and the route waypoint it steers at."""

    x: float
    y: float
    vx: float
    vy: float
    waypoint: int = 0


def sfm_step(
    state: SfmState,
    route: list[tuple[float, float]],
    params: SfmParameters,
    repulsive: bool,
    ego_box: tuple[float, float, float, float, float] | None,
    dt: float,
) -> SfmState:
    """One explicit step of the rider (the compiled core's ``vei_sfm_step``).

    The rider steers at successive waypoints of its recorded route: the next one becomes the
    destination once it is within ``waypoint_radius_m`` of the current one or has passed it (its
    projection onto the route segment lies beyond it). a = (F_dest + F_rep) / m with
    F_dest = k (v_des − v), v_des = v0 (p_dest − p) / sqrt(|p_dest − p|² + σ²), k = m/τ, and
    F_rep = A exp(−d/B) n from the closest point of the ego's box (x, y, yaw, length, width), n from
    that point to the rider (from the box centre when inside it); ``repulsive=False`` is the
    aggressive, non-cooperative rider. The acceleration is bounded along the track by the drive and
    brake limits and in total by the brake limit, the speed by ``max_speed_mps``; positions advance
    with the mean of the old and new velocities.
    """
    rx = array("d", [p[0] for p in route]).tobytes()
    ry = array("d", [p[1] for p in route]).tobytes()
    x, y, vx, vy, wp = _core.sfm_step(
        state.x, state.y, state.vx, state.vy, state.waypoint, rx, ry, params.packed, repulsive, ego_box, dt
    )
    return SfmState(x, y, vx, vy, wp)
