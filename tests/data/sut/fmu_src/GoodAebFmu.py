"""Good AEB as an FMI 2.0 co-simulation FMU (pythonfmu), threat ports only.

Inputs ego_x, ego_y, ego_yaw, ego_speed, threat_x, threat_y, threat_yaw,
threat_speed (Real); output a_cmd (Real, m/s^2).  Sees only the declared
threat (assumed a 1.2 x 0.6 m e-scooter; ego 4.8 x 1.9 m).  a_cmd = -8 when TTC < 1.8 s (released at
TTC > 2.3 s) or when the threat is in the ego's path, closing, and
closing^2/16 + 2 m > gap; else 0 (keep speed).  Same logic as aeb_good.AEB.
"""
from pythonfmu import Fmi2Causality, Fmi2Initial, Fmi2Variability, Fmi2Slave, Real
import math

EGO_LENGTH_M = 4.8  # case-study ego (car)
EGO_WIDTH_M = 1.9
THREAT_LENGTH_M = 1.2  # case-study threat (e-scooter)
THREAT_WIDTH_M = 0.6
LAT_MARGIN_M = 0.3
LONG_MARGIN_M = 0.5


def _interval(p0, v, half):
    if abs(v) < 1e-9:
        return (-math.inf, math.inf) if abs(p0) <= half else (math.inf, -math.inf)
    a, b = (-half - p0) / v, (half - p0) / v
    return (min(a, b), max(a, b))


def threat_in_ego_frame(ex, ey, eyaw, ev, tx, ty, tyaw, tv):
    c, s = math.cos(eyaw), math.sin(eyaw)
    dxw, dyw = tx - ex, ty - ey
    x = c * dxw + s * dyw
    y = -s * dxw + c * dyw
    dvx = tv * math.cos(tyaw) - ev * c
    dvy = tv * math.sin(tyaw) - ev * s
    vx = c * dvx + s * dvy
    vy = -s * dvx + c * dvy
    dh = tyaw - eyaw
    ext_x = 0.5 * THREAT_LENGTH_M * abs(math.cos(dh)) + 0.5 * THREAT_WIDTH_M * abs(math.sin(dh))
    ext_y = 0.5 * THREAT_LENGTH_M * abs(math.sin(dh)) + 0.5 * THREAT_WIDTH_M * abs(math.cos(dh))
    return x, y, vx, vy, ext_x, ext_y


def ttc_and_stop(ex, ey, eyaw, ev, tx, ty, tyaw, tv, brake_mps2=8.0, stop_margin_m=2.0,
                 horizon_s=10.0):
    """(TTC of the threat box entering the ego's front corridor, stop-distance violated)."""
    vals = (ex, ey, eyaw, ev, tx, ty, tyaw, tv)
    if not all(math.isfinite(v) for v in vals):
        return math.inf, False
    x, y, vx, vy, ext_x, ext_y = threat_in_ego_frame(*vals)
    if x <= 0.0:
        return math.inf, False
    half_x = 0.5 * EGO_LENGTH_M + ext_x + LONG_MARGIN_M
    half_y = 0.5 * EGO_WIDTH_M + ext_y + LAT_MARGIN_M
    xl, xh = _interval(x, vx, half_x)
    yl, yh = _interval(y, vy, half_y)
    lo, hi = max(xl, yl, 0.0), min(xh, yh, horizon_s)
    ttc = lo if lo <= hi else math.inf
    stop = False
    if abs(y) <= half_y and -vx > 0.0:
        gap = x - 0.5 * EGO_LENGTH_M - ext_x
        stop = vx * vx / (2.0 * brake_mps2) + stop_margin_m > gap
    return ttc, stop


class GoodAebFmu(Fmi2Slave):
    author = "vei-scenario test partners"
    description = "Good AEB: -8 m/s^2 when TTC < 1.8 s or stopping distance + 2 m > gap"

    def __init__(self, **kwargs):
        super().__init__(**kwargs)
        self.ego_x = 0.0
        self.ego_y = 0.0
        self.ego_yaw = 0.0
        self.ego_speed = 0.0
        # no threat by default: far away, standing
        self.threat_x = 1.0e9
        self.threat_y = 1.0e9
        self.threat_yaw = 0.0
        self.threat_speed = 0.0
        self.a_cmd = 0.0
        self.braking = False
        for name in ("ego_x", "ego_y", "ego_yaw", "ego_speed",
                     "threat_x", "threat_y", "threat_yaw", "threat_speed"):
            self.register_variable(Real(name, causality=Fmi2Causality.input))
        self.register_variable(Real("a_cmd", causality=Fmi2Causality.output, initial=Fmi2Initial.exact))

    def do_step(self, current_time, step_size):
        ttc, stop = ttc_and_stop(self.ego_x, self.ego_y, self.ego_yaw, self.ego_speed,
            self.threat_x, self.threat_y, self.threat_yaw, self.threat_speed)
        threshold = 1.8 + (0.5 if self.braking else 0.0)
        self.braking = ttc < threshold or stop
        self.a_cmd = -8.0 if self.braking else 0.0
        return True
