"""The metrics. Each: ``metric(pair, cfg) -> array``; formula and source in its docstring.

A metric reduces over the last (time) axis and keeps any leading axes, so the same code scores one
``vei run`` (arrays of shape (T,)) and a batch of variants (shape (V, T)). Values are raw here;
:func:`to_python` rounds them and turns undefined values (NaN, inf) into ``None``, the same way for
both paths. Time-integrated values use the run's fixed step.
"""

from __future__ import annotations

import math

import numpy as np

from vei_scenario.metrics.series import MetricConfig, PairSeries
from vei_scenario.models.boxes import boxes_overlap

ZONES = ("safe", "attention", "alert", "collision")


def collision(p: PairSeries, cfg: MetricConfig) -> np.ndarray:
    """Whether the oriented bounding boxes intersected at any step (separating-axis test)."""
    return p.contact.any(axis=-1)


def collision_time_s(p: PairSeries, cfg: MetricConfig) -> np.ndarray:
    """Time of the first contact of the two boxes (s), or None."""
    first = np.argmax(p.contact, axis=-1)
    return np.where(p.contact.any(axis=-1), p.t[first], np.nan)


def impact_speed_mps(p: PairSeries, cfg: MetricConfig) -> np.ndarray:
    """Speed of the two relative to each other at the first contact (m/s), |v_other − v_ego|: how
    violent a collision is (the Δv of the pair), or None without one."""
    first = np.argmax(p.contact, axis=-1)
    rel = np.hypot(p.other.vx - p.ego.vx, p.other.vy - p.ego.vy)
    at = np.take_along_axis(rel, np.asarray(first)[..., None], axis=-1)[..., 0]
    return np.where(p.contact.any(axis=-1), at, np.nan)


def collision_entities(p: PairSeries, cfg: MetricConfig) -> np.ndarray:
    """The names of the two entities of the first contact, or an empty list without one."""
    return p.contact.any(axis=-1)  # a flag here: to_python puts the names in


def min_gap_m(p: PairSeries, cfg: MetricConfig) -> np.ndarray:
    """Minimum shortest distance between the two boxes (m); 0 on contact."""
    return p.gap.min(axis=-1)


def min_ttc_s(p: PairSeries, cfg: MetricConfig) -> np.ndarray:
    """Minimum 2-D time to collision (s): the time until the oriented boxes first touch if both keep
    their current velocity, solved exactly on the four separating axes. Correct for crossing paths,
    not only for same-direction traffic (Hayward 1972 defines TTC; the 2-D form follows e.g. Ward et
    al. 2015). 0 on contact; None when the boxes never approach to contact."""
    return p.ttc_2d.min(axis=-1)


def min_ttc_approx_s(p: PairSeries, cfg: MetricConfig) -> np.ndarray:
    """Minimum of the seed paper's approximation TTC ≈ gap / v_ego (s), gap to the other road user
    ahead in the ego's lane band; None when nothing is ever ahead."""
    return p.ttc_approx.min(axis=-1)


def _zone_times(p: PairSeries, cfg: MetricConfig) -> np.ndarray:
    z = p.zones(cfg)
    return np.stack([(z == k).sum(axis=-1) for k in range(4)]) * p.dt


def ttc_zones_s(p: PairSeries, cfg: MetricConfig) -> dict[str, np.ndarray]:
    """Time spent in each TTC zone (s) (the seed method): safe TTC ≥ 3 s, attention 2–3 s, alert
    < 2 s, collision while the boxes touch; thresholds in ``MetricConfig``."""
    return dict(zip(ZONES, _zone_times(p, cfg)))


def safety_index(p: PairSeries, cfg: MetricConfig) -> np.ndarray:
    """S = (T_safe + T_attention) / T_total, and S = 0 if a collision occurs (the seed method)."""
    times = _zone_times(p, cfg)
    total = times.sum(axis=0)
    with np.errstate(divide="ignore", invalid="ignore"):
        s = np.where(total > 0, (times[0] + times[1]) / total, 1.0)
    return np.where(p.contact.any(axis=-1), 0.0, s)


def act_min_s(p: PairSeries, cfg: MetricConfig) -> np.ndarray:
    """Minimum Anticipated Collision Time (s): ACT = δ / (dδ/dt closing), δ the shortest distance
    between the two boxes and its closing rate (Venthuruthiyil & Chunchu 2022). 0 on contact; None
    when the boxes never close in."""
    rate = p.closing_rate
    with np.errstate(divide="ignore", invalid="ignore"):
        act = np.where(rate > 1e-6, p.gap / rate, np.inf)
    return np.where(p.contact, 0.0, act).min(axis=-1)


