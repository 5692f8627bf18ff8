"""Words of place that place no road user: a place said of nobody, and "following" naming a spacing.

- "There was nothing in front of me", "nobody was behind us", "no one ahead of me": the place is said
  of no one (a negative pronoun is its subject). Read as a place waiting for the next road user named,
  it put "the Audi behind me" that ran into the ego ahead of it.
- "Following distance to the lead car was 25 m", "a two-second following gap": "following" before a
  noun of spacing modifies that noun (how far one keeps behind another), not someone's place. Read as
  "following" said of a road user ("a car following us"), it put the lead car behind the ego.

These mentions are dropped from their clauses before the reader gives places to road users.
"""

from __future__ import annotations

#: Negative pronouns: a place said of one of them is said of no one.
_NOBODY = frozenset(("nothing", "nobody", "noone", "no-one", "none"))
#: Words between such a pronoun and the place ("nothing was behind her", "nobody directly ahead").
_BETWEEN = frozenset(("was", "is", "were", "are", "'s", "right", "directly", "immediately", "close", "at", "all"))
#: Nouns of a spacing "following" may modify ("following distance", "a following gap").
_SPACINGS = frozenset(("distance", "distances", "gap", "gaps", "time", "interval", "headway"))
#: The places such words may say: not sides or kerbs, which nobody's pronoun rarely takes.
_PLACES = frozenset(("ahead", "behind", "oncoming"))


def _said_of_nobody(tokens: list[str], start: int) -> bool:
    """Whether the place whose words start at token ``start`` has a negative pronoun as its subject, right
    before it or past a copula or an adverb of nearness ("nothing in front", "no one was behind")."""
    k = start - 1
    while k >= 0 and tokens[k] in _BETWEEN and start - k <= 3:
        k -= 1
    if k < 0:
        return False
    return tokens[k] in _NOBODY or (tokens[k] == "one" and k > 0 and tokens[k - 1] == "no")


def _names_a_spacing(m, tokens: list[str]) -> bool:
    """Whether mention ``m`` is "following" modifying a noun of spacing right after it."""
    return m.words == "following" and m.end < len(tokens) and tokens[m.end] in _SPACINGS


def without_places_of_no_one(clauses: list, tokens: list[str]) -> list:
    """Clauses (link, mentions) without the places said of nobody and the "following" of a spacing
    (``tokens``: the words the mentions index)."""
    out = []
    for link, mentions in clauses:
        kept = [
            m
            for m in mentions
            if not (
                m.slot == "relation"
                and m.value in _PLACES
                and (_said_of_nobody(tokens, m.start) or _names_a_spacing(m, tokens))
            )
        ]
        out.append((link, kept))
    return out
