"""What a description states as a whole, read from its normalised text (contractions as "did not",
numbers before a unit as digits): the outcome it asks for, and the lanes of its road.

The outcome: a collision ("was struck", "we want an impact", "there is the
crash"), a near miss ("missed it by inches", "stopped 1 m short", "didn't hit him", "no contact was
made") or a safe pass ("passes safely", "without problem", "uneventful"), read from the whole text
after its words are normalised (contractions as "did not").

A collision word counts only when nothing denies or hedges it just before ("must not hit", "almost
hit", "to avoid a collision"): a denied collision after hard braking is the near miss people mean
when they say it. A text that states none of these has no intent; nothing is assumed.
"""

from __future__ import annotations

import re

_COLLISION = re.compile(
    r"(?<!time-to-)(?<!time to )(?<!near-)(?<!near )"  # ("time-to-collision", "near-collision": none)
    r"\b(?:hit|hits|hitting|struck|strikes|striking|collid\w*|collision|crash|crashes|crashed|crashing|"
    r"impact|rear-end\w*|rear end\w*|made contact|make contact|makes contact|ran into|runs into|run into|"
    r"smash\w*|knock\w* (?:down|over)|thump|thrown onto|thrown over|ploughs? into|plowed into|slams? into|"
    r"slammed into|ran over|runs over|run over|t-bone\w*|sideswip\w*|clipped|clips|contact|tapped|taps|touch|touches|"
    r"touched|bumped|bumps|bump into|knocked|(?:went|go|goes|going|drove|drive|drives|ran|run|runs) into "
    r"(?:the (?:back|side|rear) of (?:it|him|her|them|the \S+|his \S+|her \S+)|"
    r"(?:its|his|her|their) (?:rear|back|side)|it|him|her|them))\b"
    r"(?! (?:the |his |her |my |our )?brakes?\b| point| barrier| warning)"
)
#: Words that deny or hedge a collision word a few words after them.
_DENY = re.compile(
    r"\b(?:not|never|no|without|avoid|avoids|avoided|avoiding|almost|nearly|narrowly|barely|prevent\w*|"
    r"would have|could have|nothing|nobody|no one|neither)\b(?:\s+[^\s,]+){0,3}\s*$"
)
_NEAR = re.compile(
    r"\b(?:almost|nearly|narrowly|near miss|near-miss|near-collision|near collision|"
    r"close call|just in time|by a whisker|by inches|by an inch|"
    r"hair's breadth|only just|just missed|just misses|barely missed|barely misses|"
    r"missed (?:it|him|her|them|us|me|the \S+|his \S+|her \S+|their \S+) by|"
    r"stopp?(?:ed|s|ing)? [^.;]{0,40}(?:short of|from (?:it|him|her|them|the|his|her))|"
    r"(?:metres?|meters?|m|inches) short|made it across|no contact|emergency stop|"
    r"(?:he|she|it|they|just) miss(?:es|ed)?|miss(?:es|ed)? (?:us|me|him|her|it|them) by|"
    r"to miss (?:us|me|him|her|it|them)|"
    r"by a hair|by a whisker|"
    r"by (?:centimetres|centimeters|millimetres|millimeters|a few (?:cm|centimetres|inches|feet))|"
    r"stops? in time|stopped in time|(?:at the )?last (?:second|moment|minute)|"
    r"(?:a|about a|1|one|half a|0\.5) (?:metre|meter|m|foot|yard) to spare|"
    r"(?:was|were|is) (?:a bit |very |really |pretty |quite )?(?:tight|close)|but (?:very |really |quite )?close|"
    r"stopp?(?:ed|s|ing)? (?:about |only |just )?\d+(?:\.\d+)? (?:m|metres?|meters?|feet|foot) (?:off|from|short))"
)
#: A sentence that is only the outcome, as a commentary says it ("Close!", "Clean.").
_NEAR_SENTENCE = re.compile(r"(?:^|[.!?;] )(?:very |so |too |that was )?close (?:one |call |shave )?(?:[.!?]|$)")
_SAFE_SENTENCE = re.compile(r"(?:^|[.!?;] )(?:all )?clean (?:[.!?]|$)")
_SAFE = re.compile(
    r"\b(?:safely|safe distance|without (?:any )?(?:problems?|conflict|incident|drama|issue|issues)|"
    r"no problems?|no drama|no conflict|no incident|uneventful|plenty of (?:room|space)|lots of (?:room|space)|"
    r"enough (?:room|space)|comfortably|let us go|lets us go|let me go|lets me go|gets through safely|"
    r"lets? the ego (?:go|pass|through|by|past)|"
    r"(?:loads|lots|heaps|tons|a lot) of (?:room|space)|room to spare|ample (?:margin|room|space|clearance)|"
    r"clearance (?:exceeds|of more than|above)|(?:all|totally|completely|everything|it was|was) fine|all good|"
    r"nothing (?:else )?(?:happened|happening|happens|happen)|nothing dramatic|"
    r"(?:pass|passes|passed|goes|went) (?:\S+ )?fine|nobody close|no one close|"
    r"pass(?:es|ed)? (?:him|her|it|them|the \S+ )?wide)"
)


