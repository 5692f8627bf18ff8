"""Where a road user starts beside the ego, read from the phrase that places it: a side word and the
noun it is attached to ("in the offside lane", "off the pavement on my left", "a side road on the
ego's right").

Why a module of its own: the side of a lane, kerb or junction arm is said in two orders (side word
before the noun, "the left-hand footway"; or after it, "the footway on my left") and in words whose
side depends on the country the writer drives in ("nearside", "offside", "inside lane"). Matching
fixed phrases missed most of the combinations; this reads the few closed word classes involved
(prepositions, determiners and possessives, side words, lane/kerb/arm nouns) and composes them.

Conventions:

- *nearside* is the kerb side, *offside* the centre-line side. A writer who gives speeds in miles per
  hour drives on the left (UK), so there the nearside is the left; so does one who tells something that
  happened in British road words ("kerb", "nearside", "lorry"), whatever the unit (Ireland, Australia,
  India give km/h); elsewhere the right (the project's own convention, and Euro NCAP's, whose test
  lines say "nearside" in the present tense, and whose codes are rewritten before this reads them).
- on a straight road the *inside* lane is the nearside one, the *outside* lane the offside one; on a
  roundabout *inner*/*inside* is towards the island, which is on the offside.
- a side word restated right after ("the nearside (left) footway") wins: the writer said it plainly.
- lanes are compared with the ego's own when it is said ("I was in the right lane ... the van in the
  left lane": the van is to the left).
"""

from __future__ import annotations

import re
from dataclasses import dataclass, replace
from functools import lru_cache

from lemminflect import getInflection

from vei_scenario.language import lexicon as L
from vei_scenario.language.lemmas import lemmas
from vei_scenario.language.vocabulary import GENDERED
from vei_scenario.language.vocabulary import STREET_WORDS as _STREET_WORDS

#: Side words that name a side outright.
_PLAIN = {"left": "left", "right": "right", "left-hand": "left", "right-hand": "right"}
#: Side words relative to the kerb: "near" (kerb side) or "off" (centre side), and the middle.
_RELATIVE = {
    "nearside": "near", "near-side": "near", "offside": "off", "off-side": "off",
    "slow": "near", "fast": "off", "overtaking": "off", "passing": "off",
    "middle": "middle", "centre": "middle", "center": "middle",
}  # fmt: skip
#: Words whose side depends on the road: a straight road's inside lane is the nearside one, a
#: roundabout's is towards the island (offside).
_RING = {"inside": "near", "inner": "near", "outside": "off", "outer": "off"}
#: Nouns of a kerb or the ground beside the carriageway.
KERB_NOUNS = frozenset(
    {"kerb", "curb", "kerbside", "pavement", "sidewalk", "footway", "footpath", "verge", "shoulder", "edge"}
)
#: Nouns of a junction arm; "road"/"street" only when said to be a side or minor one.
ARM_NOUNS = frozenset({"arm", "entry", "entrance", "approach", "exit"})
_ROAD_NOUNS = frozenset({"road", "street"})
_MINOR = frozenset({"side", "minor"})  # (a slip road joins as a lane does: not an arm)
#: Places off the carriageway a road user comes out of onto the road beside it, not a junction arm:
#: "out of a driveway on the right", "pulled out of the stop on my left" (a bus stop).
OFF_ROAD_PLACES = frozenset(
    {"driveway", "drive", "stop", "lay-by", "layby", "gateway", "gate", "gates", "forecourt", "bay", "track", "yard"}
)
#: Two-word places of that kind, by their first word ("a parking space", "the car park").
_PLACE_HEADS = {"parking": (["space"], ["spot"], ["bay"], ["place"]), "car": (["park"],), "bus": (["stop"],)}
#: Nouns that may name what a place beside the road belongs to, before its head ("a field gate", "the
#: school car park"): any word but these, which end or turn the noun phrase.
_NOT_A_MODIFIER = frozenset({"left", "right", "on", "to", "at", "in", "into", "onto", "of", "and", "or", "the", "a"})


def _place_head(tokens: list[str], k: int) -> int | None:
    """Where the noun phrase of a place beside the carriageway that starts at token ``k`` ends (past its
    head), or None: the head a place noun ("driveway", "gate", "stop") or a two-word one ("car park"),
    after at most two nouns that say whose it is ("the quarry gate", "a farm track", "the petrol station
    forecourt"). Only the head decides: "the stop" and "the bus stop" are one place, "the farm" none."""
    for m in range(k, min(k + 3, len(tokens))):
        word = tokens[m]
        if word in OFF_ROAD_PLACES:
            return m + 1
        if tokens[m + 1 : m + 2] in _PLACE_HEADS.get(word, ()):
            return m + 2
        if word in _NOT_A_MODIFIER or not word.isalpha():
            return None
    return None


#: A plain side as a test line or a terse note writes it in brackets ("(left)", "(R)", "(right-hand)").
_BRACKETED_SIDES = {
    "left": "left",
    "right": "right",
    "l": "left",
    "r": "right",
    "left-hand": "left",
    "right-hand": "right",
}


def place_sides_in_brackets(tokens: list[str]) -> list[str]:
    """``tokens`` with a side in brackets right after a place beside the road said as "on the" side:
    "pulls out of stop (left)", "a parking space (R)" read as "... on the left", "... on the right".
    Why: a test line or a terse note says the side of the place so; the brackets go before the sides
    are read, and the place was then put at the writer's near kerb. Only a place's head right before
    the bracket counts (not a side in brackets after an exit, which says the ego's turn)."""
    out: list[str] = []
    k, n = 0, len(tokens)
    while k < n:
        side = _BRACKETED_SIDES.get(tokens[k + 1]) if k + 2 < n and tokens[k] == "(" and tokens[k + 2] == ")" else None
        if side is not None and out and _ends_a_place(out):
            out += ["on", "the", side]
            k += 3
            continue
        out.append(tokens[k])
        k += 1
    return out


def _ends_a_place(words: list[str]) -> bool:
    """Whether ``words`` end with the head of a place beside the carriageway ("stop", "car park")."""
    if words[-1] in OFF_ROAD_PLACES:
        return True
    return any(len(words) > len(tail) and words[-1 - len(tail)] == head and words[-len(tail) :] == tail
               for head, tails in _PLACE_HEADS.items() for tail in tails)  # fmt: skip


def _in_a_state(tokens: list[str], i: int) -> bool:
    """Whether the word before the preposition at token ``i`` says where a road user is rather than
    where it arrives: a participle of state or its own noun ("a bus standing at a stop", "a van
    waiting in the lay-by", "a coach at the stop"), not a finite verb ("the bus stops at the stop on
    the left": where it stops, a landmark)."""
    if i == 0:
        return False
    word = tokens[i - 1]
    return word.endswith("ing") or "VERB" not in lemmas(word)


#: Nouns "oncoming"/"opposite" name as the other direction's part of the road.
_THE_OTHER_WAYS = frozenset({"lane", "lanes", "side", "carriageway"})


def lane_it_passes_in(relation: object, words: str, after: str, said: set) -> bool:
    """Whether "the oncoming lane" said of a road user already said to come from behind is the lane it
    overtakes in, not a start facing the ego ("a car from behind overtakes us in the oncoming lane",
    "a motorbike behind me swung out into the oncoming lane"): it starts behind. A road user first
    said to be in that lane ("a bus in the oncoming lane") comes towards the ego."""
    lane = after in _THE_OTHER_WAYS or words.split()[-1] in _THE_OTHER_WAYS  # ("oncoming lane", "in the opposite lane")
    return relation == "oncoming" and lane and "behind" in said


def waits_elsewhere(relation: object, prep: str, lane: str | None) -> bool:
    """Whether a roadside place said "at" or "in" ("waiting at the stop on my left") is not where a
    road user already said to be in a lane starts: the lane said first is where it is, and the place
    is another's (the one it passes) or where it goes."""
    return lane is not None and prep in ("at", "in") and str(relation).startswith("roadside_")


def out_of_a_place_ahead(relation: object, roadside: object, place: str | None) -> bool:
    """Whether the roadside of a place a road user comes out of (``place``, its head noun: "pulled out
    of a field gate on his left", "out of the stop") is where it starts though "ahead" or "in front"
    was said of it first ("in front of me, a tractor pulled out of a gate on the left"): in front says
    where it comes out, across the ego's way; the place says where it was before, beside the road. A
    place it only waits or stops at ("the bus ahead stops at the stop on the right") is a landmark."""
    return relation == "ahead" and place is not None and str(roadside).startswith("roadside_")


def pulls_out_from_the_kerb(
    vehicle: bool, stationary: bool, kerb_side: str | None, lane_side: str | None, first: str | None
) -> bool:
    """Whether a vehicle said to stand at a kerb of a side ("a car parked at the kerb on the left", "a
    van stopped on the nearside kerb") and first to pull out into the ego's lane starts at that
    roadside: beside the carriageway, not in a lane beside the ego's, which it would then have had to
    be driving in. A parked car said only on a side ("a parked car on the right pulls out") keeps the
    side's lane, and one in a lane said stays in it."""
    return vehicle and stationary and kerb_side in ("left", "right") and lane_side is None and first == "cut_in"


def _reversing(tokens: list[str], i: int) -> bool:
    """Whether the verb right before the phrase at token ``i`` (and its particle) is reversing ("backed
    out of", "reverses from"): one that backs out of a place is read into the lane it backs across,
    as the layers have no reversing; one that pulls or comes out starts at the roadside."""
    verb = tokens[i - 2] if i >= 2 and tokens[i - 1] == "out" else tokens[i - 1] if i else ""
    return "reverse" in lemmas(verb).get("VERB", ()) or "back" in lemmas(verb).get("VERB", ())


def _past_owner(tokens: list[str], m: int) -> int:
    """Token ``m`` moved past whose side is said before a side word: a determiner or possessive ("my",
    "the"), or a possessive noun ("the ego's", "the driver's", "V1's")."""
    if tokens[m + 1 : m + 2] == ["'s"] and tokens[m : m + 1] != ["the"]:
        return m + 2  # ("on V1's left")
    if tokens[m : m + 1] == ["the"] and tokens[m + 2 : m + 3] == ["'s"]:
        return m + 3  # ("on the ego's right", "on the driver's left")
    return m + 1 if m < len(tokens) and tokens[m] in _DETERMINERS else m


#: Verbs' particles a road user comes along a named road with ("coming down Station Road from the left").
_ALONG_A_ROAD = frozenset({"down", "along", "up"})


def named_road_at(tokens: list[str], i: int, proper: frozenset[str]) -> Said | None:
    """A road named by its name that a road user comes out of or along, starting at token ``i`` (its
    first name word, after "out of" or "from"; or after "down"/"along"/"up" when "from the left/right"
    follows), as a junction arm, with its side when one is said after it ("shot out of Albert Street on
    my left", "pulled out of Elm Close", "coming down Station Road from the left"); None otherwise.

    Why: a road user cannot come out of the road the ego drives on, so a named road it comes out of is
    a side road, an arm of a junction; read past as names, a rider out of one was taken to step off the
    kerb. The name must be written with a capital where it is not a sentence's first word (``proper``,
    lower-cased) and end in a word for a street: "out of Tesco", "out of nowhere", "from the bus lane"
    are no roads."""
    n = len(tokens)
    before = tokens[max(0, i - 2) : i]
    along = before[-1:] and before[-1] in _ALONG_A_ROAD
    if not (before[-1:] == ["from"] or before == ["out", "of"] or along):
        return None
    k = i
    while k < n and k < i + 3 and tokens[k] in proper and tokens[k] not in _STREET_WORDS:
        k += 1
    if k == i or k >= n or tokens[k] not in _STREET_WORDS:
        return None
    end = k + 1
    if tokens[end : end + 1] and tokens[end] in _LINKS | {"from"} and _side_follows(tokens, end + 1):
        m = _past_owner(tokens, end + 1)
        return Said(i, m + 1, before[-1], (("arm", None), ("side", tokens[m])))
    return None if along else Said(i, end, "from" if before[-1] == "from" else "out", (("arm", None),))


def _side_follows(tokens: list[str], m: int) -> bool:
    """Whether a side ("left"/"right", after whose it is) follows at token ``m``."""
    m = _past_owner(tokens, m)
    return tokens[m : m + 1] in (["left"], ["right"])


#: Counts of lanes between a road user and the ego ("two lanes to our right").
_LANE_COUNTS = frozenset({"two", "three", "four", "2", "3", "4"})


def lanes_away(tokens: list[str], i: int) -> bool:
    """Whether a count of lanes at token ``i`` says how many lanes over a road user is ("two lanes to
    our right", "3 lanes over on my left"): a place beside the ego on that side, not the road's lanes."""
    if tokens[i] not in _LANE_COUNTS or tokens[i + 1 : i + 2] != ["lanes"]:
        return False
    k = i + 2 + (tokens[i + 2 : i + 3] == ["over"])
    m = _past_owner(tokens, k + 1)  # (not "two lanes to the left of the median": the road's lanes)
    return tokens[k : k + 1] in (["to"], ["on"]) and _side_follows(tokens, k + 1) and tokens[m + 1 : m + 2] != ["of"]


