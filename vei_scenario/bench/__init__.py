"""``vei bench``: vei's collision-avoidance planner over every scenario of a library, with a timing
search around each conflict (:mod:`vei_scenario.bench.run`); bench.json, report.html, junit.xml."""

from vei_scenario.bench.run import BenchOptions, run_bench

__all__ = ["BenchOptions", "run_bench"]
