"""The e-scooter social force model (SFM): parameters and dynamics.

m·a = F_dest + F_rep, with F_dest = k (v_des − v), v_des = v0 (p_dest − p) / sqrt(|p_dest − p|² + σ²)
and F_rep = A·exp(−d/B)·n (d: distance from the ego's closest box point to the scooter; n: unit vector
from that point to the scooter). The step is the compiled core's (``vei_models.c``: the interpreter,
the sweep kernel and the FMUs run the same code); :func:`sfm_step_arrays` is its one vectorised form,
for the numpy batch engine, held equal to it by tests. The compiler writes the parameters into the
scenario's controller properties.
"""

from __future__ import annotations

from array import array
from dataclasses import asdict, astuple, dataclass
from functools import cached_property

import numpy as np

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
    """One explicit step of the rider (the compiled core's ``vei_sfm_step``; :func:`sfm_step_arrays`
    is the same step for arrays of riders, and tests hold the two equal).

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


def sfm_step_arrays(
    x: np.ndarray,
    y: np.ndarray,
    vx: np.ndarray,
    vy: np.ndarray,
    wp: np.ndarray,
    route: np.ndarray,
    params: SfmParameters,
    repulsive: np.ndarray | bool,
    ego_box: tuple | None,
    dt: float,
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """:func:`sfm_step` for many scooters at once (numpy arrays; ``route`` an (N, 2) array shared by
    all; ``ego_box`` (x, y, yaw, length, width) arrays). The same operations in the same order, so the
    two agree to rounding (tests/test_models.py compares them on 10 000 random states)."""
    x, y, vx, vy = (np.asarray(a, float) for a in (x, y, vx, vy))
    wp = np.asarray(wp, np.int64).copy()
    last = route.shape[0] - 1
    for _ in range(route.shape[0]):
        can = wp < last
        if not can.any():
            break
        w, n = route[wp], route[np.minimum(wp + 1, last)]
        near = np.hypot(w[..., 0] - x, w[..., 1] - y) <= params.waypoint_radius_m
        passed = (x - w[..., 0]) * (n[..., 0] - w[..., 0]) + (y - w[..., 1]) * (n[..., 1] - w[..., 1]) > 0
        advance = can & (near | passed)
        if not advance.any():
            break
        wp = wp + advance
    dest = route[wp]
    ex, ey = dest[..., 0] - x, dest[..., 1] - y
    scale = params.v0_mps / np.sqrt(ex * ex + ey * ey + params.sigma_m * params.sigma_m)
    k = params.k_n_s_per_m
    fx = k * (ex * scale - vx)
    fy = k * (ey * scale - vy)
    if ego_box is not None:
        bx, by, byaw, bl, bw = (np.asarray(v, float) for v in ego_box)
        c, s = np.cos(byaw), np.sin(byaw)
        dx, dy = x - bx, y - by
        lx = np.maximum(-0.5 * bl, np.minimum(0.5 * bl, c * dx + s * dy))
        ly = np.maximum(-0.5 * bw, np.minimum(0.5 * bw, -s * dx + c * dy))
        qx, qy = bx + c * lx - s * ly, by + s * lx + c * ly
        nx, ny = x - qx, y - qy
        d = np.hypot(nx, ny)
        outside = d > 1e-9
        with np.errstate(divide="ignore", invalid="ignore"):
            mag = params.repulsion_n * np.exp(-d / params.repulsion_range_m)
            cx, cy = x - bx, y - by
            cn = np.hypot(cx, cy)
            cn = np.where(cn == 0, 1.0, cn)
            rx = np.where(outside, mag * nx / d, params.repulsion_n * cx / cn)
            ry = np.where(outside, mag * ny / d, params.repulsion_n * cy / cn)
        on = np.asarray(repulsive, bool)
        fx = np.where(on, fx + rx, fx)
        fy = np.where(on, fy + ry, fy)
    ax, ay = fx / params.mass_kg, fy / params.mass_kg
    speed = np.hypot(vx, vy)
    moving = speed > 1e-9
    with np.errstate(divide="ignore", invalid="ignore"):
        ux, uy = vx / speed, vy / speed
        a_long = ax * ux + ay * uy
        a_lat_x, a_lat_y = ax - a_long * ux, ay - a_long * uy
        a_long = np.maximum(-params.max_decel_mps2, np.minimum(params.max_accel_mps2, a_long))
        ax = np.where(moving, a_long * ux + a_lat_x, ax)
        ay = np.where(moving, a_long * uy + a_lat_y, ay)
        a = np.hypot(ax, ay)
        over = a > params.max_decel_mps2
        ax = np.where(over, ax * params.max_decel_mps2 / a, ax)
        ay = np.where(over, ay * params.max_decel_mps2 / a, ay)
        vx1, vy1 = vx + ax * dt, vy + ay * dt
        v = np.hypot(vx1, vy1)
        fast = v > params.max_speed_mps
        vx1 = np.where(fast, vx1 * params.max_speed_mps / v, vx1)
        vy1 = np.where(fast, vy1 * params.max_speed_mps / v, vy1)
    return x + 0.5 * (vx + vx1) * dt, y + 0.5 * (vy + vy1) * dt, vx1, vy1, wp
