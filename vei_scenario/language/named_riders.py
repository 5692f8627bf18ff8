"""A person named by their name who rides or walks: a road user of the kind they ride, or a walker.

"Priya, who was riding straight on past the junction", "Dr Sarah Okonjo was cycling east on Commercial
Road", "Mr Mallett, aged 67, of Porlock, was walking home along the A39", "a van overtook Tom (on a
Voi)": reports, inquests, club newsletters and lesson notes name the cyclist, the e-scooter rider or
the walker by their name, not by a noun the reader has. Read as written, the name is no road user, so
the vehicle that meets them is read alone, as the road user it is not (it is the vehicle the story is
told from), and the one it meets is lost.

A name (a word written only with a capital where no sentence opens, or one with a capital that no
dictionary has, after a title or not) is such a road user when it is the subject of a verb of riding
or of going on foot, past what describes it (an apposition set off by commas or brackets, a relative
"who", auxiliaries: "Amira (front rider) was riding", "Priya, who was riding"), or is "on" a ridden
vehicle right after its name ("Tom (on a Voi)"). Its kind is what it rides: the vehicle right after
the verb or "on" ("riding her e-scooter"), else what the verb says ("cycling" a bicycle, "scooting" an
e-scooter, "walking" on foot), else the one kind of ridden vehicle the text names ("Our scooters log
their speed ... rider Marcus"), else a bicycle, the vehicle "riding" on a road names with no other.
The name is then said as that kind's noun, "a" the first time and "the" after, so that the reader
reads the person as the road user they are. Guards: only verbs of riding and going on foot (a named
driver, "Gareth Moss had been driving", is the ego's, left to the passes that take it); a name the
reader has a phrase for is no person ("the Bird", "a Tesla").
"""

from __future__ import annotations

import re
from collections.abc import Callable

from vei_scenario.language.discourse import DETERMINERS
from vei_scenario.language.ego import VEHICLES, lemma_in
from vei_scenario.language.lemmas import english, lemmas
from vei_scenario.language.lexicon import MOTOR_TWO_WHEELERS, SCOOTER_OPERATORS, WALKER_PACED
from vei_scenario.language.narrator_outside import ON_FOOT

KindAt = Callable[[list[str], int], "tuple[str, int] | None"]

#: Titles before a name ("Mr Mallett", "Dr Sarah Okonjo").
TITLES = frozenset({"mr", "mrs", "ms", "miss", "dr", "mx"})
#: Verbs (by lemma) of riding a bicycle or an e-scooter, and the kind each names on its own.
RIDING_VERBS = {"cycle": "bicycle", "pedal": "bicycle", "bike": "bicycle", "scoot": "e-scooter", "ride": None}
#: Verbs (by lemma) of going on foot: a named person who does one is a walker. Not "stand" (standing by
#: the road is no going) and not "run" ("ran the red" is a driver's).
WALKING_VERBS = (ON_FOOT - {"stand"}) | {"cross"}
#: The noun each kind is said by in place of the name.
_NOUNS = {
    "bicycle": ["cyclist"],
    "e-scooter": ["e-scooter", "rider"],
    "car": ["motorcyclist"],
    "pedestrian": ["pedestrian"],
}
#: Who a passenger rides with ("riding with me").
_COMPANIONS = frozenset({"me", "us", "him", "her", "them", "you"})
#: Kinds a person rides.
_RIDDEN = frozenset({"bicycle", "e-scooter"})
#: Words between a name and its verb that only help the verb ("was riding", "had been walking", "who was").
_AUXILIARIES = frozenset(
    "am is are was were be been being has have had who that then still just always usually".split()
)
#: Words that open a clause or end a sentence: no apposition goes past one.
_CLAUSE_OPENERS = frozenset({".", ";", "!", "?", "who", "which", "that", "when", "while", "and", "but"})
#: How far a comma's apposition may run before its closing comma ("Mr Mallett, aged 67, of Porlock,").
_APPOSITION = 12
_CAPITALISED = re.compile(r"\b[A-Z][a-z]+\b")


