"""Catalog entries are read and resolved once per process and reused (a sweep loads the same entries for
every variant), and never where that would change the result: an entry resolved with other parameter
values (its own, assigned ones, or the scenario's it reads), a catalog file that changed on disk, and
an entry that refers to other entries all give what a fresh process gives."""

from __future__ import annotations

import os

import pytest

from vei_scenario.interpreter import clear_file_caches, load_scenario, run_scenario


def _catalog(length_default: str = "4.5", extra: str = "") -> str:
    return f"""<?xml version="1.0"?>
<OpenSCENARIO><FileHeader revMajor="1" revMinor="2" date="2024-01-01T00:00:00" description="" author=""/>
<Catalog name="VehicleCatalog">
<Vehicle name="car" vehicleCategory="car"><ParameterDeclarations>
<ParameterDeclaration name="Length" parameterType="double" value="{length_default}"/>
<ParameterDeclaration name="Top" parameterType="double" value="${{$Length * 10}}"/></ParameterDeclarations>
<BoundingBox><Center x="1.4" y="0" z="0.7"/><Dimensions width="$Width" length="$Length" height="1.4"/></BoundingBox>
<Performance maxSpeed="$Top" maxAcceleration="10" maxDeceleration="10"/>
<Axles><FrontAxle maxSteering="0.5" wheelDiameter="0.6" trackWidth="1.6" positionX="2.8" positionZ="0.3"/>
<RearAxle maxSteering="0" wheelDiameter="0.6" trackWidth="1.6" positionX="0" positionZ="0.3"/></Axles>
<Properties/></Vehicle>{extra}</Catalog></OpenSCENARIO>"""


#: A trajectory entry, and a maneuver entry that refers to it (its start x passed on as a parameter).
NESTED = """</Catalog><Catalog name="Trajectories"><Trajectory name="line" closed="false"><ParameterDeclarations>
<ParameterDeclaration name="X0" parameterType="double" value="0"/></ParameterDeclarations><Shape><Polyline>
<Vertex><Position><WorldPosition x="$X0" y="0"/></Position></Vertex>
<Vertex><Position><WorldPosition x="${$X0 + 100}" y="0"/></Position></Vertex></Polyline></Shape></Trajectory>
</Catalog><Catalog name="Maneuvers"><Maneuver name="drive"><ParameterDeclarations>
<ParameterDeclaration name="Start" parameterType="double" value="0"/></ParameterDeclarations>
<Event name="e" priority="parallel"><Action name="a"><PrivateAction><RoutingAction><FollowTrajectoryAction>
<TrajectoryRef><CatalogReference catalogName="Trajectories" entryName="line"><ParameterAssignments>
<ParameterAssignment parameterRef="X0" value="$Start"/></ParameterAssignments></CatalogReference></TrajectoryRef>
<TimeReference><None/></TimeReference><TrajectoryFollowingMode followingMode="position"/></FollowTrajectoryAction>
</RoutingAction></PrivateAction></Action><StartTrigger><ConditionGroup><Condition name="c" delay="0"
conditionEdge="none"><ByValueCondition><SimulationTimeCondition value="0" rule="greaterOrEqual"/>
</ByValueCondition></Condition></ConditionGroup></StartTrigger></Event></Maneuver>"""


