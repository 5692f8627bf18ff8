"""What a noun phrase names, by its structure: whose it is (the writer's own vehicle or driver, "my
van", "our driver", "our old lorry", is the ego, whatever its type, as "my car" is; a person after
"my" or "our", "my kid", is someone in the ego and left as it is), its head (a closed compound,
"firetruck", names what its head names) and its modifier ("flashing lights" are a vehicle's lamps,
not a junction's signals, which "lights" alone are)."""

from __future__ import annotations

import re
from collections.abc import Callable

from vei_scenario.language.lemmas import english, lemmas
from vei_scenario.language.lexicon import CAR_MAKES, TRUCK_MAKES

#: First-person possessives, a closed class: what they own is the writer's, hence the ego.
FIRST_PERSON_POSSESSIVES = frozenset({"my", "our"})
#: At most this many modifiers between the possessive and its head noun ("our white transit van").
_MODIFIERS = 2

KindAt = Callable[[list[str], int], "tuple[str, int] | None"]


def _own_vehicle_end(tokens: list[str], i: int, kind_at: KindAt, modifier: Callable[[str], bool]) -> int | None:
    """Where the phrase "my/our [modifiers] <vehicle noun>" starting at ``i`` ends, or None."""
    for j in range(i + 1, min(i + 2 + _MODIFIERS, len(tokens))):
        found = kind_at(tokens, j)
        if found is not None:
            kind, length = found
            return j + length if kind not in ("pedestrian", "ego") else None
        if not modifier(tokens[j]):
            return None
    return None


#: Words that count what "of" takes a part of ("two of our scooters", "one of our vans"): a fleet's or a
#: group's vehicles, of which the writer's is at most one.
_COUNTS = frozenset("one two three four five six seven eight nine ten both several some none".split())


def _counted_of(before: list[str]) -> bool:
    """Whether the words ``before`` a possessive end in a count and "of" ("two of", "one of")."""
    return len(before) >= 2 and before[-1] == "of" and (before[-2] in _COUNTS or before[-2].isdigit())


def own_vehicles(tokens: list[str], kind_at: KindAt, modifier: Callable[[str], bool]) -> list[str]:
    """``tokens`` with each "my/our [modifiers] <vehicle noun>" as the one token "ego", but for a part
    of a fleet or group ("two of our scooters", "one of our vans": road users of their own).
    ``kind_at(tokens, i)`` gives the road-user type a phrase at ``i`` names and its length;
    ``modifier(word)`` whether a word may stand before a head noun (a content word the reader has no
    phrase for)."""
    out: list[str] = []
    i = 0
    while i < len(tokens):
        own = tokens[i] in FIRST_PERSON_POSSESSIVES and not _counted_of(out)
        end = _own_vehicle_end(tokens, i, kind_at, modifier) if own else None
        if end is None:
            out.append(tokens[i])
            i += 1
        else:
            out.append("ego")
            i = end
    return out


#: The shortest head and modifier a closed compound is split into ("minibus": "mini" + "bus").
_SHORTEST_PART = 3


def closed_compound(token: str, kind_of: Callable[[str], str | None]) -> list[str]:
    """A word written as one that is a modifier and a vehicle noun ("firetruck", "schoolbus",
    "minicab"), as those two words, so that it names what its head names; a word whose beginning is
    no English word of its own ("syllabus", "caravan", "vicar") is left whole. ``kind_of(word)`` is
    the road-user type a single word names, or None."""
    if kind_of(token) is not None:
        return [token]
    for cut in range(_SHORTEST_PART, len(token) - _SHORTEST_PART + 1):
        head, modifier = token[cut:], token[:cut]
        if kind_of(head) not in (None, "pedestrian", "ego") and english(modifier):
            return [modifier, head]
    return [token]


#: Modifiers of "lights" that still name a junction's signals ("traffic lights", "temporary lights");
#: any other content word before it names another kind of lamp ("flashing", "blue", "tail", "fog").
SIGNAL_MODIFIERS = frozenset(
    {"traffic", "signal", "red", "green", "amber", "yellow", "temporary", "pedestrian", "crossing", "junction"}
)


def lamps_not_signals(tokens: list[str], content_word: Callable[[str], bool]) -> list[str]:
    """``tokens`` with "lights" after a content word other than a signal's modifier as "lamps" (a word
    that names no junction). ``content_word(word)`` whether a word is no function word."""
    return [
        "lamps"
        if tok == "lights" and i > 0 and tokens[i - 1] not in SIGNAL_MODIFIERS and content_word(tokens[i - 1])
        else tok
        for i, tok in enumerate(tokens)
    ]


#: Makes: a word after one of them is its model or the vehicle's noun ("Ford Transit", "Vauxhall Astra").
MAKES = frozenset(m for m in CAR_MAKES + TRUCK_MAKES if " " not in m)


def make_and_model(tokens: list[str], kind_at: KindAt, known: Callable[[list[str], int], bool]) -> list[str]:
    """A make and what follows it as one vehicle: before a vehicle noun or a model the lexicon has ("a
    Ford Transit", "a Mercedes van", "a Vauxhall Astra") the make goes and the noun says the type; before
    a model it lacks (a word no dictionary knows, "a Toyota Prius", or a noun the reader has no phrase for,
    "a Ford Focus") the model goes and the make says it is a car. A verb after a make stays ("a BMW came
    past")."""
    out: list[str] = []
    i = 0
    while i < len(tokens):
        w = tokens[i]
        nxt = tokens[i + 1] if i + 1 < len(tokens) else ""
        if w in MAKES and nxt.isalpha():
            after = kind_at(tokens, i + 1)
            if after is not None and after[0] not in ("pedestrian", "ego"):
                i += 1  # (the make goes; its noun or model stays)
                continue
            unknown_model = not known(tokens, i + 1) and (not english(nxt) or nxt in lemmas(nxt).get("NOUN", ()))
            if unknown_model:
                out.append(w)
                i += 2
                continue
        out.append(w)
        i += 1
    return out


_WORD = re.compile(r"[A-Za-z][A-Za-z-]*")
#: Marks that open a sentence, a line or a field, after which any word is capitalised.
_OPENERS = frozenset(".!?:;\n|-(\"'\u2014\u2013*#>")


def proper_names(text: str) -> frozenset[str]:
    """The words ``text`` writes only with a capital, at least once where a sentence does not open (so
    the capital is the word's own: "a silver Mokka", "this guy in a Charger"), lower-cased as the
    reader's words are. All-capital words (abbreviations, shouting) are left out."""
    capital: set[str] = set()
    lower: set[str] = set()
    for m in _WORD.finditer(text):
        w = m.group(0)
        if w[0].islower():
            lower.add(w.lower())
        elif not w.isupper():
            j = m.start() - 1
            while j >= 0 and text[j] in " \t":
                j -= 1
            if j >= 0 and text[j] not in _OPENERS:
                capital.add(w.lower())
    return frozenset(capital - lower)
