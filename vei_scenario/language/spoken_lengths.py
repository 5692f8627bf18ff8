"""Lengths said without digits, said again in digits: "a metre", "half a metre", "a couple of feet", "a
foot and a half", "a car length", "30 cm".

People say how near something came in words far more often than in figures ("stopped a metre from
him", "missed my bonnet by a couple of feet", "with half a metre to spare", "maybe 20cm"). The reader
reads a distance where a number stands before its unit, so these say the same length as a number
before the unit the reader knows (feet and yards then become metres as written figures do, and a
car's length as "2 car lengths" does). An article before a unit of length is the number one in
English; "half a" is a half, "a couple of" two, "and a half" adds a half. "A foot" is a length only
where it is said as one (after "by", a hedge or a bound, or before a word of how far: "a foot from
him", "about a foot", "a foot to spare"), not the foot on a pedal or on the ground ("took a foot off
the brake") nor one naming a thing with the noun after it ("a foot bridge", "a foot passenger"); "a
meter" is a metre only as a unit ("a parking meter" and "a meter maid" are things, and "a metre-wide
lane" a size). "One" is already "1" here ("one car length and a half"), and "1,5 cm" a decimal comma.
"""

from __future__ import annotations

import re

from vei_scenario.language.lemmas import lemmas

#: Units of length an article may stand for one of, as the reader reads them after a number.
_UNITS = r"(?:metres?|meters?|yards?|car lengths?)"
#: Their plurals, for "a metre and a half": one and a half of them.
_PLURAL = {"metre": "metres", "meter": "meters", "yard": "yards", "car length": "car lengths", "foot": "feet"}
#: Words before "a foot" that make it a length: a measure's preposition, a hedge or a bound.
_FOOT_AFTER = (
    r"by|within|than|about|around|roughly|approx|approximately|maybe|perhaps|like|literally|only|just|barely"
    r"|hardly|scarcely|nearly|almost|under|over|least|most|some|good|mere|guess|say"
)
#: Words after "a foot" that make it a length: where from, how far, how much was left.
_FOOT_BEFORE = (
    r"from|off|short|away|ahead|behind|in front|of (?:me|us|him|her|them|it|my|our|his|its|their|the)\b"
    r"|to spare|spare|clear|apart|between|at most|max|tops|or two|or so|back|gap|clearance"
)

#: A foot off a pedal is the foot itself ("took a foot off the brake"); a word of how far after "a foot"
#: or "a meter" makes it a length even where that word is a noun ("a foot gap").
_OFF_A_PEDAL = re.compile(r" off (?:the |my |his |her |their )?(?:brakes?|pedal|gas|accelerator|throttle|clutch)\b")
_HOW_FAR = re.compile(rf" (?:{_FOOT_BEFORE})\b")

_HALF_A = re.compile(rf"\bhalf an? ({_UNITS}|foot)\b(?!-)")
_A_COUPLE_OF = re.compile(rf"\ba couple (?:of )?({_UNITS}|feet)\b(?!-)")
#: ("one" is already "1" when lengths are read: "one car length and a half")
_AND_A_HALF = re.compile(rf"(?:\ba|(?<![\d.,])1) ({_UNITS}|foot) and a half\b")
_AN_ARTICLE = re.compile(r"\ba (metre|meter|car length)\b(?!-)")  # ("a yard" is also a place)
_A_FOOT = re.compile(rf"\b(?:((?:{_FOOT_AFTER}) )a foot\b(?!-)|a foot(?= (?:{_FOOT_BEFORE})\b))")
_CENTIMETRES = re.compile(r"(?<![\w.,])(\d+(?:[.,]\d+)?)\s*(?:cm|cms|centimet(?:re|er)s?)\b")


def _a_thing(m: re.Match[str]) -> bool:
    """Whether the "a foot" or "a meter" just matched is a thing, not a length: a foot off a pedal, or
    a noun said after it that makes it part of the name of a thing ("a foot passenger", "a foot
    bridge", "a meter maid"), unless that word says how far ("a foot gap", "a foot clearance")."""
    rest = m.string[m.end() :]
    if _OFF_A_PEDAL.match(rest):
        return True
    word = re.match(r" ([a-z]+)", rest)
    if word is None or _HOW_FAR.match(rest):
        return False
    read = lemmas(word.group(1))
    return "NOUN" in read and not {"ADJ", "ADV"} & set(read)


def _singular(unit: str) -> str:
    return {"feet": "foot"}.get(unit, unit.removesuffix("s") if unit.endswith(("metres", "meters", "yards")) else unit)


def _plural(unit: str) -> str:
    unit = _singular(unit)
    return _PLURAL.get(unit.removesuffix("s"), _PLURAL.get(unit, unit))


def in_digits(text: str) -> str:
    """``text`` (lowercased) with every length said without digits said with them ("stopped a metre
    from him" → "stopped 1 metre from him", "half a metre" → "0.5 metre", "20cm" → "0.2 m")."""
    text = _AND_A_HALF.sub(lambda m: f"1.5 {_plural(m.group(1))}", text)
    text = _HALF_A.sub(lambda m: f"0.5 {_singular(m.group(1))}", text)
    text = _A_COUPLE_OF.sub(lambda m: f"2 {_plural(m.group(1))}", text)
    text = _AN_ARTICLE.sub(lambda m: m.group() if m.group(1) == "meter" and _a_thing(m) else f"1 {m.group(1)}", text)
    text = _A_FOOT.sub(lambda m: m.group() if _a_thing(m) else f"{m.group(1) or ''}1 foot", text)
    return _CENTIMETRES.sub(lambda m: f"{float(m.group(1).replace(',', '.')) / 100:g} m", text)
