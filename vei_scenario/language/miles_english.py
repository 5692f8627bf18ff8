"""The English a text is written in, where it tells the unit of a bare speed ("doing about 30").

Why: a writer who gives a speed with no unit gives it in the unit of their road signs, and says far
more often which English they speak than which unit they mean. Some words of the road and of daily
life are used only where miles per hour are signed: "quid" is British money, a "bridleway" is a
British right of way, and pelican, puffin and toucan crossings are British signals. A text that uses
one is set where miles per hour are signed. Ireland says British words too and signs km/h; its
police, the Gardaí, say so first. A town road called by its limit's number alone ("doing 40 in a 30",
"it's a twenty") is a British name too: where miles are signed, 20 and 30 are the limits of towns and a
road is called by them; where km/h is signed, towns are signed 50 and a 30 is said as a zone ("a 30
zone"), which is said in both and tells nothing.

Commoner British road words are not enough on their own: British test engineers write them and give
their speeds in km/h. A story told in the first person says more: a driver who tells their own drive
in words of British (or American) roads that Englishes of km/h say far less reads their speedometer
in mph. Of the words that tell a British side of the road
(:data:`vei_scenario.language.sides.LEFT_HAND_WORDS`), "kerb", "carriageway", "HGV" and "footway"
are said as much where km/h is signed, and count for nothing here; so do "car park" and "pushbike"
(everyday in Australia and New Zealand), "tyre", "bonnet" and "windscreen". Those kept are "pavement"
(Australia, New Zealand, India and Ireland say footpath), "nearside" and "offside", an "artic", a
"wing mirror", and "lorry" and "fender": a lorry is said in Ireland, India, Kenya and Malaysia too,
and a fender in Canada, but far more of those who write them sign mph, and those others keep left
or name their country often enough (:mod:`~vei_scenario.language.sides` reads them by it). So is a
limit called by a British one but 50 ("a 20 limit", "40 limit, and I was doing 40", "the national
speed limit"): where km/h is signed a limit is said with its unit or as a zone, and a bare "50 limit"
(or "80 limit") is a km/h one. Even so, a place named that signs km/h ("in Nairobi", "in Toronto",
:func:`vei_scenario.language.sides.names_a_km_h_place`) keeps km/h, and so does a bare speed of 90 or
more ("doing 100", "at 90 on the motorway"): Britain's fastest limit is 70, and no narrator owns to 90
mph as if it were the traffic's pace. (Roads, road users and distances only km/h countries name, "the
Autobahn", "a ute", "3 km", are asked first, by :func:`vei_scenario.language.quantities.metric_country`.)

Only the unit of a bare speed is read from here, and only where the text states no unit of its own
(:func:`vei_scenario.language.quantities.carried_unit` asks that first).
"""

from __future__ import annotations

from vei_scenario.language.lemmas import lemmas
from vei_scenario.language.sides import LEFT_HAND_WORDS, names_a_km_h_place

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


#: British road words (:data:`~vei_scenario.language.sides.LEFT_HAND_WORDS`) said where km/h is signed too.
_SAID_WHERE_KM_H = frozenset({"kerb", "kerbs", "kerbside", "carriageway", "hgv", "hgvs", "footway", "footways"})
#: Words of the road British or American English says far more than any English of km/h (see the module's
#: docstring), one word or two.
NARRATORS_MILES_WORDS = (LEFT_HAND_WORDS - _SAID_WHERE_KM_H) | {"artic", "artics", "fender", "fenders"}
NARRATORS_MILES_PAIRS = frozenset({("wing", "mirror"), ("wing", "mirrors")})
#: The town limits of Britain, by which a road or a limit is called ("a 30", "the twenty limit").
_TOWN_LIMITS = frozenset({"20", "30", "twenty", "thirty"})
#: The limits of Britain but 50, a km/h town's too ("a 40 limit"; not "a 50 limit", nor "an 80 limit").
_BRITISH_LIMITS = _TOWN_LIMITS | {"40", "60", "70", "forty", "sixty", "seventy"}
#: The least bare speed no driver means in mph: above Britain's fastest limit, 70, by more than a narrator
#: owns to ("doing 90 on the motorway", "doing 100").
_NO_MILES_SPEED = 90
#: Words a driver's own speed is said after ("doing 100", "at about 110").
_SPEED_SAID = frozenset({"doing", "doin", "at", "going", "driving", "travelling", "traveling", "hitting"})
_ROUGHLY = frozenset({"about", "around", "over", "nearly", "almost", "roughly", "maybe", "a", "steady", "good"})


def _km_h_speed(tokens: list[str]) -> bool:
    """Whether a driver's speed of 90 or more is said in ``tokens`` ("doing 100", "at about 120")."""
    for k, t in enumerate(tokens):
        if t.isdigit() and int(t) >= _NO_MILES_SPEED:
            j = k - 1
            while j >= 0 and tokens[j] in _ROUGHLY:
                j -= 1
            if j >= 0 and tokens[j] in _SPEED_SAID:
                return True
    return False


def told_in_miles_english(tokens: list[str], text: str = "") -> bool:
    """Whether the words ``tokens`` (lowercased, as written, figures as words of their own) say the road
    in words British English says far more than any English of km/h ("off the pavement", "my wing
    mirror", "the lorry"), or call a limit by a British one but 50 alone ("a 20 limit", "the national
    speed limit"), and are not set where km/h is signed (the Gardaí; a place that signs km/h named in
    ``text``, the text as written; a speed of 90 or more): in a story told in the first person, the
    narrator's bare speeds are in mph (see the module's docstring; the caller asks only of such a
    story). Not "a car park", "a 30 zone", "a 50
    limit", nor "the 50 km/h limit"."""
    if any(t in _IRISH_POLICE for t in tokens) or _km_h_speed(tokens) or names_a_km_h_place(text):
        return False
    if any(t in NARRATORS_MILES_WORDS for t in tokens):
        return True
    for k, (t, nxt) in enumerate(zip(tokens, tokens[1:])):
        if (t, nxt) in NARRATORS_MILES_PAIRS:
            return True
        if nxt == "limit" and t in _BRITISH_LIMITS:
            return True  # ("a 20 limit", "40 limit, and I was doing 40")
        if (t, nxt) == ("national", "speed") and tokens[k + 2 : k + 3] == ["limit"]:
            return True
    return False


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
