"""Parameters of the e-scooter social force model.

m·a = F_dest + F_rep, with F_dest = k (v_des − v), v_des = v0 (p_dest − p) / sqrt(|p_dest − p|² + σ²)
and F_rep = A·exp(−d/B)·n (d: distance from the ego's closest box point to the scooter; n: unit vector
from that point to the scooter). The dynamics live with the interpreter; the parameters are here so
that the compiler can write them into the scenario's controller properties.
"""

from __future__ import annotations

from dataclasses import asdict, dataclass

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
