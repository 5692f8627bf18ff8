"""The e-scooter social force model (SFM): parameters and dynamics.

m·a = F_dest + F_rep, with F_dest = k (v_des − v), v_des = v0 (p_dest − p) / sqrt(|p_dest − p|² + σ²)
and F_rep = A·exp(−d/B)·n (d: distance from the ego's closest box point to the scooter; n: unit vector
from that point to the scooter). Pure numerical code: the interpreter, the batch engine and the FMU
tests share it. The compiler writes the parameters into the scenario's controller properties.
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass

import numpy as np

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


def closest_point_on_box(px: float, py: float, bx: float, by: float, byaw: float, length: float, width: float):
    """The point of an oriented box (centre, yaw, size) closest to (px, py); the point itself if inside."""
    c, s = math.cos(byaw), math.sin(byaw)
    dx, dy = px - bx, py - by
    lx = max(-0.5 * length, min(0.5 * length, c * dx + s * dy))
    ly = max(-0.5 * width, min(0.5 * width, -s * dx + c * dy))
    return bx + c * lx - s * ly, by + s * lx + c * ly


def sfm_acceleration(
    state: SfmState,
    dest: tuple[float, float],
    params: SfmParameters,
    repulsive: bool,
    ego_box: tuple[float, float, float, float, float] | None,
) -> tuple[float, float]:
    """a = (F_dest + F_rep) / m.

    F_dest = k (v_des − v), v_des = v0 (p_dest − p) / sqrt(|p_dest − p|² + σ²), k = m/τ.
    F_rep = A exp(−d/B) n from the ego's influential point (closest point of its box, given as
    (x, y, yaw, length, width)); n points from that point to the scooter. ``repulsive=False`` is the
    aggressive, non-cooperative rider.
    """
    ex, ey = dest[0] - state.x, dest[1] - state.y
    scale = params.v0_mps / math.sqrt(ex * ex + ey * ey + params.sigma_m * params.sigma_m)
    k = params.k_n_s_per_m
    fx = k * (ex * scale - state.vx)
    fy = k * (ey * scale - state.vy)
    if repulsive and ego_box is not None:
        qx, qy = closest_point_on_box(state.x, state.y, *ego_box)
        nx, ny = state.x - qx, state.y - qy
        d = math.hypot(nx, ny)
        if d > 1e-9:
            mag = params.repulsion_n * math.exp(-d / params.repulsion_range_m)
            fx += mag * nx / d
            fy += mag * ny / d
        else:  # inside the ego box: push away from its centre
            nx, ny = state.x - ego_box[0], state.y - ego_box[1]
            n = math.hypot(nx, ny) or 1.0
            fx += params.repulsion_n * nx / n
            fy += params.repulsion_n * ny / n
    return fx / params.mass_kg, fy / params.mass_kg


def sfm_step(
    state: SfmState,
    route: list[tuple[float, float]],
    params: SfmParameters,
    repulsive: bool,
    ego_box: tuple[float, float, float, float, float] | None,
    dt: float,
) -> SfmState:
    """One explicit step: advance the waypoint, apply the bounded acceleration, bound the speed.

    The scooter steers at successive waypoints of its recorded route: the next one becomes the
    destination once the scooter is within ``waypoint_radius_m`` of the current one or has passed it
    (its projection onto the route segment lies beyond it).
    """
    wp = state.waypoint
    while wp < len(route) - 1:
        wx, wy = route[wp]
        nx_, ny_ = route[wp + 1]
        near = math.hypot(wx - state.x, wy - state.y) <= params.waypoint_radius_m
        passed = (state.x - wx) * (nx_ - wx) + (state.y - wy) * (ny_ - wy) > 0
        if near or passed:
            wp += 1
        else:
            break
    ax, ay = sfm_acceleration(state, route[wp], params, repulsive, ego_box)
    # Bound acceleration: along-track by the e-scooter's drive/brake limits, total by the brake limit.
    speed = math.hypot(state.vx, state.vy)
    if speed > 1e-9:
        ux, uy = state.vx / speed, state.vy / speed
        a_long = ax * ux + ay * uy
        a_lat_x, a_lat_y = ax - a_long * ux, ay - a_long * uy
        a_long = max(-params.max_decel_mps2, min(params.max_accel_mps2, a_long))
        ax, ay = a_long * ux + a_lat_x, a_long * uy + a_lat_y
    a = math.hypot(ax, ay)
    if a > params.max_decel_mps2:
        ax, ay = ax * params.max_decel_mps2 / a, ay * params.max_decel_mps2 / a
    vx, vy = state.vx + ax * dt, state.vy + ay * dt
    v = math.hypot(vx, vy)
    if v > params.max_speed_mps:
        vx, vy = vx * params.max_speed_mps / v, vy * params.max_speed_mps / v
    return SfmState(state.x + 0.5 * (state.vx + vx) * dt, state.y + 0.5 * (state.vy + vy) * dt, vx, vy, wp)


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
