"""Units and styles people write in, said again in the few forms the reader reads: before a
description is cut into words, numbers written as words become digits where a unit follows
("forty miles an hour" → "40 mph"), spelt-out units become their symbols ("kilometres per hour" →
"km/h", "metres per second" → "m/s"), the narrator's vehicle of a police or insurance narrative
("Vehicle 1", "V1", "Unit 1", "D1", "the insured", "my client") becomes the ego, and the other
party ("V2, a Vauxhall Corsa, ...") becomes the road user its apposition names. Euro NCAP test codes
are read by :mod:`vei_scenario.language.ncap`.

Every rewrite is a regular expression over the lowercased text, so what it does to a description is
the same for every description; words it does not rewrite reach the reader unchanged (and are
reported as not used when the reader cannot place them).
"""

from __future__ import annotations

import re
import unicodedata
from functools import lru_cache

from vei_scenario.language import lexicon as L
from vei_scenario.language import quantities as Q
from vei_scenario.language import spoken_lengths
from vei_scenario.language.function_words import BE, CLAUSE_BREAKS, DETERMINERS, PHRASE_ENDS
from vei_scenario.language.imperative import imperative_as_ego
from vei_scenario.language.lemmas import english, lemmas
from vei_scenario.language.lettered_parties import lettered_parties
from vei_scenario.language.located_first import said_in_order

_ONES = {
    "zero": 0, "one": 1, "two": 2, "three": 3, "four": 4, "five": 5, "six": 6, "seven": 7, "eight": 8,
    "nine": 9, "ten": 10, "eleven": 11, "twelve": 12, "thirteen": 13, "fourteen": 14, "fifteen": 15,
    "sixteen": 16, "seventeen": 17, "eighteen": 18, "nineteen": 19, "a": 1, "an": 1,
}  # fmt: skip
_TENS = {"twenty": 20, "thirty": 30, "forty": 40, "fourty": 40, "fifty": 50, "sixty": 60, "seventy": 70,
         "eighty": 80, "ninety": 90}  # fmt: skip
#: The English number words: words, never a slip of another ("seven" is not "even").
NUMBER_WORDS = frozenset(w for w in [*_ONES, *_TENS, "hundred"] if w not in ("a", "an"))
_NUMBER_WORD = "|".join(sorted([w for w in _ONES if w not in ("a", "an")] + list(_TENS) + ["hundred"], key=len)[::-1])
#: A number in words: "forty", "forty-five", "a hundred and ten", "one hundred", "hundred".
_NUMBER_SAID = rf"(?:(?:a|an|{_NUMBER_WORD})[\s-]+)?(?:{_NUMBER_WORD})(?:(?:[\s-]+(?:and[\s-]+)?)(?:{_NUMBER_WORD}))*"
_NUMBER = re.compile(rf"\b({_NUMBER_SAID})\b")
#: Units after which a number in words is a quantity (its unit words as the reader reads them).
_UNIT_AFTER = re.compile(
    r"\s*(?:-\s*)?(km/h|kph|kmh|mph|m/s|miles?\b|kilomet(?:er|re)s?\b|km\b|met(?:er|re)s?\b|m\b|seconds?\b|s\b"
    r"|second\b|lanes?\b|car lengths?\b|k(?:'s|s)?\b|klicks?\b|clicks\b|feet\b|ft\b|yards?\b|yds?\b|foot\b)"
)
#: Words after which a bare number is a speed ("doing like thirty", "Ego at forty", "sat on seventy"): the
#: reader reads a bare number after "at", "doing", "about" as km/h, and one after "on" where a verb of
#: keeping a speed says so.
_SPEED_BEFORE = re.compile(r"\b(at|doing|about|like|going|around|roughly|approximately|on)\s+$")
#: A guess between a verb of going and a number in words ("doing, I don't know, forty", "going probably
#: sixty"), or the limit said before its number ("doing the limit, seventy"): the number is a speed.
_GUESS_BEFORE = re.compile(
    r"\b(?:(?:at|doing|going|driving|travell?ing|moving)[\s,]+(?:i\s+(?:think|reckon|guess|'?d\s+say|would\s+say"
    r"|do(?:n'?t|\s+not)\s+know|dunno)|probably|maybe|perhaps|possibly|say|what|uh|um|er)|limit)[\s,(-]+$"
)
#: "<number> speed" said as a speed ("sixty speed only"), not a thing of speeds ("a forty speed limit").
_SPEED_AFTER = re.compile(r"\s+speed\b(?!\s*(?:limit|bump|hump|camera|zone|sign|trap|gun|breaker|-))")
#: The same words, then a number and "or"/"to" or a comma ("doing fifty or sixty", "at thirty to forty",
#: "doing ten, fifteen tops"): the second number of a choice of speeds is a speed as the first is.
_CHOICE_BEFORE = re.compile(
    rf"\b(?:at|doing|about|like|going|around|roughly|approximately)\s+(?:\d+|{_NUMBER_WORD})(?:-[a-z]+)?"
    r"(?:\s+(?:or|to)|\s*,)\s+$"
)
#: A verb of going, then hedges only ("doing like twelve", "going about ten"): a number in words after it
#: is a speed down to a walker's or a scooter's where its phrase ends as a speed's does
#: (:data:`_SLOW_SPEED_ENDS`); after "at" or a hedge alone one under fifteen may be a clock's hour or a
#: count ("at ten", "like two").
_GOING_HEDGED = re.compile(
    r"\b(?:doing|going|driving|travell?ing|riding|moving|cruising)\s+(?:(?:about|around|like|maybe|roughly|"
    r"only|just|barely|probably)\s+)*$"
)
#: How a slow speed's phrase ends after its number: a mark, where or when one went ("doing like twelve on
#: the path", "doing ten when"), or a range's top ("doing ten, fifteen tops"); not a count's noun ("doing
#: like ten things") nor a clock's aside ("going about seven, after the pub shut").
_SLOW_SPEED_ENDS = re.compile(
    r"\s*(?:[.;!?]|$|,?\s+(?:on|along|through|down|up|in|into|past|round|around|across|behind|towards|when|as|"
    r"tops|max)\b|,\s*[a-z-]+\s+(?:tops|max)\b)"
)
_MANNER_WORD = "|".join(sorted(Q.MANNER)) + r"|fast|[a-z]{3,}ly"
#: A verb of going, a particle (and its pronoun or a short place) and how one went, set off by commas, before
#: a number ("going up slowly, forty", "going past it, slowly, maybe forty", "going on the roundabout,
#: slowly, maybe twenty-five", "driving, carefully, about thirty"): the speed the verb says, as "going slowly
#: 40" is (:func:`quantities.before_manner`), where the number ends its phrase (:data:`_PHRASE_ENDS`).
_MANNER_BEFORE = re.compile(
    r"\b(?:going|doing|driving|travell?ing|riding|moving|cruising|went|drove|rode)(?:\s+(?:"
    + "|".join(sorted(Q.PARTICLES))
    + r")(?:\s+(?:"
    + "|".join(sorted(Q.PARTICLE_OBJECTS))
    + "|(?:"
    + "|".join(sorted(Q.PLACE_DETERMINERS))
    + r")\s+[a-z-]+))?)?(?:[\s,]+(?:"
    + _MANNER_WORD
    + r"))+[\s,]+(?:(?:maybe|about|around|like|roughly|probably|say)\s+)?$"
)
#: What ends a number in words set off by commas as a speed: the sentence's end, or a comma and a word that
#: opens the clause that goes on (:func:`quantities.set_off_speed_ends`, which asks the same of figures).
_PHRASE_ENDS = re.compile(r"\s*(?:[.;!?)]|$|,\s*(?:" + "|".join(sorted(Q.SET_OFF_OPENERS)) + r")\b)", re.IGNORECASE)
#: The least number in words read as a speed after a verb of going and hedges (:data:`_GOING_HEDGED`).
_LEAST_GOING = 5
#: ... and after anything else that makes it one ("at fifteen", "like twenty").
_LEAST_SAID = 15

#: Thousands a vehicle has done ("has about 380k on it", "with 200k on the clock"): a mileage, which "k"
#: after a number of a verb of having says, and no speed ("doing 100k" is one).
_MILEAGE = re.compile(
    r"\b((?:has|have|had|having|with|got)(?:\s+(?:about|around|over|nearly|almost|just|only|well))*\s+)(\d+)\s*k\b(?![/'])"
)
#: An exponent of minus one as scientists write it ("h-1", "h^-1", "h⁻¹", "s^(-1)").
_PER = r"\s*(?:\^\s*\(?\s*[-\u2212]\s*1\s*\)?|[-\u2212]1|\u207b\u00b9)(?!\d)"
#: What joins the parts of a unit in scientific notation ("km h-1", "km.h-1", "km·h-1", "kmh-1").
_JOIN = r"\s*[.\u00b7\u22c5]?\s*"
#: Every way a speed's unit is written that no rule below reads: with the slash after "p" ("mp/h", "km p/h",
#: "km/ph"), with "hr" ("mi/hr", "km per hr"), in scientific notation ("km h-1", "m s^-1", "ms-1",
#: "m·s⁻¹"), per second spelt short ("metres/sec", "m/sec"), and km/h with the hour of other languages
#: (Dutch and Afrikaans "km/u", Scandinavian "km/t", Malay and Indonesian "km/j", "km/jam").
_UNIT_FORMS = [
    (re.compile(r"(\d)\s*(?:mp/h|m/ph|(?:mi|miles?)\s*(?:/|\s+per\s+|\s+an?\s+)\s*hrs?)\b"), r"\1 mph"),
    (re.compile(r"(\d)\s*kms?\s*(?:p/h|/ph|p/hr|(?:/|\s+per\s+|\s+an?\s+)\s*hrs?\b)"), r"\1 km/h"),
    (re.compile(r"(\d)\s*kms?" + _JOIN + r"(?:hr|h)" + _PER), r"\1 km/h"),
    (re.compile(r"(\d)\s*kms?\s*/\s*(?:u|t|j|jam)\b"), r"\1 km/h"),
    (re.compile(r"(\d)\s*m" + _JOIN + r"s(?:ec)?" + _PER), r"\1 m/s"),
    (re.compile(r"(\d)\s*(?:met(?:er|re)s?|m)\s*/\s*sec(?:ond)?s?\b(?!\s*\^)"), r"\1 m/s"),
]
#: "km" after a number said as a speed is held ("going maybe 20 km", "doing 60 km", "speed was 40 km", "I go
#: behind him at 15 km"): km/h said short, as many write it. Not a distance: one followed by where or how
#: far it goes ("at 15 km from the city", "doing 20 km a day", "going 5 km further", "25 km into the trip"),
#: and "at" only in a clause of going ("was at", "driving at", "went behind him at"), not a place ("the crash
#: happened at 50 km", "At 50 km the road narrows").
_KM_AS_SPEED = re.compile(
    r"\b(at|going|doing|speed|speed was|speed is|speed of)[,:]?\s+"
    r"((?:(?:slow|slowly|fast|very|quite|about|around|approx\.?|approximately|maybe|only|just|like|roughly|almost|"
    r"nearly|max|~)[,\s]*)*(?:[5-9]|[1-9]\d{1,2})(?:\.\d+)?)\s*kms?(?![-\w/])"
    r"(?!\s+(?:away|from|to|further|farther|more|ahead|behind|later|before|after|of|long|per|each|every|an?|north|"
    r"south|east|west|past|beyond|outside|radius|stretch|trip|journey|left|remaining|mark|marker|post|point|into|"
    r"out|down|up|along|lap|laps|limit|is the limit|and\s+\d+)\b)"
)
#: Verbs of going (and "was"/"were" of being somewhere at a speed) that make a clause's "at N km" a speed.
_GOING_BEFORE_AT = re.compile(
    r"\b(?:go|goes|going|went|gone|drive|drives|driving|drove|driven|ride|rides|riding|rode|travel\w*|cruis\w*|"
    r"move|moves|moving|moved|head\w*|come|comes|coming|came|was|were|am|i'm|we're)\b(?![^.;!?]*\b(?:happened|"
    r"occurred|broke down|stopped|parked)\b)[^.;!?]*$"
)


def _km_as_speed(m: re.Match) -> str:
    """``m`` of :data:`_KM_AS_SPEED` with its "km" as km/h, or as written where its "at" is no clause of going."""
    if m.group(1) == "at" and not _GOING_BEFORE_AT.search(m.string, max(0, m.start() - 80), m.start()):
        return m.group(0)
    return f"{m.group(1)} {m.group(2)} km/h"