def _names(text: str, proper: frozenset[str], function_word: Callable[[str], bool]) -> frozenset[str]:
    """The words of ``text`` that are names: written only with a capital where no sentence opens
    (``proper``), or with a capital and no dictionary's word ("Amira" opening a sentence); no function
    word ("At", "The" open sentences, and no dictionary of content words has them)."""
    capital = {w.lower() for w in _CAPITALISED.findall(text)}
    return frozenset(w for w in proper | capital if (w in proper or not english(w)) and not function_word(w))


def _ridden_at(tokens: list[str], k: int, kind_at: KindAt) -> tuple[str, int] | None:
    """The kind of the ridden vehicle at ``k``, past a determiner ("her e-scooter", "a Voi"), and where
    its phrase ends; None where none is."""
    j = k + 1 if k < len(tokens) and tokens[k] in DETERMINERS else k
    if j >= len(tokens):
        return None
    if tokens[j] in SCOOTER_OPERATORS:
        return "e-scooter", j + 1  # ("on a Voi": the operator's scooter)
    found = kind_at(tokens, j)
    if found is None:
        return None
    if found[0] in _RIDDEN:
        return found[0], j + found[1]
    return ("car", j + found[1]) if " ".join(tokens[j : j + found[1]]) in MOTOR_TWO_WHEELERS else None


def _something_ridden(tokens: list[str], k: int, kind_at: KindAt) -> bool:
    """Whether a road user's or an animal's noun follows at ``k``, past a determiner ("the bus", "her pony")."""
    j = k + 1 if k < len(tokens) and tokens[k] in DETERMINERS else k
    return j < len(tokens) and kind_at(tokens, j) is not None


def _past_description(tokens: list[str], j: int, kind_at: KindAt) -> int:
    """Where the words after a name go on past what describes it: a bracket ("(front rider)"), an
    apposition set off by commas (", aged 67, of Porlock,"), a relative "who" (", who was")."""
    if j < len(tokens) and tokens[j] == "(" and ")" in tokens[j : j + _APPOSITION]:
        inner = tokens.index(")", j)
        return inner + 1 if tokens[j + 1 : j + 2] != ["on"] else j  # ("(on a Voi)": what they ride)
    if j < len(tokens) and tokens[j] == ",":
        if tokens[j + 1 : j + 2] == ["who"]:
            return j + 1
        for k in range(j + 1, min(j + _APPOSITION, len(tokens) - 1)):
            if tokens[k] in _CLAUSE_OPENERS or kind_at(tokens, k) is not None:
                break  # (a clause or a road user of its own: ", the driver of a VW hit a man, who was")
            if tokens[k] == "," and (tokens[k + 1] in _AUXILIARIES or "VERB" in lemmas(tokens[k + 1])):
                return k + 1  # (the last comma of the apposition, before the name's verb)
    return j


#: Words by which someone comes off what they ride ("knocked a boy off his bike", "thrown from her scooter").
_OFF = frozenset({"off", "from"})
#: Possessives of a third person: what follows is the person's own ride.
_THEIR = frozenset({"his", "her", "their"})


def _verb_at(tokens: list[str], j: int, function_word: Callable[[str], bool]) -> int | None:
    """Where the verb whose subject ends right before ``j`` is, past auxiliaries ("was riding", "had
    walked", "who was riding"); None where the word there is no verb of that subject: a bare stem with
    no auxiliary ("the Promenade cycle path"), a participle with no auxiliary before a content word
    ("Friday's walking bus", "the Redway crossing point"; "Zara riding in the lane" is one), or one
    said with "away" ("walked away with cuts": out of the scene)."""
    k = j
    while k < len(tokens) and tokens[k] in _AUXILIARIES:
        k += 1
    verb = tokens[k] if k < len(tokens) else ""
    stems = lemmas(verb).get("VERB", ()) if verb.isalpha() else ()
    nxt = tokens[k + 1] if k + 1 < len(tokens) else "."
    if not stems or nxt == "away" or k > j:
        return k if stems and nxt != "away" else None
    if verb in stems:
        return None
    return None if verb.endswith("ing") and nxt.isalpha() and not function_word(nxt) else k


