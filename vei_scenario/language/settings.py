"""The settings a description states (time of day, traffic, weather, lanes, road), where the words that
state them are weighed against each other rather than taken first-said or most-severe.

Why: people state a setting more than once and in words of different precision. "My usual commute, a
grey morning" names the morning; "commute" only hints at an hour. "17:30, autumn evening" gives a clock
and the light the writer means. "Wet track, overcast sky" says what the road surface is and what the
sky is. "A quiet lane with not another car about" says there is no traffic at all. "A two-lane highway"
with a car coming head-on is one lane each way, "a two-lane roundabout" two lanes going round. Turning
into a road ("into Church Lane", "into a side street") means the road has a junction there, whatever
else the text calls the road. Each rule below is one such construction; none names a corpus sentence.
"""

from __future__ import annotations

import re
from collections import Counter
from collections.abc import Callable

from vei_scenario.language import lexicon as L
from vei_scenario.language.lemmas import lemmas
from vei_scenario.language.vocabulary import STREET_WORDS as ROAD_NAME_ENDS

#: Time words that tell the light or the traffic, not the hour: a part of the day said with them wins.
TIME_HINTS = frozenset(
    "dark|darkness|pitch black|pitch-black|pitch dark|after dark|daylight|daytime|broad daylight|during the day|"
    "by day|rush hour|commute".split("|")
)
#: The hours (first, last) each of the lexicon's times of day covers, by the clock the lexicon gives it.
PART_OF_DAY_HOURS = {
    "23:00": (21, 5),  # night
    "02:00": (0, 5),  # the small hours
    "06:00": (5, 7),  # dawn, early morning
    "08:30": (6, 11),  # morning
    "12:00": (11, 13),  # noon
    "15:30": (12, 17),  # afternoon
    "19:30": (18, 21),  # dusk
    "20:00": (18, 22),  # evening
}
#: How far (hours) a clock may lie outside the part of the day said beside it and still be read within it
#: ("17:40, evening": early evening, 18:00); further off, the clock is what the writer means.
CLOCK_SLACK_H = 1
#: Slots of the settings a hyphenated compound may spell ("rush-hour", "mid-afternoon").
SETTING_SLOTS = frozenset({"time", "density", "weather", "map", "lanes"})
#: Weather words that say what the road surface is, not the sky: a sky word said with them wins.
SURFACE_WORDS = frozenset({"wet", "dry", "damp"})


#: Words that deny the setting word right after them ("no rain", "wasn't foggy", "not dark yet").
NEGATORS = frozenset({"no", "not", "never", "without", "nor"})
#: Words that may stand between a negator and its setting word ("not very foggy", "not any rain").
_DEGREE = frozenset({"very", "too", "that", "really", "particularly", "especially", "a", "any", "much", "even"})


def negated(tokens: list[str], i: int) -> bool:
    """Whether the setting word at ``i`` is denied by the word before it (past one word of degree):
    a denied weather, time or traffic is not the scenario's ("no rain, clear skies")."""
    k = i - 1
    if k >= 0 and tokens[k] in _DEGREE:
        k -= 1
    return k >= 0 and tokens[k] in NEGATORS


#: Verbs that end a weather ("the rain had stopped", "light rain ended", "stopped raining"): what has
#: ended is not the weather the scene is in.
ENDING_VERBS = frozenset({"ended", "stopped", "cleared", "ceased", "eased", "finished", "passed", "lifted", "gone"})
#: Conjunctions that set a later state against an earlier one ("foggy earlier, but that has cleared").
_CONTRAST = frozenset({"but", "though", "although", "yet", "however"})
_SENTENCE_END = frozenset({".", ";", "!", "?"})


def ended(tokens: list[str], i: int, n: int) -> bool:
    """Whether the weather word at ``i`` (``n`` words) is said to have ended: an ending verb right
    after it (past "had", "has", "just") or right before it ("had stopped raining"), or in a clause set
    against it later in its sentence ("misty first thing, but it has lifted now")."""
    k = i + n
    while k < len(tokens) and tokens[k] in ("had", "has", "just", "already", "finally"):
        k += 1
    if (k < len(tokens) and tokens[k] in ENDING_VERBS) or (i > 0 and tokens[i - 1] in ENDING_VERBS):
        return True
    for j in range(i + n, min(len(tokens), i + n + 8)):
        if tokens[j] in _SENTENCE_END:
            return False
        if tokens[j] in _CONTRAST:
            return _ends_clause(tokens[j + 1 : j + 7])
    return False


def _ends_clause(words: list[str]) -> bool:
    """Whether a clause ``words`` after a contrast says that something ended, with a pronoun or a
    weather noun as its subject ("that has cleared", "it had all lifted", "the fog has gone")."""
    for k, w in enumerate(words):
        if w in _SENTENCE_END or w == ",":
            return False
        if w in ENDING_VERBS and k > 0:
            if words[0] in _WEATHER_NOUNS or (words[0] == "the" and words[1] in _WEATHER_NOUNS):
                return True
            # (a pronoun may be a road user: "but it stopped in time" is a vehicle, "it has cleared" the sky)
            return words[0] in ("that", "this") or (words[0] == "it" and w not in ("stopped", "passed", "finished"))
    return False


_WEATHER_NOUNS = frozenset({"rain", "fog", "mist", "snow", "drizzle", "haze", "shower", "showers", "sleet"})


#: Prepositions, a closed class: a compound starting with one modifies ("in-car commentary").
_PREPOSITIONS = frozenset("in on off out over under up down by through inside outside within after non".split())


def compound_words(token: str, slot_of: Callable[[tuple[str, ...]], str | None]) -> list[str]:
    """A hyphenated token the reader has no entry for, as its words when they are a setting phrase
    ("rush-hour": "rush hour") or a modifier before a time of day or a road word ("mid-afternoon":
    "mid afternoon", "mini-roundabout": "mini roundabout"), or a modifier before a road user's noun
    (an English compound names what its head does: "tow-truck" is a truck, "camper-van" a van)."""
    if "-" not in token or slot_of((token,)) is not None:
        return [token]
    parts = [p for p in token.split("-") if p]
    # (a preposition first makes a modifier, not a noun: "in-car", "off-truck" name no road user)
    head_actor = slot_of((parts[-1],)) == "actor" and parts[0] not in _PREPOSITIONS
    if len(parts) < 2 or (slot_of((parts[0],)) == "actor" and not head_actor):  # ("bus-lane": no road user)
        return [token]
    if slot_of(tuple(parts)) in SETTING_SLOTS or slot_of((parts[-1],)) in ("time", "map") or head_actor:
        return parts  # ("mini-roundabout", "Y-junction": a road by its head word)
    return [token]


def time_of_day(said: list[tuple[str, str]], clock: str | None) -> str | None:
    """The scenario's time from the time words ``said`` in order as (words, clock) and a clock stated in
    the text: a part of the day over a hint of one, the first of equals; a clock over both, read within
    the part of the day said beside it when it lies just outside it."""
    parts = [value for words, value in said if words not in TIME_HINTS]
    part = parts[0] if parts else (said[0][1] if said else None)
    if clock is None:
        return part
    if not parts or parts[0] not in PART_OF_DAY_HOURS:
        return clock
    first, last = PART_OF_DAY_HOURS[parts[0]]
    hour = int(clock.split(":")[0])
    if _within(hour, parts[0]):
        return clock
    before, after = (first - hour) % 24, (hour - last) % 24
    if before <= CLOCK_SLACK_H:
        return f"{first:02d}:00"
    if after <= CLOCK_SLACK_H:
        return f"{last:02d}:00"
    return clock


