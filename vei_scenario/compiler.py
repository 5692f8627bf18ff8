"""``compile_clip``: the whole compile pipeline, clip file in, scenario files out.

clip → reconstruction (projection, time sync, world frame, resampling) → road network → conflict
analysis and scenario model → OpenSCENARIO + OpenDRIVE + variation files. Everything is rendered in
memory and written only when every file rendered, each file through a temporary file and a rename, so
a failure leaves no output behind.
"""

from __future__ import annotations

import os
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import TYPE_CHECKING

import shapely

from vei_scenario.atomic_io import OutputSet
from vei_scenario.clip import load_clip
from vei_scenario.errors import VeiInputError
from vei_scenario.geometry.projection import LocalProjection
from vei_scenario.geometry.scene_box import coarse_bbox_latlon
from vei_scenario.openscenario import SUPPORTED_MINOR_VERSIONS
from vei_scenario.roads.netconvert import NetconvertJob
from vei_scenario.roads.opendrive_lanes import read_lane_areas_from_bytes, share_on_lanes
from vei_scenario.roads.opendrive_output import finalize_opendrive
from vei_scenario.roads.osm_region import DEFAULT_MARGIN_M, crop_osm, fetch_osm

if TYPE_CHECKING:
    from vei_scenario.geometry.reconstruct import Reconstruction
    from vei_scenario.scenario.model import ScenarioModel


@dataclass(frozen=True)
class CompileOptions:
    rate_hz: float = 10.0
    osc_minor_version: int = 3
    osm: Path | None = None  # overrides the clip's map.osm
    osm_fetch: bool = False  # download the map by bounding box (online only)
    no_map: bool = False  # ignore any map: fit a road to the ego track
    map_margin_m: float = DEFAULT_MARGIN_M
    threat: str | None = None
    variants_dir: Path | None = None
    smooth: bool = True
    #: declare the rider's and the planner's model parameters as scenario parameters (MODEL_PARAMETERS)
    model_parameters: bool = False
    #: also write STEM.stochastic.xosc, a stochastic distribution for vei probability
    stochastic: bool = False
    #: the frame rate of an OpenLABEL clip without timestamps (Hz)
    frame_rate_hz: float | None = None
    #: the unit of an OpenLABEL clip's timestamps written as numbers (s, ms, us, ns; default s)
    time_unit: str | None = None


@dataclass
class CompileResult:
    model: ScenarioModel
    reconstruction: Reconstruction
    road_source: str  # "osm:<file>" or "fitted"
    ego_on_lanes: float  # share of ego GPS fixes inside driving lanes of the road network
    written: list[Path] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)


def _check_options(opts: CompileOptions) -> None:
    if not (0.5 <= opts.rate_hz <= 1000):
        raise VeiInputError(None, "--rate", f"{opts.rate_hz} Hz is outside 0.5..1000 Hz")
    if opts.osc_minor_version not in SUPPORTED_MINOR_VERSIONS:
        raise VeiInputError(None, "--osc-version", f"1.{opts.osc_minor_version} is not supported (1.0 to 1.3)")
    if opts.stochastic and opts.osc_minor_version == 0:
        raise VeiInputError(
            None, "--stochastic", "varies TimeShift, which an OpenSCENARIO 1.0 scenario does not declare (use 1.1+)"
        )


@dataclass
class _RoadJob:
    """The road network in the making: netconvert running in the background, or a road to fit."""

    proj_string: str
    source: str  # "osm:<file name>" or "fitted"
    netconvert: NetconvertJob | None = None

    def cancel(self) -> None:
        if self.netconvert is not None:
            self.netconvert.cancel()


def _start_road_network(clip, proj: LocalProjection, opts: CompileOptions, out_dir: Path, notes: list[str]) -> _RoadJob:
    """Crop the map and start netconvert (or decide on a fitted road) before the reconstruction."""
    osm = None if opts.no_map else (opts.osm or clip.osm_path)
    box = coarse_bbox_latlon(clip, proj, opts.map_margin_m)
    if opts.osm_fetch and not opts.no_map and opts.osm is None:
        osm = fetch_osm(box, out_dir / "map.osm")
    if osm is None:
        return _RoadJob(proj.proj_string, "fitted")
    if opts.osm is None and not Path(osm).is_file():  # the clip's own map reference (relative to the clip)
        raise VeiInputError(
            clip.path,
            "map.osm",
            f"map file not found at {osm} (the path is relative to the clip: copy the map beside it, "
            "or give --osm FILE or --no-map)",
        )
    region = crop_osm(Path(osm), box)
    if region.n_missing_nodes:
        notes.append(f"map: {region.n_missing_nodes} node references outside the extract were dropped")
    job = NetconvertJob(region.xml, proj.proj_string, Path(osm))
    return _RoadJob(proj.proj_string, f"osm:{Path(osm).name}", job)