def _ride_of(
    tokens: list[str], j: int, kind_at: KindAt, text_kind: str, named: bool, function_word: Callable[[str], bool]
) -> tuple[str, tuple[int, int] | None] | None:
    """What the words from ``j`` (past a person, ``named`` or said by a person's noun) say they ride or
    whether they walk: the kind, and the span of a vehicle's phrase said with it that the rider's noun
    now says ("a boy rode his bike", "off her e-scooter"); None where they say neither. A name "on" a
    ridden vehicle rides it ("Tom (on a Voi)"); a name that rides a vehicle said after the verb ("Sam
    was riding his e-scooter") is left to the passes that read a named person with their vehicle, and
    a person's noun "on" or "riding" one ("a lad on a scooter") to those that read a rider."""
    j += named and tokens[j : j + 1] == ["("]
    if tokens[j : j + 1] == ["on"] or (not named and tokens[j : j + 1] == ["riding"]):
        ride = _ridden_at(tokens, j + 1, kind_at) if named else None
        return (ride[0], (j, ride[1])) if ride else None
    if tokens[j : j + 1] and tokens[j] in _OFF and tokens[j + 1 : j + 2] and tokens[j + 1] in _THEIR:
        ride = _ridden_at(tokens, j + 1, kind_at)  # ("a teenager off his e-scooter": its rider)
        return (ride[0], (j + 1, ride[1])) if ride else None
    k = _verb_at(tokens, j, function_word)
    if k is None:
        return None
    if lemma_in(tokens[k], WALKING_VERBS):
        pressed = lemma_in(tokens[k], frozenset({"step"})) and tokens[k + 1 : k + 2] == ["on"]
        return None if pressed else ("pedestrian", None)  # ("stepped on the brake": a foot on a pedal)
    kind = next((kind for lemma, kind in RIDING_VERBS.items() if lemma_in(tokens[k], frozenset({lemma}))), "")
    if kind == "":
        return None
    if _something_ridden(tokens, k + 1, kind_at):
        ride = None if named else _ridden_at(tokens, k + 1, kind_at)  # ("rode his bike": one road user)
        return (ride[0], (k + 1, ride[1])) if ride else None  # (not "rode her pony", "rode the bus")
    if kind is None and _aboard_or_object(tokens, k + 1, kind_at):
        return None
    return kind or text_kind, None


def _aboard_or_object(tokens: list[str], k: int, kind_at: KindAt) -> bool:
    """Whether a bare "ride" at ``k - 1`` is said of a passenger or takes an object that is no vehicle:
    a motor vehicle or a companion named in its clause ("riding along in his taxi", "riding with me"), or a
    determiner's noun right after it ("riding the clutch"). Why: only "ride" with nothing ridden named
    says a bike or a scooter; riding in a car or riding a pedal is no road user of its own."""
    if k + 1 < len(tokens) and tokens[k] in DETERMINERS and tokens[k + 1] not in SCOOTER_OPERATORS:
        return True
    for j in range(k, min(k + 6, len(tokens))):
        if tokens[j] in _CLAUSE_OPENERS:
            return False
        if tokens[j] == "with" and tokens[j + 1 : j + 2] and tokens[j + 1] in _COMPANIONS:
            return True  # ("riding with me": a passenger beside the writer)
        found = kind_at(tokens, j)
        if found is not None and found[0] in VEHICLES:
            return True
    return False


def _text_kind(tokens: list[str], kind_at: KindAt) -> str:
    """The one kind of ridden vehicle ``tokens`` name, else a bicycle."""
    kinds = {found[0] for i in range(len(tokens)) if (found := kind_at(tokens, i)) and found[0] in _RIDDEN}
    return kinds.pop() if len(kinds) == 1 else "bicycle"


def _named_already(tokens: list[str], start: int, kind_at: KindAt) -> bool:
    """Whether the words before a name at ``start`` end in a noun, the name in apposition to it ("the
    pedestrian, Ms Avery,", "rider Marcus", "my son Jacob", a noun after a determiner): that noun says
    who the person is already."""
    k = start - 1 - (tokens[start - 1 : start] == [","])
    if k < 0:
        return False
    noun = "NOUN" in lemmas(tokens[k]) and k > 0 and tokens[k - 1] in DETERMINERS  # ("our marshal Bev")
    return noun or any((found := kind_at(tokens, j)) and j + found[1] == k + 1 for j in range(max(k - 2, 0), k + 1))


