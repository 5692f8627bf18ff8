"""What a noun phrase names, by its structure: whose it is (the writer's own vehicle or driver, "my
van", "our driver", "our old lorry", is the ego, whatever its type, as "my car" is; a person after
"my" or "our", "my kid", is someone in the ego and left as it is), its head (a closed compound,
"firetruck", names what its head names) and its modifier ("flashing lights" are a vehicle's lamps,
not a junction's signals, which "lights" alone are)."""

from __future__ import annotations

import re
from collections.abc import Callable

from vei_scenario.language.lemmas import english, lemmas
from vei_scenario.language.lexicon import (
    ANIMALS,
    CAR_MAKES,
    FORGONE,
    SCOOTER_OPERATORS,
    THINGS_FOR_ANIMALS,
    TRUCK_MAKES,
)

#: First-person possessives, a closed class: what they own is the writer's, hence the ego.
FIRST_PERSON_POSSESSIVES = frozenset({"my", "our"})
#: Words that pick some out of many ("one of our bikes", "two of our vans").
_PICKED = frozenset("one two three four several some each any none all many most".split())
#: At most this many modifiers between the possessive and its head noun ("our white transit van").
_MODIFIERS = 2

KindAt = Callable[[list[str], int], "tuple[str, int] | None"]


def _fleet(tokens: list[str], i: int, end: int) -> bool:
    """Whether "our <vehicles>" at ``i`` (ending at ``end``) is a fleet: its head a plural ("our
    scooters") or one picked out of many ("one of our bikes"). The writer is in one vehicle, so a
    fleet's members are other road users, as an operator's report names them."""
    head = tokens[end - 1]
    nouns = lemmas(head).get("NOUN")
    picked = i > 1 and tokens[i - 1] == "of" and (tokens[i - 2] in _PICKED or tokens[i - 2].isdigit())
    return bool(nouns and head not in nouns) or picked


def _own_vehicle_end(tokens: list[str], i: int, kind_at: KindAt, modifier: Callable[[str], bool]) -> int | None:
    """Where the phrase "my/our [modifiers] <vehicle noun>" starting at ``i`` ends, or None (also for a
    fleet: see :func:`_fleet`)."""
    for j in range(i + 1, min(i + 2 + _MODIFIERS, len(tokens))):
        found = kind_at(tokens, j)
        if found is not None:
            kind, length = found
            if kind in ("pedestrian", "ego") or _fleet(tokens, i, j + length):
                return None
            return j + length
        if not modifier(tokens[j]):
            return None
    return None


#: Words that count what "of" takes a part of ("two of our scooters", "one of our vans"): a fleet's or a
#: group's vehicles, of which the writer's is at most one.
_COUNTS = frozenset("one two three four five six seven eight nine ten both several some none".split())


def _counted_of(before: list[str]) -> bool:
    """Whether the words ``before`` a possessive end in a count and "of" ("two of", "one of")."""
    return len(before) >= 2 and before[-1] == "of" and (before[-2] in _COUNTS or before[-2].isdigit())


def own_vehicles(tokens: list[str], kind_at: KindAt, modifier: Callable[[str], bool]) -> list[str]:
    """``tokens`` with each "my/our [modifiers] <vehicle noun>" as the one token "ego", but for a part
    of a fleet or group ("two of our scooters", "one of our vans": road users of their own).
    ``kind_at(tokens, i)`` gives the road-user type a phrase at ``i`` names and its length;
    ``modifier(word)`` whether a word may stand before a head noun (a content word the reader has no
    phrase for)."""
    out: list[str] = []
    i = 0
    while i < len(tokens):
        own = tokens[i] in FIRST_PERSON_POSSESSIVES and not _counted_of(out)
        end = _own_vehicle_end(tokens, i, kind_at, modifier) if own else None
        if end is None:
            out.append(tokens[i])
            i += 1
        else:
            out.append("ego")
            i = end
    return out


#: The shortest head and modifier a closed compound is split into ("minibus": "mini" + "bus").
_SHORTEST_PART = 3


def closed_compound(token: str, kind_of: Callable[[str], str | None]) -> list[str]:
    """A word written as one that is a modifier and a vehicle noun ("firetruck", "schoolbus",
    "minicab"), as those two words, so that it names what its head names; a word whose beginning is
    no English word of its own ("syllabus", "caravan", "vicar") is left whole. ``kind_of(word)`` is
    the road-user type a single word names, or None."""
    if kind_of(token) is not None:
        return [token]
    for cut in range(_SHORTEST_PART, len(token) - _SHORTEST_PART + 1):
        head, modifier = token[cut:], token[:cut]
        if kind_of(head) not in (None, "pedestrian", "ego") and english(modifier):
            return [modifier, head]
    return [token]


def _singular_noun(word: str) -> bool:
    return word.isalpha() and word in lemmas(word).get("NOUN", ()) and word not in ("people", "folk", "folks")


def _person_at(tokens: list[str], i: int, kind_at: KindAt) -> int | None:
    """The length of a singular person's noun at ``i`` ("man", "courier", "kid"; no animal), or None."""
    found = kind_at(tokens, i) if i < len(tokens) else None
    if found is None or found[0] != "pedestrian" or tokens[i] in ANIMALS:
        return None
    return found[1] if _singular_noun(tokens[i + found[1] - 1]) else None


