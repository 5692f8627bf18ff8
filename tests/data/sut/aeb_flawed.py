"""Deliberately flawed AEB ego controllers (systems under test that MUST fail).

Same plug-in contract and same geometry as ``aeb_good.AEB`` (helpers are
copied here so this file is self-contained): every candidate road user (threat
+ objects, de-duplicated, ego excluded) is put into the ego frame (x forward,
y left), extrapolated at constant velocity, and the TTC is the first time its
box (inflated by the ego half extents + 0.3 m lateral / 0.5 m longitudinal
margin) overlaps the ego's front corridor.  Commands are plain floats (m/s^2).

``LateAEB``       -- brakes only when TTC < 0.6 s, and only at -4 m/s^2.
``BlindLeftAEB``  -- the good AEB (-8 m/s^2 at TTC < 1.8 s or stopping distance
                     + 2 m > gap) but blind to the left: it only considers road
                     users whose CURRENT ego-frame lateral position satisfies
                     y <= 0.5 * ego width.
"""

import math

EGO_DEFAULT_LENGTH_M = 4.5
EGO_DEFAULT_WIDTH_M = 1.8


def _f(state, name, default=0.0):
    v = getattr(state, name, None)
    if v is None and isinstance(state, dict):
        v = state.get(name)
    try:
        v = float(v)
    except (TypeError, ValueError):
        return default
    return v if math.isfinite(v) else default


def ego_frame(ego, obj):
    """Relative kinematics of ``obj`` in the ego frame.

    Returns ``(x, y, vx, vy, ext_x, ext_y)``: relative centre position,
    relative velocity (object minus ego, both at constant heading/speed) and
    the half extents of the object's box projected onto the ego axes.
    """
    he = _f(ego, "heading_rad")
    ho = _f(obj, "heading_rad")
    c, s = math.cos(he), math.sin(he)
    dxw = _f(obj, "x_m") - _f(ego, "x_m")
    dyw = _f(obj, "y_m") - _f(ego, "y_m")
    x = c * dxw + s * dyw
    y = -s * dxw + c * dyw
    ve, vo = _f(ego, "speed_mps"), _f(obj, "speed_mps")
    dvx = vo * math.cos(ho) - ve * c
    dvy = vo * math.sin(ho) - ve * s
    vx = c * dvx + s * dvy
    vy = -s * dvx + c * dvy
    dh = ho - he
    hl = 0.5 * _f(obj, "length_m", EGO_DEFAULT_LENGTH_M)
    hw = 0.5 * _f(obj, "width_m", EGO_DEFAULT_WIDTH_M)
    ext_x = hl * abs(math.cos(dh)) + hw * abs(math.sin(dh))
    ext_y = hl * abs(math.sin(dh)) + hw * abs(math.cos(dh))
    return x, y, vx, vy, ext_x, ext_y


def _interval(p0, v, half):
    """Times t at which |p0 + v t| <= half, as (lo, hi) (may be empty)."""
    if abs(v) < 1e-9:
        return (-math.inf, math.inf) if abs(p0) <= half else (math.inf, -math.inf)
    a, b = (-half - p0) / v, (half - p0) / v
    return (min(a, b), max(a, b))


def time_to_collision(ego, obj, lat_margin_m=0.3, long_margin_m=0.5, horizon_s=10.0):
    """Constant-velocity TTC of ``obj`` entering the ego's path ahead (inf if none)."""
    x, y, vx, vy, ext_x, ext_y = ego_frame(ego, obj)
    if x <= 0.0:
        return math.inf
    half_x = 0.5 * _f(ego, "length_m", EGO_DEFAULT_LENGTH_M) + ext_x + long_margin_m
    half_y = 0.5 * _f(ego, "width_m", EGO_DEFAULT_WIDTH_M) + ext_y + lat_margin_m
    xl, xh = _interval(x, vx, half_x)
    yl, yh = _interval(y, vy, half_y)
    lo, hi = max(xl, yl, 0.0), min(xh, yh, horizon_s)
    return lo if lo <= hi else math.inf


def stop_distance_violated(ego, obj, brake_mps2, stop_margin_m, lat_margin_m=0.3):
    """True if obj is laterally in the ego's path ahead, closing, and the
    distance needed to stop (at the closing speed) plus margin exceeds the gap."""
    x, y, vx, _vy, ext_x, ext_y = ego_frame(ego, obj)
    if x <= 0.0:
        return False
    half_y = 0.5 * _f(ego, "width_m", EGO_DEFAULT_WIDTH_M) + ext_y + lat_margin_m
    if abs(y) > half_y:
        return False
    closing = -vx
    if closing <= 0.0:
        return False
    gap = x - 0.5 * _f(ego, "length_m", EGO_DEFAULT_LENGTH_M) - ext_x
    return closing * closing / (2.0 * brake_mps2) + stop_margin_m > gap


def candidates(obs):
    """Threat plus every object, de-duplicated by name, ego excluded."""
    ego = obs.ego
    ego_name = getattr(ego, "name", None)
    seen, out = set(), []
    threat = getattr(obs, "threat", None)
    for o in ([threat] if threat is not None else []) + list(getattr(obs, "objects", None) or []):
        if o is None:
            continue
        name = getattr(o, "name", None)
        if name is not None and (name == ego_name or name in seen):
            continue
        seen.add(name)
        out.append(o)
    return out


