"""Which stated speed is the ego's, where the text says it by a limit or of traffic in general.

Two ways people give the ego's speed that no number grammar of one road user reads:

- by the limit it keeps to: "Drivers doing the 20 limit", "I was sitting at the 30 limit", "keeping
  to the 50 km/h limit": going at the limit is going at that speed (a limit said alone, "a 20 mph
  road", is only the road's, and the reader's settings read it);
- in a sentence that opens with a participle of driving and names no subject ("Coming round the
  roundabout at 15 mph, a van ...", "Towing a caravan at 80 km/h when ..."): whoever tells the story is
  the one driving, even where the road user named next is the grammatical subject;
- of traffic in general, in a text whose ego is someone in traffic in general ("Cars are usually
  doing around 20 mph on the roundabout", "Vehicles typically travel at 40 mph here"): the speed of
  the traffic is the ego's, as it is one of that traffic.
"""

from __future__ import annotations

from vei_scenario.language import vocabulary as V
from vei_scenario.language.ego import SENTENCE_END
from vei_scenario.language.lemmas import lemmas
from vei_scenario.language.quantities import _is_number

#: Words of going at a speed, before "the <number> limit" ("doing", "sitting at", "keeping to").
GOING = frozenset(
    "doing going driving travelling traveling moving riding sitting keeping sticking holding cruising".split()
)
#: Nouns that say road users in general in the plural: the traffic of a place.
TRAFFIC = frozenset({"cars", "vehicles", "drivers", "motorists", "traffic"})
#: Words between such a subject and its verb of going ("are usually", "typically", "tend to be").
_BETWEEN = frozenset(
    "are is were was usually typically normally generally often mostly still tend to be will all".split()
)
_HEDGES = frozenset({"about", "around", "roughly", "approximately", "at", "nearly", "some"})


def at_the_limit(tokens: list[str]) -> list[str]:
    """``tokens`` with "<going> (at|to) the <number> (<unit>) (speed) limit" said as "<going> (at|to)
    <number> (<unit>)": the speed the ego keeps, which the reader's numbers then read as any speed."""
    out = list(tokens)
    k = len(out) - 1
    while k >= 0:
        if out[k] != "limit":
            k -= 1
            continue
        end = k + 1
        j = k - (out[k - 1] == "speed")
        unit = j >= 1 and out[j - 1] in V.SPEED_UNITS
        n = j - 1 - unit
        if n >= 2 and _is_number(out[n]) and out[n - 1] == "the":
            verb = n - 2 - (out[n - 2] in ("at", "to"))
            if verb >= 0 and out[verb] in GOING:
                out[n - 1 : end] = out[n : n + 1 + unit]
                k = n - 1
                continue
        k -= 1
    return out


def of_traffic(tokens: list[str]) -> float | None:
    """The speed (m/s) said of traffic in general: a bare plural ("Cars", "Vehicles", "traffic") that
    opens its sentence or clause, its verb of going, then a number with its unit. None where none is
    said so (the speed of "the cars" or "two cars" is theirs)."""
    for k, w in enumerate(tokens):
        if w not in TRAFFIC or (k and tokens[k - 1] not in SENTENCE_END | {",", ":", "and"}):
            continue
        j = k + 1
        while j < len(tokens) and tokens[j] in _BETWEEN:
            j += 1
        if j >= len(tokens) or tokens[j] not in GOING | {"move", "travel", "go", "drive", "moves", "travels"}:
            continue
        j += 1
        while j < len(tokens) and tokens[j] in _HEDGES:
            j += 1
        if j + 1 < len(tokens) and _is_number(tokens[j]) and tokens[j + 1] in V.SPEED_UNITS:
            return float(tokens[j]) * V.SPEED_UNITS[tokens[j + 1]]
    return None


#: Verbs of going on foot or on a bike, or across: a sentence opening with one of their participles
#: ("Crossing the road at 6 km/h, a jogger ...") is about the road user it names next, as its grammar
#: says. Any other participle of going ("Heading home at 50 km/h, ...", "Crawling along at 10 mph when
#: ...") opens the narrator's drive, the way people tell it, whoever the sentence names next.
NOT_DRIVING = frozenset({"cross", "walk", "run", "jog", "ride", "cycle", "step", "scoot", "skate"})
#: Words that end such an opening phrase: a comma, a conjunction, the sentence's end.
_PHRASE_ENDS = frozenset({",", ";", ".", "!", "?", "and", "when", "while", "as", "but", "then"})
_OPENERS = SENTENCE_END | {":"}


def opening_participles(tokens: list[str]) -> dict[int, bool]:
    """The numbers said in a phrase that opens its sentence with a participle and no subject, by their
    index: True where the participle is of driving (the speed is the narrator's, the ego's), False
    for one of walking, riding or crossing ("Crossing the road at 6 km/h, a jogger ...": the speed of
    the one named next)."""
    out: dict[int, bool] = {}
    for k, w in enumerate(tokens):
        if not w.endswith("ing") or len(w) < 5 or (k and tokens[k - 1] not in _OPENERS):
            continue
        verbs = lemmas(w).get("VERB", ()) if lemmas(w) else (w[:-3],)  # ("pootling": a verb lemminflect lacks)
        if not verbs or "even" in verbs:  # ("Morning, ...", "Evening, ...": no participle)
            continue
        for j in range(k + 1, min(k + 14, len(tokens))):
            if tokens[j] in _PHRASE_ENDS:
                break
            if _is_number(tokens[j]) and j + 1 < len(tokens) and tokens[j + 1] in V.SPEED_UNITS:
                out[j] = not NOT_DRIVING & set(verbs)
    return out
