"""What a road user does, settled from the behaviours its clauses gave it: one path per road user.

A clause often says a road user's path and its manner in two verbs ("proceeds against the red
signal, passing the ego"; "emerged from the left against a red signal"; "stops at the give-way line
and waits"). The reader reads each verb, so the manner arrives as a second behaviour. These rules
keep the path:

* running the red light is the whole of a road user's path across the junction: a pass of the ego
  or an emergence from an arm said with it is how it goes, not a second manoeuvre;
* a road user on a junction arm that only stops (and waits) is giving way: that is what stopping at
  the line of a side road is.
"""

from __future__ import annotations

from vei_scenario.language.reading import ActorSpec

#: Behaviours that, said with running the red, are the manner of that run.
_MANNER_OF_A_RUN = frozenset(("overtake", "turn_into"))
_ARMS = frozenset(("junction_left", "junction_right", "junction_opposite"))


def one_path(spec: ActorSpec) -> list:
    """``spec``'s behaviours with the manner of its path dropped (see the module's rules)."""
    names = [b[0] for b in spec.behaviours]
    if "run_red_light" in names:
        return [b for b in spec.behaviours if b[0] not in _MANNER_OF_A_RUN]
    if names == ["stop"] and spec.relation in _ARMS:
        _, cfg, crit, link = spec.behaviours[0]
        return [("give_way", {}, crit, link)]
    return spec.behaviours