#: A clock with a one-digit hour of the afternoon's first hours and no half of the day said ("at 3:15",
#: in the reader's tokens "3 : 15"): a twelve-hour clock, as people write one.
_TWELVE_HOUR = re.compile(r"(?<![\d:] )(?<!\d)\b([1-6])(?: : |\.)[0-5]\d\b(?! (?:am|pm|hrs|hours|h)\b)")


def twelve_hour(clock: str | None, said: str, parts: list[str]) -> str | None:
    """``clock`` read as the afternoon's where it is written as people write a twelve-hour clock ("at
    3:15") and no part of the day said beside it puts it in the small hours or the morning (``parts``:
    the clocks of the parts of the day said): a driver outside a school at 3:15 means 15:15. A clock
    with its half said right after it is read in that half ("7:15 at night": 19:15, "2:30 at night":
    02:30, "8:40 in the evening": 20:40)."""
    if clock is not None and 1 <= int(clock[:2]) <= 12:  # ("7:15 at night", "8:40 in the evening")
        hour, minute = int(clock[:2]), clock[3:]
        half = re.search(rf"\b0?{hour} : {minute} (?:in the (?:afternoon|evening)|at night|tonight)\b", said)
        if half is not None and "night" in half.group(0):  # ("2:30 at night": the small hours; "7:15 at night")
            return f"{0 if hour == 12 else hour if hour <= 5 else hour + 12:02d}:{minute}"
        if half is not None:
            return f"{hour % 12 + 12:02d}:{minute}"
    if clock is None or _TWELVE_HOUR.search(said) is None or int(clock[:2]) > 6:
        return clock
    hour, pm = int(clock[:2]), int(clock[:2]) + 12
    for part in parts:
        if part in PART_OF_DAY_HOURS and (not _within(pm, part) or _within(hour, part)):
            return clock
    return f"{pm:02d}{clock[2:]}"


def _within(hour: int, part: str) -> bool:
    """Whether ``hour`` lies in the part of the day whose lexicon clock is ``part``."""
    first, last = PART_OF_DAY_HOURS[part]
    return first <= hour <= last if first <= last else (hour >= first or hour <= last)


_HOURS = {w: k + 1 for k, w in enumerate("one two three four five six seven eight nine ten eleven twelve".split())}
_MINUTES = {"quarter": 15, "half": 30, "five": 5, "ten": 10, "twenty": 20, "twenty-five": 25, "twenty five": 25}
_HOUR_WORD = r"(one|two|three|four|five|six|seven|eight|nine|ten|eleven|twelve|1[0-2]|[1-9])"
#: "quarter past eight", "twenty to seven", "half past ten", and the British "half five" (half past five).
_NOT_A_CLOCK = r"(?! (?:m|metres|meters|km/h|mph|m/s|seconds|s|hours?|minutes?|cars?|vehicles?)\b)"
_CLOCK_IN_WORDS = re.compile(
    rf"\b(?:a )?(quarter|half|twenty[- ]five|twenty|ten|five|[1-5]?\d(?: minutes)?) (past|after|to|before) "
    rf"{_HOUR_WORD}\b{_NOT_A_CLOCK}|\bhalf {_HOUR_WORD}\b{_NOT_A_CLOCK}"
)
#: Two dates of a span written with slashes ("from 5/12 to 5/16", read "5 12 to 5 16"): no "12 to 5" o'clock.
_DATE_SPAN = re.compile(r"\b\d{1,2} \d{1,2} (?:to|till|until) \d{1,2} \d{1,2}\b")
#: "six o'clock", "7 o'clock": a whole hour, its half of the day said beside it or told by the part of the day.
_OCLOCK = re.compile(rf"\b{_HOUR_WORD} o'?clock\b")
#: An hour and its minutes said as two numbers before the half of the day ("one-forty in the morning",
#: "seven thirty at night", "ten fifteen pm"); without a half said the words may be anything else.
_SPOKEN_MINUTES = {
    **{f"oh{sep}{w}": k for k, w in enumerate("one two three four five six seven eight nine".split(), 1)
       for sep in (" ", "-")},
    "ten": 10, "fifteen": 15, "twenty": 20, "twenty-five": 25, "twenty five": 25, "thirty": 30,
    "thirty-five": 35, "thirty five": 35, "forty": 40, "forty-five": 45, "forty five": 45, "fifty": 50,
    "fifty-five": 55, "fifty five": 55,
}  # fmt: skip
_HOUR_AND_MINUTES = re.compile(
    rf"\b{_HOUR_WORD}[- ]({'|'.join(sorted(_SPOKEN_MINUTES, key=len, reverse=True))})"
    r"(?= (?:in the (?:morning|afternoon|evening)|at night|am|pm|a m|p m)\b)"
)
#: Said after a clock in words, the night: twelve is then midnight, not noon.
_AT_NIGHT = re.compile(r"\b(?:at night|tonight)\b")
#: Said beside a clock in words, the half of the day it is in.
_AFTERNOON_SAID = re.compile(r"\b(?:in the (?:afternoon|evening)|at night|tonight|pm|p m)\b")
#: (Not "am" after "i": "11 o'clock, I am on duty" is the verb, no half of the day.)
_MORNING_SAID = re.compile(r"\b(?:in the morning|(?<!\bi )am|a m)\b")


def clock_in_words(said: str, parts: list[str]) -> str | None:
    """A clock said in words ("quarter past eight": "08:15", "twenty to seven in the evening": "18:40",
    "half five": "05:30" or "17:30", "one-forty in the morning": "01:40"), else None. Words give no half
    of the day: it is the one said ("in the evening", "pm"), else the one that lies within the part of
    the day said (``parts``: the lexicon's clocks of the parts said), else the afternoon for the first
    hours and the morning after."""
    said = _DATE_SPAN.sub(" ", said)
    m = _CLOCK_IN_WORDS.search(said)
    oclock = _OCLOCK.search(said) if m is None else None
    spoken = _HOUR_AND_MINUTES.search(said) if m is None and oclock is None else None
    if m is None and oclock is None and spoken is None:
        return None
    if spoken is not None:  # ("one-forty in the morning")
        m = spoken
        hour, minute = _hour(spoken.group(1)), _SPOKEN_MINUTES[spoken.group(2)]
    elif oclock is not None:
        m = oclock
        hour, minute = _hour(oclock.group(1)), 0
    elif m.group(4) is not None:  # ("half five")
        hour, minute = _hour(m.group(4)), 30
    else:
        said_minutes = m.group(1).replace(" minutes", "")
        minutes = _MINUTES.get(said_minutes.replace("-", " ")) or _MINUTES.get(said_minutes)
        minutes = minutes if minutes is not None else int(said_minutes)
        if not 0 < minutes < 60:
            return None
        hour, minute = _hour(m.group(3)), minutes
        if m.group(2) in ("to", "before"):
            hour, minute = (hour - 2) % 12 + 1, 60 - minutes
    rest = said[m.end() : m.end() + 30]
    am, pm = hour % 12, hour % 12 + 12
    if _AFTERNOON_SAID.match(rest.strip()) or _AFTERNOON_SAID.search(rest[:16]):
        hour = 0 if pm == 12 and _AT_NIGHT.search(rest[:16]) else pm  # ("twelve thirty at night": 00:30)
    elif _MORNING_SAID.search(rest[:16]):
        hour = am
    else:
        known = [p for p in parts if p in PART_OF_DAY_HOURS]
        if known and _within(pm, known[0]) and not _within(am, known[0]):
            hour = pm
        elif known and _within(am, known[0]):
            hour = am
        else:
            hour = pm if 1 <= hour <= 6 else am if hour < 12 else 12
    return f"{hour:02d}:{minute:02d}"