#: Prepositions that say a road user comes out of a place.
_OUT_OF = frozenset({"out", "from", "of"})
#: Lanes that are beside the carriageway rather than in it: a rider there starts at the kerb.
_KERB_LANES = frozenset({"cycle", "bike", "bus"})
_DETERMINERS = frozenset({"the", "a", "an", "my", "our", "its", "his", "her", "their", "your", "this", "that"})
_POSSESSIVE = (["my"], ["our"], ["its"], ["his"], ["her"], ["their"], ["your"])
_OWNERS = frozenset({"my", "our", "its", "his", "her", "their", "your"})
#: Side words of a kerb, bare ("on the nearside") or of a vehicle ("the offside of the van").
_KERB_SIDES = frozenset({"nearside", "near-side", "offside", "off-side"})
#: The parts of a vehicle a side or end word can name ("the rear bumper", "its front wing").
VEHICLE_PARTS = frozenset(
    {"bumper", "wing", "door", "doors", "wheel", "wheels", "corner", "quarter", "panel", "light", "lights", "lamp",
     "end", "tyre", "tire", "fender", "windscreen", "windshield", "window", "mirror", "offside", "nearside"}
)  # fmt: skip
_ENDS = frozenset({"rear", "front", "back"})
#: Words after which a noun phrase has ended ("went under the nearside front and ...").
_PHRASE_ENDS = frozenset({"and", "but", "then", "as", "while", "when", "so", "of", "with"})


def part_after_side(tokens: list[str], k: int, parts: frozenset[str] | set[str] = VEHICLE_PARTS) -> int | None:
    """Where a part of a vehicle named after a side word ends, the side word ending at token ``k``
    ("the nearside | wing", "the offside | front corner", "the nearside | rear passenger door", "went
    under the offside | front."), or None. Why: a side word before an end of a vehicle or a part says
    where on the vehicle something touched, not where a road user came from; read as a kerb side it
    put a rider who came off the left kerb on the right. An end word alone is a part only where its
    noun phrase ends ("the nearside front" then a stop or "and"), not "the nearside in front of me"."""
    n = len(tokens)
    m = k + (k < n and tokens[k] in _ENDS)
    if m < n and tokens[m] in parts:
        return m + 1
    if m + 1 < n and tokens[m + 1] in parts and tokens[m].isalpha() and tokens[m] not in _NOT_A_MODIFIER:
        return m + 2  # ("rear passenger door", "front driver's wing" read as "front driver 's")
    if m > k and (m >= n or not tokens[m].isalpha() or tokens[m] in _PHRASE_ENDS):
        return m
    return None


#: The parts on a vehicle's flank ("the rear passenger door", "its back wheel"): an end word before one
#: says which door or wheel, not that the road user is at that end (the bumper or boot would).
FLANK_PARTS = frozenset(
    {"door", "doors", "wheel", "wheels", "wing", "quarter", "panel", "tyre", "tire", "window", "windows", "arch",
     "seat", "seats", "pillar", "sill"}
)  # fmt: skip
#: Words that may name which flank part it is between the end word and the part.
_FLANK_MODIFIERS = frozenset(
    {"passenger", "passenger's", "driver", "driver's", "drivers", "'s", "side", "nearside", "offside", "near-side",
     "off-side", "left", "right", "lh", "rh", "wheel", "quarter"}
)  # fmt: skip


def end_of_a_flank_part(tokens: list[str], k: int) -> int | None:
    """Where a flank part named after the end word at token ``k`` ends ("rear | passenger door", "back |
    left wheel", "rear | driver 's door"), or None. Why: a road user that went "into my rear passenger
    door" struck the ego's side, coming from wherever it was said to come from (an entry, a side road);
    read as "rear" it was put behind the ego. An end part ("my rear bumper", "the back of us") keeps
    the end it names."""
    if k >= len(tokens) or tokens[k] not in _ENDS:
        return None
    j = k + 1
    while j < min(len(tokens), k + 4) and tokens[j] in _FLANK_MODIFIERS and tokens[j] not in FLANK_PARTS:
        j += 1
    return j + 1 if j < len(tokens) and tokens[j] in FLANK_PARTS else None


#: Words of the far or near side of the road, before a plain side that restates them.
_FAR_NEAR = frozenset({"far", "near", "opposite", "other"})
_OPENING = frozenset(
    {"in", "on", "from", "off", "out", "of", "along", "into", "onto", "at", "down", "up", "to", "towards", "toward"}
)
_INTO = frozenset({"into", "onto"})
#: Prepositions of being in, leaving or taking a numbered lane ("in lane 2", "keeps to lane 1").
_IN_A_LANE = frozenset({"in", "into", "from", "on", "to"})
_LINKS = frozenset({"on", "to", "at"})
_MODIFIERS = frozenset({"adjacent", "next", "neighbouring", "neighboring", "nearest"})
_ORDER = {"left": 0, "middle": 1, "right": 2}


@dataclass(frozen=True)
class Said:
    """A side phrase found at ``start`` (its first word after the preposition and determiners) up to
    ``end``: mentions as (slot, value) in the reader's slots, and the preposition before it."""

    start: int
    end: int
    prep: str
    mentions: tuple[tuple[str, object], ...]


#: Words of the road only writers who drive on the left use (British), and only writers who drive on
#: the right and give miles per hour use (American): they say which side a writer's "inside lane" or
#: "nearside" is on, with or without a unit. They tell the side, not the unit: most are said in Ireland,
#: Australia, India and Africa too, which sign km/h (:mod:`vei_scenario.language.miles_english` counts
#: for mph only those of them no English of km/h says).
LEFT_HAND_WORDS = frozenset(
    {"lorry", "lorries", "carriageway", "kerb", "kerbs", "kerbside", "hgv", "hgvs", "nearside", "offside",
     "pavement", "pavements", "footway", "footways"}
)  # fmt: skip
#: American road and car words (where a British writer says junction, saloon, people carrier, indicator,
#: town centre, windscreen, slip road, wing): with miles per hour they tell a right-hand writer.
_RIGHT_HAND_WORDS = frozenset(
    {
        "freeway", "freeways", "interstate", "sidewalk", "sidewalks", "curb", "curbs", "crosswalk", "crosswalks",
        "stoplight", "stoplights", "semi", "intersection", "intersections", "sedan", "sedans", "minivan",
        "minivans", "blinker", "blinkers", "downtown", "windshield", "on-ramp", "off-ramp", "fender", "jaywalker",
        "jaywalking", "jaywalked",
    }
)  # fmt: skip


#: Speed units of a writer who follows the metric convention (Euro NCAP's: the nearside is the right).
_METRIC_SPEEDS = frozenset({"km/h", "kph", "m/s"})


#: Words of a narrator telling their own drive.
_FIRST_PERSON = frozenset({"i", "me", "my", "mine", "we", "us", "our", "ours"})


#: Countries and cities whose traffic keeps left, and keeps right: named outright ("it's Ireland after
#: all", "UK layout", "a rental in Spain"), the place says the writer's side, whatever the speed unit
#: (Ireland, Australia and India give km/h and keep left). Nouns only: an adjective names a make or a
#: language as often as a place ("a Japanese hatchback", "my English is not good").
_KEEPS_LEFT = (
    "UK", "U.K.", "United Kingdom", "Britain", "Great Britain", "England", "Scotland", "Wales", "Ireland",
    "Northern Ireland", "Australia", "New Zealand", "South Africa", "Japan", "India", "Pakistan", "Bangladesh",
    "Sri Lanka", "Nepal", "Singapore", "Malaysia", "Indonesia", "Thailand", "Hong Kong", "Kenya", "Uganda",
    "Tanzania", "Zambia", "Zimbabwe", "Botswana", "Namibia", "Jamaica", "Cyprus", "Malta", "Mauritius",
    "London", "Dublin", "Edinburgh", "Glasgow", "Cardiff", "Belfast", "Melbourne", "Brisbane", "Auckland",
    "Johannesburg", "Cape Town", "Tokyo", "Osaka", "Mumbai", "Delhi", "Bangalore", "Bengaluru", "Chennai",
    "Kolkata", "Karachi", "Dhaka", "Nairobi", "Kuala Lumpur", "Sydney",
)  # fmt: skip
_KEEPS_RIGHT = (
    "US", "U.S.", "USA", "U.S.A.", "United States", "America", "Canada", "Mexico", "France", "Germany", "Spain",
    "Italy", "Portugal", "Netherlands", "Belgium", "Switzerland", "Austria", "Poland", "Sweden", "Norway",
    "Denmark", "Finland", "Greece", "China", "Korea", "Brazil", "Argentina", "Chile", "Turkey", "Israel",
    "Paris", "Berlin", "Munich", "Madrid", "Barcelona", "Rome", "Milan", "Amsterdam", "Toronto", "Vancouver",
    "Montreal", "New York", "Los Angeles", "Chicago", "California", "Texas", "Florida",
)  # fmt: skip
#: Upper case only: "US" the country, never "us" the pronoun.
_CASED = frozenset({"US", "UK", "USA"})


def _place_pattern(names: tuple[str, ...]) -> re.Pattern:
    cased = "|".join(re.escape(n) for n in names if n in _CASED)
    other = "|".join(re.escape(n) for n in sorted(names, key=len, reverse=True) if n not in _CASED)
    either = f"{cased}|(?i:{other})" if cased else f"(?i:{other})"
    return re.compile(rf"(?<![\w.])(?:{either})(?![\w-])")


_LEFT_PLACES, _RIGHT_PLACES = _place_pattern(_KEEPS_LEFT), _place_pattern(_KEEPS_RIGHT)
#: Of the places above, those that sign speeds in miles per hour (Britain, Northern Ireland, the US).
_SIGNS_MILES = frozenset(
    {"UK", "U.K.", "United Kingdom", "Britain", "Great Britain", "England", "Scotland", "Wales", "Northern Ireland",
     "London", "Edinburgh", "Glasgow", "Cardiff", "Belfast", "US", "U.S.", "USA", "U.S.A.", "United States",
     "America", "New York", "Los Angeles", "Chicago", "California", "Texas", "Florida"}
)  # fmt: skip
_KM_PLACES = _place_pattern(tuple(n for n in _KEEPS_LEFT + _KEEPS_RIGHT if n not in _SIGNS_MILES))
#: "Ireland" inside "Northern Ireland" is no km/h place.
_NORTHERN = re.compile(r"northern\s+$", re.IGNORECASE)


def names_a_km_h_place(text: str) -> bool:
    """Whether ``text`` names a country or city that signs speeds in km/h ("in Nairobi", "near Kuala
    Lumpur", "in Toronto"; not "in Belfast", "Northern Ireland", "in the US"): its writer's bare speeds
    are in km/h, whatever words of British or American roads they share."""
    return any(not _NORTHERN.search(text[: m.start()]) for m in _KM_PLACES.finditer(text))


#: The convention said in words: "left-hand traffic", "we drive on the left", "traffic keeps right".
_CONVENTION = re.compile(
    r"\b(left|right)[- ]hand traffic\b"
    r"|\b(?:we|you|they|i|people|everyone|traffic|cars|drivers)\s+(?:(?:am|are|is|was|were|'re|'m)\s+)?"
    r"(?:drive|drives|drove|driving|keep|keeps|keeping)\s+(?:on\s+the\s+)?(left|right)\b"
    r"(?!\s*[- ]?(?:lane|lanes|kerb|curb|verge|shoulder|pavement|sidewalk|footway|arm|turn|exit|edge|of)\b)"
    r"|(?:^|[.,;:(]\s*)driving\s+on\s+the\s+(left|right)(?:[- ]hand)?(?:\s+side)?(?:\s+of\s+the\s+road)?"
    r"\s*(?=[.,;:)]|$)",
    re.IGNORECASE,
)


def stated_side(text: str) -> str | None:
    """The side traffic keeps to, when the writer says it ("left-hand traffic", "we drive on the left")
    or names where the road is ("Dublin", "a UK layout", "US city street"); None when neither is said,
    or places of both conventions are named (a holiday abroad: the other cues decide)."""
    if m := _CONVENTION.search(text):
        return next(g for g in m.groups() if g).lower()
    left, right = bool(_LEFT_PLACES.search(text)), bool(_RIGHT_PLACES.search(text))
    return "left" if left and not right else "right" if right and not left else None


