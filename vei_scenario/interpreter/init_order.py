"""The order the Init actions start in: the file's, except that an action which reads another road
user (a position relative to it, a speed relative to its speed, a gap to it) starts after that road
user's own Init actions.

Scenario authors place one car relative to another whose Init actions come later in the file (the
ASAM example SlowPrecedingVehicle puts the ego 200 m behind a car teleported after it). The standard
lists Init actions without saying they run in file order; esmini reorders them so that what an
action reads is set first, and plays the same file as its author meant. vei does the same, measured
against esmini 3.6: positions, speeds and chains of them (a car placed relative to a car placed
relative to a third) come out as esmini's (tests/test_init_order.py). Actions that read each other
in a circle cannot be ordered: they start in file order, and the run says so in a warning.
"""

from __future__ import annotations

#: The attributes by which an action names another road user it reads.
_REFERENCES = ("entityRef", "masterEntityRef")
#: What an Init action sets of its road user, by the element that says what it is.
_SETS = {
    "TeleportAction": {"position"},
    "SpeedAction": {"speed"},
    "SpeedProfileAction": {"speed"},
    "LongitudinalDistanceAction": {"position", "speed"},
    "LateralDistanceAction": {"position"},
    "RoutingAction": {"position"},
}
#: What an action reads of the road user it names, by the element that names it (anything else: both).
_READS = {"RelativeTargetSpeed": {"speed"}, "RelativeTargetLane": {"position"}}


def _sets(action) -> frozenset[str]:
    """What the PrivateAction element ``action`` sets of its own road user in Init."""
    return frozenset(x for el in action.iter() if isinstance(el.tag, str) for x in _SETS.get(el.tag, ()))


def _reads(action, actor: str, names) -> frozenset[tuple[str, str]]:
    """What ``action`` (a PrivateAction element of ``actor``) reads of other road users: (name, what)
    pairs, where what is their position or their speed (a position relative to one reads its place)."""
    found = set()
    for el in action.iter():
        if not isinstance(el.tag, str):
            continue
        for attr in _REFERENCES:
            name = el.get(attr)
            if not name or name == actor or name not in names:
                continue
            in_position = any(a.tag == "Position" for a in el.iterancestors())
            what = {"position"} if in_position else _READS.get(el.tag, {"position", "speed"})
            found.update((name, w) for w in what)
    return frozenset(found)


def init_order(privates: list[tuple[str, object]], names, warn=None) -> list[tuple[str, object]]:
    """``privates`` (actor, PrivateAction element) in file order, reordered so that an action which
    reads another road user's position or speed comes after every action setting it: the file's order
    wherever nothing forces another (each action as early as what it reads allows; a topological
    order, linear in the actions and what they read). ``warn(element, reason)`` is told when actions
    read each other in a circle (they are then left in file order)."""
    import heapq

    items = [(actor, pa, _reads(pa, actor, names), _sets(pa)) for actor, pa in privates]
    if not any(reads for _, _, reads, _ in items):
        return list(privates)
    setters: dict[tuple[str, str], list[int]] = {}
    for j, (actor, _, _, sets) in enumerate(items):
        for what in sets:
            setters.setdefault((actor, what), []).append(j)
    after: list[list[int]] = [[] for _ in items]  # j -> the actions waiting for it
    waiting = [0] * len(items)
    for i, (_, _, reads, _) in enumerate(items):
        for j in sorted({j for key in reads for j in setters.get(key, ()) if j != i}):
            after[j].append(i)
            waiting[i] += 1
    ready = [i for i, n in enumerate(waiting) if n == 0]
    heapq.heapify(ready)
    order: list[int] = []
    while ready:
        j = heapq.heappop(ready)
        order.append(j)
        for i in after[j]:
            waiting[i] -= 1
            if waiting[i] == 0:
                heapq.heappush(ready, i)
    if len(order) < len(items):  # (what is left reads itself round in a circle)
        if warn is not None:
            first = next(items[i][1] for i, n in enumerate(waiting) if n > 0)
            warn(first, "Init actions read each other's road users in a circle: they start in file order")
        return list(privates)
    return [(items[i][0], items[i][1]) for i in order]