def _hour(word: str) -> int:
    return int(word) if word.isdigit() else _HOURS[word]


#: Words before a time that make it a bound of something else ("raining since midnight", "off until 6 pm"),
#: not the scenario's time.
BOUNDS = frozenset({"since", "until", "till"})
_BOUNDED_CLOCK = re.compile(r"\b(?:since|until|till) (?:about |around )?\d[\d.: ]*(?:am|pm|hrs|hours)?")


#: A clock after a verb of making a record ("call logged 14:10", "report written at 17:45", "ticket
#: opened 08:02"): when the record was made, not when what it tells of happened.
_RECORDED_CLOCK = re.compile(
    r"\b(?:logged|filed|recorded|received|written|submitted|entered|updated|printed|created|opened|closed|raised)"
    r"(?: at| on)? (?:about |around |approx |approximately )?"
    r"(?:\d{1,2} ?[:.] ?\d\d(?: ?(?:am|pm|hrs|hours|h)\b)?|\d{3,4} ?(?:hrs|hours|h)\b|\d{1,2} ?(?:am|pm)\b)"
)


#: A clock whose hour is a lone 0 ("0:42", in the reader's tokens "0 : 42"), which no clock of the day is
#: written as (midnight's hour is "00"): a point in a recording.
_ZERO_HOUR = re.compile(r"(?<![\d:] )(?<!\d)\b0 : [0-5]\d\b(?! (?:am|pm)\b)")
#: A point in a recording, not a time of day: a clock after "skip to" or "at ... in the video", or one
#: whose hour is a lone 0.
_TIMESTAMP = re.compile(
    r"\b(?:skip|skipping|jump|jumping|fast forward|forward|scroll|scrolling) (?:to |at )?"
    r"(?:about |around )?\d{1,2} : [0-5]\d\b"
    r"|\b\d{1,2} : [0-5]\d (?:in|into|of) the (?:video|clip|footage|recording)\b"
    rf"|{_ZERO_HOUR.pattern}"
)


#: Words of a recording a writer points into by its running time ("at 1:12 in the clip", "helmet cam
#: footage", "voice note (1:12)"); not "clips my elbow", a "speed cam" or a "video call".
_RECORDING = re.compile(
    r"\b(?:(?:the|this|my|that|full|short) clips?|videos?(?! calls?\b)|vids?|footage|recordings?|gopro|overlay"
    r"|timestamps?|youtube|voice ?(?:notes?|messages?)|voicemails?"
    r"|(?:dash|helmet|rear|front|bike|body|head) ?-? ?cams?|dashcams?|helmetcams?)\b"
)
#: Said right after a clock, its unit or its half of the day ("2:30 in the morning", "9:40 at night").
_CLOCKS_HALF_AFTER = (
    r" (?:am|pm|a m|p m|hrs|hours|h|o'clock|in the (?:morning|afternoon|evening|night)|at night|tonight"
    r"|this (?:morning|afternoon|evening))\b"
)
#: A clock with a one-digit hour and no half of the day ("1:12", in the reader's tokens "1 : 12"): how a
#: point into a recording is written.
_LOOSE_CLOCK = re.compile(rf"(?<![\d:] )(?<!\d)\b[1-9] : [0-5]\d\b(?!{_CLOCKS_HALF_AFTER}| (?:km/h|mph|m/s|m)\b)")


def without_bounds(said: str) -> str:
    """The normalised text without the clocks that bound something else ("since 5 am"), that say
    when a record of it was made ("call logged 14:10"), or that point into a recording ("skip to
    0:42"): none is the time the scenario happens. A clock with a one-digit hour and no half of the
    day is such a point too where the text points into its clip at "0:09", or speaks of a recording
    and has two such clocks ("helmet cam ... at 1:11 ... at 1:12 a Golf pulls out"): a poster who
    times the clip as they tell it. One such clock in a dash-cam post ("on my dashcam on the way to
    work at 7:40") may be the time of day, and stays."""
    points = _ZERO_HOUR.search(said) is not None or (
        _RECORDING.search(said) is not None and len(_LOOSE_CLOCK.findall(said)) > 1
    )
    said = _TIMESTAMP.sub(" ", _RECORDED_CLOCK.sub(" ", _BOUNDED_CLOCK.sub(" ", said)))
    return _LOOSE_CLOCK.sub(" ", said) if points else said


#: A four-digit 24-hour clock opening a line of a log ("1632 CALLER ADV ...", "0203 Unit 14 adv near
#: miss"): a dispatch or radio log stamps each entry so. A number inside a line is a reference ("Event
#: 0417"), one before a unit a quantity, and a year before a vehicle's make its model year.
_LOG_CLOCK = re.compile(r"(?m)^[ \t]*([01]\d|2[0-3])([0-5]\d)[ \t]+([A-Za-z][\w/-]*)")
_NOT_AFTER_A_CLOCK = frozenset(
    ("m", "km", "kph", "mph", "metres", "meters", "feet", "ft", "cc", "model", "reg", "plate", "ref", "st", "nd",
     "rd", "th", "hrs", "hours", "h")
)  # fmt: skip


def log_clock(text: str, is_vehicle: Callable[[str], bool]) -> str | None:
    """The clock of a four-digit time opening a line of the original ``text`` ("1632 CALLER ...":
    "16:32"), else None; not before a unit or a vehicle's name (``is_vehicle``: "2019 Honda Civic")."""
    for m in _LOG_CLOCK.finditer(text):
        after = m.group(3).lower()
        if after not in _NOT_AFTER_A_CLOCK and not is_vehicle(after):
            return f"{m.group(1)}:{m.group(2)}"
    return None


#: A stamp of a line of a record: a clock or a running time opening the line ("[00:12:40] Sophie: ...",
#: "07:48 Op observes ...", "00:00:02.100 --> ..."), or after a speaker's label and ending it ("Speaker 2
#: (00:31): ...", "Speaker 1: (00:05)", "Witness, 00:47:", "Noor 15:02: ...", "Marcus Feld  0:03" on a line
#: of its own, "00:01.000 --> ..."; a label is capitalised
#: words, a name or a role, not "I left at 9:15"). Only the first two fields
#: are kept, as a clock is read ("01:12:03": "01:12").
_STAMP = r"(?<![\d:])[\[(]?(\d{1,2}):([0-5]\d)(?:[.,]\d+)?(?::[0-5]\d(?:[.,]\d+)?)?[\])]?"
_LINE_STAMP = re.compile(
    rf"(?m)^[ \t]*(?:{_STAMP}(?=[ \t]|$)"
    rf"|[A-Z][\w.'&-]*(?:[ \t]+(?:[A-Z0-9][\w.'&-]*|\([^()\n]{{1,24}}\))){{0,3}}"
    rf"(?::[ \t]*[\[(]{_STAMP}|[ \t]*,?[ \t]*{_STAMP}[ \t]*(?::|$)))"
)


