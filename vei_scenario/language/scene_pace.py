"""The ego's speed where the text gives one speed of the scene and the reading put it on a road user.

Writers who give the ego's speed in a way no grammar of the reader places ("AEB no reaction to an
e-scooter crossing @ 30 kph", "he T-boned the scooter doing roughly 30kph", "She was going like 30",
"(ego straight, 50 km/h)") leave the reading with a speed on the road user named nearest and none on
the ego, which then gets a default that nothing in the text says. The one speed said of the scene is
better evidence of the ego's pace than none: the ego drives in the same traffic as the road user it
meets, and a writer whose ego went at a very different pace says so. The road user keeps its speed,
and the reading's ego speed stays unsaid: the scene's pace is only the default the layers give the ego
in place of one drawn at random.

Guards, each with its reason:

- only where the ego has no speed read: a speed said of the ego always wins;
- only one speed in the scene: with two, nothing tells whose pace the ego shares;
- no walking pace (a walker's, a jogger's): no vehicle of the traffic goes at it;
- no passing between the road user and the ego (it overtakes the ego, or the ego passes it): one
  passes the other only by going faster, so their speeds differ;
- no ego at rest: an ego said to stand keeps no speed (the reader sets 0 then, so it is not None).
"""

from __future__ import annotations

from vei_scenario.language.reading import Reading

#: The fastest a walker or runner goes (m/s): at or under it a speed is a pace on foot, no traffic's.
WALKING_PACE_MPS = 4.5
#: Behaviours of passing: the one who passes goes faster than the one passed.
PASSING = frozenset({"overtake"})


def ego_at_the_scene_pace(r: Reading, ego_passes: bool) -> None:
    """Set ``r``'s scene pace, the ego's default speed in the layers, to the one speed said of a road user
    when none is read for the ego (see the module docstring for why and for the guards); the reading's
    own ego speed stays unsaid. ``ego_passes``: the reading has the ego pass a road user."""
    if r.ego_speed_mps is not None or ego_passes:
        return
    speeds = [a.speed_mps for a in r.actors if a.speed_mps is not None and a.speed_mps > 0]
    if not speeds or max(speeds) - min(speeds) > 0.01:  # (one speed, said of one road user or of several)
        return
    if any(b[0] in PASSING for a in r.actors for b in a.behaviours):
        return
    speed = speeds[0]
    if speed > WALKING_PACE_MPS:
        r.scene_pace_mps = speed