def drives_on_left(tokens: list[str], text: str = "") -> bool:
    """Whether the writer drives on the left: said outright (:func:`stated_side`); else speeds in miles
    per hour without American road words (the reader's normaliser writes every "miles an hour" as
    "mph"); or, with no metric speed, a motorway named as Britain's ("the M25"), or a driver telling
    their own drive in British road words ("a lorry in the inside lane drifted into me"). A test line
    ("a lorry in the nearside lane cuts in ahead of the AV") or metric speeds follow Euro NCAP's
    convention, a right-hand one, whatever their words."""
    said = stated_side(text)
    if said is not None:
        return said == "left"
    words = set(tokens)
    if "mph" in words:
        return not words & _RIGHT_HAND_WORDS
    british = bool(words & LEFT_HAND_WORDS)
    if words & _METRIC_SPEEDS:
        return british and told_in_the_past(tokens)
    return _motorway_number(tokens) or (british and (bool(words & _FIRST_PERSON) or told_in_the_past(tokens)))


#: Forms of "be" and "have" that carry a clause's tense.
_PRESENT_AUXILIARIES = frozenset({"is", "are", "am", "has", "'s", "'re", "'m"})


def told_in_the_past(tokens: list[str]) -> bool:
    """Whether ``tokens`` tell an event that happened (a statement, a report, a story) rather than
    specify a test: more verbs in the past tense than in the present, and at least two. Why: a writer
    who uses British road words ("kerb", "nearside", "lorry") and metric speeds about something that
    happened drives where traffic keeps left and speeds are metric (Ireland, Australia, New Zealand,
    South Africa, India); the same words in a present-tense test line are Euro NCAP's, whose nearside
    is the right. A word after a determiner or a number is a noun ("the stops", "two parked buses")."""
    past = present = 0
    for k, word in enumerate(tokens):
        verbs = lemmas(word).get("VERB", ())
        if not verbs and word not in _PRESENT_AUXILIARIES:
            continue
        noun_place = k > 0 and (tokens[k - 1] in _DETERMINERS or tokens[k - 1][:1].isdigit())
        if noun_place:
            continue
        tense = "present" if word in _PRESENT_AUXILIARIES else _tense(word)
        present += tense == "present"
        past += tense == "past"
    return past >= 2 and past > present


@lru_cache(maxsize=16384)
def _tense(word: str) -> str | None:
    """The tense a verb form says: "present" for a third-person present one ("hides"), "past" for a
    past-tense one ("emerged"), None for any other word; looked up once per word."""
    verbs = lemmas(word).get("VERB", ())
    if any(word in getInflection(v, "VBZ") for v in verbs):
        return "present"
    if any(word != v and word in getInflection(v, "VBD") for v in verbs):
        return "past"
    return None


#: The lexicon's bare near and far kerb words, with the side each names where traffic keeps right.
_BARE_KERB_SIDES = {**dict.fromkeys(L.NEARSIDE, "right"), **dict.fromkeys(L.FARSIDE, "left")}


def kerb_side_of_the_writer(words: str, side: object, left_hand: bool) -> object:
    """The side a kerb side word read bare names ("child from behind parked cars, nearside", "to the
    other side"): the writer's near kerb or far one, as :func:`near_and_far` says for their side of the
    road; a plain side said ("from the left kerb") stays. Why: read as a word of its own, "nearside" had
    the right-hand convention's side, and a British writer's child from the nearside came from the right."""
    if words not in _BARE_KERB_SIDES or side != _BARE_KERB_SIDES[words]:
        return side
    near, far = near_and_far(left_hand)
    return near if side == "right" else far


def near_and_far(left_hand: bool) -> tuple[str, str]:
    """(near, far) kerb of a writer's road: the kerb side is the left where traffic keeps left. A kerb
    said with no side ("rode along the kerb", "stepped off the kerb") is the near one."""
    return ("left", "right") if left_hand else ("right", "left")


def _motorway_number(tokens: list[str]) -> bool:
    """A British motorway named by its number ("the M25", read as "m 25"): "m" before a number, never
    after one as a distance is."""
    return any(
        w == "m" and k + 1 < len(tokens) and tokens[k + 1].isdigit() and not (k and tokens[k - 1][:1].isdigit())
        for k, w in enumerate(tokens)
    )


def _side(word: str, after: str, left_hand: bool, ring: bool) -> str | None:
    """The side (left, right or middle) a side word says, the restated plain side winning."""
    if after in ("left", "right") and (word in _RELATIVE or word in _RING):
        return after  # "the nearside (left) lane"
    if word in _PLAIN:
        return _PLAIN[word]
    rel = _RELATIVE.get(word)
    if rel is None and word in _RING:
        rel = _RING[word]
        if ring:  # a roundabout's inner lane is by the island, on the offside
            rel = "off" if rel == "near" else "near"
    if rel is None:
        return None
    if rel == "middle":
        return "middle"
    near = "left" if left_hand else "right"
    far = "right" if left_hand else "left"
    return near if rel == "near" else far


def _is_side_word(word: str) -> bool:
    return word in _PLAIN or word in _RELATIVE or word in _RING


#: Prepositions that say where someone is or comes from beside a vehicle's side ("on my nearside"),
#: not where it was struck ("into our nearside", "clipped my offside").
_WHERE_BESIDE = frozenset({"on", "from", "off", "along", "up", "down"})
#: The seats whose side of a car names a side of the road: the passenger's is the kerb side (nearside),
#: the driver's the centre side (offside), whichever side of the road the writer drives on.
_SEATS = {"passenger": "nearside", "passengers": "nearside", "driver": "offside", "drivers": "offside"}


def _seat_side(tokens: list[str], j: int) -> tuple[str, int] | None:
    """The side word a seat's side at token ``j`` stands for ("the passenger side", "the driver's side":
    nearside and offside) and where the seat's side ends, or None. Why: a writer says the side of the
    road by the car's seats as often as by near and off, and the seats follow the convention as those
    do (a British passenger sits on the left, an American on the right)."""
    framed = tokens[j] == "ego" and tokens[j - 1 : j] == ["the"]  # (the driver's seat read as the ego's)
    seat = "offside" if framed else _SEATS.get(tokens[j])
    if seat is None:
        return None
    k = j + 1 + (tokens[j + 1 : j + 2] == ["'s"])
    if framed and tokens[k + 1 : k + 2] == ["of"]:
        return None  # ("on the ego's side of the road": the ego's half of the road, no seat)
    return (seat, k + 1) if tokens[k : k + 1] == ["side"] else None


#: Who owns a vehicle the ego is in, said before its side or after "of" ("my passenger side", "the
#: driver's side of his car": a third-person ego's, as a claim letter tells it).
_EGO_VEHICLE_OWNERS = frozenset({"my", "our", "his", "her", "their"})


def _of_the_egos_vehicle(tokens: list[str], j: int, end: int) -> bool:
    """Whether the seat side at ``tokens[j:end]`` is a side of the ego's own vehicle ("struck my
    passenger side", "the driver's side of our car", "the passenger side of my client's vehicle").
    Why: struck there, the road user came from that side, as one said to hit "the right side of my
    car"; a seat side of nobody's ("from the passenger side") is a side of the road instead."""
    if j > 0 and tokens[j - 1] in ("my", "our"):
        return True
    after = tokens[end : end + 3]
    owner = after[1:2] and after[1] in _EGO_VEHICLE_OWNERS | {"ego"}  # ("of my truck", read as the ego's)
    return after[:1] == ["of"] and bool(owner or after[1:3] == ["the", "ego"])


def the_egos_kerb_side(tokens: list[str], j: int) -> bool:
    """Whether the ego's possessive at token ``j`` owns a kerb side word ("the van's nearside", the
    reader having named the writer's van the ego: "the ego 's nearside"). Why: a vehicle's nearside is
    the kerb side of the road it faces along, so the ego's own nearside is the writer's near kerb, as
    "my nearside" is; another vehicle's ("on the bus's offside") may face either way, and stays a part
    of that vehicle."""
    return tokens[j : j + 2] == ["ego", "'s"] and tokens[j + 2 : j + 3] != [] and tokens[j + 2] in _KERB_SIDES


