"""The outcome a test or a study designs its event for: "designed as a near miss", "scripted as a
near-crash", "intended to be only just avoidable", "intended as a low-criticality control event",
"no criticality intended", "the collision was unavoidable by design".

Why apart from the other statements of the outcome: a designed class is the scenario's own, as a test
row's rating is. What else the text tells of the event (a participant who "still clipped her", "three of
the 20 made soft contact", "a crash is not intended") says how some runs went or what is not wanted,
not what the scenario is; the outcome reader reads those words as it reads a story, and the design
decides over them."""

from __future__ import annotations

#: Participles of designing an event (lowercased tokens, as the reader has them).
_DESIGNING = frozenset(
    ("designed", "intended", "scripted", "planned", "meant", "parameterised", "parameterized", "tuned", "chosen",
     "configured", "set", "calibrated", "timed")
)  # fmt: skip
#: Words that open what the design is for, after its participle ("designed as", "intended to be",
#: "tuned so that", "scripted such that").
_OPENING = frozenset(("as", "to", "so", "such"))
#: Where what the design is for ends.
_ENDS = frozenset((".", ";", ":", ",", "(", ")", "!", "?", "|"))
#: How far on from the participle the class may stand (words).
_REACH = 10

NEAR, SAFE, CONTACT = "near_miss", "safe", "collision"
#: Phrases of each designed class, as token tuples.
_CLASSES: tuple[tuple[tuple[str, ...], str], ...] = (
    (("near", "miss"), NEAR),
    (("near-miss",), NEAR),
    (("near", "crash"), NEAR),
    (("near-crash",), NEAR),
    (("near", "collision"), NEAR),
    (("near-collision",), NEAR),
    (("close", "call"), NEAR),
    (("just", "avoidable"), NEAR),
    (("barely", "avoidable"), NEAR),
    (("critical", "but", "solvable"), NEAR),
    (("critical", "but", "avoidable"), NEAR),
    (("non-critical",), SAFE),
    (("noncritical",), SAFE),
    (("uncritical",), SAFE),
    (("benign",), SAFE),
    (("low-criticality",), SAFE),
    (("low", "criticality"), SAFE),
    (("no", "criticality"), SAFE),
    (("not", "critical"), SAFE),
    (("unavoidable",), CONTACT),
)
#: Nouns of contact, a designed one where nothing denies it ("designed to end in a collision").
_CONTACTS = frozenset(("collision", "crash", "impact", "contact", "collisions", "crashes", "impacts"))
#: Words that deny or avert a contact noun after them ("designed to help avoid collisions").
_AVERTING = frozenset(
    ("no", "not", "without", "avoid", "avoiding", "prevent", "preventing", "reduce", "reducing", "mitigate",
     "mitigating", "never", "nor")
)  # fmt: skip
#: Words after which a class stands as the event's own, said backwards ("no criticality intended",
#: "impact was unavoidable by design").
_AFTER = (("intended",), ("by", "design"))


def _class_at(words: list[str], k: int) -> tuple[str, int] | None:
    """The designed class whose phrase starts at ``words[k]``, with the phrase's length."""
    for phrase, kind in _CLASSES:
        if tuple(words[k : k + len(phrase)]) == phrase:
            return kind, len(phrase)
    return None


def _window(tokens: list[str], start: int, step: int) -> list[str]:
    """The words from ``start`` on (``step`` 1) or back (-1) to the clause's end, at most ``_REACH``."""
    out: list[str] = []
    k = start
    while 0 <= k < len(tokens) and tokens[k] not in _ENDS and len(out) < _REACH:
        out.append(tokens[k])
        k += step
    return out if step == 1 else out[::-1]


def _forward(words: list[str]) -> str | None:
    """The class a design's purpose names, in the words after its opening word."""
    for k in range(len(words)):
        found = _class_at(words, k)
        if found:
            return found[0]
        if words[k] in _CONTACTS and not set(words[:k]) & _AVERTING:
            return CONTACT  # ("designed to end in a collision")
    return None


def designed_outcome(tokens: list[str]) -> str | None:
    """``near_miss``, ``safe`` or ``collision``: the class the text says its event is designed,
    scripted or intended to have, the last one said; None where it says none. ``tokens``: the
    reader's lowercased tokens, punctuation apart."""
    found: str | None = None
    for i, w in enumerate(tokens):
        if w in _DESIGNING and i + 1 < len(tokens) and tokens[i + 1] in _OPENING:
            if w == "set" and tokens[i + 1] == "to":
                continue  # ("ACC set to 100 km/h": a setting, not a design)
            kind = _forward(_window(tokens, i + 1, 1))
            found = kind or found
        for after in _AFTER:
            if tuple(tokens[i : i + len(after)]) != after:
                continue
            before = _window(tokens, i - 1, -1)
            for k in range(len(before)):
                hit = _class_at(before, k)
                if hit and not (hit[0] != SAFE and set(before[:k]) & _AVERTING):
                    found = hit[0]  # ("no criticality intended", "the crash was unavoidable by design")
                    break
    return found