#: Nouns that name a road user of any kind a test places, not a vehicle ("a child pedestrian target").
_ANY_KIND = frozenset({"target", "vehicle", "obstacle", "adversary", "dummy", "participant"})


def _vehicle_at(tokens: list[str], i: int, kind_at: KindAt) -> int | None:
    """The length of a singular vehicle's noun at ``i`` (a car, van, truck, bicycle or e-scooter), or None."""
    found = kind_at(tokens, i) if i < len(tokens) else None
    if found is None or found[0] in ("pedestrian", "ego") or _ANY_KIND & set(tokens[i : i + found[1]]):
        return None
    last = tokens[i + found[1] - 1]
    return found[1] if _singular_noun(last) or not english(last) else None


def person_with_vehicle(tokens: list[str], kind_at: KindAt) -> list[str]:
    """``tokens`` with a person's noun and a vehicle's noun said together as one noun ("a courier van",
    "a pizza courier bike", "a scooter kid", "boda-boda man", "the bike messenger") as the vehicle alone:
    a compound of the two names one road user, the person on or in that vehicle, whichever of them is
    the head. Both nouns singular and side by side; a person and a vehicle with an article each ("a
    jogger and a van") or split by a mark are two road users."""
    out: list[str] = []
    i = 0
    while i < len(tokens):
        person = _person_at(tokens, i, kind_at)
        if person is not None and _vehicle_at(tokens, i + person, kind_at) is not None:
            i += person  # ("a courier van": the van)
            continue
        vehicle = _vehicle_at(tokens, i, kind_at)
        if vehicle is not None and (after := _person_at(tokens, i + vehicle, kind_at)) is not None:
            out.extend(tokens[i : i + vehicle])  # ("a scooter kid": the scooter)
            i += vehicle + after
            continue
        out.append(tokens[i])
        i += 1
    return out


#: Places and things named after the vehicles they are for ("the scooter lane", "a bike rack", "the taxi
#: rank", "a bus shelter", "bike gear", "a bicycle helmet"), or after a place that shares a vehicle's noun
#: ("the estate entrance"): a closed class of nouns that are never a verb, after which the vehicle's
#: noun is a modifier, no road user ("stop" and "park", verbs too, are left to the phrases that have
#: them).
THINGS_FOR_VEHICLES = frozenset({"lane", "rank", "rack", "bay", "shelter", "depot", "station", "garage", "route",
                                 "lot", "showroom", "wash", "yard", "dealership", "helmet", "helmets", "gear",
                                 "shop", "lock", "seat", "clothing", "shorts", "jersey", "entrance", "forecourt",
                                 "entrances"})  # fmt: skip


def vehicle_places(tokens: list[str], kind_at: KindAt) -> list[str]:
    """``tokens`` without a vehicle's noun that names the place or thing after it ("out of the scooter
    lane", "past the taxi rank", "a man in bike gear"): the place or thing stays, the vehicle goes."""
    out: list[str] = []
    i = 0
    while i < len(tokens):
        found = kind_at(tokens, i)
        if found is not None and found[0] not in ("pedestrian", "ego"):
            end = i + found[1]
            if end < len(tokens) and tokens[end] in THINGS_FOR_VEHICLES:
                i = end
                continue
        out.append(tokens[i])
        i += 1
    return out


#: Places and things named after the people on foot they are for ("the pedestrian signal", "a pedestrian
#: island", "the pedestrian phase"): after "pedestrian" one of these closed-class nouns makes it a modifier.
THINGS_FOR_WALKERS = frozenset({"signal", "light", "lights", "phase", "island", "refuge", "barrier", "barriers",
                                "railing", "railings", "guardrail", "bridge", "footbridge", "subway", "underpass",
                                "overpass", "zone", "area", "precinct", "button", "walkway", "path", "street",
                                "mall", "plaza", "gate", "countdown", "access", "entrance", "route", "tunnel",
                                "detection", "sign", "signs", "green", "cycle", "flow", "traffic", "volume",
                                "volumes", "count", "counts"})  # fmt: skip


def walker_places(tokens: list[str], kind_at: KindAt) -> list[str]:
    """``tokens`` without a walker's noun that names the place or thing after it: an animal's before a
    thing for or against animals ("fitted with a roo bar", "over the cattle grid", "past a dog park"), and
    "pedestrian" before one for people on foot ("against the pedestrian signal", "on the pedestrian
    island"). The place or thing stays; nobody on foot is named. Other people's nouns keep their reading
    ("a man park his car" is a man, in English written as a second language)."""
    out: list[str] = []
    i = 0
    while i < len(tokens):
        found = kind_at(tokens, i)
        if found is not None and found[0] == "pedestrian":
            end = i + found[1]
            noun = " ".join(tokens[i:end])
            things = THINGS_FOR_ANIMALS if noun in ANIMALS else THINGS_FOR_WALKERS if noun == "pedestrian" else ()
            if end < len(tokens) and tokens[end] in things:
                i = end
                continue
        out.append(tokens[i])
        i += 1
    return out


