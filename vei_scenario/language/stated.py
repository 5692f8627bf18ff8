"""What a description states as a whole, read from its normalised text (contractions as "did not",
numbers before a unit as digits): the lanes of its road, a clock time, heavy rain. The traffic is read
by :mod:`vei_scenario.language.settings`, the outcome by :mod:`vei_scenario.language.outcome`
(``stated_outcome`` here is that reading, under the name the reader has always imported).
"""

from __future__ import annotations

import re

from vei_scenario.language.outcome import stated_intent as stated_outcome

__all__ = ["stated_outcome", "stated_lanes", "stated_clock", "stated_heavy_rain"]

_WORD_NUMBERS = {"one": 1, "two": 2, "three": 3, "four": 4, "1": 1, "2": 2, "3": 3, "4": 4}
_N = r"(one|two|three|four|[1-4])"
#: One word may stand between a count and its lanes ("one traffic lane each way", "two narrow lanes per
#: direction"), unless it makes them lanes beside the carriageway (a cycle lane, a bus lane, parking).
_LANE_MODIFIER = r"(?: (?!cycle |bike |bus |parking |tram )[a-z]+(?= lanes?\b))?"
_EACH_WAY = re.compile(
    rf"{_N}(?:{_LANE_MODIFIER}[ -]lanes?)? "
    r"(?:each way|in each direction|per direction|each direction|in both directions|for each side|"
    r"on each side|each side|per side|a side|either way|in either direction|for each direction|in every direction)"
)
_OF_N = re.compile(
    r"\b(?:middle|inside|outside|left|right|nearside|offside|centre|center|fast|slow) lane of " + _N + r"\b"
)
_ONE_WAY = re.compile(r"\bone[ -]way (?:street|road)[^.;]{0,25}?\b" + _N + r" lanes\b")
#: A road "two-lane" with traffic both ways: one lane each way (unless it is a motorway, dual carriageway or
#: roundabout, which traffic uses one way).
_TWO_LANE_ROAD = re.compile(
    r"\b(?:two|2)[ -]lane (?!motorway|highway|freeway|expressway|dual|roundabout|approach|slip|exit|entry|on-ramp"
    r"|off-ramp|ramp|carriageway)"
)  # (an approach, a slip road, a ramp, a carriageway: one direction's lanes)
_DIVIDED = re.compile(r"\b(?:motorway|highway|freeway|expressway|autobahn|dual carriageway|one[ -]way)\b")


#: "a 4-lane divided highway": lanes of both directions together on a road divided in two.
_DIVIDED_TOTAL = re.compile(
    r"\b(four|six|eight|4|6|8)[ -]lanes? (?:divided|dual)(?: carriageway)? ?"
    r"(?:highway|freeway|motorway|road|expressway)?"
)
_TOTAL = {"four": 4, "six": 6, "eight": 8, "4": 4, "6": 6, "8": 8}


#: A hyphenated compound of lanes and their direction ("one-lane-each-way", "two-lanes-per-direction"):
#: read as its words.
_LANE_COMPOUND = re.compile(r"\b[a-z0-9]+-lanes?-(?:each|per|in|either|a|every)(?:-[a-z]+)+\b")


def stated_lanes(text: str) -> int | None:
    """Lanes per direction a normalised, lowercased description states, where the reader's words do
    not settle it: "three lanes each way", "the middle lane of three", "a one-way street with two
    lanes", and "a two-lane road" (one lane each way on a road that is not a motorway)."""
    text = _LANE_COMPOUND.sub(lambda m: m.group(0).replace("-", " "), text)  # ("one-lane-each-way road")
    for pattern in (_EACH_WAY, _OF_N, _ONE_WAY):
        m = pattern.search(text)
        if m is not None:
            return _WORD_NUMBERS[m.group(1)]
    m = _DIVIDED_TOTAL.search(text)
    if m is not None:
        return _TOTAL[m.group(1)] // 2
    if _TWO_LANE_ROAD.search(text) and not _DIVIDED.search(text):
        return 1
    return None


#: A clock "hh : mm"; not the number of a question and its answer ("Q9: 10", a survey's or a form's
#: question 9 answered 10), nor a figure of speed or distance.
_CLOCK = re.compile(r"(?<!\bq )\b([01]?\d|2[0-3]) : ([0-5]\d)\b(?! (?:km/h|mph|m/s|m)\b)(?: (am|pm)\b)?")
_HOUR = re.compile(r"\b(1[0-2]|0?[1-9]) (am|pm)\b")


def stated_clock(text: str) -> str | None:
    """A time of day written as a clock ("at approximately 22:40 hrs": "22:40", "6:40 pm": "18:40",
    "6 am": "06:00"), from the reader's tokens joined by spaces ("22 : 40")."""
    m = _CLOCK.search(text)
    if m is not None:
        hour, minute, half = int(m.group(1)), m.group(2), m.group(3)
    else:
        m = _HOUR.search(text)
        if m is None:
            return None
        hour, minute, half = int(m.group(1)), "00", m.group(2)
    if half is not None and hour <= 12:  # (12 am is midnight, 12 pm noon)
        hour = hour % 12 + (12 if half == "pm" else 0)
    return f"{hour:02d}:{minute}"


_HEAVY_RAIN = re.compile(
    r"\b(?:rain|rains|raining|rained) (?:very |really )?(?:strong|strongly|hard|heavily|heavy|a lot|cats and dogs)\b"
    r"|\b(?:pouring|bucketing|lashing) (?:with |down )?(?:rain)?"
)


def stated_heavy_rain(text: str) -> bool:
    """Whether the rain is said to be heavy in words the weather words do not hold ("is raining strong")."""
    return _HEAVY_RAIN.search(text) is not None