#: What after "an hour" makes it a time or a difference, not a unit of speed ("100 km an hour ago", "10 km
#: an hour slower than the limit"); "over the limit" is read as a difference by the mph it is said in.
_NOT_A_TIME = r"(?!\s+(?:ago|later|earlier|slower|faster|less|more)\b)"

#: Spelt-out or unusual speed units, as the reader's symbols.
_UNITS = _UNIT_FORMS + [
    (re.compile(r"(?:\b|(?<=\d))miles?\s+(?:an|per|a)\s+hour\b" + _NOT_A_TIME + r"|\bmi/h\b|\bm\.p\.h\.?"), "mph"),
    (  # (glued to its number too: "40km an hour")
        re.compile(
            r"(?:\b|(?<=\d))(?:kilomet(?:er|re)s?|km)\s+(?:an|per|a)\s+hour\b"
            + _NOT_A_TIME
            + r"|\bkm/hr?\b|\bkmph\b|\bkm/std\b"
        ),
        "km/h",
    ),
    (re.compile(r"\bmet(?:er|re)s?\s+(?:per|a)\s+second\b|\bmps\b"), "m/s"),
    (_MILEAGE, r"\1\g<2>000"),  # ("has about 380k on it": thousands had, no speed)
    # ("50 k's": spoken km/h; not a video's resolution: "4K dashcam")
    (re.compile(r"(\d)\s*(?:kph|kmh|k's|ks|k)(?![\w'])(?!\s*(?:dash|video|footage|cam|hdr|uhd))"), r"\1 km/h"),
    (re.compile(r"(\d)\s*(?:klicks?|clicks)\b"), r"\1 km/h"),  # ("80 klicks": kilometres, the Canadian's km/h)
    (_KM_AS_SPEED, _km_as_speed),  # ("going slow, maybe 20 km", "at 15 km": km/h said short)
    (re.compile(r"m/s\s*\^\s*2|m/s/s|m/sec\^?2"), "m/s²"),  # ("decel 6 m/s^2": an acceleration)
    (re.compile(r"(\d)(km/h|mph|m/s|m)\b"), r"\1 \2"),
    (re.compile(r"(\d)\s*mins?\b"), r"\1 minutes"),  # ("45 mins": minutes, before the speller reads "minis")
    (re.compile(r"(\d)\s*yrs?\b"), r"\1 years"),
]


def _numbers_said(words: str) -> list[int] | None:
    """The numbers a run of number words says, one after another, or None where a word is none: English
    builds one number by a rule ("forty-five": a tens word, then a unit of one to nine; "a hundred and
    ten": a hundred, then the tens and units), and a word that cannot go on the number before it starts
    a number of its own ("fifteen sixteen", "forty forty-five", "five fifteen": two numbers, not 31, 85
    and 20)."""
    numbers: list[int] = []
    current, fresh = 0, True  # the number being built; whether it has no word yet
    for w in re.split(r"[\s-]+", words.strip()):
        if w == "and" or not w:
            continue
        below = current % 100  # (what follows its hundreds: the tens and units said so far)
        after_hundreds = fresh or (below == 0 and current > 0)  # (nothing yet, or only hundreds)
        if w in _ONES and (after_hundreds or (below >= 20 and below % 10 == 0 and 0 < _ONES[w] < 10)):
            current += _ONES[w]  # ("forty-five", "a hundred and two", "a hundred and fifteen")
        elif w in _TENS and after_hundreds:
            current += _TENS[w]  # ("forty", "a hundred and twenty")
        elif w == "hundred" and current < 100:
            current = max(current, 1) * 100  # ("a hundred", "two hundred", "hundred")
        elif w in _ONES or w in _TENS:
            numbers.append(current)  # (a word that goes on no number before it: the next number)
            current = _ONES.get(w, _TENS.get(w, 0))
        else:
            return None
        fresh = False
    return None if fresh else [*numbers, current]


def _number_value(words: str) -> int | None:
    """The value of a number in words ("a hundred and ten": 110), or None where the words say no one
    number (see :func:`_numbers_said`)."""
    said = _numbers_said(words)
    return said[0] if said and len(said) == 1 else None


def _range_said(words: str) -> str | None:
    """The number or range of numbers a run of number words says where it is no one number: a number said
    again is that number ("thirty - thirty": 30, a speaker's hesitation), and two numbers, the second
    above the first by no more than the first again, are a range said without its "to" ("fifteen
    sixteen", "forty forty-five", "fifteen twenty": 15-16, 40-45, 15-20), as "doing 40-45" is. Others
    ("five fifteen", "six thirty": a time; "nine nine nine": a number dialled) say no quantity: None."""
    said = _numbers_said(words)
    if not said or len(said) != 2:
        return None
    low, high = said
    if low == high:
        return str(low)
    return f"{low}-{high}" if 0 < low < high <= 2 * low else None


def _after_modifiers(text: str, m: re.Match) -> bool:
    """Whether the number in words ``m`` follows "at" or "doing", an article and one or two modifiers ("at
    a cautious thirty", "doing a steady sixty", "at a very sensible sixty-five"): a speed, as "at a steady
    50" in figures is, by the same test (:func:`quantities.speed_after_modifiers`: no count of a noun)."""
    after = re.match(r"[\s-]*([a-z]*)", text[m.end() :], re.IGNORECASE)
    return Q.speed_after_modifiers(text[: m.start()].split()[-4:], after.group(1) if after else "")


def _numbers_in_words(text: str) -> str:
    """Digits for numbers written as words where a unit follows ("thirty kilometer per hour")."""

    def sub(m: re.Match) -> str:
        after = _UNIT_AFTER.match(text, m.end())
        before = _SPEED_BEFORE.search(text, max(0, m.start() - 8), m.start())
        before = before or _CHOICE_BEFORE.search(text, max(0, m.start() - 40), m.start())
        before = before or _GUESS_BEFORE.search(text, max(0, m.start() - 40), m.start())
        before = before or _SPEED_AFTER.match(text, m.end())  # ("sixty speed only")
        before = before or _after_modifiers(text, m)  # ("at a cautious thirty", "at a very sensible sixty-five")
        if not before and _PHRASE_ENDS.match(text, m.end()):  # ("going up slowly, forty, ...")
            before = _MANNER_BEFORE.search(text, max(0, m.start() - 60), m.start())
        if after is None and before:
            going = _GOING_HEDGED.search(text, max(0, m.start() - 40), m.start()) and _SLOW_SPEED_ENDS.match(
                text, m.end()
            )  # ("doing like twelve on the path"; not "doing like ten things")
            least = _LEAST_GOING if going else _LEAST_SAID
            value = _number_value(m.group(1))  # ("at forty": a speed, said without its unit)
            if value is None and (said := _range_said(m.group(1))) is not None:
                return said if int(said.split("-")[0]) >= least else m.group(0)  # ("doing forty forty-five")
            return str(value) if value is not None and value >= least else m.group(0)
        joined = "-" in text[m.end() : after.start(1)] if after is not None else False
        if after is None or (joined and after.group(1)[0] in "lfy"):
            return m.group(0)  # ("two-lane road", "a six-foot hedge" keep their words: a name, a size)
        value = _number_value(m.group(1))
        if value is None:
            return _range_said(m.group(1)) or m.group(0)  # ("fifteen sixteen mile an hour": 15-16 mph)
        return str(value)

    return _NUMBER.sub(sub, text)


#: The narrator's own vehicle in police, insurance and witness statements.
_EGO_ALIASES = [
    re.compile(
        r"\b(?:the\s+)?(?:driver\s+of\s+)?(?:(?:vehicle|veh\.?|unit|car)\s*-?\s*(?:1|one|#1)|(?:v|d)\s*-?\s*#?1)\b"
        r"(?!\s*(?:m|km|mph|s)\b)"  # (a letter's code in figures: "done" is no "D one")
    ),
    re.compile(r"\b(?:the\s+)?(?:insured|my\s+client|our\s+client|the\s+claimant)(?:'s\s+(?:vehicle|car))?\b"),
    re.compile(r"\b(?:our|my)\s+(?:vehicle|own\s+car|own\s+vehicle)\b"),
    re.compile(
        r"\b(?:the\s+|a\s+)?(?:(?:vehicle|car)\s+under\s+test|test\s+(?:car|vehicle)|subject\s+(?:vehicle|car)|"
        r"ego\s+(?:vehicle|car|veh)|insured\s+(?:vehicle|car)|ego)\b"
    ),
]
#: The ego named again in apposition: "the ego (the ego, the ego)", "the ego, the ego,", "the driver of the
#: ego": one ego.
_EGO_AGAIN = re.compile(
    r"\bthe ego(?:\s*\(\s*(?:the ego|which is the ego|i\.e\. the ego)(?:\s*,\s*the ego)*\s*\)|"
    r"\s*,\s*(?:which is |i\.e\. )?the ego\s*(?=,))+"
)
#: The other party of a statement: "V2", "Vehicle 2", "Unit 2", "D2" (3, 4 ...).
#: (Not a version, "spec v3.1", nor a measure, "V2 km/h".)
_OTHER = re.compile(
    r"\b(?:(?:the|a|an)\s+)?(?:(?:vehicle|veh\.?|unit|v|d)\s*-?\s*([2-9])\b(?!\.\d|\s*(?:m|km|mph|s)\b)|"
    r"(?:pov|principal other vehicle)(?:\s*-?\s*([1-9]))?\b|third[- ]party(?:'s)?\s+(?:vehicle|car)\b)"
)
#: An apposition after it: "V2, a white Transit van," / "Unit 2, a pedal cyclist,".
_APPOSITION = re.compile(
    r"\s*(?:,?\s*(?:an?|the)\s+([^,.;()]+?)(?=\s*(?:,|\.|;|\s+(?:travell\w*|driving|was|were|who|which|in|on|at)\b))|"
    r"\(\s*(?:an?\s+|the\s+)?([^,.;()]+?)\s*(?:,[^()]*)?\))"  # ("(e-scooter, male rider)": the first says what)
)


#: A party's code said again in brackets after its name ("Vehicle 2 (V2)"): the apposition follows it.
_CODE_AGAIN = re.compile(r"\s*\(\s*[a-z]{1,3}\s*-?\s*[2-9]\s*\)")
#: Words that name the ego or a first code ("Vehicle 1"): a code opening such a text is another party.
_NAMES_EGO = re.compile(r"\b(?:i|we|me|us|my|our|ego|(?:vehicle|veh|unit|car|v|d)\s*-?\s*(?:1|one))\b")
#: What follows a call sign opening a radio report ("Unit 4 to control", "Car 12 calling base").
_CALLING = re.compile(r"\s*,?\s*(?:to|calling|for)\b")

#: A call sign opening a sentence that goes on to see the report's subject ("Unit 3, proceeding ...,
#: observed the subject vehicle"): the call sign is the observer, the report's own vehicle.
_OBSERVER = re.compile(
    r"(?:^|(?<=[.;!?:]\s))((?:unit|patrol|car|vehicle|v)\s*-?\s*\d+)\b[^.;!?]*?"
    r"\b(?:observed|observes|saw|sees|noticed|notices|spotted|spots|witnessed|watched)\s+(?:the\s+)?subject\s+(?:vehicle|car)\b"
)
_SUBJECT = re.compile(r"\b(?:the\s+)?subject\s+(?:vehicle|car)\b")


def _observer(text: str, known_noun) -> str:
    """In a report whose call sign sees "the subject vehicle", the call sign is the ego (every
    mention of it) and the subject is the other party: what its apposition names ("the subject
    vehicle, a blue saloon,"), else "a car", where first named, and "the" that after."""
    m = _OBSERVER.search(text)
    if m is None:
        return text
    text = re.sub(rf"\b{re.escape(m.group(1))}\b", "the ego", text)
    first = _SUBJECT.search(text)
    app = _APPOSITION.match(text, first.end())
    noun = known_noun(app.group(1) or app.group(2)) if app is not None else None
    said = f"a {app.group(1) or app.group(2)}" if noun else "a car"
    text = text[: first.start()] + said + text[app.end() if noun else first.end() :]
    return _SUBJECT.sub(f"the {noun or 'car'}", text)