#: What a vehicle tows, which goes where it goes: one road user with it ("a 4x4 towing a horsebox").
TOWED = frozenset({"trailer", "trailers", "semi-trailer", "semitrailer", "horsebox", "caravan", "boat"})
#: Words by which a vehicle has something in tow ("towing", "pulling", "with" or "and" right after its noun:
#: "a prime mover and trailer").
_TOWING = frozenset({"towing", "tows", "towed", "pulling", "hauling", "dragging", "with", "and"})
#: Parts of a trailer, after which "trailer" says whose part it is ("past the trailer wheels"): the part of
#: a vehicle named already, no new road user.
_TRAILER_PARTS = frozenset({"wheel", "wheels", "tyre", "tyres", "tire", "tires", "axle", "axles", "door", "doors",
                            "end", "side", "corner", "hitch", "coupling", "lights", "brakes"})  # fmt: skip
#: Marks that end the phrase of what is towed before its noun ("towing a 53' trailer" goes on past "'").
_TOWED_STOPS = frozenset({".", ",", ";", ":", "!", "?", "and", "or", "but", "then"})


#: Determiners of a trailer someone already has ("with the fridge trailer", "with his trailer").
_TOWED_DEFINITE = (["the"], ["my"], ["our"], ["his"], ["her"], ["its"], ["their"])
#: Verbs (lemmas) by which one meets what comes after "with" ("collided with the trailer").
_MEETING = frozenset({"collide", "crash", "clash", "tangle", "connect", "clip", "meet", "side-swipe"})


def _meets(before: list[str]) -> bool:
    """Whether the word before "with" is a verb of meeting what follows ("collided with", "tangled with")."""
    return bool(before) and bool(set(lemmas(before[-1]).get("VERB", ())) & _MEETING)


def towed(tokens: list[str], kind_at: KindAt) -> list[str]:
    """``tokens`` without the trailer a vehicle tows ("a car towing a trailer", "a ute with a horse
    trailer", "a prime mover and trailer", "pulling a 53' trailer"): it is part of that road user, no
    second one; nor is a trailer that only says whose part it is ("the trailer wheels"). "With" and "and"
    count only right after a vehicle's noun ("collided with a trailer", "a van and a trailer" name a
    trailer that is one)."""
    out: list[str] = []
    i = 0
    while i < len(tokens):
        if tokens[i] in TOWED and tokens[i + 1 : i + 2] and tokens[i + 1] in _TRAILER_PARTS:
            i += 1  # ("squeezed past the trailer wheels": the wheels of the trailer named before)
            continue
        if tokens[i] in _TOWING:
            after_vehicle = any(
                (k := kind_at(out, j)) is not None and k[0] not in ("pedestrian", "ego") and j + k[1] == len(out)
                for j in range(max(len(out) - 3, 0), len(out))
            )
            j = i + 1
            while j < len(tokens) and j < i + 5 and tokens[j] not in TOWED and tokens[j] not in _TOWED_STOPS:
                if (named := kind_at(tokens, j)) is not None:
                    j += named[1] - 1 if tokens[j + named[1] - 1] in TOWED else 0  # ("a horse trailer")
                    break
                j += 1
            # (a definite or possessive trailer one is "with" is in tow, "in lane 1 with the fridge trailer",
            # unless one meets it: "collided with the trailer")
            in_tow = tokens[i] == "with" and tokens[i + 1 : i + 2] in _TOWED_DEFINITE and not _meets(out)
            by_its_noun = tokens[i] in ("with", "and") and not in_tow
            bare = tokens[i] != "and" or j == i + 1 or tokens[i + 1] in ("its", "his", "her", "their")
            if j < len(tokens) and tokens[j] in TOWED and bare and (not by_its_noun or after_vehicle):
                i = j + 1
                continue
        out.append(tokens[i])
        i += 1
    return out


#: Verbs of going somewhere: "by" after one of them says how, not who ("I travelled by car", "we came
#: by van"); after any other participle it names the doer ("hit by car", "overtaken by van").
TRAVEL_VERBS = frozenset({"go", "come", "travel", "commute", "arrive", "return", "head", "get", "journey", "leave"})
#: Words that open a noun phrase, after which a vehicle's noun is no modifier of a compound.
_PHRASE_OPENERS = frozenset({"this", "that", "these", "those", "the", "a", "an", "every", "each", "some", "my", "our"})


def _doer_follows(word: str) -> bool:
    """Whether "by" after ``word`` names who did it: ``word`` is a participle of a verb other than one
    of going somewhere ("hit", "overtaken", "struck")."""
    from lemminflect import getAllInflections

    for lemma in lemmas(word).get("VERB", ()):
        if word in getAllInflections(lemma).get("VBN", ()) and lemma not in TRAVEL_VERBS:
            return True
    return False


