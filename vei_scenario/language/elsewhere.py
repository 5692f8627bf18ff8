"""Whether a road user or thing said to stand in a lane stands there now, on the ego's road.

A lead that swerves out of the ego's lane reveals what stands in the lane it leaves (a cut-out,
:func:`reader._cut_outs`). What the text puts in a lane of another road ("in the left lane of the
other carriageway", "on the slip road"), at another time ("earlier a lorry had broken down in the
left lane") or no longer there ("but had been towed away") is not in the ego's way, whatever side its
lane was said on.
"""

from __future__ import annotations

#: Where a sentence ends: the words a road user is said with lie between two of these.
_SENTENCE_ENDS = frozenset((".", ";", "!", "?"))
#: Roads beside the ego's: a lane of one of these is not a lane of the ego's road.
_OTHER_ROADS = frozenset(("sliproad", "slip-road", "ramp", "on-ramp", "off-ramp"))
#: What says a road of the same kind is another ("the other carriageway", "the opposite carriageway").
_ANOTHER = frozenset(("other", "opposite", "oncoming", "northbound", "southbound", "eastbound", "westbound"))
#: Words that put what is said at another time than the story's ("earlier", "the day before").
_ANOTHER_TIME = frozenset(("earlier", "previously", "yesterday", "ago"))
#: Words that say what stood there has been taken away ("had been towed away", "was cleared").
_TAKEN_AWAY = frozenset(("towed", "removed", "cleared"))


def stands_elsewhere(tokens: list[str], named_end: int) -> bool:
    """Whether the road user named ending at ``named_end`` (in ``tokens``, the scanned words) is said in
    its sentence to stand on another road, at another time, or no longer to be there. Why: such a one
    is not in the lane a lead leaves, and a cut-out revealing it would put it in the ego's way."""
    if named_end <= 0 or named_end > len(tokens):
        return False
    start = next((j + 1 for j in range(named_end - 1, -1, -1) if tokens[j] in _SENTENCE_ENDS), 0)
    end = next((j for j in range(named_end, len(tokens)) if tokens[j] in _SENTENCE_ENDS), len(tokens))
    before, after = tokens[start:named_end], tokens[named_end:end]
    if any(t in _ANOTHER_TIME for t in before + after) or any(t in _TAKEN_AWAY for t in after):
        return True
    if any(a == "no" and b == "longer" for a, b in zip(after, after[1:])):
        return True  # ("was no longer there")
    for j, t in enumerate(after):
        if t in _OTHER_ROADS or (t == "slip" and after[j + 1 : j + 2] in (["road"], ["lane"])):
            return True  # ("in the left lane of the slip road")
        if t == "carriageway" and j > 0 and after[j - 1] in _ANOTHER:
            return True  # ("of the other carriageway"; "the carriageway" alone is the ego's)
    return False
