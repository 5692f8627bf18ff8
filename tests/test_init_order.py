# ruff: noqa: E501  (the hand-written scenarios keep their XML lines whole)
"""Init actions that read another road user start after that road user's own Init actions (esmini
reorders them so; the ASAM example SlowPrecedingVehicle places the ego 200 m behind a car teleported
after it), and a RelativeLanePosition is taken along the road's reference line and by lane ids, as
esmini 3.6 takes it whichever way the reference car faces. Expected places are worked out from the
road's lane widths; where esmini is installed the same files are played by it too."""

from __future__ import annotations

import pytest
from lxml import etree

from vei_scenario.errors import VeiInputError
from vei_scenario.interpreter import run_scenario
from vei_scenario.interpreter.init_order import init_order
from vei_scenario.safe_xml import safe_parser

DT = 0.1
W = 3.5  # every lane's width: lane k's centre is at t = sign(k) (|k| - 0.5) W


def _road(path) -> None:
    def lane(i: int) -> str:
        return f'<lane id="{i}" type="driving" level="false"><width sOffset="0" a="{W}" b="0" c="0" d="0"/></lane>'

    path.write_text(
        '<?xml version="1.0"?><OpenDRIVE><header revMajor="1" revMinor="6" name="r" version="1"/>'
        '<road name="r" length="1000" id="1" junction="-1"><link/><planView><geometry s="0" x="0" y="0" hdg="0" '
        'length="1000"><line/></geometry></planView><lanes><laneSection s="0">'
        f'<left>{lane(2)}{lane(1)}</left><center><lane id="0" type="none" level="false"/></center>'
        f"<right>{lane(-1)}{lane(-2)}</right></laneSection></lanes></road></OpenDRIVE>"
    )


def _car(name: str) -> str:
    return (
        f'<ScenarioObject name="{name}"><Vehicle name="{name}" vehicleCategory="car"><BoundingBox><Center x="1.4" y="0" z="0.9"/>'
        '<Dimensions width="2" length="5" height="1.8"/></BoundingBox><Performance maxSpeed="69" maxDeceleration="30" maxAcceleration="10"/>'
        '<Axles><FrontAxle maxSteering="0.5" wheelDiameter="0.8" trackWidth="1.68" positionX="2.98" positionZ="0.4"/>'
        '<RearAxle maxSteering="0" wheelDiameter="0.8" trackWidth="1.68" positionX="0" positionZ="0.4"/></Axles><Properties/></Vehicle></ScenarioObject>'
    )


def tp(position: str) -> str:
    return f"<PrivateAction><TeleportAction><Position>{position}</Position></TeleportAction></PrivateAction>"


def speed(target: str) -> str:
    return (
        '<PrivateAction><LongitudinalAction><SpeedAction><SpeedActionDynamics dynamicsShape="step" dynamicsDimension="time" value="0"/>'
        f"<SpeedActionTarget>{target}</SpeedActionTarget></SpeedAction></LongitudinalAction></PrivateAction>"
    )


def lane_at(lane: int, s: float, extra: str = "") -> str:
    return f'<LanePosition roadId="1" laneId="{lane}" offset="0" s="{s}">{extra}</LanePosition>'


def _scenario(tmp_path, privates: dict[str, str]) -> object:
    """Three cars, each with the Init actions given (in the order given), on a straight road."""
    _road(tmp_path / "road.xodr")
    init = "".join(f'<Private entityRef="{n}">{a}</Private>' for n, a in privates.items())
    xosc = f"""<?xml version="1.0"?><OpenSCENARIO><FileHeader revMajor="1" revMinor="1" date="2024-01-01T00:00:00" description="p" author="t"/>
<ParameterDeclarations/><CatalogLocations/><RoadNetwork><LogicFile filepath="road.xodr"/></RoadNetwork>
<Entities>{_car("Ego")}{_car("A1")}{_car("B")}</Entities><Storyboard><Init><Actions>{init}</Actions></Init>
<StopTrigger><ConditionGroup><Condition name="e" delay="0" conditionEdge="none"><ByValueCondition><SimulationTimeCondition value="1" rule="greaterThan"/></ByValueCondition></Condition></ConditionGroup></StopTrigger></Storyboard></OpenSCENARIO>"""
    path = tmp_path / "s.xosc"
    path.write_text(xosc)
    return path