def travel_modes(tokens: list[str], kind_at: KindAt) -> list[str]:
    """``tokens`` without "by" and a bare vehicle's noun that say how someone travels ("going to work
    by car", "we came into town by van", "travelling home by bus"): a means of travel, no road user.
    Kept: a vehicle with an article ("by a car"), the doer of a participle ("hit by car", "overtaken by
    van"), and a compound's modifier ("by bus stop 4", "by car park C": a place)."""
    out: list[str] = []
    i = 0
    while i < len(tokens):
        found = kind_at(tokens, i + 1) if tokens[i] == "by" and i + 1 < len(tokens) else None
        if found is not None and found[0] not in ("pedestrian", "ego"):
            end = i + 1 + found[1]
            nxt = tokens[end] if end < len(tokens) else ""
            pos = lemmas(nxt) if nxt.isalpha() else {}
            compound = "NOUN" in pos and "ADV" not in pos and nxt not in _PHRASE_OPENERS
            if not compound and not (out and _doer_follows(out[-1])):
                i = end
                continue
        out.append(tokens[i])
        i += 1
    return out


#: Modifiers of "lights" that still name a junction's signals ("traffic lights", "temporary lights");
#: any other content word before it names another kind of lamp ("flashing", "blue", "tail", "fog").
SIGNAL_MODIFIERS = frozenset(
    {"traffic", "signal", "red", "green", "amber", "yellow", "temporary", "pedestrian", "crossing", "junction"}
)


#: Determiners that make "lights" a road user's lamps, which one has or lacks ("a cyclist with no
#: lights", "get some lights", "his lights were off"); a junction's are "the lights", "at lights".
LAMP_DETERMINERS = frozenset({"no", "without", "some", "any", "his", "her", "its", "their", "your"})


def lamps_not_signals(tokens: list[str], content_word: Callable[[str], bool]) -> list[str]:
    """``tokens`` with "lights" after a content word other than a signal's modifier, or after a
    determiner of a road user's lamps, as "lamps" (a word that names no junction). ``content_word(word)``
    whether a word is no function word."""
    return ["lamps" if tok == "lights" and i > 0 and _lamps_after(tokens[i - 1], content_word) else tok
            for i, tok in enumerate(tokens)]  # fmt: skip


def _lamps_after(prev: str, content_word: Callable[[str], bool]) -> bool:
    """Whether "lights" after ``prev`` are lamps: after a determiner of a road user's lamps, or a
    content word that is not a signal's modifier ("flashing lights", "tail lights")."""
    return prev in LAMP_DETERMINERS or (prev not in SIGNAL_MODIFIERS and content_word(prev))


#: Makes: a word after one of them is its model or the vehicle's noun ("Ford Transit", "Vauxhall Astra").
MAKES = frozenset(m for m in CAR_MAKES + TRUCK_MAKES if " " not in m)


#: Words after a number that make it a quantity (a distance, a speed, a time), not a model's number.
_UNITS_AFTER = frozenset(
    "m km km/h kph mph m/s s sec secs second seconds min mins minute minutes h hr hrs hour hours ft feet foot "
    "yard yards yd mile miles metre metres meter meters % pm am o'clock lane lanes".split()
)  # fmt: skip


def _model_code_end(tokens: list[str], i: int, kind_at: KindAt) -> int | None:
    """Where a model code starting at ``i`` ends ("X3", "C220", "A4", "308" are read as "x 3", "c 220",
    "a 4", "308"), or None: up to three letters that are no English word (or one letter) then a whole
    number, or a whole number alone; a number that a unit or a road user follows is a quantity
    ("a Toyota 25 m ahead", "a BMW 2 cars ahead")."""
    j = i
    w = tokens[i] if i < len(tokens) else ""
    if w.isalpha() and (len(w) == 1 or (len(w) <= 3 and not english(w))):
        j += 1
    if j >= len(tokens) or not tokens[j].isdigit():
        return None
    after = tokens[j + 1] if j + 1 < len(tokens) else ""
    if after in _UNITS_AFTER or after.isdigit() or (after and kind_at(tokens, j + 1) is not None):
        return None
    return j + 1


def model_codes(tokens: list[str], kind_at: KindAt) -> list[str]:
    """``tokens`` without the model code after a make ("a BMW X3", "a Peugeot 308", "a Scania R500
    truck"): the make says the vehicle (or the noun after the code does), the code says nothing more."""
    out: list[str] = []
    i = 0
    while i < len(tokens):
        out.append(tokens[i])
        end = _model_code_end(tokens, i + 1, kind_at) if tokens[i] in MAKES else None
        i = end if end is not None else i + 1
    return out


def make_and_model(tokens: list[str], kind_at: KindAt, known: Callable[[list[str], int], bool]) -> list[str]:
    """A make and what follows it as one vehicle: before a vehicle noun or a model the lexicon has ("a
    Ford Transit", "a Mercedes van", "a Vauxhall Astra") the make goes and the noun says the type; before
    a model it lacks (a word no dictionary knows, "a Toyota Prius", or a noun the reader has no phrase for,
    "a Ford Focus") the model goes and the make says it is a car. A verb after a make stays ("a BMW came
    past"). A model code after the make goes first (:func:`model_codes`)."""
    tokens = model_codes(tokens, kind_at)
    out: list[str] = []
    i = 0
    while i < len(tokens):
        w = tokens[i]
        nxt = tokens[i + 1] if i + 1 < len(tokens) else ""
        if w in MAKES and nxt.isalpha():
            after = kind_at(tokens, i + 1)
            if after is not None and after[0] not in ("pedestrian", "ego"):
                i += 1  # (the make goes; its noun or model stays)
                continue
            unknown_model = not known(tokens, i + 1) and (not english(nxt) or nxt in lemmas(nxt).get("NOUN", ()))
            if unknown_model:
                out.append(w)
                i += 2
                continue
        out.append(w)
        i += 1
    return out


