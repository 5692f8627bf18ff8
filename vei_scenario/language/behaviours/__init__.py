"""The library of atomic behaviours, one module each: ``BEHAVIOURS`` by name.

Each module has ``NAME``, ``AGENT`` (what drives the actor), ``SUMMARY``, ``PARAMETERS`` (name →
:class:`~vei_scenario.language.behaviours.base.Parameter`), ``PROFILES`` (criticality word class →
ranges the rules backend samples), optionally ``DEFAULT_SPAWN``, and ``compile(ctx, cfg)`` returning
the behaviour's OpenSCENARIO steps. ``vei behaviours`` lists them.
"""

from __future__ import annotations

from types import ModuleType

from vei_scenario.language.behaviours import (
    along_road,
    change_lane,
    change_speed,
    cross_in_front,
    cut_in,
    cut_out,
    follow_vehicle,
    forced_turn,
    give_way,
    keep_going,
    keep_lane,
    overtake,
    run_red_light,
    stop,
    sudden_stop,
    turn_across,
    turn_into,
    wrong_way,
)

BEHAVIOURS: dict[str, ModuleType] = {
    m.NAME: m
    for m in (
        keep_lane,
        change_speed,
        follow_vehicle,
        overtake,
        cut_in,
        change_lane,
        sudden_stop,
        forced_turn,
        run_red_light,
        cross_in_front,
        stop,
        keep_going,
        turn_across,
        turn_into,
        give_way,
        along_road,
        wrong_way,
        cut_out,
    )
}


def behaviour(name: str) -> ModuleType:
    try:
        return BEHAVIOURS[name]
    except KeyError:
        raise KeyError(f"unknown behaviour {name!r}; known: {', '.join(BEHAVIOURS)}") from None