#: EI's TTC is floored here (s): the last step before a contact is a contact value, not a criticality.
EI_MIN_TTC_S = 0.1
#: DRAC is capped here (m/s², ~2 g): beyond any vehicle's braking, so "unavoidable by braking".
DRAC_CAP_MPS2 = 20.0


def _circumradii(p: PairSeries) -> float:
    """Sum of the two boxes' circumscribed radii (half diagonals): EI's safety distance, and the
    centre distance beyond which two boxes cannot touch."""
    e, o = p.ego, p.other
    return 0.5 * (math.hypot(e.length, e.width) + math.hypot(o.length, o.width))


def ei_max_mps(p: PairSeries, cfg: MetricConfig) -> np.ndarray:
    """Maximum Emergency Index (m/s): EI = InDepth / TTC2D (Cheng et al. 2025). InDepth = D_safe − MFD:
    how deep the two safety regions would intrude into each other on the current relative course,
    MFD the closest-approach distance of the centres under constant relative velocity, D_safe the sum
    of the circumscribed radii (half box diagonals; the simplest safety region). 0 without intrusion.
    Contact values: the TTC divides no lower than :data:`EI_MIN_TTC_S` (0.1 s), so EI stays at most
    D_safe / 0.1 s instead of growing without bound in the last step before a contact."""
    e, o = p.ego, p.other
    rx, ry = o.x - e.x, o.y - e.y
    vx, vy = o.vx - e.vx, o.vy - e.vy
    v2 = vx * vx + vy * vy
    closing = (rx * vx + ry * vy) < 0
    with np.errstate(divide="ignore", invalid="ignore"):
        mfd = np.where(v2 > 1e-12, np.abs(rx * vy - ry * vx) / np.sqrt(v2), np.hypot(rx, ry))
        d_safe = _circumradii(p)
        in_depth = np.where(closing, d_safe - mfd, 0.0)
        ttc = np.maximum(p.ttc_2d, EI_MIN_TTC_S)
        ei = np.where((in_depth > 0) & np.isfinite(p.ttc_2d), in_depth / ttc, 0.0)
    return ei.max(axis=-1)


def drac_max_mps2(p: PairSeries, cfg: MetricConfig) -> np.ndarray:
    """Maximum Deceleration Rate to Avoid a Crash (m/s²): DRAC = v_c² / (2 δ), v_c the closing rate of
    the box gap δ (Almqvist et al. 1991, with the gap between boxes instead of bumper distance).
    Contact values: capped at :data:`DRAC_CAP_MPS2` (20 m/s², about 2 g). No tyre brakes harder than
    ~1 g, so 20 reads "cannot be avoided by braking"; as the gap closes to contact DRAC would otherwise
    grow without bound (733 m/s² one step before a crash)."""
    rate, gap = p.closing_rate, p.gap
    with np.errstate(divide="ignore", invalid="ignore"):
        drac = np.where((rate > 0) & (gap > 1e-3), rate * rate / (2 * gap), 0.0)
    return np.minimum(drac.max(axis=-1), DRAC_CAP_MPS2)


#: Paths meeting at less than this angle (deg) are following or merging, not crossing: no PET.
PET_MIN_CROSSING_ANGLE_DEG = 20.0


def pet_step(dt: float) -> int:
    """Every how many samples (of step ``dt``) the conflict area is looked at: every 0.05 s."""
    return max(1, int(round(0.05 / dt))) if dt > 0 else 1


def conflict_area_samples(p: PairSeries) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(sample indices every 0.05 s, ego box in the conflict area, other box in it).

    The conflict area is where the areas swept by the two boxes overlap; a box of one road user lies
    in it exactly when it overlaps some box of the other. Only pairs whose circumscribed circles meet,
    among the samples near the other's path, are tested (separating axes)."""
    e, o = p.ego, p.other
    step = pet_step(p.dt)
    idx = np.arange(0, p.t.size, step)
    ex, ey, eyaw = e.x[idx], e.y[idx], e.yaw[idx]
    ox, oy, oyaw = o.x[idx], o.y[idx], o.yaw[idx]
    in_e, in_o = np.zeros(idx.size, bool), np.zeros(idx.size, bool)
    reach = _circumradii(p)

    def near(x, y, bx, by):
        return np.nonzero(
            (x >= bx.min() - reach) & (x <= bx.max() + reach) & (y >= by.min() - reach) & (y <= by.max() + reach)
        )[0]

    ie, io = near(ex, ey, ox, oy), near(ox, oy, ex, ey)
    if ie.size and io.size:
        close = (ex[ie, None] - ox[None, io]) ** 2 + (ey[ie, None] - oy[None, io]) ** 2 <= reach * reach
        a, b = np.nonzero(close)
        a, b = ie[a], io[b]
        hit = boxes_overlap(ex[a], ey[a], eyaw[a], e.length, e.width, ox[b], oy[b], oyaw[b], o.length, o.width)
        in_e[a[hit]] = True
        in_o[b[hit]] = True
    return idx, in_e, in_o