def _other_parties(text: str, known_noun) -> str:
    """Each other party named by its code becomes the road user its apposition names (a car when
    that names none the reader knows: "a Toyota Prius"), and later mentions of the code that one."""
    names: dict[str, str] = {}
    out, pos = [], 0
    for m in _OTHER.finditer(text):
        if m.start() < pos:
            continue  # (inside what was read already: "(V2)" after "Vehicle 2")
        opening = not re.sub(r"\[[^\]]*\]", "", text[: m.start()]).strip(" -*,.:")
        if opening and (_CALLING.match(text, m.end()) or not _NAMES_EGO.search(text)):
            continue  # "Unit 4 to control, ...", "Unit 6 AEB event, ...": the report's own vehicle (discourse)
        code = m.group(1) or m.group(2) or m.group(0).split()[-1]
        out.append(text[pos : m.start()])
        pos = m.end()
        if text[: m.start()].rstrip().endswith("(") and text[m.end() :].lstrip().startswith(")"):
            # "an e-scooter rider (V2)": the code of the road user just named; later mentions are that one
            named = known_noun(" ".join(text[: m.start()].rstrip()[:-1].split()[-4:]))
            names.setdefault(code, named or "car")
            out[-1] = out[-1].rstrip()[:-1]
            pos = text.index(")", m.end()) + 1
            continue
        if code in names:
            out.append(f"the {names[code]}")
            continue
        code_again = _CODE_AGAIN.match(text, m.end())  # ("Vehicle 2 (V2), a Ford Transit van, ...")
        if code_again is not None:
            pos = code_again.end()
        app = _APPOSITION.match(text, pos)
        if app is not None:
            phrase = app.group(1) or app.group(2)
            noun = known_noun(phrase)
            names[code] = noun or "car"
            out.append(f"a {phrase}" if noun else f"a {phrase} car")
            pos = app.end()
        else:
            names[code] = "car"
            out.append("a car")
    out.append(text[pos:])
    return "".join(out)


_HEADING = re.compile(r"\b(north|south|east|west)(?:bound|wards)\b")
_OPPOSITE = {"north": "south", "south": "north", "east": "west", "west": "east"}


def _headings(text: str) -> str:
    """Compass headings of a statement ("Unit 1 was southbound ... Unit 2, travelling northbound"): the
    first is the ego's (said in its sentence); a later opposite one is the other way, the same one the
    same way as the ego."""
    first = _HEADING.search(text)
    if first is None or "the ego" not in text[max(text.rfind(".", 0, first.start()), 0) : first.end()]:
        return text
    own = first.group(1)

    def sub(m: re.Match) -> str:
        if m.start() == first.start():
            return m.group(0)
        if m.group(1) == _OPPOSITE[own]:
            return "in the opposite direction"
        return "in the same direction" if m.group(1) == own else m.group(0)

    return _HEADING.sub(sub, text)


_SIDE = {"l": "left", "r": "right"}
#: What a hand or side is said of: a place beside the road, a lane, a side, a turn or an arm.
_SIDED = (
    r"arm|lane|lanes|side|kerb|curb|edge|pavement|footway|footpath|sidewalk|verge|shoulder|turn|bend|junction|exit|"
    r"side road|side street|carriageway"
)
#: Shorthand of radio reports, notes and chat, said in full ("M/bike from L arm", "ego veh NB",
#: "lt traffic", "dual c/way", "doesnt", "nite"): the same words every writer's shorthand stands for.
#: "Heads up" as a notice ("Heads up:", "a heads-up for tomorrow's run", "quick heads up on ..."), said
#: before what the notice is about or a stop: no verb of the road user named after it ("heads up the
#: hill" is one, and stays).
_HEADS_UP = re.compile(
    r"\b(?:(?:just |quick |friendly )?an? )?(?:quick |friendly )?heads[- ]up"
    r"(?=\s*(?:[:,;!.\-\u2013\u2014]|(?:for|on|about|re|that|guys|everyone|all)\b|$))"
)
#: One person or thing said, then said again at once with what tells it apart (a speaker's self-repair:
#: "a boy, a boy on a scooter", "this man, this man riding an e-scooter"): one mention, the fuller one.
#: Only where the same words come back right after the comma and go on with a modifier; a list of two
#: of a kind ("a car, a car and a van") goes on with no modifier and stays.
_SAID_AGAIN_FULLER = re.compile(
    r"\b(?:a|an|the|this|that|some) ((?:[a-z-]+ ){0,2}?[a-z-]+),\s+(?=(?:a|an|the|this|that|some) \1 "
    r"(?:on|riding|in|with|wearing|carrying|pushing|who|that)\b)"
)
_SHORTHAND = [
    (re.compile(r"\bm/(?:bike|cycle)s?\b|\bm/c\b"), "motorbike"),
    (re.compile(r"\bp/cycle\b|\bpedal cycle\b"), "bicycle"),
    (re.compile(r"\b4\s?x\s?4s?\b"), "four-by-four"),
    (re.compile(r"\bc/way\b"), "carriageway"),
    (re.compile(r"\brd\b"), "road"),
    # a roundabout's shorthand ("RBT", "mini-rbt", "r'bout"); not Australia's random breath test ("RBT unit")
    (
        re.compile(
            r"\b(mini-)?(?:rbt|rndbt|rndabt|r'bout)\b(?!\s+(?:unit|units|test|tests|testing|station|site|checkpoint|operation))"
        ),
        r"\1roundabout",
    ),
    (re.compile(r"\b(?:jct|jcn|junc)\b\.?"), "junction"),
    (re.compile(r"\bvehs\b\.?"), "vehicles"),
    (re.compile(r"\bveh\b\.?"), "vehicle"),
    (re.compile(r"\btrk\b\.?"), "truck"),
    (re.compile(r"\b(?:chg|chng|chnge)\b\.?"), "change"),  # ("lane chg L", "spd chg")
    # a fleet call sign written as a code ("VAN-112", "TRK-22"): the noun and its number, as "Van 07" is
    (re.compile(r"\b(van|bus|truck|trk|car|coach|unit|cab|taxi)-(\d{1,4})\b(?!\s*(?:m|km|mph|s)\b)"), r"\1 \2"),
    (re.compile(r"\bpeds?\b"), "pedestrian"),
    (re.compile(r"\b(?:lt|lite)\b(?= (?:traffic|rain|snow|fog)\b)"), "light"),
    (re.compile(r"\b(?:hvy|hevy)\b"), "heavy"),
    (re.compile(r"\b(?:mod|med)\b\.?(?= traffic\b)"), "moderate"),
    (re.compile(r"\bnb\b"), "northbound"),
    (re.compile(r"\bsb\b"), "southbound"),
    (re.compile(r"\beb\b"), "eastbound"),
    (re.compile(r"\bwb\b"), "westbound"),
    # a crossing's direction in notation ("L->R", "R > L", "right to left"): from the side said first
    (
        re.compile(r"\b(?:from )?(l|r|left|right) ?(?:-+>|=>|\u2192|>|to) ?(l|r|left|right)\b(?!')"),
        lambda m: (
            m.group(0) if m.group(1)[0] == m.group(2)[0] else f"from {_SIDE[m.group(1)[0]]} to {_SIDE[m.group(2)[0]]}"
        ),
    ),
    # a hand or side said short before what it is of ("RH kerb", "L/H lane", "the LHS", "N/S footway", "O/S
    # lane"): left-hand, right-hand, nearside, offside ("RH 88 %", relative humidity, names no place)
    (re.compile(r"\b(l|r)(?:/h|h)\.?(?= (?:" + _SIDED + r")\b)"), lambda m: f"{_SIDE[m.group(1)]}-hand"),
    (re.compile(r"\b(on|to|from|at) the (l|r)hs\b"), lambda m: f"{m.group(1)} the {_SIDE[m.group(2)]}-hand side"),
    (re.compile(r"\bn/s\.?(?= (?:" + _SIDED + r")\b)"), "nearside"),
    (re.compile(r"\bo/s\.?(?= (?:" + _SIDED + r")\b)"), "offside"),
    # a single L or R where a side is said: "from L arm", "lane to the R", "on the L", "R turn"
    (re.compile(r"\b(from|to|on|at|in|the|turning|turns|turn)( the)? l\b(?!')"), r"\1\2 left"),
    (re.compile(r"\b(from|to|on|at|in|the|turning|turns|turn)( the)? r\b(?!')"), r"\1\2 right"),
    # ... or after the place it names: "junction L", "side road R", "kerb L": on that side
    (
        re.compile(
            r"\b(junction|arm|entry|exit|side road|side street|kerb|curb|pavement|footpath|sidewalk|verge) (l|r)\b(?!')"
        ),
        lambda m: f"{m.group(1)} on the {_SIDE[m.group(2)]}",
    ),
    (re.compile(r"\bl(?= (?:arm|lane|side|kerb|edge|turn)\b)"), "left"),
    (re.compile(r"\br(?= (?:arm|lane|side|kerb|edge|turn)\b)"), "right"),
    # "doesnt", "dosnt", "didnt", "wasnt": the verb, then "not" (as "doesn't" is read)
    (re.compile(r"\b(does|dos|doe|do|did|is|was|were|are|could|would|should|has|have|had)nt\b"), r"\1 not"),
    (re.compile(r"\bcant\b"), "can not"),
    (re.compile(r"\bwont\b"), "will not"),
    (re.compile(r"\bdos\b(?= not\b)"), "does"),
    (re.compile(r"\b(?:nite|nyt)\b"), "night"),
    (re.compile(r"\btonite\b"), "tonight"),
    (re.compile(r"\binfront\b"), "in front"),
    (re.compile(r"\bthru\b"), "through"),
]
#: Lengths in other units, as metres ("50 feet": 15.2 m), and the clock said in other ways.
_FOOT_M, _YARD_M = 0.3048, 0.9144
_LENGTHS = re.compile(r"(\d+(?:\.\d+)?)\s*(feet|foot|ft|yards?|yds?)\b(?! (?:per|a) second)")
#: "1930 hrs", "0750h": a four-digit clock; "6pm", "3 in the afternoon", "9 at night": the hour said.
_FOUR_DIGIT_CLOCK = re.compile(r"\b([01]\d|2[0-3])([0-5]\d)\s*(?:hrs|hours|h)\b")
#: "18h30", "7h15", "17u05" (as the Dutch write it), and "8h" after a word of when, a form's field of time or a
#: date ("around 8h", "at 22h", "Time: 14h", "12/12/2023 14h"): the clock as much of Europe writes it; a bare
#: "3h" after anything else ("a 3h drive", "for 2h", "travel time: 2h", "3h after I left") is a duration.
_CLOCK_WITH_H = re.compile(
    r"\b([01]?\d|2[0-3])[hu]([0-5]\d)\b|((?:\b(?:at|around|about|approx|approximately|towards|toward|by|circa)"
    r"|(?<![a-z] )\btime:|\b\d{1,2}[/.-]\d{1,2}[/.-]\d{2,4}) )([01]?\d|2[0-3])h\b"
    r"(?! (?:after|later|before|ago|into|of|drive|trip|journey|walk|ride|away|long)\b)"
)


def _clock_with_h(m: re.Match) -> str:
    return f"{m.group(1)}:{m.group(2)}" if m.group(1) else f"{m.group(3)}{m.group(4)}:00"


_HOUR_OF = re.compile(r"\b(1[0-2]|0?[1-9])(?: o'?clock)? (in the (?:morning|afternoon|evening)|at night)\b")
_HALF = {"in the morning": "am", "in the afternoon": "pm", "in the evening": "pm", "at night": "pm"}


def _hour_of(m: re.Match) -> str:
    hour = int(m.group(1))
    half = _HALF[m.group(2)] if not (m.group(2) == "at night" and hour in (12, 1, 2, 3, 4)) else "am"
    return f"{hour} {half} {m.group(2)}"


def _lengths(m: re.Match) -> str:
    per = _YARD_M if m.group(2).startswith("y") else _FOOT_M
    return f"{float(m.group(1)) * per:.1f} m"


_DEFINED = re.compile(r"\b((?:[a-z][\w-]* ){1,5})\(\s*([a-z]{2,6})\s*\)")


_EGO_AS_A_CAR = re.compile(
    r"\b(?:ego car|ego vehicle|my car|our car|my vehicle|our vehicle|test car|camera car|camera vehicle)\b"
)
_OTHER_CAR = re.compile(r"\b(?:a|an|another|one|other|some|second|third-party|third party)\s+(?:[a-z-]+\s+)?car\b")
_THE_CAR = re.compile(r"\bthe car\b(?! (?:in front|ahead|behind|beside|next|on|in|from|that|which|coming))")


#: "car" or "vehicle" opening a clause with no article ("..., car is brake hard", "and vehicle stops").
_BARE_CAR = re.compile(
    r"(?:(?<=[,.;:] )|(?<=\band )|(?<=\bbut )|(?<=\bso ))(?:car|vehicle)\b"
    r"(?! (?:in front|ahead|behind|beside|next|on|in|from|that|which|coming))"
)


