"""The metrics. Each: ``metric(pair, cfg) -> value``; formula and source in its docstring.

Time-integrated values use the run's fixed step. Infinite or undefined values are returned as
``None`` so that metrics.json stays valid JSON.
"""

from __future__ import annotations

import math

import numpy as np
import shapely

from vei_scenario.metrics.series import MetricConfig, PairSeries
from vei_scenario.models.boxes import box_corners


def _finite_or_none(v: float) -> float | None:
    return float(v) if math.isfinite(v) else None


def _r(v: float | None, digits: int = 4) -> float | None:
    return None if v is None else round(float(v), digits)


def collision(p: PairSeries, cfg: MetricConfig) -> bool:
    """Whether the oriented bounding boxes intersected at any step (separating-axis test)."""
    return bool(p.contact.any())


def collision_time_s(p: PairSeries, cfg: MetricConfig) -> float | None:
    """Time of the first contact of the two boxes (s), or None."""
    idx = np.nonzero(p.contact)[0]
    return _r(p.t[idx[0]], 3) if idx.size else None


def collision_entities(p: PairSeries, cfg: MetricConfig) -> list[str]:
    """The two entities of the contact, or an empty list."""
    return [p.ego.name, p.other.name] if p.contact.any() else []


def min_gap_m(p: PairSeries, cfg: MetricConfig) -> float:
    """Minimum shortest distance between the two boxes (m); 0 on contact."""
    return _r(p.gap.min())


def min_ttc_s(p: PairSeries, cfg: MetricConfig) -> float | None:
    """Minimum 2-D time to collision (s): the time until the oriented boxes first touch if both keep
    their current velocity, solved exactly on the four separating axes. Correct for crossing paths,
    not only for same-direction traffic (Hayward 1972 defines TTC; the 2-D form follows e.g. Ward et
    al. 2015). 0 on contact; None when the boxes never approach to contact."""
    return _r(_finite_or_none(p.ttc_2d.min()))


def min_ttc_approx_s(p: PairSeries, cfg: MetricConfig) -> float | None:
    """Minimum of the seed paper's approximation TTC ≈ gap / v_ego (s)."""
    return _r(_finite_or_none(p.ttc_approx.min()))


def _zone_times(p: PairSeries, cfg: MetricConfig) -> np.ndarray:
    z = p.zones(cfg)
    return np.array([(z == k).sum() for k in range(4)]) * p.dt


def ttc_zones_s(p: PairSeries, cfg: MetricConfig) -> dict[str, float]:
    """Time spent in each TTC zone (s) (the seed method): safe TTC ≥ 3 s, attention 2–3 s, alert
    < 2 s, collision while the boxes touch; thresholds in ``MetricConfig``."""
    safe, att, alert, coll = _zone_times(p, cfg)
    return {"safe": _r(safe, 3), "attention": _r(att, 3), "alert": _r(alert, 3), "collision": _r(coll, 3)}


def safety_index(p: PairSeries, cfg: MetricConfig) -> float:
    """S = (T_safe + T_attention) / T_total, and S = 0 if a collision occurs (the seed method)."""
    if p.contact.any():
        return 0.0
    times = _zone_times(p, cfg)
    total = times.sum()
    return _r((times[0] + times[1]) / total) if total > 0 else 1.0


def act_min_s(p: PairSeries, cfg: MetricConfig) -> float | None:
    """Minimum Anticipated Collision Time (s): ACT = δ / (dδ/dt closing), δ the shortest distance
    between the two boxes and its closing rate (Venthuruthiyil & Chunchu 2022). 0 on contact; None
    when the boxes never close in."""
    rate = p.closing_rate
    with np.errstate(divide="ignore", invalid="ignore"):
        act = np.where(rate > 1e-6, p.gap / rate, np.inf)
    act = np.where(p.contact, 0.0, act)
    return _r(_finite_or_none(act.min()))


def ei_max_mps(p: PairSeries, cfg: MetricConfig) -> float:
    """Maximum Emergency Index (m/s): EI = InDepth / TTC2D (Cheng et al. 2025). InDepth = D_safe − MFD:
    how deep the two safety regions would intrude into each other on the current relative course,
    MFD the closest-approach distance of the centres under constant relative velocity, D_safe the sum
    of the circumscribed radii (half box diagonals; the simplest safety region). 0 without intrusion."""
    e, o = p.ego, p.other
    rx, ry = o.x - e.x, o.y - e.y
    vx, vy = o.vx - e.vx, o.vy - e.vy
    v2 = vx * vx + vy * vy
    closing = (rx * vx + ry * vy) < 0
    with np.errstate(divide="ignore", invalid="ignore"):
        mfd = np.where(v2 > 1e-12, np.abs(rx * vy - ry * vx) / np.sqrt(v2), np.hypot(rx, ry))
        d_safe = 0.5 * (math.hypot(e.length, e.width) + math.hypot(o.length, o.width))
        in_depth = np.where(closing, d_safe - mfd, 0.0)
        ttc = np.maximum(p.ttc_2d, p.dt)
        ei = np.where((in_depth > 0) & np.isfinite(p.ttc_2d), in_depth / ttc, 0.0)
    return _r(float(ei.max()) if ei.size else 0.0)