def running_time(stamps: frozenset[str]) -> bool:
    """Whether a text's line stamps count a recording's or a meeting's running time, not the clock: one
    has the hour 0 ("[00:03:12] A: ...", "Ella  00:03", "00:00:01,000 --> ..."). (A log kept past
    midnight is read so too; its part of the day said, "night", is then the time.)"""
    return any(stamp.startswith("00:") for stamp in stamps)


def agrees(clock: str | None, part: str | None) -> bool:
    """Whether ``clock`` lies within the part of the day ``part`` (the lexicon's clock of it), or within
    ``CLOCK_SLACK_H`` of it; any clock agrees with no part said. A line's stamp that agrees is the time,
    to the minute ("02:14 Patrol observed ..." on a night shift); one that does not is a recording's
    running time or a meeting's clock ("[02:01] Kath: ... Afternoon.")."""
    if clock is None or part is None or part not in PART_OF_DAY_HOURS:
        return clock is not None
    first, last = PART_OF_DAY_HOURS[part]
    hour = int(clock.split(":")[0])
    return _within(hour, part) or min((first - hour) % 24, (hour - last) % 24) <= CLOCK_SLACK_H


#: A speaker's label: a capitalised word and up to three more, then a colon ("Kerry: ", "Ms Lee: ",
#: "Amelia (Chair): ").
TURN_LABEL = r"[A-Z][\w.'-]*(?:[ \t]+[\w.'()-]+){0,3}:[ \t]"
#: A speaker's label right after a stamp ("00:05:11 Kerry: ..."): the clock stamps a turn.
_SPEAKER_AFTER = re.compile(rf"[ \t]*{TURN_LABEL}")


def line_stamps(text: str) -> frozenset[str]:
    """The clocks ("HH:MM") of the stamps that open the lines of the original ``text`` or end their
    speakers' labels. A stamp says when a line was logged, said or shown (a meeting transcript's
    running time, an audio-description cue, a log's entry): where the text also says a part of the
    day, that part is when what it tells of happened, and the stamp is not. A record stamps two lines
    or more, or marks its stamp (brackets, a speaker's label beside it): one bare clock opening a text
    ("1:40 in the morning, empty streets.") is said, not stamped."""
    found, marked = [], False
    for m in _LINE_STAMP.finditer(text):
        hour, minute = next((h, mm) for h, mm in zip(m.groups()[::2], m.groups()[1::2]) if h is not None)
        found.append(f"{int(hour):02d}:{minute}")
        said = m.group(0).strip()
        marked = marked or said[:1] in "[(" or not said[:1].isdigit() or bool(_SPEAKER_AFTER.match(text, m.end()))
    return frozenset(found) if len(found) > 1 or marked else frozenset()  # (one bare clock opening a text is said)


#: A greeting with a part of the day ("Good afternoon.", "good evening all"): when a message is written,
#: not when what it tells of happened. It stands alone, or before whom it greets.
_GREETED = frozenset(("good",))
_AFTER_A_GREETING = frozenset(
    ("", ".", ",", "!", ";", ":", "-", "all", "everyone", "everybody", "sir", "madam", "team", "folks", "guys")
)


#: What follows a greeting that opens a turn ("Evening.", "Morning all"); not a comma, after which the
#: part of the day is told ("Evening, about 7, dry").
_AFTER_A_TURNS_GREETING = _AFTER_A_GREETING - {",", ";", ":", "-"}


def greeting(prev: str, words: str, next_: str, speaker: bool = False) -> bool:
    """Whether the time words ``words`` between the tokens ``prev`` and ``next_`` are a greeting ("Good
    morning.", "good evening all"); not "a good morning for a drive". A part of the day alone opening a
    speaker's turn (``speaker``: the label before ``prev``, a colon, is one of :func:`speakers`:
    "OFFICER: Evening. ...", "Paul: Morning all") greets too; after a field's label ("Time: evening.")
    it is the time."""
    parts = ("morning", "afternoon", "evening", "night", "day")
    if speaker and prev == ":" and words in parts[:3] and next_ in _AFTER_A_TURNS_GREETING:
        return True
    return prev in _GREETED and words in parts and next_ in _AFTER_A_GREETING


#: A label opening a line of a dialogue, after any stamp ("OFFICER:", "[00:00:03] Paul Gren:", "Speaker 2
#: (00:31):"): its last word, as the reader's tokens have it before the colon.
_SPEAKER_LABEL = re.compile(
    r"(?m)^[ \t]*(?:[\[(]?\d{1,2}:\d\d(?::\d\d)?[\])]?[ \t]+)?(?:[A-Za-z][\w.'-]*[ \t]+){0,3}([A-Za-z][\w'-]*)"
    r"(?:[ \t]*[\[(][\d:.]+[\])])?[ \t]*:(?!\d)"
)


#: Words a dialogue's greeting opens with, which a greeting in the next turn returns ("Dad: Evening. /
#: Son: Evening.").
_GREETS = frozenset(("morning", "afternoon", "evening", "hello", "hi", "hey", "good", "hiya"))


def opens_a_turn(tokens: list[str], i: int, talking: frozenset[str]) -> bool:
    """Whether the words at token ``i`` open a dialogue's first turn, or the second where the first greets
    (right after a label of ``talking`` and its colon), and answer no question: the turn before it,
    past its stamp, does not end with "?"
    ("Keith: morning or afternoon? / Mandy: Morning, about 9." is an answer, not a greeting)."""
    if i < 2 or tokens[i - 1] != ":" or tokens[i - 2] not in talking:
        return False
    turns = [k for k in range(i - 2) if tokens[k] in talking and tokens[k + 1] == ":"]
    if len(turns) > 1 or (turns and tokens[turns[0] + 2 : turns[0] + 3] != [] and tokens[turns[0] + 2] not in _GREETS):
        return False  # (a greeting opens a dialogue or returns one: later, a part of the day said alone answers)
    k = i - 3
    while k >= 0 and (tokens[k].isalpha() and tokens[k] not in talking) and k > i - 7:
        k -= 1  # (the label's other words: "paul gren")
    while k >= 0 and (tokens[k].isdigit() or tokens[k] in (":", ".", "[", "]", "(", ")")):
        k -= 1  # (the stamp, and the line's end)
    return k < 0 or tokens[k] != "?"


def without_clocks(said: str, clocks: frozenset[str]) -> str:
    """``said`` (the reader's tokens joined) without the clocks whose "HH:MM" is one of ``clocks`` (the
    stamps of its lines)."""
    if not clocks:
        return said

    def cut(m: re.Match) -> str:
        return " " if f"{int(m.group(1)):02d}:{m.group(2)}" in clocks else m.group(0)

    return _STAMP_SAID.sub(cut, said)


#: A clock as the reader's tokens have it ("00 : 12 : 40", "0 : 03").
_STAMP_SAID = re.compile(r"(?<!: )(?<!\d)\b(\d{1,2}) : ([0-5]\d)\b(?: : [0-5]\d\b)?")


def speakers(text: str) -> frozenset[str]:
    """The speakers of a dialogue written one turn a line (the last word of each label that opens two or
    more lines of the original ``text``, lowercased): a field label opens one line."""
    labels = Counter(m.group(1).lower() for m in _SPEAKER_LABEL.finditer(text))
    return frozenset(label for label, n in labels.items() if n >= 2)