#: What only the ego's own driver-assistance system does, said of its vehicle: it beeps (not at someone,
#: nor its horn), chimes or warns, gives a warning or a brake jolt, flashes its red warning, brakes, slows or
#: stops by itself, phantom brakes, does not detect someone or show them on its screen, or does nothing.
_SYSTEM_ACT = (
    r"(?:(?:still|then|also|just|even|immediately|instantly|again|suddenly)\s+)*(?:"
    r"(?:beeps|beeped|pinged|chimes|chimed)(?![^.;,!?]*\b(?:at|horn)\b)|warns|warned|alerts|alerted|"
    r"(?:gave|gives|give)\s+(?:me\s+|us\s+)?(?:a|an|the)\s+(?:[\w'-]+\s+){0,2}(?:warning|alert|beep|chime|jolt|bong)s?"
    r"(?=\s*(?:[,.;!?]|$|(?:and|at|when|as|but|before|then)\b))|"
    r"flash(?:es|ed)\s+(?:the\s+|a\s+|its\s+)?(?:red|orange|amber|warning)|"
    r"(?:braked|brakes|slowed|slows|stopped|stops)\s+(?:itself|on\s+its\s+own|by\s+itself|automatically)|"
    r"phantom[- ]?brak\w*|did(?:n't|\s+not)?\s+(?:even\s+)?detect\b|"
    r"did(?:n't|\s+not)?\s+(?:even\s+)?show\s+(?:[\w'-]+\s+){0,2}on\s+(?:the|its|my)\s+(?:screen|display|"
    r"visuali[sz]ation|dash|dashboard|hud)\b|(?:did|does)\s+nothing(?=\s*(?:[,.;!?]|$)))"
)
#: The vehicle of a clause, with "the" or none, whose act is the ego's system's ("Car beeps, flashes and does
#: that pre-brake jerk", "the car still flashes the red bar", "Van flashed the red light on the windscreen
#: and braked itself"): the narrator's own vehicle, the ego. Not one placed ("the car in front beeped").
_OWN_SYSTEMS_VEHICLE = re.compile(
    r"(?:(?<=^)|(?<=[.;:!?,]\s)|(?<=\band\s)|(?<=\bbut\s)|(?<=\bthen\s)|(?<=\bso\s))(?:the\s+)?"
    r"(?:car|van|vehicle|suv)\s+(?=" + _SYSTEM_ACT + ")"
)
#: A road user brought in with "a" ("a car was waiting", "an old BMW"): "the car" after it may be that one.
_BROUGHT_IN = re.compile(r"\b(?:a|an|another|one)\s+((?:[\w-]+\s+){0,2}[\w-]+)")
#: The narrator out of a vehicle: on a bike or scooter, on foot, crossing ("I was cycling home", "I was on my
#: bike", "I was crossing the road"): "the car" that beeps or does not detect them is another's.
_NARRATOR_OUT = re.compile(
    r"\b(?:i|we)\s+(?:was|were|am|'m|are)\s+(?:just\s+)?(?:on\s+(?:my|a|our|the)\s+(?:[\w-]+\s+)?(?:bike|bicycle|"
    r"scooter|e-scooter|escooter|moped|motorbike|skateboard)|on\s+foot|cycling|riding|walking|crossing|jogging|"
    r"running|scooting)\b|\bmy\s+(?:bike|bicycle|e-scooter|escooter|scooter)\b",
    re.IGNORECASE,
)
#: The words of road users that are no motor vehicle, whom "the car" cannot name again.
_NOT_MOTOR = frozenset(w for kind in ("pedestrian", "bicycle", "e-scooter") for w in L.ACTOR_NOUNS.get(kind, ()))


def _own_systems_vehicle(text: str, known_noun) -> str:
    """``text`` with the vehicle whose act only the ego's driver-assistance system does named as the ego
    ("Car beeps, flashes and does that pre-brake jerk": "the ego beeps, ..."). Why: an owner writing of
    their car's emergency braking or collision warning calls it "the car" and names no other by it; read
    as a road-user noun it became a second car that beeps and brakes. Where a motor vehicle was brought
    in before with "a" ("A car was waiting at the give way line. The car did nothing, then pulled
    out"), "the car" may be that one, and the text is left as it is; so is a car placed ("the car in
    front beeped"), and every car of a narrator on a bike, a scooter or foot ("I was cycling home. The
    car did not detect me": :data:`_NARRATOR_OUT`)."""
    if _NARRATOR_OUT.search(text):
        return text

    def sub(m: re.Match) -> str:
        for b in _BROUGHT_IN.finditer(text, 0, m.start()):
            noun = known_noun(b.group(1))
            if noun is not None and noun not in _NOT_MOTOR:
                return m.group(0)
        return "the ego "

    return _OWN_SYSTEMS_VEHICLE.sub(sub, text)


def _the_car_is_the_ego(text: str) -> str:
    """ "Ego car is driving ..., an e-scooter enters ..., the car must brake": with the ego named as a car
    and no other car in the text, "the car" is the ego (not one placed in front or coming from somewhere)."""
    if not _EGO_AS_A_CAR.search(text) or _OTHER_CAR.search(text):
        return text
    first = _EGO_AS_A_CAR.search(text).end()
    rest = _BARE_CAR.sub("the ego", _THE_CAR.sub("the ego", text[first:]))  # ("..., car is brake hard")
    return text[:first] + rest


#: Role words of the one vehicle a film's run sheet ("hero car", "our hero") or a game's encounter ("player
#: vehicle", "Player: delivery van") is built round: its vehicle under test, as the ego is a spec's.
_ROLE = r"(?:hero|player)"
#: The role word before a road-user word ("hero van", "the player's car"): the vehicle it names.
_ROLE_BEFORE = re.compile(rf"\b(?:(?:the|our)\s+)?{_ROLE}(?:'s)?\s+([a-z][a-z-]*)", re.IGNORECASE)
#: The role word opening a line or an item as its label ("Player: tuk-tuk", "player = muscle car").
_ROLE_LABEL = re.compile(rf"(?:^|(?<=[\n.;|/-]))\s*(?:the\s+)?{_ROLE}\s*[:=]", re.MULTILINE | re.IGNORECASE)
#: "our hero": a story's own vehicle ("the little bus (our hero)", "Our hero, a tractor, ...").
_OUR_HERO = re.compile(r"\bour\s+hero\b", re.IGNORECASE)
#: Every mention of the role, once the text names one ("hero's right", "in front of the player"), with
#: the word after it.
_ROLE_MENTION = re.compile(
    rf"\b(?:(?:the|our)\s+)?{_ROLE}('s)?(?:\s+([a-z][a-z-]*)(\s+[a-z]{{0,3}}-?\d+[a-z]?\b)?)?", re.IGNORECASE
)
#: Words before a vehicle's noun said again that bring in no other ("the bus", "of bus", "and taxi").
_THE_OR_LINKING = frozenset("the of to into onto in on at by behind past with and then so but as for from than".split())
#: A regulation's automated lane keeping system (UN R157) and the vehicle with it: the vehicle under test.
_ALKS = re.compile(
    r"\b(?:the\s+)?(?:vehicle|car)\s+with\s+(?:an?\s+|the\s+|its\s+)?(?:active\s+)?alks\b|"
    r"\b(?:the\s+|an?\s+)?alks(?:[- ]equipped)?(?:\s+(?:vehicle|car))?\b",
    re.IGNORECASE,
)


def _names_a_role(text: str, known_noun) -> bool:
    """Whether ``text`` names its vehicle by a role: the role word before a road-user word, as a
    label, or "our hero" (not "some hero in an Audi", said of another in scorn, nor a football player,
    whom no road-user word follows)."""
    return bool(
        _ROLE_LABEL.search(text)
        or _OUR_HERO.search(text)
        or any(
            known_noun(m.group(1).lower()) and _no_other_before(text, m.start()) for m in _ROLE_BEFORE.finditer(text)
        )
    )


def _word_before(text: str, at: int) -> str:
    """The word (or mark) right before ``at``, lowercased; "." at the start (a short look back only, so
    that asking it of every mention stays linear in the text)."""
    return (text[max(at - 40, 0) : at].split()[-1:] or ["."])[0].lower()


def _no_other_before(text: str, at: int) -> bool:
    """Whether the role word at ``at`` opens its phrase ("hero van", "the player's car", "(hero BMW"), not
    one said of somebody ("some hero cyclist", "a local hero driver"): praise or scorn, not a role."""
    before = _word_before(text, at)
    return not before[-1:].isalpha() or before in _THE_OR_LINKING or before == "our"


def _role_is_the_ego(text: str, known_noun) -> str:
    """ "Hero van at 20 km/h ... from hero's left", "Player: city bus, ...", "ALKS follows a lead car":
    the vehicle a run sheet, an encounter or a regulation's test is built round is the ego, in every
    mention; a road-user word right after the role ("hero van", "the player's car") is that vehicle."""
    text = re.sub(r"\balks\s+lane\b", "the ego's lane", text, flags=re.IGNORECASE)
    text = _ALKS.sub("the ego", text)
    if not _names_a_role(text, known_noun):
        return text

    nouns: list[str] = []

    def ego(m: re.Match) -> str:
        after = m.group(2)
        if after is not None and known_noun(after.lower()):
            nouns.append(after.lower())
            return "the ego"
        return ("the ego's" if m.group(1) else "the ego") + (f" {after}{m.group(3) or ''}" if after is not None else "")

    text = re.sub(r"\bthe ego\s*=", "the ego:", _ROLE_MENTION.sub(ego, text))
    return _role_noun_again(text, nouns[0]) if nouns else text


def _role_noun_again(text: str, noun: str) -> str:
    """ "Hero taxi eastbound ... into the taxi's path, taxi brakes": the noun the role named, said again
    with "the" or bare, is the same vehicle; unless another of its kind is brought in after the role
    ("a taxi", "stunt taxi 2", "the parked taxi"), when which one is meant is unclear."""
    start = text.find("the ego")
    said = list(re.finditer(rf"\b{re.escape(noun)}\b", text[start:], re.IGNORECASE))
    if not said or noun in ("car", "vehicle"):
        return text  # ("car" and "vehicle" are said of every vehicle: another may be meant)
    for m in said:
        before = _word_before(text, start + m.start())
        if before[-1:].isalpha() and before not in _THE_OR_LINKING:
            return text  # ("a taxi", "another bus", "stunt taxi", "parked bus": another of its kind)
    again = re.compile(rf"\b(?:the\s+)?{re.escape(noun)}\b", re.IGNORECASE)
    return text[:start] + again.sub("the ego", text[start:])


_NOMINAL_VERBS = {
    "lane change": "changes lane",
    "lane-change": "changes lane",
    "crossing manoeuvre": "crosses",
    "crossing maneuver": "crosses",
    "crossing": "crosses",
    "cut-in": "cuts in",
    "cut in": "cuts in",
    "emergency stop": "brakes hard to a stop",
    "emergency brake": "brakes hard to a stop",
    "hard stop": "brakes hard to a stop",
    # (braking said as the noun of a hard stop: "makes an emergency braking", "performs heavy braking")
    "emergency braking": "brakes hard",
    "hard braking": "brakes hard",
    "heavy braking": "brakes hard",
    "harsh braking": "brakes hard",
    "full braking": "brakes hard",
    "overtaking manoeuvre": "overtakes",
    "overtaking maneuver": "overtakes",
    "overtake": "overtakes",
    "u-turn": "turns around",
}
_NOMINAL = re.compile(
    r"\b(performs?|performed|performing|initiates?|initiated|initiating|executes?|executed|executing|"
    r"carries out|carried out|makes|made|making|does|did|perform|make|do) "
    r"(?:an? |the )?(?:full |sudden |late |aggressive |abrupt |"
    r"(?:moderately |very )?(?:moderate|gentle|sharp) )?("
    + "|".join(sorted(_NOMINAL_VERBS, key=len, reverse=True))
    + r")\b"
)
#: The verbs :data:`_NOMINAL_VERBS` say, in the plain form and the past tense.
_PLAIN_AND_PAST = {
    "changes": ("change", "changed"),
    "crosses": ("cross", "crossed"),
    "cuts": ("cut", "cut"),
    "brakes": ("brake", "braked"),
    "overtakes": ("overtake", "overtook"),
    "turns": ("turn", "turned"),
}
_PAST_LIGHT_VERBS = frozenset(("performed", "initiated", "executed", "carried out", "made", "did"))
_PLAIN_LIGHT_VERBS = frozenset(("perform", "initiate", "execute", "make", "do"))