def model_said_again(tokens: list[str], kind_at: KindAt, known: Callable[[list[str], int], bool]) -> list[str]:
    """A model the lexicon lacks, said after its make ("a grey Honda Civic") and then again on its own
    after "the" ("the Civic's right", "struck the Civic"), is that make's vehicle: the later mention
    says the make ("the Honda"), which the reader reads as the same vehicle. A model word said without
    "the" ("the focus of ...", "a Civic") and one said before its make stay."""
    models: dict[str, str] = {}
    out = list(tokens)
    for i, w in enumerate(out):
        nxt = out[i + 1] if i + 1 < len(out) else ""
        if w in MAKES and nxt.isalpha() and nxt not in MAKES and kind_at(out, i + 1) is None:
            if not english(nxt) or not {"VERB", "ADV"} & set(lemmas(nxt)):  # ("Civic", "Focus"; not "came")
                models.setdefault(nxt, w)
        elif w in models and i and out[i - 1] in ("the", "that", "this") and models[w] != w:
            out[i] = models[w]
    return out


_WORD = re.compile(r"[A-Za-z][A-Za-z-]*")
#: Marks that open a sentence, a line or a field, after which any word is capitalised.
_OPENERS = frozenset(".!?:;\n|-(\"'\u2014\u2013*#>")


def proper_names(text: str) -> frozenset[str]:
    """The words ``text`` writes only with a capital, at least once where a sentence does not open (so
    the capital is the word's own: "a silver Mokka", "this guy in a Charger"), lower-cased as the
    reader's words are. All-capital words (abbreviations, shouting) are left out."""
    capital: set[str] = set()
    lower: set[str] = set()
    for m in _WORD.finditer(text):
        w = m.group(0)
        if w[0].islower():
            lower.add(w.lower())
        elif not w.isupper():
            j = m.start() - 1
            while j >= 0 and text[j] in " \t":
                j -= 1
            if j >= 0 and text[j] not in _OPENERS:
                capital.add(w.lower())
    return frozenset(capital - lower)


#: What opens a noun phrase that names someone: an article, a quantifier or a count.
_OPENING = frozenset("a an the some another one two three four five six seven eight nine ten several".split())
#: Words that may stand between someone's noun and what they do, telling who they are ("a figure in
#: black", "a man with a dog", "someone on wheels").
DESCRIBING = frozenset(("in", "on", "with", "wearing", "carrying", "dressed"))
#: Verbs of riding: who does one is a rider ("rider", "scooterer").
_RIDING = frozenset(("ride", "scoot"))
#: Words that end one clause, after which the next may open with its subject.
_CLAUSE_MARKS = frozenset(".;:,!?\n|*•-\u2014\u2013")


def _verb_word(word: str) -> bool:
    """Whether ``word`` can be a finite verb or a participle ("came", "rolled", "swings", "darting")."""
    return "VERB" in lemmas(word)


def agent_noun(noun: str) -> bool:
    """Whether ``noun`` (singular) names who does a verb ("punter": punt, "skater": skate), a person,
    not a thing or a place ("corner", "border")."""
    stems = (noun[:-1], noun[:-2], noun[:-2] + "e", noun[:-3] if noun[-3:-2] == noun[-4:-3] else "")
    return noun.endswith(("er", "or")) and any(len(s) > 2 and s in lemmas(s).get("VERB", ()) for s in stems)


def rider_noun(noun: str) -> bool:
    """Whether ``noun`` (singular) names who does a verb of riding ("rider")."""
    return noun.endswith("er") and any(s in _RIDING for s in (noun[:-1], noun[:-2], noun[:-2] + "e"))


#: Words that put a person on what they ride ("on", "riding", "astride", "aboard").
_ON_IT = frozenset({"on", "riding", "astride", "aboard", "atop"})
#: Words of a hedge or of a part that may stand between riding and the vehicle's phrase: "one of those
#: (hire bikes)", "what looked like (a rented e-scooter)", "what appeared to be", "some sort of", "one of
#: them", with the determiners and possessives they take. A closed class of function words.
_HEDGE_OR_PART = frozenset({"one", "of", "them", "those", "these", "the", "a", "an", "what", "looked", "looks",
                            "look", "like", "seemed", "seems", "appeared", "appears", "to", "be", "sort", "kind",
                            "type", "some", "his", "her", "their", "your", "its"})  # fmt: skip
#: How far back from the vehicle's noun the word that puts the person on it may stand.
_HEDGE_SPAN = 8
#: At most this many words of the vehicle's own phrase before its noun ("a bright pink kick scooter").
_HEDGE_MODIFIERS = 3