def _pet_one(p: PairSeries) -> float:
    idx, in_e, in_o = conflict_area_samples(p)
    if not in_e.any():
        return math.nan
    eyaw, oyaw = p.ego.yaw[idx], p.other.yaw[idx]
    te, to = p.t[idx][in_e], p.t[idx][in_o]
    he = np.angle(np.mean(np.exp(1j * eyaw[in_e])))
    ho = np.angle(np.mean(np.exp(1j * oyaw[in_o])))
    crossing = abs(np.degrees(np.angle(np.exp(1j * (he - ho)))))
    if min(crossing, 180.0 - crossing) < PET_MIN_CROSSING_ANGLE_DEG:
        return math.nan
    if te[0] <= to[0]:
        first_exit, second_entry = te[-1], to[0]
    else:
        first_exit, second_entry = to[-1], te[0]
    return max(0.0, float(second_entry - first_exit))


def pet_s(p: PairSeries, cfg: MetricConfig) -> np.ndarray:
    """Post-Encroachment Time (s) for crossing conflicts (Allen et al. 1978): the time between the
    first road user leaving the conflict area and the second entering it. The conflict area is where
    the areas swept by the two boxes overlap. 0 when both occupy it at once; None without a conflict
    area or when the paths meet at less than 20° (following traffic, for which PET is undefined).
    Evaluated every 0.05 s (:func:`conflict_area_samples`; tests/test_metrics_pet.py checks it
    against shapely's swept-area geometry)."""
    if p.gap.ndim == 1:
        return np.array(_pet_one(p))
    return np.array([_pet_one(p.variant(i)) for i in range(p.gap.shape[0])])


def peak_decel_mps2(p: PairSeries, cfg: MetricConfig) -> np.ndarray:
    """Largest deceleration of the ego (m/s², positive)."""
    return np.maximum(0.0, -p.ego.accel.min(axis=-1)) + 0.0  # (+ 0.0: no "-0.0" when it never brakes)


def _jerk(p: PairSeries) -> np.ndarray:
    return np.gradient(p.ego.accel, p.t, axis=-1) if p.t.size > 1 else np.zeros_like(p.ego.accel)


def max_jerk_mps3(p: PairSeries, cfg: MetricConfig) -> np.ndarray:
    """Largest absolute jerk of the ego (m/s³), from its acceleration by finite differences."""
    return np.abs(_jerk(p)).max(axis=-1)


def comfort_score(p: PairSeries, cfg: MetricConfig) -> np.ndarray:
    """Share of the run in which the ego stays within comfortable limits, |a| ≤ 2 m/s² and |jerk| ≤
    2 m/s³ (1 = always; thresholds in ``MetricConfig``). Comfort limits of this order are common in
    ride-comfort studies (e.g. Bae et al. 2020 for automated vehicles); LinguaSim reports comfort as a
    criticality companion in the same spirit."""
    ok = (np.abs(p.ego.accel) <= cfg.comfort_accel_mps2 + 1e-9) & (np.abs(_jerk(p)) <= cfg.comfort_jerk_mps3 + 1e-9)
    return ok.mean(axis=-1)


#: The ego stands at or below this speed (m/s): a collision then is not the ego's doing.
STANDING_MPS = 0.1
#: The deceleration (m/s²) whose first reaching is the brake onset: Euro NCAP's AEB protocols time the
#: AEB's activation from the acceleration's crossing of -1 m/s².
BRAKE_ONSET_MPS2 = 1.0


def _first_contact(p: PairSeries) -> tuple[np.ndarray, np.ndarray]:
    """(index of the first contact, whether there is one), over the leading axes."""
    return np.argmax(p.contact, axis=-1), p.contact.any(axis=-1)


def _at(values: np.ndarray, index: np.ndarray) -> np.ndarray:
    return np.take_along_axis(values, np.asarray(index)[..., None], axis=-1)[..., 0]


def ego_speed_at_contact_mps(p: PairSeries, cfg: MetricConfig) -> np.ndarray:
    """The ego's own speed at the first contact (m/s), or None without one: Euro NCAP rates AEB by it
    (the impact speed of the vehicle under test); 0 means the road user ran into a standing ego."""
    first, hit = _first_contact(p)
    return np.where(hit, _at(p.ego.speed, first), np.nan)


def collision_ego_moving(p: PairSeries, cfg: MetricConfig) -> np.ndarray:
    """A collision with the ego moving at its first contact (speed above :data:`STANDING_MPS`, 0.1 m/s):
    a failure of the system that drives the ego. A road user running into the standing ego is a
    collision (:func:`collision`), not a failure of that system."""
    first, hit = _first_contact(p)
    return hit & (_at(p.ego.speed, first) > STANDING_MPS)


