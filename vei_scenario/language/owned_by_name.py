"""The vehicle a story is told about, named by its owner's name: "Lena's car", "Mem's Octavia", "the
survey team's van".

A mechanic's job sheet, a script, a council's minutes or a patrol log often follow one person who is
not the writer, and name that person's vehicle once, by its owner, before the story: "Mem's Octavia,
rear tyre. Mem said a lad on an e-scooter came off the kerb and he had to swerve", "Lena's car in the
outside lane. In her mirror, a white van was tailgating her" (the lane it is in places it by no one).
The story is told from that vehicle: it is the ego, and listing it as a road user of its own would give
the scenario a road user too many and leave the ego's speed ("he was doing 35") unsaid.

:func:`frame` reads it where no earlier rule named the ego (see :mod:`ego` and :mod:`protagonist`)
and no narrator is in the story (no "I", "we", "me", "us": "I was behind Priya's Fiesta" is someone
the writer meets). The owned vehicle must be the first road user the text names: one named after
someone else ("A cyclist was riding along when Tesco's lorry pulled out") is met by the one named
first. Its owner is one or two plain words before "'s" that name no road user, no time ("Friday's
bus") and no one at all ("there's a car"), and no determiner but "the" opens them ("a neighbour's
car" is someone besides the one followed). The owner named again, its pronouns (where the first he
or she after it can be no one else) and a bare "the driver" who reacts ("the driver had to brake")
are the ego too; another owner's vehicle ("John's car and Mary's car collided") is someone else. A
vehicle that acts on the road user named next in its clause, with an owner the story does not go on
with (never named again, no "he" or "she": a shop's, company's or brand's, "McDonald's lorry pulled
out in front of a cyclist") is told from outside, as one met.
"""

from __future__ import annotations

from vei_scenario.language.ego import (
    BE,
    DEFINITE,
    INDEFINITE,
    NARRATOR_INVOLVED,
    NARRATOR_PERSON,
    PRONOUNS,
    PUNCT,
    VEHICLES,
    KindAt,
    Known,
    as_ego,
    driver_is_ego,
    names_ego,
    owner_by_pronouns,
    placed_by_word,
    pronouns_as_ego,
    road_users,
    stands_parked,
)
from vei_scenario.language.function_words import CLAUSE_BREAKS, NO_ONE, PHRASE_ENDS, SAYING, WORDS_OF_TIME
from vei_scenario.language.lemmas import lemmas
from vei_scenario.language.protagonist import verb_of_reacting

#: Verbs of saying after the owner named again ("Mem said", "Bea reckons"): what follows is what happened.
REPORTING = SAYING


def _named_owner(tokens: list[str], p, kind_at: KindAt) -> int | None:
    """Where the owner's words start, for a vehicle named by its owner's name or by a noun of a
    person or group that is no road user: "Lena's car", "Mem's Octavia", "the audit team's car"
    (one or two plain words, after an optional "the"); None for a road user's ("the cyclist's
    bike"), a time's ("Friday's bus") or a word that names no one ("there's a car")."""
    if p.det:
        return None
    s = p.start - 1  # (past the plain words of its make or model: "Lena's Mini car", "the team's grey Golf")
    while s >= p.start - 3 and s > 0 and tokens[s].isalpha() and tokens[s] not in NO_ONE | DEFINITE | INDEFINITE:
        s -= 1
    if s < 1 or tokens[s] != "'s":
        return None
    o = s - 1
    start = o
    for k in (o, o - 1):
        if k < 0 or k < o and tokens[k] in DEFINITE | {"a", "an"}:
            break
        w = tokens[k]
        word = lemmas(w)
        plain = w.isalpha() and w not in NO_ONE | WORDS_OF_TIME | PRONOUNS | BE | PHRASE_ENDS | CLAUSE_BREAKS
        if not plain or (word and "NOUN" not in word) or (k < o and not word) or kind_at(tokens, k) is not None:
            if k == o:
                return None
            break
        start = k
    if start and tokens[start - 1] == "the":
        start -= 1
    elif start and tokens[start - 1] in INDEFINITE | DEFINITE | NARRATOR_INVOLVED | {"his", "her", "their"}:
        return None  # ("a neighbour's car", "this team's van": someone besides the one the story follows)
    return start