def phrase_at(tokens: list[str], i: int, left_hand: bool, ring: bool) -> Said | None:
    """The side phrase starting at token ``i`` (at its preposition, determiner or first content word),
    or None. Two orders are read:

    - side word, noun: "in the offside lane", "from the left-hand footway", "the right arm";
    - noun, "on/to/at", determiner or possessive, side word: "a side street on my left", "off the
      pavement on our right", "the lane to my left".

    "lane" followed by a number ("lane 1") is numbered from the nearside."""
    n = len(tokens)
    j = i
    prep = ""
    if j < n and tokens[j] in _OPENING:
        prep = tokens[j]
        j += 1
        if prep == "out" and tokens[j : j + 1] == ["of"]:
            j += 1
    elif i > 0 and tokens[i - 1] in _OPENING:  # (the preposition read with its verb: "swerved into")
        prep = tokens[i - 1]
    while j < n and tokens[j] in _DETERMINERS:
        j += 1
    while j < n and tokens[j] in _MODIFIERS:
        j += 1
    if j >= n:
        return None
    egos = the_egos_kerb_side(tokens, j)
    j += 2 * egos  # ("on the van's nearside", the van being the ego's: read past whose it is)
    start = j
    if i != start and tokens[i] not in _OPENING and tokens[i] not in _DETERMINERS:
        return None
    if (seat := _seat_side(tokens, j)) is not None and _of_the_egos_vehicle(tokens, j, seat[1]):
        # ("hit my passenger side", "the driver's side of our car"): as "the right side of my car"
        return Said(start, seat[1], prep, (("side", _side(seat[0], "", left_hand, False)),))
    if seat is not None:  # ("the passenger side": the nearside)
        tokens, j = [*tokens[:j], seat[0], *tokens[seat[1] :]], j  # (read as the side word it stands for)
        shift = seat[1] - j - 1
        said = phrase_at(tokens, i, left_hand, ring)
        return None if said is None else replace(said, end=said.end + shift * (said.end > j))
    if tokens[j] in _KERB_SIDES:
        # ("on my nearside", "on the taxi's offside" of the ego's taxi: beside the ego)
        owned = (tokens[j - 1] in _OWNERS or egos) and prep in _WHERE_BESIDE
        of_one = tokens[j - 1] in _OWNERS or tokens[j - 1] == "'s"
        part = tokens[j + 1 : j + 2] == ["of"] or (of_one and not owned)
        if part:  # "the offside of the HGV", "into our nearside": a side of a vehicle, no road user's place
            return Said(start, j + 1, prep, ())
        if (end := part_after_side(tokens, j + 1)) is not None:  # ("the offside front corner")
            return Said(start, end, prep, ())
        if tokens[j + 1 : j + 2] not in (["lane"], ["left"], ["right"], ["hand"]) and prep in _KERB_SIDE_PREPOSITIONS:
            side = _side(tokens[j], "", left_hand, ring)  # "from the nearside": that kerb (a walker's),
            # or the lane on that side (a driver's, "a car on the offside drifted in"): the reader says whose;
            # come up or gone past on, as "the inside" (:func:`_bare_ring_side`), it comes from behind
            behind = (("relation", "behind"),) if prep in _FROM_BEHIND or _particle_before(tokens, i) else ()
            return Said(start, j + 1, prep, (("kerb", None), ("kerb_side", side), ("lane_side", side), *behind))
    if tokens[j] in _ENDS and tokens[j + 1 : j + 2] and tokens[j + 1] in VEHICLE_PARTS:
        return Said(start, j + 2, prep, ())  # "clipped his rear bumper": a part of a vehicle, no place
    restated = tokens[j + 1 : j + 2] in (["left"], ["right"]) and tokens[j + 2 : j + 3] in (["side"], ["kerb"])
    if tokens[j] in _FAR_NEAR and restated:  # "from the far (left) side": the side said plainly
        return Said(start, j + 3, prep, (("kerb", None), ("kerb_side", tokens[j + 1])))
    kerb_after = tokens[j + 1 : j + 2] and (tokens[j + 1] in KERB_NOUNS or tokens[j + 1] == "side")
    if tokens[j] in _FAR_NEAR and kerb_after and j > i and tokens[j - 1] in _DETERMINERS:
        # "off the far kerb", "from the opposite pavement": across the road, the offside; "the near kerb" the nearside
        side = _restated(tokens, j + 2) or _side("nearside" if tokens[j] == "near" else "offside", "", left_hand, False)
        # ("from the opposite side": the far approach; not "the far side", "the other side of the road")
        across = tokens[j] in ("opposite", "other") and tokens[j + 1] == "side" and tokens[j + 2 : j + 3] != ["of"]
        return Said(
            start, j + 2, prep, (("kerb", None), ("kerb_side", side), *((("far_side", None),) if across else ()))
        )
    if not ring and (bare := _bare_ring_side(tokens, i, j, prep, left_hand)) is not None:
        return bare
    # side word, then noun
    if _is_side_word(tokens[j]):
        k = j + 1
        after = tokens[k] if k < n else ""
        if after in ("left", "right") and tokens[j] not in _PLAIN:
            k += 1
        if tokens[k : k + 1] == ["hand"]:  # ("right hand lane")
            k += 1
        noun = tokens[k] if k < n else ""
        side = _side(tokens[j], after, left_hand, ring)
        if side is None:
            return None
        owner = tokens[k + 2 : k + 4]
        of_another = tokens[k + 1 : k + 2] == ["of"] and (owner[:1] in _POSSESSIVE or owner == ["the", "ego"])
        if noun == "lane" and not of_another:  # (not "the left lane of the ego": a lane named by another's)
            if prep in _INTO:  # where it moves to, not where it starts
                return Said(start, k + 1, prep, (("toward", side),)) if side != "middle" else None
            return Said(start, k + 1, prep, (("lane_side", side),))
        if noun in KERB_NOUNS and side != "middle":
            return Said(start, k + 1, prep, (("kerb", None), ("kerb_side", side)))
        if (noun in ARM_NOUNS or noun in ("road", "street")) and side != "middle" and tokens[j] in _PLAIN:
            return Said(start, k + 1, prep, (("arm", None), ("side", side)))
        minor = noun in _MINOR and tokens[k + 1 : k + 2] and tokens[k + 1] in _ROAD_NOUNS
        if minor and side != "middle" and tokens[j] in _PLAIN:  # ("from the left side street": that arm)
            return Said(start, k + 2, prep, (("arm", None), ("side", side)))
        return None
    # "lane 1": numbered from the nearside
    numbered = j + 1 < n and tokens[j + 1] in LANE_NUMBERS
    held = prep == "" and j == i and i > 0 and "VERB" in lemmas(tokens[i - 1])  # ("holds lane 3", "using lane 1")
    if tokens[j] == "lane" and numbered and tokens[j + 2 : j + 3] != ["m"] and (held or prep in _IN_A_LANE):
        number = LANE_NUMBERS[tokens[j + 1]]
        if tokens[j + 2 : j + 3] in (["on"], ["to"]) and _side_follows(tokens, j + 3):
            m = _past_owner(tokens, j + 3)  # "lane 1 (on the ego's left)": the side said plainly wins
            return Said(start, m + 1, prep, (("lane_side", tokens[m]),))
        side = _side("nearside", "", left_hand, ring) if number == 1 else "middle" if number == 2 else None
        if side is None:
            side = _side("offside", "", left_hand, ring)
        return Said(start, j + 2, prep, (("lane_side", side),))
    # noun, then "on my left"
    k = j
    kind = None
    place = None
    if tokens[k] in _MINOR and k + 1 < n and tokens[k + 1] in _ROAD_NOUNS:
        kind, k = "arm", k + 2
    elif tokens[k] in ARM_NOUNS or (tokens[k] == "junction" and prep in _OUT_OF | {"at"}):
        kind, k = "arm", k + 1  # ("from the junction on the left": the road joining there on that side)
    elif tokens[k] in KERB_NOUNS:
        kind, k = "kerb", k + 1
    elif prep in _OUT_OF and (head := _place_head(tokens, k)) is not None:
        kind, k = "place", head
        place = tokens[head - 1]  # (its head: "driveway", "gate", "stop", "park" of "car park")
    elif prep in ("at", "in") and _in_a_state(tokens, i) and (head := _place_head(tokens, k)) is not None:
        kind, k = "waits", head  # ("a bus standing at a stop on the left": beside the road there)
    elif tokens[k] in _KERB_LANES and tokens[k + 1 : k + 2] == ["lane"]:
        kind, k = "kerb", k + 2
    elif tokens[k] == "lane":
        kind, k = "lane", k + 1
    elif lanes_away(tokens, k):
        kind, k = "lane", k + 2 + (tokens[k + 2] == "over")  # ("two lanes (over) to our right": a lane there)
    if kind is not None:
        k = past_how_far_along(tokens, k)  # ("the lay-by ahead on the left": the lay-by's side)
    if kind is not None and k < n and tokens[k] in _LINKS:
        tokens = kerb_side_said_plainly(tokens, _past_owner(tokens, k + 1), left_hand)
    sided = k < n and tokens[k] in _LINKS and _side_follows(tokens, k + 1)
    if kind == "place" and not sided and not _reversing(tokens, i):
        near = "left" if left_hand else "right"  # ("pulled out from the stop": beside the writer's near kerb)
        return Said(start, k, prep, (("kerb", None), ("place", place), ("relation", f"roadside_{near}")))
    if kind is None or k >= n or tokens[k] not in _LINKS:
        return None
    m = _past_owner(tokens, k + 1)
    if m >= n or tokens[m] not in ("left", "right"):
        return None
    side = tokens[m]
    end = m + 1
    if tokens[end : end + 1] in (["side"], ["hand"]):  # ("on my left side")
        end += 1
    if tokens[end : end + 1] == ["lane"] or (tokens[end : end + 1] == ["-"]):
        return None  # ("the lane to the left lane": not this)
    if kind == "arm":
        return Said(start, end, prep, (("arm", None), ("side", side)))
    if kind == "kerb":
        return Said(start, end, prep, (("kerb", None), ("kerb_side", side)))
    if kind == "waits":  # at a place beside the carriageway on that side: that roadside, no lane
        return Said(start, end, prep, (("place", None), ("relation", f"roadside_{side}")))
    if kind == "place":  # beside the carriageway, where it comes onto the road from: that roadside
        if _reversing(tokens, i):  # (it backs across into the lane on that side: no pulling out ahead)
            return Said(start, end, prep, (("kerb", None), ("lane_side", side)))
        return Said(
            start, end, prep, (("kerb", None), ("place", place), ("lane_side", side), ("relation", f"roadside_{side}"))
        )
    return Said(start, end, prep, (("lane_side", side),))


#: Words that sharpen "ahead" said of a place ("just ahead", "up ahead", "further ahead").
_BEFORE_AHEAD = frozenset({"just", "up", "further", "farther", "right", "directly", "immediately", "slightly"})


def past_how_far_along(tokens: list[str], k: int) -> int:
    """Token ``k`` moved past "ahead" said between a place and its side ("a lay-by ahead on the left",
    "a field gate just ahead on the right", "the side road up ahead on our left"), when a side follows.
    Why: "ahead" there says how far along the road the place is, and the side after it is still the
    place's; read as the end of the place's phrase, the side was lost and a lorry waiting in a lay-by
    on the left started in the lane on the left."""
    m = k + (tokens[k : k + 1] != [] and tokens[k] in _BEFORE_AHEAD)
    if tokens[m : m + 1] == ["ahead"] and tokens[m + 1 : m + 2] and tokens[m + 1] in _LINKS:
        return m + 1 if _side_follows(tokens, m + 2) else k
    return k


def kerb_side_said_plainly(tokens: list[str], m: int, left_hand: bool) -> list[str]:
    """``tokens`` with a kerb side word at token ``m`` that ends a place's phrase ("a driveway on the
    offside", "the side road on the nearside (left)") written as the plain side it names, a plain side
    restated right after it winning. Why: a place is said on the nearside or offside as on the left
    or right; read only with "left"/"right" there, a driveway on the offside was put at the near kerb."""
    if m >= len(tokens) or tokens[m] not in _KERB_SIDES or tokens[m + 1 : m + 2] == ["of"]:
        return tokens  # (not "on the offside of the van": a part of a vehicle)
    restated = tokens[m + 1] if m + 1 < len(tokens) else ""  # ("on the offside (right)": the brackets gone)
    side = _side(tokens[m], restated, left_hand, False)
    return [*tokens[:m], side or tokens[m], *tokens[m + 1 :]]  # (as long as before: the ends said still hold)


#: Prepositions a bare "nearside"/"offside" follows when it names a side of the ego ("up the nearside").
_KERB_SIDE_PREPOSITIONS = frozenset({"on", "from", "off", "up"})
#: Prepositions a bare "inside"/"outside" follows when it names a side of the ego ("up the inside").
_ALONG = frozenset({"on", "up", "down", "along", "by", "past"})
#: Prepositions of going up to and past the ego along its side: said of one that comes from behind.
_FROM_BEHIND = frozenset({"up", "past"})
#: Verbs whose "up" is coming to a stop, not coming up from behind ("pulled up", "drew up", "parked up").
_STOPPING_WITH_UP = frozenset({"pull", "draw", "park", "stop", "wait", "line", "fetch"})
#: Words after "the inside" that make it a noun phrase of its own: "the inside of the bend" is no side.
_OF_A_PLACE = frozenset({"bend", "curve", "corner", "turn", "roundabout", "car", "van", "vehicle", "bus", "cab"})


def _bare_ring_side(tokens: list[str], i: int, j: int, prep: str, left_hand: bool) -> Said | None:
    """ "on my inside", "up the inside (of him)", "on the outside": inside or outside said as a noun, the
    side of the ego's road a rider or driver goes by on, in the ego's direction (a lane beside it, not a
    kerb a walker steps off): the inside is the kerb side, the outside the centre-line side. Coming
    "up" or "past" it, it comes from behind. Which side is which follows the writer's driving side, as
    "nearside" does. (On a roundabout the same words may point to the island or the outer edge: the
    caller leaves them unread there.)"""
    word = tokens[j]
    if word not in ("inside", "outside") or prep not in _ALONG or j == i or tokens[j - 1] not in _DETERMINERS:
        return None
    after = tokens[j + 1 : j + 2]
    end = j + 1
    if after == ["of"]:
        owner = tokens[j + 2 : j + 4]
        if owner[:1] and owner[0] in ("me", "us", "him", "her", "them", "it"):
            end = j + 3
        elif owner[:1] and owner[0] in _DETERMINERS and owner[1:] and owner[1] in _OF_A_PLACE:
            return None  # ("the inside of the bend": a place on the road, no side of the ego)
        else:
            end = j + 1
    elif after and (after[0] in _RING_NOUNS or after[0] in KERB_NOUNS or after[0] in _ROAD_NOUNS):
        return None  # ("the inside lane", "the outside line": a side word before its noun)
    near, far = ("left", "right") if left_hand else ("right", "left")
    # "came up the inside", "coming up on my inside", "went past on the outside": it comes from behind
    # (the verb's particle said before: "came up on my inside", "went past me on the outside")
    behind = (("relation", "behind"),) if prep in _FROM_BEHIND or _particle_before(tokens, i) else ()
    if word == "inside":  # (by the kerb: a rider there rides at its edge)
        return Said(j, end, prep, (("kerb", None), ("lane_side", near), *behind))
    return Said(j, end, prep, (("lane_side", far), *behind))


#: Words of the object between a verb's particle and the side ("came past the test car on the inside").
_OBJECT_WORDS = frozenset({"me", "us", "him", "her", "them", "it", "ego", "car", "van", "vehicle", "bus", "truck"})


def _particle_before(tokens: list[str], i: int) -> bool:
    """Whether "up" or "past" ends the verb before token ``i``, right before it or before the verb's
    object ("came up on my inside", "went past me on the outside", "shot past the ego on the inside");
    never across a clause ("up ahead, on the inside"), nor the "up" of stopping ("pulled up on the
    nearside", "parked up", "broken down up on the verge"), which says where one stands, not whence."""
    for k in range(i - 1, max(-1, i - 5), -1):
        if tokens[k] in _FROM_BEHIND:
            before = tokens[k - 1] if k else ""
            stops = before == "down" or bool(set(lemmas(before).get("VERB", ())) & _STOPPING_WITH_UP)
            return not (tokens[k] == "up" and stops)
        if tokens[k] not in _OBJECT_WORDS and tokens[k] not in _DETERMINERS:
            return False
    return False


#: Nouns "inside"/"outside" qualify as side words ("the outside lane", "its inside wheel").
_RING_NOUNS = frozenset(
    {"lane", "lanes", "line", "track", "wheel", "wheels", "mirror", "mirrors", "loop", "bend", "corner", "ring"}
)


def _restated(tokens: list[str], k: int) -> str | None:
    """A plain side restating a far or near side later in its sentence ("from the far side of the road,
    i.e. from my client's left"): "from" and, within four words, left or right. The writer said it
    plainly, and that wins over the driving convention."""
    for m in range(k, min(k + 10, len(tokens))):
        if tokens[m] == ";" or (tokens[m] == "." and len(tokens[m - 1]) > 1):  # (not the stops of "i.e.")
            return None
        if tokens[m] == "from":
            return next((w for w in tokens[m + 1 : m + 5] if w in ("left", "right")), None)
    return None


#: Forms of the verbs that say a road user comes or heads somewhere.
_COMING = frozenset(
    {"come", "comes", "coming", "came", "head", "heads", "heading", "headed", "drive", "drives", "driving", "drove"}
)
#: Prepositions of going along a lane (not "into" it: that is a cut-in).
_ALONG_LANE = frozenset({"on", "in", "down", "along", "up"})
_EGO_OWNERS = (["my"], ["our"], ["the", "ego", "'s"], ["ego", "'s"])