def drac_max_mps2(p: PairSeries, cfg: MetricConfig) -> float:
    """Maximum Deceleration Rate to Avoid a Crash (m/s²): DRAC = v_c² / (2 δ), v_c the closing rate of
    the box gap δ (Almqvist et al. 1991, with the gap between boxes instead of bumper distance)."""
    rate, gap = p.closing_rate, p.gap
    with np.errstate(divide="ignore", invalid="ignore"):
        drac = np.where((rate > 0) & (gap > 1e-3), rate * rate / (2 * gap), 0.0)
    return _r(float(drac.max()) if drac.size else 0.0)


#: Paths meeting at less than this angle (deg) are following or merging, not crossing: no PET.
PET_MIN_CROSSING_ANGLE_DEG = 20.0


def pet_s(p: PairSeries, cfg: MetricConfig) -> float | None:
    """Post-Encroachment Time (s) for crossing conflicts (Allen et al. 1978): the time between the
    first road user leaving the conflict area and the second entering it. The conflict area is where
    the areas swept by the two boxes overlap. 0 when both occupy it at once; None without a conflict
    area or when the paths meet at less than 20° (following traffic, for which PET is undefined)."""
    e, o = p.ego, p.other
    step = max(1, int(round(0.05 / p.dt))) if p.dt > 0 else 1
    idx = np.arange(0, p.t.size, step)
    ce = box_corners(e.x[idx], e.y[idx], e.yaw[idx], e.length, e.width)
    co = box_corners(o.x[idx], o.y[idx], o.yaw[idx], o.length, o.width)
    pe, po = shapely.polygons(ce), shapely.polygons(co)
    area = shapely.intersection(shapely.union_all(pe), shapely.union_all(po))
    if area.is_empty or area.area < 1e-6:
        return None
    shapely.prepare(area)
    in_e, in_o = shapely.intersects(area, pe), shapely.intersects(area, po)
    te, to = p.t[idx][in_e], p.t[idx][in_o]
    if te.size == 0 or to.size == 0:
        return None
    he = np.angle(np.mean(np.exp(1j * e.yaw[idx][in_e])))
    ho = np.angle(np.mean(np.exp(1j * o.yaw[idx][in_o])))
    crossing = abs(np.degrees(np.angle(np.exp(1j * (he - ho)))))
    if min(crossing, 180.0 - crossing) < PET_MIN_CROSSING_ANGLE_DEG:
        return None
    if te[0] <= to[0]:
        first_exit, second_entry = te[-1], to[0]
    else:
        first_exit, second_entry = to[-1], te[0]
    return _r(max(0.0, second_entry - first_exit), 3)


def peak_decel_mps2(p: PairSeries, cfg: MetricConfig) -> float:
    """Largest deceleration of the ego (m/s², positive)."""
    return _r(max(0.0, -float(p.ego.accel.min())))


def max_jerk_mps3(p: PairSeries, cfg: MetricConfig) -> float:
    """Largest absolute jerk of the ego (m/s³), from its acceleration by finite differences."""
    if p.t.size < 2:
        return 0.0
    return _r(float(np.abs(np.gradient(p.ego.accel, p.t)).max()))


def comfort_score(p: PairSeries, cfg: MetricConfig) -> float:
    """Share of the run in which the ego stays within comfortable limits, |a| ≤ 2 m/s² and |jerk| ≤
    2 m/s³ (1 = always; thresholds in ``MetricConfig``). Comfort limits of this order are common in
    ride-comfort studies (e.g. Bae et al. 2020 for automated vehicles); LinguaSim reports comfort as a
    criticality companion in the same spirit."""
    if p.t.size < 2:
        return 1.0
    jerk = np.gradient(p.ego.accel, p.t)
    ok = (np.abs(p.ego.accel) <= cfg.comfort_accel_mps2 + 1e-9) & (np.abs(jerk) <= cfg.comfort_jerk_mps3 + 1e-9)
    return _r(float(ok.mean()))


def near_miss(p: PairSeries, cfg: MetricConfig) -> bool:
    """No contact, and the minimum 2-D TTC inside the near-miss band (default 0.5–1.5 s)."""
    lo, hi = cfg.near_miss_ttc_s
    m = p.ttc_2d.min()
    return bool(not p.contact.any() and lo <= m <= hi)


METRICS = {
    "collision": collision,
    "collision_time_s": collision_time_s,
    "collision_entities": collision_entities,
    "min_gap_m": min_gap_m,
    "min_ttc_s": min_ttc_s,
    "min_ttc_approx_s": min_ttc_approx_s,
    "ttc_zones_s": ttc_zones_s,
    "safety_index": safety_index,
    "act_min_s": act_min_s,
    "ei_max_mps": ei_max_mps,
    "drac_max_mps2": drac_max_mps2,
    "pet_s": pet_s,
    "peak_decel_mps2": peak_decel_mps2,
    "max_jerk_mps3": max_jerk_mps3,
    "comfort_score": comfort_score,
    "near_miss": near_miss,
}
