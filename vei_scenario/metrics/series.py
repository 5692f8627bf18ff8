"""The time series metrics are computed from: the ego and one other entity, plus derived signals."""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np

from vei_scenario.models.boxes import box_distance, boxes_overlap, time_to_contact


def median(values: np.ndarray) -> float:
    """``np.median`` of finite values (the mean of the two middle ones for an even count), without the
    import of numpy.ma that ``np.median`` triggers (8 ms of a 0.2 s ``vei run``)."""
    s = np.sort(np.asarray(values, float), axis=None)
    mid = s.size // 2
    return float(s[mid]) if s.size % 2 else float((s[mid - 1] + s[mid]) / 2)


#: The TTCs the zones and the safety index can use (MetricConfig.zone_ttc).
ZONE_TTCS = ("2d", "approx")


@dataclass(frozen=True)
class MetricConfig:
    """Thresholds of the seed method's TTC zones and of the comfort score."""

    safe_ttc_s: float = 3.0  # safe zone: TTC ≥ 3 s
    alert_ttc_s: float = 2.0  # attention: 2–3 s; alert: < 2 s
    #: which TTC the zones and the safety index use: "2d" (default: exact for crossing paths) or "approx"
    #: (the seed paper's gap / v_ego to a road user ahead in the ego's lane band, blind to crossings)
    zone_ttc: str = "2d"
    comfort_accel_mps2: float = 2.0
    comfort_jerk_mps3: float = 2.0
    near_miss_ttc_s: tuple[float, float] = (0.5, 1.5)
    #: A pass without contact closer than this (minimum box gap, m) is a near miss in the sweep report
    #: whatever its TTC: crossing or side by side, the TTC can stay long while the boxes almost touch.
    close_pass_m: float = 0.5

    def __post_init__(self) -> None:
        if self.zone_ttc not in ZONE_TTCS:
            from vei_scenario.errors import VeiInputError

            raise VeiInputError(None, "--zone-ttc", f"{self.zone_ttc!r} is not one of {', '.join(ZONE_TTCS)}")


@dataclass
class Track:
    name: str
    length: float
    width: float
    x: np.ndarray
    y: np.ndarray
    yaw: np.ndarray
    speed: np.ndarray
    accel: np.ndarray

    @property
    def vx(self) -> np.ndarray:
        return self.speed * np.cos(self.yaw)

    @property
    def vy(self) -> np.ndarray:
        return self.speed * np.sin(self.yaw)


@dataclass
class PairSeries:
    """Two road users over time; arrays (T,) for one run or (V, T) for a batch of variants."""

    t: np.ndarray
    ego: Track
    other: Track

    @classmethod
    def from_run(cls, result, other: str | None = None) -> PairSeries:
        """The ego and ``other`` (default: the run's threat) from a :class:`RunResult`."""
        name = other or result.threat
        tracks = []
        for n in (result.ego, name):
            tr = result.traces[n]
            x, y = tr.x, tr.y
            if tr.center_x:  # the metrics measure boxes: move the reference point to the box centre
                x, y = x + tr.center_x * np.cos(tr.yaw), y + tr.center_x * np.sin(tr.yaw)
            tracks.append(Track(n, tr.length, tr.width, x, y, tr.yaw, tr.speed, tr.accel))
        return cls(result.t, *tracks)

    def variant(self, i: int) -> PairSeries:
        """The pair of one variant of a batch (arrays (V, T) → (T,))."""

        def one(tr: Track) -> Track:
            return Track(tr.name, tr.length, tr.width, tr.x[i], tr.y[i], tr.yaw[i], tr.speed[i], tr.accel[i])

        return PairSeries(self.t, one(self.ego), one(self.other))

    def _boxes(self):
        e, o = self.ego, self.other
        return (e.x, e.y, e.yaw, e.length, e.width, o.x, o.y, o.yaw, o.length, o.width)

    @cached_property
    def dt(self) -> float:
        return median(np.diff(self.t)) if self.t.size > 1 else 0.0

    @cached_property
    def gap(self) -> np.ndarray:
        """Shortest distance between the two boxes (m); 0 while they overlap."""
        return box_distance(*self._boxes())

    @cached_property
    def contact(self) -> np.ndarray:
        return boxes_overlap(*self._boxes())

    @cached_property
    def closing_rate(self) -> np.ndarray:
        """−d(gap)/dt (m/s): positive while the boxes approach each other."""
        return -np.gradient(self.gap, self.t, axis=-1) if self.t.size > 1 else np.zeros_like(self.gap)

    @cached_property
    def path_gap(self) -> np.ndarray:
        """Gap (m) from the ego's front to the other's near edge while the other is ahead within the
        ego's lane band (its box overlaps the band of the ego's width along its heading); inf otherwise."""
        e, o = self.ego, self.other
        c, s = np.cos(e.yaw), np.sin(e.yaw)
        dx, dy = o.x - e.x, o.y - e.y
        rel = o.yaw - e.yaw
        ahead = (
            c * dx + s * dy - 0.5 * e.length - 0.5 * (o.length * np.abs(np.cos(rel)) + o.width * np.abs(np.sin(rel)))
        )
        lateral = np.abs(-s * dx + c * dy)
        half_band = 0.5 * e.width + 0.5 * (o.length * np.abs(np.sin(rel)) + o.width * np.abs(np.cos(rel)))
        return np.where((lateral <= half_band) & (ahead >= 0), ahead, np.inf)

    @cached_property
    def ttc_approx(self) -> np.ndarray:
        """The seed paper's approximation TTC ≈ gap / v_ego (s), gap the :attr:`path_gap` to the other
        in front of the ego; inf when nothing is ahead in the lane band or the ego stands still."""
        v = self.ego.speed
        with np.errstate(divide="ignore", invalid="ignore"):
            out = np.where((v > 1e-3) & np.isfinite(self.path_gap), self.path_gap / v, np.inf)
        return np.where(self.contact, 0.0, out)

    @cached_property
    def ttc_2d(self) -> np.ndarray:
        """Time until the boxes touch if both keep their velocity (s); inf if they never do."""
        e, o = self.ego, self.other
        return time_to_contact(
            e.x, e.y, e.yaw, e.length, e.width, e.vx, e.vy, o.x, o.y, o.yaw, o.length, o.width, o.vx, o.vy
        )

    def zone_ttc(self, cfg: MetricConfig) -> np.ndarray:
        return self.ttc_approx if cfg.zone_ttc == "approx" else self.ttc_2d

    def zones(self, cfg: MetricConfig) -> np.ndarray:
        """Per step: 0 safe (TTC ≥ safe), 1 attention, 2 alert (< alert threshold), 3 collision."""
        ttc = self.zone_ttc(cfg)
        z = np.where(ttc >= cfg.safe_ttc_s, 0, np.where(ttc >= cfg.alert_ttc_s, 1, 2))
        return np.where(self.contact, 3, z)