#: A day, or "this", with its half said as "am" or "pm" ("Tues AM", "Friday pm", "this am").
_DAY_HALF = re.compile(
    r"\b(?:(?:mon|tue|wed|thu|fri|sat|sun)[a-z]*\.?|today|yesterday|tomorrow|this) (am|pm)\b(?! [0-9])"
)
#: The clock each half of the day is read at, as the lexicon reads "morning" and "afternoon".
_HALF_CLOCK = {"am": "08:30", "pm": "15:30"}


def day_halves(said: str) -> list[tuple[str, str]]:
    """(words, clock) of a day said with its half and no hour ("Weds AM": the morning, "Friday pm":
    the afternoon), as time words the reader reads beside the others; "Monday I am driving" has none."""
    return [(m.group(0), _HALF_CLOCK[m.group(1)]) for m in _DAY_HALF.finditer(said)]


#: Words for a street after its name ("Sunset Boulevard", "Evening Rd"), and those a street named for a
#: time of day may also end in ("Sunset Strip", "Dawn Circle").
STREET_WORDS = ROAD_NAME_ENDS | frozenset(("highway", "hwy", "strip", "square", "circle"))
_ORDINAL_ENDS = frozenset(("st", "nd", "rd", "th"))


def time_in_a_name(tokens: list[str], i: int, n: int, proper: frozenset[str]) -> bool:
    """Whether the time words ``tokens[i:i+n]`` are written as a name (each only with its own capital,
    ``proper``) of a street: a street's word after them ("Sunset Boulevard", "Evening Road") or another
    street joined to them, by a name or a numbered street ("Sunset & 3rd", "Sunset/Vine"; the tokens
    keep no "&" or "/"). Why: a street named for a time of day is where, not when ("Heading along Sunset
    Blvd at noon"), while "at sunset" and "on a Friday Evening" stay the time."""
    if not all(t in proper for t in tokens[i : i + n]):
        return False
    after = tokens[i + n : i + n + 3]
    if after[:1] and after[0] in STREET_WORDS:
        return True
    if after[:1] == ["and"]:
        after = after[1:]
    numbered = len(after) >= 2 and after[0].isdigit() and after[1] in _ORDINAL_ENDS
    return numbered or (bool(after) and after[0] in proper)


#: Seasons among the weather words: the weather they bring only where no other is said ("a winter
#: morning": snow; "foggy winter mornings": fog).
SEASON_WORDS = frozenset({"winter"})
#: Words before a weather word that put it before the scene ("surface wet after rain", "since the
#: snow"): it left the road wet or white, it is not the sky now.
PAST_WEATHER = frozenset({"after", "since"})
_SEVERITY = {"clear": 0, "cloudy": 1, "rain": 2, "fog": 2, "snow": 3, "heavy_rain": 3}


def weather_said(mentions: list[tuple[str, str, str]]) -> list[tuple[str, str]]:
    """The weather words of ``mentions`` (words, value, word before) as (words, value): one said of a
    time before the scene ("after rain") counts as what it left on the road, a surface word; a season
    only where no other weather word is said."""
    said = [("wet" if prev in PAST_WEATHER else words, value) for words, value, prev in mentions]
    other = [(w, v) for w, v in said if w not in SEASON_WORDS]
    return other or said


def most_severe(said: list[tuple[str, str]]) -> str | None:
    """The most severe weather of ``said`` (words, value), of equals the first."""
    values = [v for _, v in said]
    return max(values, key=lambda v: (_SEVERITY.get(v, 0), -values.index(v))) if values else None


def sky_over_surface(said: list[tuple[str, str]]) -> str | None:
    """The weather of the sky words among the weather words ``said`` as (words, value), when surface
    words ("wet track") are said with them (the most severe sky word, of equals the first); else None."""
    severity = _SEVERITY
    sky = [value for words, value in said if words not in SURFACE_WORDS]
    if not sky or len(sky) == len(said):
        return None
    return max(sky, key=lambda v: (severity.get(v, 0), -sky.index(v)))


#: "no other car", "not another vehicle about", "not a single other car", "nobody else on the road",
#: "no background traffic", "no through traffic": a negated other road user, or traffic with one word of
#: what kind, is no background traffic (not "no traffic lights": a compound naming something else; not
#: "no heavy traffic": a degree denied). Who was involved in an incident is not who was about.
_NO_OTHERS = re.compile(
    r"(?:\b(?:nobody|no one|no-one|not a soul) else\b"
    r"|\b(?:no |not (?:a |one )?(?:single )?)other (?:cars?|vehicles?|traffic|road users?)\b"
    r"|\bnot (?:a single |one )?(?:another|other) (?:cars?|vehicles?|soul)\b"
    r"|\bnot a single (?:cars?|vehicles?)\b"
    r"|\bno (?!(?:heavy|real|much|major|serious|big|bad|dense|busy) )(?:[a-z]+ )?traffic\b"
    r"(?! (?:lights?|signals?|islands?|cones?|calming|control|police|wardens?|lanes?|jams?|queues?|cameras?)\b))"
    r"(?! (?:were|was|are|is|got|had been) (?:involved|hurt|injured|damaged)\b)"
)
#: "no other vehicles were involved", "no traffic lights": words the lexicon reads as no traffic that do
#: not speak of the traffic about (who took part in an incident; a road's signals).
_NOT_TRAFFIC = re.compile(
    r"\b(?:no|not any) other (?:cars?|vehicles?|road users?|parties|party|people|persons)"
    r" (?:were|was|are|is|got|had been) (?:involved|hurt|injured|damaged)\b"
    r"|\bno traffic (?:lights?|signals?|islands?|cones?|calming|control|police|wardens?|lanes?|cameras?)\b"
)


#: A request that leaves other traffic out ("do not add any background traffic", "don't include other
#: vehicles", "nothing else on the road"): a scene with no one but those named.
_LEFT_OUT = re.compile(
    r"\b(?:do not|never|no need to|without) (?:add|adding|include|including|put|putting|spawn|spawning|place|have)"
    r" (?:any )?(?:other |background |more |extra |additional |ambient )*(?:traffic|cars|vehicles|road users)\b"
    r"|\bnothing (?:else|more) (?:in the (?:scene|scenario|picture)|on the road|around|about|in sight)\b"
)


def no_other_traffic(said: str) -> bool:
    """Whether the normalised text says there is no other road user about (no background traffic), or
    asks for none."""
    return _NO_OTHERS.search(said) is not None or _LEFT_OUT.search(said) is not None


#: "barely any traffic", "not much traffic", "only a handful of cars": a small quantity of other traffic.
_FEW_OTHERS = re.compile(
    r"\b(?:hardly|barely|scarcely) any (?:other )?(?:traffic|cars|vehicles)\b"
    r"|\bnot (?:much|many|a lot of) (?:other )?(?:traffic|cars|vehicles)\b"
    r"|\ba handful of (?:other )?(?:cars|vehicles)\b"
    r"|\bvery (?:little|few) (?:other )?(?:traffic|cars|vehicles)\b"
)


#: "loads of traffic", "tons of cars", "a lot of vehicles": a large quantity of other traffic (not "lots
#: of cars parked": parked cars are scenery).
_MANY_OTHERS = re.compile(
    r"\b(?:loads|lots|tons|heaps|masses|plenty|a lot|a load|a ton|a great deal|a fair bit|a stack)"
    r" of (?:other )?(?:traffic|cars|vehicles)\b(?! (?:were |are )?parked\b)"
)


