"""Property-based fuzzing: whatever a file or a command line holds, every outcome is a clean result
or a clean refusal (VeiInputError, exit 2 with one line), never another exception, a hang or a
non-finite number in a result. Hypothesis generates the inputs; examples are capped so the suite
stays within CI's time."""

from __future__ import annotations

import json
import math
import os
import string

import pytest

hypothesis = pytest.importorskip("hypothesis")
from hypothesis import HealthCheck, example, given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402

from vei_scenario.errors import VeiInputError  # noqa: E402

#: VEI_FUZZ_SCALE=10 runs ten times as many examples (a longer search, outside CI).
SCALE = float(os.environ.get("VEI_FUZZ_SCALE", "1"))
FAST = settings(max_examples=int(150 * SCALE), deadline=None, suppress_health_check=[HealthCheck.too_slow])
SLOW = settings(max_examples=int(40 * SCALE), deadline=None, suppress_health_check=[HealthCheck.too_slow])

#: Numbers as hostile files write them.
NUMBER_TEXT = st.one_of(
    st.sampled_from(["nan", "NaN", "inf", "-inf", "Infinity", "1e400", "-1e400", "1e308", "-1", "0", "", " ", "abc",
                     "0x10", "1_000", "١", "--1", "1e-320", "9" * 400, "true", "$", "${", "${1/0}", "${1e308*10}"]),
    st.floats(allow_nan=True, allow_infinity=True).map(repr),
    st.integers(min_value=-(10**30), max_value=10**30).map(str),
)  # fmt: skip


# --- expressions ----------------------------------------------------------------------------------
EXPR_TOKENS = st.sampled_from(
    ["1", "2.5", "1e308", "1e400", "0", "$A", "$B", "$missing", "+", "-", "*", "/", "%", "(", ")", ",", "pi",
     "sqrt", "pow", "sin", "max", "min", "round", "not", "and", "or", "abs", " ", "@", "1e", ".5", "acos"]
)  # fmt: skip


@FAST
@given(st.lists(EXPR_TOKENS, max_size=60))
def test_expressions_evaluate_or_refuse(tokens):
    from vei_scenario.interpreter.expressions import ExpressionError, evaluate

    try:
        value = evaluate("".join(tokens) if len(tokens) % 2 else " ".join(tokens), {"A": "2", "B": "true"})
    except ExpressionError:
        return
    assert isinstance(value, float)


@FAST
@given(st.integers(min_value=0, max_value=5000), st.sampled_from(["(", "-", "+", "not "]))
def test_deep_or_long_expressions_are_refused_cleanly(n, op):
    from vei_scenario.interpreter.expressions import ExpressionError, evaluate

    text = op * n + "1" + (")" * n if op == "(" else "")
    try:
        evaluate(text, {})
    except ExpressionError:
        pass


@FAST
@given(st.integers(min_value=1, max_value=5000), st.sampled_from(["+", "*", " or ", " and ", "-", "/"]))
def test_long_chains_never_exhaust_the_stack(n, op):
    from vei_scenario.interpreter.expressions import ExpressionError, evaluate

    try:
        value = evaluate(op.join(["1"] * n), {})
    except ExpressionError:
        return
    assert isinstance(value, float)


