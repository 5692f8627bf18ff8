"""The English a text is written in, where it tells the unit of a bare speed ("doing about 30").

Why: a writer who gives a speed with no unit gives it in the unit of their road signs, and says far
more often which English they speak than which unit they mean. Some words of the road and of daily
life are used only where miles per hour are signed: "quid" is British money, a "bridleway" is a
British right of way, and pelican, puffin and toucan crossings are British signals. A text that uses
one is set where miles per hour are signed. Commoner British words ("pavement", "lorry") are not
used: British test engineers write them and give their speeds in km/h. Ireland says British words
too and signs km/h; its police, the Gardaí, say so first. A town road called by its limit's number
alone ("doing 40 in a 30", "it's a twenty") is a British name too: where miles are signed, 20 and 30 are
the limits of towns and a road is called by them; where km/h is signed, towns are signed 50 and a 30 is
said as a zone ("a 30 zone"), which is said in both and tells nothing.

A story told in the first person says more: a driver who tells their own drive in the words of British
roads ("the lorry in front", "a kid came off the pavement", "clipped my wing mirror") reads their
speedometer in mph, as the British one is. Those words alone are not enough: a test engineer in
Britain writes them and gives km/h. Only words no other English of km/h says are counted: "lorry" and
"pavement" (Australia says truck and footpath), "nearside" and "offside", a "pushbike", an "artic",
a "car park" and a "wing mirror"; and the American "fender". Commonwealth words ("kerb", "tyre",
"bonnet", "windscreen") are said in Australia and India too, which sign km/h. So does a limit called by
its bare number ("it's a 20 limit", "40 limit, and I was doing 40", "the national speed limit"): where
km/h is signed, a limit is said with its unit or as a zone ("a 30 zone", said in both).

Only the unit of a bare speed is read from here, and only where the text states no unit of its own
(:func:`vei_scenario.language.quantities.carried_unit` asks that first).
"""

from __future__ import annotations

from vei_scenario.language.lemmas import lemmas

#: Words only British or American English use of the road and its traffic (see the module's docstring).
MILES_ENGLISH_WORDS = frozenset({"quid", "bridleway", "bridleways"})
#: Crossings by the names only Britain gives its signal crossings ("the pelican crossing").
_CROSSING_NAMES = frozenset({"pelican", "puffin", "toucan"})
_CROSSINGS = frozenset({"crossing", "crossings"})
#: The Irish police by their own name: a text that names them is set in Ireland, which signs km/h.
_IRISH_POLICE = frozenset({"garda", "gardai", "gardaí"})


def said_in_miles_english(tokens: list[str]) -> bool:
    """Whether the words ``tokens`` (lowercased) are British or American English by a word of the road
    only that English uses ("fifty quid", "along the bridleway", "the pelican crossing"), and
    not set in Ireland ("the gardai"). A pelican that is a bird is none: only a crossing's name counts."""
    if any(t in _IRISH_POLICE for t in tokens):
        return False
    if any(t in MILES_ENGLISH_WORDS for t in tokens):
        return True
    return any(t in _CROSSING_NAMES and nxt in _CROSSINGS for t, nxt in zip(tokens, tokens[1:]))


#: Words of the road only British (or American) English says (see the module's docstring), one word or two.
NARRATORS_MILES_WORDS = frozenset(
    {"lorry", "lorries", "pavement", "pavements", "nearside", "offside", "pushbike", "pushbikes", "artic", "artics",
     "fender", "fenders"}
)  # fmt: skip
NARRATORS_MILES_PAIRS = frozenset({("car", "park"), ("car", "parks"), ("wing", "mirror"), ("wing", "mirrors")})


#: Numbers of a limit called by them alone, in words ("the forty limit"); figures are read as figures.
_LIMIT_NUMBERS = frozenset({"twenty", "thirty", "forty", "fifty", "sixty", "seventy"})


def told_in_miles_english(tokens: list[str]) -> bool:
    """Whether the words ``tokens`` (lowercased, as written, figures as words of their own) say the road
    in words only British or American English uses ("the lorry", "off the pavement", "my wing mirror"),
    or call a limit by its bare number ("a 20 limit", "the national speed limit"), and are not set in
    Ireland: in a story told in the first person, the narrator's bare speeds are in mph (see the module's
    docstring; the caller asks only of such a story). Not "a 30 zone", nor "the 50 km/h limit"."""
    if any(t in _IRISH_POLICE for t in tokens):
        return False
    if any(t in NARRATORS_MILES_WORDS for t in tokens):
        return True
    for k, (t, nxt) in enumerate(zip(tokens, tokens[1:])):
        if (t, nxt) in NARRATORS_MILES_PAIRS:
            return True
        if nxt == "limit" and (t.isdigit() or t in _LIMIT_NUMBERS):
            return True  # ("a 20 limit", "40 limit, and I was doing 40")
        if (t, nxt) == ("national", "speed") and tokens[k + 2 : k + 3] == ["limit"]:
            return True
    return False


#: The town limits of Britain, by which a road is called ("a 30", "the twenty"): in figures and in words.
_TOWN_LIMITS = frozenset({"20", "30", "twenty", "thirty"})
#: Words before a road called by its limit: where one is ("in a 30") or what a road is ("it's a twenty").
_BEFORE_ROAD = frozenset({"in", "through", "is", "'s", "was"})
#: The noun of an age before "old" ("a 30, 35 year old", "a twenty or so yrs old").
_YEARS = frozenset({"year", "years", "yr", "yrs"})
#: Words after which nothing more is said of the number: its phrase ends ("in a 30, so", "in the 30 when").
_PHRASE_ENDS = frozenset(
    {"", ".", ",", ";", ":", "!", "?", ")", "-", "and", "but", "so", "when", "while", "as", "then", "with", "at"}
)


def road_called_by_its_limit(tokens: list[str]) -> bool:
    """Whether a road is called by its town limit's number alone in ``tokens`` (lowercased): "in a 30",
    "in the 30 last night", "it's a twenty," (see the module's docstring). Not where the number counts
    or measures the noun after it ("in a 30 zone", "in the 30 seconds", "a 20 tonne truck"): the word
    after it ends the phrase or is no noun ("last", "yesterday" may be one, and are said as adverbs).
    Nor where it is an age, "year old" within the five words after it ("she was a 30, 35 year old
    woman", "a twenty, maybe twenty-two year old bloke"; "in the 30 last year" is still the road)."""
    for k in range(1, len(tokens) - 1):
        if tokens[k] not in ("a", "the") or tokens[k - 1] not in _BEFORE_ROAD or tokens[k + 1] not in _TOWN_LIMITS:
            continue
        after = tokens[k + 2 : k + 7]
        if any(w.endswith("year-old") or (w in _YEARS and nxt == "old") for w, nxt in zip(after, after[1:] + [""])):
            continue  # (an age: "was a 30, 35 year old")
        nxt = tokens[k + 2] if k + 2 < len(tokens) else ""
        said = lemmas(nxt)
        if nxt in _PHRASE_ENDS or ("NOUN" not in said and said) or "ADV" in said:
            return True
    return False