def stated_outcome(text: str) -> str | None:
    """``collision``, ``near_miss``, ``safe`` or None, from normalised, lowercased ``text``."""
    positive = denied = False
    for m in _COLLISION.finditer(text):
        start = max(text.rfind(".", 0, m.start()), text.rfind(";", 0, m.start()), 0)
        before = text[start : m.start()]
        if _DENY.search(before):
            denied = True
        else:
            positive = True
    if positive:
        return "collision"
    near = _NEAR.search(text) is not None or _NEAR_SENTENCE.search(text) is not None
    if (_SAFE.search(text) or _SAFE_SENTENCE.search(text)) and not near:
        return "safe"
    if near or denied:
        return "near_miss"
    return None


_WORD_NUMBERS = {"one": 1, "two": 2, "three": 3, "four": 4, "1": 1, "2": 2, "3": 3, "4": 4}
_N = r"(one|two|three|four|[1-4])"
_EACH_WAY = re.compile(
    _N + r"(?:[ -]lanes?)? (?:each way|in each direction|per direction|each direction|in both directions|for each side|"
    r"on each side|each side|per side|a side|either way|in either direction|for each direction|in every direction)"
)
_OF_N = re.compile(
    r"\b(?:middle|inside|outside|left|right|nearside|offside|centre|center|fast|slow) lane of " + _N + r"\b"
)
_ONE_WAY = re.compile(r"\bone[ -]way (?:street|road)[^.;]{0,25}?\b" + _N + r" lanes\b")
#: A road "two-lane" with traffic both ways: one lane each way (unless it is a motorway, dual carriageway or
#: roundabout, which traffic uses one way).
_TWO_LANE_ROAD = re.compile(r"\b(?:two|2)[ -]lane (?!motorway|highway|freeway|expressway|dual|roundabout)")
_DIVIDED = re.compile(r"\b(?:motorway|highway|freeway|expressway|autobahn|dual carriageway|one[ -]way)\b")


#: "a 4-lane divided highway": lanes of both directions together on a road divided in two.
_DIVIDED_TOTAL = re.compile(
    r"\b(four|six|eight|4|6|8)[ -]lanes? (?:divided|dual)(?: carriageway)? ?"
    r"(?:highway|freeway|motorway|road|expressway)?"
)
_TOTAL = {"four": 4, "six": 6, "eight": 8, "4": 4, "6": 6, "8": 8}


def stated_lanes(text: str) -> int | None:
    """Lanes per direction a normalised, lowercased description states, where the reader's words do
    not settle it: "three lanes each way", "the middle lane of three", "a one-way street with two
    lanes", and "a two-lane road" (one lane each way on a road that is not a motorway)."""
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


_CLOCK = re.compile(r"\b([01]?\d|2[0-3]) : ([0-5]\d)\b(?! (?:km/h|mph|m/s|m)\b)(?: (am|pm)\b)?")
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


_DENSITY = re.compile(
    r"\b(?:traffic|motorway|road|roads|street|streets|highway) (?:is|was|were|being) (?:very |quite |fairly |pretty |"
    r"really )?(light|moderate|heavy|busy|quiet|dense|sparse|empty)\b"
)
_DENSITY_WORDS = {"light": "light", "sparse": "light", "moderate": "moderate", "heavy": "heavy", "busy": "heavy",
                  "dense": "heavy", "quiet": "light", "empty": "none"}  # fmt: skip


def stated_density(text: str) -> str | None:
    """Background traffic said of the road ("the motorway was heavy", "traffic was moderate")."""
    m = _DENSITY.search(text)
    return None if m is None else _DENSITY_WORDS[m.group(1)]


_HEAVY_RAIN = re.compile(
    r"\b(?:rain|rains|raining|rained) (?:very |really )?(?:strong|strongly|hard|heavily|heavy|a lot|cats and dogs)\b"
    r"|\b(?:pouring|bucketing|lashing) (?:with |down )?(?:rain)?"
)


def stated_heavy_rain(text: str) -> bool:
    """Whether the rain is said to be heavy in words the weather words do not hold ("is raining strong")."""
    return _HEAVY_RAIN.search(text) is not None
