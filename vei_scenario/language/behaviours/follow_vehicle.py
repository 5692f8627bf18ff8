"""follow vehicle: an ACC follower holding a time gap behind a target (the ego by default)."""

from __future__ import annotations

from scenariogeneration import xosc

from vei_scenario.language.behaviours.base import ActorContext, Parameter, Step, value

NAME = "follow_vehicle"
AGENT = "ACC follower"
SUMMARY = "Hold a time gap behind a vehicle (continuous LongitudinalDistanceAction, bounded accelerations)."
DEFAULT_SPAWN = {"relation": "behind"}
PARAMETERS = {
    "headway_s": Parameter(1.5, 0.2, 4.0, "time gap to the followed vehicle (s), free space"),
    "max_accel_mps2": Parameter(2.5, 0.5, 6.0, "largest acceleration while following (m/s²)"),
    "max_decel_mps2": Parameter(4.0, 0.5, 10.0, "largest deceleration while following (m/s²)"),
    "hold_s": Parameter(8.0, 0.0, 120.0, "how long it follows before what follows (s)"),
}
PROFILES = {
    "dangerous": {"headway_s": (0.25, 0.5)},
    "moderate": {"headway_s": (0.8, 1.2)},
    "safe": {"headway_s": (1.8, 2.5)},
}


#: How much faster than the ego (or its own start speed) a follower may drive to close in (m/s).
CLOSING_MPS = 6.0


def compile(ctx: ActorContext, cfg: dict) -> list[Step]:
    target = str(cfg.get("target", ctx.ego))
    action = xosc.LongitudinalDistanceAction(
        target,
        freespace=True,
        continuous=True,
        max_acceleration=value(cfg, PARAMETERS, "max_accel_mps2"),
        max_deceleration=ctx.max_decel(value(cfg, PARAMETERS, "max_decel_mps2")),
        # closing in, not racing: a few m/s above the faster of the two
        max_speed=round(min(45.0, max(ctx.ego_speed_mps, ctx.actor_speed_mps) + CLOSING_MPS), 3),
        timeGap=round(value(cfg, PARAMETERS, "headway_s"), 3),
    )
    return [Step("follow", [action], hold_s=value(cfg, PARAMETERS, "hold_s"))]


def place(ego_speed: float, lengths_m: float, cfg: dict) -> tuple[float, float]:
    """(spawn longitudinal_m, speed_mps): behind the ego at twice its headway, a little faster."""
    return -(lengths_m / 2 + 2 * value(cfg, PARAMETERS, "headway_s") * ego_speed), ego_speed + 2.0