def ridden_past_a_hedge(tokens: list[str], i: int, describes: Callable[[str], bool]) -> bool:
    """Whether the vehicle's noun at ``i`` is said as what someone rides, past its phrase's own words and
    a hedge or a part ("on what looked like a rented e-scooter", "on one of those hire bikes", "riding
    some sort of electric scooter", "on a bright pink kick scooter"): past at most
    :data:`_HEDGE_MODIFIERS` words right before the noun for which ``describes`` holds (the phrase's
    own modifiers), only hedge words and determiners lead back to the word that puts the person on it.
    Nothing else may stand in the hedge ("a woman on the phone to one of the cyclists" is not on a
    bike)."""
    j = i - 1
    while j >= 0 and i - j <= _HEDGE_MODIFIERS and tokens[j] not in _HEDGE_OR_PART and describes(tokens[j]):
        j -= 1
    while j >= 0 and i - j <= _HEDGE_SPAN and tokens[j] in _HEDGE_OR_PART:
        j -= 1
    return j >= 0 and tokens[j] in _ON_IT


def rides_next(tokens: list[str], i: int) -> bool:
    """Whether ``tokens[i]`` names a rider ("rider", "riders"), so that a word the reader has no entry
    for right before it says what or whose the ride is ("a Voi rider", "a delivery rider", "a Brompton
    rider"), not who: the rider is the road user."""
    if i >= len(tokens):
        return False
    noun = tokens[i]
    return rider_noun(min(lemmas(noun).get("NOUN", (noun,))))


def unnamed_subject(
    text: str,
    known: Callable[[str], bool],
    road_user: Callable[[str], bool],
    acts: Callable[[list[str], int], bool] = lambda words, i: True,
) -> tuple[str, str] | None:
    """``text`` with the first noun phrase the reader has no noun for, that opens a clause as the
    subject of a verb ("The rider shot off the kerb", "Two riders rolled across", "A figure in dark
    clothes walked out"), said by a general noun the reader has: a rider (someone who rides) as a
    scooter rider (the two-wheeler this project is about), anyone else as someone (a walker, or the
    driver a vehicle's behaviour then makes them), several as so many people; and that noun. None if
    there is none.

    Only for a description in which the reader found no road user at all, so that a noun missing from
    its lexicon does not lose the one road user a text names. A noun after a road-user noun names a
    thing of it ("a bike rack", "the scooter bay") and is left alone; ``known(word)`` is whether the
    reader has a phrase for the word, ``road_user(word)`` whether it names a road user. Of several such
    subjects, the first that does what a road user does in its clause (``acts(words, i)``: a behaviour
    from word ``i`` before the clause ends) is taken: "The app sent me down the high street. Two lads
    walked out in front of me" is about the lads, not the app."""
    chosen = unnamed_subjects(text, known, road_user, acts)
    return chosen[0] if chosen else None


def unnamed_subjects(
    text: str,
    known: Callable[[str], bool],
    road_user: Callable[[str], bool],
    acts: Callable[[list[str], int], bool] = lambda words, i: True,
) -> list[tuple[str, str]]:
    """Each reading :func:`unnamed_subject` may take, best first (those that act, else all), so that a
    caller may pass over one whose deed names no road user of its own ("The accused was driving a
    lorry. The deceased was walking ...": the one driving is the lorry's driver; the one walking is the
    road user)."""
    words = list(_WORD.finditer(text))
    lower = [m.group(0).lower() for m in words]
    found = _unnamed_subjects(text, words, lower, known, road_user)
    acting = [c for c in found if acts(lower[: _clause_end(text, words, c[2])], c[2] + 1)]
    return [c[:2] for c in acting or found]


def _clause_end(text: str, words: list[re.Match], k: int) -> int:
    """The index of the first word after word ``k`` that opens a new clause (or the number of words)."""
    for n in range(k + 1, len(words)):
        if any(c in _CLAUSE_MARKS for c in text[words[n - 1].end() : words[n].start()]):
            return n
    return len(words)


def _adjective_as_noun(lower: list[str], n: int, h: int) -> bool:
    """Whether the word at ``h`` is a participle adjective standing for a person right after "the" at
    ``n`` ("the deceased was walking", "the injured stepped out"): a report's way of naming someone by
    their state ("the same happened" is no one)."""
    pos = lemmas(lower[h])
    return h == n + 1 and lower[n] == "the" and lower[h].endswith("ed") and "ADJ" in pos and "VERB" in pos


#: Pronouns that name no one ("nobody had to stop", "no-one was hurt", "anyone could have ...").
_NOBODY = frozenset(("nobody", "no-one", "noone", "none", "nothing", "anyone", "anybody", "anything"))