def _scenario(tmp_path, assign_length: bool, maneuver: bool = False):
    assignment = (
        '<ParameterAssignments><ParameterAssignment parameterRef="Length" value="$CarLength"/></ParameterAssignments>'
        if assign_length
        else ""
    )
    story = ""
    if maneuver:
        story = (
            '<Story name="s"><Act name="a"><ManeuverGroup name="g" maximumExecutionCount="1"><Actors '
            'selectTriggeringEntities="false"><EntityRef entityRef="Ego"/></Actors><CatalogReference '
            'catalogName="Maneuvers" entryName="drive"><ParameterAssignments><ParameterAssignment parameterRef="Start" '
            'value="$StartX"/></ParameterAssignments></CatalogReference></ManeuverGroup><StartTrigger><ConditionGroup>'
            '<Condition name="go" delay="0" conditionEdge="none"><ByValueCondition><SimulationTimeCondition value="0" '
            'rule="greaterOrEqual"/></ByValueCondition></Condition></ConditionGroup></StartTrigger></Act></Story>'
        )
    path = tmp_path / "s.xosc"
    path.write_text(
        f"""<?xml version="1.0"?>
<OpenSCENARIO><FileHeader revMajor="1" revMinor="2" date="2024-01-01T00:00:00" description="" author=""/>
<ParameterDeclarations><ParameterDeclaration name="CarLength" parameterType="double" value="4.0"/>
<ParameterDeclaration name="Width" parameterType="double" value="1.8"/>
<ParameterDeclaration name="StartX" parameterType="double" value="0"/></ParameterDeclarations>
<CatalogLocations><VehicleCatalog><Directory path="cat"/></VehicleCatalog></CatalogLocations><RoadNetwork/>
<Entities><ScenarioObject name="Ego"><CatalogReference catalogName="VehicleCatalog" entryName="car">{assignment}
</CatalogReference></ScenarioObject></Entities>
<Storyboard><Init><Actions><Private entityRef="Ego"><PrivateAction><TeleportAction><Position><WorldPosition x="0"
y="0" h="0"/></Position></TeleportAction></PrivateAction><PrivateAction><LongitudinalAction><SpeedAction>
<SpeedActionDynamics dynamicsShape="step" value="0" dynamicsDimension="time"/><SpeedActionTarget>
<AbsoluteTargetSpeed value="10"/></SpeedActionTarget></SpeedAction></LongitudinalAction></PrivateAction></Private>
</Actions></Init>{story}<StopTrigger><ConditionGroup><Condition name="end" delay="0" conditionEdge="none">
<ByValueCondition><SimulationTimeCondition value="1" rule="greaterThan"/></ByValueCondition></Condition>
</ConditionGroup></StopTrigger></Storyboard></OpenSCENARIO>"""
    )
    return path


def _write_catalog(tmp_path, text: str) -> None:
    (tmp_path / "cat").mkdir(exist_ok=True)
    (tmp_path / "cat" / "vehicles.xosc").write_text(text)


def _box(path, values: dict) -> tuple[str, str, str]:
    dims = load_scenario(path, values).root.find(".//ScenarioObject/Vehicle/BoundingBox/Dimensions")
    perf = load_scenario(path, values).root.find(".//ScenarioObject/Vehicle/Performance")
    return dims.get("length"), dims.get("width"), perf.get("maxSpeed")


def test_an_entry_follows_the_values_it_is_resolved_with(tmp_path):
    """The same entry, loaded again and again in one process with the values of an assignment, of
    the scenario's parameters it reads itself, and its own defaults derived from them."""
    _write_catalog(tmp_path, _catalog())
    assigned = _scenario(tmp_path, assign_length=True)
    assert _box(assigned, {}) == ("4.0", "1.8", "40")
    assert _box(assigned, {"CarLength": 5.5}) == ("5.5", "1.8", "55")
    assert _box(assigned, {"CarLength": 5.5, "Width": 2.1}) == ("5.5", "2.1", "55")  # (read from the scenario)
    assert _box(assigned, {}) == ("4.0", "1.8", "40")
    own = _scenario(tmp_path, assign_length=False)  # the entry's default length
    assert _box(own, {"CarLength": 5.5}) == ("4.5", "1.8", "45")


def test_a_catalog_file_changed_on_disk_is_read_again(tmp_path):
    _write_catalog(tmp_path, _catalog("4.5"))
    path = _scenario(tmp_path, assign_length=False)
    assert _box(path, {}) == ("4.5", "1.8", "45")
    catalog = tmp_path / "cat" / "vehicles.xosc"
    stat = catalog.stat()
    _write_catalog(tmp_path, _catalog("3.5"))  # (same size, and the same modification time)
    os.utime(catalog, ns=(stat.st_atime_ns, stat.st_mtime_ns))
    assert _box(path, {}) == ("3.5", "1.8", "35")