def _start(result) -> dict[str, tuple[float, float, float]]:
    return {n: (float(tr.x[0]), float(tr.y[0]), float(tr.speed[0])) for n, tr in result.traces.items()}


def centre(lane: int) -> float:
    return (1 if lane > 0 else -1) * (abs(lane) - 0.5) * W


CASES = {
    # the ASAM SlowPrecedingVehicle pattern: the ego relative to a car placed after it, and at its speed
    "ahead_of_its_reference": (
        {
            "Ego": tp('<RelativeLanePosition entityRef="A1" dLane="0" ds="-50"/>')
            + speed('<RelativeTargetSpeed entityRef="A1" value="0" speedTargetValueType="delta" continuous="false"/>'),
            "A1": speed('<AbsoluteTargetSpeed value="20"/>') + tp(lane_at(-1, 200)),
            "B": tp(lane_at(1, 100)),
        },
        {"Ego": (150, centre(-1), 20), "A1": (200, centre(-1), 20), "B": (100, centre(1), 0)},
    ),
    # a chain: the ego relative to A1, A1 relative to B, B placed last
    "chain": (
        {
            "Ego": tp('<RelativeLanePosition entityRef="A1" dLane="0" ds="-50"/>'),
            "A1": tp('<RelativeLanePosition entityRef="B" dLane="-2" ds="100"/>'),
            "B": tp(lane_at(1, 100)),
        },
        {"Ego": (150, centre(-2), 0), "A1": (200, centre(-2), 0), "B": (100, centre(1), 0)},
    ),
    # not a circle: the ego's place reads A1's place, A1's speed reads the ego's speed
    "place_and_speed_cross": (
        {
            "Ego": tp('<RelativeLanePosition entityRef="A1" dLane="0" ds="-50"/>')
            + speed('<AbsoluteTargetSpeed value="5"/>'),
            "A1": tp(lane_at(-1, 200))
            + speed('<RelativeTargetSpeed entityRef="Ego" value="3" speedTargetValueType="delta" continuous="false"/>'),
            "B": tp(lane_at(1, 100)),
        },
        {"Ego": (150, centre(-1), 5), "A1": (200, centre(-1), 8), "B": (100, centre(1), 0)},
    ),
    "object_and_world_relative": (
        {
            "Ego": tp('<RelativeObjectPosition entityRef="A1" dx="-20" dy="1"/>'),
            "A1": tp(lane_at(-1, 200)),
            "B": tp('<RelativeWorldPosition entityRef="Ego" dx="-20" dy="0"/>'),
        },
        {"Ego": (180, centre(-1) + 1, 0), "A1": (200, centre(-1), 0), "B": (160, centre(-1) + 1, 0)},
    ),
    # RelativeLanePosition from a car in the oncoming lane (facing its lane's direction): along s, by lane ids
    "from_an_oncoming_car": (
        {
            "B": tp(lane_at(1, 200)),
            "A1": tp('<RelativeLanePosition entityRef="B" dLane="-1" ds="50"/>'),
            "Ego": tp('<RelativeLanePosition entityRef="B" dLane="1" ds="-30"/>'),
        },
        {"B": (200, centre(1), 0), "A1": (250, centre(-1), 0), "Ego": (170, centre(2), 0)},
    ),
    # ... and from a wrong-way car (in a right lane, turned round)
    "from_a_wrong_way_car": (
        {
            "B": tp(lane_at(-1, 200, '<Orientation type="relative" h="3.14159265"/>')),
            "A1": tp('<RelativeLanePosition entityRef="B" dLane="-1" ds="50"/>'),
            "Ego": tp('<RelativeLanePosition entityRef="B" dLane="2" ds="-30"/>'),
        },
        {"B": (200, centre(-1), 0), "A1": (250, centre(-2), 0), "Ego": (170, centre(2), 0)},
    ),
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_init_places_and_speeds(tmp_path, case):
    privates, expected = CASES[case]
    result = run_scenario(_scenario(tmp_path, privates), {}, DT)
    got = _start(result)
    for name, (x, y, v) in expected.items():
        assert got[name] == pytest.approx((x, y, v), abs=1e-9), name
    assert result.warnings == ()
    if case.startswith("from_"):  # a relative lane position heads along the road (esmini), not the lane
        assert abs(float(result.traces["A1"].yaw[0])) < 1e-9 and abs(float(result.traces["Ego"].yaw[0])) < 1e-9


@pytest.mark.parametrize("case", sorted(CASES))
def test_init_places_as_esmini_plays_them(tmp_path, case, esmini):
    from vei_scenario.conformance.esmini import run_esmini

    path = _scenario(tmp_path, CASES[case][0])
    ours = _start(run_scenario(path, {}, DT))
    theirs = run_esmini(esmini, path, DT)
    for name, tr in theirs.tracks.items():
        assert ours[name] == pytest.approx((float(tr.x[0]), float(tr.y[0]), float(tr.speed[0])), abs=0.02), name


def test_places_that_read_each_other_in_a_circle_start_in_file_order_with_a_warning(tmp_path):
    privates = {
        "Ego": tp('<RelativeLanePosition entityRef="A1" dLane="0" ds="-50"/>'),
        "A1": tp('<RelativeLanePosition entityRef="Ego" dLane="0" ds="-30"/>'),
        "B": tp(lane_at(1, 100)),
    }
    result = run_scenario(_scenario(tmp_path, privates), {}, DT)
    assert len(result.warnings) == 1 and "in a circle" in result.warnings[0] and "s.xosc: line " in result.warnings[0]


def test_the_order_itself():
    """File order is kept where nothing reads a later road user; a reader moves right after the last
    action that sets what it reads, and only that far."""
    root = etree.fromstring(
        "<I><P a='Ego'><TeleportAction><Position><RelativeLanePosition entityRef='A1'/></Position></TeleportAction></P>"
        "<P a='Ego'><SpeedAction/></P><P a='A1'><SpeedAction/></P><P a='A1'><TeleportAction/></P>"
        "<P a='B'><TeleportAction/></P></I>",
        safe_parser(),
    )
    privates = [(p.get("a"), p) for p in root]
    names = {"Ego", "A1", "B"}
    order = [(a, p[0].tag) for a, p in init_order(privates, names)]
    assert order == [
        ("Ego", "SpeedAction"),
        ("A1", "SpeedAction"),
        ("A1", "TeleportAction"),
        ("Ego", "TeleportAction"),
        ("B", "TeleportAction"),
    ]
    plain = [(a, p) for a, p in privates if a != "Ego"]
    assert init_order(plain, names) == plain


def test_a_relative_lane_the_road_lacks_is_refused_naming_it(tmp_path):
    privates = {
        "B": tp(lane_at(-2, 100)),
        "A1": tp('<RelativeLanePosition entityRef="B" dLane="-1" ds="0"/>'),
        "Ego": tp(lane_at(1, 10)),
    }
    with pytest.raises(
        VeiInputError, match=r"s\.xosc: line \d+: <RelativeLanePosition>: road 1 has no lane -3 at s = 100"
    ):
        run_scenario(_scenario(tmp_path, privates), {}, DT)


def test_a_long_chain_written_backwards_is_put_in_order():
    """Car k placed relative to car k+1, every one written before the car it reads: the order runs the
    whole chain backwards (linear in the actions: a file of thousands of placed cars does not hang)."""
    n = 2000
    xml = "".join(
        f"<P a='c{k}'><TeleportAction><Position><RelativeLanePosition entityRef='c{k + 1}'/></Position></TeleportAction></P>"
        for k in range(n - 1)
    )
    root = etree.fromstring(f"<I>{xml}<P a='c{n - 1}'><TeleportAction/></P></I>", safe_parser())
    order = [a for a, _ in init_order([(p.get("a"), p) for p in root], {f"c{k}" for k in range(n)})]
    assert order == [f"c{k}" for k in range(n - 1, -1, -1)]