def _finish_road_network(job: _RoadJob, rec) -> bytes:
    """The normalised OpenDRIVE bytes of the road network."""
    clip = rec.clip
    if job.netconvert is not None:
        return finalize_opendrive(job.netconvert.result(), clip.id, job.proj_string, clip.recorded_at)
    from vei_scenario.roads.fitted_road import fitted_road_element

    try:
        raw = ET.tostring(fitted_road_element(rec.ego))
    except ValueError as exc:
        raise VeiInputError(clip.path, "ego.samples", str(exc)) from None
    bounds = shapely.union_all([a.polygon for a in read_lane_areas_from_bytes(raw)]).bounds
    return finalize_opendrive(raw, clip.id, job.proj_string, clip.recorded_at, bounds)


def compile_clip(clip_path: str | Path, output: str | Path, options: CompileOptions | None = None) -> CompileResult:
    """Compile ``clip_path`` into ``output`` (a ``.xosc`` path) plus its ``.xodr`` and variation files."""
    opts = options or CompileOptions()
    _check_options(opts)
    output = Path(output)
    if output.suffix != ".xosc":
        raise VeiInputError(output, "-o", "the output must be a .xosc file")
    clip = load_clip(clip_path, opts.frame_rate_hz, opts.time_unit)
    proj = LocalProjection(float(clip.ego.lat[0]), float(clip.ego.lon[0]))
    notes: list[str] = []
    road = _start_road_network(clip, proj, opts, output.parent, notes)
    try:
        # The heavy imports (scipy, scenariogeneration: ~1 s) and the reconstruction overlap with
        # netconvert, which runs on the other core.
        from vei_scenario.geometry.reconstruct import reconstruct
        from vei_scenario.scenario.model import build_model
        from vei_scenario.scenario.road_users import replay_note

        rec = reconstruct(clip, rate_hz=opts.rate_hz, smooth=opts.smooth)
        for tid, why in sorted(rec.skipped_tracks.items()):
            notes.append(f"track {tid}: {why}")
        for tid, track in sorted(rec.others.items()):
            notes.append(f"track {tid}: {replay_note(track.category)}")
        for tid, track in sorted(rec.road_users.items()):
            for a, b in track.gaps:
                notes.append(f"track {tid}: not observed for {b - a:.1f} s (t = {a:.1f}..{b:.1f} s); spline-bridged")
        stem = output.stem
        xodr_path = output.with_suffix(".xodr")
        model = _with_road_file(
            build_model(rec, threat=opts.threat, name=stem, expose_models=opts.model_parameters), xodr_path.name
        )
        xodr_bytes = _finish_road_network(road, rec)
    except BaseException:
        road.cancel()
        raise
    road_source = road.source
    ego_box = (rec.ego_fix_x.min(), rec.ego_fix_y.min(), rec.ego_fix_x.max(), rec.ego_fix_y.max())
    share = share_on_lanes(read_lane_areas_from_bytes(xodr_bytes, bbox=ego_box), rec.ego_fix_x, rec.ego_fix_y)

    from vei_scenario.openscenario.distribution_writer import (
        distribution_xml,
        stochastic_distribution_xml,
        variant_combinations,
        variant_filename,
    )
    from vei_scenario.openscenario.scenario_writer import declares_time_shift, scenario_xml

    outputs = OutputSet()
    outputs.add(output, scenario_xml(model, opts.osc_minor_version))
    outputs.add(xodr_path, xodr_bytes)
    # ParameterValueDistribution exists since OpenSCENARIO 1.1; a 1.0 scenario gets a 1.1 distribution.
    dist_minor = max(opts.osc_minor_version, 1)
    if dist_minor != opts.osc_minor_version:
        notes.append("OpenSCENARIO 1.0 has no ParameterValueDistribution: the variations file is written as 1.1")
        notes.append(
            "OpenSCENARIO 1.0 has no expressions for the Timing offset ${-$TimeShift}: the 1.0 scenario replays the"
            " threat as recorded and declares no TimeShift (the --variants files carry each shift)"
        )
    outputs.add(
        output.with_name(f"{stem}.variations.xosc"),
        distribution_xml(model, output.name, dist_minor, time_shift=declares_time_shift(opts.osc_minor_version)),
    )
    if opts.stochastic:
        outputs.add(
            output.with_name(f"{stem}.stochastic.xosc"), stochastic_distribution_xml(model, output.name, dist_minor)
        )
    if opts.variants_dir is not None:
        vdir = Path(opts.variants_dir)
        for i, values in enumerate(variant_combinations(model)):
            vmodel = _with_road_file(model, _relative(xodr_path, vdir))
            outputs.add(
                vdir / variant_filename(i, values), scenario_xml(vmodel, opts.osc_minor_version, resolved=values)
            )
    outputs.commit()
    return CompileResult(model, rec, road_source, share, outputs.paths, notes)


def _relative(target: Path, from_dir: Path) -> str:
    return Path(os.path.relpath(target.resolve(), from_dir.resolve())).as_posix()


def _with_road_file(model: ScenarioModel, road_file: str) -> ScenarioModel:
    return replace(model, road_file=road_file)
