"""A walker or rider beside the ego on a road of one lane each way is at the road's edge, not in a lane.

"There's a cyclist riding along the left-hand edge" of "a country lane, one lane each way"; "a lad on
an e-scooter on my left, single carriageway"; "a guy on a bike on the right hugging the curb, one
lane each direction": the side is read, and the reader may put the road user in the lane on that
side (start ``left`` or ``right``). On a road with one lane per direction there is no lane beside
the ego's going its way: what is beside it on the near side is the kerb or the verge, and on the far
side of a two-way road the oncoming lane. A walker or a rider (a bicycle, an e-scooter) said on a
side there is at the edge of the road on that side (``roadside_left``/``roadside_right``), where the
layers put one going along the kerb or stepping off it. A vehicle (a car, a motorbike) keeps the
lane: one beside the ego there is passing it through the other lane, and a road with two lanes or
more, or whose lanes are not said, may have the lane the reader put the rider in.
"""

from __future__ import annotations

from vei_scenario.language.discourse import VULNERABLE
from vei_scenario.language.reading import Reading

#: A lane beside the ego's → the edge of the road on that side.
_EDGE_OF = {"left": "roadside_left", "right": "roadside_right"}


def to_the_edge(r: Reading) -> None:
    """Put each walker or rider that ``r`` starts in a lane beside the ego's at the road's edge on that
    side, where ``r`` says the road has one lane per direction (see the module docstring)."""
    if r.lanes != 1:
        return  # (two lanes or more, or not said: the lane beside may be there)
    for spec in r.actors:
        if spec.kind in VULNERABLE and spec.relation in _EDGE_OF:
            spec.relation = _EDGE_OF[spec.relation]