def _unnamed_subjects(
    text: str, words: list[re.Match], lower: list[str], known: Callable[[str], bool], road_user: Callable[[str], bool]
) -> list[tuple[str, str, int]]:
    """Each candidate of :func:`unnamed_subject`, in order: the text said with it, its noun, and the
    index of its noun among the words."""
    out: list[tuple[str, str, int]] = []
    for n, m in enumerate(words):
        opens = n == 0 or any(c in _CLAUSE_MARKS for c in text[words[n - 1].end() : m.start()])
        if not opens:
            continue
        k = n + 1 if lower[n] in _OPENING else n  # (a bare noun opens a clause too: "Rider came out of ...")
        head = None
        for h in range(k, min(k + 3, len(words) - 1)):
            if road_user(lower[h]) or known(lower[h]) or lower[h] in _OPENING or rider_noun(lower[h - 1]):
                break  # (a road user's thing, "a bike rack", "the rider manual"; or a phrase the reader has)
            if lower[h - 1 : h + 1] in FORGONE:
                break  # ("rather than swerve": an alternative set aside, no one's noun)
            if lower[h] in _NOBODY or lower[h] == "no":
                break  # ("Nobody had to step back", "At no point did anyone ...": no one is named)
            if ("NOUN" in lemmas(lower[h]) or not english(lower[h]) or _adjective_as_noun(lower, n, h)) and (
                lower[h + 1] in DESCRIBING or _verb_word(lower[h + 1])
            ):
                head = h
                break
        if head is None:
            continue
        noun = lower[head]
        singular = min(lemmas(noun).get("NOUN", (noun,)))
        plural = noun != singular
        count = [lower[n]] if k == n + 1 and lower[n] not in ("a", "an", "the", "some", "another", "one") else []
        if rider_noun(singular):
            det = count or ([] if plural else ["the"] if lower[n] == "the" else ["a"])
            said = " ".join([*det, "scooter", "riders" if plural else "rider"])
        else:
            said = " ".join([*count, "people"]) if plural else "someone"
        out.append((text[: m.start()] + said + text[words[head].end() :], noun, head))
    return out


#: South Asian English names a road user by what they ride or drive and the agent suffix "wala" ("one
#: bike wala came wrong side", "a cycle-wallah", "the autowala"): the suffix's spellings.
_WALA = ("wala", "walla", "wallah", "waala", "vala", "valla", "wale", "waale", "wali", "waali")
#: The vehicle each stem names in that English ("bike" and "scooter" there are a motor two-wheeler,
#: "cycle" a pedal cycle, "auto" an auto-rickshaw, "tempo" a light goods van), by the word the reader
#: types it by. A stem that names no vehicle ("chai wallah", "sabzi wala") stays as it is.
_WALA_STEMS = {
    "bike": "motorbike", "motorbike": "motorbike", "motorcycle": "motorbike", "scooter": "motorbike",
    "scooty": "motorbike", "cycle": "cyclist", "bicycle": "cyclist", "auto": "auto-rickshaw",
    "rickshaw": "rickshaw", "tuk-tuk": "tuk-tuk", "car": "car", "cab": "cab", "taxi": "taxi", "truck": "truck",
    "lorry": "lorry", "tanker": "tanker", "bus": "bus", "tempo": "van", "van": "van", "jeep": "jeep",
    "tractor": "tractor",
}  # fmt: skip


def _wala_stem(word: str) -> str | None:
    """The vehicle stem of a fused "bikewala" or "cycle-wallah", else None."""
    for suffix in _WALA:
        if word.endswith(suffix) and len(word) > len(suffix):
            stem = word[: -len(suffix)].rstrip("-")
            if stem in _WALA_STEMS:
                return stem
    return None


def wala_riders(tokens: list[str]) -> list[str]:
    """ "one bike wala came on the wrong side", "a cycle wala, milk delivery", "the autowala cut in": a
    vehicle's word with the agent suffix "wala" is the person on or in it, one road user of that
    vehicle's type, typed as that English means it ("bike" is a motorbike there, "cycle" a bicycle).
    Only a vehicle's stem is read: "the chai wallah" and "a sabzi wala" stay what they are."""
    out: list[str] = []
    for w in tokens:
        if w in _WALA and out and out[-1] in _WALA_STEMS:
            out[-1] = _WALA_STEMS[out[-1]]
            continue
        if out and w in _WALA and out[-1] == "-" and len(out) > 1 and out[-2] in _WALA_STEMS:
            out[-2:] = [_WALA_STEMS[out[-2]]]
            continue
        stem = _wala_stem(w)
        out.append(_WALA_STEMS[stem] if stem else w)
    return out


#: What may stand before a shared e-scooter's operator name in a road user's place.
_OPERATOR_BEFORE = frozenset(("a", "an", "the", "another", "one", "some", "his", "her", "their", "two", "three"))
#: What may follow such a name, ending its noun phrase: punctuation or a word that opens what it does.
_PHRASE_END = frozenset(".,;:!?") | frozenset(("and", "then", "which", "that", "who", "with", "from", "on", "at"))
#: Prepositions of where a road user is or goes, which end its noun phrase as well ("a girl on a Lime in
#: the bike lane", "a Voi across the crossing"); not "to" ("took a Bolt to the airport": a ride-hail car).
_PLACE_AFTER = frozenset(
    ("in", "into", "onto", "across", "along", "through", "off", "past", "near", "beside", "behind")
)
#: The person on a shared e-scooter, named after its operator ("a Lime rider", "a Voi user"); a "Bolt
#: driver" drives a ride-hail car and stays one.
_SCOOTER_PERSON = frozenset(("rider", "riders", "user", "users"))


#: Words that put a person on what follows them ("a lad on a lime", "two guys doubled up on one bird").
_ON = frozenset(("on", "riding", "rode", "rides", "ride", "onto"))
#: The operators whose name is no thing a person is otherwise on ("on a spin", "on the beam", "on a bolt",
#: "on one tier" are): only these are read in lower case.
_ON_IN_LOWER_CASE = frozenset(("lime", "bird", "voi", "dott", "neuron", "superpedestrian"))