def towards_in_ego_lane(tokens: list[str], i: int) -> int | None:
    """Where a phrase ends that says a road user comes at the ego along its own lane, starting at token
    ``i`` ("coming on our lane", "came down my lane", "heading at us"), or None. Coming in the ego's
    lane, with nothing saying it is behind ("coming up behind us in our lane"), is coming at it.
    Not "coming into our lane" (a cut-in) nor "coming at 40 km/h" (a speed)."""
    if tokens[i] not in _COMING or i + 2 >= len(tokens):
        return None
    if tokens[i + 1] == "at" and tokens[i + 2] in ("me", "us", "ego") and tokens[i + 1 : i + 3] != ["at", "the"]:
        return i + 3  # ("heading at us")
    if tokens[i + 1] not in _ALONG_LANE:
        return None
    if tokens[i + 1] in ("in", "on") and not tokens[i].endswith("ing"):
        return None  # ("once he came in my lane": arrived in it, a cut-in; "coming on our lane" goes on)
    k = i + 2
    owner = next((o for o in _EGO_OWNERS if tokens[k : k + len(o)] == o), None)
    if owner is None or tokens[k + len(owner) : k + len(owner) + 1] != ["lane"]:
        return None
    end = k + len(owner) + 1
    if "behind" in tokens[max(0, i - 3) : end + 3]:
        return None  # ("coming up behind us in our lane")
    return end


#: Lemmas of the verbs that say a road user travels somewhere (not sideways: "swerve", "veer").
_TRAVEL = frozenset(
    {"come", "head", "drive", "ride", "travel", "speed", "race", "hurtle", "barrel", "fly", "zoom", "charge", "career"}
)
#: Words that end the stretch between such a verb and where it goes: a clause's end, or a place it
#: comes out of, off or across ("came out of the side road towards me": it turns out, no oncoming).
_NOT_ALONG = frozenset(
    {",", ".", ";", ":", "!", "?", "and", "but", "when", "then", "while", "as", "out", "off", "from", "across",
     "into", "onto", "behind", "past", "alongside", "after", "overtake", "overtaking", "pass", "passing"}
)  # fmt: skip
#: How many words back from "towards" the verb of travelling may be ("came the wrong way down the bus
#: lane straight at me": nine).
_REACH = 10
#: The edge of the road: one travelling along it towards the ego keeps to it, as its kerb says.
_EDGE = KERB_NOUNS | {"side", "gutter"}
#: The ego said after "towards", "at" or "for".
_EGO_AFTER = frozenset({"me", "us", "ego"})


def _the_ego_after(tokens: list[str], i: int) -> int | None:
    """Where the ego named right after "towards", "toward", "at" or "for" (token ``i``) ends ("at me",
    "towards her", "for my car", "at the ego"), or None: that preposition is not aimed at the ego."""
    if tokens[i] not in ("towards", "toward", "at", "for") or i + 1 >= len(tokens):
        return None
    after = tokens[i + 1]
    if after in _EGO_AFTER or told_of_the_ego(tokens, i + 1):
        return i + 2
    if after in ("my", "our") and i + 2 < len(tokens) and tokens[i + 2] not in ("left", "right"):
        return i + 3  # ("towards my car", "at our van")
    return i + 3 if tokens[i + 1 : i + 3] == ["the", "ego"] else None


def coming_at_the_ego(tokens: list[str], i: int) -> int | None:
    """Where a phrase ends that says a road user travels at the ego, starting at "towards", "toward",
    "at" or "for" (token ``i``) with the ego after it ("towards me", "straight at us", "for my car"),
    when a verb of travelling comes before it with no more than where it travels between ("came round
    the corner towards me", "came flying down the hill straight at me", "heading right for us"), or
    None. Why: the lexicon's "come towards" and "come at" hold only with nothing between, and writers
    say the road or bend it comes along first, often with a comma ("came round the corner, straight at
    me"). Not a move sideways ("swerved towards me": no verb of
    travelling), nor coming out of, off or across a place ("came off the pavement towards me"), nor
    along the edge of the road ("riding down the side of the road toward me": it keeps to that edge)."""
    end = _the_ego_after(tokens, i)
    if end is None:
        return None
    opens = i - 1 - _on_its_line_before(tokens, i)  # (the word before "straight at me")
    for k in range(i - 1, max(-1, i - _REACH - 1), -1):
        if k == opens and tokens[k] == ",":
            continue  # ("came round the corner, straight at me": a comma sets off how it comes)
        if tokens[k] in _NOT_ALONG or (tokens[k] in _EDGE and not _a_half_of_the_road(tokens, k)):
            return None  # (not "riding down the side of the road toward me": along the edge, its kerb's)
        verbs = set(lemmas(tokens[k]).get("VERB", ()))
        if verbs & _TRAVEL and (tokens[i] != "for" or "head" in verbs or _on_its_line_before(tokens, i) > 0):
            said_by_the_lexicon = k == i - 1 and bool(verbs & _LEXICON_TOWARDS.get(tokens[i], set()))
            return None if said_by_the_lexicon else end  # (right after "came" the lexicon's "come at" reads it)
    return None


#: Words that say a road user comes at the ego on its very line, not merely from ahead ("straight at
#: me", "right for us", "directly towards my car", "dead at me", "head-on at us").
_ON_ITS_LINE = frozenset({"straight", "right", "directly", "direct", "dead", "square", "squarely", "smack", "head-on"})
#: Words before "right" that make it a side ("on the right towards me", "to my right"), not a manner.
_SIDE_BEFORE = frozenset({"the", "to", "on", "my", "our", "your", "his", "her", "its", "their", "from"})


def _on_its_line_before(tokens: list[str], i: int) -> int:
    """How many words before the preposition at token ``i`` say the road user comes on the ego's very
    line ("straight at", "right for", "head on towards"), 0 where none: "right" only as a manner, not
    a side ("on the right towards me")."""
    before = tokens[i - 1] if i else ""
    if i > 1 and tokens[i - 2 : i] == ["head", "on"]:
        return 2
    if before == "right" and i > 1 and tokens[i - 2] in _SIDE_BEFORE:
        return 0
    return int(before in _ON_ITS_LINE)


def on_the_egos_line(tokens: list[str], i: int, end: int) -> bool:
    """Whether a phrase that says a road user travels at the ego, from token ``i`` (its verb or
    preposition) to ``end``, says it comes on the ego's own line: with "straight", "right",
    "directly" or "dead" before the preposition ("came straight at me", "rode right at us", "heading
    directly for my car") or "head-on" before or after it ("coming head-on at me", "came at us
    head-on"). Why: one in its own lane comes towards the ego and goes by; only one in the ego's lane
    comes at it on its line, so the writer's stress says head-on, the wrong way."""
    at = next((k for k in range(i, end) if tokens[k] in ("towards", "toward", "at", "for")), None)
    ego_end = None if at is None else _the_ego_after(tokens, at)
    if ego_end is None:
        return False  # (not "coming straight at high speed": at no one)
    after = tokens[max(end, ego_end) : max(end, ego_end) + 2]
    return _on_its_line_before(tokens, at) > 0 or after[:1] == ["head-on"] or after[:2] == ["head", "on"]


#: The ego told of in the second or third person, as whom a road user travels at ("towards you",
#: "straight at her") or whose half of the road it is on ("on her side of the road"), with the
#: pronoun a clause of the ego's own would open with (None: "you" is the reader, never a road user).
_EGO_PERSONS = {"you": None, "your": None, "him": "he", "his": "he", "her": "she", "them": "they", "their": "they"}
#: The narrator as a subject: a text told by "I" or "we" names the ego so, and "her" is someone else.
_NARRATOR_SUBJECTS = frozenset({"i", "we"})
#: Words that open a clause: its subject comes after them.
_CLAUSE_OPENERS = frozenset({".", ";", ":", "!", "?", ",", "and", "but", "when", "while", "as", "until", "before"})


def told_of_the_ego(tokens: list[str], j: int) -> bool:
    """Whether the pronoun at token ``j`` ("you", "your"; "her", "him", "them", "his", "their") is the
    ego told of in the second or third person, as the one a road user comes at ("came towards her",
    "riding towards you") or whose half of the road it is on ("on her side of the road"). "You" is the
    reader, the one driving in a text that tells them their own drive. A third-person pronoun is the
    ego only in a text with no narrator of its own ("I", "we": then "her" is someone else), and not
    when its clause's subject is that same person ("she kept to her side of the road": her own), nor
    where a person it fits is named since the ego was ("A woman is walking along the kerb. A cyclist in
    front of her": the woman)."""
    person = _EGO_PERSONS.get(tokens[j], "")
    if person is None:
        return True
    if not person or _NARRATOR_SUBJECTS & set(tokens):
        return False
    k = j - 1
    while k >= 0 and tokens[k] not in _CLAUSE_OPENERS:
        if tokens[k] == person:
            return False  # (its clause's own subject: "he stayed on his side")
        k -= 1
    since = next((e for e in range(j - 1, -1, -1) if tokens[e] == "ego"), -1)
    return not GENDERED.get(_POSSESSIVE_OF.get(person, ""), frozenset()) & set(tokens[since + 1 : j])


#: The possessive of a subject pronoun, as :data:`vocabulary.GENDERED` keys its person nouns.
_POSSESSIVE_OF = {"she": "her", "he": "his"}


#: The object form of a possessive pronoun ("her" side: "towards her").
_OBJECT_OF = {"your": "you", "his": "him", "her": "her", "their": "them"}


def _said_at_before(tokens: list[str], k: int) -> bool:
    """Whether the possessive pronoun at token ``k`` is the ego's because its clause has just said the
    road user comes at that person ("towards her on her side of the road", "at him in his lane"); a
    possessive with nothing such before it is its own subject's ("a cyclist riding on his side of
    the road": the cyclist's own half). "Your" is the reader's, the one driving, anyway."""
    if tokens[k] == "your":
        return True
    start = max(0, k - 6)
    return any(
        tokens[j] in ("towards", "toward", "at") and tokens[j + 1] == _OBJECT_OF.get(tokens[k])
        for j in range(start, k - 1)
    )


#: A half of the road or a lane one owns ("side of the road", "side of the street", "lane", "own lane").
_HALVES = (["side", "of", "the", "road"], ["side", "of", "the", "street"], ["own", "lane"], ["lane"])


def on_the_egos_half(tokens: list[str], i: int, road_user_word) -> int | None:
    """Where a phrase ends that puts a road user on the ego's half of the road or in its lane, with the
    ego told of in the second or third person, starting at token ``i`` ("on her side of the road", "in
    your lane", "on Ruth's side of the road"), or None. Why: the lexicon reads "my side of the road"
    and "in our lane"; a story or a report about someone else says the same of them. The owner is a
    pronoun of the ego (``told_of_the_ego``) or a person's name with "'s" (not a road user's:
    ``road_user_word`` says which words name one, "the van's lane" is its own)."""
    if tokens[i] not in ("on", "in", "down", "along", "up") or i + 2 >= len(tokens):
        return None
    k = i + 1 + (tokens[i + 1 : i + 3] == ["the", "ego"])  # ("on the ego's side": a role the reader named so)
    if tokens[k] in _EGO_PERSONS:
        if not (told_of_the_ego(tokens, k) and _said_at_before(tokens, k)):
            return None
        k += 1
    elif (
        k + 1 < len(tokens)
        and tokens[k + 1] == "'s"
        and tokens[k].isalpha()
        and tokens[k] != "its"
        and not road_user_word(tokens[k])
    ):
        k += 2
    else:
        return None
    half = next((h for h in _HALVES if tokens[k : k + len(h)] == h), None)
    return None if half is None else k + len(half)


#: Words that stress a place exactly ("right in the middle", "slap bang in the middle").
_INTENSIFIERS = frozenset({"right", "smack", "slap", "bang", "dead", "plumb", "slap-bang", "smack-bang"})
#: Words that may follow a bare "down the middle" (not "the middle lane": a lane of its own).
_AFTER_A_BARE_MIDDLE = frozenset({"and", "but", "towards", "toward", "at", "straight", "when", "as", "with", "so"})
#: The whole width a road user may be in the middle of: the road, or a lane when the road has one.
_WIDTHS = frozenset({"road", "lane", "street", "carriageway", "track", "roadway", "lane's"})


