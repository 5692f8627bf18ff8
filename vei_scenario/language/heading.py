"""A heading over a report names the road users its body tells of again: the same ones, not more.

An issue-tracker ticket, a test case, a notice or a news item opens with a line of its own that names
the case ("Cyclist rides out of a driveway on the right, AEB late", "Child running into the road",
"SCOOTERS ON MILL LANE") and then tells it in sentences that bring its road users in afresh ("A
cyclist comes out of a driveway ..."). The heading is a summary of the body, not
an earlier moment of the story: a road user it names, of a kind the body names too, is that road user
of the body, and the reading keeps the body's telling of it (which says more: where, how far, how fast),
with the speed and gap the heading gives where the body gives none. What else the heading says (the
time, the weather, the ego's speed) is still read. This goes further than :mod:`heading_named`, which
folds a road user named bare in any heading or label: a line of its own over a body may name its road
user with an article too. Both keep the two apart by one test, :func:`heading_named.told_apart`, read
as a summary's: a first line that tells a road user of its own (parked, said in words to be somewhere
the body's is not, doing a thing the body's does not) is no restating heading but the first message
of a chat written without full stops ("van parked on the left with hazards on" over "a van came the
other way"), and both road users stay. A heading that says no place, or one of the body's acts, is a
summary read less fully than the body. Not a road user that another reveals (what a cut-out uncovers
stands there, whoever names it).

A heading is the text's first line when more lines follow it, it does not end as a sentence or a
salutation does (a full stop, a question, a colon, a comma), no subject pronoun tells someone's act in
it ("we went", "I braked": a first sentence written without its stop), and the body after it is the
longer. A question set over its body by a blank line is a heading too, as a forum post's or an issue's
title is ("How do I make an e-scooter cut in at 30 km/h?"): whoever asks is no one of the scene.
The body's road user is the heading's told again only where the body brings it in as new ("a", "an",
"two"): one it names as one more ("another", "a second") is another, and one it names as
said before ("the taxi", or bare as notes write it) is the heading's own. A heading's road user of a
kind the body never brings in stays, and so does one named as someone's ("Dave's van": the writer's).
"""

from __future__ import annotations

import re
from collections.abc import Callable
from typing import Protocol

from vei_scenario.language.discourse import OTHER
from vei_scenario.language.function_words import POSSESSIVE, SUBJECT_PRONOUNS
from vei_scenario.language.heading_named import told_apart
from vei_scenario.language.reading import Reading
from vei_scenario.language.said_again import fold_into, without

#: How a line that is a sentence or a salutation ends (not a heading).
_SENTENCE_END = re.compile(r"[.!?:;,]\s*$")

#: The words of a line, as the reader's tokens are (lower case).
_WORD = re.compile(r"[a-z][a-z'-]*")


class _Named(Protocol):
    """What the reader gathered of a road user, as far as this module reads it."""

    kind: str
    det: str
    named_after: str
    named_end: int
    counted: bool


def _titled_question(head: str, rest: str) -> bool:
    """Whether the first line ``head`` is a question set over its body by a blank line (``rest``: the
    text after the line's break), as a forum post's or an issue's title is: it asks for what the body
    then tells ("How do I make a cyclist turn across the ego?"), and the one who asks is no one of the
    scene."""
    return head.endswith("?") and rest.lstrip(" \t").startswith("\n")


def _heading_and_body(text: str) -> tuple[str, str] | None:
    """(the heading line, the body after it) of ``text``, or None when its first line is no heading."""
    lines = text.strip().split("\n", 1)
    if len(lines) < 2:
        return None
    head, body = lines[0].strip(), lines[1].strip()
    words = _WORD.findall(head.lower())
    if words and body and _titled_question(head, lines[1]):
        return head, body  # ("How do I make an e-scooter cut in at 30 km/h?" over a post that tells it)
    if not words or not body or _SENTENCE_END.search(head) or SUBJECT_PRONOUNS & set(words):
        return None
    if len(_WORD.findall(body.lower())) <= len(words):
        return None  # (a body no longer than its heading tells nothing more: lines of one list)
    return head, body


def heading_end(text: str, scanned: list[str], tokens_of: Callable[[str], list[str]]) -> int | None:
    """The index in ``scanned`` (the reader's words of ``text``) just past the heading's words, the
    line break read as a full stop; None where ``text`` opens with no heading. ``tokens_of`` gives the
    reader's words of a line (where its own stops are: "ul. Pilsudskiego", "SCN-12 | scooter")."""
    parts = _heading_and_body(text)
    if parts is None:
        return None
    stops = tokens_of(parts[0]).count(".") + 1  # (the heading's own stops, then its line's end)
    seen = 0
    for i, word in enumerate(scanned):
        if word == ".":
            seen += 1
            if seen == stops:
                return i + 1
    return None


def _brought_in(a: _Named) -> bool:
    """Whether the body brings ``a`` in as new: with "a" or "an", or counted ("two e-scooters"), not
    as one more of its kind ("another", "a second van") nor as one said before ("the taxi", "taxi")."""
    return (a.det in ("a", "an") or a.counted) and a.named_after not in OTHER


def _owned(a: _Named) -> bool:
    """Whether ``a`` is named as someone's ("our van", "Tommo's van"): in a heading, the writer's own."""
    return a.det in POSSESSIVE or a.named_after == "'s"


def fold_told_again(actors: list, reading: Reading, end: int | None) -> list:
    """Fold each road user of ``reading`` named in the heading (before scanned word ``end``) into the
    first the body brings in again of its kind and does not tell apart from it (see the module): the
    body's telling stays, with the speed and gap the heading gives where the body gives none.
    ``actors`` are what the reader gathered of them, in the same order; returns them without the ones
    folded."""
    if end is None:
        return actors
    specs = reading.actors
    drop: set[int] = set()
    taken: set[int] = set()  # (each of the body's road users is one of the heading's, at most)
    for j, a in enumerate(actors):
        if not 0 <= a.named_end <= end or _owned(a):
            continue
        k = next(
            (
                k
                for k, b in enumerate(actors)
                if b.named_end > end
                and k not in taken
                and _brought_in(b)
                and specs[k].kind == specs[j].kind
                and not told_apart(a, b, specs[j], specs[k], summary=True)
            ),
            None,
        )
        if k is not None and not any(s.obstacle in (j, k) for s in specs):
            fold_into(specs[k], specs[j])
            drop.add(j)
            taken.add(k)
    return without(actors, reading, drop)