# --- scenarios ------------------------------------------------------------------------------------
SCENARIO = """<?xml version="1.0"?>
<OpenSCENARIO><FileHeader revMajor="1" revMinor="1" date="2024-01-01T00:00:00" description="" author=""/>
<ParameterDeclarations><ParameterDeclaration name="V" parameterType="double" value="{p}"/></ParameterDeclarations>
<CatalogLocations/><RoadNetwork/>
<Entities>
 <ScenarioObject name="Ego"><Vehicle name="Ego" vehicleCategory="car">
  <BoundingBox><Center x="{cx}" y="0" z="0.8"/><Dimensions width="{w}" length="{l}" height="1.6"/></BoundingBox>
  <Performance maxSpeed="60" maxAcceleration="{acc}" maxDeceleration="9"/>
  <Axles><FrontAxle maxSteering="0.5" wheelDiameter="0.8" trackWidth="1.7" positionX="2.8" positionZ="0.4"/>
  <RearAxle maxSteering="0" wheelDiameter="0.8" trackWidth="1.7" positionX="0" positionZ="0.4"/></Axles>
  <Properties/></Vehicle></ScenarioObject>
 <ScenarioObject name="Ped"><Pedestrian name="Ped" mass="80" pedestrianCategory="pedestrian">
  <BoundingBox><Center x="0" y="0" z="0.9"/><Dimensions width="0.5" length="0.5" height="1.8"/></BoundingBox>
  <Properties/></Pedestrian></ScenarioObject>
</Entities>
<Storyboard><Init><Actions>
 <Private entityRef="Ego">
  <PrivateAction><TeleportAction><Position><WorldPosition x="{x}" y="0" h="{h}"/></Position></TeleportAction>
  </PrivateAction>
  <PrivateAction><LongitudinalAction><SpeedAction>
   <SpeedActionDynamics dynamicsShape="{shape}" value="{dv}" dynamicsDimension="{dim}"/>
   <SpeedActionTarget><AbsoluteTargetSpeed value="{v}"/></SpeedActionTarget></SpeedAction></LongitudinalAction>
  </PrivateAction>
 </Private>
 <Private entityRef="Ped">
  <PrivateAction><TeleportAction><Position><WorldPosition x="20" y="-3" h="1.57"/></Position></TeleportAction>
  </PrivateAction>
 </Private>
</Actions></Init>
<Story name="s"><Act name="a"><ManeuverGroup maximumExecutionCount="{count}" name="g">
 <Actors selectTriggeringEntities="false"><EntityRef entityRef="Ped"/></Actors>
 <Maneuver name="m"><Event name="e" priority="overwrite"><Action name="go"><PrivateAction><LongitudinalAction>
  <SpeedAction><SpeedActionDynamics dynamicsShape="linear" value="{dv}" dynamicsDimension="time"/>
  <SpeedActionTarget><AbsoluteTargetSpeed value="1.5"/></SpeedActionTarget></SpeedAction>
 </LongitudinalAction></PrivateAction></Action>
 <StartTrigger><ConditionGroup><Condition name="c" delay="{delay}" conditionEdge="none"><ByValueCondition>
  <SimulationTimeCondition value="{t}" rule="greaterThan"/></ByValueCondition></Condition></ConditionGroup>
 </StartTrigger></Event></Maneuver></ManeuverGroup>
 <StartTrigger><ConditionGroup><Condition name="s" delay="0" conditionEdge="none"><ByValueCondition>
  <SimulationTimeCondition value="0" rule="greaterOrEqual"/></ByValueCondition></Condition></ConditionGroup>
 </StartTrigger></Act></Story>
<StopTrigger><ConditionGroup><Condition name="end" delay="0" conditionEdge="none"><ByValueCondition>
 <SimulationTimeCondition value="0.5" rule="greaterThan"/></ByValueCondition></Condition></ConditionGroup></StopTrigger>
</Storyboard></OpenSCENARIO>"""

FIELDS = ("p", "cx", "w", "l", "acc", "x", "h", "shape", "dv", "dim", "v", "count", "delay", "t")
GOOD = {"p": "3", "cx": "1.4", "w": "2", "l": "5", "acc": "5", "x": "0", "h": "0", "shape": "linear", "dv": "1",
        "dim": "time", "v": "$V", "count": "1", "delay": "0", "t": "0.1"}  # fmt: skip


@SLOW
@given(
    st.dictionaries(
        st.sampled_from(FIELDS), st.one_of(NUMBER_TEXT, st.sampled_from(["step", "rate", "distance", "cubic", "bogus"]))
    )
)
def test_scenario_values_run_cleanly_or_are_refused(tmp_path_factory, values):
    from xml.sax.saxutils import escape

    from vei_scenario.interpreter import run_scenario

    fields = {**GOOD, **{k: escape(v, {'"': "&quot;"}) for k, v in values.items()}}
    path = tmp_path_factory.mktemp("fz") / "s.xosc"
    path.write_text(SCENARIO.format(**fields))
    try:
        result = run_scenario(path, max_time_s=5.0)
    except VeiInputError as exc:
        assert str(exc).startswith(str(path)) and "\n" not in str(exc)
        return
    for tr in result.traces.values():
        for arr in (tr.x, tr.y, tr.yaw, tr.speed, tr.accel):
            assert all(math.isfinite(v) for v in arr), tr.name