def _acts_on_another(tokens: list[str], p, other) -> bool:
    """Whether the owned vehicle ``p`` does something to the road user ``other`` named next in its own
    clause ("McDonald's lorry pulled out in front of a cyclist", "Tesco's lorry cut up a cyclist"): a
    verb right after it (not "was": "was hit by a van", "was behind a bus"), and the other no agent
    of it ("by a van") and not joined to it ("John's car and a van collided")."""
    between = tokens[p.end : other.start]
    if not between or between[0] in BE or "VERB" not in lemmas(between[0]):
        return False
    return not set(between) & (CLAUSE_BREAKS | PUNCT | {"by"})


def _followed(tokens: list[str], p, owner: list[str]) -> bool:
    """Whether the owner of ``p`` is someone the story goes on with: named again ("Mem said") or a
    person's pronoun after it ("she braked"). A shop's, company's or brand's is neither."""
    rest = tokens[p.end :]
    again = any(rest[i : i + len(owner)] == owner for i in range(len(rest)))
    return again or bool({"he", "she", "him", "his", "her"} & set(rest))


def frame(tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """``tokens`` with the vehicle named first, by its owner's name (see :func:`_named_owner`), said
    "the ego", with its owner, their pronouns and a bare driver who reacts (see the module's
    docstring), where no ego is named and no narrator is in the story; the words that only named it
    are added to ``dropped``. Unchanged otherwise, and where that vehicle is placed by someone ("the
    team's car ahead") or stands ("Mem's parked van")."""
    if NARRATOR_PERSON & set(tokens) or names_ego(tokens, kind_at, known):
        return tokens
    users = road_users(tokens, kind_at, known)
    if len(users) < 2:
        return tokens  # (no one for it to meet)
    p = users[0]
    if p.kind not in VEHICLES or placed_by_word(tokens, p) or stands_parked(tokens, p):
        return tokens
    start = _named_owner(tokens, p, kind_at)
    if start is None:
        return tokens
    owner = [w for w in tokens[start : tokens.index("'s", start)] if w != "the"]
    if _acts_on_another(tokens, p, users[1]) and not _followed(tokens, p, owner):
        return tokens  # ("McDonald's lorry pulled out in front of a cyclist": told from outside)
    noun = tokens[p.end - 1]
    dropped.extend(w for w in tokens[start : p.end] if w.isalpha() and w != "the")
    out = [*tokens[:start], "the", "ego", *tokens[p.end :]]
    out = as_ego(out, kind_at, known, noun, dropped, owner=frozenset(owner))  # (not "Mary's car")
    i = start + 2
    while i < len(out):  # (the owner named again: "Mem said ...")
        if out[i : i + len(owner)] == owner and out[i + len(owner) : i + len(owner) + 1] != ["'s"]:
            at = i - 1 if out[i - 1] == "the" else i  # ("overtakes the uploader")
            end = i + len(owner)
            if out[end : end + 1] and out[end] in REPORTING:
                out[at : end + 1] = []  # ("Mem said a lorry braked": what is said, said plainly)
                continue
            out[at:end] = ["the", "ego"]
        i += 1
    out = driver_is_ego(out, kind_at, known, dropped)
    for k in range(len(out) - 2, 0, -1):  # ("the driver had to brake": the one who reacts is the ego's)
        if out[k - 1 : k + 1] == ["the", "driver"] and out[k + 1] != "of" and verb_of_reacting(out, k + 1):
            dropped.append("driver")
            out[k] = "ego"
    gender = owner_by_pronouns(out)
    return pronouns_as_ego(out, gender, kind_at, known) if gender else out