#: "traffic moderate", "traffic: heavy", "traffic = light": a note of the traffic, its value after it
#: (not "traffic light", a signal, unless a colon or equals sign says it is a value).
_TRAFFIC_NOTE = re.compile(
    r"\btraffic(?: (moderate|heavy|busy|dense|sparse|quiet)"
    r"| ?[:=] ?(light|moderate|heavy|busy|dense|sparse|quiet|none))\b"
)
#: Traffic said of the road ("the motorway was heavy", "traffic was moderate", "traffic's on heavy"), or
#: the traffic said to be bad ("traffic was too much", "the traffic was mad"): congestion, heavy.
_SAID_OF_ROAD = re.compile(
    r"\b(?:traffic(?: volumes?| levels?| flows?)?|motorway|road|roads|street|streets|highway|circulation)"
    r" (?:is|was|were|are|being|looked|seemed|'s)(?: on| set to| at)? (?:very |quite |fairly |pretty |so |"
    r"really |absolutely |just )?(light|moderate|heavy|busy|quiet|dense|sparse|empty)\b"
    r"|\btraffic (?:is|was|were|are|being|looked|seemed|'s) (?:very |so |really |absolutely |just )?"
    r"(too much|bad|terrible|horrendous|awful|mad|crazy|insane|manic|chaos|chaotic|gridlocked|jammed|rammed|"
    r"murder|nuts)\b"
)
#: A degree of traffic before up to two words saying which traffic ("heavy morning traffic", "moderate bg
#: traffic", "zero ambient traffic", "slow queuing traffic"): the degree is said of the traffic all the
#: same. A word of the weather between ("light rain traffic") or a signal after ("traffic lights") is not.
_DEGREE_OF_TRAFFIC = re.compile(
    r"\b(light|moderate|heavy|busy|dense|sparse|zero|slow|queuing|queueing|crawling|stationary)"
    r"((?: (?!(?:and|or|but|with|of|in|on|the|a|rain|snow|fog|drizzle|mist|wind)\b)[a-z-]+){0,2}) traffic\b"
    r"(?! (?:lights?|signals?|islands?|cones?|calming|control|police|wardens?|lanes?|cameras?)\b)"
)
#: A degree of the traffic said by a noun of its amount ("light volumes", "moderate density"), not of a
#: vehicle ("a heavy lorry") or the weather ("light rain").
_DEGREE_OF_VOLUME = re.compile(
    r"\b(light|moderate|heavy|dense|sparse|low) (?:traffic )?(?:volumes?|density|densities|flows?)\b"
)
#: What each word of the patterns above says of the traffic; a queue is heavy traffic.
_DENSITY_WORDS = {"light": "light", "sparse": "light", "quiet": "light", "moderate": "moderate", "heavy": "heavy",
                  "busy": "heavy", "dense": "heavy", "empty": "none", "none": "none", "zero": "none",
                  "slow": "heavy", "queuing": "heavy", "queueing": "heavy", "crawling": "heavy",
                  "stationary": "heavy", "low": "light", "too much": "heavy", "bad": "heavy", "terrible": "heavy",
                  "horrendous": "heavy", "awful": "heavy", "mad": "heavy", "crazy": "heavy", "insane": "heavy",
                  "manic": "heavy", "chaos": "heavy", "chaotic": "heavy", "gridlocked": "heavy", "jammed": "heavy",
                  "rammed": "heavy", "murder": "heavy", "nuts": "heavy"}  # fmt: skip


def density(said: str, read: str | None = None) -> str | None:
    """Background traffic said as a quantity of other road users: none ("not another car about"), light
    ("barely any traffic", "only a handful of cars"), heavy ("loads of traffic"), as a note ("traffic
    moderate") or of the road ("the motorway was heavy", "traffic volumes are heavy"); else ``read``
    (what the reader's words gave), unless that was "none" read only from words that do not speak of
    the traffic about ("no other vehicles were involved", "no traffic lights")."""
    said_of_traffic = _NOT_TRAFFIC.sub(" ", said)
    if no_other_traffic(said_of_traffic):
        return "none"
    if _FEW_OTHERS.search(said_of_traffic):
        return "light"
    if _MANY_OTHERS.search(said_of_traffic):
        return "heavy"
    note = _TRAFFIC_NOTE.search(said_of_traffic)
    if note is not None:
        return _DENSITY_WORDS[note.group(1) or note.group(2)]
    m = _SAID_OF_ROAD.search(said_of_traffic)
    if m is not None:
        return _DENSITY_WORDS[m.group(1) or m.group(2)]  # (of the road; or of the traffic, as congestion)
    m = _DEGREE_OF_TRAFFIC.search(said_of_traffic)
    if m is not None and (m.group(2) or read is None):  # (a degree right before "traffic": the lexicon's first)
        return _DENSITY_WORDS[m.group(1)]
    m = _DEGREE_OF_VOLUME.search(said_of_traffic)
    if m is not None and read is None:
        return _DENSITY_WORDS[m.group(1)]
    if read == "none" and _NOT_TRAFFIC.search(said) and not _NONE_WORDS.search(said_of_traffic):
        return None
    return read


#: The lexicon's words of no traffic, as a pattern over the normalised text.
_NONE_WORDS = re.compile(r"\b(?:" + "|".join(re.escape(w) for w in L.DENSITY["none"]) + r")\b")


#: The sun or a blue sky said ("blue skies", "the sun was out", "sunshine", "low sun glare"): clear.
_SUN = re.compile(
    r"\b(?:blue sk(?:y|ies)|sunshine|sunlight|sun (?:was |is )?(?:out|shining|blazing|beating down)|"
    r"(?:bright|strong|low|blazing|hot) sun|sun glare)\b"
)


def sunny(said: str) -> str | None:
    """``clear`` when the normalised text speaks of the sun or a blue sky, else None (to be used where
    no weather word is said)."""
    return "clear" if _SUN.search(said) else None


#: "8.15 am", "6.45 pm": a clock written with a dot, which its half of the day tells from a decimal.
_DOTTED_CLOCK = re.compile(r"\b(1[0-2]|0?[1-9])\.([0-5]\d) (am|pm)\b")


#: A clock written with a dot after a word of time or a form's field of time and no unit ("at 23.10", "approx
#: 3.15,", "Time: 13.15", "21.09.2023 time 14.10"): the hour as written, which a part of the day said beside
#: it may put in the afternoon (:func:`twelve_hour`). Not a date ("Time: 10.01.2024"), nor a time of something
#: ("lap time 1.45", "reaction time: 1.50").
_DOTTED_AT = re.compile(
    r"(?:\b(?:at|around|about|approx|approximately|circa|by|~)|(?<![a-z] )\btime ?:|(?<=\d )time) "
    r"([01]?\d|2[0-3])\.([0-5]\d)\b(?! ?\. ?\d{2}(?:\d{2})?\b)"
    r"(?! ?(?:m|metres?|meters?|km|km/h|kph|mph|m/s|s|seconds?|min|mins|minutes?|h|hrs?|hours?|miles?|feet|ft|%)\b)"
)


