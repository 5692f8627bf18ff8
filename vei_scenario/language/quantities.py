"""A number as a quantity: its unit, its head (what it measures) and its owner (whom it is said of),
read from the grammar around it rather than from where it stands.

Why: a speed or a gap lost or given to the wrong road user is the commonest way a description is read
unfaithfully, and position alone ("the road user named last") cannot tell "van speed 60 km/h, ego speed
80 km/h" apart from "a van overtakes the ego at 60 km/h". The constructions that name a number's owner
are few and closed, and the same in every writer's style:

- a noun heading the quantity: "<road user> speed N", "speed of <road user> N", "<road user> N km/h";
- a key and its values: "<road user>: 6 m ahead, 20 mph, ..." (a bullet or a line of notes);
- a coordinated subject with "both": "<road user> and <road user> both at N".

What a number measures is said by the unit after it and, where a unit is shared, by its head noun: a
lateral speed, a sideways clearance, a visibility distance are numbers of the scene, not the speed a road
user travels at or its gap to the ego. A bare number ("I'm at 50") carries the speed unit the text used
before it. Everything here works on the reader's tokens; what a road-user mention is comes from the
reader (a callback), so the owner is the mention the reader already found.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import replace

from vei_scenario.language import lexicon as L
from vei_scenario.language import vocabulary as V
from vei_scenario.language.clauses import sentence_start
from vei_scenario.language.function_words import ABOUT
from vei_scenario.language.lemmas import lemmas
from vei_scenario.language.sides import KERB_NOUNS

#: Heads that make a number no speed of travel nor a starting gap: a measure across the road ("a lateral
#: velocity of 1 m/s", "1.5 m clearance"), how far one sees ("visibility reduced to 150 m"), or the
#: closest approach, an outcome ("a minimum separation of 0.5 m"); a plain "separation of 120 m" is a gap.
LATERAL_HEADS = frozenset(
    {"lateral", "laterally", "sideways", "clearance", "visibility", "offset", "minimum", "closest", "remaining"}
)
#: The sides of a vehicle a passing margin is measured off ("passed 1 m off our left side").
_FLANKS = frozenset({"side", "flank", "wing", "mirror", "door", "doors", "nearside", "offside"})
#: Nouns a test engineer calls the other road user by, whatever it is ("target speed: 15 km/h"): heading a
#: number after a road user is named, they name that one.
ROLE_NOUNS = frozenset({"target", "other vehicle"})
#: Nouns that head a speed ("van speed 60 km/h", "speed of the bus 15 km/h").
SPEED_HEADS = frozenset({"speed", "velocity"})
#: Words between a head and its number that carry nothing ("speed is about 20", "speed of ~20").
_LINKS = frozenset({"about", "is", "was", "of", "at", "=", "approximately", "around", "roughly", "ca", "circa"}) | {
    "least", "most", "over", "under", "nearly", "almost", "well", "easily", "maybe", "like", "just", "only"
}  # fmt: skip
#: Words that bound or hedge a number ("at least 70", "well over 60", "nearly 50", "just under 30"): the
#: number is still the speed the words before them say.
APPROXIMATORS = frozenset(
    {"least", "most", "over", "under", "nearly", "almost", "well", "easily", "maybe", "like", "just", "only"}
)


#: Words that bound a number by a comparison ("no more than 50", "less than 30", "a bit over 40", "a
#: little under 60"): the number is still the speed the words before them say.
BOUNDS = frozenset({"than", "more", "less", "no", "not", "bit", "little", "fraction", "touch", "tad"})


#: Words of a guess said before a number ("doing probably 40", "going close to 50", "doing max 40", "doing,
#: uh, 40", "going, what, 40?"): the number is still the speed the words before them say.
GUESSES = frozenset(
    {"probably", "possibly", "perhaps", "prob", "maybe", "say", "what", "max", "maximum", "barely", "hardly",
     "close", "near", "uh", "um", "er", "erm", "uhh", "umm", "dunno", "like"}
)  # fmt: skip
#: Verbs of an opinion a speaker puts between a verb and its number ("I think", "I reckon", "I'd say",
#: "I don't know", "I would guess", "I believe", "I'd estimate", "I suppose", "you know").
OPINION_VERBS = frozenset(
    {"think", "reckon", "guess", "say", "believe", "estimate", "suppose", "know", "reckoned", "thought",
     "guessed", "figure", "imagine", "bet", "expect", "recall", "remember", "mean", "dunno"}
)  # fmt: skip
#: Words between the speaker and the verb of opinion ("I would say", "I do not know", "I 'd guess").
OPINION_AUXILIARIES = frozenset({"would", "do", "did", "not", "'d", "should", "must", "'m"})
_SPEAKERS = frozenset({"i", "you", "we", "ego"})


def _guess_before(tokens: list[str], k: int) -> int:
    """The index before the guess that ends at token ``k`` ("I think", ", I don't know,", "probably",
    "close to", ", uh,"), or ``k`` where none ends there. A comma is part of the guess only next to one
    of its words (", I'd say, 40"); "to" only after "close"/"near" ("close to 50")."""
    j = k
    while j > 0:
        w, s = tokens[j], j - 1
        while w in OPINION_VERBS and s > 0 and tokens[s] in OPINION_AUXILIARIES:
            s -= 1
        if w in OPINION_VERBS and tokens[s] in _SPEAKERS:  # ("I think", "I would say", "I do not know")
            j = s - 1
        elif w in GUESSES:
            j -= 1
        elif w == "to" and tokens[j - 1] in ("close", "near"):
            j -= 2
        elif w == "," and j < k:  # (the comma that opens the guess: ", I think, 40")
            j -= 1
        elif w == "," and j == k and j > 1 and (tokens[j - 1] in GUESSES or tokens[j - 1] in OPINION_VERBS):
            j -= 1  # (the comma that closes it: ", I don't know, 40")
        else:
            break
    return j


def before_hedge(tokens: list[str], i: int) -> str:
    """The word before the number at ``i`` past its hedge or bound ("doing at least 70": "at"; "going well
    over 60": "going"; "doing no more than 50", "doing a bit over 40": "doing"), the plain word before it
    where there is none."""
    k = i - 1
    while k > 0 and (
        tokens[k] in APPROXIMATORS or tokens[k] in BOUNDS or (tokens[k] == "a" and tokens[k + 1] in BOUNDS)
    ):
        k -= 1
    return tokens[k] if k >= 0 else ""


#: Words of how one goes, besides adverbs in -ly, that stand between a verb of going and its bare speed ("going
#: straight 40", "driving slow 20"), and the words that strengthen them ("very slowly", "quite carefully").
MANNER = frozenset({"straight", "slow", "steady", "normal", "careful", "very", "quite", "really"})
#: Words of a guess right before a number ("with about 60", "slowly, maybe 20").
_HEDGE_WORDS = ABOUT | {"approx", "maybe", "like", "~", "some"}


def _manner(word: str) -> bool:
    return word in MANNER or (len(word) > 4 and word.endswith("ly") and word not in APPROXIMATORS)


#: Words between how one went and a bare number: hedges, bounds, and the commas that set the number off
#: ("going slowly, maybe 40,").
_BEFORE_ITS_NUMBER = APPROXIMATORS | BOUNDS | _HEDGE_WORDS | {","}


#: What may follow a number set off by commas as a speed: the sentence's end, or a comma and a word that
#: opens the clause that goes on ("going slowly, 40, and a cyclist ...", "going up slowly, 40, I stopped").
#: Not another number or a word of what the number counts ("carefully, 17, only passed my test", "slowly,
#: 20, 30 metres behind", "slowly, 4, 5 of us", "slowly, 11, maybe half past").
SENTENCE_ENDS = frozenset({"", ".", ";", "!", "?", ")"})
SET_OFF_OPENERS = frozenset(
    "and but then when as while so until till i we he she they it you his her the a my our".split()
)


def set_off_speed_ends(tokens: list[str], i: int) -> bool:
    """Whether the number at ``i``, set off by a comma before it, ends as a speed does (see
    :data:`SET_OFF_OPENERS`): a unit of speed, the sentence's end, or a comma and a clause's opener."""
    nxt = tokens[i + 1] if i + 1 < len(tokens) else ""
    after = tokens[i + 2] if i + 2 < len(tokens) else ""
    return nxt in V.SPEED_UNITS or nxt in SENTENCE_ENDS or (nxt == "," and after in SET_OFF_OPENERS)


def before_manner(tokens: list[str], i: int) -> str:
    """The word before the manner of going said between it and the number at ``i`` ("going slowly 20":
    "going"; "driving very carefully 30": "driving"; "going straight with 40", "driving with about 60":
    "going", "driving"), or "" where no manner stands there. Why: a writer says how they went between
    the verb and its speed, and a learner of English says the speed "with" it (as "con", "mit", "ile"
    do), and the number is still the speed the verb says; the caller still asks that the number end
    its phrase ("going slowly 2 cars behind" is no speed)."""
    k = i - 1
    while k > 0 and tokens[k] in _BEFORE_ITS_NUMBER:
        k -= 1
    if "," in tokens[k + 1 : i] and not set_off_speed_ends(tokens, i):
        return ""  # ("driving home carefully, 17, only passed my test": an age said as an aside)
    start = k
    k -= k > 0 and tokens[k] == "with"
    n = 0
    while k > 0 and n < 3 and (_manner(tokens[k]) or (n and tokens[k] == ",")):
        k, n = k - 1, n + (tokens[k] != ",")
    if 0 < k < start:  # ("going up slowly, 40", "going past it, slowly, 40", "going on the bridge, slowly, 40")
        k = _past_particle(tokens, k)
    return tokens[k] if k < start and k >= 0 else ""


#: Particles and prepositions of where one goes, said between a verb of going and how one went ("going up
#: slowly", "going past it, slowly").
PARTICLES = frozenset(
    {"up", "down", "along", "past", "by", "over", "through", "round", "around", "home", "back", "in", "out", "off",
     "on", "into", "across"}
)  # fmt: skip
#: What may follow such a particle before how one went: a pronoun ("past it"), or a place's determiner and
#: one word ("on the roundabout").
PARTICLE_OBJECTS = frozenset({"it", "them", "him", "her"})
PLACE_DETERMINERS = frozenset({"the", "a", "this", "that", "my"})


def _past_particle(tokens: list[str], k: int) -> int:
    """The index of the word before the particle and its object ending at ``k`` ("up", "past it", "on the
    roundabout", after a comma or not), or ``k`` where none ends there."""
    j = k - (tokens[k] == ",")
    if j > 0 and tokens[j] in PARTICLES:
        return j - 1
    if j > 1 and tokens[j] in PARTICLE_OBJECTS and tokens[j - 1] in PARTICLES:
        return j - 2
    if j > 2 and tokens[j - 1] in PLACE_DETERMINERS and tokens[j - 2] in PARTICLES:
        return j - 3
    return k


def _start_of_guess(tokens: list[str], i: int) -> int:
    """The index of the word before the guess (and any hedge in it) that ends right before the number
    at ``i`` ("doing I reckon 40", "going, I don't know, 40", "at probably 40", "doing close to 50":
    the index of "doing", "going", "at"), or ``i`` where no guess stands there."""
    k, guessed = i - 1, False
    while k > 0:
        if tokens[k] in APPROXIMATORS or tokens[k] in BOUNDS or (tokens[k] == "a" and tokens[k + 1] in BOUNDS):
            k -= 1
        elif (j := _guess_before(tokens, k)) < k:
            k, guessed = j, True
        else:
            break
    return k if guessed else i


#: Words after a number that end the phrase it says a speed in ("going, I think, 40, and ...").
_SPEED_PHRASE_ENDS = frozenset({"", ".", ",", ";", "!", "?", "and", "then", "when", "while", "but", ")", "or"})


def without_guesses(tokens: list[str], going: frozenset[str]) -> list[str]:
    """``tokens`` with the guess between a verb of going (``going``, or "doing", "at") and its number
    left out ("he was going, I don't know, 40, and ...": "he was going 40, and ..."; "doing I reckon 60
    mph": "doing 60 mph"), hedges kept ("doing probably about 40": "doing about 40"). Why: a speaker
    who is unsure says so there, and the number is still the speed the verb says; the "I" of "I think"
    is no one in the scene. Only where the number is a speed (a unit, the phrase's end or a place
    follows): "doing, what, 3 tasks at once" stays as said."""
    out = list(tokens)
    i = len(out) - 1
    while i > 0:
        nxt = out[i + 1] if i + 1 < len(out) else ""
        if is_number(out[i]) and (nxt in V.SPEED_UNITS or nxt in _SPEED_PHRASE_ENDS or nxt in WHERE_AFTER_SPEED):
            j = _start_of_guess(out, i)
            if j < i and out[j] in going | {"doing", "at"}:
                out[j + 1 : i] = [w for w in out[j + 1 : i] if w in APPROXIMATORS or w in BOUNDS or w == "a"]
                i = j
        i -= 1
    return out


#: Words between a speed's head and its number ("speed: 50", "velocity = 40", "speed was 30", "speed of
#: approx 70"); "spd" is how a note shortens "speed".
_HEAD_LINKS = frozenset({":", "=", "is", "was", "of", "at", "about", "around", "approx", "approximately", "~"})


def after_speed_head(tokens: list[str], i: int) -> bool:
    """Whether the bare number at ``i`` follows a speed's head ("Ego initial speed: 50", "ego spd 60", "our
    speed was 30"): a speed, in the unit the text carries, as "at 50" is. Not a number that names a
    thing the head names ("speed camera 3": the head is "camera")."""
    k = i - 1
    while k > 0 and k >= i - 3 and tokens[k] in _HEAD_LINKS:
        k -= 1
    return k >= 0 and tokens[k] in SPEED_HEADS | {"spd"}


_STOPS = frozenset({".", ";", "!", "?"})
#: Verbs of going whose subject a speed after "at" is said of ("the ego drives at 40 km/h").
_MOTION = frozenset(
    "doing going driving travelling traveling moving riding drives travels moves rides goes drove travelled "
    "traveled moved rode went cruising cruises cruised drive travel move ride go cruise".split()
)  # (the base forms after a modal or a plural subject: "shall both travel at 50 km/h")
#: Modals between a coordinated subject and "both" ("the ego and the van will both drive at 60").
_MODALS = frozenset({"will", "shall", "should", "must", "would", "can", "could", "may", "might"})
#: Forms of "be" whose subject a speed after "at" is said of ("we were at maybe 50 km/h").
_BE = frozenset({"is", "was", "are", "were", "am", "be"})
_AUXILIARIES = frozenset({"is", "was", "are", "were", "am", "be", "been", "'s", "still", "also", "then", "just"})
#: Words after which a noun opens a clause, as its subject ("; the bus at 15 km/h", "and the van at 60").
_CLAUSE_OPENERS = frozenset({",", ";", ":", ".", "?", "!", "and", "but", "while", "whereas", "when", "then", "as"})
OBJECT_PRONOUNS = frozenset({"me", "us", "him", "her", "them", "it", "you"})
_DETERMINERS = frozenset({"the", "a", "an", "this", "that", "our", "my", "its", "their", "his", "her"})

#: A car's length (m), the unit of "two car lengths behind".
CAR_LENGTH_M = 4.5
#: Words that may stand between "at" and a bare speed: an article and one modifier ("at a steady 50").
_ARTICLES = frozenset({"a", "an"})

#: "20-30 mph", "70–90 km/h", "between 8 and 12 metres": a range with its unit.
_RANGE = re.compile(
    r"\b(?:between\s+)?(\d+(?:\.\d+)?)\s*(?:-|\u2013|\u2014|(?<=\d) and|(?<=\d) or)\s*(\d+(?:\.\d+)?)\s*"
    r"(?=(?:km/h|mph|m/s|m|metres|meters|metre|meter|car lengths?)\b)"
)


_UNITS_AHEAD = r"(?=\s*(?:km/h|kph|kmh|mph|m/s|m|metres|meters)\b)"
#: "40ish mph", "70-odd mph", "30 plus km/h": a hedge between a number and its unit.
_HEDGED_AFTER = re.compile(r"\b(\d+(?:\.\d+)?)\s*-?\s*(?:ish|odd|plus|or so)\b" + _UNITS_AHEAD)
#: The verbs of going (and "at") after which a bare number hedged or ranged is a speed ("doing 50ish",
#: "drove 30-35"): the same for a hedge as for a range.
_GOING_BARE = r"(doing|going|did|went|drove|driving|travelling|traveling|travelled|traveled|riding|cruising|at)"
#: "doing 50ish", "did 40-ish in the left lane": a bare speed hedged after it, after a verb of going (or
#: "at"), is about that number; "a 40ish man" (an age) has no such verb before it.
_HEDGED_BARE = re.compile(rf"\b{_GOING_BARE}\s+(\d+)\s*-?\s*ish\b")
#: "40-something mph": a number in the decade of a round one, about its middle.
_SOMETHING = re.compile(r"\b([1-9])0\s*-?\s*something\b" + _UNITS_AHEAD)
#: "at 40 to 50 km/h", "doing about 30 to 40 mph": a choice of two after a word of a speed held, its
#: middle ("from 50 to 20 km/h" is a change, and has no such word before it).
_CHOICE_TO = re.compile(
    r"\b(at|about|around|roughly|approximately|approx|doing|going|travelling|traveling|of)\s+"
    r"(\d+(?:\.\d+)?)\s+to\s+(\d+(?:\.\d+)?)" + _UNITS_AHEAD
)
#: "doing 30-35", "going between 40 and 50", "travelling 60 to 70", "doing 50 or 60", "doing about 30,
#: 35": a range or a choice said bare after a verb of going (or "at"), its unit the text's, with no clock,
#: age or measure after it ("at 3-4 pm", "doing 30, 40 m behind"). A talker gives a range with a comma
#: as a writer does with a dash, where its phrase ends with it (:func:`_bare_range`); a falling pair
#: ("going 50, 20 faster than ...") is no range.
_BARE_RANGE = re.compile(
    _GOING_BARE + r"((?:\s+(?:somewhere|about|around|roughly|approximately|approx|maybe|like|between))*)\s+"
    r"(\d+(?:\.\d+)?)\s*(-|\u2013|\u2014|/|to|and|or|,)\s*(\d+(?:\.\d+)?)\b"
    r"(?!\s*(?:[:.]\d|am\b|pm\b|a\.m|p\.m|hours?\b|hrs\b|o'clock|%|years?\b|yrs\b|mins?\b|minutes\b|seconds?\b"
    r"|s\b|m\b|metres\b|meters\b|feet\b|ft\b|yards?\b|car\b|km\b(?!/h)|miles?\b))"
)


#: The word after a number (or the mark, or the text's end).
_NEXT_WORD = re.compile(r"\s*([a-z/]+|[^\sa-z]|$)", re.IGNORECASE)


def _bare_range(m: re.Match) -> str:
    """ "doing about 32.5" for "doing 30-35": the middle of a range of speeds said bare; as written
    where it is none ("at 5 and 10 m later": "and" makes a range only after "between"; "2 to 300"). With
    a comma the second number must end the range's phrase: a unit of speed, a mark, a word that ends a
    note or names where one goes, "max" or "tops" after it ("doing 30, 35 max", "going 30, 35 through
    the village"); else it counts what follows ("doing 30, 35 people were on the pavement", "at 30, 40
    kids were at the gate", "going 30, 45 degrees to the road"): a new clause, not a range."""
    low, high = float(m.group(3)), float(m.group(5))
    if (m.group(4) == "and" and "between" not in m.group(2)) or not 3 <= low < high <= 250 or high > 2 * low + 10:
        return m.group(0)
    if m.group(4) == "," and not _ends_a_speed(_NEXT_WORD.match(m.string, m.end()).group(1).lower()):
        return m.group(0)
    return f"{m.group(1)} about {(low + high) / 2:.1f}"  # (with its decimal: no value a writer rounded to)


def _ends_a_speed(word: str) -> bool:
    """Whether ``word`` after a bare number ends it as a speed: a unit of speed, a mark or a word that
    ends a note or opens a clause, a place one goes ("on", "through", "at"), or "max"/"tops"."""
    return (
        word in V.SPEED_UNITS
        or word in NOTE_ENDS
        or word in _CLAUSE_OPENERS
        or word in WHERE_AFTER_SPEED
        or word in ("at", "max", "tops")
    )


#: "30 mph-ish": a hedge on the unit.
_UNIT_ISH = re.compile(r"\b(km/h|kph|kmh|mph|m/s)-?ish\b")
#: "the high 60s mph", "doing the mid-40s": a speed said by its decade (an age is not: "in his mid-40s").
_DECADE = re.compile(r"\b(?:(?:in )?the )?(low|mid|high)[- ]?([1-9])0s\b")
_IN_DECADE = {"low": 2, "mid": 5, "high": 8}
_SPEED_UNIT_AHEAD = re.compile(r"\s*(?:km/h|kph|kmh|mph|m/s)\b")


def _decade(m: re.Match) -> str:
    """ "about 68" for "the high 60s" said as a speed: with a speed unit after it, or after a verb of
    going or "at"; else as written."""
    before = m.string[: m.start()].split()[-1:]
    if _SPEED_UNIT_AHEAD.match(m.string, m.end()) is None and before not in (["doing"], ["going"], ["at"]):
        return m.group(0)
    return f"about {int(m.group(2)) * 10 + _IN_DECADE[m.group(1)]}"


#: A reference to a numbered source in square brackets ("[12]", "[3, 7]", "[4-6]").
_CITATION = re.compile(r"\[\s*\d+(?:\s*[,\u2013-]\s*\d+)*\s*\]")


def citations(text: str) -> str:
    """``text`` without its numbered references ("the taxonomy of [12]"): a writer citing a source
    says no quantity of the scene, and a bare number there would read as a speed."""
    return _CITATION.sub(" ", text)


_SPEED_AFTER = re.compile(r"\s*(?:km/h|kph|kmh|mph|m/s)\b")


def _a_label_before_a_speed(m: re.Match) -> bool:
    """Whether a range ``m`` of :data:`_RANGE` is a numbered label, a dash, then a speed ("Run 3 - 60 km/h",
    "Test 2 – 40 km/h"): no range of speeds spans more than twice its low end and ten, as a bare one
    may not either (:func:`_bare_range`)."""
    low, high = float(m.group(1)), float(m.group(2))
    return _SPEED_AFTER.match(m.string, m.end()) is not None and high > 2 * low + 10


def ranges(text: str) -> str:
    """Each range of a quantity in the normalised ``text`` as its middle, approximately ("20-30 mph":
    "about 25 mph"): a writer giving a range means a value within it, and the middle is the one that
    errs least; so is a choice of two ("50 or 60 km/h", "at 40 to 50 km/h"). "From 50 to 20 km/h" is
    a change of speed, not a range, and stays; a range said bare after a verb of going ("doing 30-35") is
    one too ("50/20 km/h" is no range: a test's two speeds, the ego's and the target's). A number hedged
    after it ("40ish mph", "30 or so mph",
    "30 mph-ish", "doing 50ish") or said by its decade ("the high 60s mph", "40-something mph") is about that number."""
    text = _UNIT_ISH.sub(r"\1", _HEDGED_AFTER.sub(r"about \1", text))
    text = _HEDGED_BARE.sub(r"\1 about \2", text)
    text = _SOMETHING.sub(lambda m: f"about {m.group(1)}5", text)
    text = _CHOICE_TO.sub(lambda m: f"{m.group(1)} about {(float(m.group(2)) + float(m.group(3))) / 2:g}", text)
    text = _BARE_RANGE.sub(_bare_range, text)
    text = _DECADE.sub(_decade, text)

    def middle(m: re.Match) -> str:
        if not m.group(0).startswith("between") and " and" in m.group(0):
            return m.group(0)  # ("slows to 30 and 20 m later": a list, not a range)
        if _a_label_before_a_speed(m):
            return m.group(0)
        value = (float(m.group(1)) + float(m.group(2))) / 2
        return f"about {value:g} "

    return _RANGE.sub(middle, text)


#: Words that make a number of seconds a time gap between two road users ("a 2 s gap", "1.5 s headway",
#: "3 seconds ahead"), not a time of the story ("at t = 3 s", "TTC 1.5 s", "for 2 seconds").
HEADWAY_WORDS = frozenset({"gap", "headway", "ahead", "behind", "apart", "back", "following", "interval"})
#: The units of a time (a gap said in time, "1.5 s headway", is the headway of a follower).
SECONDS = frozenset({"s", "sec", "secs", "second", "seconds"})


def headway_m(tokens: list[str], i: int) -> float | None:
    """The distance (m) of a time gap at ``i`` ("a 2 s gap" at 72 km/h: 40 m): the seconds times the
    ego's speed where it is said as the ego's, else the speed said last before it with its unit (a time
    gap is the time one takes to reach where the other is); None where it is no time gap or no speed
    is said before it."""
    if tokens[i + 1 : i + 2] == [] or tokens[i + 1] not in SECONDS:
        return None
    nxt = tokens[i + 2 : i + 3] if tokens[i + 2 : i + 3] != ["time"] else tokens[i + 3 : i + 4]  # ("1.5 s time gap")
    before = tokens[max(i - 6, 0) : i]
    follows = any(w.startswith(("follow", "tailgat")) for w in before) and tokens[i - 1] in ("at", "about", "a")
    if not (nxt and nxt[0] in HEADWAY_WORDS) and not follows:
        return None
    ego = ego_speed_mps(tokens)
    if ego is not None:
        return float(tokens[i]) * ego
    for k in range(i - 1, 0, -1):
        if tokens[k] in V.SPEED_UNITS and tokens[k - 1].replace(".", "", 1).isdigit():
            return float(tokens[i]) * float(tokens[k - 1]) * V.SPEED_UNITS[tokens[k]]
    return None


#: Words that name the ego as the subject of its own speed ("ego 90 km/h", "I was doing 72 km/h").
_EGO_SUBJECTS = frozenset({"ego", "i", "we", "vut", "sv"})


def ego_speed_mps(tokens: list[str]) -> float | None:
    """The ego's speed (m/s) where the text gives it with its unit right after naming the ego (within
    four words of its clause: "Ego: 90 km/h", "I was doing 72 km/h"), else None. A time gap to the ego
    is covered at this speed: the ego's, or its follower's, who keeps pace with it."""
    for k, word in enumerate(tokens):
        if word not in V.SPEED_UNITS or not k or not tokens[k - 1].replace(".", "", 1).isdigit():
            continue
        for j in range(k - 2, max(k - 7, -1), -1):
            if tokens[j] in _STOPS or tokens[j] == ",":
                break
            if tokens[j] in _EGO_SUBJECTS:
                return float(tokens[k - 1]) * V.SPEED_UNITS[word]
    return None


#: Measures of things other than speed or distance along the road, after a number ("50 cm to spare",
#: "20 minutes later", "a man of 60 years", "40 tonnes", "6 inches", "150 hp"): the number is no speed.
OTHER_MEASURES = frozenset(
    {"cm", "cms", "centimetre", "centimetres", "centimeter", "centimeters", "mm", "millimetre", "millimetres",
     "millimeter", "millimeters", "inch", "inches", "min", "mins", "minute", "minutes", "hr", "hour", "day", "days",
     "week", "weeks", "month", "months", "year", "years", "yr", "yrs", "yo", "tonne", "tonnes", "ton", "tons",
     "kgs", "kilo", "kilos", "lb", "lbs", "pound", "pounds", "litre", "litres", "liter", "liters", "cc", "hp",
     "bhp", "kw", "rpm", "percent", "times", "quid", "euros", "dollars", "rupees", "rand", "pence"}
)  # fmt: skip


def other_measure(tokens: list[str], i: int) -> bool:
    """Whether the number at ``i`` measures something other than a speed (:data:`OTHER_MEASURES` after
    it), or is the minutes of a clock said in words ("10 past 5", "20 to 6")."""
    nxt = tokens[i + 1] if i + 1 < len(tokens) else ""
    clock = nxt in ("past", "to") and i + 2 < len(tokens) and tokens[i + 2].isdigit() and int(tokens[i + 2]) <= 12
    return nxt in OTHER_MEASURES or (clock and not (i + 3 < len(tokens) and tokens[i + 3] in V.SPEED_UNITS))


def of_a_total(tokens: list[str], i: int) -> bool:
    """Whether the number at ``i`` is the total a place in a series is counted out of ("run 3 of 6",
    "session 4 of about 6", "lane 1 of 3"): "<number> of (about) <number>" says the one before is the
    how-manyeth, and the number after "of" how many there are, no speed ("a speed of 40" has no number
    before its "of")."""
    k = i - 1
    while k > 0 and (tokens[k] in APPROXIMATORS or tokens[k] in _HEDGE_WORDS):
        k -= 1
    return k >= 1 and tokens[k] == "of" and is_number(tokens[k - 1])


#: Words after a number that count the steps of a setting (a following-distance or sensitivity setting:
#: "ACC at 3 bars", "gap on 2 lines", "sensitivity at 4 notches").
_SETTING_STEPS = frozenset("bar bars notch notches dot dots line lines click clicks step steps pip pips".split())
#: The most steps a setting or a series counted so has ("3 of 5", "level 2 of 4"); a number out of more is
#: a speed against its limit ("doing 30 of 30").
_MOST_STEPS = 10


def place_in_a_series(tokens: list[str], i: int) -> bool:
    """Whether the number at ``i`` is a place counted out of a total or a step of a setting ("ACC at 3 of
    5", "time gap set to 3 (of 5)", "run 2 of 6", "ACC at 3 bars"): a setting or a count, no speed,
    whatever "at" or "set to" stands before it (:func:`of_a_total` reads the total after "of")."""
    k = i + 1 + (tokens[i + 1 : i + 2] == ["("])
    if tokens[k : k + 1] == ["of"] and k + 1 < len(tokens) and is_number(tokens[k + 1]):
        return float(tokens[k + 1]) <= _MOST_STEPS  # (not "doing 30 of 30", "48 (of 50 allowed)": the limit)
    return tokens[i + 1 : i + 2] != [] and tokens[i + 1] in _SETTING_STEPS


#: Names of a change of speed in a crash, as reconstruction reports write them: "delta-v" (also "delta v",
#: "dV") and the energy equivalent speed, "EES": how much speed the crash took, not a speed travelled.
_CRASH_CHANGES = frozenset({"delta-v", "deltav", "dv", "d-v", "ees"})
#: How far back from a number its crash measure may stand ("delta-v of the ego was approx. 38 km/h").
_CRASH_CHANGE_REACH = 6


def crash_change_of_speed(tokens: list[str], i: int) -> bool:
    """Whether the number at ``i`` measures a change of speed in a crash ("delta-v V1 = 38 km/h", "Delta V
    for the car was 25 km/h", "the EES was 35 km/h"): a crash measure names it before, within its clause.
    Why: it says how hard the crash was, so it is the speed of no one (not "a Lancia Delta at 40 km/h")."""
    for k in range(i - 1, max(i - 1 - _CRASH_CHANGE_REACH, -1), -1):
        if tokens[k] in _STOPS or tokens[k] == ",":
            return False
        if tokens[k] in _CRASH_CHANGES or (tokens[k] == "v" and k and tokens[k - 1] == "delta"):
            return True
    return False


#: Words between "over" and the limit it is over ("over the posted limit", "above the 30 mph speed limit").
_BEFORE_LIMIT = frozenset({"the", "a", "posted", "speed", "legal", "signed", "its", "that", "mph", "km/h", "kph"})
_OVER = frozenset({"over", "above"})


def over_the_limit(tokens: list[str], i: int) -> bool:
    """Whether the number at ``i`` says how far over a limit a speed was ("8 mph over the limit", "12 km/h
    above the posted limit", "over the limit by 15 mph"): a difference of two speeds, no one's speed. Why: a
    speeding report gives both, and the excess is the smaller number, said where a speed is said. Only with
    "limit" after it: "38 mph over the bridge" is a speed over a place."""
    j = i + 1 + (i + 1 < len(tokens) and tokens[i + 1] in V.SPEED_UNITS)
    if j < len(tokens) and tokens[j] in _OVER:
        k = j + 1
        while k < len(tokens) and k <= j + 4 and (tokens[k] in _BEFORE_LIMIT or is_number(tokens[k])):
            k += 1
        if k < len(tokens) and tokens[k] == "limit":
            return True
    nxt = tokens[i + 1] if i + 1 < len(tokens) else ""  # ("by 15 mph", "by 15."; not "by 30 m": a distance)
    by = i >= 2 and tokens[i - 1] == "by" and (nxt in V.SPEED_UNITS or nxt in NOTE_ENDS)
    return by and "limit" in tokens[max(i - 5, 0) : i - 1]


#: Words after "<number> speed" that end its phrase ("going 40 speed only", "coming 50 speed, ...", "with
#: 60 speed on the flyover"): the number is then a speed, not a thing of speeds ("a 40 speed limit", "a 5
#: speed gearbox", "3 speed bumps").
_AFTER_NUMBER_SPEED = frozenset({"only", "so", "also", "as", "at", "in", "exactly", "approx", "approximately"})


def number_speed(tokens: list[str], i: int) -> bool:
    """Whether the number at ``i`` is a speed said "<number> speed" ("I was going 40 speed only", "at 60
    speed on the flyover", "sixty speed, ..."), as South Asian English says it: "speed" ends the phrase
    or a place or a clause follows it. Not where a noun follows it, which the number and "speed" then
    describe ("a 40 speed limit", "a 21 speed bike", "3 speed bumps")."""
    if i + 1 >= len(tokens) or tokens[i + 1] not in SPEED_HEADS:
        return False
    after = tokens[i + 2] if i + 2 < len(tokens) else ""
    return after in _SPEED_PHRASE_ENDS or after in WHERE_AFTER_SPEED or after in _AFTER_NUMBER_SPEED


#: Parts of the day, and words of the day said of the story, beside which a bare hour is a time ("around
#: 7 this morning", "at 9 last night", "Today morning, around 7", "tonight around 10").
#: The light of a time of day, which the lexicon reads as one too: said with no hour ("in the dark, at 8").
_LIGHT = frozenset({"dark", "darkness", "dusky", "daylight", "daytime"})
#: Parts of the day, by every one-word name the lexicon reads as a time ("arvo", "lunchtime", "sundown").
_PARTS_OF_DAY = frozenset(
    {"morning", "mornings", "afternoon", "evening", "evenings", "night", "tonight", "today", "yesterday", "dawn",
     "dusk", "midnight", "noon", "midday", "am", "pm", "a.m.", "p.m.", "forenoon", "daybreak", "sunrise", "sunset"}
    | {name for names in L.TIMES.values() for name in names if name.isalpha() and name not in _LIGHT}
)  # fmt: skip
#: Words that say a time before an hour ("at 7", "around 7", "by 8", "after 9", "till 10").
_BEFORE_HOUR = frozenset({"at", "around", "about", "approx", "approximately", "by", "after", "before", "till",
                          "until", "roughly", "circa", "~", "like", ",", "just"})  # fmt: skip
#: Words between an hour and the part of the day after it ("7 this morning", "9 last night", "8 in the morning").
_HOUR_LINKS = frozenset({"this", "last", "in", "the", "on", "that", "yesterday", "tomorrow", "o'clock", ","})


#: A clock written with a dot and no half of the day ("3.15", "7.30", "23.10"): an hour and its minutes.
_DOTTED_TIME = re.compile(r"([01]?\d|2[0-3])\.([0-5]\d)")


#: The hours said in words, beside which "to" or "past" makes a number minutes ("twenty to seven").
_HOUR_WORDS = frozenset("one two three four five six seven eight nine ten eleven twelve".split())


#: Words ending in "s" that are no plural noun after an hour ("at ten past two this morning", "as").
_NOT_PLURAL = frozenset({"as", "is", "was", "this", "his", "its", "us", "yes", "whereas", "has"})


def _minutes_to_an_hour(tokens: list[str], i: int) -> bool:
    """Whether the number at ``i`` is minutes to or past an hour ("at twenty to seven", "at 10 past 8"),
    which the reader reads as a number: a whole number of minutes up to half an hour, then "to" or
    "past", then an hour (1 to 12, or its word) that no unit, number or counted noun follows ("at 10 to
    12 mph" is a speed; "from 5/12 to 5/16" is dates; "at 20 past two parked vans" counts vans)."""
    if not tokens[i].isdigit() or not 1 <= int(tokens[i]) <= 30 or i + 2 >= len(tokens):
        return False
    hour = tokens[i + 2]
    if tokens[i + 1] not in ("to", "past") or not (hour in _HOUR_WORDS or hour.isdigit() and 1 <= int(hour) <= 12):
        return False
    after = tokens[i + 3] if i + 3 < len(tokens) else ""
    counted = after.isalpha() and after.endswith("s") and after not in _NOT_PLURAL
    if after in ("parked", "stationary", "stopped") or counted:
        return False  # ("at 20 past two parked vans", "at 30 past two cars": a count of what is passed)
    return after not in V.SPEED_UNITS and not is_number(after)


def clock_hour(tokens: list[str], i: int) -> bool:
    """Whether the bare number at ``i`` is a time of day: a clock with a dot after a word of time ("at
    approx 3.15", "around 7.30"), or a whole hour, 1 to 12, after a word of time ("at", "around", "by")
    with a part of the day right after it ("around 7 this morning", "at 9 last night") or within the
    three words before it ("Today morning, around 7", "tonight around 10") and no verb of going right
    before the number ("At lunchtime, doing about 12", "Around sundown, going just 10": speeds). Why:
    an hour said so reads like "at 7" of a speed, and one of a few km/h is the pace of no car; a speed
    is never written with minutes."""
    if i == 0 or tokens[i - 1] not in _BEFORE_HOUR:
        return False
    if _DOTTED_TIME.fullmatch(tokens[i]):
        return True
    if _minutes_to_an_hour(tokens, i):
        return True
    if not tokens[i].isdigit() or not 1 <= int(tokens[i]) <= 12:
        return False
    k = i + 1
    while k < len(tokens) and k <= i + 3 and tokens[k] in _HOUR_LINKS:
        k += 1
    if k < len(tokens) and tokens[k] in _PARTS_OF_DAY:
        return True
    j = i - 1
    while j > 0 and (tokens[j] in APPROXIMATORS or tokens[j] in _HEDGE_WORDS):
        j -= 1
    if tokens[j] in _MOTION and tokens[j].endswith("ing"):
        return False  # ("At lunchtime, doing about 12 through the car park": how fast one goes)
    return any(tokens[k] in _PARTS_OF_DAY for k in range(max(i - 4, 0), i - 1))


#: Prepositions of where one goes, after "going 40" ("going 40 down the hill", "driving 30 past the
#: school"): the number between a verb of going and its place is how fast it goes.
WHERE_AFTER_SPEED = frozenset(
    "on down along through past by in into up round around towards toward over across near".split()
)


def after_at(tokens: list[str], i: int) -> bool:
    """Whether a bare number at ``i`` is a speed after "at" (or "doing"), an article and one or two
    modifiers (:func:`speed_after_modifiers`)."""
    return speed_after_modifiers(tokens[max(i - 4, 0) : i], tokens[i + 1] if i + 1 < len(tokens) else "")


def speed_after_modifiers(before: list[str], after: str) -> bool:
    """Whether a number with the words ``before`` it and the word ``after`` it follows "at" (or "doing")
    past an article and one modifier ("at a steady 50", "doing a brisk 30"), or a word that describes it
    before that ("at a nice steady 50", "at a very sensible 65"): a speed, as "at 50" is. The first of two
    words is then an adjective or an adverb and no noun, so a place named there ("at the old station 12
    ...") stays no speed; and a number before a word that is only a noun counts that noun ("at a very
    quiet 4 way stop", "doing a careful 3 point turn", "at a nice 5 star hotel"): no speed. Figures and
    numbers in words alike (:mod:`normalise` asks it of "at a cautious thirty")."""
    words = [w.lower() for w in before]
    if len(words) < 3 or not words[-1].isalpha() or _counted(after.lower()):
        return False
    if words[-2] in _ARTICLES and words[-3] in ("at", "doing"):
        return True
    return len(words) >= 4 and words[-3] in _ARTICLES and words[-4] in ("at", "doing") and _describes(words[-2])


def _counted(word: str) -> bool:
    """Whether ``word`` is only a noun ("way", "point", "star", "room"), which a number before it counts;
    not a word of time or place that may follow a speed ("today", "past", "behind": adverbs too)."""
    said = lemmas(word) if word.isalpha() else {}
    return "NOUN" in said and not {"ADJ", "ADV"} & set(said) and word != "all"  # ("at a steady 50 all the way")


def _describes(word: str) -> bool:
    """Whether ``word`` is only an adjective or an adverb ("nice", "very"), never a noun ("old", "station")."""
    said = lemmas(word)
    return bool({"ADJ", "ADV"} & set(said)) and "NOUN" not in said


#: Verbs of keeping a speed "on" a number (lemmas): "sitting on 110", "sat on 70", "cruising on 100".
_HELD_ON = frozenset({"sit", "cruise", "hold", "stay", "keep"})


def held_on(tokens: list[str], i: int) -> bool:
    """Whether the bare number at ``i`` is one a driver sits on ("sitting on 110 in the left lane",
    "we sat on 90 the whole way"): a speed held, as the speedometer shows it. Only where the number ends
    its phrase or a place follows ("sitting on 3 points", "sat on bus 100" are no speeds)."""
    if i < 2 or tokens[i - 1] != "on":
        return False
    nxt = tokens[i + 1] if i + 1 < len(tokens) else ""
    verbs = set(lemmas(tokens[i - 2]).get("VERB", ()))
    return bool(_HELD_ON & verbs) and (nxt in NOTE_ENDS or nxt in WHERE_AFTER_SPEED or nxt in ("the", "all"))


#: Words after which a number ends its note ("ego 50, ...", "ego 50 and a van ...").
NOTE_ENDS = frozenset({"", ".", ",", ";", "!", "?", "and", "then", "when", "while", "but", ")"})


def after_ego(tokens: list[str], i: int) -> bool:
    """Whether the bare number at ``i`` stands right after the ego's name and ends its note ("..., ego
    50", "SUT 40, cyclist ..."): the ego's speed, as "cyclist 15 km/h" is the cyclist's. (Only the
    ego's: "Vehicle 2." or "lane 3," name things by a number.)"""
    nxt = tokens[i + 1] if i + 1 < len(tokens) else ""
    return i >= 1 and tokens[i - 1] == "ego" and nxt in NOTE_ENDS


#: ``mention_ending_at(k)``: the start of the road-user (or ego) mention whose last word is token ``k``.
Mentions = Callable[[int], "int | None"]


def carried_unit(
    tokens: list[str], i: int, imperial: bool = False, metric: bool = False, narrated: bool = False
) -> float:
    """The factor to m/s of a bare speed at ``i`` ("I'm at 50"): the unit of the last speed said with
    one before it, else of the first said after it, else mph on a road of a country that signs miles
    (:func:`miles_country`; ``imperial``: the text measured a length in feet or yards, see
    :func:`imperial_lengths`), else km/h (the unit of a test engineer who gives none; a motorway says
    neither: in heavy traffic 60 km/h is as likely there as 60 mph). ``metric``: the text as written was
    set where km/h is signed (:func:`metric_country` of its tokens before the reader named the ego's
    own vehicle "the ego": "in the ute"). ``narrated``: the text is told in the first person, whose bare
    speeds a value only mph limits round to makes mph (:func:`miles_limit_speed`)."""
    for k in range(i - 1, 0, -1):
        if tokens[k] in V.SPEED_UNITS and tokens[k - 1].replace(".", "", 1).isdigit():
            return V.SPEED_UNITS[tokens[k]]
    for k in range(i + 1, len(tokens)):  # none before: the one said after it ("at 30 and ... 20 mph")
        if tokens[k] in V.SPEED_UNITS and tokens[k - 1].replace(".", "", 1).isdigit():
            return V.SPEED_UNITS[tokens[k]]
    if metric or metric_country(tokens):
        return 1 / 3.6
    miles = (
        imperial
        or miles_country(tokens)
        or free_motorway_speed(tokens, i)
        or (narrated and miles_limit_speed(tokens, i))
    )
    return V.SPEED_UNITS["mph"] if miles else 1 / 3.6


#: Bare speeds only a mile-per-hour limit rounds to (:data:`_MILES_LIMITS` above a walker's or rider's 15):
#: where km/h is signed, limits are multiples of ten and a driver rounds to them.
_MILES_ONLY_SPEEDS = frozenset({25, 35, 45, 55, 65, 75})
#: Words of riding a bike or scooter: a rider's bare 25 is the km/h an e-bike or e-scooter is held to.
_RIDING = frozenset(
    {"ride", "rides", "riding", "rode", "cycle", "cycles", "cycling", "cycled", "scooting", "scooted", "pedalling",
     "pedaling", "pedalled", "pedaled"}
)  # fmt: skip


def miles_limit_speed(tokens: list[str], i: int) -> bool:
    """Whether the bare speed at ``i`` is one only a mile-per-hour limit rounds to ("doing about 35", "at a
    steady 55"): a driver gives the speed they hold by their limits, and km/h limits are multiples of ten,
    so a bare 25, 35, 45 ... is said where miles are signed. Not a rider's (a bare "riding at 25" is the
    e-scooter's 25 km/h), not "45 speed", the km/h of Indian English, and not the middle of a range ("doing
    30-40" is "doing about 35.0"), which no writer rounded. The caller asks only in a story told in the
    first person: a narrator reads their own speedometer; a third party's bare number is an estimate or a
    spec's, in km/h as a test engineer gives it."""
    value = float(tokens[i])
    if not tokens[i].isdigit() or int(value) not in _MILES_ONLY_SPEEDS or tokens[i + 1 : i + 2] == ["speed"]:
        return False
    return not any(t in _RIDING for t in tokens[sentence_start(tokens, i, _STOPS) : i])


#: Words of slow traffic ("heavy traffic", "jammed", "rush hour", "roadworks"): at them a motorway's
#: speed is anyone's, in either unit.
_SLOW_TRAFFIC = frozenset(
    {"heavy", "queue", "queues", "queuing", "queueing", "jam", "jammed", "congestion", "congested", "rush", "peak",
     "crawling", "crawl", "stop-start", "roadworks", "works", "slow", "slow-moving", "busy", "gridlock", "tailback",
     "tailbacks", "traffic-jam", "standstill"}
)  # fmt: skip
#: The lowest speed (km/h) a motorway is signed at where km/h is signed: a free-flowing motorway
#: speed said bare below it is one in mph ("on the motorway doing 70": 70 mph, the British limit).
_METRIC_MOTORWAY_KPH = 80


def free_motorway_speed(tokens: list[str], i: int) -> bool:
    """Whether the bare speed at ``i`` is one of free-flowing traffic on a motorway that only mph makes
    a motorway speed: 50 to 79 on a "motorway" where no slow traffic is said. Why: where km/h is signed a
    motorway runs at 100 or more, so a driver there who gives 70 is in a queue and says so; one who
    gives 70 bare on a clear motorway drives in Britain."""
    value = float(tokens[i])
    if not 50 <= value < _METRIC_MOTORWAY_KPH or not any(t in ("motorway", "motorways") for t in tokens):
        return False
    return not any(t in _SLOW_TRAFFIC and not _of_the_weather(t, nxt) for t, nxt in zip(tokens, [*tokens[1:], ""]))


#: Words of the weather ("rain", "fog", "spray"): "heavy" said of one is how hard it falls, not how slow traffic is.
_WEATHER_WORDS = frozenset(w for words in L.WEATHER.values() for w in words) | {"spray", "showers"}


def _of_the_weather(word: str, nxt: str) -> bool:
    """Whether ``word`` is "heavy" said of the weather word ``nxt`` after it ("heavy rain", "heavy
    fog"): the weather, not heavy traffic."""
    return word == "heavy" and nxt in _WEATHER_WORDS


#: Roads only countries that sign km/h have, by their own names (the German Autobahn and Bundesstrasse,
#: the French autoroute, the Italian autostrada, the Spanish autopista), and distances in kilometres: a
#: text set on one reads a bare speed in km/h whatever else looks British or American ("the A8", "the B27").
_METRIC_ROADS = frozenset(
    {"autobahn", "autobahns", "bundesstrasse", "bundesstra", "autoroute", "autostrada", "autopista", "km", "kms"}
)


#: Road users by names said only where speeds are signed in km/h: the pickup of Australia and South
#: Africa, the minibus taxis of Africa and the Philippines, the motorbike taxis of Africa, the
#: three-wheelers of South and South-East Asia. Who names one tells of the traffic there, whatever road
#: word the text shares with Britain or America ("the freeway", "the curb", "the carriageway").
_METRIC_ROAD_USERS = frozenset(
    {"ute", "utes", "bakkie", "bakkies", "kombi", "kombis", "matatu", "matatus", "dala-dala", "jeepney", "jeepneys",
     "trotro", "tro-tro", "danfo", "danfos", "molue", "okada", "okadas", "keke", "boda", "boda-boda", "bodaboda",
     "tuk-tuk", "tuk-tuks", "tuktuk", "tuktuks", "auto-rickshaw", "auto-rickshaws", "autorickshaw", "bajaj",
     "bajaji", "songthaew", "angkot", "bemo", "habal-habal"}
)  # fmt: skip


#: The police and emergency lines of countries that sign km/h by their own names (the Irish Gardai, the
#: German Polizei and its Notruf, the Dutch and Belgian politie, the French gendarmes, the Italian
#: carabinieri and polizia): a text that names one is set there, whatever else looks British ("a mile
#: past the creamery", "the A7").
_METRIC_POLICE = frozenset(
    {"garda", "gardai", "polizei", "notruf", "politie", "gendarmerie", "gendarmes", "carabinieri", "polizia"}
)


def metric_country(tokens: list[str]) -> bool:
    """Whether the text is set where speeds are signed in km/h: a road of such a country by its own
    name, a distance said in kilometres, a road user by a name only such countries use, or its police
    by their own name."""
    return any(t in _METRIC_ROADS or t in _METRIC_ROAD_USERS or t in _METRIC_POLICE for t in tokens)


#: A length in feet or yards ("ten feet ahead", "by a foot", "a few yards"), as written (the reader's
#: tokens hold it in metres); "on foot" and "his feet" measure nothing.
_IMPERIAL_LENGTH = re.compile(
    r"(?:\d|\b(?:a|an|few|of|several|one|two|three|four|five|six|seven|eight|nine|ten|eleven|twelve|fifteen"
    r"|twenty|thirty|forty|fifty|sixty|hundred)\s)\s*(?:-\s*)?(?:feet|foot|ft|yards?|yds?)\b"
)


#: A numbered road of Britain written as one word ("A46", "m6", "B4521"): never the article "a" before a
#: number ("a 40", "a 30 zone"), which has a space. Not a model after its make ("Audi A4", "BMW M3").
_ROAD_NUMBER = re.compile(r"(?:^|(?<=[\s(/,;:]))(?P<make>(?:audi|bmw|mercedes|merc|benz|amg)\s+)?[amb]\d{1,4}\b")


def road_number_written_whole(text: str) -> bool:
    """Whether ``text`` (lowercased) names a numbered road of Britain written as one word ("A46 towards
    Lincoln", "on m6 southbound"): a road of a country that signs miles per hour, where the tokens lose
    the "a" of "A46" as an article at the start of a sentence or with no "the" before it."""
    return any(not m.group("make") for m in _ROAD_NUMBER.finditer(text))


#: The class of a British main road written with its hyphen ("on the A-road", "quiet A-roads"), which the
#: tokens read as "a road" (the B-road keeps its letter there, and :func:`miles_country` reads it).
_A_ROAD = re.compile(r"(?<![\w-])a-roads?\b")


def a_road_named(text: str) -> bool:
    """Whether ``text`` (lowercased) names the British class of main road, "A-road": a road of a country
    that signs miles per hour, as "the A46" is (:func:`road_number_written_whole`)."""
    return _A_ROAD.search(text) is not None


def imperial_lengths(text: str) -> bool:
    """Whether ``text`` (lowercased) measures a length in feet or yards: a writer who does signs speeds
    in miles per hour, so a bare speed of theirs is in mph."""
    return _IMPERIAL_LENGTH.search(text) is not None


#: Roads only countries that sign speeds in miles per hour have: the British "carriageway" and the
#: American interstate, freeway, turnpike, and the places beside an American road by their American
#: names (curb, sidewalk, crosswalk, gas station, parking lot). ("Motorway" and "highway" are said where
#: km/h is signed too.)
_MILES_ROADS = frozenset(
    {"carriageway", "carriageways", "interstate", "freeway", "freeways", "turnpike", "curb", "curbs", "sidewalk",
     "sidewalks", "crosswalk", "crosswalks", "sliproad", "sliproads", "lay-by", "lay-bys", "laybys", "stoplight",
     "stoplights"}
)  # fmt: skip
#: Two-word road names of Britain ("the slip road", "the hard shoulder": the motorway's, said in Britain,
#: where Australians say on-ramp and emergency lane) and of America ("a divided highway", "the gas
#: station", "a parking lot", "an 18-wheeler", "a state trooper", "the highway patrol").
_MILES_PAIRS = frozenset(
    {("divided", "highway"), ("gas", "station"), ("parking", "lot"), ("18", "wheeler"), ("slip", "road"),
     ("slip", "roads"), ("hard", "shoulder"), ("state", "trooper"), ("state", "troopers"), ("highway", "patrol")}
)  # fmt: skip
#: Distances in miles ("for a mile", "two miles back"): a writer who measures the road in miles reads
#: its speeds in miles per hour.
_MILES = frozenset({"mile", "miles"})
#: Letters of numbered roads in Britain (M6, A34, B1234) and the United States (I-95), as tokens.
_ROAD_LETTERS = frozenset({"m", "a", "b", "i-"})
#: Speed limits only miles per hour have (25, 35, 45, 55, 65 mph); km/h limits are multiples of ten.
_MILES_LIMITS = frozenset({15, 25, 35, 45, 55, 65, 75})


#: Units of length and time after a number: a number said with one measures, it names no road.
_MEASURES = frozenset({"m", "metres", "meters", "metre", "meter", "km", "s", "sec", "secs", "seconds", "%"})


def is_number(word: str) -> bool:
    return word.replace(".", "", 1).isdigit()


def miles_country(tokens: list[str]) -> bool:
    """Whether the road the text is set on is one of a country that signs speeds in mph: a British or
    American road word (a "high street" too), a numbered road ("the M25", "the A34", "B-road", "I-95"), a limit only mph
    has ("a 35 zone"), or a distance in miles. Why: a driver who gives a bare number ("doing about
    70") gives it in the unit of their road signs, and names the road far more often than the unit."""
    for k, tok in enumerate(tokens):
        nxt = tokens[k + 1] if k + 1 < len(tokens) else ""
        if tok in _MILES_ROADS or tok in _MILES or (tok, nxt) in _MILES_PAIRS:
            return True
        measured = tokens[k + 2 : k + 3] != [] and (tokens[k + 2] in _MEASURES or tokens[k + 2] in V.SPEED_UNITS)
        if tok in _ROAD_LETTERS and nxt.isdigit() and not measured and not (k and is_number(tokens[k - 1])):
            # "the M25", "I-95" (not "5 m 20": metres; not "a 40": an article unless "the" stands before it;
            # not "car B 20 m ahead": a label, then a measure)
            if tok in ("m", "i-") or (tok == "b" and len(nxt) >= 2) or (k and tokens[k - 1] == "the"):
                return True
        if tok == "b" and nxt in ("road", "roads"):  # ("a B-road"; "A-road" reads as "a road")
            return True
        if tok.isdigit() and int(tok) in _MILES_LIMITS and nxt in ("limit", "zone"):
            return True
        if tok == "high" and nxt in ("street", "st"):  # (the British town-centre road: "down the high street")
            return True
    return False


def lateral(tokens: list[str], i: int, used: int) -> bool:
    """Whether the number at ``i`` (``used`` tokens with its unit) measures across the road: a lateral
    head in the three words before it or the two after it, within its clause."""
    for k in range(i - 1, max(i - 4, -1), -1):
        if tokens[k] in _STOPS or tokens[k] == ",":
            break
        if tokens[k] in LATERAL_HEADS:
            return True
    after = tokens[i + used : i + used + 2]
    return (
        (bool(after) and after[0] in LATERAL_HEADS)
        or _subject_is_lateral(tokens, i)
        or _off_a_flank(tokens, i, used)
        or _from_the_kerb(tokens, i + used)
        or _how_far_one_sees(tokens, i)
        or _clearance_of_a_pass(tokens, i)
    )


def _off_a_flank(tokens: list[str], i: int, used: int) -> bool:
    """Whether the words after the length at ``i`` (``used`` tokens with its unit) say it off a vehicle's
    side ("1 m off the left side of the van", "a foot off my wing mirror"), or from it after a verb of
    passing ("came past a metre from my door", "passing a foot from my mirror"): a passing margin across
    the road, as the room a pass is made "with", not a gap ahead."""
    k = i + used
    if not (tokens[k : k + 1] in (["off"], ["from"]) and _FLANKS & set(tokens[k + 1 : k + 5])):
        return False
    return tokens[k] == "off" or _a_pass_before(tokens, i)


#: Words after a length that make it the size of a thing ("a 2 m wide trailer", "a pothole a foot deep").
_SIZE_WORDS = frozenset({"wide", "long", "high", "tall", "deep", "thick"})


def a_size(tokens: list[str], i: int, used: int) -> bool:
    """Whether the length at ``i`` (``used`` tokens with its unit) is how big something is, not how far
    apart: a word of size follows it ("a foot deep", "3 m long"), or "across" ending its phrase ("it's
    about a foot across and deep"; "2 m across the road" is where someone is)."""
    after = tokens[i + used : i + used + 2]
    if not after:
        return False
    if after[0] in _SIZE_WORDS:
        return True
    return after[0] == "across" and (len(after) < 2 or after[1] in _STOPS or after[1] in (",", "and", "or"))


#: Words between "for" and the length of a stretch gone along ("for a good 200 m", "for about 300
#: metres", "for the last 100 m", "for another 50 m").
_STRETCH_HEDGES = frozenset(
    {"a", "good", "about", "around", "roughly", "nearly", "almost", "another", "at", "least", "the", "last",
     "next", "first", "best", "part", "of", "maybe", "some", "over", "well", "easily", "approx", "approximately"}
)  # fmt: skip


#: Nouns of the room left between two, after a length ("for 1.5 m of clearance", "for a 2 m gap").
_ROOM_LEFT = frozenset({"clearance", "gap", "space", "room", "margin", "separation", "berth", "distance"})


def a_stretch(tokens: list[str], i: int, used: int) -> bool:
    """Whether the length at ``i`` (``used`` tokens with its unit) is how far someone went, not how far
    apart: "for" before it with only hedges between ("sat 2 m behind him for a good 200 m", "tailgated
    me for 300 metres"). English says a stretch of road gone along as it says a time, with "for"; the gap
    is said apart ("2 m"). Not a room aimed for ("aiming for 1.5 m of clearance", "for a 2 m gap")."""
    after = tokens[i + used : i + used + 2]
    if after[:1] and (after[0] in _ROOM_LEFT or (after[0] == "of" and after[1:] and after[1] in _ROOM_LEFT)):
        return False
    k = i - 1
    while k >= 0 and i - k <= 4 and tokens[k] in _STRETCH_HEDGES:
        k -= 1
    return k >= 0 and tokens[k] == "for"


#: How far back in its clause "visibility" may head a length ("visibility was down to about 50 m").
_SEEING_REACH = 7
#: Verbs (lemmas) "visibility" comes to a length with ("visibility was/dropped/was reduced to 50 m").
_SEEING_VERBS = frozenset({"be", "reduce", "drop", "fall", "limit", "come", "get"})
#: Words that open a new clause, whose length is no longer what the one before it governs.
_NEW_CLAUSE = frozenset({"and", "but", "then", "when", "while", "whilst", "until"})


def _finite_verb(word: str) -> bool:
    """Whether ``word`` is only a verb ("braked", "ran", "pulled"; not "spray", "down", "being")."""
    read = lemmas(word)
    return bool(read.get("VERB")) and not set(read) - {"VERB", "AUX"}


def _how_far_one_sees(tokens: list[str], i: int) -> bool:
    """Whether the length at ``i`` is what "visibility" comes to in its clause ("visibility was down to
    about 50 m", "visibility in the spray under 40 m"): how far one sees, however it is put, no gap. Only
    a length "visibility" governs: a new clause or another verb between them ("visibility was good and a
    lorry braked 30 m ahead", "in poor visibility a car pulled out 20 m ahead") gives it to that verb."""
    for k in range(i - 1, max(i - 1 - _SEEING_REACH, -1), -1):
        if tokens[k] in _STOPS or tokens[k] in (",", ";", ":") or tokens[k] in _NEW_CLAUSE:
            return False
        if tokens[k] == "visibility":
            return True
        if _finite_verb(tokens[k]) and not set(lemmas(tokens[k])["VERB"]) & _SEEING_VERBS:
            return False
    return False


#: Verbs (lemmas) of going past someone by themselves ("passed me with a metre to spare").
_PASS_VERBS = frozenset({"pass", "squeeze", "skim", "shave", "brush", "scrape"})
#: Verbs (lemmas) of motion that go past someone with a particle ("swerved past us", "went round him").
_MOVE_VERBS = frozenset({"go", "come", "get", "swerve", "ride", "drive", "fly", "whizz", "zip", "squeeze", "nip"})
_PAST = frozenset({"past", "by", "round", "around"})
#: Verbs (lemmas) of stopping or coming in ahead: "with" a length after one of them, nearer than a pass,
#: is the gap left ahead ("passes us and cuts back in with 3 m to spare"), not a pass's room.
_AHEAD_VERBS = frozenset({"stop", "halt", "pull", "brake", "cut", "merge", "swing"})
#: How far back in its clause the verb of a pass may stand before "with" ("passed me on the left with").
_PASS_REACH = 7


def _clearance_of_a_pass(tokens: list[str], i: int) -> bool:
    """Whether the length at ``i`` is the room a pass was made "with" ("passed with maybe half a metre to
    spare", "swerved past us with a metre to spare"): how far apart side by side, across the road, not
    where anyone starts. Overtaking keeps its own reading (the gap it cuts back in at)."""
    k = i - 1
    while k >= 0 and (tokens[k] in _HEDGE_WORDS or tokens[k] in APPROXIMATORS or tokens[k] in GUESSES):
        k -= 1
    return k >= 0 and tokens[k] == "with" and _a_pass_before(tokens, k)


def _a_pass_before(tokens: list[str], k: int) -> bool:
    """Whether a verb of going past someone stands in the clause before ``k`` ("passed me with", "came
    past me a foot from my mirror"), nearer than a verb of stopping or coming in ahead; not across "and",
    "then" or "but" ("passed me and with 10 m between us it braked": the gap the new clause says)."""
    for j in range(k - 1, max(k - 1 - _PASS_REACH, -1), -1):
        if tokens[j] in _STOPS or tokens[j] in (",", ";", ":") or tokens[j] in _NEW_CLAUSE:
            return False
        said = set(lemmas(tokens[j]).get("VERB", ()))
        if said & _AHEAD_VERBS:
            return False
        if said & _PASS_VERBS or (said & _MOVE_VERBS and tokens[j + 1 : j + 2] and tokens[j + 1] in _PAST):
            return True
    return False


#: Marks on the road and what stands at its edge that a length may be said from or before ("stopped a
#: metre before the stop line", "2 m short of the zebra crossing"), besides the kerb itself.
_MARKS = frozenset({"line", "lines", "crossing", "crosswalk", "lights", "bollard", "bollards", "island", "sign"})


def _from_the_kerb(tokens: list[str], k: int) -> bool:
    """Whether the words from ``k`` (after a length) measure it from the kerb or the road's edge ("rode
    a metre from the kerb", "2 m off the verge"), or from or before a line, a crossing or a thing at the
    edge ("stopped a metre before the stop line", "3 m short of the crossing"): where a road user is,
    no gap to the ego."""
    if tokens[k : k + 2] == ["short", "of"]:
        k += 1
    if tokens[k : k + 1] in (["from"], ["off"]) and KERB_NOUNS & set(tokens[k + 1 : k + 4]):
        return True
    return tokens[k : k + 1] in (["from"], ["before"], ["of"]) and bool(_MARKS & set(tokens[k + 1 : k + 5]))


_COPULAS = frozenset({"is", "was", "are", "were", "'s"})
#: The words of the lateral heads that say "across" themselves (not "minimum" or "closest", which a
#: gap ahead can be too: "the minimum gap to the van was 3 m").
_ACROSS = frozenset({"lateral", "laterally", "sideways", "offset"})
#: How far back a copula's subject may reach ("the minimum lateral separation measured from the
#: footage is 0.5 m").
_SUBJECT_REACH = 8


def _subject_is_lateral(tokens: list[str], i: int) -> bool:
    """Whether the number at ``i`` is the complement of a copula whose subject, within its clause, is a
    lateral measure ("the smallest lateral gap recorded was about 0.4 m", "its sideways offset is 0.3
    m"): said across the road however many words the subject runs to."""
    k = i - 1
    while k >= 0 and tokens[k] in _LINKS and tokens[k] not in _COPULAS:
        k -= 1
    if k < 0 or tokens[k] not in _COPULAS:
        return False
    for m in range(k - 1, max(k - 1 - _SUBJECT_REACH, -1), -1):
        if tokens[m] in _STOPS or tokens[m] in (",", ";", ":"):
            return False
        if tokens[m] in _ACROSS:
            return True
    return False


#: Words that hedge or bound a number and say nothing else ("about", "approx.", "~", "just under"): a
#: number after a noun past them is said of the noun as one right after it is ("cyclist approx. 15 km/h").
#: (normalise writes "approx.", "circa", "ca." and "est." before a digit as "about"; "ca" without its dot
#: is still read here, "Truck ca 80 km/h", and "circa" and "est" before another hedge, "circa ~80 km/h".)
_HEDGES = (_HEDGE_WORDS | APPROXIMATORS | {"ca", "circa", "est", "estimated"}) - {"some"}


def _only_hedges(words: list[str]) -> bool:
    """Whether ``words`` (between a noun and its number) are one or more hedges only (see :data:`_HEDGES`)."""
    return bool(words) and all(w in _HEDGES for w in words)


def _past_conversion(tokens: list[str], j: int) -> int:
    """The index after a speed's conversion to another unit that starts at ``j`` ("55 mph (89 km/h)": the
    reader's tokens keep "89 km/h" without its brackets), or ``j`` where none stands there."""
    if j + 1 < len(tokens) and is_number(tokens[j]) and tokens[j + 1] in V.SPEED_UNITS:
        return j + 2
    return j


#: Words before a change "from X to Y" that say it slows ("slowed", "braked", "dropped", "eased off",
#: "came down from"): it starts at X. Lemmas, and the nouns of the change ("a deceleration from").
_SLOWING = frozenset(
    ("slow", "slowdown", "brake", "braking", "decelerate", "deceleration", "drop", "ease", "reduce", "reduction")
    + ("decrease", "lower", "fall", "scrub", "shed", "cut", "down")
)
#: Words before it that say it speeds up ("accelerated", "sped up", "picked up", "built up", "increased
#: from"): it reaches Y. ("speed" is not one: "my speed from 50 mph to 30 mph" says neither.)
_SPEEDING_UP = frozenset(("accelerate", "acceleration", "increase", "climb", "rise", "pick", "build", "gather", "up"))
#: Words that end the clause of a change's verb, going back ("I braked, then accelerated from ...").
_BEFORE_THE_VERB = frozenset((",", ";", ":", ".", "?", "!", "and", "then", "but", "when", "while", "as", "after"))


def _slowing(tokens: list[str], k: int, first: float, second: float) -> bool:
    """Whether the change whose "from" is at ``k``, from ``first`` to ``second`` (one unit), is a slowing:
    by the verb of its clause ("slowed", "braked" / "accelerated", "sped up"), a slowing word first,
    else, where the verb says neither ("went from", "drove from", "changed from"), by the numbers."""
    said: set[str] = set()
    for w in tokens[max(k - 5, 0) : k][::-1]:
        if w in _BEFORE_THE_VERB:
            break
        forms = lemmas(w)
        said |= {w, *forms.get("VERB", ()), *forms.get("NOUN", ())}
    if said & _SLOWING:
        return True
    if said & _SPEEDING_UP:
        return False
    return second < first


def from_one_speed_to_another(tokens: list[str], i: int) -> tuple[float, int, bool] | None:
    """(the speed in m/s it changes to, the words used from ``i``, whether it slows) where the speed at
    ``i``, with its unit, is the one a change of speed starts from and the one it changes to follows with
    its own unit ("slowed from around 55 mph (89 km/h) to about 20 mph (32 km/h)", "accelerated from 20
    mph to 40 mph"). A conversion of either into another unit is read with it. Else None. A slowing
    starts at the first speed (the speed it had, then the one it goes to, as "from 55 to 20 mph" says
    it); a speeding up reaches the second, the speed it has when what follows happens (see
    :func:`_slowing`)."""
    k = i - 1
    while k >= 0 and tokens[k] in _HEDGES:
        k -= 1
    if k < 0 or tokens[k] != "from":
        return None
    j = _past_conversion(tokens, i + 2)
    if tokens[j : j + 1] != ["to"]:
        return None
    j += 1
    while j < len(tokens) and tokens[j] in _HEDGES:
        j += 1
    if j + 1 >= len(tokens) or not is_number(tokens[j]) or tokens[j + 1] not in V.SPEED_UNITS:
        return None
    first = float(tokens[i]) * V.SPEED_UNITS[tokens[i + 1]]
    second = float(tokens[j]) * V.SPEED_UNITS[tokens[j + 1]]
    return second, _past_conversion(tokens, j + 2) - i, _slowing(tokens, k, first, second)


def _skip_back(tokens: list[str], j: int) -> int:
    while j >= 0 and tokens[j] in _LINKS:
        j -= 1
    return j


#: An owner the reader has no word for ("challenger speed 90 km/h"): a road user other than the ego.
UNNAMED = -1


def owners(
    tokens: list[str], i: int, unit: bool, mention_ending_at: Mentions, noun: Callable[[str], bool] = lambda w: False
) -> tuple[int, ...]:
    """The starts of the mentions the number at ``i`` is said of by grammar (empty where the grammar
    names none and the reader's reading of the clause decides). ``unit``: a speed unit follows it;
    ``noun(word)``: whether a word is only a noun (a name of someone, not "top" or "constant")."""
    j = _skip_back(tokens, i - 1)
    if j < 0:
        return ()
    if tokens[j] in SPEED_HEADS:  # "van speed 60 km/h"; "challenger speed 90 km/h": someone not the ego
        owner = mention_ending_at(j - 1)
        if owner is None and j >= 2 and tokens[j - 1] == "'s":  # "the bus's speed is 30 km/h"
            owner = mention_ending_at(j - 2)
        if owner is None and j and noun(tokens[j - 1]) and tokens[j - 2 : j - 1] not in (["the"], ["a"], ["its"]):
            return (UNNAMED,)
        return (owner,) if owner is not None else ()
    be = _be_at(tokens, i)
    if be is not None:  # "we were at maybe 50 km/h", "I was at about 40": the subject of "be"
        owner = mention_ending_at(be)
        return (owner,) if owner is not None else ()
    owner = mention_ending_at(j)
    if owner is not None:
        k = owner - 1
        while k >= 0 and tokens[k] in _DETERMINERS:
            k -= 1
        if k >= 1 and tokens[k] == "of" and tokens[k - 1] in SPEED_HEADS:  # "speed of the bus 15 km/h"
            return (owner,)
        right_after = j == i - 1 or (unit and _only_hedges(tokens[j + 1 : i]))  # ("ego ~50 km/h": "ego 50 km/h")
        if right_after and _in_a_place_phrase(tokens, owner):
            return ()  # "steps out between parked cars 3 m/s": the cars say where; the clause says whose
        if right_after and (unit or after_ego(tokens, i)):  # "cyclist 15 km/h", "ego 50": of the noun before it
            return (owner,)
        if tokens[j + 1] == "at" and (k < 0 or tokens[k] in _CLAUSE_OPENERS) and not compared(tokens, k):
            return (owner,)  # "the van at 60 km/h overtakes ...": said of the subject opening its clause
        if tokens[j + 1] == "at" and unit and k >= 0 and judged_at(tokens, k):
            return (owner,)  # "estimates the scooter at 15 mph", "clocked the van at 50 mph": the object's
    subject = mention_ending_at(j - 1) if unit and j and tokens[j].endswith("ing") else None
    if subject is not None and subject and tokens[subject - 1] == "with":
        return (subject,)  # "with us coming at 80 km/h": the subject of a participle after "with"
    if tokens[j] in _MOTION and j and tokens[j - 1] == "both":  # "... are both doing 50 km/h"
        j -= 1
    elif tokens[j] in _MOTION and tokens[j - 1] in OBJECT_PRONOUNS:  # (with a unit or bare: "doing 70")
        passer = _subject_before(tokens, j - 2, mention_ending_at)  # ("a lorry went past us doing 70 km/h")
        return (passer,) if passer is not None else ()
    elif tokens[j] in _MOTION and unit and tokens[j - 1] not in OBJECT_PRONOUNS:
        # "the ego drives at 40 km/h", "a tractor doing 15 mph": its subject's ("overtakes me doing 18 mph": not mine)
        k = j - 1
        while k > 0 and tokens[k] in _AUXILIARIES:  # ("the van was going 40 mph", "I was doing 50")
            k -= 1
        owner = mention_ending_at(k)
        return (owner,) if owner is not None else ()
    if tokens[j] == "both":  # "the ego and a lead truck both at 70 km/h"
        k = j - 1
        while k >= 0 and (tokens[k] in ("are", "were", "is", "was") or tokens[k] in _MODALS):
            k -= 1
        second = _mention_near(k, mention_ending_at)  # (past a word after it: "the van ahead")
        joint = next((a for a in range(second - 1, second - 4, -1) if a >= 1 and tokens[a] in ("and", "&")), None)
        first = None if joint is None else _mention_near(joint - 1, mention_ending_at)
        if joint is None:  # ("Ego: behind a bus, 20 m back, both at 40 km/h"): the last two its sentence names
            named = _in_sentence(tokens, j, mention_ending_at)
            egos = [s for s in named if _EGO_SUBJECTS & set(tokens[s : s + 2])]  # (the ego, where named, is one)
            others = [s for s in named if s not in egos]
            first, second = (egos[0], others[-1]) if egos and others else (None, -1)
        return (first, second) if first is not None and first >= 0 and first != second else ()
    if unit and tokens[j] == "," and (noted := _noted_after(tokens, j, mention_ending_at)) is not None:
        return (noted,)
    return _key_of_line(tokens, i, mention_ending_at)


def _subject_before(tokens: list[str], k: int, mention_ending_at: Mentions) -> int | None:
    """The start of the nearest mention ending at or before ``k`` within its clause: the subject of a
    verb that has an object pronoun ("a motorbike overtook me going 90": the motorbike; a participle
    after an object says what its clause's subject does, as "while I was doing 50" would say the
    narrator's)."""
    while k >= 0 and tokens[k] not in _CLAUSE_OPENERS:
        start = mention_ending_at(k)
        if start is not None:
            return start
        k -= 1
    return None


#: Words before a road user that introduce it as the subject or the thing that is there ("ahead is a
#: cyclist", "there is a tractor", "; a jogger").
_INTRODUCING = frozenset({"is", "are", "was", "were", ",", ";", ":", ".", "?", "!", "and"})
#: How many words a note may run between the road user it follows and its speed.
_NOTE_REACH = 8


def _noted_after(tokens: list[str], comma: int, mention_ending_at: Mentions) -> int | None:
    """The road user a speed noted after a comma is said of ("Ahead is a cyclist, same direction, 15
    km/h"): the one road user named before it in its sentence, within a few words of notes, when that
    road user is introduced (after "is", "there is", a clause break), not the object of someone's verb
    ("I overtook a cyclist, 60 km/h at the time": the narrator's speed)."""
    k = comma - 1
    while k >= 0 and comma - k <= _NOTE_REACH and tokens[k] not in _STOPS and tokens[k] not in (";", ":"):
        start = mention_ending_at(k)
        if start is not None:
            b = start - 1
            while b >= 0 and (tokens[b] in _DETERMINERS or tokens[b] == "one"):
                b -= 1
            return start if b < 0 or tokens[b] in _INTRODUCING else None
        k -= 1
    return None


#: What only someone at the wheel does: a person said to do one of these ("some lunatic overtook us") is a driver.
_DRIVERS_ACTS = frozenset(
    {"overtake", "cut_in", "run_red_light", "turn_across", "wrong_way", "forced_turn", "follow_vehicle", "change_lane"}
)


def drives(actor) -> bool:
    """Whether ``actor`` (the reader's), named by a person noun (read as a walker), is said to do what
    only a driver does: a speed no walker reaches is then its own ("a maniac overtook me doing 70 mph"),
    not the ego's. (A rider stays a rider: "a cyclist drifts in, with the ego at 60 km/h".)"""
    return actor.kind == "pedestrian" and any(b[0] in _DRIVERS_ACTS for b in actor.behaviours)


def _be_at(tokens: list[str], i: int) -> int | None:
    """The last word of the subject of "<subject> <be> at <number>" for the number at ``i`` (past hedges:
    "we were at maybe 50", "I'm at about 30"), else None. Why: "be at" a speed says whose speed it is as
    plainly as a verb of going does, wherever the clause stands in a run-on sentence."""
    k = i - 1
    while k > 0 and tokens[k] in _LINKS and tokens[k] not in _BE and tokens[k] != "at":
        k -= 1
    if k < 2 or tokens[k] != "at":
        return None
    k -= 1
    while k > 0 and tokens[k] in _AUXILIARIES - _BE:
        k -= 1
    if tokens[k] not in _BE:
        return None
    k -= 1
    while k > 0 and tokens[k] in _AUXILIARIES - _BE:
        k -= 1
    return k


#: Verbs (lemmas) of judging a quantity that take an object and "at" and the value ("estimates the
#: scooter at 15 mph", "clocked the van at 50 mph", "I'd put him at 60 mph"): the value is said of the
#: object, as "the scooter was doing 15 mph" says it; the one who judges (the subject) need not move at all.
JUDGING_VERBS = frozenset({"estimate", "clock", "judge", "gauge", "put", "reckon", "guess", "place"})


#: Of the verbs of judging, those British English also says of noticing ("I only clocked the cyclist
#: at 30 mph": saw him while doing 30 mph): said by the narrator, the speed is the narrator's.
_ALSO_NOTICING = frozenset({"clock"})
#: How many words (adverbs, auxiliaries: "I only clocked", "we didn't clock") may stand between the
#: narrator and a verb of noticing.
_NOTICER_REACH = 3


def judged_at(tokens: list[str], k: int) -> bool:
    """Whether ``tokens[k]`` is a verb of judging a quantity (:data:`JUDGING_VERBS`) in any of its forms;
    "clock" only where the narrator ("I", "we") is not its subject: a camera or an officer that clocks
    a road user measures its speed, a narrator who clocks one notices it."""
    verbs = JUDGING_VERBS & set(lemmas(tokens[k]).get("VERB", ()))
    if verbs and verbs <= _ALSO_NOTICING:
        return not {"i", "we"} & set(tokens[max(k - _NOTICER_REACH, 0) : k])
    return bool(verbs)


def compared(tokens: list[str], k: int) -> bool:
    """Whether ``tokens[k]`` is the "as" of a comparison ("in the same lane as the ego at 18 km/h"): the
    noun after it is what the subject is compared with, not the subject of a clause of its own."""
    return tokens[k] == "as" and "same" in tokens[max(k - 4, 0) : k]


#: Prepositions whose object is scenery a road user comes out of or past, not one that moves itself.
_PLACE_OF_COMING_OUT = frozenset({"between", "among", "amongst", "behind"})
#: Words that may stand in that object's noun phrase before its noun ("between two parked vans").
_IN_THE_PHRASE = frozenset(
    {"parked", "stationary", "stopped", "two", "three", "few", "couple", "some", "several", "of", "the", "a", "an"}
)


def _in_a_place_phrase(tokens: list[str], start: int) -> bool:
    """Whether the road-user noun starting at ``start`` is the object of a place preposition ("between
    parked cars", "from behind two stationary vans"): a number right after it is not said of it (the
    scenery stands), but of the one the clause says comes out from there."""
    k = start - 1
    while k >= 0 and tokens[k] in _IN_THE_PHRASE:
        k -= 1
    return k >= 0 and tokens[k] in _PLACE_OF_COMING_OUT and k + 1 < start


def _in_sentence(tokens: list[str], before: int, mention_ending_at: Mentions) -> list[int]:
    """The starts of the road-user mentions of the sentence that holds token ``before``, before it."""
    start = before
    while start > 0 and tokens[start - 1] not in _STOPS:
        start -= 1
    return [s for k in range(start, before) if (s := mention_ending_at(k)) is not None and s >= start]


def _mention_near(k: int, mention_ending_at: Mentions) -> int:
    """The start of a mention ending at ``k`` or one word before it, else -1."""
    for end in (k, k - 1):
        start = mention_ending_at(end) if end >= 0 else None
        if start is not None:
            return start
    return -1


def _key_of_line(tokens: list[str], i: int, mention_ending_at: Mentions) -> tuple[int, ...]:
    """ "<road user> ...: 6 m ahead, 20 mph": the road user that keys the line the number is on, when
    no other road user is named between the key and the number."""
    start = i
    while start > 0 and tokens[start - 1] not in _STOPS:
        start -= 1
    colon = next((k for k in range(start, i) if tokens[k] == ":"), None)
    if colon is None or colon - start > 4:
        return ()
    key = next((s for k in range(start, colon) if (s := mention_ending_at(k)) is not None and s >= start), None)
    if key is None or any(mention_ending_at(k) is not None for k in range(colon + 1, i)):
        return ()
    return (key,)


#: Words that say a road user stands still ("was stationary", "were waiting", "sat at a red light").
STILL_WORDS = frozenset(
    "stationary stopped parked waiting queuing queueing queued sat sitting idling halted".split() + ["at a standstill"]
)
#: Words before a still word that make it a state the subject is in, not a stop it makes ("was stopped",
#: "had stopped", "were still waiting"); a stop said as an event ("I stopped just short") is a reaction.
_STATE_BEFORE = _AUXILIARIES | {"had", "have", "has", "already", "patiently"}
#: Adverbs of degree between an auxiliary and a still word ("was completely stopped", "had fully stopped").
_DEGREE = frozenset({"completely", "fully", "totally"})
#: Conjunctions that make a clause the background of what happens ("... while I was queuing").
_BACKGROUND = frozenset({"while", "whilst", "as", "when"})


#: Words of standing, as British says them ("we were stood still", "I was standing at the lights").
_STANDING = frozenset({"stood", "standing"})
#: The perfect: a stop it makes before the scene opens is done ("I had pulled up", "we'd come to a stop").
_PERFECT = frozenset({"had", "has", "have"})


#: Verbs of going that, denied, say one stands ("we weren't moving", "I was not driving", "never rolled").
_MOVING = frozenset({"moving", "going", "driving", "rolling", "travelling", "traveling", "moved", "rolled"})


def _motion_denied(m, after) -> bool:
    """Whether the mention ``m`` is a verb of going said with "not" or "never" before it ("we weren't
    moving", "I was not driving"): the subject stands. Not "not going to ...", an intention (``after``:
    the mention after ``m``, which "to" then stands before)."""
    if m.slot not in ("behaviour", "ego_verb", "unknown_verb") or m.prev not in ("not", "never"):
        return False
    if m.words.split()[0] not in _MOVING:
        return False
    return not (after and after[0].prev == "to" and after[0].start == m.end + 1)


def _stop_as_state(m) -> bool:
    """Whether the stop ``m`` says a state the scene opens in, not a stop under way: a still word
    ("stopped at", "halted"), standing ("stood still"), or a stop done before, in the perfect ("had pulled
    up", "had come to a stop")."""
    first = m.words.split()[0]
    return first in STILL_WORDS or first in _STANDING or (m.prev in _PERFECT and not first.endswith("ing"))


def _stopped_fully(m, tokens: list[str]) -> bool:
    """Whether the still word ``m`` follows a degree adverb after an auxiliary ("my car was completely
    stopped", "I had fully stopped"): a state. Not denied ("had not completely stopped": still rolling),
    nor a stop of doing something ("I completely stopped paying attention")."""
    if m.prev not in _DEGREE or m.start < 2:
        return False
    aux = tokens[m.start - 2]
    if aux not in _STATE_BEFORE or (m.start >= 3 and tokens[m.start - 3] in ("not", "never", "n't")):
        return False
    return not (m.end < len(tokens) and tokens[m.end].endswith("ing"))


def ego_at_rest(clauses, tokens: list[str]) -> bool:
    """Whether the ego is said to stand still as the scene opens: the ego, then a state of standing
    ("was stationary", "were waiting at the lights", "had stopped in a queue"), said before anyone does
    anything or as the background of what they do ("... while I was queuing"). Why: the one struck
    while waiting is a common report, and a stop the ego makes in reply ("... and I was stopped just
    in time") is no start at rest. ``clauses``: the reader's (link, mentions); ``tokens``: the words they
    index."""
    acted = other = False
    subject = None  # (the road user named last as a subject: whom "it" says again)
    for _, mentions in clauses:
        said = [
            m
            for m in mentions
            if m.slot not in ("punct", "conj")
            and not (m.slot == "ego_verb" and m.value is None)
            and not (m.slot == "unknown_verb" and m.words in _BE)  # ("I am stopped at ...")
        ]
        for k, m in enumerate(said):
            if not k and not other and _subjectless_state(m, said[1:]):
                return True  # ("Stationary at the lights when ...", "Waiting at the junction to turn right, ...")
            other = other or (m.slot == "actor" and m.value != "ego")
            if m.slot == "actor" and m.prev in _SUBJECT_BEFORE:
                subject = m
            if m.slot == "behaviour" and other:  # (what the ego did before it stood is no one acting on it)
                acted = True
            stop = m.slot == "behaviour" and m.value[0] == "stop" and _stop_as_state(m)
            still = m.words in STILL_WORDS or m.words in _STANDING  # ("was stationary", "we were stood at the lights")
            stative = k > 0 and _stative_past(said[k - 1], m, tokens)  # ("I waited at the lights", "we sat in traffic")
            denied = _motion_denied(m, said[k + 1 : k + 2])  # ("we weren't moving", "I was not driving")
            if not k or not (stop or denied or stative or (still and m.slot in ("stationary", "unknown_verb"))):
                continue  # ("was stationary", "were stopped at the junction": a state)
            ego = said[k - 1]
            if _it_the_egos_vehicle(ego, subject):
                ego = subject  # ("My car got hit while it was parked": the car, said again)
            if not other and _protagonist(ego, clauses):
                ego = replace(ego, slot="actor", value="ego")  # ("She had stopped for the zebra when ...")
            if (
                ego.slot == "actor"
                and ego.value == "ego"
                and (
                    m.prev in _STATE_BEFORE
                    or denied
                    or _verbless_state(ego, m)
                    or _stopped_fully(m, tokens)
                    or _stative_past(ego, m, tokens)
                )
            ):
                if (not acted or ego.prev in _BACKGROUND or held_throughout(tokens, m.end)) and not _sets_off_after(
                    tokens, m.end, _others_at(clauses)
                ):
                    return True
    return False


#: Words before a road user named as the subject of its clause ("My car ...", "..., while the van ...");
#: after a preposition it is an object ("hit by a cyclist", "behind the bus").
_SUBJECT_BEFORE = frozenset({"", ".", ";", ":", ",", "!", "?", "and", "but", "then", "while", "whilst", "when", "as"})
#: The ego said as the person who tells the story: "it" never says them again.
_EGO_AS_PERSON = frozenset({"i", "we", "me", "us"})


#: Pronouns of one person: "he" or "she" said before any road user is the one a story is about.
_PERSON = frozenset({"he", "she"})


def _protagonist(pronoun, clauses) -> bool:
    """Whether the mention ``pronoun`` is "he" or "she" said of the one a story told in the third person is
    about ("She had stopped for the zebra when a scooter ...", "He was stood at the lights and ..."): the
    caller asks only before any road user is named, and the text names no ego (no "I", "we", "you", no
    ego phrase), so the person is the one driving, the ego."""
    if pronoun.slot != "pronoun" or pronoun.words not in _PERSON:
        return False
    return not any(m.slot == "actor" and m.value == "ego" for _, mentions in clauses for m in mentions)


def _it_the_egos_vehicle(pronoun, subject) -> bool:
    """Whether the mention ``pronoun`` is "it" said of the ego's vehicle: the subject named last is the
    ego, named as a vehicle ("My car got damaged while it was stopped", "Our van was hit while it was
    parked"), not as a person ("I ..."), and no road user was a subject since."""
    return (
        pronoun.slot == "pronoun"
        and pronoun.words == "it"
        and subject is not None
        and subject.value == "ego"
        and subject.words not in _EGO_AS_PERSON
    )


#: What may stand before the ego in a note that opens with it ("Ego stationary at the lights.", "With
#: my car parked at the kerb, ..."): the start of a sentence or clause, its article, or "with".
_NOTE_OPENERS = frozenset({"", ".", ";", ":", ",", "!", "?", "-", "(", "the", "with"})


#: Words a note's first sentence opens after: nothing, or the end of a heading.
_TEXT_OPENERS = frozenset({"", ":"})


def _subjectless_state(m, after) -> bool:
    """Whether ``m`` opens the text, before anyone is named, with a state of standing and no subject
    ("Stationary at the lights when a scooter hit my door", "Waiting at the junction to turn right when
    ...", "Sat in the queue, a van ..."): the one left out is who tells it, the ego, as a participle
    that opens a sentence is. Not a still word right before a word it modifies ("Parked car on the
    left", "Stationary traffic ahead": said of that), nor one that is also a stop made ("Stopped just
    short": an act), nor where the narrator is named next, going on from it ("Sat at the lights, green goes,
    I pull off, and ..."). ``after``: the mentions after it in its clause."""
    still = m.slot == "stationary" or (m.slot == "unknown_verb" and m.words in STILL_WORDS)  # ("Sat at ...")
    if m.prev not in _TEXT_OPENERS or not still or m.words in _STOPS_MADE:
        return False
    if after and after[0].start == m.end:  # ("Stationary traffic ahead": said of what it names)
        return False
    named = next((x for x in after if x.slot in ("actor", "pronoun")), None)
    return not (named is not None and named.value == "ego")


#: What the ego says to set off from where it stood ("... then I pulled away", "we moved off and ...").
_SETTING_OFF = (
    ("pulled", "away"), ("pulled", "off"), ("pulled", "out"), ("drove", "off"), ("drove", "on"), ("moved", "off"),
    ("moved", "away"), ("moved", "forward"), ("set", "off"), ("went", "through"), ("crept", "forward"),
    ("started", "moving"), ("started", "off"), ("overtook",), ("filtered",), ("proceeded",),
)  # fmt: skip


def _others_at(clauses) -> frozenset[int]:
    """The positions of the words that name a road user other than the ego, as the reader found them."""
    return frozenset(
        i
        for _, mentions in clauses
        for m in mentions
        if m.slot == "actor" and m.value != "ego"
        for i in range(m.start, m.end)
    )


#: Phrases that hold a state through the whole event ("I was stationary the whole time", "we were parked
#: at the time", "I was stopped throughout").
_THROUGHOUT = (
    ("the", "whole", "time"), ("the", "entire", "time"), ("all", "the", "time"), ("at", "the", "time"),
    ("throughout",), ("all", "along"), ("the", "whole", "while"), ("at", "that", "point"), ("at", "the", "moment"),
)  # fmt: skip


def held_throughout(tokens: list[str], end: int) -> bool:
    """Whether the state that ends at ``end`` is said to hold through the event ("A van came past me. I was
    stationary the whole time."): told after what others did, it is still how the ego stood while they did
    it, not a stop it made in reply. One word of place may come between ("stopped there the whole time"),
    and the state's own "at" may begin the phrase ("stopped at the time")."""
    if end and tokens[end - 1] == "at":
        end -= 1
    for skip in (0, 1):
        at = tokens[end + skip :]
        if skip and (not at or at[0] not in ("there", "still", "then")):
            break
        if any(tuple(at[: len(p)]) == p for p in _THROUGHOUT):
            return True
    return False


def _sets_off_after(tokens: list[str], start: int, others: frozenset[int]) -> bool:
    """Whether the ego is said to set off after the state that ends at ``start`` and before any contact
    ("I waited at the red light. When it turned green I pulled away and a car ran the red", "I waited at
    the stop line, then moved off and a walker stepped out", "I waited behind a bus; when the lights
    changed I moved off and ..."): then it moves when the scene happens, and did not stand through it.
    A setting off told after the contact ("... when a car hit me from behind. Afterwards I drove off")
    is after the event, and one said of a road user ("the cyclist ahead moved off": ``others``, the
    positions of the words that name one) is not the ego's."""
    for i in range(start, len(tokens)):
        if tokens[i] in _CONTACT_WORDS:
            return False  # (what comes after the contact is after the event)
        for phrase in _SETTING_OFF:
            if tuple(tokens[i : i + len(phrase)]) != phrase:
                continue
            if others & set(range(max(start, i - 3), i)):
                continue  # ("the cyclist ahead drove off": another's)
            if set(tokens[max(start, i - 3) : i]) & {"i", "we"} or tokens[i - 1] in (
                "then",
                "and",
                "eventually",
                "finally",
            ):
                return True
    return False


#: Words of contact: a setting off said after them is after the event ("... hit me from behind.
#: Afterwards I drove off").
_CONTACT_WORDS = frozenset(
    ("hit", "hits", "struck", "crashed", "collided", "bumped", "scraped", "clipped", "rammed", "shunted", "smashed",
     "rear-ended", "pushed", "into")
)  # fmt: skip


#: Verbs of standing whose simple past is a state the subject was in, not a stop it made ("I waited at
#: the lights", "we sat in the queue", "I queued at the roundabout"); "I stopped" and "I pulled up" are acts.
_STATIVE_PAST = frozenset({"waited", "sat", "stood", "queued", "idled"})


def _stative_past(ego, state, tokens: list[str]) -> bool:
    """Whether a verb of standing in the simple past follows the ego's name right after it, and then
    where it stood ("While I waited at the lights, a cyclist ...", "I sat at the lights when a van hit
    me", "we queued in the traffic"): the past of waiting, sitting or queuing at a place is a state, as
    "was waiting" is. Not a wait for something to be done ("I waited too long to brake", "I waited for
    a gap and pulled out"), nor a going ("we idled through the car park", "I stood up on the pedals"), nor
    a place behind someone ("I sat behind the bus for ages, then overtook it": following)."""
    verb, *rest = state.words.split()  # ("sat in", read as one phrase, says its place word too)
    after = rest[0] if rest else (tokens[state.end] if state.end < len(tokens) else "")
    return verb in _STATIVE_PAST and ego.end == state.start and after in _WHERE_IT_STOOD


#: Words after a verb of standing that say where the one stood ("waited at", "sat in the queue",
#: "stood still").
_WHERE_IT_STOOD = frozenset({"at", "in", "still", "stationary"})


def _verbless_state(ego, state) -> bool:
    """Whether a state of standing follows the ego right after its name with no verb, in a note that
    opens with the ego ("Ego stationary at the red light.", "Us parked up at the kerb, ..."): a note
    drops "is", and says the state all the same. (A stop, a verb, is not read so: "I stopped" is an act.)"""
    return (
        state.slot == "stationary"
        and state.words not in _STOPS_MADE
        and ego.end == state.start
        and ego.prev in _NOTE_OPENERS
    )


#: Still words that are also the simple past of a stop someone makes: right after the subject they are
#: that act ("A bus driver stopped in time"), so they do not say a verbless note's state.
_STOPS_MADE = frozenset({"stopped", "halted"})


def struck_at_rest(actors, ego_speed_mps: float | None, intent: str | None) -> None:
    """Each road user read as going along the ego's lane (ahead, or nowhere said) that meets the ego at
    rest comes from behind it: one ahead going the same way never reaches a standing ego. ``actors``:
    the reading's specs; ``intent``: the outcome read (a collision or a near miss is a meeting)."""
    if ego_speed_mps != 0.0 or intent not in ("collision", "near_miss"):
        return
    for a in actors:
        going = [b[0] for b in a.behaviours] in ([], ["keep_going"]) and a.speed_mps != 0.0
        if going and a.relation in (None, "ahead"):
            a.relation = "behind"
