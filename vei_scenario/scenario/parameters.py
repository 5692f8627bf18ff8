"""The scenario's declared parameters: the seed method's variations.

=================  =========  ==========================================================================
name               type       meaning (default)
=================  =========  ==========================================================================
TimeShift          double     delay (s) of the threat scooter's recorded timing; 0 replays the clip as
                              recorded, ``ConflictTimeShift`` puts scooter and ego at the conflict point
                              together (default 0)
RiderType          string     ``replay`` (recorded trajectory), ``normal`` (social force model with
                              repulsion from the ego) or ``aggressive`` (no repulsion) (default replay)
CapEnabled         boolean    the ego's collision-avoidance planner is active (default false)
EgoCruiseSpeed     double     cruise speed (m/s) the planner holds; default the median recorded ego speed
ConflictTimeShift  double     the TimeShift found by the conflict analysis (informative, for tools that
                              sweep around it)
=================  =========  ==========================================================================
"""

from __future__ import annotations

from dataclasses import dataclass

from vei_scenario.models.sfm import RIDER_TYPES


@dataclass(frozen=True)
class ParameterSpec:
    name: str
    type: str  # OpenSCENARIO ParameterType: double | string | boolean
    default: object
    doc: str

    def literal(self, value: object) -> str:
        return format_value(self.type, value)


def format_value(type_: str, value: object) -> str:
    """Parameter value as OpenSCENARIO writes it."""
    if type_ == "boolean":
        if isinstance(value, str):
            return value.lower()
        return "true" if value else "false"
    if type_ == "double":
        return f"{float(value):.6g}" if abs(float(value)) < 1e6 else repr(float(value))
    return str(value)


#: Model parameters a scenario can declare (``vei compile --model-parameters``), so that sweeps,
#: risk searches and falsification vary them like the seed method's: name -> (controller, property).
MODEL_PARAMETERS = {
    "RiderDesiredSpeed": ("sfm", "v0_mps", "Desired speed of the social-force rider (m/s)."),
    "RiderRepulsion": ("sfm", "repulsion_n", "Repulsion strength A of the social-force rider from the ego (N)."),
    "PlannerTimeHeadway": ("cap", "t_h_s", "Time headway t_h in the planner's safe distance (s)."),
    "PlannerMaxDecel": ("cap", "a_max_mps2", "The planner's maximum braking a_max (m/s²)."),
    "PlannerStandstillGap": ("cap", "d0_m", "Standstill gap d0 the planner stops short of the conflict (m)."),
}


def model_parameters(sfm, cap) -> list[ParameterSpec]:
    """The declarations of :data:`MODEL_PARAMETERS`, defaulting to the models' values."""
    models = {"sfm": sfm, "cap": cap}
    return [
        ParameterSpec(name, "double", getattr(models[which], prop), doc)
        for name, (which, prop, doc) in MODEL_PARAMETERS.items()
    ]


def declared_parameters(cruise_speed_mps: float, conflict_shift_s: float) -> list[ParameterSpec]:
    return [
        ParameterSpec("TimeShift", "double", 0.0, "Delay of the threat scooter's recorded timing (s)."),
        ParameterSpec("RiderType", "string", "replay", f"Threat scooter rider: one of {', '.join(RIDER_TYPES)}."),
        ParameterSpec("CapEnabled", "boolean", False, "The ego's collision-avoidance planner is active."),
        ParameterSpec("EgoCruiseSpeed", "double", round(cruise_speed_mps, 2), "Cruise speed of the ego (m/s)."),
        ParameterSpec(
            "ConflictTimeShift",
            "double",
            round(conflict_shift_s, 3),
            "TimeShift that brings the threat scooter to the conflict point with the ego (s).",
        ),
    ]
