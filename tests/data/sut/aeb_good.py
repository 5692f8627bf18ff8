"""A reasonable AEB (autonomous emergency braking) ego controller.

Plug-in contract (vei-scenario ``--controller EGO=aeb_good.py:AEB``):

* constructed with the controller's properties as ``str`` keyword arguments;
* ``reset(info)`` is called (optionally) before a run;
* ``step(obs)`` is called once per step and returns the longitudinal
  acceleration command in m/s^2 as a plain ``float``.

``obs`` carries ``t_s``, ``dt_s``, ``ego``, ``threat`` (or ``None``) and
``objects``; each state has ``name, kind, x_m, y_m, heading_rad, speed_mps,
accel_mps2, length_m, width_m`` (box centre, OpenDRIVE world frame, heading
counter-clockwise from +x).

Behaviour
---------
* Cruise: with a ``cruise_mps`` property the controller holds that speed with
  a clipped P-controller (|a| <= 2 m/s^2); without it the command is 0 (keep
  the current speed).
* Every candidate road user (the threat plus every object, de-duplicated by
  name, the ego itself excluded) is transformed into the ego frame (x forward,
  y to the left).  Both are extrapolated at constant velocity; the object's box
  is inflated by the ego's half extents plus a margin (``lat_margin_m`` = 0.3,
  ``long_margin_m`` = 0.5) and the time-to-collision (TTC) is the first time
  ``t >= 0`` at which the relative centre lies inside that inflated box, i.e.
  the object's box is in the ego's path (lateral overlap with the ego's
  width plus margin) and touches the ego's front.  Only objects whose centre
  is currently ahead of the ego's centre (ego-frame x > 0) are considered.
  This covers lead vehicles (TTC = gap / closing speed) as well as crossing
  road users (TTC = when their box enters the ego's corridor at the moment
  the ego arrives there).
* Braking: ``brake_mps2`` (default 8) i.e. a command of -8 m/s^2 when
  TTC < ``ttc_brake_s`` (default 1.8 s), or, for an object already laterally in
  the ego's path and closing, when the distance needed to stop at
  ``brake_mps2`` plus ``stop_margin_m`` (default 2 m) exceeds the gap.
  Braking is held (hysteresis) until TTC > ttc_brake_s + ``release_hyst_s``
  (default 0.5 s) and the stopping criterion is clear.

Expected outcome in vei: no collision in rear-end / cut-in / crossing cases
whenever the ego's vehicle performance allows ~8 m/s^2 of deceleration and
the threat is visible (it is) >= 1.8 s before impact at constant velocity.
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


class AEB:
    """Reasonable AEB: brake -8 m/s^2 at TTC < 1.8 s or when stopping distance + 2 m > gap."""

    def __init__(self, **kwargs):
        self.cruise_mps = _opt_float(kwargs, "cruise_mps", None)
        self.ttc_brake_s = _opt_float(kwargs, "ttc_brake_s", 1.8)
        self.brake_mps2 = abs(_opt_float(kwargs, "brake_mps2", 8.0))
        self.stop_margin_m = _opt_float(kwargs, "stop_margin_m", 2.0)
        self.lat_margin_m = _opt_float(kwargs, "lat_margin_m", 0.3)
        self.long_margin_m = _opt_float(kwargs, "long_margin_m", 0.5)
        self.release_hyst_s = _opt_float(kwargs, "release_hyst_s", 0.5)
        self.braking = False
        self.last_ttc_s = math.inf
        self.last_reason = None

    def reset(self, info=None):
        self.braking = False
        self.last_ttc_s = math.inf
        self.last_reason = None

    def relevant(self, ego, obj):
        """Hook for subclasses/variants: which road users are considered."""
        return True

    def step(self, obs):
        ego = obs.ego
        ttc, stop = math.inf, False
        for o in candidates(obs):
            if not self.relevant(ego, o):
                continue
            ttc = min(ttc, time_to_collision(ego, o, self.lat_margin_m, self.long_margin_m))
            stop = stop or stop_distance_violated(
                ego, o, self.brake_mps2, self.stop_margin_m, self.lat_margin_m)
        self.last_ttc_s = ttc
        threshold = self.ttc_brake_s + (self.release_hyst_s if self.braking else 0.0)
        self.braking = ttc < threshold or stop
        if self.braking:
            self.last_reason = "ttc" if ttc < threshold else "stop_distance"
            return -self.brake_mps2
        self.last_reason = None
        return float(cruise_accel(_f(ego, "speed_mps"), self.cruise_mps))
