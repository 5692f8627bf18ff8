"""OpenSCENARIO 1.2 variables (declarations, VariableAction set/modify, VariableCondition), `vei run
--dist`, and the Euro NCAP single executions that vei plays, against esmini."""

from __future__ import annotations

from pathlib import Path

import pytest

from conftest import ROOT
from vei_scenario.cli import main
from vei_scenario.interpreter import run_scenario

NCAP = ROOT.parent / "shared" / "osc-ncap" / "OpenSCENARIO" / "NCAP"

SCENARIO = """<?xml version="1.0"?>
<OpenSCENARIO><FileHeader revMajor="1" revMinor="2" date="2024-01-01T00:00:00" description="" author=""/>
<ParameterDeclarations><ParameterDeclaration name="$Step" parameterType="double" value="${pi / pi}"/>
</ParameterDeclarations>
<VariableDeclarations><VariableDeclaration name="count" variableType="double" value="0"/>
<VariableDeclaration name="done" variableType="boolean" value="false"/></VariableDeclarations>
<CatalogLocations/><RoadNetwork/>
<Entities><ScenarioObject name="Box"><MiscObject name="Box" mass="1" miscObjectCategory="obstacle">
<BoundingBox><Center x="0" y="0" z="0"/><Dimensions width="1" length="1" height="1"/></BoundingBox><Properties/>
</MiscObject></ScenarioObject></Entities>
<Storyboard><Init><Actions/></Init>
<Story name="s"><Act name="a"><ManeuverGroup name="g" maximumExecutionCount="1">
<Actors selectTriggeringEntities="false"/>
<Maneuver name="m">
 <Event name="tick" priority="parallel" maximumExecutionCount="3"><Action name="add"><GlobalAction>
  <VariableAction variableRef="count"><ModifyAction><Rule><AddValue value="$Step"/></Rule></ModifyAction>
  </VariableAction>
 </GlobalAction></Action><StartTrigger><ConditionGroup><Condition name="t" delay="0" conditionEdge="none">
  <ByValueCondition><SimulationTimeCondition value="0.1" rule="greaterThan"/></ByValueCondition></Condition>
 </ConditionGroup></StartTrigger></Event>
 <Event name="finish" priority="parallel"><Action name="set"><GlobalAction>
  <VariableAction variableRef="done"><SetAction value="true"/></VariableAction></GlobalAction></Action>
 <StartTrigger><ConditionGroup><Condition name="c" delay="0" conditionEdge="none"><ByValueCondition>
  <VariableCondition variableRef="count" rule="greaterOrEqual" value="3"/></ByValueCondition></Condition>
 </ConditionGroup></StartTrigger></Event>
</Maneuver></ManeuverGroup><StartTrigger/></Act></Story>
<StopTrigger><ConditionGroup><Condition name="end" delay="0.5" conditionEdge="none"><ByValueCondition>
 <VariableCondition variableRef="done" rule="equalTo" value="true"/></ByValueCondition></Condition></ConditionGroup>
 <ConditionGroup><Condition name="limit" delay="0" conditionEdge="none"><ByValueCondition>
 <SimulationTimeCondition value="10" rule="greaterThan"/></ByValueCondition></Condition></ConditionGroup></StopTrigger>
</Storyboard></OpenSCENARIO>"""


def test_variables_are_set_modified_and_conditioned_on(tmp_path):
    path = tmp_path / "vars.xosc"
    path.write_text(SCENARIO)
    result = run_scenario(path)
    # three ticks (each adds $Step = 1, a parameter declared with a leading $ and a pi expression), then
    # "done" is set and the stop trigger fires 0.5 s later: long before the 10 s limit
    assert result.end_reason == "storyboard stop trigger"
    assert 0.6 <= result.t[-1] <= 1.0


def test_a_variable_action_on_an_undeclared_variable_is_refused(tmp_path, capsys):
    path = tmp_path / "bad.xosc"
    path.write_text(SCENARIO.replace('variableRef="count"><ModifyAction>', 'variableRef="nope"><ModifyAction>'))
    assert main(["run", str(path), "--no-plots"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") <= 1 and "undeclared variable 'nope'" in err


SINGLE = [
    ("AEB_C2C_2023", "NCAP_AEB_C2C_CCR_2023.xosc", "NCAP_AEB_C2C_CCRm_50kph_2023.xosc"),
    ("AEB_C2C_2023", "NCAP_AEB_C2C_CCR_2023.xosc", "NCAP_AEB_C2C_CCRs_50kph_2023.xosc"),
    ("AEB_C2C_2023", "NCAP_AEB_C2C_CCFhos_2023.xosc", "NCAP_AEB_C2C_CCFhos_50kph_2023.xosc"),
    ("AEB_VRU_2023", "NCAP_AEB_VRU_CBLA_2023.xosc", "NCAP_AEB_VRU_CBLA-50_50kph_2023.xosc"),
    ("AEB_VRU_2023", "NCAP_AEB_VRU_CBLA_2023.xosc", "NCAP_AEB_VRU_CPLA-25_50kph_2023.xosc"),
]


@pytest.mark.parametrize("folder, base, variation", SINGLE)
def test_ncap_single_executions_agree_with_esmini(folder, base, variation):
    from vei_scenario.conformance.esmini import cross_check, find_esmini
    from vei_scenario.interpreter.document import load_scenario
    from vei_scenario.variation import read_distribution

    esmini = find_esmini(ROOT.parent / "shared" / "esmini" / "bin" / "esmini")
    if esmini is None or not NCAP.is_dir():
        pytest.skip("esmini or the NCAP pack is not here")
    scenario = NCAP / folder / base
    values = read_distribution(NCAP / folder / "Variations" / variation, load_scenario(scenario).parameter_types)[0]
    c = cross_check(esmini, scenario, values)
    assert c.max_deviation_m <= 0.10, c
    assert bool(c.vei_collisions) == bool(c.esmini_collisions)


def test_run_takes_a_distribution_variant(capsys):
    if not NCAP.is_dir():
        pytest.skip("the NCAP pack is not here")
    base = NCAP / "AEB_C2C_2023" / "NCAP_AEB_C2C_CCR_2023.xosc"
    dist = NCAP / "AEB_C2C_2023" / "Variations" / "NCAP_AEB_C2C_CCRm_50kph_2023.xosc"
    assert main(["run", str(base), "--dist", str(dist), "--no-plots"]) == 0
    out = capsys.readouterr().out
    assert "Scenario_ID=CCRm" in out and "Ego_speed_kph=50" in out
    assert main(["run", str(base), "--dist", str(dist), "--permutation", "3", "--no-plots"]) == 2
    assert "not in 0..0" in capsys.readouterr().err


def test_distribution_values_may_be_expressions(tmp_path):
    from vei_scenario.variation import read_distribution

    dist = tmp_path / "d.xosc"
    dist.write_text(
        """<?xml version="1.0"?><OpenSCENARIO><FileHeader revMajor="1" revMinor="2" date="2024-01-01T00:00:00"
 description="" author=""/><ParameterValueDistribution><ScenarioFile filepath="s.xosc"/><Deterministic>
<DeterministicSingleParameterDistribution parameterName="X"><DistributionSet><Element value="${0.6/2-0.36}"/>
</DistributionSet></DeterministicSingleParameterDistribution></Deterministic></ParameterValueDistribution>
</OpenSCENARIO>"""
    )
    assert float(read_distribution(dist, {"X": "double"})[0]["X"]) == pytest.approx(-0.06)
    assert Path(dist).is_file()