def in_the_middle_of_the_road(tokens: list[str], i: int) -> int | None:
    """Where a phrase ends that puts a road user in the middle of the road, starting at token ``i``
    ("in the middle of the road", "right down the middle of the lane", "down the middle"), or None.
    Why: the middle of a two-way road is on the line between its halves, so one said there coming
    towards the ego is partly on the ego's half, as one said over the centre line is. Not "the
    middle lane" (a lane of a road with three) nor "in the middle of the junction" (a place)."""
    j = i
    while j < len(tokens) and tokens[j] in _INTENSIFIERS:
        j += 1  # ("right in the middle", "slap bang in the middle")
    if j == len(tokens) or tokens[j] not in ("in", "down", "along", "up", "through") or j + 3 > len(tokens):
        return None
    k = j + 1 + (tokens[j + 1] == "the")
    if tokens[k : k + 1] != ["middle"]:
        return None
    if tokens[k + 1 : k + 3] != ["of", "the"]:
        bare = k + 1 == len(tokens) or not tokens[k + 1].isalpha() or tokens[k + 1] in _AFTER_A_BARE_MIDDLE
        return k + 1 if tokens[j] in ("down", "along", "up") and bare else None  # ("right down the middle")
    return k + 4 if tokens[k + 3 : k + 4] and tokens[k + 3] in _WIDTHS else None


#: The verbs the lexicon's own oncoming phrases put right before "at" / "towards" ("come at", "drive
#: towards"): with nothing between, the lexicon reads them, verb and all.
_LEXICON_TOWARDS = {"at": {"come"}, "towards": {"come", "drive", "head"}, "toward": {"come"}}
#: Who owns a half of the road ("my side of the road", "their side"), or which half it is ("the wrong side").
_HALF_OWNERS = frozenset({"my", "our", "your", "his", "her", "their", "its", "wrong", "other", "opposite", "own"})


def _a_half_of_the_road(tokens: list[str], k: int) -> bool:
    """Whether "side" at token ``k`` is a half of the road one travels on ("on my side of the road",
    "on our side"), owned or named so, not the road's edge ("down the side of the road"): travelling
    on the ego's half at the ego is coming head-on, and on one's own half is oncoming."""
    return tokens[k] == "side" and k > 0 and tokens[k - 1] in _HALF_OWNERS


#: Places on the road that hide what comes the other way: coming round or over one, a road user
#: comes into sight towards the ego.
_BLIND_PLACES = frozenset(
    {"bend", "corner", "crest", "brow", "hill", "rise", "summit", "hump", "hillcrest", "blind", "curve", "kink"}
)
#: Words between "round"/"over" and such a place ("over the blind crest", "round a sharp bend").
_BEFORE_A_PLACE = frozenset({"the", "a", "that", "this", "blind", "sharp", "tight", "left-hand", "right-hand", "next"})
#: Words after the place that say where it comes from or is, not towards the ego.
_NOT_TOWARDS = frozenset({"from", "behind", "after", "out", "into", "onto", "ahead", "in front"})


#: Words between a subject and its verb ("a van had just come", "the lorry then came").
_BETWEEN_SUBJECT_AND_VERB = frozenset({"just", "then", "suddenly", "had", "has", "have", "was", "were", "is", "'d"})
#: Words before a verb that leave its subject out or make it the narrator's.
_NO_NAMED_SUBJECT = _FIRST_PERSON | {"and", "but", "as", "when", "while", "so", "then", "just", "the", "a", "an"}


def _named_subject_before(tokens: list[str], k: int) -> bool:
    """Whether the verb at token ``k`` has a subject named right before it that is not the narrator
    ("a van came", "the lorry had just come"): not "I came", "we came", nor a verb with no subject
    ("Doing 60, came round the bend and ...": the narrator's)."""
    j = k - 1
    while j >= 0 and tokens[j] in _BETWEEN_SUBJECT_AND_VERB:
        j -= 1
    return j >= 0 and tokens[j].isalpha() and tokens[j] not in _NO_NAMED_SUBJECT


def over_a_blind_place(tokens: list[str], i: int) -> int | None:
    """The end of "round" or "over" at token ``i`` when a verb of coming stands right before it (or
    before a participle of manner: "came flying over") and a place that hides the road beyond
    follows ("came over the crest", "comes round the bend", "coming around a blind corner"): one
    that comes into sight there comes towards the ego, oncoming. None otherwise, and where the words
    after the place say it comes from elsewhere or is behind ("came round the corner from the side
    road", "... behind me"). Only "round"/"over" is read: the place is read on as the road's shape."""
    if tokens[i] not in ("round", "around", "over") or i < 1:
        return None
    k = i - 1
    if tokens[k].endswith("ing") and k > 0 and "come" not in lemmas(tokens[k]).get("VERB", ()):
        k -= 1  # ("came flying over the crest")
    if "come" not in lemmas(tokens[k]).get("VERB", ()) or not _named_subject_before(tokens, k):
        return None
    j = i + 1
    while j < len(tokens) and j < i + 4 and tokens[j] in _BEFORE_A_PLACE:
        j += 1
    if j >= len(tokens) or tokens[j] not in _BLIND_PLACES or j == i + 1 and tokens[j] == "blind":
        return None
    if tokens[j + 1 : j + 2] and tokens[j + 1] in _NOT_TOWARDS:
        return None
    return i + 1


#: Adjectives that say a direction is against the ego's, and the nouns of a direction.
_AGAINST = frozenset({"opposite", "contrary", "other", "reverse", "opposing"})
_DIRECTIONS = frozenset({"direction", "way"})
#: Verbs whose direction is where they turn or look, not where a road user comes from.
_TURNING = frozenset({"turn", "look", "face", "glance", "swerve", "steer", "veer", "point", "pull", "jerk"})


def the_other_direction(tokens: list[str], i: int) -> int | None:
    """Where a phrase that says a road user travels against the ego's direction ends, starting at token
    ``i`` ("in the contrary direction", "in the reverse direction", "driving the other direction"),
    or None. Why: an adjective of opposition and a noun of direction say it in many combinations, more
    than a phrase list holds. Not after a verb of turning or looking ("turned the other direction",
    "looked the other way"): where it turns or looks, no start."""
    n = len(tokens)
    j = i + (tokens[i] in ("in", "from"))
    j += j < n and tokens[j] == "the"
    if j == i or j + 1 >= n or tokens[j] not in _AGAINST or tokens[j + 1] not in _DIRECTIONS:
        return None
    verb = tokens[i - 1] if i else ""
    if set(lemmas(verb).get("VERB", ())) & _TURNING:
        return None
    return j + 2


def approaches_from(tokens: list[str], i: int, key: tuple[str, ...]) -> bool:
    """Whether ``key`` at token ``i`` is a bare verb of approaching followed by where it approaches from
    ("approaching from behind", "approaches from the left", "approached from the side road"): the
    place after "from" says where it starts, and the verb alone says nothing of facing the ego. Why:
    read as "oncoming" (as a bare "an approaching van" is), it put a rider overtaking from behind
    head-on. "Approaching from the front" is the lexicon's own, longer phrase: oncoming."""
    after = tokens[i + len(key) : i + len(key) + 1]
    return len(key) == 1 and after == ["from"] and "approach" in lemmas(key[0]).get("VERB", ())


def kerb_beside_lane(kerb: bool, kerb_side: str | None, came_from: bool, toward: str | None) -> str | None:
    """The side of a kerb said without one that a road user comes off into a lane of a side ("stepped
    off the verge into the right lane", "came out of the hard shoulder into the left lane"): a lane is
    entered from the kerb beside it, so the kerb is on that lane's side. Why: read as a move across
    from the other side, it started on the far kerb. None where a side is said or it did not come
    from the kerb."""
    return toward if kerb and kerb_side is None and came_from and toward in ("left", "right") else None


def overtaker_start(before: str | None, after: str | None, relation: str | None) -> str | None:
    """Where a road user starts whose first act, an overtake (``before``), was read as no more than how
    it gets to its next act (``after``: "overtook me and turned left across my path" is the turn) when
    nothing else places it: behind the ego, the overtake's own start. Why: otherwise the start of the
    act left (a lane beside) is sampled, and it began beside the ego it had yet to pass. An overtake
    still first keeps its start as read (the overtake's own, behind, when none is said)."""
    dropped = before == "overtake" and after != "overtake"
    return "behind" if dropped and relation is None else relation


def beside(lane: str | None, ego_lane: str | None) -> str | None:
    """The side of the ego a road user in ``lane`` is on, when the ego's own lane is said too (lanes
    as left, middle or right): the lane with the lower rank is to the left. Without the ego's lane the
    lane's own side is kept (the ego is then in the other one); the same lane as the ego's, or a middle
    lane with nothing to compare it with, says no side."""
    if lane not in _ORDER:
        return lane
    if ego_lane not in _ORDER:
        return lane if lane != "middle" else None
    if _ORDER[lane] == _ORDER[ego_lane]:
        return None
    return "left" if _ORDER[lane] < _ORDER[ego_lane] else "right"


def on_the_ego_side(words: str) -> bool:
    """Whether a side said as ``words`` puts its road user on that side of the ego ("on my left", "on
    our right"), not on a side of the road it comes from ("from the left", "on the left")."""
    said = words.split()
    return said[:1] == ["on"] and said[1:2] in (["my"], ["our"])


def at_the_edge(edge: str | None, lane_side: str | None, first: str | None) -> bool:
    """Whether a rider said at the edge of a side of the road (``edge``: "riding along the
    right-hand kerb", "hugging the left edge"; not a cycle lane) and in no lane of its own, whose
    first act is a move across ("pulls out", "swerves into my lane"), starts at that edge, beside
    the ego's lane: not in a lane beside it, which a kerb is not."""
    return edge in ("left", "right") and lane_side is None and first == "cut_in"


def kerb_overtaker(relation: str | None, behaviours: list, side_said: bool, passes_another: bool) -> str | None:
    """Where a road user read at the kerb with no side said starts when its first act is overtaking the
    ego ("a kid in the bike lane overtook me", "came along the kerb and overtook me"): behind the ego,
    the overtake's own start. Why: read as the kerb, it started level with the ego at the roadside
    and had nothing to pass. A side said ("in the cycle lane on my left") or someone else overtaken
    ("overtook a parked van") keeps the reading."""
    first = behaviours[0][0] if behaviours else None
    at_kerb = relation in ("roadside_left", "roadside_right")
    return "behind" if first == "overtake" and at_kerb and not side_said and not passes_another else relation


def lane_of_the_followed(lane: str | None, ego_behind: bool, ego_lane: str | None) -> str | None:
    """The side of the lane of a road user the ego follows or is behind ("following a van in the right
    lane", "stuck behind a tractor in the nearside lane"), when the ego's own lane is not said: none,
    since the ego is in that lane too and the road user is ahead in it. Why: read as a lane beside the
    ego's, the lead started level with the ego in the next lane. A lane the ego's own is said apart
    from is compared with it (:func:`beside`) and kept."""
    return None if ego_behind and ego_lane is None and lane in _ORDER else lane


def starts_in_lane(lane: str | None, side: str | None, toward: str | None) -> bool:
    """Whether a lane changer's lane was said as where it starts ("a coach in the left lane moves
    over"): a lane of its own beside the ego's, and no other side said for where it goes."""
    return lane in ("left", "right") and side is None and toward is None


#: Behaviours that end in the ego's lane in front of it: a cut-in, an overtake of the ego.
_ENDS_IN_FRONT = frozenset({"cut_in", "overtake"})


def where_it_ends(relation: object, behaviours: list) -> bool:
    """Whether "ahead" (or "in my lane") said of a road user after it has cut in or overtaken the ego
    says where that behaviour ends, not where it starts ("overtakes me, and once in my lane he
    brakes", "cuts in 10 m ahead"): overtaking the ego, it started behind or beside it."""
    return relation == "ahead" and any(b[0] in _ENDS_IN_FRONT for b in behaviours)


def gap_where_it_ends(behaviours: list) -> str | None:
    """The behaviour a distance said of a road user is the end gap of, when it is said after the road
    user has overtaken the ego ("overtakes me and pulls back in 3 m ahead", "whips back in front of me
    with 20 feet to spare"): the overtake's gap where it cuts back in, not where it starts."""
    return "overtake" if any(b[0] == "overtake" for b in behaviours) else None


#: Words of order before a junction arm ("the first exit", "the next turning on the left").
_ORDER_WORDS = frozenset(
    {"first", "second", "third", "fourth", "fifth", "next", "last", "1st", "2nd", "3rd", "4th", "5th", "final"}
)


def before_the_order(tokens: list[str], i: int) -> str | None:
    """The word before an arm's determiner and word of order ("came off at the first exit": "at"), or
    None where no word of order comes right before the arm at token ``i``. Why: the preposition says
    whether the arm is where a road user comes from or where it acts (:func:`arm_is_where_it_acts`),
    and the word of order stood in its place."""
    if i < 2 or tokens[i - 1] not in _ORDER_WORDS:
        return None
    j = i - 2 if tokens[i - 2] in ("the", "a", "its", "his", "her", "their", "my", "our") else i - 1
    return tokens[j - 1] if j >= 1 else None


