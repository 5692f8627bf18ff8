"""Collision probability under a stochastic distribution: both estimators against an analytic value
(the collision interval that vei risk finds, integrated under the distribution), and importance
sampling against crude Monte Carlo on the planner's rare failures."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from vei_scenario.cli import main
from vei_scenario.probability import estimate_probability, wilson

DATA = Path(__file__).parent / "data" / "sut"

DIST = """<?xml version="1.0" encoding="UTF-8"?>
<OpenSCENARIO><FileHeader revMajor="1" revMinor="2" date="2024-05-14T00:00:00" description="" author=""/>
<ParameterValueDistribution><ScenarioFile filepath="scenario.xosc"/>
<Stochastic numberOfTestRuns="100" randomSeed="7">{body}</Stochastic></ParameterValueDistribution></OpenSCENARIO>"""


def _dist(tmp_path, body: str):
    p = tmp_path / "dist.xosc"
    p.write_text(DIST.format(body=body))
    return p


def test_estimates_match_the_integral_over_the_risk_interval(compiled, tmp_path):
    """Replay rider, no planner, TimeShift uniform on [0, 4]: P(collision) is the length of the
    collision interval (found by vei risk to 0.0025 s) over 4."""
    from vei_scenario.risk import find_risk

    scenario = compiled["case_study"].written[0]
    (search,) = find_risk(scenario, None, "collision", ["RiderType=replay", "CapEnabled=false"])
    ((a, b),) = search.intervals
    exact = (min(b, 4.0) - max(a, 0.0)) / 4.0
    uniform = '<UniformDistribution><Range lowerLimit="0" upperLimit="4"/></UniformDistribution>'
    dist = _dist(tmp_path, f'<StochasticDistribution parameterName="TimeShift">{uniform}</StochasticDistribution>')
    fixed = {"RiderType": "replay", "CapEnabled": "false"}
    for e in estimate_probability(scenario, dist, runs=4000, fixed=fixed, seed=3):
        slack = 0.01 / 4  # the interval's edges are known to a quarter of --tol
        assert e.low - slack <= exact <= e.high + slack, (e, exact)


def test_importance_sampling_agrees_with_monte_carlo_on_rare_failures_and_needs_fewer_runs(compiled, tmp_path):
    scenario = compiled["case_study"].written[0]
    dist = _dist(
        tmp_path,
        '<StochasticDistribution parameterName="TimeShift"><NormalDistribution expectedValue="2.6" variance="0.36">'
        '<Range lowerLimit="-1" upperLimit="6"/></NormalDistribution></StochasticDistribution>'
        '<StochasticDistribution parameterName="RiderType"><ProbabilityDistributionSet>'
        '<Element value="replay" weight="1"/><Element value="normal" weight="1"/>'
        '<Element value="aggressive" weight="1"/>'
        "</ProbabilityDistributionSet></StochasticDistribution>",
    )
    # every contact (the planner's windows 0.03-0.07 s wide, most with the ego standing: the search machinery)
    mc, imp = estimate_probability(
        scenario, dist, "collision_any", runs=10000, fixed={"CapEnabled": "true"}, seed=5
    )  # fmt: skip
    assert 0.005 < mc.probability < 0.05  # rare
    assert mc.low <= imp.probability <= mc.high
    needed = mc.runs * (mc.width / imp.width) ** 2  # Monte Carlo runs for the importance-sampling width
    assert needed >= 10 * imp.runs, (needed, imp.runs)


def test_wilson_interval_is_sound_at_zero_and_all():
    lo, hi = wilson(0, 1000)
    assert lo == 0.0 and 0.003 < hi < 0.004
    lo, hi = wilson(1000, 1000)
    assert hi == 1.0 and lo > 0.996
    lo, hi = wilson(500, 1000)
    assert math.isclose(0.5 - lo, hi - 0.5, rel_tol=1e-9)


def test_bad_probability_requests_are_one_line(compiled, tmp_path, capsys):
    scenario = str(compiled["case_study"].written[0])
    det = tmp_path / "det.xosc"
    det.write_text(
        DIST.replace(
            '<Stochastic numberOfTestRuns="100" randomSeed="7">{body}</Stochastic>', "<Deterministic/>"
        ).format(body="")  # fmt: skip
    )
    for argv, needle in (
        (["--dist", str(det)], "not a stochastic"),
        (
            [
                "--dist",
                str(
                    _dist(
                        tmp_path,
                        '<StochasticDistribution parameterName="Nope"><UniformDistribution>'
                        '<Range lowerLimit="0" upperLimit="1"/></UniformDistribution>'
                        "</StochasticDistribution>",
                    )
                ),
            ],
            "does not declare",
        ),  # fmt: skip
        (["--dist", str(det), "--runs", "5"], "outside"),
        (["--dist", str(det), "--band", "nan:1"], "finite"),
    ):
        assert main(["probability", scenario, *argv]) == 2
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and needle in err, err


@pytest.mark.parametrize("body", ['<NormalDistribution expectedValue="1" variance="0"/>',
                                  '<UniformDistribution/>',
                                  '<LogNormalDistribution expectedValue="-1" variance="1"/>'])  # fmt: skip
def test_degenerate_distributions_are_refused(compiled, tmp_path, capsys, body):
    dist = _dist(tmp_path, f'<StochasticDistribution parameterName="TimeShift">{body}</StochasticDistribution>')
    assert main(["probability", str(compiled["case_study"].written[0]), "--dist", str(dist)]) == 2
    assert capsys.readouterr().err.count("\n") == 1


def test_the_files_random_seed_is_used_without_seed_and_the_run_says_which(compiled, tmp_path, capsys):
    """As vei sweep does: the distribution's randomSeed draws the sample unless --seed is given."""
    scenario = compiled["case_study"].written[0]
    uniform = '<UniformDistribution><Range lowerLimit="0" upperLimit="4"/></UniformDistribution>'
    dist = _dist(tmp_path, f'<StochasticDistribution parameterName="TimeShift">{uniform}</StochasticDistribution>')
    fixed = {"RiderType": "replay", "CapEnabled": "false"}
    kw = {"estimators": ("monte-carlo",), "runs": 400, "fixed": fixed}
    (own,) = estimate_probability(scenario, dist, **kw)
    (seven,) = estimate_probability(scenario, dist, seed=7, **kw)
    (zero,) = estimate_probability(scenario, dist, seed=0, **kw)
    assert own.seed == 7 and own.failures == seven.failures and zero.failures != seven.failures
    argv = ["probability", str(scenario), "--dist", str(dist), "--estimator", "monte-carlo", "--runs", "400"]
    assert main([*argv, "--param", "RiderType=replay", "--param", "CapEnabled=false"]) == 0
    assert "seed 7 (the distribution's randomSeed)" in capsys.readouterr().out
    assert main([*argv, "--param", "RiderType=replay", "--param", "CapEnabled=false", "--seed", "3"]) == 0
    assert "seed 3 (--seed)" in capsys.readouterr().out


