"""What the OSMP participant tests plug in and the configurations they build participants for, shared by
the native (C) and the Python (pythonfmu) participants' tests."""

from __future__ import annotations

from vei_scenario.study import CONFIGURATIONS

#: Which entity each participant drives: the rider alone, the planner alone, or both.
PLUGS = {"rider": {"scooter_1": "sfm"}, "planner": {"Ego": "cap"}, "both": {"Ego": "cap", "scooter_1": "sfm"}}
#: The configurations participants are built for (their values the start values): the replayed rider with
#: the planner off and the aggressive social force with the planner on (every code path of the build);
#: all five run on participants built once with the defaults (test_*_built_with_the_defaults_*).
BUILT_FOR = [c for c in CONFIGURATIONS if c[0] in (1, 5)]