def arm_is_where_it_acts(prep: str | None, said: set, behaviours: list) -> bool:
    """Whether a junction arm (or a kerb or crossing) said "at" after what a road user ahead of (or
    behind) the ego does is where it does it ("the car in front slows at the entry", "the van behind me
    stops at the exit", "the scooter ahead stops at the zebra crossing"),
    or said after it has passed the ego is where it goes, not an arm it comes out of: it drives in
    the ego's lane towards that arm."""
    if gap_where_it_ends(behaviours):
        return True  # (having passed the ego: "overtakes me, then takes the next exit": where it goes)
    return prep == "at" and bool(said & {"ahead", "behind"}) and bool(behaviours)


#: What a road user does first that keeps it on the ego's road even when it is said to come from a side.
_ALONG_THE_EGOS_ROAD = frozenset({"overtake", "follow_vehicle", "cut_out", "change_lane", "wrong_way"})


def arm_it_comes_from(junction: bool, came_from: bool, side: str | None, first: str | None, said: set) -> str | None:
    """The junction arm a vehicle or rider comes along when, at a junction, it is said to come *from*
    a side with no lane or kerb named ("a cyclist is coming along from the right", "a van comes from
    my left and slows"): the road on that side, not a lane beside the ego. None where it is not so
    (a lane or the kerb said, "ahead" said of it, or what it does keeps it on the ego's road)."""
    if not (junction and came_from and side in ("left", "right")) or "ahead" in said:
        return None
    return None if first in _ALONG_THE_EGOS_ROAD else f"junction_{side}"


def off_the_kerb(vehicle: bool, came_from: bool, kerb: bool, side: str | None, near: str) -> str | None:
    """Where a walker or rider said to come off or from a kerb, pavement or footway starts ("came off
    the kerb on my left", "rode off the footpath at the exit"): at that roadside, at a junction or a
    roundabout too. The arm said with it ("at the exit", "on the entry") is where it crosses, not a
    road it comes out of; a side road said as its origin is read by the arm rules, not here."""
    if vehicle or not (came_from and kerb):
        return None
    return f"roadside_{side if side in ('left', 'right') else near}"


_TOWARDS = frozenset({"to", "towards", "toward"})


def crossing_from(side: object, words: str, prev: str, after: str, behaviours: list) -> object:
    """The side a crossing starts from when a side is said of it: "runs across to the left", "dashed
    across the road towards the right" say where it goes, so it starts on the other side; any other
    side ("from the left", "on the right", "to the right of the bus": a place) is where it starts."""
    towards = (prev in _TOWARDS or words.split()[0] in _TOWARDS) and after != "of"
    if towards and side in ("left", "right") and behaviours and behaviours[-1][0] == "cross_in_front":
        return "right" if side == "left" else "left"
    return side


def travels_on_the_wrong_side(kind: str, words: str, after: str) -> bool:
    """Whether a road user that rides or drives (``kind``, not on foot) is said to come on or from "the
    wrong side" (``words``) with no place after it ("came from wrong side", "coming wrong side at
    me"): against the traffic, as Indian and other Englishes say the wrong way. A walker "from the
    wrong side", or the wrong side of a place ("the wrong side of the bus"), is the far side."""
    return kind != "pedestrian" and words.split()[-2:] == ["wrong", "side"] and after != "of"


def where_it_goes(side: object, words: str, prev: str, after: str) -> str | None:
    """The side a road user is said to go to ("ran off to the left", "dashed across towards the right
    kerb", "over to the left-hand pavement"), or None: a side after "to" or "towards" is a
    destination, save a place beside another ("to the left of the bus") or the ego ("a kid to my
    left": where it is)."""
    towards = (prev in _TOWARDS or words.split()[0] in _TOWARDS) and after != "of"
    owned = bool(_OWNERS & set(words.split()))
    return side if towards and not owned and side in ("left", "right") else None


def across_from(side: str | None, goes_to: str | None, kerb_side: str | None) -> str | None:
    """The side a crossing starts from: the kerb or lane said as where it is, else the side opposite
    the one it is said to go to ("the dog ran off to the left, across in front of me": from the
    right), read once all is said, as the verb of crossing may come after the side ("ran off to the
    left straight across")."""
    if kerb_side in ("left", "right") or goes_to not in ("left", "right"):
        return side
    if side in (None, goes_to):
        return "right" if goes_to == "left" else "left"
    return side


def origin_lane(origin: str | None, relation: str | None) -> str | None:
    """Where a lane changer starts when its own lane and the lane it moves to are both said ("a coach
    in the middle lane, 25 m ahead, moves over to the right lane", the ego in the left lane): the
    side of its own lane, beside the ego, even when a distance ahead is said too ("ahead" says how
    far along, the lane which lane); None when the lane says no side or the relation stands. (Its own
    lane is relative to the ego's, the lane it moves to is named as the road's: they are not compared.)"""
    if origin in ("left", "right") and relation in (None, "ahead"):
        return origin
    return None


def starts_in_ego_lane(said: set) -> bool:
    """Whether a wrong-way road user starts in the ego's lane facing it, rather than oncoming in its
    own and drifting over: not when it is said to come towards the ego ("comes at me head-on in my
    lane", "over the centre line, coming straight at me"): the writer saw it arrive from the other
    way, and "in my lane" says where it drives into."""
    return "oncoming" not in said


def narrator_lane(clauses: list) -> list:
    """Clauses (link, mentions) with a lane said before anyone is named given to the ego, when the
    first road user named after it has a lane or a place beside the road of its own said right after
    it ("On the motorway in the middle lane doing 60, a lorry in the inside lane wanders across": the
    middle lane is the narrator's; "in lane 1, I saw a lorry in the lay-by on the left": the lay-by is
    the lorry's). One road user does not start in two places, and the writer drives in the first."""
    flat = [m for _, mentions in clauses for m in mentions]
    first = next((k for k, m in enumerate(flat) if m.slot in ("actor", "pronoun", "lane_side")), None)
    if first is None or flat[first].slot != "lane_side":
        return clauses
    after = next((k for k in range(first + 1, len(flat)) if flat[k].slot in ("actor", "pronoun")), None)
    if after is None or flat[after].slot != "actor" or flat[after].value == "ego" or after + 1 >= len(flat):
        return clauses
    if flat[after + 1].slot not in ("lane_side", "place") or flat[first].end == flat[after].start:
        return clauses  # (its lane or place is not said, or the first lane is the road user's: "middle-lane car")
    lane = flat[first]
    ego = replace(lane, slot="actor", value="ego", words="ego", end=lane.start, next_=lane.words.split()[0])
    return [(link, [x for m in mentions for x in ((ego, m) if m is lane else (m,))]) for link, mentions in clauses]


#: Numbers a lane is numbered by ("lane 2", "lane two").
LANE_NUMBERS = {
    **{str(k): k for k in range(1, 7)},
    **{w: k for k, w in enumerate(("one", "two", "three", "four", "five", "six"), 1)},
}


def _lane_number(words: str) -> int | None:
    """The number of a numbered lane mention's words ("lane 2"), None when it is not one or its side
    was said plainly ("lane 1 on the ego's left")."""
    parts = words.split()
    if len(parts) != 2 or parts[0] != "lane":
        return None
    return LANE_NUMBERS.get(parts[1])


def numbered_lanes(clauses: list, left_hand: bool) -> list:
    """Clauses (link, mentions) with numbered lanes compared with the ego's own: lanes are numbered
    from the kerb, so where traffic keeps left a higher number is further right, where it keeps right
    further left ("in lane one ... a van in lane two": the van is on the ego's right in the UK). The
    ego's lane is the one said of it, or the one a road user moves into directly in front of it ("moved
    from lane 2 into lane 1 directly in front of IV"). Then the ego's lane reads as the middle, a road
    user's as the side of it, and the ego's own lane says no side (moving into it is a cut-in).
    Without the ego's number the lanes keep their reading from the kerb."""
    flat = [m for _, mentions in clauses for m in mentions]
    owner: dict[int, object] = {}
    last = None
    for m in flat:
        if m.slot in ("actor", "pronoun"):
            last = m
        elif m.slot == "lane_side" and _lane_number(m.words) is not None:
            owner[id(m)] = last
    ego = next(
        (
            _lane_number(m.words)
            for m in flat
            if id(m) in owner and owner[id(m)] is not None and owner[id(m)].value == "ego" and m.prev not in _INTO
        ),
        None,
    )
    if ego is None:
        ego = next((_lane_number(m.words) for m in flat if id(m) in owner and _in_front_after(flat, m)), None)
    if ego is None:
        return clauses
    out = []
    for link, mentions in clauses:
        kept = []
        for m in mentions:
            number = _lane_number(m.words) if id(m) in owner else None
            if number is None:
                kept.append(m)
                continue
            who = owner[id(m)]
            if who is not None and who.value == "ego":
                kept.append(replace(m, value="middle"))
            elif number != ego:
                kept.append(replace(m, value="right" if (number > ego) == left_hand else "left"))
            # (the ego's own lane: no side beside it, and moving into it is the cut-in's)
        out.append((link, kept))
    return out


def _in_front_after(flat: list, m) -> bool:
    """Whether the numbered lane ``m`` is one moved into directly in front of the ego: "into lane 1"
    followed, before any other road user is named, by "in front (of ...)" or "ahead"."""
    if m.prev not in _INTO:
        return False
    k = flat.index(m)
    for x in flat[k + 1 : k + 4]:
        if x.slot == "relation":
            return x.value == "ahead"
        if x.slot in ("actor", "pronoun") and x.value != "ego":
            return False
    return False


#: Lemmas of the verbs of keeping behind someone.
_FOLLOW = frozenset({"follow", "tail", "trail"})


def _follows(m) -> bool:
    """Whether mention ``m`` is a verb of following: a follow behaviour, or "following" read as a place
    behind someone ("a car following us")."""
    if not (m.slot == "behaviour" and m.value[0] == "follow_vehicle") and not (
        m.slot == "relation" and m.value == "behind"
    ):
        return False
    return any(_FOLLOW & set(lemmas(w).get("VERB", ())) for w in m.words.split())


def ego_follows(clauses: list) -> list:
    """Clauses (link, mentions) with "the ego follows X" read as X ahead of the ego: the ego (named as
    the subject) then a verb of following then a road user ("ego follow a e-scooter", "the EV follows
    a lead vehicle", "ego following a city bus at 20 m"). Why: the verb of following says where the one
    followed is, not what the ego does (the planner drives it); read as the ego's behaviour it was lost,
    read as "following" of the next road user ("a car following us") it put the bus behind. The verb
    becomes "ahead" said of the road user, right after it, as the reader reads "Following a truck".
    The ego may be set off from its verb by a colon or a comma, as a label or an apposition ("Ego:
    following a truck", "Driver statement: following a box van", "the ego, following a tanker,")."""
    out = []
    for link, mentions in clauses:
        kept = list(mentions)
        for k in range(len(kept) - 2):
            ego = kept[k]
            if ego.slot != "actor" or ego.value != "ego":
                continue
            v = k + 1 + _set_off(kept[k + 1])
            if v + 1 >= len(kept) or not _follows(kept[v]):
                continue
            verb, who = kept[v], kept[v + 1]
            if who.slot != "actor" or who.value == "ego":
                continue
            ahead = replace(verb, slot="relation", value="ahead", words="following", start=who.end, prev=who.words)
            kept[v : v + 2] = [who, ahead]
        out.append((link, kept))
    return out


def _set_off(m) -> bool:
    """Whether mention ``m`` is a colon or a comma: what sets a label or an apposition off from its verb."""
    return m.slot == "punct" and m.value in (":", ",")


#: Compass headings in degrees, and the words that say them ("eastbound"; "heading east").
_COMPASS = {"north": 0, "east": 90, "south": 180, "west": 270}
_BOUND = {f"{word}bound": word for word in _COMPASS}
_MOTION = frozenset(
    {"heading", "headed", "travelling", "traveling", "going", "driving", "riding", "proceeding", "moving"}
)
#: Nouns a compass adjective names, not a road user's heading ("in the northbound lane").
_COMPASS_NOUNS = frozenset({"lane", "lanes", "carriageway", "side", "sidewalk", "pavement", "kerb", "footway", "exit"})


def heading_at(tokens: list[str], i: int) -> str | None:
    """The compass heading said at token ``i`` of a road user ("eastbound", "heading north"), or None
    (a compass word naming a lane or a place: "the northbound lane", "from the east sidewalk")."""
    word = tokens[i]
    after = tokens[i + 1] if i + 1 < len(tokens) else ""
    if after in _COMPASS_NOUNS:
        return None
    if tokens[i + 1 : i + 3] == ["in", "the"] and tokens[i + 3 : i + 4] and tokens[i + 3] in _BOUND:  # (the wrong
        return None  # way in the other's lane, "northbound in the southbound lane", which motion.py reads)
    if word in _BOUND:
        return _BOUND[word]
    if word in _COMPASS and i > 0 and tokens[i - 1] in _MOTION:
        return word
    return None