def ego_standing_before_contact_s(p: PairSeries, cfg: MetricConfig) -> np.ndarray:
    """How long the ego had stood (speed ≤ 0.1 m/s, without a break) when the first contact came (s):
    0 when it was moving; None without a contact."""
    first, hit = _first_contact(p)
    idx = np.arange(p.t.size)
    before = idx <= np.asarray(first)[..., None]
    last_moving = np.where(before & (p.ego.speed > STANDING_MPS), idx, -1).max(axis=-1)
    start = np.minimum(last_moving + 1, first)
    stood = _at(p.ego.speed, first) <= STANDING_MPS
    return np.where(hit, np.where(stood, p.t[first] - p.t[start], 0.0), np.nan)


def _brake_onset(p: PairSeries) -> tuple[np.ndarray, np.ndarray]:
    """(index of the brake onset, whether there is one): the first step, up to the first contact (the
    whole run without one), at which the ego decelerates at :data:`BRAKE_ONSET_MPS2` or more."""
    first, hit = _first_contact(p)
    limit = np.where(hit, first, p.t.size - 1)
    braking = (p.ego.accel <= -BRAKE_ONSET_MPS2) & (np.arange(p.t.size) <= np.asarray(limit)[..., None])
    return np.argmax(braking, axis=-1), braking.any(axis=-1)


def brake_onset_s(p: PairSeries, cfg: MetricConfig) -> np.ndarray:
    """Time the ego first brakes (s): its acceleration reaches -1 m/s² (Euro NCAP's AEB activation
    level), looked for up to the first contact; None when it never brakes so hard."""
    onset, braked = _brake_onset(p)
    return np.where(braked, p.t[onset], np.nan)


def ttc_at_brake_onset_s(p: PairSeries, cfg: MetricConfig) -> np.ndarray:
    """The 2-D TTC at the brake onset (s): how much time the system left itself; None without a brake
    onset or when the two were not on a collision course then."""
    onset, braked = _brake_onset(p)
    return np.where(braked, _at(p.ttc_2d, onset), np.nan)


def speed_reduction_mps(p: PairSeries, cfg: MetricConfig) -> np.ndarray:
    """How much speed the ego's braking took off before the first contact (m/s): its speed at the brake
    onset minus its speed at the contact, the speed it would have hit at without braking being the
    speed it had when it began (0 when it did not brake before the contact); None without a contact."""
    first, hit = _first_contact(p)
    onset, braked = _brake_onset(p)
    at_contact = _at(p.ego.speed, first)
    return np.where(hit, np.where(braked, _at(p.ego.speed, onset) - at_contact, 0.0), np.nan)


def near_miss(p: PairSeries, cfg: MetricConfig) -> np.ndarray:
    """No contact, and the minimum 2-D TTC inside the near-miss band (default 0.5–1.5 s)."""
    lo, hi = cfg.near_miss_ttc_s
    m = p.ttc_2d.min(axis=-1)
    return ~p.contact.any(axis=-1) & (lo <= m) & (m <= hi)


METRICS = {
    "collision": collision,
    "collision_time_s": collision_time_s,
    "collision_entities": collision_entities,
    "impact_speed_mps": impact_speed_mps,
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
    "ego_speed_at_contact_mps": ego_speed_at_contact_mps,
    "collision_ego_moving": collision_ego_moving,
    "ego_standing_before_contact_s": ego_standing_before_contact_s,
    "brake_onset_s": brake_onset_s,
    "ttc_at_brake_onset_s": ttc_at_brake_onset_s,
    "speed_reduction_mps": speed_reduction_mps,
}

#: Decimal places of each reported value (bool metrics are reported as booleans).
DIGITS = {"collision_time_s": 3, "ttc_zones_s": 3, "pet_s": 3, "brake_onset_s": 3, "ego_standing_before_contact_s": 3}
BOOLEAN = {"collision", "near_miss", "collision_ego_moving"}


def _number(v: float, digits: int) -> float | None:
    v = float(v)
    return round(v, digits) if math.isfinite(v) else None


def to_python(name: str, raw, index: tuple = (), names: tuple[str, str] = ("", "")):
    """The JSON value of metric ``name`` for the variant at ``index`` of its raw array(s)."""
    if name == "ttc_zones_s":
        return {z: _number(raw[z][index], 3) for z in ZONES}
    if name == "collision_entities":
        return list(names) if bool(raw[index]) else []
    if name in BOOLEAN:
        return bool(raw[index])
    return _number(raw[index], DIGITS.get(name, 4))