def dotted_clock(said: str) -> str | None:
    """A clock written with a dot: with its half of the day ("6.45 pm": "18:45"), or after a word of
    time ("at 23.10": "23:10"; "approx 3.15" in the afternoon: "15:15"), else None."""
    m = _DOTTED_CLOCK.search(said)
    if m is not None:
        hour = int(m.group(1)) % 12 + (12 if m.group(3) == "pm" else 0)
        return f"{hour:02d}:{m.group(2)}"
    m = _DOTTED_AT.search(said)
    return None if m is None else f"{int(m.group(1)):02d}:{m.group(2)}"


_TWO_LANE_HIGHWAY = re.compile(r"\b(?:two|2)[ -]lane (?:highway|freeway|expressway|road)\b")
_EACH_WAY = re.compile(r"\b(?:each|per|either|every|both) (?:way|direction|side)s?\b|\bone[ -]way\b")
_TWO_WAY = re.compile(r"\b(?:oncoming|head-on|head on|the other way|opposite direction|wrong way)\b")


_WORD = {"one": 1, "two": 2, "three": 3, "four": 4, "five": 5, "six": 6}
_N = r"(\d|one|two|three|four|five|six)"
#: "lane 2 of 3", "lane one of two": the lane the writer is in, of the road's lanes in its direction.
_LANE_OF = re.compile(r"\blane " + _N + r" of " + _N + r"\b")


#: "lanes: 3", "lanes: 2/dir", "lanes = two": a field of notes giving the lanes (per direction, as the
#: reader counts them).
_LANES_FIELD = re.compile(r"\blanes\s*[:=]?\s*" + _N + r"\b")


def lanes_counted(said: str) -> int | None:
    """The lanes of "lane 2 of 3" (3) or of a lanes field ("lanes: 2/dir"), else None."""
    m = _LANE_OF.search(said)
    word = m.group(2) if m is not None else None
    if word is None:
        field = _LANES_FIELD.search(said)
        word = field.group(1) if field is not None else None
    if word is None:
        return None
    n = int(word) if word.isdigit() else _WORD[word]
    return n if 1 <= n <= 6 else None


#: Verbs of moving sideways, whose count of lanes is how far a road user moves ("shifted one lane").
_SIDEWAYS = frozenset(("move", "shift", "drift", "change", "switch", "swerve", "veer", "slide", "step", "jump", "hop",
                       "pull", "cut", "weave", "edge", "come", "go"))  # fmt: skip
#: Words after "over" that end a place said as lanes away ("a van one lane over, braking").
_AFTER_PLACE = frozenset((".", ",", ";", "!", "?", "to", "from", "on", "and", "but", "then", "when", "as", "in"))


def lanes_moved(tokens: list[str], i: int) -> bool:
    """Whether a count of lanes at token ``i`` ("one lane", "two lanes") is how far a road user moves
    or how far over it is, not the lanes of the road: the object of a verb of moving sideways or of
    "over"/"across"/"by" after one ("moved over one lane", "drifted across two lanes", "shifted one lane
    to the left"), or a place "N lanes over". Why: the last count of lanes said sets the road's, and a
    move of one lane would otherwise leave a three-lane road with one."""
    if tokens[i + 1 : i + 2] not in (["lane"], ["lanes"]):
        return False
    after = tokens[i + 2 : i + 4]
    if after[:1] == ["over"] and (len(after) < 2 or after[1] in _AFTER_PLACE):
        return True  # ("a van one lane over", "changed one lane over, right in front")
    j = i - 1
    if j >= 0 and tokens[j] in ("over", "across", "by"):
        j -= 1
    if j < 0:
        return False
    found = lemmas(tokens[j])
    return "VERB" in found and bool(set(found["VERB"]) & _SIDEWAYS)


#: A road that traffic uses one way ("a one-way street", "the one-way bit of Castle Street"); not a
#: one-way system, a city's ring of such roads, which often has several lanes.
_ONE_WAY_ROAD = re.compile(
    r"\bone[ -]way (?:[a-z]+ )?(?:street|road|lane|bit|section|stretch|part|side street|alley)\b"
)


def lanes_of_one_way_road(said: str) -> int | None:
    """1 for a one-way road whose lanes the text does not count (the caller asks only then): the
    whole width of such a street is mostly one lane, and a road user met there comes the wrong way
    in the ego's lane, not in an oncoming lane beside it."""
    return 1 if _ONE_WAY_ROAD.search(said) else None


#: A road said to have many turns ("a road with lots of turns", "the lane is full of twists").
_MANY_TURNS = re.compile(
    r"\b(?:road|lane|street|route|stretch|section|way)\b[^.;!?]{0,25}?"
    r"\b(?:a lot of|lots of|loads of|many|full of|plenty of) (?:sharp |tight |blind )?"
    r"(?:turns|twists|bends|curves|corners)\b(?! later)"
)


def many_turns(said: str) -> str | None:
    """``curve`` for a road said to have many turns, twists or bends (the road's own, after a road's
    noun; not "many turns later"), else None."""
    return "curve" if _MANY_TURNS.search(said) else None


def bend_only_a_corner(said: str) -> bool:
    """Whether the only word of a bend the normalised text says is "corner": a corner is where two
    roads meet as often as where one bends, so the ego turning left or right there turns at a junction
    ("I waited on the corner, then pulled away turning left"), while "the bend" stays a bend."""
    words = set(said.split())
    bends = {w for w in L.MAPS["curve"] if " " not in w}
    return bool(words & {"corner", "corners"}) and not words & (bends - {"corner"})


def lanes_of_two_way_road(said: str, oncoming: bool) -> int | None:
    """1 for "a two-lane highway" that traffic uses both ways (someone comes towards the ego on it, or
    the text says so), where the text does not count its lanes per direction itself."""
    if not _TWO_LANE_HIGHWAY.search(said) or _EACH_WAY.search(said):
        return None
    return 1 if oncoming or _TWO_WAY.search(said) else None


#: A turn into or onto a road: said with the verb "turn" ("turns left into") or as a turn made, taken or
#: hung ("makes a right onto", "hangs a left into").
_TURN = (
    r"(?:turn(?:s|ed|ing)?(?: (?:left|right|off))?"
    r"|(?:makes?|making|made|takes?|taking|took|hangs?|hanging|hung) a (?:left|right)"
    r"|(?:makes?|making|made|takes?|taking|took|wants?|wanted|wanting|goes|going|went|is going|swings?|swung)"
    r" the (?:left|right))"
)
#: A side road or street, or the main road (what one turns onto from a side road).
_INTO_SIDE_ROAD = re.compile(
    rf"\b{_TURN} (?:in|on)to (?:a |the |one of the )?(?:side[ -]?(?:roads?|streets?)|main road)\b"
)
#: A road named ("into Church Lane", "onto 9th St"): capitalised or numbered words before a road's noun.
_INTO_NAMED_ROAD = re.compile(
    rf"\b(?i:{_TURN}) (?:in|on)to (?:(?:[A-Z0-9][\w']* )+"
    r"(?:Road|Lane|Street|Avenue|Close|Drive|Way|Grove|Crescent|Place|Terrace|Boulevard|Rd|St|Ave|Blvd)\b"
    r"|\d+(?:st|nd|rd|th)\b)"  # (or an American street by its number alone: "onto 42nd")
)
#: The road turned into said before its turn ("the street we are turning into", "the side road the bus
#: turned onto"): a relative clause whose preposition is left at its end.
_ROAD_TURNED_INTO = re.compile(
    r"\b(?:road|street|lane|avenue|side road|side street)s? (?:that |which )?(?:[a-z]+ ){1,3}?"
    rf"{_TURN} (?:in|on)to(?= [.,;:!?]| and\b| but\b| then\b| when\b| as\b|$)"
)
#: A turn across the opposing traffic without a protected signal phase ("an unprotected left"): made at
#: a junction, whatever else the text calls the road.
_UNPROTECTED = re.compile(r"\bunprotected (?:left|right)\b")


