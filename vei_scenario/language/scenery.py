"""What is scenery, not a road user: a vehicle said to stand, and vehicles named only as the place
someone comes out from.

The format lists the road users that act on the road; a vehicle that stands and does nothing is
scenery (the scenario may hold it, parked, as an occluder). Two pieces of noun-phrase grammar say so,
and the reader asks them here:

- **A state word is said of its noun, past the modifiers between them.** "a stationary foam target
  car", "a parked white van", "a stopped grey lorry": the state word heads a noun phrase whose noun
  may come a few plain modifiers later (colours, makes, materials the reader has no word for). Only
  words that are neither function words nor verbs may stand between, so "stopped, and a car ..."
  or "parked to let a car by" keep the state away from the noun.
- **A negated quantifier says there is none.** "not another car for miles", "barely another vehicle
  about", "no other cars", "hardly a van on the road": the phrase names no one; it tells how quiet the
  road was (the settings read it as no traffic).
- **The object of "between" / "among" is a place, however it is counted.** "out from between two
  vans", "between three lorries", "between two of the cars": a count or a partitive does not make
  the vehicles road users; the one who comes out is the road user, the vehicles are where it was.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import replace

from vei_scenario.language.lemmas import lemmas

#: At most this many modifiers between a state word and its noun ("a stationary foam target car").
_MODIFIERS = 3
#: Prepositions whose object is where someone was, among several of them.
_AMID = frozenset(("between", "among", "amongst"))
#: Words of a counted noun phrase between such a preposition and its noun ("between two of the parked").
_COUNTED_PHRASE = frozenset(
    "two three four five six several a couple pair few some of the these those our parked stationary stopped".split()
)


def plain_modifiers(tokens: list[str], start: int, end: int, function_word: Callable[[str], bool]) -> bool:
    """Whether ``tokens[start:end]`` may stand between a state word and the noun it is said of: at
    most a few words, each a plain word (no number, no punctuation), none a function word, none a
    word that can only be a verb ("a parked white van", not "parked to let"; "stationary, and")."""
    words = tokens[start:end]
    if len(words) > _MODIFIERS:
        return False
    for w in words:
        if not w.replace("-", "").isalpha() or function_word(w):
            return False
        pos = set(lemmas(w))
        if pos and not pos & {"NOUN", "ADJ", "PROPN"}:
            return False
    return True


def among_them(tokens: list[str], start: int) -> bool:
    """Whether the vehicle noun at ``start`` is the object of "between" or "among", past a count or a
    partitive and its state ("between two vans", "between two of the parked cars"): where someone
    comes out from, not a road user of the scene."""
    j = start - 1
    while j >= 0 and start - j <= 5 and tokens[j] in _COUNTED_PHRASE:
        j -= 1
    return j >= 0 and tokens[j] in _AMID


#: Road-user types whose noun can modify another noun ("scooter incidents", "estate roads").
_VEHICLE_KINDS = frozenset(("car", "van", "truck", "bicycle", "e-scooter"))
#: Plural nouns a vehicle noun makes a measure of ("four car lengths back"): a distance, read as one.
_MEASURES = frozenset(("lengths", "widths"))
#: Counts that make a plural: a count over one before a singular noun agrees with the noun after it.
_MANY = frozenset("two three four five six seven eight nine ten several many few".split())


def _plural_noun(word: str, counted: bool) -> bool:
    """Whether ``word`` is a plural noun ("incidents", "roads", "near-misses"). A word that may also be
    a verb ("crashes", "swerves") is one only where a count before it agrees with it ("two car
    crashes"; "the car crashes" is a verb)."""
    if not word.endswith("s") or word.endswith("ss") or not word.replace("-", "").isalpha():
        return False
    pos = lemmas(word)
    if not pos:
        return counted  # (a word the dictionary lacks: "four scooter near-misses")
    nouns = pos.get("NOUN", ())
    return bool(nouns) and word not in nouns and ("VERB" not in pos or counted)


#: Plurals of the words people use for a thing they have no name for, or scorn ("these scooter
#: contraptions", "those bike gadgets", "e-scooter thingies"): after a vehicle's noun they are that
#: vehicle, said with a shrug, not something of it (a closed class).
_STAND_INS = frozenset((
    "contraptions", "gadgets", "devices", "things", "thingies", "thingys", "machines", "toys", "deathtraps",
    "death-traps", "menaces", "monstrosities", "contrivances", "doohickeys",
))  # fmt: skip


def _plural(noun: str) -> str:
    """The plural of vehicle noun ``noun`` ("scooter" -> "scooters", "bus" -> "buses")."""
    from lemminflect import getInflection

    forms = getInflection(noun, "NNS")
    return forms[0] if forms else noun + "s"


def vehicle_modifiers(tokens: list[str], kind_at: Callable[[list[str], int], tuple[str, int] | None],
                      dropped: list[str]) -> list[str]:  # fmt: skip
    """``tokens`` without a singular vehicle noun that modifies the plural noun right after it ("three
    scooter incidents", "the estate roads", "two car crashes"): the phrase names incidents or roads,
    no road user. What follows the vehicle noun must be a plural noun that names no road user itself
    ("two scooter riders" are two riders). The words left out are listed as not used."""
    out: list[str] = []
    i = 0
    while i < len(tokens):
        found = kind_at(tokens, i)
        if found is None or found[0] not in _VEHICLE_KINDS:
            out.append(tokens[i])
            i += 1
            continue
        end = i + found[1]
        noun = tokens[end - 1]
        head = tokens[end] if end < len(tokens) else ""
        counted = i > 0 and tokens[i - 1] in _MANY  # (not a figure: "16:06 cyclist crosses" is a clock)
        singular = "NOUN" in lemmas(noun) and noun in lemmas(noun)["NOUN"] or not noun.endswith("s")
        measure = head in _MEASURES
        if singular and head in _STAND_INS:  # ("these scooter contraptions": the scooters themselves)
            out.extend([*tokens[i : end - 1], _plural(noun)])
            dropped.append(head)
            i = end + 1
            continue
        if singular and head and not measure and kind_at(tokens, end) is None and _plural_noun(head, counted):
            dropped.extend(tokens[i:end])
        else:
            out.extend(tokens[i:end])
        i = end
    return out


#: Words that deny or all but deny what the noun phrase after them names ("no", "not another",
#: "barely a", "hardly any", "without another").
_NEGATING = frozenset(("no", "not", "barely", "hardly", "scarcely", "without", "nary"))
#: Determiners and quantifiers between such a word and the noun ("not a single other", "hardly any").
_NEGATED_QUANTIFIER = frozenset(("a", "an", "another", "other", "one", "single", "any", "more"))
#: Road users a negated quantifier can deny: vehicles and riders ("not a single cyclist").
_DENIED_KINDS = frozenset(("car", "van", "truck", "bicycle"))


def _denied(tokens: list[str], i: int) -> bool:
    """Whether the noun phrase starting at ``i`` is denied by a quantifier before it: a negating word
    and only determiners or quantifiers between. "Not" and "without" need one ("not another car";
    "not the car but the van", "did not stop" are no such phrase), "no" and the near-negations need
    none ("no cars", "barely another vehicle", "hardly a van")."""
    j = i - 1
    while j >= 0 and tokens[j] in _NEGATED_QUANTIFIER and i - j <= 3:
        j -= 1
    if j < 0 or tokens[j] not in _NEGATING:
        return False
    return j < i - 1 or tokens[j] not in ("not", "without")


def absent(tokens: list[str], kind_at: Callable[[list[str], int], tuple[str, int] | None],
           dropped: list[str]) -> list[str]:  # fmt: skip
    """``tokens`` without a vehicle or rider named only to say there was none ("not another car for
    miles", "barely another vehicle about", "no other cars around"): no road user, however the rest
    of the sentence goes. A measure of length ("not a car length ahead") is kept; the words left out
    are listed as not used."""
    out: list[str] = []
    i = 0
    while i < len(tokens):
        found = kind_at(tokens, i)
        end = i + found[1] if found is not None else i
        after = tokens[end] if end < len(tokens) else ""
        if found is None or found[0] not in _DENIED_KINDS or after in _MEASURES or after.startswith("length"):
            out.append(tokens[i])
            i += 1
            continue
        if _denied(tokens, i):
            dropped.extend(tokens[i:end])
        else:
            out.extend(tokens[i:end])
        i = end
    return out


#: "There is / are / was / were": what follows is said to be there.
_EXISTENTIAL = frozenset(("is", "are", "was", "were", "'s"))
#: Behaviours of stopping that, said as a participle after what is there, are the state it is in.
_STOPPING = frozenset(("stop", "sudden_stop"))


def standing_there(clauses: list, tokens: list[str]) -> list:
    """``clauses`` with a participle of stopping right after a road user said to be there ("there's a
    car stopped dead in lane 2", "there was a van halted in our lane") read as the state it is in,
    standing: in an existential sentence the participle after the noun describes it (a reduced
    relative), it tells no event. A finite stop ("a van stopped dead in our lane") or one in a
    relative clause ("there was a van that stopped dead") is the stop it says."""
    out = []
    for link, mentions in clauses:
        kept = list(mentions)
        for k in range(len(kept) - 1):
            m, nxt = kept[k], kept[k + 1]
            if m.slot != "actor" or m.value == "ego" or nxt.start != m.end:
                continue
            i = m.start - 1
            while i >= 0 and tokens[i] in ("a", "an", "another", "one"):
                i -= 1
            there = i >= 1 and tokens[i] in _EXISTENTIAL and tokens[i - 1] == "there"
            stop = nxt.slot == "behaviour" and nxt.value[0] in _STOPPING
            if there and stop and nxt.words.split()[0].endswith("ed"):
                kept[k + 1] = replace(nxt, slot="stationary", value=None, words="stopped")
        out.append((link, kept))
    return out