def _as_its_verb(m: re.Match) -> str:
    """A behaviour said as a noun a road user performs (``m``: the light verb, then the noun) said as
    its own verb in the light verb's tense ("did an emergency stop": "braked hard to a stop"; "make a
    lane change": "change lane"): the tense is how a story with its subject left out is told by
    its narrator ("Did an emergency stop."), so it stays."""
    verb, _, rest = _NOMINAL_VERBS[m.group(2)].partition(" ")
    plain, past = _PLAIN_AND_PAST[verb]
    light = m.group(1)
    verb = past if light in _PAST_LIGHT_VERBS else plain if light in _PLAIN_LIGHT_VERBS else verb
    return f"{verb} {rest}".strip()


def _initials(words: list[str]) -> str:
    """The initials of ``words``, a hyphenated word giving one per part ("e-scooter target": "est",
    "powered two-wheeler": "ptw"), as abbreviations are made."""
    return "".join(part[0] for w in words for part in w.split("-") if part)


#: A word that may be an abbreviation: three or four letters, no vowel but as its first letter (units
#: excepted).
_SHORT = re.compile(r"\b(?!(?:mph|kph|kmh|mps|hrs)\b)[a-z][b-df-hj-np-tv-z]{2,3}\b")
#: Words an abbreviated term does not start with.
_NOT_IN_TERMS = frozenset("a an the at in on of to and or my our his her their its with from by".split())


def _acronyms_defined(text: str, known_noun=lambda phrase: None) -> str:
    """A term and its abbreviation in brackets ("principal other vehicle (POV)", "insured vehicle (IV)"):
    the term once, so the bracket is not read as a second road user, and the term again wherever the
    abbreviation is used after it ("the path of the IV": of the insured vehicle). A road user's term
    used first in full and then by its initials without brackets ("an e-scooter target ... EST
    crosses") is the same: writers of test protocols abbreviate what they have just named."""
    terms: dict[str, str] = {}

    def sub(m: re.Match) -> str:
        words, short = m.group(1).split(), m.group(2)
        for n in range(1, len(words) + 1):
            if _initials(words[-n:]) == short:
                terms[short] = " ".join(words[-n:])
                return m.group(1).rstrip() + " "
        return m.group(0)

    text = _DEFINED.sub(sub, text)
    for m in _SHORT.finditer(text):
        short = m.group(0)
        if short in terms or english(short) or known_noun(short):
            continue
        words = re.findall(r"[a-z][a-z-]*", text[: m.start()])
        found = next(
            (
                words[end - n : end]
                for end in range(len(words), 0, -1)
                for n in range(1, min(len(short), end) + 1)
                if _initials(words[end - n : end]) == short
                and words[end - n] not in _NOT_IN_TERMS
                and known_noun(" ".join(words[end - n : end]))
            ),
            None,
        )
        if found:
            terms[short] = " ".join(found)
    for short, term in terms.items():
        if len(short) > 1:  # ("the IV", "ahead of TC": the term, with its article)
            text = re.sub(rf"\b(?:the\s+)?{re.escape(short)}\b(?!\s*\()", f"the {term}", text)
    return text


#: A sentence opening with a participle right before a noun ("Crossing car from the right runs the red").
_PARTICIPLE_OPENING = re.compile(r"(^|[.;!?]\s+)([a-z]+ing) ([a-z][a-z-]*)\b")
#: Nouns of the time of day that end as participles do ("evening bus"): no participle.
_TIME_NOUNS = frozenset({"morning", "evening"})
#: Verbs of one road user towards another, whose participle takes the noun after it as its object
#: ("Following lorry at 30 m, ego brakes": the ego follows it): those stay as written.
_TOWARDS_ANOTHER = frozenset(
    {"follow", "overtake", "approach", "pass", "tail", "chase", "lead", "trail", "meet", "see", "spot", "hit", "avoid"}
)


def _with_article(m: re.Match, known_noun) -> str:
    """A terse line's participle before a road user's noun with its article restored ("crossing car
    ...": "a crossing car ..."): the road user's own participle, not a clause of whoever came before
    (the reader reads a sentence opening with a participle as its narrator's, "Crossing the road, I ...")."""
    start, participle, noun = m.groups()
    verbs = lemmas(participle).get("VERB", ())
    if participle in _TIME_NOUNS or not verbs or _TOWARDS_ANOTHER & set(verbs) or known_noun(noun) != noun:
        return m.group(0)
    return f"{start}a {participle} {noun}"


#: A person's age said as a noun: "a six-year-old", "the 8 year old", "two ten-year-olds" (its number in
#: digits or words, "year" or "yr", hyphens or spaces), and the word after it.
_AGE = re.compile(
    rf"\b(\d{{1,3}}|(?:{_NUMBER_WORD})(?:-(?:{_NUMBER_WORD}))?)[\s-]+(?:year|yr)s?[\s-]+old(s?)\b(?=\s*([a-z][a-z-]*)?)"
)
#: Relative pronouns, which lemminflect also has as nouns ("WHO"): after an age, its person goes on.
_RELATIVES = frozenset({"who", "that", "which", "whose"})
#: Below this age a person is a child.
_CHILD_UNDER = 13


def _ages(text: str, known_noun) -> str:
    """``text`` with an age that stands for the person ("a six-year-old chased a ball", "the 8 year old on
    a bike") said as the person it names ("a child", "the person"), so the reader reads the walker (or,
    on a vehicle, its rider) the text is about. An age before a noun only describes it ("a 6-year-old
    boy", "a 24-year-old e-scooter rider", "a 30-year-old driver"): it is left as it is."""

    def sub(m: re.Match) -> str:
        nxt = m.group(3) or ""
        pos = lemmas(nxt) if nxt else {}
        if nxt not in _RELATIVES and (known_noun(nxt) or ("NOUN" in pos and "VERB" not in pos)):
            return m.group(0)  # (the age of the noun after it)
        age = int(m.group(1)) if m.group(1).isdigit() else _number_value(m.group(1))
        if age is None:
            return m.group(0)
        child = age < _CHILD_UNDER
        if m.group(2):
            return "children" if child else "people"
        return "child" if child else "person"

    return _AGE.sub(sub, text)


#: A person's age said after them: "aged about 8", "age 12", "aged 14-15", "a boy of about 8", "a lad of
#: 15 or 16" (a number with no unit after it). Said so, it describes the person; left in, "about 8"
#: would be read as a speed.
_AGE_NUMBER = rf"(?:\d{{1,3}}(?![.,]\d)|{_NUMBER_WORD})"  # (not "a man of 1.8 m": a height)
_AGE_HEDGE = r"(?:(?:about|around|approx\.?|approximately|roughly|maybe|perhaps|under|over|between|only)\s+)?"
#: No unit after the number: "aged 12" is an age, "12 m" or "12 mph" is not.
_NO_UNIT_AFTER = r"(?!\s*(?:mph|km|kph|kmh|m/s|m\b|metres|meters|feet|ft|yards|%))"
_AGED = re.compile(
    rf"\b(?:aged|age)\s+{_AGE_HEDGE}{_AGE_NUMBER}(?:\s*(?:-|to|or|and)\s*{_AGE_NUMBER})?\b{_NO_UNIT_AFTER}"
)
#: The people an age follows with "of" ("a boy of 8"), a closed class.
_PEOPLE = ("boy", "girl", "lad", "lass", "kid", "child", "youth", "teenager", "teen", "man", "woman", "lady",
           "bloke", "guy", "chap", "fella", "gentleman", "person", "son", "daughter", "pedestrian")  # fmt: skip
_OF_AGE = re.compile(
    rf"\b({'|'.join(_PEOPLE)})s?\s+of\s+{_AGE_HEDGE}{_AGE_NUMBER}(?:\s*(?:-|to|or)\s*{_AGE_NUMBER})?\b" + _NO_UNIT_AFTER
)


def _ages_after(text: str) -> str:
    """``text`` without a person's age said after them ("a boy aged about 8", "a lad of 15"): it says
    who they are, not how fast anyone goes."""
    return _OF_AGE.sub(lambda m: m.group(1), _AGED.sub("", text))


#: A name joined by underscores with a number in it ("scooter_follow_pass_03", "fcw_stopngo_12", "car_1"):
#: the identifier a test spec or a log gives a scenario or a road user.
_IDENTIFIER = re.compile(r"\b(?=[a-z0-9_-]*\d)(?=[0-9_-]*[a-z])[a-z0-9-]+(?:_[a-z0-9-]+)+\b")


def _identifier_named(m: re.Match, known_noun) -> str:
    """The road users an identifier names (``m``; "car_1": "car", "ped_2": "ped"), and nothing of the rest: the
    words of a scenario's name ("scooter_follow_pass_03", "cutin_hard_brake_2") label the test, they
    are not what its road users do (that is said in its text)."""
    words = [part for part in m.group().split("_") if part.isalpha()]
    if len(words) == 1:
        return words[0]  # ("ped_2", "veh_01": the road user numbered)
    return " ".join(w for w in words if known_noun(w) == w)


#: "Lead" opening a clause before the word after it ("; lead hard brakes to 0", "then the lead slows").
_LEAD_SUBJECT = re.compile(r"(?:^|(?<=[.;:,!?])|(?<=\band\b)|(?<=\bthen\b)|(?<=\bwhen\b))(\s*(?:the )?)(lead|leader)"
                           r" ([a-z]+)")  # fmt: skip


def _lead_as_a_noun(m: re.Match, known_noun) -> str:
    """The lead vehicle, where "lead" is said alone as a clause's subject before its verb or an adverb
    ("lead hard brakes", "the lead slows", "leader suddenly stops"), as a test spec shortens it; not
    "lead car" (already its noun) nor "lead to" (the verb)."""
    after = m.group(3)
    found = lemmas(after)
    verb_like = ("VERB" in found and after.endswith(("s", "ed"))) or "ADV" in found
    if known_noun(after) or after in ("to", "vehicle", "vehicles", "veh") or not verb_like:
        return m.group()
    opening = m.group(1) if "the" in m.group(1) else f"{m.group(1)}the "  # (the one named before)
    return f"{opening}lead vehicle {after}"


#: A side said and at once taken back ("from the right, no, sorry, from the left", "on my right, I mean
#: my left", "the left... correction, the right"): its preposition and owner, the words of taking it
#: back, then the side put right with or without its own.
_SIDE_TAKEN_BACK = re.compile(
    r"\b((?:from|on|to|off|towards?)\s+)?((?:the|my|our|his|her|its)\s+)?(?:left|right)\b[\s,.;:\u2013\u2014-]*"
    r"(?:(?:no|sorry|wait|oops|correction|rather|i mean|i meant|or rather|i should say|my bad)[\s,.;:\u2013\u2014-]+)+"
    r"((?:from|on|to|off|towards?)\s+)?((?:the|my|our|his|her|its)\s+)?(left|right)\b"
    r"(?![\s-]*(?:turns?\b|on red|of way))"  # (not "no right turn", "no right of way": a sign, a rule)
)


def _side_put_right(m: re.Match) -> str:
    """The side a speaker put right, with the preposition and owner said first where the repair
    leaves them out ("from the right, sorry, left": "from the left"). Why: read as said, both sides
    were phrases of the road user and the first one won."""
    prep, owner = m.group(3) or m.group(1) or "", m.group(4) or m.group(2) or ""
    return f"{prep}{owner}{m.group(5)}"


#: Arrows ("->", "=>", "-->", "\u2192"), with the spaces around them: a note's "what follows from it".
_ARROW = re.compile(r"\s*(?:-+>|=+>|[\u2190-\u21ff\u27f6\u27f9])+\s*")
#: Arrows between values, at least one with its speed unit ("slows 50 -> 30 km/h", "SV 68 mph -> 49 mph",
#: "80 -> 60 -> 40 km/h"): a change of speed, from the first value to the last (no range, and the first is
#: what it was). Not a lane, a count or a time ("lane 1 -> 2", "3 -> 2 lanes"), nor a limit ("limit 50 -> 30").
_SPEED_UNIT = r"(?:km/h|km/hr|kmh|kph|kmph|mph|m/s)\b"
_ARROW_ONLY = r"(?:-+>|=+>|[\u2192\u21d2\u2794\u27f6\u27f9])"
_VALUE_ARROW = re.compile(
    rf"(?<![\w.:\-\u2212])(\d+(?:\.\d+)?)(\s*{_SPEED_UNIT})?"
    rf"((?:\s*{_ARROW_ONLY}\s*\d+(?:\.\d+)?(?:\s*{_SPEED_UNIT})?)+)"
)
_LAST_VALUE = re.compile(rf"{_ARROW_ONLY}\s*(\d+(?:\.\d+)?)(\s*{_SPEED_UNIT})?\s*$")


