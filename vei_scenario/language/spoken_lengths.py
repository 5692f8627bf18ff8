"""Lengths said without digits, said again in digits: "a metre", "half a metre", "a couple of feet", "a
foot and a half", "a car length", "30 cm".

People say how near something came in words far more often than in figures ("stopped a metre from
him", "missed my bonnet by a couple of feet", "with half a metre to spare", "maybe 20cm"). The reader
reads a distance where a number stands before its unit, so these say the same length as a number
before the unit the reader knows (feet and yards then become metres as written figures do, and a
car's length as "2 car lengths" does). An article before a unit of length is the number one in
English; "half a" is a half, "a couple of" two, "and a half" adds a half. "A foot" is a length only
where it is said as one (after "by", a hedge or a bound, or before a word of how far: "a foot from
him", "about a foot", "a foot to spare"), not the foot on a pedal or on the ground; "a meter" is a
metre only as a unit ("a parking meter" is a thing, and "a metre-wide lane" a size).
"""

from __future__ import annotations

import re

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

_HALF_A = re.compile(rf"\bhalf an? ({_UNITS}|foot)\b(?!-)")
_A_COUPLE_OF = re.compile(rf"\ba couple (?:of )?({_UNITS}|feet)\b(?!-)")
_AND_A_HALF = re.compile(rf"\b(?:a|one) ({_UNITS}|foot) and a half\b")
_AN_ARTICLE = re.compile(r"\b(?:a|one) (metre|meter|car length)\b(?!-)")  # ("a yard" is also a place)
_A_FOOT = re.compile(rf"\b(?:((?:{_FOOT_AFTER}) )a foot\b(?!-)|a foot(?= (?:{_FOOT_BEFORE})\b))")
_CENTIMETRES = re.compile(r"\b(\d+(?:\.\d+)?)\s*(?:cm|cms|centimet(?:re|er)s?)\b")


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
    text = _AN_ARTICLE.sub(lambda m: f"1 {m.group(1)}", text)
    text = _A_FOOT.sub(lambda m: f"{m.group(1) or ''}1 foot", text)
    return _CENTIMETRES.sub(lambda m: f"{float(m.group(1)) / 100:g} m", text)