@pytest.mark.parametrize("start", [0.0, 12.5, -7.0])
def test_entries_referring_to_entries_take_the_values_passed_on(tmp_path, start):
    """A maneuver entry passes its parameter on to the trajectory entry it refers to: each start gives
    its own path, in one process, as a fresh one gives it."""
    _write_catalog(tmp_path, _catalog(extra=NESTED))
    path = _scenario(tmp_path, assign_length=False, maneuver=True)
    for warm in (12.5, 0.0):  # (other values resolved first)
        run_scenario(path, {"StartX": warm})
    x = run_scenario(path, {"StartX": start}).traces["Ego"].x
    clear_file_caches()
    fresh = run_scenario(path, {"StartX": start}).traces["Ego"].x
    assert x[0] == start and x[-1] > start + 9.0
    assert list(x) == list(fresh)


# --- trajectories built once per process ---------------------------------------------------------------


def _road(lane_width: float) -> str:
    return (
        '<OpenDRIVE><header revMajor="1" revMinor="6"/><road id="1" length="300" junction="-1"><planView>'
        '<geometry s="0" x="0" y="0" hdg="0" length="300"><line/></geometry></planView><lanes><laneSection s="0">'
        '<center><lane id="0" type="none"/></center><right><lane id="-1" type="driving"><width sOffset="0" '
        f'a="{lane_width}" b="0" c="0" d="0"/></lane></right></laneSection></lanes></road></OpenDRIVE>'
    )


def _on_a_trajectory(tmp_path) -> object:
    """Ego following an untimed clothoid that starts on lane -1 at s = $S0 (a road position's place)."""
    path = _scenario(tmp_path, assign_length=False)
    shape = (
        '<Clothoid curvature="0.01" curvatureDot="0" length="80"><Position><LanePosition roadId="1" laneId="-1" '
        's="$S0" offset="0"/></Position></Clothoid>'
    )
    follow = (
        '<PrivateAction><RoutingAction><FollowTrajectoryAction><TrajectoryRef><Trajectory name="t" closed="false">'
        f"<Shape>{shape}</Shape></Trajectory></TrajectoryRef><TimeReference><None/></TimeReference>"
        '<TrajectoryFollowingMode followingMode="position"/></FollowTrajectoryAction></RoutingAction></PrivateAction>'
    )
    text = path.read_text()
    text = text.replace("<RoadNetwork/>", '<RoadNetwork><LogicFile filepath="road.xodr"/></RoadNetwork>')
    text = text.replace('<ParameterDeclarations><ParameterDeclaration name="CarLength"',
                        '<ParameterDeclarations><ParameterDeclaration name="S0" parameterType="double" value="10"/>'
                        '<ParameterDeclaration name="CarLength"')  # fmt: skip
    text = text.replace("</Private>\n</Actions>", f"{follow}</Private>\n</Actions>")
    assert follow in text and "S0" in text
    path.write_text(text)
    return path


def test_a_trajectory_follows_its_values_and_its_road(tmp_path):
    """The same trajectory with another start, and on a road whose lane changed on disk: each run
    places it as a fresh process does."""
    _write_catalog(tmp_path, _catalog())
    (tmp_path / "road.xodr").write_text(_road(3.5))
    path = _on_a_trajectory(tmp_path)

    def start(values):
        ego = run_scenario(path, values).traces["Ego"]
        return ego.x[0], ego.y[0]

    assert start({}) == pytest.approx((10.0, -1.75))
    assert start({"S0": 30.0}) == pytest.approx((30.0, -1.75))
    assert start({}) == pytest.approx((10.0, -1.75))
    (tmp_path / "road.xodr").write_text(_road(5.0))
    assert start({}) == pytest.approx((10.0, -2.5))
    clear_file_caches()
    assert start({}) == pytest.approx((10.0, -2.5))