def _value_arrow(m: re.Match) -> str:
    """``m`` of :data:`_VALUE_ARROW` as "from <first> to <last>" where it is a change of speed, else as written."""
    last = _LAST_VALUE.search(m.group(3))
    limit = re.search(r"\blimits?\W*$", m.string[max(0, m.start() - 12) : m.start()])
    if last is None or limit or not (m.group(2) or last.group(2)):
        return m.group(0)
    return f"from {m.group(1)}{m.group(2) or ''} to {last.group(1)}{last.group(2) or ''}"


def _arrow_break(m: re.Match) -> str:
    """An arrow as a clause break (", "), except between two numbers ("slows 50 -> 30 km/h": a change
    of value) or two letters or sides ("crossing L->R", "left -> right": a direction, read as such below):
    kept as written."""
    text, start, end = m.string, m.start(), m.end()
    before = re.search(r"(\w+)\W*$", text[:start])
    after = re.match(r"\W*(\w+)", text[end:])
    short = (before is not None and len(before.group(1)) == 1) or (after is not None and len(after.group(1)) == 1)
    numbers = before is not None and after is not None and before.group(1).isdigit() and after.group(1).isdigit()
    sides = before is not None and after is not None and {before.group(1), after.group(1)} <= {"left", "right"}
    return m.group(0) if short or numbers or sides else ", "


#: Letters that no accent mark makes: each as the plain letters a keyboard without it writes.
_PLAIN_LETTERS = str.maketrans({"ß": "ss", "ł": "l", "Ł": "L", "ø": "o", "Ø": "O", "đ": "d", "Đ": "D", "ı": "i",
                                "æ": "ae", "Æ": "Ae", "œ": "oe", "Œ": "Oe"})  # fmt: skip


def plain_letters(text: str) -> str:
    """``text`` with its accented letters as plain ones ("piéton" as "pieton", "Fußgänger" as
    "Fussganger", "Hoża" as "Hoza"): a writer of English keeps a word or a name of their own language
    with its accents, and the reader's words are plain letters; read letter by letter, an accent would
    split the word in two ("ho", "a"). Only marks on letters go (canonical decomposition), no symbol
    ("½", "–", "°") changes."""
    if text.isascii():
        return text
    return "".join(_plain_letter(c) for c in text.translate(_PLAIN_LETTERS))


@lru_cache(maxsize=4096)
def _plain_letter(c: str) -> str:
    """``c`` without its marks where that leaves a plain letter ("é" as "e"); any other character as it
    is, so that scripts whose letters decompose into parts of their own (Hangul, kana) stay whole."""
    if c.isascii():
        return c
    base = "".join(x for x in unicodedata.normalize("NFD", c) if not unicodedata.combining(x))
    return base if base and base.isascii() else c


#: Things that lie on a road and are no road user: what falls or is shed from loads, what a storm brings
#: down, what roadworks put out, the generic words for them ("debris", "an object", "lost cargo"). Not what
#: people carry (bags, parcels: "a woman with shopping bags in the road" is a walker) nor signs ("no signs
#: on the road" says none stands there).
_THINGS = (
    r"debris|rubble|junk|pallets?|mattress(?:es)?|obstacles?|objects?|items?|boxes|box|crates?|cartons?|"
    r"bales?|barrels?|drums?|tyres?|tires?|rocks?|boulders?|stones?|bricks?|"
    r"logs?|branch(?:es)?|trees?|planks?|timber|sheets?|plasterboard|boards?|pipes?|poles?|ladders?|"
    r"furniture|sofas?|couch(?:es)?|chairs?|fridges?|tarpaulins?|tarps?|scaffold(?:ing| poles?| boards?)?|"
    r"cones?|barriers?|load|cargo"
)
_A_THING = re.compile(rf"\b(?:{_THINGS})\b")


def lies_on_roads(word: str) -> bool:
    """Whether ``word`` names a thing that lies on a road ("debris", "pallets", "a tree"): what a
    vehicle strikes there is an obstacle of the scene, met as a road user is."""
    return _A_THING.fullmatch(word) is not None


#: A noun phrase of one of them: its article, a measure of it ("a pile of", "a line of"), how it came
#: there or what it is made of, a noun before it after those ("a quantity of plasterboard sheets"; never a
#: bare word before it: "to avoid debris"), and what a bracket says it is ("a static obstacle (lost cargo)").
_ARTICLE = r"(?:an?|the|some|one|two|three|several|a few|a couple of) "
_MEASURE = r"(?:pile|load|piece|pieces|bits|heap|line|row|set|stack|couple|number|quantity|lot|bunch) of "
_HOW = (
    r"(?:fallen|dropped|shed|lost|loose|spilt|spilled|stray|static|stationary|abandoned|large|big|huge|small|"
    r"spare|wooden|metal|plastic|steel|broken|roadworks?|road closed|traffic) "
)
_ONE_THING = (
    rf"(?:(?:{_ARTICLE}(?:{_MEASURE})?|{_MEASURE})(?:{_HOW})*(?:[a-z]+ (?=(?:{_THINGS})\b))?|(?:{_HOW})+)?"
    rf"(?:{_THINGS})\b(?: \([^()]{{0,60}}\))?"
)
#: One such noun phrase, or two joined ("a line of cones and a road closed sign"): they lie there together.
_THING = rf"{_ONE_THING}(?: and {_ONE_THING})?"
#: How a thing lies somewhere: a verb of lying or of having fallen there ("left", not "left of").
_LIES = (
    r"lying|lay|laying|sitting|sat|left(?! (?:of|side|hand|lane)\b)|standing|stood|stuck|fallen|dropped|strewn|"
    r"scattered|spilt|spilled|blocking"
)
#: Where a thing lies when no verb says it: in, on or across a lane, the carriageway or the road ("a tree on
#: the left" is by the road).
_IN_A_LANE = (
    r"(?:all )?(?:in|on|across|over) (?:the middle of )?(?:(?:the |my |our |his |her |its |their |ego |"
    r"the ego 's |the ego's )?(?:[a-z0-9-]+ ){0,2}(?:lane|lanes|carriageway)|(?:the )?(?:road|roadway))\b"
)
#: A thing lying in a lane (by a verb of lying, or by being in a lane), or one a vehicle reveals by moving
#: away ("revealing a mattress"): only a thing said to lie there stands in a lane ("a tree on the left" does
#: not, and neither does "a load of bricks on its trailer").
_THING_IN_THE_LANE = re.compile(
    rf"\b(?:(revealing|reveals|revealed|reveal|exposing|exposes|exposed|expose|uncovering|uncovered) )?"
    rf"{_THING}(?(1)|(?= (?:{_LIES}|(?:is |are |was |were |now |still )?{_IN_A_LANE})))"
)

#: Where a thing lying in a lane came from ("boxes fallen from some truck", "having apparently fallen from an
#: unidentified vehicle"): a vehicle gone by, which the scene does not have.
_FALLEN_FROM = re.compile(
    r"\b(a stationary obstacle\b[^.;!?]{0,80}?)(?:,? (?:having |which had |that had |that )?(?:[a-z]+ly )?"
    r"(?:fallen|fell|dropped|been dropped|been shed|been lost|come|came|blown|blew) (?:off|from|out of) "
    r"(?:the back of )?(?:an? |the |some |one |another )?(?:[a-z-]+ )?"
    r"(?:lorry|lorries|truck|trucks|van|trailer|vehicle|car|pickup|ute|hgv|lgv|wagon|tipper|load)s?\b)"
)


#: A question of how fast the one asked was going ("How fast were you going?", "What speed were you
#: doing?", "And your speed?", "Ms Lee, your speed?"), to the end of its question mark; or one that names
#: nobody, asked as a question of its own (group ``bare``: "Speed?", "At what speed?", "How fast?"), which
#: in a transcript's turn is put to the one who answers unless a road user was just named.
_SPEED_QUESTION = re.compile(
    r"\b(?:how\s+(?:fast|quick(?:ly)?)\s+(?:were|was|are|r)\s+(?:you|u|ya)\b|(?:at\s+)?what\s+speed\s+(?:were|was|are|did)\s+"
    r"(?:you|u)\b|what\s+was\s+(?:your|ur)\s+speed\b)[^?\n]*\?|(?:^|(?<=[:.?!,])|\band\b)[ \t]*(?:your|ur)\s+speed\s*\?"
    r"|(?P<bare>(?:^|(?<=[:.?!]))[ \t]*(?:(?:and\s+)?(?:at\s+what\s+)?speed|(?:and\s+)?how\s+fast)\s*\?)",
    re.IGNORECASE | re.MULTILINE,
)
#: A second question asked with the first ("What speed were you doing, and how old are you?"): the answer
#: may be to either.
_SECOND_QUESTION = re.compile(r"\band\s+(?:how|what|where|when|who|why|did|do|were|was|are|is|have|had)\b", re.I)
#: ... or just before it, of something a number may also answer ("How far from the exit? How fast?").
_OTHER_QUESTION = re.compile(r"\b(?:how\s+(?:far|long|old|many|much)|where|when|what\s+time|distance)\b[^?]*\?", re.I)
#: A speaker's label opening a turn of a transcript ("C:", "Caller:", "A:", "[15:42] Driver:", "Call taker:"):
#: one to three words.
_SPEAKER = r"[ \t]*(?:\[[^\]\n]*\][ \t]*)?(?:[a-z][a-z0-9.'/-]*(?: [a-z0-9.'/-]+){0,2}:"
_TURN_LABEL = re.compile(_SPEAKER + r")[ \t]*", re.I)
#: ... or, in a deposition or a cross-examination (a text with a line opening "Q.", or lines opening "A." and
#: none "B."), its "Q." and "A." too (elsewhere "a." opens a list's item).
_DEPOSITION_LABEL = re.compile(_SPEAKER + r"|[qa]\.(?=[ \t]))[ \t]*", re.I)
_LINE_OPENING = re.compile(r"^[ \t]*([qab])\.[ \t]", re.I | re.MULTILINE)
#: Whom a question is put to, right before it, after the turn's other sentences ("Thank you. Ms. Lindqvist,
#: your speed?", "Officer Murray, how fast were you going?"): a title and a name, or a name of one or two
#: capitalised words, and a comma; not a clause that tells the question ("The cop asked, how fast ...").
_VOCATIVE = re.compile(
    r"(?:^|[.?!][ \t]+)(?:(?i:mr|mrs|ms|miss|mx|dr|sir|madam|officer|constable|sergeant|sgt|inspector|detective|"
    r"witness)\.?(?: [A-Z][A-Za-z'-]+){0,2}|[A-Z][a-z'-]+(?: [A-Z][a-z'-]+)?),$"
)
#: The first number of an answer, in figures or words.
_ANSWER_NUMBER = re.compile(rf"\b(\d+(?:\.\d+)?|{_NUMBER_SAID})\b", re.IGNORECASE)
#: What may stand in an answer before its number: fillers, hedges and a yes or no ("Um, maybe thirty",
#: "Not fast, fifteen", "Oh God, I don't know, forty?"), and nothing that says what the number is of
#: ("I'm 82", "the limit is 30", "he did 50").
_ANSWER_FILLERS = frozenset(
    "um uh er erm ah oh hmm well yeah yes yep no nope so like about around maybe probably roughly approximately "
    "only just not fast slow slowly very really quite i think reckon guess dunno don't do know sure say god "
    "sorry honestly uh-huh".split()
)
#: A unit of length after an answer's number, ending the phrase ("90 kilometres.", "40 miles?"): the speed
#: asked for in that unit per hour.
_ANSWER_LENGTH_UNIT = re.compile(r"\s*(miles|kilomet(?:er|re)s|km)(?=\s*(?:[.!?;]|$))", re.IGNORECASE | re.MULTILINE)
#: What may follow an answer's number: its end, a mark, a unit of speed, a range's second number or a hedge.
_ANSWER_ENDS = re.compile(
    rf"\s*(?:[.,?!;)]|$|-|(?:mph|km/h|kph|kmh|ks?|tops|max|maximum|ish|maybe|probably|at\s+most|at\s+least|odd|"
    rf"plus|i\s+think|i\s+reckon)\b|(?:or|to)\s+(?:\d|{_NUMBER_WORD})|{_ANSWER_LENGTH_UNIT.pattern})",
    re.IGNORECASE,
)


#: What :func:`speed_answered` puts before an answer's number ("i was doing 30").
ANSWER_SAID = "i was doing "