# --- roads ----------------------------------------------------------------------------------------
ROAD = """<?xml version="1.0"?><OpenDRIVE><header revMajor="1" revMinor="4"/>
<road id="1" length="{length}" junction="-1"><planView>
<geometry s="0" x="{x}" y="0" hdg="{hdg}" length="{length}">{shape}</geometry></planView>
<lanes><laneSection s="0"><center><lane id="0" type="none"/></center>
<right><lane id="-1" type="driving"><width sOffset="0" a="{width}" b="0" c="0" d="{wd}"/></lane></right></laneSection>
</lanes></road></OpenDRIVE>"""
SHAPES = st.sampled_from(
    ['<line/>', '<arc curvature="{k}"/>', '<spiral curvStart="0" curvEnd="{k}"/>', '<poly3 a="0" b="0" c="0" d="{k}"/>',
     '<paramPoly3 aU="0" bU="{k}" cU="0" dU="0" aV="0" bV="0" cV="{k}" dV="0" pRange="normalized"/>']
)  # fmt: skip


@FAST
@given(SHAPES, NUMBER_TEXT, NUMBER_TEXT, NUMBER_TEXT, NUMBER_TEXT, NUMBER_TEXT)
def test_roads_load_drivable_or_are_refused(tmp_path_factory, shape, k, length, x, hdg, wd):
    from vei_scenario.roads.road_model import RoadNetwork

    path = tmp_path_factory.mktemp("rd") / "r.xodr"
    path.write_text(ROAD.format(length=length, x=x, hdg=hdg, width="3.5", wd=wd, shape=shape.format(k=k)))
    try:
        net = RoadNetwork.load(path)
    except VeiInputError:
        return
    road = net.roads["1"]
    for f in (0.0, 0.5, 1.0):
        px, py, ph = road.ref_pose(f * road.length)
        assert math.isfinite(px) and math.isfinite(py) and math.isfinite(ph)


# --- JSON inputs: clips and layers -----------------------------------------------------------------
JSON_LEAVES = st.one_of(st.none(), st.booleans(), st.integers(), st.floats(allow_nan=False, allow_infinity=False),
                        st.text(max_size=8))  # fmt: skip


def _containers(children):
    return st.lists(children, max_size=4) | st.dictionaries(st.text(max_size=6), children, max_size=4)


JSON_VALUES = st.recursive(JSON_LEAVES, _containers, max_leaves=20)


@FAST
@given(st.dictionaries(st.sampled_from(["format", "id", "ego", "annotations", "map", "extensions", "x"]), JSON_VALUES))
def test_clip_documents_load_or_are_refused(tmp_path_factory, doc):
    from vei_scenario.clip import load_clip

    path = tmp_path_factory.mktemp("clip") / "c.json"
    path.write_text(json.dumps({"format": "vei-clip/1", **doc}))
    try:
        load_clip(path)
    except VeiInputError:
        pass


@FAST
@given(st.one_of(JSON_VALUES, st.dictionaries(st.sampled_from(["format", "environment", "ego", "adversaries",
                                                              "background"]), JSON_VALUES)))  # fmt: skip
def test_layers_documents_are_validated_or_refused(doc):
    from vei_scenario.language.layers import validate_layers

    try:
        validate_layers(doc, "layers.json")
    except VeiInputError as exc:
        assert "\n" not in str(exc)


@FAST
@given(st.integers(min_value=1, max_value=20000), st.sampled_from(["[", '{"a":']), st.sampled_from(["1e400", "1"]))
def test_deep_or_overflowing_json_is_refused(tmp_path_factory, depth, opener, leaf):
    from vei_scenario.clip import load_clip

    closer = "]" if opener == "[" else "}"
    path = tmp_path_factory.mktemp("deep") / "c.json"
    path.write_text(opener * depth + leaf + closer * depth)
    with pytest.raises(VeiInputError):
        load_clip(path)