def test_help_prints_percent_once_and_the_defaults(capsys):
    for command, needles in (
        (
            "probability",
            ["Wilson's 95 % interval", "runs per estimator (default 20000)", "(default: the distribution's"],
        ),
        ("falsify", ["slices per other range (default 7)", "(default 0.005)"]),
        ("risk", ["(default 0.01)"]),
    ):
        assert main([command, "--help"]) == 0
        text = " ".join(capsys.readouterr().out.split())
        assert "%%" not in text
        for n in needles:
            assert n in text, (command, n)


def test_a_deterministic_distribution_is_refused_with_how_to_write_a_stochastic_one(compiled, capsys):
    """The compiled scenario.variations.xosc lists values; a probability needs densities."""
    written = compiled["case_study"].written
    scenario = next(p for p in written if p.name == "scenario.xosc")
    variations = next(p for p in written if p.name.endswith(".variations.xosc"))
    assert main(["probability", str(scenario), "--dist", str(variations)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1
    assert "Deterministic" in err and "<Stochastic>" in err and "vei compile --stochastic" in err


def test_compile_writes_a_stochastic_distribution_that_probability_takes(tmp_path, capsys):
    """`vei compile --stochastic`: the rider's timing normal around the conflict shift (standard deviation
    half the collision interval), the rider type uniform; valid against the ASAM XSD, the same bytes on
    every compile, and the documented probability example runs on it."""
    from vei_scenario.openscenario.validation import validate_files

    clip = Path(__file__).parent.parent / "examples" / "case_study" / "clip.json"
    out = []
    for k in (1, 2):
        assert main(["compile", str(clip), "-o", str(tmp_path / f"c{k}" / "scenario.xosc"), "--stochastic"]) == 0
        out.append((tmp_path / f"c{k}" / "scenario.stochastic.xosc").read_bytes())
    capsys.readouterr()
    assert out[0] == out[1]
    dist = tmp_path / "c1" / "scenario.stochastic.xosc"
    assert validate_files([dist]) == []
    text = dist.read_text()
    assert 'parameterName="TimeShift"' in text and "<NormalDistribution" in text and 'parameterName="RiderType"' in text
    scenario = tmp_path / "c1" / "scenario.xosc"
    argv = ["probability", str(scenario), "--dist", str(dist), "--param", "CapEnabled=true", "--runs", "2000"]
    assert main([*argv, "--estimator", "monte-carlo"]) == 0
    line = capsys.readouterr().out
    assert "P(collision) = " in line and "seed 1 (the distribution's randomSeed)" in line
    assert not (tmp_path / "plain").exists()
    assert main(["compile", str(clip), "-o", str(tmp_path / "plain" / "scenario.xosc")]) == 0
    assert not (tmp_path / "plain" / "scenario.stochastic.xosc").exists()


def test_a_stochastic_distribution_for_openscenario_1_0_is_refused_up_front(tmp_path, capsys):
    clip = Path(__file__).parent.parent / "examples" / "case_study" / "clip.json"
    out = tmp_path / "s" / "scenario.xosc"
    assert main(["compile", str(clip), "-o", str(out), "--stochastic", "--osc-version", "1.0"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "--stochastic" in err and not out.parent.exists()


def test_a_plugged_systems_probability_agrees_with_monte_carlo_and_the_exact_value(compiled, tmp_path):
    """The late AEB, interpreted, TimeShift uniform on [1, 4], the aggressive rider: P(collision with the
    ego moving) is the length of its failure window (vei falsify to 0.01 s) over 3. Both estimators
    hold it, agree with each other, and importance sampling spends at most twice the runs asked for on
    a probability that is not rare (its levels no larger than the estimate)."""
    from vei_scenario.falsify import Axis, falsify
    from vei_scenario.sut import parse_controller_options

    scenario = compiled["case_study"].written[0]
    controllers = tuple(parse_controller_options([f"Ego={DATA}/aeb_flawed.py:LateAEB"]))
    fixed = {"RiderType": "aggressive"}
    (region,) = falsify(scenario, [Axis("TimeShift", 1, 4)], fixed, tol=0.01, controllers=controllers).regions
    exact, slack = (region.high - region.low) / 3, 0.02 / 3
    uniform = '<UniformDistribution><Range lowerLimit="1" upperLimit="4"/></UniformDistribution>'
    dist = _dist(tmp_path, f'<StochasticDistribution parameterName="TimeShift">{uniform}</StochasticDistribution>')
    mc, imp = estimate_probability(scenario, dist, runs=100, fixed=fixed, seed=3, controllers=controllers)
    for e in (mc, imp):
        assert e.low - slack <= exact <= e.high + slack, (e, exact)
    assert mc.low <= imp.probability <= mc.high
    assert imp.runs <= 2 * 100, imp.runs