def _the_answer(text: str, q: re.Match, labels: re.Pattern, known_noun) -> int | None:
    """Where the answer to the question ``q`` starts: after the label (``labels``) of the next speaker's
    turn, on the same line or the next; None where the question is not itself a labelled turn (a question
    told in a story: "I asked the rider: how fast were you going?"), is asked with another ("How far? How
    fast?"), asks without "you" just after a road user is named ("A motorbike flew past. / CT: How
    fast?", "And the van? Speed?": that one's speed), or no turn follows."""
    line_start = text.rfind("\n", 0, q.start()) + 1
    own = labels.match(text, line_start)
    begins = q.start() + len(q.group(0)) - len(q.group(0).lstrip())
    if own is None or own.end() > begins or _SECOND_QUESTION.search(q.group(0)):
        return None
    asked = text[own.end() : begins].rstrip()
    if _OTHER_QUESTION.search(asked):
        return None
    if asked and not asked.lower().endswith((".", "?", "!", "and", "ok", "okay", "so", "right")):
        if not _VOCATIVE.search(asked):
            return None  # ("Driver: The cop asked how fast were you going?": a question told, not asked)
    if q.group("bare"):  # (what was said on this line and the one before, past the speakers' labels)
        said_before = text[text.rfind("\n", 0, max(line_start - 1, 0)) + 1 : begins].split("\n")
        if any(known_noun(line[(m.end() if (m := labels.match(line)) else 0) :].lower()) for line in said_before):
            return None
    label = labels.match(text, q.end())
    if label is None:
        line_end = text.find("\n", q.end())
        if line_end < 0 or text[q.end() : line_end].strip():
            return None
        label = labels.match(text, line_end + 1)
    return None if label is None else label.end()


def _answers(text: str, question: re.Pattern, known_noun) -> list[tuple[int, int]]:
    """Where each question of ``question``'s kind put in a turn of ``text`` starts, and where its answer
    does (see :func:`_the_answer`); the turns are a deposition's "Q."/"A." where those open its lines,
    else its speakers' labels."""
    openings = {m.group(1).lower() for m in _LINE_OPENING.finditer(text)}
    labels = _DEPOSITION_LABEL if "q" in openings or openings == {"a"} else _TURN_LABEL
    found = ((q.start(), _the_answer(text, q, labels, known_noun)) for q in question.finditer(text))
    return [(asked, start) for asked, start in found if start is not None]


def speed_answered(text: str, known_noun=lambda phrase: None) -> str:
    """``text`` with the answer to a question of the one asked's speed said as a speed ("CT: How fast were
    you going? / C: Twenty? Not even. Twenty.": "C: i was doing Twenty, Not even. ..."; "Q: What speed
    were you doing? A: 30, about."). Why: in a transcript of a call, an interview or a cross-examination
    the speed is the answer's first number, said bare, with no verb before it. Only a number that opens
    the answer (past fillers and hedges) and ends its phrase (a mark, a unit of speed, a range, a hedge)
    is one: "I'm 82", "the limit is 30", "3 cars ahead" are left as said. ``known_noun(phrase)``: the
    road-user noun a phrase ends in, or None."""
    out, at = [], 0
    for asked, start in _answers(text, _SPEED_QUESTION, known_noun):
        if asked < at:
            continue
        answer = text[start : start + 80].split("\n")[0]
        number = _ANSWER_NUMBER.search(answer)
        if number is None or not _ANSWER_ENDS.match(answer, number.end()):
            continue
        before = re.findall(r"[a-z'-]+", answer[: number.start()].lower())
        if any(w not in _ANSWER_FILLERS for w in before):
            continue
        out += [text[at : start + number.start()], ANSWER_SAID, number.group(0)]
        at = start + number.end()
        unit = _ANSWER_LENGTH_UNIT.match(text, at)
        if unit is not None:  # ("90 kilometres.": a speed's unit said short, as its length)
            out.append(" mph" if unit.group(1).lower() == "miles" else " km/h")
            at = unit.end()
        if text.startswith("?", at):  # ("Twenty? Not even.": a guess said as a question, still the answer)
            out.append(",")
            at += 1
    return "".join(out) + text[at:]


#: A question of the way the one asked went through a junction ("Which way were you going?", "Were you
#: turning left or right?"); its answer's first word says the ego's route. (The group ``bare`` never
#: matches: a question of way is always put to "you".)
_ROUTE_QUESTION = re.compile(
    r"\b(?:which\s+(?:way|direction)\s+(?:were|was|are)\s+(?:you|u)\s+(?:going|travelling|traveling|heading|headed|"
    r"turning|driving|riding|coming)\b|were\s+(?:you|u)\s+(?:turning|going)\s+(?:left|right|straight(?:\s+on)?)\s+or\b"
    r"|where\s+were\s+(?:you|u)\s+turning\b)[^?\n]*\?(?P<bare>(?!))?",
    re.IGNORECASE,
)
#: The answer's way and what ends it: a mark, the line's end, or the words that go with a way ("Left
#: into Church Street", "Straight on"); a comma only after "left" or "straight" ("Right, so I was ..."
#: opens a sentence, no way).
_ROUTE_ANSWER = re.compile(
    r"(?:(left|straight)\b(?=\s*,)|(left|right|straight)\b(?=\s*(?:[.;!]|$|into\b|onto\b|across\b|on\b)))"
    r"|(straight)\b(?=\s+ahead\b)",
    re.I,
)
#: Words that may open an answer before its way; a denial ("not", "no") is none: "Not left, ..."
_ROUTE_FILLERS = _ANSWER_FILLERS - {"not", "no", "nope", "never"}
#: What is put before an answer's way: the ego's turn or its going straight on.
ROUTE_SAID = {"left": "i was turning ", "right": "i was turning ", "straight": "i was going "}


def route_answered(text: str, known_noun=lambda phrase: None) -> str:
    """``text`` with the answer to a question of the way the one asked went said as the ego's route
    ("DC Smith: Which way were you going? / Suspect: Left. Towards the roundabout.": "Suspect: i was
    turning Left. ..."). Why: in an interview or a cross-examination the way is the answer's first
    word, said bare; only one that opens the answer (past fillers, not a denial) and ends its phrase
    is read, so "Left the house at eight", "Right, so I was ...", "Not left" stay as said; a question
    of which way the one asked looked, faced or was thrown asks no way of going."""
    out, at = [], 0
    for asked, start in _answers(text, _ROUTE_QUESTION, known_noun):
        if asked < at:
            continue
        answer = text[start : start + 80].split("\n")[0]
        way = None
        for word in re.finditer(r"[A-Za-z'-]+", answer):
            if _ROUTE_ANSWER.match(answer, word.start()):
                way = word
                break
            if word.group(0).lower() not in _ROUTE_FILLERS:
                break
        if way is None:
            continue
        out += [text[at : start + way.start()], ROUTE_SAID[way.group(0).lower()]]
        at = start + way.start()
    return "".join(out) + text[at:]


#: "HV" is a host vehicle (the ego) in a safety analysis and a heavy vehicle (a lorry) in an Australian or
#: New Zealand crash report: the lorry where said with "a"/"an", in the plural, or placed by the narrator
#: ("the HV in front of me braked").
_HEAVY_VEHICLE = re.compile(
    r"\b(?:an?\s+hv|hvs)\b|\bhv\s+(?:in front of|ahead of|behind|beside|next to|alongside)\s+(?:me|us|my|our)\b"
)


def _heavy_vehicles(text: str) -> str:
    """``text`` with "HV" said as a heavy vehicle (:data:`_HEAVY_VEHICLE`) written as a lorry, everywhere in it."""
    if not _HEAVY_VEHICLE.search(text):
        return text
    return re.sub(r"\bhv(s?)\b", r"lorry\1", text).replace("lorrys", "lorries")


#: An hour said in words before its half of the day with the dots ("seven a.m.", "ten p.m"): a clock.
_HOUR_WORD_HALF = re.compile(r"\b(one|two|three|four|five|six|seven|eight|nine|ten|eleven|twelve)\s+([ap])\.\s?m\b\.?")


#: "camera car" after a word that describes it or an indefinite article ("the Street View camera car", "a
#: police camera car", "a camera car"): somebody else's car that carries a camera, not the clip's own.
_DESCRIBED_CAMERA_CAR = re.compile(r"\b([a-z][a-z-]*) camera (car|vehicle|van)\b")
#: Words that may stand before the clip's own camera car ("from the camera car", "then camera car brakes").
_BEFORE_OWN_CAMERA_CAR = DETERMINERS | PHRASE_ENDS | CLAUSE_BREAKS | BE | {"so", "then", "as", "while", "when"}


def _camera_car(m: re.Match) -> str:
    own = m.group(1) in _BEFORE_OWN_CAMERA_CAR and m.group(1) not in ("a", "an", "another")
    return m.group(0) if own else f"{m.group(1)} {m.group(2)}"


#: The camera car placed from the narrator ("the camera car in front of me"): another's.
_CAMERA_CAR_FROM_ME = re.compile(
    r"\bcamera (car|vehicle|van)(?= (?:in front of|ahead of|behind|beside|next to) (?:me|us)\b)"
)


#: Amounts of traffic said in other words, as the reader's densities ("traffic was medium": moderate).
_TRAFFIC_AMOUNTS = {
    "medium": "moderate", "small": "light", "little": "light", "low": "light", "dense": "heavy", "high": "heavy",
    "strong": "heavy",
}  # fmt: skip


#: A point after a word with its own capital (and a small letter after it: "behind a VW. the cyclist"
#: ends a sentence whose next capital was missed), then spaces and a word in lower case ("out of
#: Hauptstr. from the right", "near the Co. depot"); and a sentence's first letter after its end.
_POINT_THEN_LOWER = re.compile(r"\b([A-Z][a-z][A-Za-z]*)\.(?=[ ]+[a-z])")
_SENTENCE_START = re.compile(r"[.!?][ ]+([A-Za-z])")


def abbreviation_points(text: str) -> str:
    """``text`` (as written, before it is lowercased) without the points of abbreviations: where its
    writer starts sentences with a capital (most of the letters after a sentence's end are), a point
    after a word with its own capital and before a word in lower case ends an abbreviation ("came out
    of Wildenbruchstr. from the right", "Station Rd. at 30"), not a sentence, and what follows still
    belongs to the clause. A writer who types in lower case ends sentences so, and is left as written;
    so is a point after a word in lower case (the reader's own rewording may put one there)."""
    starts = [m.group(1) for m in _SENTENCE_START.finditer(text)]
    upper = sum(c.isupper() for c in starts)
    if upper < 2 or upper < 2 * (len(starts) - upper):
        return text
    return _POINT_THEN_LOWER.sub(r"\1", text)