def _person_noun(tokens: list[str], i: int, kind_at: KindAt) -> int | None:
    """Where a singular person's noun at ``i`` ends ("the boy", "a young man", "the 15-year-old"), after
    a determiner or a modifier; None for no person, an animal or one at a walker's pace."""
    found = kind_at(tokens, i)
    if found is None or found[0] != "pedestrian" or not i or not tokens[i - 1].isalpha():
        return None
    noun = " ".join(tokens[i : i + found[1]])
    last = tokens[i + found[1] - 1]
    singular = last in lemmas(last).get("NOUN", (last,))
    return i + found[1] if singular and noun not in WALKER_PACED else None


def _name_end(tokens: list[str], i: int, names: frozenset[str], kind_at: KindAt) -> int:
    """Where the run of names from ``i`` ends ("sarah okonjo"); ``i`` where none starts there."""
    end = i
    while end < len(tokens) and tokens[end] in names and kind_at(tokens, end) is None:
        end += 1
    return end


def _article(kind: str) -> str:
    return "an" if _NOUNS[kind][0][0] in "aeiou" else "a"


def named_riders(
    tokens: list[str], text: str, proper: frozenset[str], kind_at: KindAt, function_word: Callable[[str], bool]
) -> list[str]:
    """``tokens`` with each named person who rides or walks, and each person's noun that rides (see the
    module), said as a road user of their kind: a name as "a cyclist" where first named and "the
    cyclist" after; a person's noun as the rider's noun, its determiner kept ("the boy rode off": "the
    cyclist rode off"); the vehicle's phrase said with it goes ("a boy rode his bike", "off his
    e-scooter"). A name first said where it does neither keeps its reading everywhere: its later
    mentions are the person the passes before read ("Kyle Bradshaw was riding an e-scooter ... Kyle")."""
    # (a named rider or walker is a road user beside a motor vehicle; with none, "Zara was riding in the
    # cycle lane when a man stepped off the kerb", the named rider is the one the story is told from)
    motor = any((found := kind_at(tokens, i)) and found[0] in VEHICLES for i in range(len(tokens)))
    names = _names(text, proper, function_word) - TITLES if motor else frozenset()
    text_kind = _text_kind(tokens, kind_at)
    said: dict[str, str] = {}  # (each word of a name read as a road user, and its kind)
    passed: set[str] = set()  # (the words of a name first said where it neither rides nor walks)
    out: list[str] = []
    cut: set[int] = set()
    i = 0
    while i < len(tokens):
        if i in cut:
            i += 1
            continue
        end = _name_end(tokens, i, names, kind_at)
        named = end > i
        end = end if named else (_person_noun(tokens, i, kind_at) or i)
        if end == i:
            out.append(tokens[i])
            i += 1
            continue
        start = i - 1 if named and i and tokens[i - 1] in TITLES else i
        if not named:
            ride = _ride_of(tokens, end, kind_at, text_kind, False, function_word)
            ride = None if ride is not None and ride[0] == "pedestrian" else ride  # (a walker's noun says it)
        elif any(w in passed for w in tokens[i:end]) or _named_already(tokens, start, kind_at):
            ride = None
        elif known := next((said[w] for w in tokens[i:end] if w in said), None):
            ride = known, None
        else:
            ride = _ride_of(tokens, _past_description(tokens, end, kind_at), kind_at, text_kind, True, function_word)
        if ride is None:
            passed.update(tokens[i:end] if named else ())
            out.extend(tokens[i:end])
            i = end
            continue
        kind, vehicle = ride
        cut.update(range(*vehicle) if vehicle is not None else ())
        if named:
            del out[len(out) - (i - start) :]  # (the title)
            out.extend(["the" if tokens[i] in said else _article(kind), *_NOUNS[kind]])
            said.update(dict.fromkeys(tokens[i:end], kind))  # ("Dr Sarah Okonjo ... Okonjo")
        else:
            out.extend(_NOUNS[kind])
        i = end
    return out