def cruise_accel(speed_mps, cruise_mps, gain=0.5, limit=2.0):
    if cruise_mps is None:
        return 0.0
    return max(-limit, min(limit, gain * (cruise_mps - speed_mps)))


def _opt_float(kwargs, key, default):
    v = kwargs.get(key)
    if v is None or (isinstance(v, str) and v.strip() == ""):
        return default
    return float(v)



class LateAEB:
    """Late and weak AEB: command -4 m/s^2 only while TTC < 0.6 s, else cruise.

    Properties (str kwargs): ``cruise_mps`` (hold speed; default: accel 0),
    ``ttc_brake_s`` (default 0.6), ``brake_mps2`` (default 4).

    WHERE IT MUST FAIL: against a stationary obstacle in the ego's lane, the
    trigger gap is ~0.6*v (+ one step of latency), but stopping at 4 m/s^2
    needs v^2/8, so it collides for every ego speed v > 4.8 m/s; the impact
    speed is about sqrt(v^2 - 4.8 v) (10 m/s -> ~7.2 m/s, 13.9 m/s -> ~11.2
    m/s).  Against a lead vehicle it collides whenever the closing speed
    exceeds 4.8 m/s.  In the case study's crossing scenario (e-scooter
    crossing from the ego's right, ego at 5.61 m/s, TimeShift =
    ConflictTimeShift = 2.197, CapEnabled=false) it collides with the ego
    still moving: replaying the recorded run gives contact at ~11.43 s at
    ~2.0 m/s (no controller: 11.24 s at 5.61 m/s); in multi_scooter at
    TimeShift=1.407 (scooter_2 from the left) ~10.83 s at ~2.8 m/s.  It must
    PASS when no conflict exists (it never brakes then) and at closing
    speeds < 4.8 m/s.
    """

    def __init__(self, **kwargs):
        self.cruise_mps = _opt_float(kwargs, "cruise_mps", None)
        self.ttc_brake_s = _opt_float(kwargs, "ttc_brake_s", 0.6)
        self.brake_mps2 = abs(_opt_float(kwargs, "brake_mps2", 4.0))
        self.last_ttc_s = math.inf

    def reset(self, info=None):
        self.last_ttc_s = math.inf

    def step(self, obs):
        ego = obs.ego
        ttc = math.inf
        for o in candidates(obs):
            ttc = min(ttc, time_to_collision(ego, o))
        self.last_ttc_s = ttc
        if ttc < self.ttc_brake_s:
            return -self.brake_mps2
        return float(cruise_accel(_f(ego, "speed_mps"), self.cruise_mps))


class BlindLeftAEB:
    """Good AEB logic, blind to road users on the ego's left.

    Identical to ``aeb_good.AEB`` (-8 m/s^2 when TTC < 1.8 s or when the
    distance needed to stop + 2 m exceeds the gap, 0.5 s release hysteresis)
    except that a road user is only considered while its current ego-frame
    lateral position is y <= 0.5 * ego width (its centre is right of the
    ego's left edge).  Road users on the right (y < 0) and in front (|y| small)
    are handled exactly like the good AEB.

    WHERE IT MUST FAIL: a road user approaching from the LEFT (crossing car or
    pedestrian coming from the ego's left, a cut-in from the left lane) is
    ignored until its centre has crossed the ego's left edge, i.e. until it is
    already inside the ego's lane; by then the predicted TTC is typically
    ~0 (the boxes touch as soon as half the object is in the lane), so the
    ego is still at (or close to) full speed at impact -> collision
    (multi_scooter example, TimeShift=1.407: scooter_2 comes from the left,
    contact ~10.80 s at the full 5.61 m/s, it never brakes).  The
    same scenario mirrored (threat from the RIGHT), a lead vehicle / stopped
    obstacle straight ahead, or no threat at all must PASS, just as for AEB
    -- including the case study itself, whose scooter comes from the RIGHT.
    """

    def __init__(self, **kwargs):
        self.cruise_mps = _opt_float(kwargs, "cruise_mps", None)
        self.ttc_brake_s = _opt_float(kwargs, "ttc_brake_s", 1.8)
        self.brake_mps2 = abs(_opt_float(kwargs, "brake_mps2", 8.0))
        self.stop_margin_m = _opt_float(kwargs, "stop_margin_m", 2.0)
        self.release_hyst_s = _opt_float(kwargs, "release_hyst_s", 0.5)
        self.braking = False
        self.last_ttc_s = math.inf

    def reset(self, info=None):
        self.braking = False
        self.last_ttc_s = math.inf

    @staticmethod
    def relevant(ego, obj):
        _x, y, _vx, _vy, _ex, _ey = ego_frame(ego, obj)
        return y <= 0.5 * _f(ego, "width_m", EGO_DEFAULT_WIDTH_M)

    def step(self, obs):
        ego = obs.ego
        ttc, stop = math.inf, False
        for o in candidates(obs):
            if not self.relevant(ego, o):
                continue
            ttc = min(ttc, time_to_collision(ego, o))
            stop = stop or stop_distance_violated(ego, o, self.brake_mps2, self.stop_margin_m)
        self.last_ttc_s = ttc
        threshold = self.ttc_brake_s + (self.release_hyst_s if self.braking else 0.0)
        self.braking = ttc < threshold or stop
        if self.braking:
            return -self.brake_mps2
        return float(cruise_accel(_f(ego, "speed_mps"), self.cruise_mps))