def turns_into_a_road(text: str, said: str) -> bool:
    """Whether someone turns into or onto a road (a side road, the main road, one named in the
    original ``text``, or one said before its turn: "the street we are turning into") or makes an
    unprotected turn: the road has a junction there."""
    return (
        _INTO_SIDE_ROAD.search(said) is not None
        or _INTO_NAMED_ROAD.search(text) is not None
        or _ROAD_TURNED_INTO.search(said) is not None
        or _UNPROTECTED.search(said) is not None
    )


#: Two streets said to meet at a corner, in the original text: "the corner of Main and 11th", "cnr Beach Rd
#: & Marine Pde", "corner of Elm/Oak", "the Jalan Ampang corner with Jalan Tun Razak". Both streets start
#: with a capital or a number; "the corner of the building" names no street.
_STREETS_MEET = re.compile(
    r"\b(?i:corner|cnr|crnr)\.?\s+(?:(?i:of)\s+)?(?:[A-Z0-9][\w'.]*\s*){1,4}(?:and|&|/)\s*[A-Z0-9]"
    r"|\b(?i:corner)\s+(?i:with)\s+[A-Z0-9]"
)
#: Coming out of a side road ("pulling out of a side road", "from a side street").
_OUT_OF_SIDE_ROAD = re.compile(r"\b(?:out of|from) (?:a|the|one of the) side[ -]?(?:roads?|streets?|turnings?)\b")


def streets_meet(text: str, said: str) -> bool:
    """Whether the original ``text`` puts the scene where two named streets meet at a corner, or the
    normalised ``said`` has someone come out of a side road: the road has a junction there, whatever
    "corner" alone would make of it (a bend)."""
    return _STREETS_MEET.search(text) is not None or _OUT_OF_SIDE_ROAD.search(said) is not None


#: Words that make a crossing one for people on foot ("a zebra crossing", "the pelican", "a crosswalk").
FOOT_CROSSINGS = frozenset({"zebra", "pelican", "puffin", "toucan", "pedestrian", "crosswalk", "crosswalks"})


def foot_crossing_named_before(tokens: list[str], i: int) -> bool:
    """Whether a crossing for people on foot is named before token ``i``: then "the crossing" at ``i``
    is that one, a known mention (the article says so), and not a junction."""
    return any(t in FOOT_CROSSINGS for t in tokens[:i])


#: Words before a part of the day that make it a time said of the story ("last night", "this morning",
#: "Friday evening"), never a modifier of a noun after it ("a night bus").
DEICTIC_DAYS = frozenset(
    ("last", "this", "yesterday", "tomorrow", "that", "one", "every", "each", "monday", "tuesday", "wednesday",
     "thursday", "friday", "saturday", "sunday")
)  # fmt: skip


def superlative(token: str, key: tuple[str, ...]) -> bool:
    """Whether ``token`` is the superlative of the one-word weather entry ``key`` ("finest" for
    "fine", "clearest" for "clear"): it ranks something ("his finest moment"), it reports no weather."""
    return len(key) == 1 and token != key[0] and token.endswith("est")


#: Words of a bend in the road; not "corner", which a junction has too.
_BEND_WORDS = frozenset(w for w in L.MAPS["curve"] if " " not in w and w != "corner")


def bend_named(tokens: list[str]) -> bool:
    """Whether the text names a bend ("on the bend", "a bendy lane", "a hairpin"): then "the crossing"
    is a crossing for people on foot on that bend, not a junction."""
    return any(t in _BEND_WORDS for t in tokens)


#: "lane 3", "lane two" (not "lane 2 of 3", which counts the lanes itself, nor "into the ego lane 6 m
#: ahead", a distance after the lane): a lane numbered from the kerb.
_LANE_NUMBER = re.compile(r"\blane " + _N + r"\b(?! of\b| (?:m|metres?|meters?|ft|feet|foot|yards?|yds|km)\b)")
#: "the middle lane", "the centre lane": a lane with one on each side.
_MIDDLE_LANE = re.compile(r"\b(?:middle|centre|center) lane\b")


def lanes_at_least(said: str) -> int | None:
    """The fewest lanes a direction has for the lanes the normalised text names: a lane numbered N
    ("in lane 3") needs N, a middle lane three; None where it names neither. Why: a writer who puts
    someone in lane 3 or the middle lane seldom also counts the lanes."""
    numbers = [int(w) if w.isdigit() else _WORD[w] for w in _LANE_NUMBER.findall(said)]
    fewest = max([n for n in numbers if 1 <= n <= 6] + [3 if _MIDDLE_LANE.search(said) else 0])
    return fewest or None


#: Running a red light ("ran the red", "blew a red light", "jumped the lights"): signals stand at a
#: junction, unless a crossing for people on foot is named, whose lights they are.
_RED_RUN = re.compile(
    r"\b(?:ran|runs|run|running|blew|blows|blown|blowing|jumped|jumps|jumping|went through|goes through|going through"
    r"|shot through|shoots through|sailed through|ignored|ignores) (?:the|a|its|his|her|their) "
    r"(?:red|red light|red lights|lights|light)\b"
)
#: Lights named by their street ("at the Harbour Rd lights", "at Silk Board signal"), in the original text.
_NAMED_LIGHTS = re.compile(r"\b(?i:at|by|near) (?:the )?(?:[A-Z0-9][\w'.]* ){1,3}(?:lights|signals?)\b")
#: A traffic signal said by its colour ("the light was green for me", "signal became green", "the robot
#: turned red", "lights had changed to amber"): a robot is a traffic light in southern Africa.
_SIGNAL_COLOUR = re.compile(
    r"\b(?:light|lights|signal|signals|robot|robots) "
    r"(?:(?:was|were|is|are) (?:just |still |already )?|(?:had |has |just )?(?:turned|turns|went|goes|became|becomes"
    r"|changed|changes|switched|switches) (?:to )?)(?:green|red|amber|yellow|orange)\b"
)
#: Two streets written with a slash ("Queen/Albert", "4TH/MARKET", "Elm St / High St"), in the original text:
#: where they cross. Both sides start with a capital or a street number; units ("km/h") and shorthand
#: ("w/", "m/c") are lower case.
_SLASHED_STREETS = re.compile(
    r"(?<![\w/])(?:[A-Z][A-Za-z]+|\d+(?:st|nd|rd|th|ST|ND|RD|TH))(?: (?:St|Rd|Ave|Street|Road|Avenue))?"
    r" ?/ ?(?:[A-Z][A-Za-z]+|\d+(?:st|nd|rd|th|ST|ND|RD|TH))\b"
)


def signalled_junction(text: str, said: str) -> bool:
    """Whether the text puts the scene at a junction by its signals or its streets: a red light run or
    a signal said by its colour (no foot crossing named), lights named by their street, or two streets
    written with a slash."""
    if (_RED_RUN.search(said) or _SIGNAL_COLOUR.search(said)) and not set(said.split()) & (
        FOOT_CROSSINGS | {"crossing"}
    ):
        return True
    return _NAMED_LIGHTS.search(text) is not None or _SLASHED_STREETS.search(text) is not None