# --- suites and distributions ---------------------------------------------------------------------
@FAST
@given(st.text(alphabet=string.printable + "\x00\x01é", max_size=300))
def test_suites_load_or_are_refused(tmp_path_factory, text):
    from vei_scenario.ci_check import load_suite

    path = tmp_path_factory.mktemp("suite") / "s.toml"
    path.write_text('[[case]]\nname = "x"\nscenario = "s.xosc"\n' + text, encoding="utf-8")
    try:
        load_suite(path)
    except VeiInputError:
        pass


DIST = """<?xml version="1.0"?><OpenSCENARIO><FileHeader revMajor="1" revMinor="2" date="2024-01-01T00:00:00"
 description="" author=""/><ParameterValueDistribution><ScenarioFile filepath="s.xosc"/>
<Stochastic numberOfTestRuns="{runs}" randomSeed="{seed}">
 <StochasticDistribution parameterName="V">{dist}</StochasticDistribution>
</Stochastic></ParameterValueDistribution></OpenSCENARIO>"""
DISTS = st.sampled_from(
    ['<NormalDistribution expectedValue="{a}" variance="{b}"/>',
     '<LogNormalDistribution expectedValue="{a}" variance="{b}"/>',
     '<UniformDistribution/>', '<UniformDistribution><Range lowerLimit="{a}" upperLimit="{b}"/></UniformDistribution>',
     '<PoissonDistribution expectedValue="{a}"/>',
     '<Histogram><Bin weight="{a}"><Range lowerLimit="0" upperLimit="{b}"/></Bin></Histogram>',
     '<ProbabilityDistributionSet><Element value="1" weight="{a}"/><Element value="2" weight="{b}"/>'
     '</ProbabilityDistributionSet>']
)  # fmt: skip


@FAST
@given(DISTS, NUMBER_TEXT, NUMBER_TEXT, st.sampled_from(["3", "-1", "0", "1e12", "nan", "2.5"]),
       st.sampled_from(["0", "-1", "7", "1e30", "nan"]))  # fmt: skip
# (an expectedValue whose square underflows: it divided by zero before it was refused)
@example('<LogNormalDistribution expectedValue="{a}" variance="{b}"/>', "4.0470553681336033e-237", "0.0", "3", "0")
@example('<LogNormalDistribution expectedValue="{a}" variance="{b}"/>', "1e-200", "1e10", "3", "0")
def test_distributions_give_variants_or_are_refused(tmp_path_factory, dist, a, b, runs, seed):
    from vei_scenario.variation import read_distribution

    path = tmp_path_factory.mktemp("dist") / "d.xosc"
    path.write_text(DIST.format(runs=runs, seed=seed, dist=dist.format(a=a, b=b)))
    try:
        variants = read_distribution(path, {"V": "double"})
    except VeiInputError:
        return
    assert 1 <= len(variants) <= 3
    assert all(math.isfinite(float(v["V"])) for v in variants)


# --- command-line values --------------------------------------------------------------------------
@FAST
@given(st.sampled_from([["run", "s.xosc", "--dt"], ["sweep", "s.xosc", "-o", "o", "--dt"], ["compile", "c", "-o", "o",
       "--rate"], ["sweep", "s", "-o", "o", "--workers"], ["sweep", "s", "-o", "o", "--seed"], ["risk", "s", "--band"],
       ["risk", "s", "--tol"], ["view", "s", "--fps"], ["describe", "x", "-o", "o", "--count"], ["study", "s", "-o",
       "o", "--time-shift"]]), NUMBER_TEXT)  # fmt: skip
def test_numeric_arguments_are_checked_by_the_parser(argv, value):
    from vei_scenario.cli import build_parser

    parser = build_parser()
    try:
        args = parser.parse_args([*argv, value])
    except SystemExit as exc:
        assert exc.code == 2
        return
    got = vars(args)[argv[-1].lstrip("-").replace("-", "_")]
    if isinstance(got, tuple):
        assert all(math.isfinite(v) for v in got)
    else:
        assert math.isfinite(got)
