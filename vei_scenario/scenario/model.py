"""Build the VEI scenario model from a reconstruction: entities, threat, parameters, variations."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from vei_scenario.errors import VeiInputError
from vei_scenario.geometry.conflict import Conflict, analyse_conflict, primary_threat
from vei_scenario.geometry.reconstruct import Reconstruction
from vei_scenario.geometry.resample import Trajectory
from vei_scenario.models.cap import CapParameters
from vei_scenario.models.sfm import RIDER_TYPES, SfmParameters
from vei_scenario.scenario.parameters import ParameterSpec, declared_parameters, model_parameters
from vei_scenario.scenario.road_users import E_SCOOTER, road_user_class

#: E-scooter with a standing rider (m): deck and bars ~1.1–1.2 m long, shoulders ~0.6 m, ~1.9 m tall.
SCOOTER_BOX_M = (E_SCOOTER.length_m, E_SCOOTER.width_m, E_SCOOTER.height_m)
EGO_HEIGHT_M = 1.5
#: Timing shifts of the variation set, around the conflict shift (s). The SFM's desired speed defaults
#: to the threat's median recorded speed, so that a model rider keeps the recorded pace.
SHIFT_OFFSETS_S = (-1.0, -0.5, 0.0, 0.5, 1.0)


@dataclass(frozen=True)
class EntitySpec:
    name: str
    category: str  # the OpenSCENARIO category of its kind ("car", "bicycle", "pedestrian", ...)
    length_m: float
    width_m: float
    height_m: float
    trajectory: Trajectory
    kind: str = "vehicle"  # the ScenarioObject element: "vehicle", "pedestrian" or "misc"
    #: the annotated category where OpenSCENARIO's is coarser ("e-scooter"): the objectType property
    object_type: str = ""
    mass_kg: float = 0.0


@dataclass(frozen=True)
class ScenarioModel:
    name: str
    description: str
    date: str | None
    proj_string: str
    entities: tuple[EntitySpec, ...]  # Ego first, then scooters by track id, then other road users
    threat: str
    conflicts: dict[str, Conflict]
    parameters: tuple[ParameterSpec, ...]
    sfm: SfmParameters = field(default_factory=SfmParameters)
    cap: CapParameters = field(default_factory=CapParameters)
    duration_s: float = 0.0
    #: The OpenDRIVE file as the scenario's LogicFile names it (relative to the .xosc).
    road_file: str = "scenario.xodr"

    @property
    def ego(self) -> EntitySpec:
        return self.entities[0]

    def parameter(self, name: str) -> ParameterSpec:
        return next(p for p in self.parameters if p.name == name)

    def defaults(self) -> dict[str, object]:
        return {p.name: p.default for p in self.parameters}

    def variations(self) -> dict[str, list[object]]:
        """The seed method's variations: timing shifts (0 and around the conflict shift), the three
        rider types, CAP off/on."""
        c = self.parameter("ConflictTimeShift").default
        shifts = sorted({0.0, *(round(float(c) + o, 3) for o in SHIFT_OFFSETS_S)})
        return {"TimeShift": shifts, "RiderType": list(RIDER_TYPES), "CapEnabled": [False, True]}


def build_model(
    rec: Reconstruction, threat: str | None = None, name: str | None = None, expose_models: bool = False
) -> ScenarioModel:
    """Entities from the reconstruction, conflicts for every scooter, the threat and the parameters."""
    clip = rec.clip
    cruise = float(np.median(clip.ego.speed_mps))
    # the ego drives its path at the cruise speed: where that takes it past the end of its recording it
    # runs straight on (as esmini's default does on), not stopping dead where the path ends
    short = cruise * rec.duration_s - float(rec.ego.arc_length()[-1])
    ego_path = with_run_out(rec.ego, max(short, 0.0) + EGO_RUN_OUT_MARGIN_M)
    ego = EntitySpec("Ego", "car", clip.ego.length_m, clip.ego.width_m, EGO_HEIGHT_M, ego_path)
    scooters = tuple(
        EntitySpec(tid, "bicycle", *SCOOTER_BOX_M, track.trajectory, object_type="e-scooter", mass_kg=E_SCOOTER.mass_kg)
        for tid, track in sorted(rec.scooters.items())
    )
    others = tuple(_road_user(tid, track.category, track.trajectory) for tid, track in sorted(rec.others.items()))
    ego_box = (ego.length_m, ego.width_m)
    driven = ego_at_constant_speed(rec.ego, cruise)
    if driven.t.size < 2 or cruise < MIN_CRUISE_MPS:  # (no path to time a conflict on, no speed to drive it)
        raise VeiInputError(
            clip.path,
            "ego.samples",
            f"the ego does not drive in this clip (median speed {cruise:.2f} m/s, track "
            f"{float(rec.ego.arc_length()[-1]):.1f} m long): vei reconstructs encounters with a moving vehicle",
        )
    conflicts = {
        s.name: analyse_conflict(s.name, driven, s.trajectory, ego_box, (s.length_m, s.width_m)) for s in scooters
    }
    if threat is None:
        threat = primary_threat(conflicts)
    elif threat not in conflicts:
        raise VeiInputError(
            clip.path, "--threat", f"no e-scooter track {threat!r} (tracks: {', '.join(sorted(conflicts))})"
        )
    params = tuple(declared_parameters(cruise, conflicts[threat].time_shift_s))
    threat_speed = float(np.median(rec.scooters[threat].trajectory.speed))
    sfm, cap = SfmParameters(v0_mps=round(threat_speed, 2)), CapParameters()
    if expose_models:  # the model parameters become scenario parameters (their properties read $Name)
        params += tuple(model_parameters(sfm, cap))
    return ScenarioModel(
        name=name or clip.id,
        description=f"Reconstructed vehicle–e-scooter interaction from clip {clip.id}",
        date=clip.recorded_at,
        proj_string=rec.projection.proj_string,
        entities=(ego, *scooters, *others),
        threat=threat,
        conflicts=conflicts,
        parameters=params,
        sfm=sfm,
        cap=cap,
        duration_s=rec.duration_s,
    )


def _road_user(name: str, category: str, trajectory: Trajectory) -> EntitySpec:
    """A road user vei has no behaviour model for: replayed as recorded, typed by its category. Not a
    candidate threat (the conflict analysis and the rider model are the e-scooters')."""
    cls = road_user_class(category)
    object_type = "" if cls.category == category.strip().lower() else category
    return EntitySpec(
        name, cls.category, cls.length_m, cls.width_m, cls.height_m, trajectory, cls.kind, object_type, cls.mass_kg
    )


#: Below this median speed (m/s) the ego is taken to stand for the whole clip.
MIN_CRUISE_MPS = 0.1

#: How far the ego's path runs on beyond what driving it at the cruise speed needs (m).
EGO_RUN_OUT_MARGIN_M = 10.0


def with_run_out(traj: Trajectory, metres: float) -> Trajectory:
    """``traj`` with one more sample ``metres`` straight ahead of its last, reached at its last speed."""
    h, v = float(traj.yaw[-1]), max(float(traj.speed[-1]), 0.1)
    return Trajectory(
        np.append(traj.t, traj.t[-1] + metres / v),
        np.append(traj.x, traj.x[-1] + metres * np.cos(h)),
        np.append(traj.y, traj.y[-1] + metres * np.sin(h)),
        np.append(traj.yaw, h),
        np.append(traj.speed, traj.speed[-1]),
    )


def ego_at_constant_speed(ego: Trajectory, speed_mps: float) -> Trajectory:
    """The ego as the scenario drives it without the planner: its path at a constant speed from t = 0.

    The conflict analysis times the ego this way, so that ``ConflictTimeShift`` centres the collision
    for the scenario as written, not for the recorded speed profile (they differ by ~0.1 s here).
    """
    arc = ego.arc_length()
    t = arc / max(speed_mps, 0.1)
    keep = np.concatenate([[True], np.diff(t) > 1e-9])
    return Trajectory(t[keep], ego.x[keep], ego.y[keep], ego.yaw[keep], np.full(int(keep.sum()), speed_mps))
