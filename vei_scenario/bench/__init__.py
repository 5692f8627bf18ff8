"""``vei bench``: a system under test (vei's collision-avoidance planner, or the user's own controller)
over every scenario of a library, with a timing search around each conflict
(:mod:`vei_scenario.bench.run`); bench.json, report.html, junit.xml; two systems compared
(:mod:`vei_scenario.bench.compare`)."""

from vei_scenario.bench.compare import compare_bench, read_bench, write_compare
from vei_scenario.bench.run import BenchOptions, bench_entry, read_library, run_bench
from vei_scenario.bench.systems import System, parse_systems

__all__ = [
    "BenchOptions",
    "System",
    "bench_entry",
    "compare_bench",
    "parse_systems",
    "read_bench",
    "read_library",
    "run_bench",
    "write_compare",
]