def _ridden(tokens: list[str], i: int) -> bool:
    """Whether the operator name at ``i`` is what a person is on ("a kid on a lime", "riding a bird"):
    there a writer who types in lower case names the scooter, not the fruit or the animal. Only where
    its phrase ends at it: punctuation or an inflected verb follows ("on a lime came out", "on one
    bird, swerved"), not a word that may go on the noun ("on a lime green bike", "on a bird table")."""
    if tokens[i] not in _ON_IN_LOWER_CASE:
        return False
    if i < 2 or tokens[i - 2] not in _ON or i + 1 >= len(tokens):
        return i >= 2 and tokens[i - 2] in _ON
    nxt = tokens[i + 1]
    verbs = lemmas(nxt).get("VERB", ())
    return nxt in _PHRASE_END or (bool(verbs) and nxt not in verbs)


def shared_scooters(tokens: list[str], proper: frozenset[str], verb: Callable[[str], bool]) -> list[str]:
    """ "a Lime came down the pavement", "some lad on a Tier", "a Voi shot the red": an operator of shared
    e-scooters written with its capital (``proper``: :func:`proper_names`), after an article and ending
    its noun phrase (a verb, punctuation or a preposition follows), is an e-scooter; so is it before its
    rider ("a Voi user"). Before "scooter" the
    name only says whose it is, and goes. In lower case only what someone is on or rides is one ("a lad
    on a lime came out"); else ("lime green", "a bird flew") or in a longer name ("Lime Street") it stays
    the word it is."""
    out: list[str] = []
    for i, w in enumerate(tokens):
        nxt = tokens[i + 1] if i + 1 < len(tokens) else "."
        if w in SCOOTER_OPERATORS and (w in proper or _ridden(tokens, i)) and i and tokens[i - 1] in _OPERATOR_BEFORE:
            if nxt in ("scooter", "scooters", "e-scooter", "e-scooters", "escooter"):
                continue
            if (nxt in _PHRASE_END or nxt in _PLACE_AFTER or verb(nxt)) and nxt not in proper:
                out.append("e-scooter")
                continue
            if nxt in _SCOOTER_PERSON:  # ("a Lime rider": the e-scooter's rider)
                out.append("e-scooter")
                continue
        out.append(w)
    return out


#: The most road users a count in figures makes: a count above it is traffic, not road users one by one.
_MOST_COUNTED = 5


def _modifier(word: str) -> bool:
    """Whether ``word`` may describe a noun after a number: a plain word, no plural noun of its own
    ("stolen", "rental"; not "hours", "lanes")."""
    nouns = lemmas(word).get("NOUN", ())
    return word.isalpha() and not (nouns and word not in nouns)


def counted_in_figures(tokens: list[str], i: int, kind_at: KindAt) -> int | None:
    """The number of road users a whole number in figures at ``i`` counts, when a plural road-user noun
    follows it ("2 escooters riding side by side", "3 cyclists in a line"), as "two" and "three" count
    one; else None. A singular after it is a label or a measure, no count ("car 2", "2 car lengths")."""
    if not tokens[i].isdigit() or not 2 <= int(tokens[i]) <= _MOST_COUNTED or i + 1 >= len(tokens):
        return None
    at = i + 1
    found = kind_at(tokens, at)
    if found is None and at + 1 < len(tokens) and _modifier(tokens[at]):
        at += 1  # ("3 rental e-scooters", "2 stolen bikes": a word that describes them between)
        found = kind_at(tokens, at)
    if found is None or found[0] == "ego":
        return None
    head = tokens[at + found[1] - 1]
    nouns = lemmas(head).get("NOUN", ())
    plural = head not in nouns if nouns else head.endswith("s") and not head.endswith("ss")
    return int(tokens[i]) if plural else None


#: Words between "standing" and the scooter it names the kind of ("standing type electric scooters").
_KIND_FILLERS = frozenset({"type", "kind", "style", "sort", "electric", "motorised", "motorized", "rental", "shared"})
#: Nouns a standing rider rides: scooters, whose stand-up kind people tell apart from the seated one.
_STOOD_ON = frozenset({"scooter", "scooters", "e-scooter", "e-scooters", "escooter", "escooters", "kick"})
#: Nouns that stand for a kind after "the standing" ("the standing kind", "the standing type").
_KIND_NOUNS = frozenset({"kind", "type", "sort", "one", "ones", "variety", "model"})


def standing_names_a_kind(tokens: list[str], i: int) -> bool:
    """Whether "standing" at token ``i`` names the kind of a scooter ("a standing e-scooter", "those
    standing type electric scooters", "a rental e-scooter, the standing kind"), not a road user
    that stands still. Why: read as a state, the rider was parked and did nothing it was said to."""
    j = i + 1
    while j < len(tokens) and j <= i + 3 and tokens[j] in _KIND_FILLERS:
        j += 1
    if j < len(tokens) and tokens[j] in _STOOD_ON:
        return True
    return i > 0 and tokens[i - 1] == "the" and tokens[i + 1 : i + 2] != [] and tokens[i + 1] in _KIND_NOUNS