def normalise(text: str, known_noun=lambda phrase: None) -> str:
    """``text`` (lowercased) with numbers in words, units, and the parties of a statement said the
    way the reader reads them. ``known_noun(phrase)`` returns the road-user noun a phrase ends in,
    or None."""
    text = _heavy_vehicles(text)
    text = lettered_parties(text, known_noun)  # ("Vehicle B: Transit van ... B reversed": the van reversed)
    text = _DESCRIBED_CAMERA_CAR.sub(_camera_car, text)  # ("the speed camera car": a car of its own)
    text = _CAMERA_CAR_FROM_ME.sub(r"\1", text)  # ("the camera car in front of me": not the one I drive)
    text = imperative_as_ego(text)  # ("Follow a decelerating van": we follow it)
    # "ran his red", "passing their red light": the runner's own signal is the red light, said as any is
    text = re.sub(r"\b(?:his|her|their|its)\s+(?=red\b)", "the ", text)
    # a list (bullets, numbered steps, one item a line): each item its own sentence
    text = re.sub(r"^\s*(?:[-*\u2022\u00b7\u2013]|\d{1,2}[.)])\s+", "", text)
    text = re.sub(r"\s*\n\s*(?:(?:[-*\u2022\u00b7\u2013]|\d{1,2}[.)])\s+)?", ". ", text)
    text = re.sub(r"\s*\|\s*|\s+/\s+", ". ", text)  # fields between bars or spaced slashes: one a sentence
    text = re.sub(r"[ ]*\t\s*", ". ", text.strip("\t"))  # (the cells of a row pasted from a sheet, as bars)
    text = said_in_order(text, known_noun)  # ("from the left comes a cyclist": "a cyclist comes from the left")
    # an arrow of a note ("no braking -> impact") ends a clause as a comma does: what stands before it
    # does not govern what follows
    text = _VALUE_ARROW.sub(_value_arrow, text)
    text = _ARROW.sub(_arrow_break, text)
    # a spaced dash before a word ("light rain - delivery truck ...", "triggered 22:16 - lead vehicle"): a
    # break in the sentence, as a comma is (between numbers, "30 - 40 km/h", it is a range)
    text = re.sub(r"(?<=[^\W_])\s+[-\u2013\u2014]\s+(?=[^\W\d_])", ", ", text)
    text = _SIDE_TAKEN_BACK.sub(_side_put_right, text)
    # "@ 3 m/s", "car@30kph": the shorthand for "at" before a number, so the number keeps the grammar of
    # "at 3 m/s" (said of the one that acts), not of a bare number after a noun
    text = re.sub(r"\s*@\s*(?=[~\d])", " at ", text)
    text = _HOUR_WORD_HALF.sub(lambda m: f"{_ONES[m.group(1)]} {m.group(2)}m", text)  # ("seven a.m.": "7 am")
    text = re.sub(r"(\d)\s*([ap])\.\s?m\.?", r"\1 \2m", text)  # "6 a.m.": "6 am" (no sentence ends there)
    text = re.sub(r"(\d)([ap]m)\b", r"\1 \2", text)  # "6pm": "6 pm"
    # the reader addressed ("you're doing 50 km/h", "your lane", "you brake hard"): the ego, as "I" is
    text = re.sub(r"\byou(?:'re| are| were)\b", "i am", text)
    text = re.sub(r"\byour\b", "my", text)
    text = re.sub(
        r"\byou(?= (?:just |then |also )?(?:brake|stop|pass|slow|swerve|drive|turn|overtake|follow|approach|hit|"
        r"rear-end|go|come|get|see|keep|manage|miss)\w*)",
        "i",
        text,
    )
    # the reader addressed before a modal of what will or must be done and a verb of driving ("you'll be
    # driving at 80 km/h", "you will follow", "you should be doing 50", "you must keep to 40"): the ego's, as
    # what they do is (not one of permission or chance: "then you can go", "you may see")
    text = re.sub(
        r"\byou(?=(?:'ll|'d| will| would| should| must| shall)(?: not| then| also| just| now| first)?(?: be)? "
        r"(?:brak|stop|pass|slow|swerv|driv|turn|overtak|follow|approach|go|com|keep|travel|rid|mov|cruis|head|"
        r"do|at|enter|reach|leav|merg|chang|join|exit|pull)\w*)",
        "i",
        text,
    )
    text = _IDENTIFIER.sub(lambda m: _identifier_named(m, known_noun), text)
    text = _LEAD_SUBJECT.sub(lambda m: _lead_as_a_noun(m, known_noun), text)
    text = _acronyms_defined(text, known_noun)
    text = _HEADS_UP.sub("note", text)
    text = _SAID_AGAIN_FULLER.sub("", text)  # ("a boy, a boy on a scooter": one boy, on a scooter)
    text = _PARTICIPLE_OPENING.sub(lambda m: _with_article(m, known_noun), text)
    for pattern, repl in _SHORTHAND:
        text = pattern.sub(repl, text)
    text = _FOUR_DIGIT_CLOCK.sub(r"\1:\2", text)
    text = _CLOCK_WITH_H.sub(_clock_with_h, text)  # ("around 8h", "18h30")
    # "..., PM." / "Snowing, AM": the half of the day said alone
    text = re.sub(r"(^|[,.;:]\s*)am(?=\s*(?:[,.;!]|$))", r"\1morning", text)
    text = re.sub(r"(^|[,.;:]\s*)pm(?=\s*(?:[,.;!]|$))", r"\1afternoon", text)
    # "the sun was going down": sunset
    text = re.sub(r"\b(?:the )?sun (?:was |is )?(?:going down|setting|low in the sky)\b", "sunset", text)
    # "traffic: none", "background traffic density: high", "density: moderate": the traffic said as a field
    text = re.sub(
        r"\b(?:(?:background )?traffic(?: density)?|density)\s*:\s*"
        r"(none|nil|zero|light|low|moderate|medium|heavy|high)\b",
        lambda m: {"nil": "no traffic", "zero": "no traffic", "none": "no traffic", "low": "light traffic",
                   "medium": "moderate traffic", "high": "heavy traffic"}.get(m.group(1), f"{m.group(1)} traffic"),
        text,
    )  # fmt: skip
    for pattern, repl in _UNITS:
        text = pattern.sub(repl, text)
    text = _ages_after(_ages(text, known_noun))  # (before numbers in words become digits)
    text = _numbers_in_words(text)
    for pattern, repl in _UNITS:  # ("10 meter per second" once its number is digits)
        text = pattern.sub(repl, text)
    text = _VALUE_ARROW.sub(_value_arrow, text)  # (again, its unit now written as a symbol: "68 -> 49 mi/h")
    text = spoken_lengths.in_digits(text)  # ("a metre", "half a foot": as figures, then as metres)
    text = _LENGTHS.sub(_lengths, text)
    text = _HOUR_OF.sub(_hour_of, text)
    text = re.sub(r"\b(?:approx\.?|approximately|circa|ca\.|roughly|around|maybe|some|like)\s+(?=\d)", "about ", text)
    text = re.sub(r"~\s*(?=\d)", "about ", text)
    # ("at an est. 15 mph", "speed est. 28 mph": "estimated" cut short, whose full stop ends no sentence)
    text = re.sub(r"\b(?:an?\s+)?est(?:\.\s*|\s+)(?=\d)", "about ", text)
    text = re.sub(r"(\d+(?:\.\d+)?)\s*-\s*(?=km/h|mph|m/s|m\b)", r"\1 ", text)
    # "our speed is 100 km/h", "we have 40 km/h", "we are 50 km/h": the ego's speed
    text = re.sub(
        r"\b(?:our|my|the ego's|ego) speed (?:is |was |of |at |:)?\s*(?=(?:about )?\d)", "the ego drives at ", text
    )
    text = re.sub(
        r"\b(we|i) (?:have|are|am|were|was)\s+(?=(?:about )?\d+(?:\.\d+)? (?:km/h|mph|m/s)\b)", r"\1 drive at ", text
    )
    # English without articles ("from opposite direction", "on right side"), and "turning to left"
    text = re.sub(
        r"\b(from|on|at|to|in|into) (?=(?:opposite|left|right|front|same|other|far|near|left-hand|right-hand) "
        r"(?:direction|side|lane|kerb|curb|sidewalk|pavement|footpath)\b)",
        r"\1 the ",
        text,
    )
    text = re.sub(r"\b(turn|turns|turning|turned) to (?:the )?(left|right)\b", r"\1 \2", text)
    # "a van two lanes over": in a lane to the side (which side unsaid), not the road's lanes
    text = re.sub(r"\b(?:one|a|two|three|\d) lanes? (?:over|across)\b", "from the next lane", text)
    # "crossing left to right": from the left
    text = re.sub(r"\b(?:from )?(?:the )?(left|right) to (?:the )?(?:right|left)\b(?! lane)", r"from the \1", text)
    # "traffic was moderate": moderate traffic (the word is then no criticality of what follows)
    text = re.sub(r"\btraffic (?:is|was|were) (?:very |quite |fairly )?(light|moderate|heavy)\b", r"\1 traffic", text)
    # "the traffic was medium", "traffic small", "traffic dense": the amount in a translation's words
    text = re.sub(
        r"\btraffic (?:is |was |were )?(?:very |quite |fairly )?(medium|small|little|low|dense|high|strong)"
        r"(?=\s*(?:[.,;:!?)]|$|\s(?:and|but|so|then|too|as|with|for|on|in|at|today|tonight|this|that)\b))",
        lambda m: f"{_TRAFFIC_AMOUNTS[m[1]]} traffic",
        text,
    )
    text = _own_systems_vehicle(text, known_noun)  # ("Car beeps and does that pre-brake jerk": the ego's system)
    text = _the_car_is_the_ego(text)
    text = _role_is_the_ego(text, known_noun)
    text = _observer(text, known_noun)
    for pattern in _EGO_ALIASES:
        text = pattern.sub("the ego", text)
    text = re.sub(r"\b(?:the )?(?:driver|rider|operator) of the ego\b", "the ego", text)
    text = _EGO_AGAIN.sub("the ego", text)
    text = _other_parties(text, known_noun)
    text = _headings(text)
    text = re.sub(r"\bthe ego's (?:vehicle|car)\b", "the ego", text)
    # "speed of the ego is 25 km/h", "ego: 30 km/h", "like 35 kph for me": the ego's speed
    text = re.sub(r"\bspeed of the ego (?:is |was |:)?\s*(?=(?:about )?\d)", "the ego drives at ", text)
    text = re.sub(r"\bthe ego\s*:\s*(?=(?:about )?\d+(?:\.\d+)? (?:km/h|mph|m/s)\b)", "the ego drives at ", text)
    text = re.sub(
        r"((?:about )?\d+(?:\.\d+)? (?:km/h|mph|m/s)) for (?:me|us|the ego|my car|my vehicle)\b",
        r"the ego drives at \1",
        text,
    )
    text = re.sub(r"\b(let|lets|letting)\s+(?:me|us)\b", r"\1 the ego", text)  # (whom it lets go: the ego)
    # "my line", "right line", "two line for each side": a lane in a learner's English ("stop line" stays)
    text = re.sub(
        r"\b(my|his|her|its|right|left|same|next|other|opposite|inside|outside|middle|one|two|three|four|\d) "
        r"line(s?)\b",
        r"\1 lane\2",
        text,
    )
    # something lying in the lane ("debris lying in our lane", "a pile of fallen pallets", "a sofa lying across
    # lane one", "a static obstacle (lost cargo) in the ego lane", "revealing a mattress"): a standing
    # obstacle, which a vehicle ahead may swerve round and reveal
    if _A_THING.search(text):  # (one quick pass first: most descriptions name no such thing)
        text = _THING_IN_THE_LANE.sub(lambda m: f"{m[1] or ''} a stationary obstacle".lstrip(), text)
    text = _FALLEN_FROM.sub(r"\1", text)  # ("fallen from a lorry": the lorry it came from is no road user here)
    text = re.sub(rf"\b(a stationary obstacle) (?:{_LIES})\b", r"\1", text)
    # "changed to 3rd lane", "changes over to lane 2", "change into the left lane": a move to the lane named
    # (a light that "changed to red" names no lane)
    text = re.sub(
        r"\bchang(e|es|ed|ing)( over)? ((?:in)?to) "
        r"(?=(?:the |my |our |its |his |her )?(?:lane \d|\d(?:st|nd|rd|th) lane|"
        r"(?:first|second|third|fourth|left|right|left-hand|right-hand|middle|centre|center|inside|outside|"
        r"nearside|offside|next|other|adjacent|fast|slow|overtaking|passing) lane)\b)",
        lambda m: {"e": "move", "es": "moves", "ed": "moved", "ing": "moving"}[m[1]] + f"{m[2] or ''} {m[3]} ",
        text,
    )
    # "drifts over into my lane", "is change to my lane": a move into the ego's lane, whatever verb of motion says it
    text = re.sub(
        r"\b(?:is |was )?(?:drift\w*|change|changed|changing|wander\w*|veer\w*|slide|slides|slid|sliding|swing\w*|"
        r"swung|come|comes|came|coming|go|goes|went|going)(?: over| across)? (?:in)?to "
        r"(my|our|the ego's|the ego 's) lane\b",
        r"moves into \1 lane",
        text,
    )
    # "both vehicles continued": the ego and the other after the event, no new pair ("both cars at 50 km/h" stays)
    text = re.sub(
        r"\bboth (?:vehicles|vehicle|cars|parties)(?= (?:continued|carried|stopped|came|remained|were))", "they", text
    )
    # a behaviour said as a noun a road user performs ("performs a lane change", "initiates a crossing
    # manoeuvre", "makes an emergency stop"): said as its verb
    text = _NOMINAL.sub(_as_its_verb, text)
    # "struck the ego on its nearside", "hit me in the rear door": where on the ego's body, not a side of the road
    text = re.sub(
        r"\b((?:struck|strikes|hit|hits|impacted|clipped|collided with|made contact with) (?:the ego|me|us|my car)) "
        r"(?:on|in|at) (?:its|the|my|our) (?:nearside|offside|left|right|front|rear|back|side)[a-z -]*?(?=[,.;!]|$)",
        r"\1",
        text,
    )
    # "the ego was following a lorry", "I'm following a bus": the description opens with the ego
    # following, so what it follows is ahead
    text = re.sub(
        r"^(?:the ego|i|we)(?: (?:am|is|are|was|were|also|just|then))* (?:follow|follows|followed|following|tailing) "
        r"(?=[a-z])",
        "following ",
        text,
    )
    return text