_COMPASS_ADJECTIVES = {"northern": "north", "eastern": "east", "southern": "south", "western": "west"}
#: What a compass origin names: a junction's arm (or road), or the footway along the ego's road.
_ORIGIN_ARMS = frozenset({"arm", "road", "entry", "approach", "side", "street", "junction"})
_ORIGIN_KERBS = frozenset({"footway", "footpath", "pavement", "sidewalk", "kerb", "curb", "verge"})


def compass_origin_at(tokens: list[str], i: int) -> tuple[str, str, int] | None:
    """The compass point a road user is said to come from at token ``i`` ("from the east arm", "from
    the northern footway", "from the west"), what it names ("arm" or "kerb") and where the phrase ends;
    None if no such phrase starts there. Where it lies from the ego depends on the ego's heading
    (:func:`relate_headings`)."""
    if tokens[i : i + 2] != ["from", "the"]:
        return None  # (not "from East Street": a street's name, no compass point)
    k = i + 2
    word = tokens[k] if k < len(tokens) else ""
    point = _COMPASS_ADJECTIVES.get(word) or (word if word in _COMPASS else None)
    if point is None:
        return None
    noun = tokens[k + 1] if k + 1 < len(tokens) else ""
    if noun in _ORIGIN_KERBS:
        return point, "kerb", k + 2
    return point, "arm", k + 2 if noun in _ORIGIN_ARMS else k + 1


def _from_origin(point: int, ego_heading: int, kind: str) -> str | None:
    """Where a road user coming from compass ``point`` starts for an ego heading ``ego_heading``: the
    arm or kerb on the ego's right when the point lies 90 degrees clockwise of its heading (north and
    east: the right, whichever side traffic keeps to), on its left at 270; ahead, the far arm."""
    bearing = (point - ego_heading) % 360
    where = {90: "right", 270: "left"}.get(bearing)
    if where is not None:
        return f"{'roadside' if kind == 'kerb' else 'junction'}_{where}"
    return "junction_opposite" if bearing == 0 and kind == "arm" else None


def relate_headings(clauses: list) -> list:
    """Clauses (link, mentions) with each road user's compass heading made its start relative to the
    ego's heading: the opposite heading is oncoming, a crossing one comes from the junction arm on the
    side it comes from (heading south towards an ego heading east: from the north, on its left); the
    same heading says nothing more. A heading is the road user's named last before it ("V2, eastbound";
    "the path of V1, which was westbound": V1's). Without the ego's heading, headings say nothing."""
    flat = [m for _, mentions in clauses for m in mentions]
    owner: dict[int, object] = {}
    last = None
    for m in flat:
        if m.slot == "actor":
            last = m
        elif m.slot == "pronoun":
            last = None  # (whom a pronoun names is the reader's to say)
        elif m.slot in ("heading", "origin") and last is not None:
            owner[id(m)] = last
    ego = next((m.value for m in flat if m.slot == "heading" and id(m) in owner and owner[id(m)].value == "ego"), None)
    out = []
    for link, mentions in clauses:
        kept = []
        for m in mentions:
            if m.slot == "origin":
                who = owner.get(id(m))
                point, kind = m.value
                where = _from_origin(_COMPASS[point], _COMPASS[str(ego)], kind) if ego and who is not None else None
                if where is not None and who.value != "ego":
                    kept.append(type(m)(**{**m.__dict__, "slot": "relation", "value": where}))
                continue
            if m.slot != "heading":
                kept.append(m)
                continue
            who = owner.get(id(m))
            if ego is None or who is None or who.value == "ego":
                continue
            relation = _from_heading(_COMPASS[str(m.value)], _COMPASS[str(ego)])
            if relation is not None:
                kept.append(type(m)(**{**m.__dict__, "slot": "relation", "value": relation}))
        out.append((link, kept))
    return out


def _from_heading(heading: int, ego_heading: int) -> str | None:
    """Where a road user heading ``heading`` starts for an ego heading ``ego_heading`` (degrees)."""
    turn = (heading - ego_heading) % 360
    if turn == 180:
        return "oncoming"
    if turn == 0:
        return None
    came_from = (heading + 180 - ego_heading) % 360  # the side it comes from, clockwise from the ego's front
    return "junction_right" if came_from == 90 else "junction_left"


def comes_onto_the_road(out_of_place: bool, relation: str | None) -> bool:
    """Whether a road user said to come out of a place beside the road ("rides out of a gate on the
    right") starts at that roadside and comes onto the road: it does not go along the kerb, whatever
    plain verb of going it has ("rides", "goes")."""
    return out_of_place and (relation or "").startswith("roadside")


def along_its_kerb(on_foot: bool, kerb: bool, came_from: bool) -> bool:
    """Whether a walker coming towards the ego at a junction is said on a kerb, verge or pavement and
    not to come from it ("walking along the right verge towards us", "towards me along the pavement"):
    it goes along that kerb, facing the ego, not out of an arm of the junction. (A rider in a bike lane
    towards the ego rides through the junction from the opposite arm.)"""
    return on_foot and kerb and not came_from


def opposite_approach(junction: bool, kind: str, far_side: bool, first: str | None) -> bool:
    """Whether a rider said to come from the other side at a junction ("a cyclist came from the opposite
    side going straight", "a scooter from the other side carried straight on") rides towards the ego
    from the opposite arm, as a vehicle from there does: the side of a junction is an approach to it,
    not a kerb, when the one who comes from it rides and does not cross. A walker from there, or a
    rider said to cross, comes off the far kerb."""
    return junction and far_side and kind in ("bicycle", "e-scooter") and first in (None, "keep_going", "keep_lane")


#: Degree words that say a place is exactly there ("right in front", "just ahead", "directly behind"):
#: they sharpen the place, they never change it.
_DEGREE = frozenset(("right", "just", "directly", "straight", "immediately", "bang", "dead", "smack", "slap"))


def place_after_degree(tokens: list[str], i: int, key: tuple[str, ...], place_at) -> int | None:
    """Where the place phrase ends when ``key`` (a phrase the lexicon lists at ``i``, of another slot)
    is a degree word and the start of a place phrase ("right in front of me", "just ahead", "right
    behind us"), else None. Why: the lexicon lists such phrases whole as a manner or as noise, and the
    longest match then swallowed the place, so "stopped right in front of me" said no start at all
    while "stopped in front of me" is ahead. ``place_at(tokens, k)`` is the length of the place phrase the
    lexicon lists at token ``k`` (0 when none); the place must cover the rest of ``key``."""
    if len(key) < 2 or key[0] not in _DEGREE or tokens[i] != key[0]:
        return None
    used = place_at(tokens, i + 1)
    return i + 1 + used if used and 1 + used >= len(key) else None


#: Particles and prepositions "right" can stress ("pulled right out", "came right up behind me"): before
#: one of these, after a verb that does not say a heading, "right" means "just". ("right across", "right
#: at" are read with the verb before them, by the reader's own list.)
_STRESSED = frozenset(
    {"out", "up", "into", "across", "onto", "through", "over", "past", "under", "off", "down", "along",
     "round", "around", "beside", "alongside", "away", "back", "behind", "toward", "towards", "in", "on", "by"}
)  # fmt: skip
#: Verbs whose "left"/"right" is the way they head ("turned right into", "swerved right onto").
_HEADING = frozenset({"turn", "veer", "swerve", "steer", "swing", "bear", "head", "move", "merge", "drift", "keep"})
#: Verbs whose side before "across" is the way the move across goes ("cut right across my lane").
_CUT_ACROSS = frozenset({"cut"})
#: Words before a side that make it a place ("to the right", "on my right", "from right across").
_SIDE_OPENERS = _DETERMINERS | _OPENING | {"'s", "hand", "far", "hard", "sharp", "slightly"}
#: Subjects and perfect auxiliaries "left" the verb follows ("as we left", "she had just left").
_LEAVERS = frozenset(
    {"i", "we", "he", "she", "they", "you", "it", "had", "has", "have", "'d", "'ve", "just", "already", "then",
     "finally", "recently", "who", "that"}
)  # fmt: skip
_LEFT_OBJECTS = _DETERMINERS | {"me", "us", "him", "them", "it", "home", "work", "town"}


def not_a_side(tokens: list[str], i: int) -> bool:
    """Whether "left" or "right" at token ``i`` is another word than a side. Why: both are common words
    of other classes, and read as a side they place a road user on the wrong side or turn the ego:

    - "right" stressing a particle or preposition ("pulled right out", "came right up behind me", "ran
      right past my mirror", "rode right across the front of my car"): unless a determiner or
      preposition says it is a place ("to the right across the road") or the verb before says a
      heading ("turned right into the side road");
    - "left" the past of "leave", after a subject or a perfect auxiliary and before what was left ("as we
      left the roundabout", "she had just left the car park"), never after a determiner ("on the left
      the van") or a heading verb ("turn left the moment ...")."""
    word = tokens[i]
    prev = tokens[i - 1] if i else ""
    nxt = tokens[i + 1] if i + 1 < len(tokens) else ""
    if word == "right":
        if nxt not in _STRESSED or not prev or prev in _SIDE_OPENERS:
            return False
        heading = _HEADING | _CUT_ACROSS if nxt == "across" else _HEADING
        return not (set(lemmas(prev).get("VERB", ())) & heading)
    if word == "left":
        return prev in _LEAVERS and nxt in _LEFT_OBJECTS
    return False


#: The ends of a vehicle a road user can go into from behind ("into the rear of my car", "the back of us").
_REAR = frozenset({"rear", "back"})


def into_the_ego_rear(clauses: list) -> list:
    """Clauses (link, mentions) with "into the rear/back of" the ego said of a road user moved right
    after that road user, so it is the first place said of it. Why: going into the ego's rear says
    where it started (behind), even when it was first said to travel "in the same direction" (read as
    ahead) or the start is said only in this later phrase; the rear of another road user ("went into
    the back of it", "the rear of the van") says nothing of where that one starts."""
    out = []
    for link, mentions in clauses:
        kept = list(mentions)
        for k in range(1, len(kept) - 1):
            rear, owner = kept[k], kept[k + 1]
            if rear.slot != "relation" or rear.value != "behind" or rear.words not in _REAR:
                continue
            if rear.prev != "into" or rear.next_ != "of" or owner.slot != "actor" or owner.value != "ego":
                continue
            who = _mover_before(kept, k)
            if who is None:
                continue
            del kept[k]
            kept.insert(who + 1, rear)
        out.append((link, kept))
    return out


def _mover_before(mentions: list, k: int) -> int | None:
    """The index of the road user that goes into the ego's rear at ``k``: the nearest before it, past
    the ego named as an object ("going the same way as us"); None when the ego is the one that acts
    ("we went into the back of ...")."""
    for j in range(k - 1, -1, -1):
        m = mentions[j]
        if m.slot != "actor":
            continue
        if m.value != "ego":
            return j
        if mentions[j + 1].slot in ("behaviour", "intent", "ego_verb"):
            return None
    return None


def owners_side(m, owner) -> bool:
    """Whether side mention ``m`` says where the clause's road user comes from, seen from a road user
    named as its owner just before it ("from the Civic's right", "from V1's left"): the side of the frame
    that road user gives, not the owner's own place. (On a side, "on the lorry's left", is a place
    beside the owner, and may be where the owner is too: that keeps its reading.)"""
    return (
        m.slot == "side"
        and m.prev == "'s"
        and owner is not None
        and owner.slot == "actor"
        and owner.prev == "from"
        and owner.value != "ego"
        and owner.end == m.start - 1
    )


def _a_verb_form(word: str) -> bool:
    """Whether ``word`` is an inflected verb: a participle or past ("coming", "approaching", "came"),
    not a noun that is also a verb ("the bus", "the buses")."""
    pos = lemmas(word)
    verbs = pos.get("VERB", ())
    return bool(verbs) and word not in verbs and ("NOUN" not in pos or word.endswith("ing"))


def crosses_from_beside_a_landmark(m, subject_acts: list, landmark_named_after: bool) -> bool:
    """Whether side mention ``m`` ("from the left") says where the clause's subject crosses from rather
    than where the road user named last is: the subject's latest act a crossing, the other named after
    that verb as its landmark ("a woman crossed in front of the bus from the left"). Why: "from the
    left" goes with the verb of motion; the vehicle she crosses before is where she passes, and read as
    the vehicle's, her own side was lost and she came from the near kerb. A side right after a verb of
    the landmark's own is the landmark's ("in front of the van coming from the left": the van comes)."""
    return (
        m.slot == "side"
        and m.words.split()[0] == "from"
        and not _a_verb_form(m.prev)
        and landmark_named_after
        and bool(subject_acts)
        and subject_acts[-1][0] == "cross_in_front"
    )
