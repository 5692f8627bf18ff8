"""How near the ego came to a road user that crossed its path: the distance it stopped short of it.

A witness of a near miss with someone who crosses ("a boy ran out and I stopped 2 m short of him", "the
van ran the red and we stopped about 3 m from it") gives one distance, the one that matters to them: how
far the ego was from that road user when it was in the ego's path. That is what the reader's gap of a
road user that crosses means (:func:`vei_scenario.language.rules_backend._cross_at_distance`: in the
ego's lane when the ego is that far away), so it is that road user's gap where no other is said of it.
A road user that goes along the ego's road (a lead car that brakes, one that cuts in) starts somewhere
else than where the ego stopped behind it, so there the distance stays how the ego's stop went.
"""

from __future__ import annotations

from vei_scenario.language.reading import ActorSpec

#: Behaviours that take a road user across the ego's path: where the ego stopped short of one, it was in
#: the ego's way, which is what its gap says.
ACROSS_THE_PATH = frozenset({"cross_in_front", "run_red_light", "turn_into"})


def gap_from_the_stop(spec: ActorSpec, stopped_short_m: float | None) -> None:
    """Give ``spec`` the distance the ego stopped short of it as its gap, where it crosses the ego's path
    and no distance of its own is read."""
    if stopped_short_m is None or spec.distance_m is not None or not spec.behaviours:
        return
    if spec.behaviours[0][0] in ACROSS_THE_PATH:
        spec.distance_m = stopped_short_m
