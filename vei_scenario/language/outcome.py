"""The outcome a description states (its intent: ``collision``, ``near_miss`` or ``safe``; ``critical``
where a test rates its scenario so), read from
the structure of its clauses rather than from a list of phrases.

People state an outcome in three ways, and each is a construction, not a set of words:

* **an event between the ego and a road user**: a verb of contact ("hit", "clipped", "was struck
  by", "went into the side of him", "made contact"), a noun of one ("a collision", "the impact"), or a
  person "down" ("rider down"); a verb of missing with a person as object ("missed him", "missed each
  other"); a margin ("with inches to spare", "stopped a foot short", "0.5 m clearance");
* **the scope of a negation or a hedge over that event**: "no contact", "did not hit", "without
  touching", "avoided a collision" deny it; "nearly", "almost", "barely", "would have" hedge it. A
  denied or hedged contact is not a collision: a hedged one is a near miss, a denied one a near miss
  when the ego had to act (swerve, brake, stop short) or it was close, and a safe pass when the ego only
  gave way;
* **what the ego does about it**: swerving or braking hard with no contact said is a near miss;
  waiting, giving way or letting the other go with nothing else said is a safe pass.

A scope ends at the clause: punctuation or a conjunction ("no contact, but he fell" leaves "fell"
alone). One contact stated anywhere makes the whole a collision (a near miss followed by contact is
still a collision). A text that states none of these has no intent: nothing is assumed.

The closed classes below are grammatical (negators, hedges, conjunctions, pronouns) or the small set
of English verbs and nouns of contact; the rest is read from where words stand in a clause.
"""

from __future__ import annotations

from collections import OrderedDict
from dataclasses import dataclass, field
from functools import lru_cache
from threading import Lock

from vei_scenario.language import lexicon as L
from vei_scenario.language import vocabulary as V
from vei_scenario.language.braking_sounds import braking_sound
from vei_scenario.language.clauses import split
from vei_scenario.language.designed_outcome import designed_outcome
from vei_scenario.language.elided_verb import elliptical_negation
from vei_scenario.language.function_words import (
    CLAUSE_BREAKS,
    FIRST_PERSON,
    PHRASE_ENDS,
    POSSESSIVE,
    SUBJECT_PRONOUNS,
)
from vei_scenario.language.lemmas import lemmas
from vei_scenario.language.light_contact import LOCATING, knock_felt, marking_met
from vei_scenario.language.no_response import no_response_expected
from vei_scenario.language.normalise import lies_on_roads
from vei_scenario.language.quantities import a_size
from vei_scenario.language.settings import FOOT_CROSSINGS
from vei_scenario.language.thought_of import only_thought_of
from vei_scenario.language.who import TOWED

COLLISION, NEAR_MISS, SAFE, CRITICAL = "collision", "near_miss", "safe", "critical"
#: The kind of a cue of the class an event is designed for, before that class ("designed:near_miss").
DESIGNED = "designed:"

#: What ends a clause, and with it the scope of a negation or a hedge: these marks and the words of
#: :data:`function_words.CLAUSE_BREAKS`.
_BREAK_PUNCT = frozenset(".;!?:,")
#: Negators: they deny what follows them in their clause.
_NEGATORS = frozenset(("no", "not", "never", "without", "nobody", "nothing", "neither", "nor", "none", "cannot"))
#: Verbs (lemmas) whose object is denied: "avoided contact", "prevents a collision".
_DENYING_VERBS = frozenset(("avoid", "prevent", "escape", "evade", "avert"))
#: Hedges: what follows them almost happened ("nearly hit", "barely missed", "almost a crash").
HEDGES = frozenset(("nearly", "almost", "narrowly", "barely", "virtually", "practically"))
#: Words of a condition or a counterfactual: what follows did not happen ("would have hit", "if it hits").
_HYPOTHETICAL = frozenset(("would", "could", "might", "if", "before"))

#: English verbs of contact (lemmas). Ambiguous ones ("hit the brakes", "touch 50") are checked for
#: what they take as object.
_CONTACT_VERBS = frozenset(
    ("hit", "strike", "collide", "crash", "clip", "tag", "scrape", "touch", "bump", "smash", "ram", "sideswipe",
     "rear-end", "t-bone", "graze", "wallop", "thump", "knock", "tap", "mow", "swipe", "shunt", "total", "whack",
     "clout", "bash", "smack", "clobber")
)  # fmt: skip
#: Forms of verbs of a knock that the lemmatiser does not know ("dinged the door", "biffed my bumper").
_SLANG_CONTACT = frozenset(("dinged", "dings", "dinging", "biffed"))
#: Nouns of a contact; "rtc" and "rta" are the road traffic collision (accident) of a report.
_CONTACT_NOUNS = frozenset(
    ("collision", "crash", "impact", "contact", "accident", "smash", "prang", "rtc", "rta", "shunt", "pile-up",
     "pileup", "smash-up", "fender-bender", "coming-together")
)  # fmt: skip
#: The sounds of an impact, said as what happened ("there was a horrible thump").
_IMPACT_SOUNDS = frozenset(("thump", "thud", "bang", "smack", "crunch", "bump"))
#: A contact noun before one of these is a modifier of something else ("collision warning").
_COMPOUND_HEADS = frozenset(
    ("warning", "avoidance", "barrier", "barriers", "mitigation", "system", "systems", "detection", "alert", "sensor",
     "helmet", "zone", "risk", "test", "tests", "course", "imminent", "scene", "data", "report", "ref", "reference",
     "type", "types", "category", "categories", "sport", "sports")
)  # fmt: skip
#: Objects that make a contact verb something else ("hit the brakes", "hit the gas", "clipped the kerb").
#: The controls a driver presses, met by no contact verb ("hit the brakes", "hit to the brakes").
_CONTROLS_PRESSED = frozenset(("brake", "brakes", "gas", "accelerator", "pedal", "throttle", "horn"))
_NOT_ROAD_USERS = _CONTROLS_PRESSED | frozenset(
    ("pothole", "puddle", "button", "road", "jackpot", "traffic", "red", "green", "lights", "light", "speed", "mph",
     "km/h", "m/s", "limit", "eye", "base")
)  # fmt: skip
#: The closed class of object pronouns and reciprocal phrases: who is met or missed.
_PERSON_OBJECTS = frozenset(("me", "us", "him", "her", "it", "them", "you", "each", "one"))
_POSSESSIVES = frozenset(("my", "our", "his", "her", "its", "their", "your"))
#: Motion verbs that carry the mover into what it meets ("went into the side of it", "ploughed into him").
_INTO = "into"
#: The parts of a vehicle a body is thrown against ("bounced off my bonnet").
_STRUCK_PARTS = frozenset(("bonnet", "hood", "windscreen", "windshield", "bumper", "roof", "wing", "mirror", "door"))
#: The places one moves into (a path, not a thing one meets): "into my lane", "into the side road".
_PLACES = frozenset(
    ("lane", "lanes", "road", "street", "path", "way", "junction", "intersection", "roundabout", "carriageway", "gap",
     "space", "traffic", "crossing", "exit", "entry", "lay-by", "bay", "stop", "drive", "driveway", "verge", "shoulder",
     "kerb", "curb", "pavement", "footway", "sidewalk", "footpath", "bend", "corner", "view", "position", "line",
     "arm", "spot", "skid", "spin", "park", "lot", "entrance", "carpark", "turn", "area", "zone", "middle", "centre",
     "place")
)  # fmt: skip
#: The parts of a road user one runs into.
_PARTS = frozenset(("side", "back", "rear", "front", "wing", "door", "trailer", "bumper", "tail", "bonnet", "boot"))
#: Words that end a small margin: units of length and the idioms of a hair's width.
_SMALL_UNITS = frozenset(("inch", "inches", "cm", "centimetre", "centimetres", "centimeter", "centimeters", "mm",
                          "millimetres", "foot", "feet", "whisker", "hair", "hairs", "paint", "fraction", "breadth",
                          "width", "cigarette", "fag"))  # fmt: skip
_LENGTH_UNITS = frozenset(("m", "metre", "metres", "meter", "meters", "foot", "feet", "yard", "yards"))
#: Quantity words of a wide margin ("plenty of room", "loads of space").
_WIDE = frozenset(
    ("plenty", "lots", "loads", "heaps", "tons", "ample", "enough", "room", "space", "wide", "generous", "comfortable",
     "healthy")
)  # fmt: skip
#: Nouns of trouble that, denied, state a safe pass ("no issues", "without incident", "no danger").
_TROUBLE = frozenset(
    ("issue", "issues", "problem", "problems", "conflict", "conflicts", "danger", "drama", "incident", "incidents",
     "trouble", "harm", "risk", "worry", "worries", "dramas", "interaction", "interactions")
)  # fmt: skip
#: Nouns of a fuss that, denied right before them, state a safe pass ("no bother", "without any fuss");
#: also verbs ("didn't bother to indicate"), so only as the noun of "no", "any" or "without".
_FUSS = frozenset(("fuss", "bother", "hassle", "hassles", "bovver", "biggie", "palaver"))
#: Words of a close call said of the situation ("it was close", "dangerous", "scary").
_CLOSE = frozenset(
    ("close", "tight", "dangerous", "scary", "scared", "frightening", "hairy", "terrified", "terrifying", "petrified")
)
#: Auxiliaries, modals and adverbs between a subject and its verb ("the ego has to quickly brake").
_BETWEEN = frozenset(
    ("has", "have", "had", "to", "must", "also", "just", "then", "is", "was", "were", "are", "be", "been", "will",
     "would", "can", "could", "should", "did", "does", "do", "quickly", "immediately", "simply", "still", "got",
     "gets", "needs", "need", "needed", "am", "too", "both", "only", "really", "instantly", "hard", "sharply")
)  # fmt: skip
#: The ego's names as the reader normalises them (a narrator, the ego, the subject vehicle).
_EGO_HEADS = frozenset(("i", "we", "ego", "sv", "vut", "av", "im"))
_EGO_PHRASES = ("ego vehicle", "ego car", "subject vehicle", "test vehicle", "vehicle under test", "our car",
                "my car", "host vehicle")  # fmt: skip
#: What the ego does when it has to act: evasion, and its manner.
#: The verbs of pressing the brakes with force (:data:`lexicon.PRESSING`) are evasion only said of the
#: pedal (:func:`_on_the_brakes`); "hit" is not one here: a verb of contact, and a plain brake when it
#: works one (:data:`_WORKING`).
_EVADE = frozenset(("swerve", "dodge", "veer", "yank", "jerk", "wrench", "anchor")) | (L.PRESSING - {"hit"})
_HARD = frozenset(("hard", "dead", "sharply", "heavily", "suddenly", "firmly", "harshly", "violently", "emergency",
                   "full", "strongly", "abruptly"))  # fmt: skip
_BRAKE = frozenset(("brake", "stop"))
#: What one brakes "like" when one brakes as hard as one can ("like mad", "like hell").
_FURY = frozenset(("mad", "hell", "crazy", "anything", "fury", "billy-o"))
_MILD = frozenset(("gently", "softly", "lightly", "slightly", "normally", "smoothly", "gradually", "calmly"))
#: What a road user that gives way does (lemmas).
_YIELD = frozenset(("wait", "yield", "give", "let", "hang", "hold", "pause"))
#: Words after "let X": it goes, so the one who lets gives way ("let it pass", "let him go first").
_LET_GO = frozenset(("pass", "go", "through", "by", "past", "first", "cross", "in", "out", "across", "over"))


@lru_cache(maxsize=8192)
def _pos(word: str) -> dict[str, tuple[str, ...]]:
    """lemminflect's lemmas by part of speech; a hyphenated word ("rear-ended", "T-boned") by its last
    part, joined again."""
    found = lemmas(word)
    if not found and "-" in word:
        head, _, last = word.rpartition("-")
        found = {pos: tuple(f"{head}-{x}" for x in forms) for pos, forms in lemmas(last).items()}
    if not found:
        found = _closed_compound(word)
    return found


def _closed_compound(word: str) -> dict[str, tuple[str, ...]]:
    """A compound verb of a collision written as one word ("tboned", "rearended", "rearending"), read as
    its hyphenated form ("t-bone", "rear-end"): texting and voice-to-text drop the hyphen. Only the
    compounds of :data:`_COMPOUND_FIRST`, and only inflected ("a tbone steak" is a noun)."""
    for first, verb in _COMPOUND_FIRST.items():
        rest = word[len(first) :]
        if word.startswith(first) and rest != verb and verb in lemmas(rest).get("VERB", ()):
            return {"VERB": (f"{first}-{verb}",)}
    return {}


@lru_cache(maxsize=8192)
def _lemmas(word: str) -> frozenset[str]:
    out = {word}
    for forms in _pos(word).values():
        out.update(forms)
    return frozenset(out)


def _is_verb(word: str) -> bool:
    return "VERB" in _pos(word)


_WORD_NUMBERS = {"two": 2.0, "three": 3.0, "four": 4.0, "five": 5.0, "six": 6.0, "half": 0.5}


def _number(word: str) -> float | None:
    """A number as digits, or a small one in words ("three feet from her": no unit the normaliser knows)."""
    try:
        return float(word)
    except ValueError:
        return _WORD_NUMBERS.get(word)


@dataclass
class _Clause:
    """One clause's tokens, and the subject it inherits when it names none ("braked and swerved")."""

    words: list[str]
    first_of_sentence: bool
    inherited: str | None = None
    #: An earlier clause of its sentence is a condition ("if I had not braked, I would have hit him").
    after_if: bool = False
    signs: set[str] = field(default_factory=set)


def _clauses(tokens: list[str]) -> list[_Clause]:
    """The clauses of ``tokens``: cut at punctuation and at conjunctions; one after a clause with "if"
    or "unless" in its sentence is marked ``after_if``."""
    out: list[_Clause] = []
    condition = False
    for words, first in split(tokens, _BREAK_PUNCT | CLAUSE_BREAKS):
        condition = condition and not first  # (a condition holds to the end of its sentence)
        out.append(_Clause(words, first, after_if=condition))
        condition = condition or bool({"if", "unless"} & set(words))
    return out


def _scoped(words: list[str], i: int, closed: frozenset[str], reach: int = 4) -> bool:
    """Whether a word of ``closed`` stands up to ``reach`` words before ``i`` in the clause."""
    return any(w in closed for w in words[max(0, i - reach) : i])


#: Words that deny the verb after them as a negator does ("was unable to avoid", "failed to stop").
_FAILING = frozenset(("unable", "fail", "fails", "failed", "failing"))


#: Words that open a clause embedded as the object of a verb of knowing or saying ("don't know how I
#: stopped", "no idea why he missed us"): a negation before one is of the knowing, not of what is known.
_WH_COMPLEMENT = frozenset(("how", "why", "whether", "what"))


def forgone(words: list[str], i: int) -> bool:
    """Whether the word at ``i`` is the alternative a clause sets aside ("waited instead of squeezing
    past", "rather than hitting the scooter, he swerved"; :data:`~vei_scenario.language.lexicon.FORGONE`):
    what follows the marker was not done."""
    return any(words[k : k + 2] in L.FORGONE for k in range(max(0, i - 3), i - 1))


#: Modals of a counterfactual perfect ("would have", "could easily have", "might well have").
_MODALS = frozenset(("would", "could", "might", "should"))


def _modal_perfect(words: list[str], i: int) -> bool:
    """Whether the word at ``i`` stands after a modal and "have" in its clause, adverbs between ("would
    certainly have meant hitting her", "could easily have killed him"): what did not happen."""
    return any(w in _MODALS and "have" in words[k + 1 : min(k + 4, i)] for k, w in enumerate(words[:i]))


#: Subjects of a prediction about anyone at all ("someone is going to be killed"), and markers of a
#: time to come ("one day", "sooner or later").
_INDEFINITE = frozenset(("someone", "somebody", "anyone", "anybody", "people", "eventually", "sooner"))


#: The spoken contractions of "going to" as a future ("someone's gonna get hurt", "a kid finna get hit").
_GOING_TO = frozenset(("gonna", "gunna", "gonnae", "finna", "gon"))


def _predicted(words: list[str], i: int) -> bool:
    """Whether the word at ``i`` is under a future ("is going to", "will") said of anyone at all or
    of a time to come ("someone is going to get hit", "one day a child will be killed"): a warning,
    not what happened. A test's "the lorry is going to hit the cyclist" names who, and plays."""
    before = words[max(0, i - 8) : i]
    future = any(before[k : k + 2] in (["going", "to"], ["bound", "to"]) for k in range(len(before) - 1))
    future = future or "will" in before[-4:] or bool(set(before[-4:]) & _GOING_TO)
    one_day = any(words[k : k + 2] == ["one", "day"] for k in range(i))
    return future and (bool(set(words[:i]) & _INDEFINITE) or one_day)


def _denied_before(words: list[str], i: int) -> bool:
    """Whether what stands at ``i`` is denied in its clause: an odd count of negators and denying
    verbs before it ("no contact", "did not make contact", "managed to avoid hitting"); two cancel
    ("was unable to avoid the collision", "could not avoid him": it happened). A negation's scope ends
    at a wh-complement ("I don't know how I stopped in time": the stop happened), and an alternative
    set aside counts as denied ("instead of hitting him")."""
    start = max((k + 1 for k in range(i) if words[k] in _WH_COMPLEMENT | {"if"}), default=0)
    count = sum(
        1
        for k in range(start, i)
        if (words[k] in _NEGATORS or words[k] in _FAILING)
        and not _of_a_noun(words, k, i)
        and not elliptical_negation(words, k)  # ("the truck does not → we get rear-ended")
    )
    count += sum(1 for w in words[max(start, i - 4) : i] if _lemmas(w) & _DENYING_VERBS)  # ("avoid a crash")
    count += forgone(words, i)
    return count % 2 == 1


def _of_a_noun(words: list[str], k: int, i: int) -> bool:
    """Whether the negator "not" at ``k`` denies only the possessed noun right after it, which ends
    before ``i`` ("the driver behind, not our customer, rear-ended him", "it was not my fault he hit
    me"): a noun phrase set aside, not the verb that follows it."""
    return words[k] == "not" and words[k + 1 : k + 2] != [] and words[k + 1] in _POSSESSIVES and k + 2 < i


#: Possessive pronouns that stand for a noun said before them ("his mirror took mine off").
_OWN_ONES = frozenset(("mine", "ours"))


def _part_said_before(words: list[str], i: int) -> bool:
    """Whether the object of the verb at ``i`` is "mine" or "ours" standing for a vehicle's part named
    before it in its clause ("the Range Rover's wing mirror takes mine clean off"): the narrator's own
    part of that kind, met."""
    return words[i + 1 : i + 2] != [] and words[i + 1] in _OWN_ONES and any(w in _VEHICLE_PARTS for w in words[:i])


def _own_one(words: list[str], i: int) -> bool:
    """Whether the verb at ``i`` has the ego as its subject and "mine" or "ours" as its object with no
    vehicle's part named before it ("I had to touch mine as well", after "you did brake"): the ego
    handling its own control, which meets no road user."""
    if words[i + 1 : i + 2] == [] or words[i + 1] not in _OWN_ONES or _part_said_before(words, i):
        return False
    j = i - 1
    while j >= 0 and (words[j] in _BETWEEN or words[j].endswith("ly")):
        j -= 1
    return j >= 0 and words[j] in _EGO_HEADS


def _object_of(words: list[str], i: int) -> list[str]:
    """The words after a verb at ``i`` up to its object's head (past a particle and determiners)."""
    return words[i + 1 : i + 4]


#: Street furniture and the road's edges: what a road user hits when it escapes another is not a road
#: user ("swerved and hit the kerb", "struck a bollard"), so hitting one then is no contact between the
#: two (a pickup that "hit the kerb and rolled", escaping no one, crashed).
_FURNITURE = frozenset(
    ("kerb", "curb", "kerbs", "bollard", "bollards", "lamppost", "lamp-post", "lamp", "post", "pole", "wall", "fence",
     "barrier", "railing", "railings", "tree", "hedge", "sign", "signpost", "verge", "ditch", "bin", "bench",
     "guardrail", "gatepost", "pillar", "kerbstone", "bridge", "parapet")
)  # fmt: skip
#: Ordinal suffixes the tokeniser splits from a street's number ("5th" -> "5 th").
_ORDINALS = frozenset(("st", "nd", "rd", "th"))


#: Words between a verb and the furniture it meets ("swerved straight into the hedge", "went up onto the kerb").
_TO_FURNITURE = frozenset(("into", "onto", "against", "straight", "right", "up", "off", "on"))


def _escaping_into_furniture(words: list[str], i: int, sentence: list[str]) -> bool:
    """Whether the contact verb at ``i`` hits street furniture (its object's head) while its sentence
    so far tells of escaping someone ("I swerved to miss him and hit the kerb", "swerved into the
    hedge to miss him") or a move forced on its doer ("had to pull in to the hedge, scraped it"), or
    the one who hits it is a walker or a rider ("a lad on a scooter came off the pavement, hit the
    kerb", "she wobbled, clipped the curb and came off"): their own fall, no contact with the ego (a
    vehicle that "hit the kerb and rolled" may be the ego's own crash)."""
    skip = _DETERMINERS | _POSSESSIVES | _TO_FURNITURE
    at = next((k for k in range(i + 1, min(i + 6, len(words))) if words[k] not in skip), None)
    head = words[at] if at is not None else ""
    if head == "it":  # ("had to pull in to the hedge, scraped it": the furniture moved to, told again)
        head = _goal_before(sentence[: len(sentence) - len(words) + i])
    nxt = words[at + 1] if at is not None and at + 1 < len(words) else ""
    if head not in _FURNITURE and nxt in _FURNITURE and not _road_user_word(head):
        head = nxt  # ("hit the metal post", "into a low wall": one word of what it is made of or like)
    if head not in _FURNITURE:
        return False
    escaping = any(_lemmas(x) & (_EVADE | {"avoid", "miss", "dodge"}) for x in sentence)
    # (braking is escaping where the ego hits it: "I brake, I not touch him, but my van hit the kerb";
    # not where someone else does: "Driver slammed on and an old lady banged her head on the pole")
    before = sentence[: len(sentence) - len(words) + i]
    egos = next((w for w in reversed(before) if w in _EGO_HEADS | _POSSESSIVES | _THIRD_SUBJECTS), "")
    escaping = escaping or (egos in _EGO_HEADS | {"my", "our"} and any(_lemmas(x) & _BRAKE for x in sentence))
    forced = any(sentence[k : k + 2] == ["had", "to"] for k in range(len(sentence) - len(words) + i))
    return escaping or forced or _walker_or_rider_before(sentence[: len(sentence) - len(words) + i])


#: Prepositions of a move's goal ("pull in to the hedge", "swerved towards the fence", "onto the verge").
_TO_A_GOAL = frozenset(("to", "towards", "toward", "into", "onto", "against"))


def _goal_before(before: list[str]) -> str:
    """The thing ``it`` stands for at the end of ``before``: its last noun of street furniture or of a
    road user, when that is furniture a move was made to ("had to pull in to the hedge": "hedge"; not
    "a car stopped by the hedge", where the hedge is only where the car was), else ""."""
    for k in range(len(before) - 1, -1, -1):
        w = before[k]
        if w in _FURNITURE:
            j = k - 1
            while j >= 0 and before[j] in _DETERMINERS | _POSSESSIVES:
                j -= 1
            return w if j >= 0 and before[j] in _TO_A_GOAL else ""
        if _road_user_word(w) or w in _PERSON_OBJECTS | _EGO_HEADS:
            return ""
    return ""


#: The kinds of road user that are walkers or riders: never the ego's own vehicle.
_UNPROTECTED = ("pedestrian", "bicycle", "e-scooter")
#: The subject pronouns of a third person, and the ego's own.
_THIRD_SUBJECTS = frozenset(("he", "she", "they"))


@lru_cache(maxsize=1)
def _unprotected_heads() -> frozenset[str]:
    """The last words of the lexicon's nouns of walkers and riders ("jogger", "kid", "cyclist", "lime")."""
    phrases = [p for kind in _UNPROTECTED for p in L.ACTOR_NOUNS[kind]] + list(L.GENERIC_PERSONS)
    return frozenset(p.split()[-1] for p in phrases) | {"rider", "cyclist", "lad", "boy", "girl", "kid"}


def _walker_or_rider_before(before: list[str]) -> bool:
    """Whether the nearest subject said before a verb (``before``: its sentence up to it) is a walker
    or a rider (a third person's pronoun, or a noun of a walker or a rider), not the ego or a vehicle.
    Object pronouns ("on her left") and other nouns are passed over."""
    for w in reversed(before):
        if w in _EGO_HEADS:
            return False
        if w in _THIRD_SUBJECTS or w in _unprotected_heads():
            return True
        if _road_user_word(w):
            return False  # ("the pickup did not stop, hit the kerb": a vehicle, maybe the ego's)
    return False


def _meets_road_user(after: list[str]) -> bool:
    """Whether the object after a contact verb is a road user, not a brake pedal, a speed or street
    furniture. A number is an age when "year-old" follows it ("struck a 72 year-old woman"), and a
    street's number before its ordinal suffix is where, not what, was hit ("PED STRUCK 4TH/MARKET":
    a report's passive without its auxiliary)."""
    if not after:
        return True  # ("... and it crashed", "they collided")
    for k, w in enumerate(after):
        nxt = after[k + 1] if k + 1 < len(after) else ""
        if _number(w) is not None and (nxt.startswith("year") or nxt in _ORDINALS):
            return True
        if w in _NOT_ROAD_USERS or _number(w) is not None:
            return False
        if w in ("in", "to", "at") and _CONTROLS_PRESSED & set(after[k + 1 : k + 4]):
            return False  # ("hit to the brakes", "hit in the brake pedal": said with a preposition, as in translation)
        if w in ("the", "a", "an", "on", "off", "down", "over", "into", "with") or w in _POSSESSIVES:
            continue
        return True
    return True


#: What a walker pushes or a vehicle tows (:data:`who.TOWED`), met as its road user is ("hit the pram",
#: "the caravan").
_PUSHED = TOWED | frozenset(("pram", "buggy", "pushchair", "stroller", "trolley", "cart", "wheelbarrow"))


def names_a_thing(phrase: list[str], named: frozenset[str] = frozenset()) -> bool:
    """Whether the noun phrase opening ``phrase`` (its determiners already passed) has a head that
    English knows only as a noun of a thing: no road user, no part of a vehicle or a body, no street
    furniture, nothing pushed or towed ("the pram", "the caravan") ("the sirens off", "my rating lol",
    "the radio"). A verb of contact with such an object ("knocked the sirens off", "hit the indicator")
    handles a control or a possession, not another road user. A word English does not know (a model's
    name: "the Qashqai") is no such noun, nor is one of ``named``, the words the reader named the
    story's road users by ("a Golf pulled out ... I hit the Golf")."""
    head = None
    for w in phrase:
        found = _pos(w)
        if w in ("'s", "s"):
            head = None  # ("my client's vehicle": the possessor's noun is no head; what it has follows)
            continue
        if ("NOUN" not in found and "ADJ" not in found) or w in CLAUSE_BREAKS or w in PHRASE_ENDS:
            break
        if w in named or w in _PUSHED or _road_user_word(w) or w in _PERSON_OBJECTS:
            return False  # ("I hit the Golf" after "a Golf pulled out": one of the story's road users)
        if w in _MET_NOUNS or w.rstrip("s") in _MET_NOUNS:
            return False
        if lies_on_roads(w):
            return False  # ("struck the debris": an obstacle on the road, met)
        if w in _unprotected_heads() or w in _EGO_HEADS or w in _EGO_NOUN_HEADS or w.endswith(("body", "one")):
            return False  # ("hits ego", "nobody hits anybody": the ego, a person)
        head = w if "NOUN" in found else head
    else:
        return False  # (the phrase runs on past what was given: its head is not seen)
    return head is not None


def _destination(words: list[str], i: int) -> bool:
    """Whether the noun of contact at ``i`` is the object of "to" (its article between) after a noun
    or a number, no verb: where a call or a journey goes ("Cat 2 to an RTC", "on the way to a
    crash", "a call to an accident"), another scene than the one told. After a verb it may be a
    consequence ("led to a collision") and is read as before."""
    k = i - 1
    if k < 2 or words[k] not in _DETERMINERS or words[k - 1] != "to":
        return False
    before = words[k - 2]
    return not _is_verb(before) and ("NOUN" in _pos(before) or _number(before) is not None)


def _modifies_a_noun(nxt: str) -> bool:
    """Whether a contact noun before ``nxt`` is the first noun of a compound ("response" in "RTC
    response", "statistics", "investigation"): ``nxt`` is only ever a noun, and not a road user's, so
    the compound names a job, a record or a kind of thing, not a contact that happened ("a crash
    yesterday", "a collision happened", "collision cyclist vs car" stay contacts)."""
    found = _pos(nxt)
    return set(found) == {"NOUN"} and not _road_user_word(nxt) and nxt not in _PERSON_OBJECTS


def _plural_of_contact(words: list[str], i: int) -> bool:
    """Whether an "-es" plural of a contact noun ("crashes", "smashes") is a noun here, a count or a
    determiner before it ("3 crashes"), not a verb after its subject ("the van crashes")."""
    return words[i].endswith("es") and words[i][:-2] in _CONTACT_NOUNS and _plural_noun(words, i)


def _is_contact(words: list[str], i: int, named: frozenset[str] = frozenset()) -> bool:
    """Whether the word at ``i`` states a contact between road users (``named``: the words the
    story's road users were named by, see :func:`names_a_thing`)."""
    w = words[i]
    nxt = words[i + 1] if i + 1 < len(words) else ""
    prev = words[i - 1] if i > 0 else ""
    if _contact_noun(w) or _plural_of_contact(words, i):
        if w not in _CONTACT_NOUNS and _counted(words, i):
            return False  # ("47 reported collisions involving e-scooters last year": a statistic)
        if nxt in _COMPOUND_HEADS or prev in ("time-to", "eye") or w.startswith("time-to"):
            return False
        if _modifies_a_noun(nxt):
            return False  # ("an RTC response", "the crash investigation unit": a kind of job, not the event)
        if prev == "to" and i > 1 and words[i - 2] == "time":
            return False
        if prev in ("near", "near-"):
            return False  # ("a near collision": a near miss, read by _is_near)
        if _destination(words, i):
            return False  # ("Cat 2 to an RTC", "on our way to a crash": a call to another scene)
        if w in ("crash", "crashes") and nxt in ("into", "through"):
            return True
        return not (w == "contact" and prev in ("eye",))
    if w == "against" and _driven_against_a_part(words, i):
        return True  # ("slapped against his bumper", "impacted with its front against the rear of my car")
    if w == "across" and not _lemmas(prev) & _SLIDING:
        pass  # ("cut across my bonnet", "darted across the front of the bus": a path in front, not a contact)
    elif w in ("onto", "off", "over", "across") and _is_verb(prev) and prev not in _LENGTH_UNITS | _SMALL_UNITS:
        rest = words[i + 1 : i + 4]
        if rest[:1] and rest[0] in _POSSESSIVES | {"the"} and set(rest[1:]) & _STRUCK_PARTS:
            return True  # ("bounced off my bonnet", "rolled over the windscreen")
    if w == "onto" and _driven_onto_a_part(words, i):
        return True  # ("slid up onto the back of it", "ran onto the rear of car 2")
    if w == "on" and i > 0 and (_lemmas(prev) & {"land"} or words[i - 2 : i] in (["ended", "up"], ["ends", "up"])):
        rest = words[i + 1 : i + 4]
        if rest[:1] and rest[0] in _POSSESSIVES | {"the"} and set(rest[1:]) & _STRUCK_PARTS:
            return True  # ("landed on my bonnet", "ended up on the windscreen")
    if w in _THROWN_RESULTS and i > 1 and any(_lemmas(x) & {"send", "knock"} for x in words[max(0, i - 5) : i - 1]):
        k = next(k for k in range(max(0, i - 5), i) if _lemmas(words[k]) & {"send", "knock"})
        return names_road_user(words[k + 1 : i])  # ("sent the jogger flying", "knocked him sprawling")
    if w == _INTO and all(x in _ONSET for x in words[:i]) and _into_road_user(words, i):
        return True  # (a clause of its own: ", straight into my door", "Right into the back of the van.")
    if w == "under" and _came_out_under_the_front(words, i):
        return False  # ("pulled out right under my bonnet": where it came, just in front of the ego)
    path = i == 0 or _verb_before_path(words, i) or all(x in _ONSET for x in words[:i])
    if w == "under" and (path or (prev == "right" and not set(words[i + 1 : i + 3]) & _FRONT_SEEN)):
        obj = words[i + 1 : i + 6]  # (met wherever it came from: "from between the cars right under the wheels")
        if obj[:1] and (obj[0] in _POSSESSIVES or obj[0] in ("the", "a")) and _under_road_user(obj[1:]):
            return True  # ("went under the nearside front", "and under the wheels of the lorry")
    if w in ("versus", "vs") and 0 < i < len(words) - 1:
        side = words[i + 1 : i + 4]
        # ("car versus e-scooter": a report's name for a collision between the two; not "lane change
        # versus braking", two ways of escaping)
        return names_road_user(side) or side[0] in _EGO_HEADS or _road_user_word(prev) or prev in _EGO_HEADS
    if (
        w in _IMPACT_SOUNDS
        and prev not in ("speed", "road")
        and (prev in ("a", "an", "the") or words[i - 2 : i - 1] == ["a"])
    ):
        return True
    if knock_felt(words, i) and _knock_on_a_road_user(words, i):
        return True  # ("felt the tap", "heard a soft clunk from the bumper")
    lem = _lemmas(w)
    if "wipe" in lem and "out" in words[i + 1 : i + 4]:
        k = words.index("out", i + 1)  # ("wiped out the cyclist", "wiped him out"; "wiped out on the ice": fell)
        return names_road_user(words[i + 1 : k] or words[k + 1 : k + 4])
    if lem & _PHRASAL_CONTACT and _is_verb(w) and _phrasal_object(words, i) and not _party_outing(words, i):
        return True  # ("took out a jogger", "knocked the child over")
    if lem & _TOUCHING and _is_verb(w) and (_vehicle_part(words[i + 1 : i + 6]) or _part_said_before(words, i)):
        return True  # ("caught my front bumper", "nicked the wing mirror of the taxi", "his mirror took mine off")
    if lem & _TOUCHING and _is_verb(w) and _touched_with_a_part(words, i):
        return True  # ("caught it with my knee", "nicked me with its trailer")
    if prev in _COMPOUND_FIRST and _COMPOUND_FIRST[prev] in _lemmas(w) and _compound_verb(words, i):
        return _meets_road_user(_object_of(words, i))  # ("rear ended me", "got T boned by a van")
    if w == "bender" and prev == "fender":
        return True  # ("a fender bender")
    if lem & _STRIKING and _is_verb(w) and _struck_object(words[i + 1 : i + 6]):
        return True  # ("an auto dashed my car", "the okada jammed the taxi", "a bus banged my door")
    if w in _SLANG_CONTACT and (_vehicle_part(words[i + 1 : i + 6]) or names_road_user(words[i + 1 : i + 4])):
        return True  # ("dinged the van's door", "biffed my bumper")
    if lem & {"run"} and _is_verb(w) and _run_over(words, i):
        return True  # ("ran over a jogger", "ran him over"; not "ran down the hill")
    if lem & {"knock", "mow"} and nxt in ("over", "down"):
        return _meets_road_user(words[i + 2 : i + 5])
    if lem & {"make", "come"} and nxt == "contact":
        return True
    if lem & {"come"} and nxt == "together" and _is_verb(w):
        return True  # ("the taxi and the moped came together": two road users meeting, a collision)
    if (
        lem & {"meet"}
        and _is_verb(w)
        and ("head-on" in words[i + 1 : i + 6] or "head on" in " ".join(words[i + 1 : i + 7]))
    ):
        return True  # ("met the tractor head-on", "they met head on")
    if _injury_adjective(words, i) or _knocked_about(words, i):
        return False  # ("grazed knees and a cut elbow": an injury's adjective before a bare body part)
    if lem & _CONTACT_VERBS and words == [w] and w.endswith("s"):
        return False  # ("Tags: #cyclist": a plural noun as a label, no subject and no object)
    if lem & _CONTACT_VERBS and _is_verb(w) and _verbal(words, i):
        if w.startswith("crash") and nxt in _COMPOUND_HEADS:
            return False
        if "tag" in lem and _tags_a_record(words, i):
            return False  # ("Safe, tag it.", "tagging as a safe pass": the event labelled, no one met)
        if "bump" in lem and prev in ("speed", "road"):
            return False  # ("put in speed bumps", "over the road bumps": the road's traffic calming)
        if _thing_subject(words, i) and not names_road_user(_object_of(words, i)):
            return False  # ("the booking website crashed", "my phone app crashed twice")
        if _own_one(words, i):
            return False  # ("you braked late, I had to touch mine": the ego's own pedal, no one met)
        if marking_met(words, i):
            return False  # ("its wheel touched the white line": paint on the road, no one met)
        obj = words[i + 1 : i + 7] + [""] * (len(words) <= i + 7)  # (its clause's end closes the phrase)
        if obj[:1] and (obj[0] in _DETERMINERS or obj[0] in _POSSESSIVES) and names_a_thing(obj[1:], named):
            return False  # ("knocked the sirens off", "is this going to hit my rating")
        return _meets_road_user(_object_of(words, i))
    if lem & _SHOVING and _is_verb(w) and _shoved_into_a_road_user(words, i):
        return True  # ("a van behind pushed us into the car ahead", "I was pushed onto the van")
    if _is_verb(w) and not lem & {"turn", "look", "get", "change", "switch", "fall", "slow"}:
        j = i + 1
        if w in _DIRECTIONS and i > 0 and _is_verb(words[i - 1]):
            return False  # ("turned left into it": a direction after its verb, not "left" the verb)
        while j < len(words) and (words[j].endswith("ly") or words[j] in ("straight", "head-on", "back", *_DIRECTIONS)):
            j += 1  # ("went straight into the side of it")
        if j < len(words) and words[j] == _INTO and not w.endswith("ing") and not _begun(words, i):
            if words[i + 1] in _DIRECTIONS and words[j + 1 : j + 2] == ["it"]:
                return False  # ("swung left into it": a turn into a place)
            return _into_road_user(words, j)  # (not "starts merging into me": a motion under way)
        if lem & {"throw", "fling", "launch", "toss"} and j < len(words) and words[j] in ("onto", "over"):
            return True  # ("was thrown onto the bonnet": it was hit)
    return False


#: Light and what shines it: what it "hits" ("low sun hit in the windscreen", "headlights hit in my mirror") it
#: dazzles, no one met.
_LIGHT = frozenset(
    ("sun", "sunlight", "sunshine", "light", "lights", "headlight", "headlights", "glare", "beam", "beams",
     "reflection", "rays", "dazzle", "lamps", "lamp")
)  # fmt: skip
#: Verbs of moving someone by a blow ("pushed us into the car ahead", "was shoved onto the van"): no contact
#: verb themselves (people push prams and bikes), one where what is moved meets a road user.
_SHOVING = frozenset(("push", "shove", "propel", "thrust"))
#: Vehicles said as the one shoved ("shoved my car into the back of the bus"); not what people push by hand.
_SHOVED_VEHICLES = frozenset(("car", "van", "vehicle", "lorry", "truck", "bus", "taxi", "cab", "ego", "motor"))


def _shoved_into_a_road_user(words: list[str], i: int) -> bool:
    """Whether the verb of shoving at ``i`` moves someone into or onto a road user or a part of one ("pushed
    us into the car ahead", "I was pushed onto the transporter", "shoved my car into the back of the bus"):
    the one shoved meets it. The one shoved is the subject of a passive ("was pushed onto"), or a person or
    a vehicle as the object ("pushed us", "shoved my car"), not what people push ("pushed her pram", "his
    bike") nor their own way ("pushed her way onto the bus"); with neither ("passengers pushed onto the
    tram") people board. Not into a place ("into the road"), street furniture ("into the kerb"), nor a
    place named after a vehicle ("onto the tram tracks")."""
    passive = i > 0 and words[i - 1] in ("was", "were", "got", "been", "be", "get", "gets", "being")
    for j in range(i + 1, min(i + 5, len(words))):
        if words[j] in PHRASE_ENDS:
            return False
        if words[j] in (_INTO, "onto"):
            shoved = words[i + 1 : j]
            person = len(shoved) == 1 and shoved[0] in _PERSON_OBJECTS
            ridden = shoved and (shoved[-1] in _PUSHED or shoved[-1] in ("bike", "bicycle", "scooter", "e-scooter"))
            rider = shoved and _road_user_word(shoved[-1]) and not ridden  # ("pushed the cyclist into the car")
            if not (passive or person or rider or (shoved and shoved[-1] in _SHOVED_VEHICLES)):
                return False
            obj = [x for x in words[j + 1 : j + 6] if x not in _DETERMINERS and x not in _POSSESSIVES]
            head = obj[0] if obj else ""
            named_after = len(obj) > 1 and _road_user_word(head) and "NOUN" in _pos(obj[1]) and obj[1] != "ahead"
            return head not in _FURNITURE and not named_after and _into_road_user(words, j)
    return False


#: What a label is given to: the event or the clip under review ("tag it", "tag this one").
_THE_RECORD = frozenset(("it", "this", "that", "them", "these", "those"))


def _tags_a_record(words: list[str], i: int) -> bool:
    """Whether "tag" at ``i`` labels a record (a meeting's or a triage's "tag it as a near miss",
    "tagging as safe", "Safe, tag it."), not a knock ("the van tagged it", "tagged my bumper"): "as"
    follows it or its pronoun, or it opens its clause as a command on a bare "it"/"this"."""
    after = words[i + 1 : i + 4]
    label_at = 1 if after[:1] == ["as"] else 2 if after[:1] and after[0] in _THE_RECORD and after[1:2] == ["as"] else 0
    if label_at:  # ("tag it as a near miss"; not "tagged it as it went by", a clause of time)
        return not set(after[label_at : label_at + 1]) & (SUBJECT_PRONOUNS | {"it", "the"})
    opens = i == 0 or words[i - 1] in _BREAK_PUNCT or words[i - 1] in ("so", "then", "just", "please", "and")
    ends = len(words) <= i + 2 or words[i + 2] in _BREAK_PUNCT or words[i + 2] in ("one", "and", "then")
    return opens and words[i] == "tag" and after[:1] != [] and after[0] in _THE_RECORD and ends


#: Verbs of a body or a thing at rest against another ("leaned against my door", "stacked against
#: the side of the lorry"): no blow. Verbs of getting on ("jumped against the door") are no blow either.
_RESTING = frozenset(
    ("lean", "rest", "press", "prop", "park", "stand", "sit", "brace", "hold", "push", "stack", "load", "jump", "hop",
     "climb", "step", "leap", "get", "lift", "put", "tie", "strap")
)  # fmt: skip
#: Small words that stand between a verb of motion and "against" ("impacted with its front against",
#: "went straight against").
_TO_THE_GOAL = frozenset(("up", "straight", "right", "head-on", "with", "its", "his", "her", "their", "my", "front",
                          "nose", "end", "side", "back", "rear", "full", "square", "squarely", "hard"))  # fmt: skip


def _driven_against_a_part(words: list[str], i: int) -> bool:
    """Whether "against" at ``i`` ends a motion into a part of a road user: a verb of motion or
    impact before it (past an adverb or the mover's own part: "impacted with its front against") and
    a vehicle's part as its object that belongs to someone ("against his bumper", "against the
    lateral right rear of my car"). A part is met, not a place moved into: "rode against the
    traffic" and "ran against the red" name no part; "leaned against my door" is at rest, not a blow.
    ("onto the back of" is not read so: coming up onto the back of a slower vehicle is catching it
    up.)"""
    k = i - 1
    while k >= 0 and i - k <= 4 and words[k] in _TO_THE_GOAL:
        k -= 1
    if k < 0 or not _is_verb(words[k]) or _lemmas(words[k]) & _RESTING or words[k] in _BETWEEN:
        return False
    obj = words[i + 1 : i + 8]
    if not obj or obj[0] not in _POSSESSIVES | {"the", "a", "an"}:
        return False
    return (obj[0] in _POSSESSIVES or _of_a_road_user(obj)) and _vehicle_part(obj)


def _driven_onto_a_part(words: list[str], i: int) -> bool:
    """Whether "onto" at ``i`` carries a vehicle driven by a verb of motion (a particle "up" between)
    onto a part of a road user named after "of" ("drove up onto the rear of car 2", "slid onto the
    back of it"): a shunt, told as where it ended. Not a verb of getting on or loading ("climbed onto
    the back of the truck"), of coming up behind ("came up onto the back of a tractor": caught up), a
    place ("pulled onto the shoulder of the road", "onto the back of the queue"), nor a side without
    its owner ("cut the corner onto our side": the road's)."""
    k = i - 2 if words[i - 1 : i] == ["up"] else i - 1
    if k < 0 or not _is_verb(words[k]) or _lemmas(words[k]) & (_RESTING | {"come"}):
        return False
    part = next((n for n in range(i + 1, min(i + 4, len(words))) if words[n] in _PARTS), None)
    if part is None or words[part + 1 : part + 2] != ["of"]:
        return False
    owner = words[part + 2 : part + 5]
    return bool(owner) and (owner[0] in _PERSON_OBJECTS | _EGO_HEADS or names_road_user(owner))


def _of_a_road_user(obj: list[str]) -> bool:
    """Whether a part's noun phrase ``obj`` goes on with "of" and a road user or the ego ("the rear of
    vehicle 2", "the side of my car", "the back of the bus"), not a place or a line ("the back of the
    queue", "the side of the road")."""
    if "of" not in obj[1:5]:
        return False
    owner = [w for w in obj[obj.index("of", 1) + 1 :][:3] if w not in _DETERMINERS]
    return bool(owner) and (owner[0] in _EGO_HEADS or owner[0] in _POSSESSIVES or names_road_user(owner))


#: Verbs of contact compounded of a noun and a verb, by their first word, when written as two words
#: ("rear ended", "T boned"); the closed class of English's compound verbs of a collision.
_COMPOUND_FIRST = {"rear": "end", "t": "bone", "side": "swipe"}


def _compound_verb(words: list[str], i: int) -> bool:
    """Whether the second word of a two-word compound at ``i`` is a verb: inflected ("rear ended",
    "T boned") or before its object ("rear end the bus"); "the rear end of the van" and "the rear ends
    of the cars" are nouns."""
    nxt = words[i + 1] if i + 1 < len(words) else ""
    if words[i].endswith("ed"):
        return True
    return nxt in _PERSON_OBJECTS | _DETERMINERS | _POSSESSIVES and (i < 2 or words[i - 2] not in _DETERMINERS)


#: Words before a verb that make a noun-verb homograph a verb ("I hit", "to strike", "did not tap").
_VERBAL_BEFORE = frozenset(("i", "we", "you", "he", "she", "it", "they", "to", "not", "will", "would", "could", "did",
                            "does", "do", "ego", "then", "and", "just", "might", "may", "must", "can", "should",
                            "is", "was", "were", "be", "been", "being", "got", "get", "gets", "are"))  # fmt: skip


#: Adverbs that open a clause with no verb of its own ("and straight into the side of it").
_ONSET = frozenset(("straight", "right", "smack", "slap", "bang", "slam", "head-first", "headfirst", "directly", "and",
                    "then", "just", "full", "square", "squarely"))  # fmt: skip
#: Verbs of a body carried over a surface: across a vehicle's part with one of these is a contact.
_SLIDING = frozenset(("slide", "roll", "bounce", "fly", "tumble", "skid", "sprawl", "throw", "fling", "scrape"))
_DETERMINERS = frozenset(("the", "a", "an", "this", "that", "some"))


def _verb_before_path(words: list[str], i: int) -> bool:
    """Whether a verb heads the path that the preposition at ``i`` opens, right before it or past the
    adverbs of degree that lead a path and a particle of the verb ("went under", "went right under the
    lorry", "slid straight under", "ran out right under the wheels"). "right" after a noun is the
    degree of a place, no verb ("out onto the roundabout right under the bonnet": where it came, in
    front of the ego, not under it; the caller takes a part other than the ego's front there as met:
    "from between the cars right under the wheels")."""
    k = i - 1
    while k > 0 and words[k] in _ONSET and words[k] != "and":
        k -= 1
    if k > 0 and words[k] in _PARTICLES | _OFF_AND_BACK:
        k -= 1  # ("ran out right under", "fell off right under": the particle of the verb)
    return k >= 0 and _is_verb(words[k]) and (k == i - 1 or words[k] not in _ONSET)


#: The particles of a verb of motion besides :data:`_PARTICLES` ("fell off", "stepped back").
_OFF_AND_BACK = frozenset(("off", "back"))
#: The ego's front as seen from its seat: what comes out "right under my bonnet" is just in front of it.
_FRONT_SEEN = frozenset(("bonnet", "hood", "nose"))


def _came_out_under_the_front(words: list[str], i: int) -> bool:
    """Whether "under" at ``i`` is "right under my bonnet" (or the nose or the hood) after a coming out
    in its clause ("pulled out right under my bonnet", "came out of the side road right under my
    bonnet", "came out right under my nose"): where the other came, just in front of the ego, not under
    it: a near miss, not a contact."""
    obj = words[i + 1 : i + 3]
    return (
        words[i] == "under"
        and words[i - 1 : i] == ["right"]
        and len(obj) == 2
        and (obj[0] in _POSSESSIVES or obj[0] == "the")
        and obj[1] in _FRONT_SEEN
        and "out" in words[: i - 1]
    )


def _knock_on_a_road_user(words: list[str], i: int) -> bool:
    """Whether the light knock at ``i`` (one :func:`knock_felt` accepts) is located on or from a
    vehicle's part or a road user ("a small knock on the front", "a soft clunk from the bumper", "the
    nudge on my door") or nowhere ("felt the tap"); not one on a body part, a window or a thing ("a tap
    on my shoulder", "a knock on the window", "a clunk from the engine", "a knock from the boot": a
    load, where "boot" is no body part's wear)."""
    after = words[i + 1 : i + 7]
    if not after or after[0] not in LOCATING:
        return True
    obj = after[1:]
    if set(obj[:3]) & _BODY_PARTS:
        return False
    return _vehicle_part(obj) or names_road_user(obj[:4]) or obj[:1] in ([x] for x in _PERSON_OBJECTS)


def _under_road_user(obj: list[str]) -> bool:
    """Whether the noun phrase after "under the" is a vehicle's part or a road user ("the nearside
    front", "the wheels of the bus"), not a place ("the railway bridge")."""
    for w in obj:
        if w in PHRASE_ENDS:
            return False
        if w in _VEHICLE_PARTS or w.rstrip("s") in _VEHICLE_PARTS or _road_user_word(w):
            return True
    return False


def _thing_subject(words: list[str], i: int) -> bool:
    """Whether the verb at ``i`` has as subject a noun phrase opened by a determiner that names no road
    user ("the booking website", "my phone app"): software or a market crashes, not a road user."""
    for k in range(i - 1, max(-1, i - 5), -1):
        if words[k] in _DETERMINERS or words[k] in _POSSESSIVES:
            phrase = words[k + 1 : i]  # (a road user's part is the road user: "his handlebar scraped the door")
            if phrase and all(_number(x) is not None or x == "both" for x in phrase):
                return False  # ("the two collided": a count of the road users named before)
            return bool(phrase) and not any(
                _road_user_word(x) or x in _EGO_HEADS or x in _PERSON_OBJECTS or x.rstrip("s") in _VEHICLE_PARTS
                for x in phrase
            )
        if words[k] in CLAUSE_BREAKS or words[k] in PHRASE_ENDS or words[k] in _VERBAL_BEFORE:
            return False
    phrase = words[max(0, i - 4) : i]  # (a bare noun opening its clause: "app crashed twice")
    return 0 < i <= 2 and all(
        not (_road_user_word(x) or x in _EGO_HEADS | _PERSON_OBJECTS | _NEGATORS | {"both"})
        and not (_number(x) is not None or any(c.isdigit() for c in x))
        and not x.endswith(("body", "one"))  # ("nobody hits anybody", "someone crashed")
        and "VERB" not in _pos(x)
        and "ADV" not in _pos(x)
        for x in phrase
    )


#: Adverbs of degree that stand between an auxiliary and its verb ("was very nearly hit").
_INTENSIFIERS = frozenset(("very", "so", "too", "just", "only", "really"))


#: Determiners that open a plural noun phrase ("the clips", "these hits").
_PLURAL_DETERMINERS = frozenset(("the", "these", "those", "some", "many", "several", "more", "fewer", "few"))
#: Of those, the ones no singular noun follows: with modifiers between, the head is still their plural.
_ONLY_PLURAL = frozenset(("these", "those", "many", "several", "more", "fewer", "few"))


def _plural_noun(words: list[str], i: int) -> bool:
    """Whether the -s form at ``i`` is a plural noun: a determiner or a number right before it ("the
    clips I sent", "47 crashes"); a verb's -s form follows its subject ("the van clips her"), and so
    may a speed ("a van at 20 hits the ego": a number after "at" or "doing" counts nothing)."""
    w = words[i]
    if not w.endswith("s") or "NOUN" not in _pos(w) or i == 0:
        return False
    if _number(words[i - 1]) is not None:
        return i < 2 or words[i - 2] not in _SPEED_BEFORE
    if words[i - 1] in _PLURAL_DETERMINERS:
        return True
    # ("follow for more London cabbie clips", "these dashcam crashes": a determiner only a plural takes, its
    # noun's modifiers between, none of them a verb)
    for k in range(i - 2, max(i - 4, -1), -1):
        if words[k] in _ONLY_PLURAL:
            return not any(_is_verb(x) and "NOUN" not in _pos(x) for x in words[k + 1 : i])
        if words[k] in PHRASE_ENDS:
            break
    return False


#: Words before a number that make it a speed, not a count ("at 20", "doing 30"; "about 40 crashes" is one).
_SPEED_BEFORE = frozenset(("at", "doing"))


#: Words that say a count of events is a record kept ("47 reported collisions", "per year", "involving").
_RECORDED = frozenset(("reported", "recorded", "per", "year", "years", "annually", "involving", "involved", "since",
                       "figures", "statistics", "stats"))  # fmt: skip


def _past_verb(w: str) -> bool:
    """Whether ``w`` is a verb's past form ("piled", "followed", "ran"), not its base, -s or -ing form."""
    return _is_verb(w) and w not in _pos(w)["VERB"] and not w.endswith(("s", "ing")) and w not in _AUXILIARIES


def _counted(words: list[str], i: int) -> bool:
    """Whether the plural noun of contact at ``i`` is counted by a number of two or more, its
    modifiers between ("47 reported collisions", "two recorded slight injury crashes"): a figure of
    many events, a statistic, not this scene's outcome. Said with a past verb after it and no word of a
    record ("there were 3 crashes as the cars behind piled in", "4 collisions followed") they are
    counted as they happen in the scene told."""
    for k in range(i - 1, max(-1, i - 5), -1):
        value = _number(words[k])
        if value is not None:
            return value >= 2.0 and (bool(set(words) & _RECORDED) or not any(map(_past_verb, words[i + 1 :])))
        if words[k] in PHRASE_ENDS or words[k] in CLAUSE_BREAKS or words[k] in _NEGATORS:
            return False
    return False


def _verbal(words: list[str], i: int) -> bool:
    """Whether a word that can be a noun ("hit", "strike", "tag") is a verb here: inflected, after a
    subject pronoun, a modal or "to", or before its object; "the rail strike" and "a hit" are nouns."""
    w = words[i]
    if _plural_noun(words, i):
        return False  # ("watch the clips", "two clips a day": a plural noun, not "the van clips")
    if "NOUN" not in _pos(w) or w not in _pos(w).get("VERB", ()):
        return True  # (no noun, or inflected: "struck", "tagged", "hits")
    k = i - 1
    while k > 0 and (words[k] in HEDGES | _INTENSIFIERS or (words[k].endswith("ly") and "ADV" in _pos(words[k]))):
        k -= 1  # ("was nearly hit", "had only narrowly struck": the word before its adverbs)
    prev = words[k] if k >= 0 else ""
    nxt = words[i + 1] if i + 1 < len(words) else ""
    if prev in ("a", "an", "the", "this", "that") or prev in _POSSESSIVES:
        return False
    if prev in _NEGATORS:
        return True  # ("no hit": denied, as a noun or a verb alike)
    if set(words[max(0, k) : i]) & HEDGES:
        return True  # ("only almost hit!": a hedge of degree modifies a verb, never a noun)
    if _vehicle_part(["the", *words[i + 1 : i + 4]]) or _road_user_word(nxt):
        return True  # ("scooter hit rear wheel", "van hit cyclist": a report's object without its article)
    if nxt == "ego":
        return True  # ("a taxi hit my car", read as "hit ego": the ego's vehicle is the object)
    if nxt in ("on", "against") and _vehicle_part(words[i + 2 : i + 6]):
        return True  # ("hit on my front door", "struck against the rear bumper": a blow where it landed)
    if nxt in ("in", "to", "at") and _vehicle_part(words[i + 2 : i + 6]) and not _LIGHT & set(words[max(0, i - 5) : i]):
        return True  # ("hit in the right side of my car", "hit at my front bumper"; not light that "hit in my mirror")
    return prev in _VERBAL_BEFORE or nxt in {"the", "a", "an", "into", "with", "by"} | _POSSESSIVES | _PERSON_OBJECTS


def into_road_user(words: list[str], j: int) -> bool:
    """Whether "into" at ``j`` has a road user or thing met as object (see :func:`_into_road_user`):
    a verb the reader lacks + such "into" ("banged into my car", "ploughed into us") is a collision,
    not a move into a place."""
    return _into_road_user(words, j)


#: The parts of a vehicle that no road or place has ("door", "bumper", a lorry's "trailer"; not "side",
#: "back", "front" or "boot", which a road, a queue or a load has too): met, whoever's they are.
_FITTED_PARTS = frozenset(
    ("door", "bumper", "wing", "bonnet", "windscreen", "windshield", "tailgate", "fender", "trailer")
)


def _into_road_user(words: list[str], j: int) -> bool:
    """Whether "into" at ``j`` has a thing met as object ("into the side of it", "into him", "into the
    back of the van", "into the pallets"), not a place ("into my lane", "into the side road")."""
    obj = words[j + 1 : j + 7]
    if not obj:
        return False
    if obj[0] in _PERSON_OBJECTS:
        return True
    if obj[0] in _EGO_HEADS:
        return not (obj[1:2] and obj[1] in _PLACES)  # ("into my car" read as "into ego"; not "into ego lane")
    chunk: list[str] = []
    for w in obj:
        if w in PHRASE_ENDS:
            break
        chunk.append(w)
    if not chunk or (set(chunk) & _PLACES and not _owned_part(chunk, words[j + 1 + len(chunk) :])):
        return False  # ("into the right lane", "into our path")
    if _no_thing_met(chunk):
        return False  # ("into the crosswalk", "gone into the dark", "tucked into the sun visor")
    if set(chunk) & L.HOLLOWS:
        return False  # ("front wheel into a pothole": a hollow of the road ridden into, nothing met)
    if chunk[-1] in _FITTED_PARTS:
        return True  # ("went into the rear passenger door": a part only a vehicle has, its owner unsaid)
    if set(chunk) & _PARTS:
        return "of" in obj or chunk[0] in _POSSESSIVES  # ("into the side of it", "into his back")
    nouns = [w for w in chunk if "NOUN" in _pos(w) and _number(w) is None]
    return bool(nouns) and chunk[0] in {"the", "a", "an", "some"} | _POSSESSIVES


def _owned_part(chunk: list[str], rest: list[str]) -> bool:
    """Whether the noun phrase ``chunk`` after "into" ends in a word that names a vehicle's part as well
    as a place ("corner") and a road user owns it: a possessive opens it ("into my rear corner"; not
    "into my corner of the junction", the writer's share of a place) or an "of" after it names one by
    its head ("into the front left corner of the car"; not "the corner of the car park", whose head is
    a place)."""
    if chunk[-1] not in _VEHICLE_PARTS or set(chunk[:-1]) & _PLACES:
        return False
    owner = [w for w in rest[1:5] if w not in _DETERMINERS and w not in _POSSESSIVES]
    head = next((k for k, w in enumerate(owner) if w in PHRASE_ENDS or w in CLAUSE_BREAKS), len(owner))
    if chunk[0] in _POSSESSIVES:  # (not the writer's share of a place: "into my corner of the junction")
        return not (rest[:1] == ["of"] and head > 0 and owner[head - 1] in _PLACES | _ENTERED)
    if rest[:1] != ["of"]:
        return False
    return head > 0 and (_road_user_word(owner[head - 1]) or owner[head - 1] in _EGO_HEADS)


#: The places of a road and beside it one rides or walks into, over the ones of :data:`_PLACES`
#: ("rode into the crosswalk", "pulled into the forecourt").
_ENTERED = frozenset(
    ("crosswalk", "crosswalks", "zebra", "pelican", "puffin", "toucan", "cycleway", "bikeway", "busway", "ramp",
     "slip", "sliproad", "slip-road", "forecourt", "yard", "gateway", "gate", "field", "alley", "alleyway", "tunnel",
     "underpass", "median", "island", "refuge", "layby", "box", "filter", "bus-stop", "garage", "estate")
)  # fmt: skip
#: Light, dark and weather one goes into: nothing is met ("gone into the dark", "rode off into the rain").
_LIGHT_AND_DARK = frozenset(
    ("dark", "darkness", "night", "distance", "fog", "mist", "murk", "gloom", "shadow", "shadows", "shade", "sun",
     "sunlight", "sunshine", "glare", "sunset", "sunrise", "dusk", "rain", "snow", "spray", "haze", "smoke",
     "headlights", "beam", "beams", "wind", "storm", "downpour")
)  # fmt: skip
#: The vehicle's own controls and fittings things are put into ("tucked into the sun visor", "into the glovebox").
_CONTROLS = frozenset(
    ("visor", "dashboard", "dash", "glovebox", "glove", "footwell", "seat", "seats", "ignition", "gear", "gears",
     "gearbox", "reverse", "neutral", "cupholder", "holder", "console", "pocket", "cradle", "socket", "slot")
)  # fmt: skip


def _no_thing_met(chunk: list[str]) -> bool:
    """Whether the noun phrase ``chunk`` after "into" names a place, light or dark, or the vehicle's
    own fittings, with no road user or part of one after that word ("into the crosswalk against the
    light", "into the night"; not "into the dark blue van", where "dark" only modifies the van)."""
    k = next((k for k, w in enumerate(chunk) if w in _ENTERED | _LIGHT_AND_DARK | _CONTROLS), None)
    return k is not None and not any(_road_user_word(w) or w in _PARTS for w in chunk[k + 1 :])


#: Directions said after a verb of motion; "left" is also the past of "leave".
_DIRECTIONS = ("left", "right")
#: Verbs that with a particle (out, over, down) and a road user as object are a contact ("took out a
#: jogger", "knocked the child over"); with any other object they are not ("took out his phone").
_PHRASAL_CONTACT = frozenset(("take", "knock", "mow", "bowl"))
_PARTICLES = frozenset(("out", "over", "down"))
#: What a road user sent or knocked by a blow does ("sent him flying", "knocked the rider sprawling").
_THROWN_RESULTS = frozenset(("flying", "sprawling", "spinning", "tumbling"))
#: Verbs of touching that are a contact only when their object is a part of a vehicle ("caught my
#: bumper"; not "caught sight of", "caught up with").
_TOUCHING = frozenset(
    ("catch", "nick", "kiss", "brush", "touch", "clip", "scratch", "dent", "take", "nudge", "contact", "impact")
)
#: The parts of a vehicle (and of a bicycle) that a contact is said to touch.
_VEHICLE_PARTS = _STRUCK_PARTS | _PARTS | frozenset(
    ("wheel", "pedal", "handlebar", "handlebars", "arch", "panel", "quarter", "corner", "headlight", "taillight",
     "indicator", "tailgate", "sill", "fender", "basket")
)  # fmt: skip


def vehicle_part_word(word: str) -> bool:
    """Whether ``word`` names a part of a vehicle ("door", "mirror", "bumper")."""
    return word in _VEHICLE_PARTS


#: Verbs of a motion only begun ("started drifting into me"): what it would have met, it did not yet.
_BEGIN = frozenset(("start", "begin", "try", "attempt"))


@lru_cache(maxsize=1)
def _road_user_heads() -> frozenset[str]:
    """The last words of the lexicon's road-user nouns ("jogger", "rider", "cyclist", "bloke")."""
    phrases = [p for ps in L.ACTOR_NOUNS.values() for p in ps] + list(L.CAR_NOUNS) + list(L.GENERIC_PERSONS)
    phrases += [k for k, (slot, _) in V.ACTORS.items() if slot == "actor"]
    return frozenset(p.split()[-1] for p in phrases) | {"rider", "driver", "cyclist", "motorcyclist", "pensioner"}


def _road_user_word(w: str) -> bool:
    """Whether ``w`` (or its noun lemma) names a road user."""
    heads = _road_user_heads()
    return w in heads or any(x in heads for x in _pos(w).get("NOUN", ()))


def _phrasal_object(words: list[str], i: int) -> bool:
    """Whether the verb at ``i`` takes a particle and a road user ("took out a jogger", "took me out",
    "knocked the rider over"): the particle right after the verb or after its object."""
    after = words[i + 1 : i + 7]
    if not after:
        return False
    if after[0] in _PARTICLES:
        obj = after[1:]
    else:
        k = next((k for k, x in enumerate(after) if x in _PARTICLES), None)
        if k is None:
            return False
        if after[k] == "out" and after[k + 1 : k + 2] and (after[k + 1] in _OUTING or after[k + 1].endswith("ing")):
            return False  # ("took me out for a drive", "took us out driving": an outing, not a blow)
        obj = after[:k]
    return names_road_user(obj)


#: Who takes a learner out: the narrator's own party and their teachers.
_TAKERS_OUT = V.PARTY | frozenset(("instructor", "teacher", "examiner", "tutor", "coach"))


def _party_outing(words: list[str], i: int) -> bool:
    """Whether "take" at ``i`` is one of the narrator's party or their instructor taking the narrator
    out ("Dad took me out on the country lanes", "my instructor takes us out"): a drive, not a blow
    ("a van took me out on the roundabout", "Dad took out a cyclist" stay blows)."""
    return i > 0 and words[i - 1] in _TAKERS_OUT and words[i + 1 : i + 3] in (["me", "out"], ["us", "out"])


#: Words after "took someone out" that make it an outing ("out for practice", "out to the coast").
_OUTING = frozenset(("for", "to", "again"))


def names_road_user(obj: list[str]) -> bool:
    """Whether the object ``obj`` is a road user: a person pronoun, or a noun phrase whose noun names
    one ("a jogger", "its rider", "the scooter rider")."""
    for w in obj:
        if w in ("the", "a", "an", "this", "that", "some") or w in _POSSESSIVES:
            continue
        if w in _PERSON_OBJECTS - {"it", "one", "each"}:
            return True
        if _road_user_word(w):
            return True
        if w in PHRASE_ENDS or w in CLAUSE_BREAKS:
            return False
    return False


def _vehicle_part(after: list[str]) -> bool:
    """Whether ``after`` (a verb's object) is a vehicle's part: a determiner or possessive, then up to
    three modifiers, then the part ("my front bumper", "the wing mirror of the taxi")."""
    if after[1:2] == ["'s"]:
        after = ["the", *after[2:]]  # ("ego 's side mirror": a possessor's noun and "'s" are its determiner)
    if not after or not (after[0] in _POSSESSIVES or after[0] in ("the", "a", "his", "her")):
        return False
    reach = 6 if "'s" in after[1:4] else 4  # ("my driver's side mirror": its owner's noun between)
    for w in after[1:reach]:
        if w in _VEHICLE_PARTS or w.rstrip("s") in _VEHICLE_PARTS:
            return True
        if w in PHRASE_ENDS:
            return False
    return False


#: The parts of a body one touches another road user with ("caught it with my knee").
_BODY_PARTS = frozenset(("knee", "elbow", "shoulder", "arm", "hand", "leg", "foot", "hip", "head", "boot", "helmet",
                         "palm", "shin", "chin", "wrist", "ankle", "face", "rib", "finger"))  # fmt: skip


def _injury_adjective(words: list[str], i: int) -> bool:
    """Whether a verb of contact at ``i`` in "-ed" stands before a bare body part as an injury's
    adjective ("grazed knees", "scraped palms", "bumped head"), not a manner ("crashed head first into
    the windscreen", "smashed head on")."""
    w, part, after = words[i], words[i + 1 : i + 2], words[i + 2 : i + 3]
    if not (_lemmas(w) & _CONTACT_VERBS and w.endswith("ed") and part):
        return False
    return (part[0] in _BODY_PARTS or part[0][:-1] in _BODY_PARTS) and after not in (["first"], ["on"], ["into"])


#: What says a state of a person before its predicate ("he's just scraped up", "was all banged up").
_STATE_BEFORE = frozenset(("'s", "s", "is", "was", "were", "are", "got", "looked", "just", "all", "a", "bit",
                           "badly", "pretty", "fine", "only"))  # fmt: skip


def _knocked_about(words: list[str], i: int) -> bool:
    """Whether a verb of contact at ``i`` in "-ed" with "up" ending its clause is a person's state
    after a copula ("he's fine, just scraped up", "she was all banged up"): hurt, which says nothing
    of what hurt them (a fall of their own), not a blow between road users."""
    w = words[i]
    if not (_lemmas(w) & _CONTACT_VERBS and w.endswith("ed") and words[i + 1 :] == ["up"]):
        return False
    return i > 0 and words[i - 1] in _STATE_BEFORE


def _touched_with_a_part(words: list[str], i: int) -> bool:
    """A verb of touching at ``i`` with someone as its object and a part of a body or vehicle as its
    instrument ("caught it with my knee", "nicked me with its trailer"); not "caught up with him",
    "caught him with my eyes"."""
    after = words[i + 1 : i + 8]
    if not after or not (after[0] in _PERSON_OBJECTS - {"each", "one"} or names_road_user(after[:3])):
        return False
    k = next((k for k, x in enumerate(after[:4]) if x == "with"), None)
    if k is None:
        return False
    part = after[k + 1 : k + 5]
    return _vehicle_part(part) or (
        part[:1] != [] and part[0] in _POSSESSIVES and any(x in _BODY_PARTS for x in part[1:3])
    )


#: Verbs that are a blow only with a road user or a vehicle's part as their direct object: "dash" and
#: "jam" as Indian and Nigerian English say a collision ("a bus dashed my car", "the okada jammed
#: him"), "bang" ("banged my door"); "dashed across", "jammed the brakes on" are something else.
_STRIKING = frozenset(("dash", "jam", "bang"))


def _struck_object(after: list[str]) -> bool:
    """Whether ``after`` (the words after a verb) opens with its direct object, and that object is a
    road user or a vehicle's part ("my car", "the okada man", "him", "her front wheel")."""
    if not after:
        return False
    if after[0] in _PERSON_OBJECTS - {"it", "one", "each"} or after[0] in _EGO_HEADS:
        return True  # (or the ego: "dashed my car", read as "dashed ego")
    if after[0] not in _POSSESSIVES | {"the", "a", "an", "this", "that"}:
        return False
    return _vehicle_part(after) or names_road_user(after[:4])


def _run_over(words: list[str], i: int) -> bool:
    """ "run" at ``i`` with "over" or "down" and something met as its object: right after the particle
    anything but a place ("ran over the cyclist", "ran over a fox"; not "ran down the hill", "ran over
    the kerb"), before it a road user ("ran him over", "ran it down"; not "ran the route over")."""
    after = words[i + 1 : i + 6]
    if after[:1] and after[0] in ("over", "down"):
        place = set(after[1:4]) & (_PLACES | _FURNITURE | {"hill", "slope", "steps", "stairs", "bank", "alley"})
        return _meets_road_user(after[1:4]) and not place
    k = next((k for k, x in enumerate(after[:4]) if x in ("over", "down")), None)
    if not k:
        return False
    obj = after[:k]
    return names_road_user(obj) or obj in (["it"], ["them"])


def _begun(words: list[str], i: int) -> bool:
    """Whether the verb at ``i`` follows a verb of beginning in its clause ("started edging into me")."""
    return any(_lemmas(x) & _BEGIN for x in words[max(0, i - 3) : i])


def _lets_do(words: list[str], i: int) -> bool:
    """ "let" at ``i`` with an object and a bare verb after it ("lets the ego finish its turn", "let me
    clear the bridge"): the one who lets gives way to whatever the other does."""
    for w in words[i + 1 : i + 5]:
        if w in ("the", "a", "an") or w in _PERSON_OBJECTS or w in _EGO_HEADS or w in _POSSESSIVES:
            continue
        if w in _pos(w).get("VERB", ()):
            return True  # (its bare form: "finish", "clear", "complete")
        if "VERB" in _pos(w) or w in PHRASE_ENDS:
            return False  # (an inflected verb or a preposition: no object and bare verb)
    return False


def _negated_by_prefix(w: str) -> bool:
    """A noun of an event or of trouble negated by its prefix ("non-event", "nonevent", "non-issue"):
    nothing of note happens."""
    for prefix in ("non-", "non"):
        if w.startswith(prefix) and w[len(prefix) :] in _TROUBLE | {"event", "events"}:
            return True
    return False


def _denied_after(words: list[str], i: int) -> str | None:
    """A contact noun at ``i`` as the subject of a passive denying verb after it in its clause
    ("collision avoided", "a crash was narrowly averted"): "hedged" with a hedge, else "denied"."""
    after = words[i + 1 : i + 5]
    if _never_occurred(words[i + 1 : i + 6]):
        return "denied"  # ("a collision did not take place", "the crash never happened")
    for k, x in enumerate(after):
        if x.endswith("ed") and _lemmas(x) & _DENYING_VERBS:
            return "hedged" if set(after[:k]) & (HEDGES | {"just"}) else "denied"
        if x not in ("was", "is", "were", "been", "being", "be", "has", "had", "only", "just") and x not in HEDGES:
            return None
    return None


#: Verbs (lemmas) of an event's happening: a contact noun as their denied subject did not happen.
_OCCURRING = frozenset(("happen", "occur", "take", "result", "ensue", "materialise", "materialize", "eventuate"))
#: Auxiliaries between an event's noun and the negator of its verb ("did not", "has not", "had never").
_AUXILIARIES = frozenset(("did", "does", "do", "has", "have", "had", "was", "were", "is", "thankfully", "luckily"))


def _never_occurred(after: list[str]) -> bool:
    """Whether the words ``after`` a contact noun deny that it happened: auxiliaries, a negator, then
    a verb of happening ("did not take place", "didn't happen", "has not occurred", "never
    happened", "never came" at its clause's end, "was not going to happen"); not "did not stop him",
    whose verb says what the contact did."""
    k = 0
    while k < len(after) and after[k] in _AUXILIARIES:
        k += 1
    if k >= len(after) or after[k] not in ("not", "never"):
        return False
    k += 2 if after[k + 1 : k + 3] in (["going", "to"], ["about", "to"]) else 0  # ("was not going to happen")
    verb = after[k + 1 : k + 2]
    if verb and _lemmas(verb[0]) & {"come"}:
        return len(after) == k + 2  # ("the impact never came"; not "never came to court")
    return bool(verb) and bool(_lemmas(verb[0]) & _OCCURRING) and (verb[0] != "take" or "place" in after)


#: Pronouns that stand for what a sentence told was coming ("I braked and it was avoided").
_THAT_EVENT = frozenset(("it", "this", "that", "which"))


def _averted(words: list[str], i: int, before: list[str]) -> bool:
    """A passive of a denying verb at ``i`` whose subject is trouble or a pronoun for it ("disaster
    was averted", "the danger was avoided", "I stepped on the brake and it was avoided"): what was
    coming did not happen. A pronoun stands for a contact only after an escape in its sentence
    (``before``: its words up to ``i``); "the motorway was closed so it was avoided" is a route."""
    if not (words[i].endswith("ed") and _lemmas(words[i]) & _DENYING_VERBS):
        return False
    j = i - 1
    while j >= 0 and (words[j] in HEDGES or words[j] in ("just", "only", "luckily", "thankfully", "fortunately")):
        j -= 1
    if j < 1 or words[j] not in ("was", "were", "been", "is", "got", "be"):
        return False
    k = j - 1
    while k >= 0 and words[k] in ("has", "had", "have", "could", "would"):
        k -= 1
    subject = words[k] if k >= 0 else ""
    if subject in _TROUBLE | _DISASTERS | _HARM_NOUNS:
        return True
    return subject in _THAT_EVENT and any(_lemmas(x) & _ESCAPING and _is_verb(x) for x in before)


def _miss(words: list[str], i: int) -> bool:
    """A verb of missing whose object is someone ("missed him", "missed each other", "miss the cyclist")."""
    if "miss" not in _lemmas(words[i]) or i > 0 and words[i - 1] == "near":
        return False  # ("no near misses": the noun, read by _near_noun)
    after = words[i + 1 : i + 3]
    if not after:
        return True  # ("he swerved and just missed")
    if after[0] in _PERSON_OBJECTS or after[0] == "by" or after[0] in _POSSESSIVES:
        return True
    return after[0] in ("the", "a") and len(after) > 1 and after[1] not in ("turn", "exit", "junction", "light")


def _near_noun(words: list[str], i: int) -> bool:
    """ "a near miss", "near-collision", "a close call", "a narrow escape"."""
    w = words[i]
    nxt = words[i + 1] if i + 1 < len(words) else ""
    if w.startswith("near-") and (w[5:] in _CONTACT_NOUNS or w[5:].startswith("mis")):
        return True
    if w == "near" and (
        nxt.startswith("mis") or nxt in _CONTACT_NOUNS or nxt.rstrip("s") in _CONTACT_NOUNS or nxt == "thing"
    ):
        return True
    narrow = w in ("close", "narrow", "lucky") and nxt in ("call", "shave", "escape", "one", "thing")
    return narrow or w == "near-miss"


#: Words that set a road user apart as one standing by, not the one met ("the parked cars").
_STANDING = frozenset(("parked", "stationary", "stopped", "queuing", "waiting"))


def _clear_of_another(words: list[str], k: int) -> bool:
    """Whether "clear" at ``k`` is "clear of" a place, a line, street furniture or a third party
    ("1 m clear of the parked cars", "a metre clear of the stop line"): room from something else than
    the one met, no margin between the two ("1 m clear of the test car", "1 m clear" are)."""
    if words[k + 1 : k + 2] != ["of"]:
        return False
    obj = words[k + 2 : k + 7]
    if set(obj) & _STANDING:
        return True
    for w in obj:
        if w in _DETERMINERS or w in _POSSESSIVES or ("ADJ" in _pos(w) and "NOUN" not in _pos(w)):
            continue
        return w in _EDGES_AND_LINES or (w.endswith("s") and _road_user_word(w[:-1]))
    return False


def _margin(words: list[str], i: int, lead: list[str] | tuple[str, ...] = ()) -> str | None:
    """A margin stated at ``i``: "with inches to spare", "stopped a foot short", "by a whisker",
    "0.5 m clearance", "a separation of 0.5 m". Small: a near miss; wide: safe. ``lead``: the words of
    its sentence before its clause ("I stopped, what, two metres to spare": the stop it is said of)."""
    w = words[i]
    if _ample_measure(words, i) and not (i + 1 < len(words) and _relative_to_other(words, i + 1)):
        at_least = _length_said(words[max(0, i - 3) : i + 1]) or 0.0  # ("a good 2 metres": 2 m or more)
        if at_least > (3.0 if _gap_ahead([*lead, *words[:i]][-12:]) else 1.5 - 1e-9):
            return SAFE  # ("went round me with a good 2 metres", "stopped a good 10 metres away")
    spare = w == "spare" and i > 0 and (words[i - 1] == "to" or _length_unit(words[i - 1]))  # ("a metre spare")
    if spare:
        said = words[max(0, i - 6) : i - (words[i - 1] == "to")]
        if set(said) & _WIDE or any(_vehicle_width(said, k) for k in range(len(said))):
            return SAFE  # ("plenty to spare", "with a full car width to spare")
        metres = _length_said(said)
        stopped = _gap_ahead([*lead, *words[:i]][-12:])
        if metres is not None and not stopped:
            # (a pass's clearance sideways; a longer one is a gap ahead, which the text tells as close)
            return SAFE if 1.5 <= metres <= 5.0 else NEAR_MISS if metres <= 1.0 or metres > 5.0 else None
        return NEAR_MISS if said else None
    if _vehicle_width(words, i) and set(words[max(0, i - 10) : i]) & _LEAVING:
        return SAFE  # ("leaving a full car's width", "gave him a car width", "with a whole lane's width")
    if _one_length_after_a_stop(words, i):
        return NEAR_MISS  # ("we stopped maybe a car's length from him", "stopped a car length back")
    gap = w in ("gap", "berth") and words[i + 1 : i + 2] not in (["in"], ["between"], ["for"])  # (not a place)
    if (w in ("clearance", "separation", "margin", "room", "space", "distance") or gap) and set(
        words[max(0, i - 3) : i]
    ) & (_WIDE | _SUFFICIENT) - {"room", "space"}:
        if set(words[max(0, i - 4) : i]) & {"without", "not", "no", "never"}:
            return None  # ("without sufficient clearance": how close is not said)
        return SAFE  # ("plenty of room", "an ample margin", "enough distance", "adequate clearance")
    if w == "clear" and i > 0 and words[i - 1] in _WELL:
        return SAFE
    small = _small_length_said(words, i, lead)
    if small is not None:
        return small
    stopping = any(_lemmas(x) & {"stop", "brake", "halt"} or x == "up" for x in words[max(0, i - 6) : i])
    if w == "time" and stopping and words[max(0, i - 2) : i] in (["in", "good"], ["in", "ample"], ["plenty", "of"]):
        return SAFE  # ("pulled up in good time", "stops in plenty of time": time to spare)
    arriving = words[i + 1 : i + 2] in (["to"], ["for"])  # ("got there just in time for the start")
    arriving = arriving or any(_lemmas(x) & _PERCEIVING for x in words[:i])  # ("spotted him just in time")
    if w == "time" and words[i - 1 : i] == ["in"] and set(words[max(0, i - 3) : i - 1]) & (HEDGES | {"just"}):
        return None if arriving else NEAR_MISS  # ("pulled back just in time", "swerved barely in time")
    if w == "time" and words[max(0, i - 3) : i] == ["the", "nick", "of"]:
        return NEAR_MISS  # ("in the nick of time")
    if w == "time" and i > 0 and words[i - 1] == "in" and stopping:
        after = words[i + 1 : i + 6]
        if after[:1] == ["with"] and set(after) & (_WIDE - {"enough"}):
            return SAFE  # ("stopped in time with plenty of room", "... with a comfortable margin")
        return NEAR_MISS  # ("stopped just in time")
    if w in ("moment", "second", "minute", "instant") and i > 1 and words[i - 1] == "last":
        return NEAR_MISS  # ("swerved back at the last second")
    context = set(words[max(0, i - 6) : i + 2])  # ("with at least 2 m margin")
    if w in ("clearance", "separation", "margin") and (
        w == "clearance" or context & {"minimum", "lateral", "with", "passing"}
    ):
        metres = _length_said(words[max(0, i - 4) : i + 6])
        return None if metres is None else NEAR_MISS if metres <= 1.0 else SAFE if metres >= 1.5 else None
    left = _stop_left(words, i, lead)
    if left is not None:
        return left
    if w in _LENGTH_UNITS | _SMALL_UNITS and i + 1 < len(words):
        k = i + 1
        if words[k] == "or" and k + 2 < len(words):
            k += 2  # ("a metre or two from my bumper")
        if words[k : k + 2] == ["away", "from"]:
            k += 1  # ("stopped about a foot away from me")
        front = _relative_to_other(words, k)  # ("2 m in front of us", "a metre ahead")
        if words[k] == "clear" and not set(words[max(0, i - 3) : i]) & _WIDE and not _clear_of_another(words, k):
            metres = _length_said(words[max(0, i - 3) : i + 1])
            if metres is not None and metres <= 1.0:
                return NEAR_MISS  # ("rider continued, approx 1 m clear": the clearance left, a metre or less)
        if (
            front
            or (
                words[k] in ("from", "off", "short", "before")
                and not _short_of_a_marking(words, k)
                and k + 1 < len(words)
                and (
                    words[k + 1] in _POSSESSIVES | _PERSON_OBJECTS | {"the", "of"}
                    or _vehicle_part(["the", *words[k + 1 : k + 4]])  # ("~1 m off front bumper": no article)
                )
            )
            or _apart_after_a_stop(words, i, k)
        ):
            value = _number(words[i - 1]) if i > 0 else None
            if value is None and i > 0 and words[i - 1] in _MERE and words[i].endswith(("s", "feet")):
                value = 1.0  # ("only feet from her", "mere inches from the cyclist")
            if value is None and words[i] in ("inches", "centimetres", "centimeters", "cm", "millimetres", "mm"):
                value = 0.1  # ("stopped inches from my door")
            if value is None and i > 0 and words[i - 1] in ("a", "an", "few", "couple", "of"):
                value = 2.0 if "couple" in words[max(0, i - 3) : i] else 1.0
            if value is not None:
                metres = value * (
                    0.3048 if words[i] in ("foot", "feet") else 0.0254 if words[i].startswith("inch") else 1.0
                )
                if metres <= 3.0:
                    return NEAR_MISS  # ("stopped two metres off his door", "a foot from him")
    if w in ("before", "back") and i > 0 and words[i - 1] in _WELL and _stop_before_someone(words, i):
        return SAFE  # ("stopped well before her", "pulled up well back from him": a wide margin)
    if w == "short" and i > 0 and not _short_of_a_marking(words, i) and not _measured_before(words, i):
        if any(_lemmas(x) & {"stop", "pull", "come", "halt"} for x in words[max(0, i - 7) : i]):
            # (by a wide margin: "well short", "comfortably short", "a long way short")
            wide = words[i - 1] in _WELL or words[i - 2 : i] in (
                ["long", "way"],
                ["good", "way"],
            )
            return SAFE if wide else NEAR_MISS
    if w == "by" and i > 0 and "miss" in _lemmas(words[i - 1]) | (_lemmas(words[i - 2]) if i > 1 else frozenset()):
        return NEAR_MISS
    if w in _SMALL_UNITS and i > 0 and words[i - 1] in ("a", "an", "few", "inches") + tuple("0123456789"):
        before = words[max(0, i - 6) : i]
        if any(_lemmas(x) & {"stop", "miss", "pass", "clear", "halt"} for x in before) or "by" in before:
            return NEAR_MISS
    return None


#: Where a measured stop leaves the stopper from the one it stopped for ("stopped 1 m behind it",
#: "halts 6 m short", "came to a stop 8 m before the dummy").
_STOPPED_FROM = frozenset(("behind", "short", "before", "from", "back"))
#: The least length of a stop with room to spare: a few metres or less is close, several are not.
_ROOMY_METRES = 4.0


#: Words that end the search for the subject of a stop: a clause of its own before it ("... as the car stops").
_SUBORDINATE = frozenset(("as", "when", "while", "whilst", "after", "before", "until", "once", "where"))


def _anothers_stop(
    words: list[str], i: int, inherited: str | None, story: bool, named: frozenset[str] = frozenset()
) -> bool:
    """Whether the measured stop told at the unit ``i`` is another road user's, short of someone who is
    not the ego ("the bus stopped 4 m behind her, I was behind the bus", "the rider jumps off as the car
    stops 5 m short of him"): the length is a margin between two others, not the ego's. Its subject is
    the nearest noun before the stop: a name the reader gave a road user (``named``), a third person, or
    in a story told by the ego a road user's noun; with none, the clause's inherited subject. Not a stop
    short of the ego ("the car stopped 5 m short of me")."""
    if set(words[i + 1 : i + 5]) & ({"me", "us", "my", "our"} | _EGO_HEADS):
        return False  # (short of the ego: its margin)
    s = next((k for k in range(i - 1, max(-1, i - 9), -1) if _lemmas(words[k]) & {"stop", "halt", "pull"}), None)
    if s is None:
        return False
    for k in range(s - 1, -1, -1):
        w = words[k]
        if w in _SUBORDINATE:
            break
        if w in _EGO_HEADS or _names_ego(words[: k + 1]):
            return False
        if w in named or w in ("he", "she", "they") or (story and _road_user_word(w)):
            return True
    return story and inherited == "other"


def _measured_before(words: list[str], i: int) -> bool:
    """Whether the word at ``i`` comes right after a length ("6 m short"): the length says the margin."""
    return i > 0 and words[i - 1] in _UNIT_METRES and _length_said(words[max(0, i - 4) : i]) is not None


def _stop_left(words: list[str], i: int, lead: list[str] | tuple[str, ...] = ()) -> str | None:
    """The margin a stop leaves, told as a length at the unit ``words[i]`` and where it left the
    stopper ("the ego stops about 1 m behind", "halted 6 m short of him", "came to a stop 8 m before
    the dummy"): a verb or noun of stopping before it in its clause. A few metres or less is a near
    miss; several metres (:data:`_ROOMY_METRES` or more) is ``room``: the stop had room to spare, a
    safe pass unless an emergency stop or a swerve is said with it (see :func:`decide`). A hard stop
    or a swerve said before it in its sentence (``lead``: the sentence before the clause; "which
    braked hard and stopped 6 m short of it") makes any length the end of an emergency stop: a near
    miss. Not a length to a place, a line or in a queue ("stopped 5 m behind the van at the lights",
    "2 m short of the stop line"): where one waits, no margin."""
    if words[i] not in _UNIT_METRES or not set(words[i + 1 : i + 2]) & _STOPPED_FROM:
        return None
    stopped = any(
        _lemmas(x) & {"stop", "halt"} or (_lemmas(x) & {"pull"} and words[k + 1 : k + 2] == ["up"])
        for k, x in enumerate(words[max(0, i - 8) : i], start=max(0, i - 8))
    )
    metres = _length_said(words[max(0, i - 3) : i + 1])
    if not stopped or metres is None:
        return None
    k = i + 2 + (words[i + 1] in ("short", "back") and words[i + 2 : i + 3] in (["of"], ["from"]))
    obj = []
    for x in words[k : k + 6]:
        if x in CLAUSE_BREAKS or (x in PHRASE_ENDS and obj):
            break
        obj.append(x)
    if set(obj) & (_EDGES_AND_LINES | _QUEUE | _STOPPING_MARKINGS) or set(words[k : k + 8]) & _QUEUE:
        return None  # ("stopped 5 m behind the car at the lights", "3 m before the stop line": a place)
    if words[i + 1] in ("from", "back") and not obj:
        return None  # ("stopped 5 m back": from what is not said)
    if metres <= 3.0 or _hard_stop_said([*lead, *words[:i]]):
        return NEAR_MISS
    return "room" if metres >= _ROOMY_METRES else None


def _on_the_brakes(words: list[str], k: int) -> bool:
    """Whether what a verb of pressing (:data:`lexicon.PRESSING`) says from ``k`` on, up to the end of
    its clause, is the brakes: the brakes or the pedal named ("hit the brakes", "mashed the brakes",
    "jammed my foot on the brake", "stood on everything"), or "on" right after it (an adverb between)
    with no noun phrase of its own after it ("slammed on and stopped", "stood hard on them"). Not a
    verb of pressing with anything else ("stood on the verge", "jumped on his bike", "a van stands still")."""
    phrase: list[str] = []
    for x in words[k : k + 6]:
        if x in _BREAK_PUNCT or x in CLAUSE_BREAKS:
            break
        phrase.append(x)
    if set(phrase) & (L.PRESSED | {"pedal"}):
        return True
    on = next((n for n, x in enumerate(phrase[:2]) if x == "on" and (n == 0 or phrase[0] in _HARD)), None)
    if on is None:
        return False
    nxt = phrase[on + 1 : on + 2]
    return not nxt or _is_verb(nxt[0]) or not (nxt[0] in _DETERMINERS | _POSSESSIVES or "NOUN" in _pos(nxt[0]))


def _hard_stop_said(before: list[str]) -> bool:
    """Whether ``before`` says a hard stop or a swerve not denied ("braked hard", "slammed on", "hit
    the brakes", "stomped on them", "an emergency stop"; not "no hard braking")."""
    for k, x in enumerate(before):
        if set(before[max(0, k - 2) : k]) & {"no", "not", "without", "never"}:
            continue
        if _is_verb(x) and _lemmas(x) & L.PRESSING:
            if _on_the_brakes(before, k + 1):
                return True  # ("slammed on", "hit the brakes"; not "a van stands still", "the rider jumps off")
            continue
        if _is_verb(x) and _lemmas(x) & _EVADE:
            return True  # ("swerved")
        if x in _HARD and any(_lemmas(y) & _BRAKE for y in before[max(0, k - 2) : k + 3]):
            return True
    return False


#: The road markings a stop is made at: a stop or give-way line, the yellow box of a junction. (A
#: crossing or a path is not one: "stopped short of the crossing" as a rider came out is close, and so
#: is one short of its markings, "the zebra lines".)
_STOPPING_MARKINGS = frozenset(("line", "lines", "box", "markings"))


def _short_of_a_marking(words: list[str], i: int) -> bool:
    """Whether "short of" at ``i`` has a road marking for its object ("stopped short of the stop line",
    "pulled up short of the box"): where the stop was made, not a margin left to anyone. Not the
    markings of a foot crossing ("the zebra lines"), nor a line or queue of something ("a line of
    schoolchildren", "the line of traffic"): the head followed by "of" is a quantity, and what it
    counts is the object."""
    if words[i] != "short" or words[i + 1 : i + 2] != ["of"]:
        return False
    phrase = []
    for w in words[i + 2 :]:
        if w in PHRASE_ENDS:
            break
        phrase.append(w)
    counted = words[i + 2 + len(phrase) : i + 3 + len(phrase)] == ["of"]
    return (
        bool(phrase)
        and phrase[-1] in _STOPPING_MARKINGS
        and not counted
        and not (FOOT_CROSSINGS | {"crossing"}) & set(phrase)
    )


#: Adverbs that say a margin was wide ("well short", "comfortably back").
_WELL = frozenset(("well", "comfortably", "safely"))


def _stop_before_someone(words: list[str], i: int) -> bool:
    """Whether "before" or "back" at ``i`` tells where a stop ("stopped", "halted", "pulled up/in")
    left the stopper from a road user ("stopped well before her", "pulled up well back from the
    cyclist"): not a pull-out ("pulled out well before the junction"), nor a place or a clause after
    it ("well before I got there")."""
    stop = any(
        _lemmas(x) & {"stop", "halt"} or (_lemmas(x) & {"pull"} and words[k + 1 : k + 2] in (["up"], ["in"]))
        for k, x in enumerate(words[max(0, i - 5) : i], start=max(0, i - 5))
    )
    k = i + 1 + (words[i] == "back" and words[i + 1 : i + 2] == ["from"])
    obj = words[k : k + 3]
    return stop and bool(obj) and (obj[0] in _PERSON_OBJECTS or names_road_user(obj))


#: Prepositions of a stretch of road gone along ("for a good 200 m", "over a good kilometre").
_ALONG_THE_ROAD = frozenset(("for", "over", "after", "along"))


def _ample_measure(words: list[str], i: int) -> bool:
    """Whether the unit of length at ``i`` is said with "a good" right before its number or itself ("a
    good 2 metres", "a good metre to spare", "still a good 10 metres away"): "good" before a measure
    says the length was at least that, so the margin's thresholds apply to it as a lower bound. Not "a
    good few" (several), nor a length from the kerb or a line (where someone is, not a margin), nor a
    stretch of road gone along ("for a good 200 m")."""
    if words[i] not in _UNIT_METRES or set(words[i + 1 : i + 5]) & _EDGES_AND_LINES:
        return False
    k = next((k for k in range(max(0, i - 2), i) if words[k - 1 : k + 1] == ["a", "good"]), None)
    if k is not None and words[max(0, k - 2) : k - 1] and words[k - 2] in _ALONG_THE_ROAD:
        return False  # ("sat 2 m behind him for a good 200 m": how far it went, no margin)
    return k is not None and (k + 1 == i or _number(words[k + 1]) is not None)


#: Verbs (lemmas) of stopping or of coming in ahead: a margin said after one is the gap left ahead,
#: not a pass's clearance sideways ("stopped with 2 m to spare", "cut in with 2 metres to spare").
_AHEAD_GAP = frozenset(("stop", "halt", "pull", "brake", "cut", "merge"))
#: Verbs (lemmas) of passing someone: a margin said after one is the clearance sideways.
_PASSING = frozenset(("pass", "overtake", "undertake", "go", "get", "squeeze", "drive", "ride", "come", "give"))


def _gap_ahead(before: list[str]) -> bool:
    """Whether the margin after ``before`` (its sentence up to it) is a gap ahead: the nearest verb of
    stopping, cutting in or passing before it is one of stopping or cutting in ("the lorry slammed
    on and we stopped, two metres to spare"); "overtook the bus, stopped at the lights, with ..."
    reads its nearest verb."""
    for x in reversed(before):
        lem = _lemmas(x)
        if lem & _AHEAD_GAP:
            return True
        if lem & _PASSING and _is_verb(x):
            return False
    return False


def _length_unit(w: str) -> bool:
    """A unit of length, or a vehicle's length ("two car lengths spare")."""
    return w in _UNIT_METRES or w in ("length", "lengths")


#: What bounds a length from above ("1 m max", "half a metre at most", "30 cm tops", "if that").
_AT_MOST = (["max"], ["maximum"], ["tops"], ["at", "most"], ["at", "best"], ["if", "that"], ["or", "less"])
#: Places a length may be said from: a margin to one of these is where someone is, not how close two
#: road users came.
_EDGES_AND_LINES = _PLACES | _FURNITURE | frozenset(("edge", "line", "marking", "markings", "gutter", "centre-line"))
#: Nouns a road user's contact may land on besides road users: a vehicle's parts, a body's parts,
#: and the furniture and places whose hits are read by their own rules.
_MET_NOUNS = _VEHICLE_PARTS | _BODY_PARTS | _EDGES_AND_LINES
#: Words after "left" that make it a side, not what was left ("2 m left of the line", "left lane"); a
#: verb after "left to" makes it a distance still to go ("200 m left to go").
_LEFT_AS_SIDE = frozenset(("of", "on", "in", "lane", "turn", "side", "hand", "-hand", "for", "edge", "kerb"))


def _small_length_said(words: list[str], i: int, lead: list[str] | tuple[str, ...] = ()) -> str | None:
    """A margin said as a length at the unit ``words[i]``: bounded from above ("1 m max", "half a
    metre at most", "50 cm tops"), the clearance of a pass ("passed me with maybe 50 cm"), or what was
    left after a stop ("stopped with about 1 m left", "stops w/ ~2 m left"). A near miss when it is a
    metre or less (a gap ahead after a stop, up to five); None otherwise: how wide a pass was is read
    by the rest of :func:`_margin`."""
    if words[i] not in _UNIT_METRES:
        return None
    metres = _length_said(words[max(0, i - 3) : i + 1])
    if metres is None:
        return None
    after = words[i + 1 : i + 3]
    if any(after[: len(b)] == b for b in _AT_MOST):
        return NEAR_MISS if metres <= 1.0 else None
    if a_size(words, i, 1):
        return None  # ("with a 50 cm wide box on the back")
    if set(words[i + 1 : i + 5]) & _EDGES_AND_LINES:
        return None  # ("rode with 50 cm to the kerb", "stopped with 2 m left to the stop line": a place)
    said_with = {"with", "w"} & set(words[max(0, i - 5) : i])
    before = [*lead, *words[:i]][-12:]
    to_go = words[i + 2 : i + 3] == ["to"] and _is_verb(words[i + 3]) if i + 3 < len(words) else False
    if said_with and after[:1] == ["left"] and not set(after[1:2]) & _LEFT_AS_SIDE and not to_go:
        return NEAR_MISS if metres <= 5.0 and _gap_ahead(before) else None  # ("pulled up with a metre left")
    if said_with and metres <= 1.0 and not _gap_ahead(before) and any(_lemmas(x) & _PASSING for x in before[-8:]):
        return NEAR_MISS  # ("the bus passed me with maybe 50 cm")
    return None


#: Words that give a margin to the one passed ("leaving a car's width", "gave her a lane", "with").
_LEAVING = frozenset(("leaving", "leave", "left", "gave", "give", "giving", "gives", "with", "allowing", "allowed"))
#: The kinds of road user as wide as a lane's share: a margin of one of their widths is a wide one.
_WIDE_KINDS = ("car", "van", "truck")
#: Words that make the width that follows less than said ("less than a car's width", "not even").
_SHORT_OF = frozenset(("less", "under", "not", "never", "barely", "hardly", "scarcely", "only", "half", "no"))


#: Words a margin told alone may carry before its unit ("Literally inches.", "Just a whisker.").
_MARGIN_FILLERS = HEDGES | _INTENSIFIERS | frozenset(("literally", "mere", "a", "by", "bare"))


def _margin_alone(words: list[str]) -> bool:
    """Whether a sentence is only a small margin, a unit of a hair's breadth with no number ("Inches.",
    "Literally centimetres!", "By a whisker."): the distance the last thing told passed by, a near
    miss, as "Just." is a hedge of it. A number makes it a measure ("30 cm."), not a verdict."""
    return (
        len(words) <= 4
        and words[-1] in _SMALL_UNITS
        and words[-1] not in ("foot", "inch", "cm", "mm")
        and all(w in _MARGIN_FILLERS for w in words[:-1])
    )


@lru_cache(maxsize=1)
def _wide_heads() -> frozenset[str]:
    """The last words of the nouns of a car, a van or a truck, and "lane": the widths of a margin that
    is a wide one ("a car's width", "a full lane")."""
    phrases = [p for kind in _WIDE_KINDS for p in L.ACTOR_NOUNS[kind]] + list(L.CAR_NOUNS)
    return frozenset(p.split()[-1] for p in phrases) | {"lane", "vehicle"}


def _vehicle_width(words: list[str], i: int) -> bool:
    """Whether ``words[i]`` is "width" said of a car, a van, a lorry or a lane ("a full car's width", "a
    car width", "a whole lane's width"), or a lane given whole ("a whole lane", "a full lane"): a
    margin as wide as a vehicle, so a pass with room. Not a width cut short ("less than a car's
    width", "not even half a car width") and not the width of the road ("the lane width is 3 m")."""
    k = i - 2 if words[i - 1 : i] == ["'s"] else i - 1  # ("a car 's width", as the tokens split it)
    if words[i] == "width" and k >= 0 and words[k].removesuffix("'s").removesuffix("s'") in _wide_heads():
        pass
    elif words[i] == "lane" and i > 1 and words[i - 1] in ("full", "whole", "entire"):
        k = i  # ("gave him a whole lane")
    else:
        return False
    article = next((j for j in range(k - 1, max(-1, k - 4), -1) if words[j] in ("a", "an", "one")), None)
    return article is not None and not set(words[max(0, article - 3) : article]) & _SHORT_OF


#: Words that set a length from the one it is kept to ("a car length back", "a car's length from him").
_KEPT_FROM = frozenset(("from", "back", "short", "behind", "away", "off"))


def _one_length_after_a_stop(words: list[str], i: int) -> bool:
    """Whether ``words[i]`` is "length" of one vehicle ("a car's length", "a car length", "one bus
    length") that a stop left from someone ("we stopped maybe a car's length from him", "stopped a car
    length back"): a vehicle's length is the least gap a stop is told in, so a near miss. Not in a queue
    ("a car's length behind the bus at the lights", "behind the van in front"): a stop in one's turn."""
    k = i - 2 if words[i - 1 : i] == ["'s"] else i - 1
    if words[i] != "length" or k < 1 or words[k].removesuffix("'s") not in _wide_heads():
        return False
    if words[k - 1] not in ("a", "one") or words[i + 1 : i + 2] == [] or words[i + 1] not in _KEPT_FROM:
        return False
    if (
        set(words[i + 1 : i + 8]) & _QUEUE
        or words[i + 1] == "behind"
        and set(words[i + 2 : i + 7]) & {"front", "ahead"}
    ):
        return False  # ("a car's length behind the bus at the lights", "behind the van in front": a queue)
    return any(_lemmas(x) & {"stop", "halt", "pull"} for x in words[max(0, k - 6) : k])


#: Adjectives that call a margin enough ("adequate clearance", "a sufficient distance").
_SUFFICIENT = frozenset(("sufficient", "adequate", "safe", "decent", "reasonable", "good", "big", "large"))
#: Metres in one of each unit of length a margin is said in.
_UNIT_METRES = {"m": 1.0, "metre": 1.0, "metres": 1.0, "meter": 1.0, "meters": 1.0, "foot": 0.3048, "feet": 0.3048,
                "yard": 0.9144, "yards": 0.9144, "cm": 0.01, "centimetre": 0.01, "centimetres": 0.01,
                "centimeter": 0.01, "centimeters": 0.01, "inch": 0.0254, "inches": 0.0254}  # fmt: skip


#: Verbs of perceiving: what is seen "just in time" is seen, not escaped ("caught him with my eyes just
#: in time", "spotted her just in time and braked"); the act that follows says the outcome.
_PERCEIVING = frozenset(("see", "spot", "notice", "catch", "look", "hear", "glimpse", "sight", "clock"))


def _length_said(words: list[str]) -> float | None:
    """The first length in ``words`` in metres: a number, or "a"/"half a", before a unit ("3 metres or
    more", "30 cm", "half a metre"), else None."""
    for k in range(1, len(words)):
        unit = _UNIT_METRES.get(words[k])
        if unit is None:
            continue
        value = _number(words[k - 1])
        if value is None and words[k - 2 : k] == ["a", "good"]:
            value = 1.0  # ("a good metre": at least one)
        if value is None and words[k - 1] in ("a", "an"):
            value = 0.5 if words[k - 2 : k - 1] == ["half"] else 1.0
        if value is not None:
            return value * unit
    return None


def _apart_after_a_stop(words: list[str], i: int, k: int) -> bool:
    """A distance at ``i`` said as what was left between the two once they stopped ("we both pulled up
    with a metre between us", "ended up 2 metres apart", "stopped with a metre in it"), ``k`` the word
    after its unit; not the spacing of road users riding along ("two scooters 2 m apart")."""
    between = words[k] in ("apart", "between") or words[k : k + 2] == ["in", "it"]
    stopped = any(_lemmas(x) & {"stop", "halt", "pull", "end", "finish"} for x in words[max(0, i - 8) : i])
    return between and stopped


#: Words that make a bare plural unit small ("only feet from", "mere inches").
_MERE = frozenset(("only", "just", "mere", "barely", "scarcely", "within"))


def _relative_to_other(words: list[str], k: int) -> bool:
    """Whether "in front" or "ahead" at ``k`` (after a distance) is relative to the ego or the other
    road user: said alone at the end of its clause, or "of" the ego, a pronoun or a road user; not "2 m
    in front of the stop line"."""
    if words[k : k + 2] == ["in", "front"]:
        k += 1
    elif words[k] != "ahead":
        return False
    after = words[k + 1 : k + 5]
    if not after or after[0] != "of":
        return not after or after[0] in CLAUSE_BREAKS or after[0] in PHRASE_ENDS - {"of"}
    obj = after[1:]  # (or a part of one: "3 m ahead of the front bumper", "in front of my bonnet")
    return bool(obj) and (obj[0] in _PERSON_OBJECTS | _EGO_HEADS or names_road_user(obj) or _vehicle_part(obj))


def _passed_close(before: list[str], after: list[str]) -> bool:
    """A pass said close with a strong degree ("overtook us really close", "went by far too close",
    "squeezed past so close"): ``before`` its sentence up to "close", ``after`` the next words; not
    closeness to a place ("too close to the kerb")."""
    if not before or before[-1] not in ("so", "too", "really", "very", "dangerously", "uncomfortably", "bloody"):
        return False
    if after[:1] == ["to"] and after[1:2] and after[1] not in _PERSON_OBJECTS | _EGO_HEADS:
        return False
    passing = {"pass", "overtake", "go", "squeeze", "come", "cut", "swing", "drive", "ride", "shave"}
    return any(_lemmas(x) & passing for x in before[-7:-1])


def _passed_wide(before: list[str], after: list[str]) -> bool:
    """ "wide" said of a pass ("passed wide", "overtook him nice and wide", "went round wide of her"):
    ``before`` its sentence up to it, ``after`` the rest of its clause; not "a wide load"."""
    if after and after[0] not in ("of", "and", "berth", "around", "round", "enough"):
        return False  # (before its noun: "a wide load", "the wide lane")
    passing = {"pass", "overtake", "go", "swing", "give", "drive", "steer", "ride"}
    return any(_lemmas(x) & passing for x in before[-6:])


def _subject_is_ego(words: list[str], i: int, clause: _Clause, story: bool) -> bool:
    """Whether the verb at ``i`` is the ego's: its subject before it is the ego, or it has none and the
    clause inherits the ego or opens a narrator's sentence ("Had to brake", "Swerved round him")."""
    j = i - 1
    while j >= 0 and (words[j] in _BETWEEN or words[j].endswith("ly") or (j == i - 1 and words[j] in _HARD)):
        j -= 1  # (and the manner of a braking said as a noun: "AEB full braking", "emergency braking")
    if j < 0:
        if clause.inherited is not None:
            return clause.inherited == "ego"
        return story and clause.first_of_sentence
    return _names_ego(words[: j + 1]) or _ego_system(words[: j + 1])


#: The names of an emergency brake, as the reader lowercases them ("AEB", "emergency brake assist"). The
#: ego's is its emergency stop when it brakes ("the AEB brakes hard"); not a cruise control or a pilot,
#: whose braking is routine.
_EMERGENCY_BRAKES = frozenset(("aeb", "aebs"))
#: Owners before a system that make it another's ("their AEB", "another AEB"; "the lorry's AEB" too).
_OTHERS = (POSSESSIVE - FIRST_PERSON) | {"other", "another"}


def _ego_system(words: list[str]) -> bool:
    """Whether the noun phrase ending ``words`` is the ego's emergency brake, not another's ("the AEB",
    "AEB"; not "the lorry's AEB", "their AEB")."""
    if not words or words[-1] not in _EMERGENCY_BRAKES:
        return False
    owner = words[-2] if len(words) > 1 else ""
    return not (owner.endswith("'s") or owner in _OTHERS)


#: Words after which the ego is an object, not the subject ("the car behind the ego", "following ego").
_OBJECT_MARKERS = frozenset(
    ("of", "behind", "to", "with", "for", "at", "from", "past", "by", "than", "before", "after", "towards", "toward",
     "ahead", "beside", "alongside", "near", "like", "into")
)  # fmt: skip


#: Words that bring a learner in as someone new ("a pupil", "another learner"): no one at the ego's wheel.
_INDEFINITE_BEFORE = frozenset(("a", "an", "another", "one", "some", "other"))


def _names_ego(words: list[str]) -> bool:
    """Whether the noun phrase ending ``words`` is the ego (not the ego as an object inside it)."""
    if not words:
        return False
    n = 0
    if words[-1] in _EGO_HEADS:
        n = 1
    elif words[-1] in V.LEARNER and not (len(words) > 1 and words[-2] in _INDEFINITE_BEFORE):
        n = 1  # ("the candidate", "Applicant": the learner at the ego's wheel; not "a pupil")
    else:
        tail = " ".join(words[-3:])
        phrase = next((p for p in _EGO_PHRASES if tail.endswith(p)), None)
        if phrase is None:
            return False
        n = len(phrase.split())
    rest = [w for w in words[: len(words) - n] if w not in ("the", "a", "an")]
    return not rest or not (rest[-1] in _OBJECT_MARKERS or rest[-1].endswith("ing"))


def _subject(words: list[str]) -> str | None:
    """The clause's own subject, told apart only as the ego or someone else ("I at 50": the ego)."""
    if words and words[0] in _EGO_HEADS:
        return "ego"
    for k, w in enumerate(words):
        if _is_verb(w) and w not in _BETWEEN and k > 0 and w not in ("ego", "car", "rider", "lane"):
            if _escape_noun(words, k - 1):
                continue  # ("Emergency stop.": the head of a noun phrase, no verb with a subject)
            return "ego" if _names_ego(words[:k]) else "other"
    return None


def _does_next(after: list[str]) -> bool:
    """Whether a bare verb follows the object of "let" ("lets the ego complete the turn", "lets me make
    the turn"): the one let does something, so the one who lets gives way."""
    k = 1 if after[:1] in (["the"], ["a"]) else 0
    return len(after) > k + 1 and _is_verb(after[k + 1]) and after[k + 1] in _lemmas(after[k + 1])


#: The auxiliaries of a denied finite verb ("does not enter", "did not cross").
_DID = (["does"], ["did"], ["do"], ["will"], ["would"], ["could"], ["can"])


def _failure_to(words: list[str], i: int) -> bool:
    """Whether the verb at ``i`` is what a noun of failing says was not done ("failure to give way",
    "a refusal to yield"): the opposite of a road user giving way."""
    return words[i - 1 : i] == ["to"] and words[i - 2 : i - 1] in (["failure"], ["refusal"])


#: Verbs (lemmas) of moving out of one place into another's: denied, the mover stayed where it was.
_ENTERING = frozenset(("enter", "leave", "cross"))


def _kept_to_its_place(words: list[str], i: int) -> bool:
    """Whether the finite verb at ``i`` (its subject a road user, not the ego) is denied by a negator
    right before it, auxiliaries between, that it left its place or entered another ("the rider never
    left the shoulder", "does not enter the vehicle's lane", "didn't cross the line"): it stayed out of
    the ego's way, so nothing forced an escape. Not a participle under a negation of something else
    ("did not slow for a rider crossing the road", "with no lamps rolled across from the left verge")."""
    if words[i].endswith("ing") or not (_is_verb(words[i]) and _lemmas(words[i]) & _ENTERING):
        return False
    j = i - 1
    while j >= 0 and words[j] in ("even", "ever", "once"):
        j -= 1
    if j < 0 or words[j] not in ("not", "never") or (words[j] == "not" and words[j - 1 : j] not in _DID):
        return False
    obj = words[i + 1 : i + 5]
    return bool(set(obj) & (_PLACES | _ROAD_EDGES | _ENTERED))


#: The edges of a road the ego is driven onto to escape ("had to mount the verge", "forced onto the grass").
_ROAD_EDGES = frozenset(("verge", "gravel", "shoulder", "grass", "kerb", "curb", "pavement", "footpath", "sidewalk",
                         "ditch", "hedge", "reservation", "median", "dirt", "rumble"))  # fmt: skip
#: Words that make what follows a forced act ("had to", "was forced onto").
_FORCED = frozenset(("had", "force", "forced", "made", "needed", "mount", "mounted", "mounting"))


def _off_the_road(words: list[str], i: int) -> bool:
    """The ego's verb at ``i`` taking it onto the road's edge when it is forced to ("had to put two
    wheels on the gravel", "was forced onto the grass", "mounted the kerb"): it escaped something."""
    after = words[i + 1 : i + 7]
    edge = next((k for k, x in enumerate(after) if x in _ROAD_EDGES), None)
    if edge is None or not ({"onto", "on", "up", "into", "over"} & set(after[:edge]) or _lemmas(words[i]) & {"mount"}):
        return False
    before = words[max(0, i - 3) : i + 1]
    return bool(set(before) & _FORCED or _lemmas(words[i]) & {"force", "mount"})


#: Verbs (lemmas) that work a brake said as their object ("hit the brakes", "applied the brake",
#: "used his brakes", "put the brakes on", "pressed the brake pedal", "tapped the brakes").
_WORKING = frozenset(("hit", "apply", "use", "press", "push", "put", "step", "get", "tap", "dab", "feather", "pump"))


#: Prepositions between a verb and the brake it works ("got on the brake"; "hit to the brakes", "hit
#: in the brake" as translations put it).
_ONTO_BRAKE = frozenset(("on", "onto", "to", "in", "at"))


def _brakes_worked(words: list[str], i: int) -> bool:
    """Whether the verb at ``i`` takes the brake as its object, up to a determiner and a preposition
    between ("hit the brakes", "got on the brake", "hit to the brakes", "used his brake"): a brake said
    with its noun. Not the brake as what something else does ("pushed the car with the brakes off")."""
    k = i + 1
    while k < len(words) and k <= i + 3 and (words[k] in _DETERMINERS | _POSSESSIVES or words[k] in _ONTO_BRAKE):
        k += 1
    return k < len(words) and words[k] in ("brake", "brakes", "anchors")


def _ego_acts(words: list[str], i: int) -> str | None:
    """What the ego's verb at ``i`` says of the outcome: "evade" (swerve, brake hard), "brake" (a
    plain brake), "stop" (a plain stop), "yield" (waits, gives way, stops gently, lets the other go)
    or None."""
    lem = _lemmas(words[i])
    if not _is_verb(words[i]):
        return None
    if words[i].endswith(("ed", "ing")) and i + 1 < len(words) and set(_pos(words[i + 1])) == {"NOUN"}:
        return None  # ("Stopped car ahead": a participle before its noun)
    window = words[max(0, i - 3) : i + 5]
    if _off_the_road(words, i):
        return "evade"
    if lem & _EVADE:
        if lem & L.PRESSING and not _on_the_brakes(words, i + 1):
            return None  # (a brake only said of the pedal: not "stood at the kerb on my right", "jumps off")
        return "evade"
    if lem & _WORKING and not words[i].endswith("ing") and _brakes_worked(words, i):
        if set(window) & _MILD or lem & {"tap", "dab", "feather"}:
            return "yield"  # ("tapped the brakes", "gently applied the brake")
        return "evade" if set(words[i + 1 : i + 7]) & _HARD else "brake"  # ("hit the brakes", "used his brake")
    if lem & {"lock"} and set(words[i + 1 : i + 4]) & {"up", "wheels", "brakes", "tyres", "tires"}:
        return "evade"  # ("I locked up", "locked the wheels": braking as hard as it goes)
    if lem & {"brake"} and words[i + 1 : i + 2] == ["like"] and set(words[i + 2 : i + 3]) & _FURY:
        return "evade"  # ("braked like mad")
    if lem & _BRAKE or words[i] == "braking":
        if set(window) & _MILD or "behind" in words[i + 1 : i + 3]:
            return "yield"
        if set(window) & _HARD or _sharp_brake(words, i):
            return "evade"
        return "brake" if lem & {"brake"} else "stop" if lem & {"stop"} else None
    if lem & _YIELD:
        after = words[i + 1 : i + 4]
        if lem & {"give"} and not {"way", "priority", "precedence"} & set(words[i + 1 : i + 5]):
            return None  # (giving way, priority or precedence: "gives priority to the rider")
        if lem & {"let"} and not set(after) & _LET_GO and not (_lets_do(words, i) or _does_next(after)):
            return None  # (letting someone go, or do anything: "lets the ego complete the turn")
        if lem & {"hang", "hold"} and "back" not in after:
            return None
        if lem & {"wait"} and set(words[i + 1 : i + 8]) & _QUEUE:
            return None  # ("we waited in the queue", "waiting at the lights": one's turn, not giving way)
        return "yield"
    return None


def _sharp_brake(words: list[str], i: int) -> bool:
    """Whether "sharp" is said of the brake or stop at ``i``: right after its verb ("braked sharp") or
    right before it as a noun ("a sharp stop"); not "sharp" before another noun ("braked for a sharp
    bend")."""
    return words[i + 1 : i + 2] == ["sharp"] or words[i - 1 : i] == ["sharp"]


@dataclass(frozen=True)
class Cue:
    """One statement of the outcome found in a clause: what it says (``contact``, ``knock``: a light
    knock felt or heard, a contact unless a miss or a safe pass is said, ``hedged``,
    ``denied``, ``required``: a contact denied as what the test requires, ``near``, ``close``,
    ``safe``, ``lucky``: relief at luck, ``late``: the other seen late, ``unforced``: an escape not
    needed, ``evade``, ``brake``, ``yield``, ``critical``: the scenario rated so) and the words it was
    read from, so a reading can say why it chose its intent."""

    kind: str
    words: str


#: Modals of what a test requires ("must", "should", "needs to", "has to"); the past "had to" is what
#: was forced, and "must have" a guess, not a requirement.
_REQUIRING = frozenset(("must", "should", "shall", "needs", "need", "has", "have", "is", "are"))


def _required(sentence: list[str]) -> bool:
    """Whether ``sentence`` (its words so far) states what the test requires ("the ego must pass him",
    "should get by", "needs to overtake"): a modal of obligation, not "must have" nor "is driving"."""
    if set(sentence) & _HARD or any(_lemmas(w) & _EVADE for w in sentence):
        return False  # ("has to brake hard but must not hit it": a forced escape, whoever brakes)
    for k, w in enumerate(sentence):
        nxt = sentence[k + 1] if k + 1 < len(sentence) else ""
        if w in ("must", "should", "shall") and nxt != "have":
            return True
        if (
            w in ("needs", "need", "has", "have", "is", "are")
            and nxt == "to"
            and (w != "have" or k == 0 or sentence[k - 1] != "would")
        ):
            return True
    return False


def _after_contact_noun(words: list[str], i: int) -> int:
    """Where the noun phrase of a word at ``i`` begins after an earlier contact noun in its clause: a
    negation governs its own noun, not one set beside it ("no collision (near miss)")."""
    return max((k + 1 for k in range(i) if words[k] in _CONTACT_NOUNS and words[k - 1 : k] != ["near"]), default=0)


#: Harm to a road user (lemmas as passive participles): "was injured", "were badly hurt", "got killed".
_HARMED = frozenset(("injure", "hurt", "kill", "wound", "maim"))
#: Nouns of the consequences of a contact: denied ("no damage", "escaped injury"), a contact was not.
_HARM_NOUNS = frozenset(("damage", "injury", "injuries", "casualty", "casualties", "scratch", "dent"))
#: Words of being unhurt, said of a person ("the boy was fine"): no injury, which is not a safe pass.
#: A note's one-word verdict at the end of a sentence ("ego gives way -> ok").
_FINE = frozenset(("ok", "okay", "alright"))
_UNHURT = frozenset(("fine", "ok", "okay", "alright", "unhurt", "unharmed", "unscathed", "uninjured"))
_PASSIVE_AUX = frozenset(("was", "were", "got", "get", "gets", "is", "are", "been", "be", "being"))


#: Nouns of a mark left on a vehicle by a blow (singular and plural).
_DAMAGE = frozenset(("damage", "dent", "dents", "scratch", "scratches", "scrape", "scrapes"))
#: Prepositions that name where such a mark is ("damage to my wing", "a dent in the door", "damage at both cars").
_DAMAGE_PLACE = frozenset(("to", "in", "on", "at", "of"))
#: Quantifiers that may open the vehicles damaged ("damage at both vehicles", "scratches on all the cars").
_BOTH = frozenset(("both", "all", "each", "either"))


def _damage_to_a_vehicle(words: list[str], i: int) -> bool:
    """Whether the noun of damage at ``i`` is said of a vehicle or a part of one ("slight damage to my
    nearside wing", "a dent in the passenger door", "sheet metal damage at both vehicles"): the mark
    of a contact, which a report states instead of the blow. Not damage to a thing ("damage to the
    kerb")."""
    if words[i] not in _DAMAGE or words[i + 1 : i + 2] == [] or words[i + 1] not in _DAMAGE_PLACE:
        return False
    obj = [w for w in words[i + 2 : i + 7] if w not in _BOTH]
    return _vehicle_part(obj) or names_road_user(obj[:4]) or bool(obj[:1] and obj[0] in _EGO_HEADS)


def _person_subject(words: list[str], i: int, inherited: str | None = None) -> bool:
    """Whether the predicate at ``i`` (after a copula or passive auxiliary and adverbs) is said of a
    person or road user: "a pedestrian was killed", "the boy was fine", "she was okay". ``inherited``:
    the subject the clause carries from the clause before it; a clause that opens on its auxiliary
    says its predicate of that one ("the boy stepped back and was not hurt"), if it is not the ego."""
    k = i - 1
    while k >= 0 and (words[k].endswith("ly") or words[k] in _DEGREE | {"not", "all"}):
        k -= 1
    if k < 0 or words[k] not in _PASSIVE_AUX:
        return False
    if k == 0 and inherited == "other":
        return True  # ("... and was unhurt": said of the road user of the clause before)
    subject = words[max(0, k - 4) : k]
    return bool(subject) and any(
        x
        in (
            "he",
            "she",
            "they",
            "everyone",
            "everybody",
            "nobody",
            "kid",
            "boy",
            "girl",
            "baby",
            "rider",
            "one",
            "no-one",
            "noone",
            "someone",
            "somebody",
            "anyone",
            "anybody",
        )
        or _road_user_word(x)
        for x in subject
    )


def _nobody_before(words: list[str], i: int) -> bool:
    """Whether the harm participle at ``i`` has a negative pronoun right before it ("nobody hurt",
    "no one injured", "no-one hurt"): no one was harmed, the auxiliary left out as reports do."""
    if i > 1 and words[i - 1] in _PASSIVE_AUX:
        i -= 1  # ("no-one was injured", "nobody got hurt": the auxiliary said)
    return i > 0 and (words[i - 1] in ("nobody", "no-one", "noone") or words[i - 2 : i] == ["no", "one"])


#: Words of relief at luck ("luckily", "so lucky I was only doing 20"): said of an event, a close call.
_RELIEF = frozenset(("luckily", "thankfully", "fortunately"))


def _relief(words: list[str], i: int) -> bool:
    """Relief said at ``i``: an adverb of luck, or "lucky" as a verdict ("so lucky I ...", "lucky
    that ...", "we were lucky"), not before its noun ("a lucky charm")."""
    if words[i] in _RELIEF:
        return True
    if words[i] != "lucky":
        return False
    nxt = words[i + 1] if i + 1 < len(words) else ""
    return not nxt or nxt in ("i", "we", "that", "it", "he", "she", "they") or "NOUN" not in _pos(nxt)


#: Words of nearness before "from"/"to" a contact ("inches from hitting", "so close to a crash", "a
#: split second away from"): the units of a small margin, and of a short time.
_NEARNESS = _SMALL_UNITS | frozenset(
    ("close", "closer", "near", "nearer", "away", "short", "millimetres", "millimeters", "second", "seconds",
     "moment", "moments", "metre", "metres", "meter", "meters", "yards")
)  # fmt: skip


def _near_to(words: list[str], i: int) -> bool:
    """Whether the contact at ``i`` (a verb's gerund or a noun) is what someone came near to ("I was
    millimetres from hitting him", "came so close to running him over", "seconds from a collision"):
    a measure of nearness, then "from", "to" or "of", then the contact: it was not made."""
    k = i - 1
    while k >= 0 and words[k] in ("a", "an", "the"):
        k -= 1
    if k >= 1 and words[k].endswith("ing") and words[k - 1] in ("from", "to", "of"):
        k -= 1  # ("close to going under the wheels", "seconds from ending up in the side of it")
    if k >= 2 and words[k] == "up" and words[k - 1].endswith("ing"):
        k -= 2  # ("came close to ending up under the bus")
    if k < 1 or words[k] not in ("from", "to", "of"):
        return False
    if words[k] == "to" and not _came_near(words, k):
        return False  # ("I had to hit the brakes", "went to clip him": not a nearness)
    if words[k] == "of" and words[k - 1] != "short":
        return False  # ("just short of hitting him"; not "the moment of impact")
    return bool(set(words[max(0, k - 4) : k]) & _NEARNESS)


def _came_near(words: list[str], k: int) -> bool:
    """Whether "to" at ``k`` follows a nearness: right after it ("close to hitting him") or after a
    verb of coming or getting that follows it ("how close he came to going under", "so near we got
    to hitting it"); not "had to", "went to"."""
    if words[k - 1] in ("close", "closer", "near", "nearer"):
        return True
    if not _lemmas(words[k - 1]) & {"come", "get"}:
        return False
    return bool(set(words[max(0, k - 4) : k - 1]) & {"close", "closer", "near", "nearer"})


#: Verbs of a belief or an expectation held at the time ("I thought I'd hit him", "we braced for impact").
_BELIEVING = frozenset(("thought", "expected", "feared", "braced", "reckoned", "assumed"))
#: Adjectives of a belief, after a past copula ("I was sure I'd hit it", "was convinced he'd hit me").
_SURE = frozenset(("sure", "certain", "convinced", "positive"))
_PRONOUNS = frozenset(("i", "we", "he", "she", "they", "ego"))


def _believed(words: list[str], i: int) -> bool:
    """Whether the contact at ``i`` is what someone believed or expected would happen ("I thought I
    was going to hit him", "I honestly thought I'd hit her", "I was sure I'd hit it", "we braced for
    impact"): it did not happen as said (a contact that did is said again: "... and I did"). Only a
    belief of a person said as such (a pronoun before it), not a spec's "Expected: collision"."""
    for k in range(max(0, i - 7), i):
        w = words[k]
        if w in _BELIEVING or (w in _SURE and words[k - 1 : k] in (["was"], ["were"])):
            j = k - 1 if w in _BELIEVING else k - 2
            while j >= 0 and (words[j].endswith("ly") or words[j] in ("really", "fully", "half", "genuinely")):
                j -= 1
            if j >= 0 and words[j] in _PRONOUNS:
                return True
    return False


def _in_question(words: list[str], i: int) -> bool:
    """Whether the contact at ``i`` is in a question embedded after "whether", or after "if" that
    follows a word of knowing or certainty ("not clear if the car touched her", "wasn't sure if the
    van hit him", "don't know whether it clipped him"): neither asserted nor denied, a hedge."""
    for k in range(i - 1, -1, -1):
        if words[k] == "whether":
            return True
        if words[k] == "if":
            return k > 0 and (
                words[k - 1] in _SURE | {"clear", "unsure", "uncertain"}
                or bool(_lemmas(words[k - 1]) & {"know", "tell"})
            )
    return False


#: Verbs (lemmas) of a fright someone was given ("scared the life out of me", "it terrified us").
_FRIGHTENING = frozenset(("scare", "frighten", "terrify", "petrify", "startle", "spook"))


def _fright(words: list[str], i: int) -> bool:
    """An idiom of a fright at ``i``, which says how close it came: a verb of scaring with the narrator
    as its object ("scared the life out of me", "frightened us half to death"), "heart in my mouth",
    "(nearly) had a heart attack", "my life flashed before my eyes", "a brown-trouser moment"."""
    w = words[i]
    after = words[i + 1 : i + 7]
    if _is_verb(w) and _lemmas(w) & _FRIGHTENING and not w.endswith("ing"):
        out_of = any(after[k : k + 3] in (["out", "of", "me"], ["out", "of", "us"]) for k in range(len(after)))
        return out_of or after[:1] in (["me"], ["us"]) or _names_ego(after[:2])  # (not "scared the cyclist")
    if w == "heart" and (words[i + 1 : i + 3] == ["in", "my"] or words[i + 1 : i + 3] == ["in", "our"]):
        return True
    if w == "heart" and words[i + 1 : i + 2] == ["attack"] and bool(set(words[max(0, i - 4) : i]) & (HEDGES | {"had"})):
        return True
    if w == "life" and words[i + 1 : i + 2] == ["flashed"]:
        return True
    return (
        w.startswith("brown")
        and words[i + 1 : i + 2] in (["trouser"], ["trousers"])
        or w
        in (
            "brown-trouser",
            "brown-trousers",
        )
    )


#: Words of how bad something would have been ("could have been nasty", "would have been a disaster").
_BAD = frozenset(
    ("bad", "worse", "nasty", "ugly", "serious", "fatal", "disaster", "disastrous", "tragic", "tragedy", "messy",
     "horrible", "horrific", "terrible", "awful", "catastrophic", "catastrophe", "carnage", "deadly", "grim", "dire",
     "curtains", "badly", "tears", "story", "game", "critical")
)  # fmt: skip
#: Nouns of a disaster, which a hedge makes one that nearly happened ("nearly a disaster").
_DISASTERS = frozenset(("disaster", "tragedy", "catastrophe", "carnage"))
#: Verbs of how something turns out, after a modal perfect ("could have ended badly", "might have gone").
_TURNING_OUT = frozenset(("been", "ended", "gone", "turned", "finished", "got"))


def _could_have_been_bad(words: list[str], i: int) -> bool:
    """A word of badness at ``i`` under "would/could/might have been" (or "ended", "gone") in its
    clause: what the event could have been ("could have been nasty", "it'd have been a different
    story", "could have ended in tears", "would have been game over"); it was not, a near miss. Not
    "should have" (what was due) nor "would have been better" (a judgement of another choice)."""
    if words[i] == "story" and words[i - 1 : i] != ["different"]:
        return False  # (only "a different story")
    if words[i] == "game" and words[i + 1 : i + 2] != ["over"]:
        return False  # (only "game over")
    for k in range(max(0, i - 7), i):
        if words[k] not in ("would", "could", "might"):
            continue
        if "have" in words[k + 1 : k + 4]:
            h = words.index("have", k + 1)
            return bool(set(words[h + 1 : i]) & _TURNING_OUT) or words[h + 1 : h + 2] == [words[i]]
        if words[k + 1 : k + 2] and words[k + 1] in _TURNING_OUT - {"got"}:
            return True  # ("could've been bad" with its "'ve" dropped: "could been bad")
    return False


def _within(words: list[str], i: int) -> bool:
    """ "within" at ``i`` with a small margin "of" someone ("came within a foot of my door", "within
    inches of her handlebars", "within a couple of feet of us", "within a hair's breadth of my
    mirror"): the two came that near, a near miss; not "within 2 m of the kerb"."""
    after = words[i + 1 : i + 9]
    unit = next((k for k, x in enumerate(after[:6]) if x in _SMALL_UNITS | _LENGTH_UNITS), None)
    if unit is None or after[unit + 1 : unit + 2] != ["of"]:
        return False
    said = after[: unit + 1]
    if after[unit] in _LENGTH_UNITS - _SMALL_UNITS or after[unit] in ("foot", "feet"):
        metres = _length_said([x for x in said if x not in ("couple", "of")])
        if metres is None and "couple" in said:
            metres = 2.0 * _UNIT_METRES.get(after[unit], 1.0)
        if metres is None or metres > 3.0:
            return False
    obj = after[unit + 2 : unit + 6]
    return bool(obj) and (
        obj[0] in _PERSON_OBJECTS | _POSSESSIVES | _EGO_HEADS
        or names_road_user(obj)
        or _vehicle_part(obj)
        or obj[0].endswith("ing")
    )


def _close_idiom(words: list[str], i: int, whole: list[str], at: int) -> bool:
    """An idiom of a close call at ``i``: "too close for comfort", "touch and go" (read in ``whole``,
    its sentence, as "and" ends a clause; ``at`` where the clause starts in it), "closer than I'd
    like"."""
    w = words[i]
    if w == "close" and words[i + 1 : i + 3] == ["for", "comfort"]:
        return True
    if w == "touch" and whole[at + i : at + i + 3] == ["touch", "and", "go"]:
        return True
    return (
        w == "closer"
        and words[i + 1 : i + 2] == ["than"]
        and bool(set(words[i + 2 : i + 6]) & {"like", "liked", "comfortable", "wanted", "expected", "usual", "normal"})
    )


def _seen_late(words: list[str], i: int, whole: list[str], at: int) -> bool:
    """A verb of seeing at ``i``, denied, "until" something late ("didn't see him until Dad shouted",
    "never noticed the scooter till it was right there"; read in ``whole``, its sentence, as "until"
    ends a clause; ``at`` where the clause starts in it): the other was seen too late to be far off."""
    if not (_is_verb(words[i]) and _lemmas(words[i]) & {"see", "spot", "notice"} and _denied_before(words, i)):
        return False
    return bool({"until", "till", "til"} & set(whole[at + i + 1 : at + i + 6]))


#: An escape said as a noun phrase ("took evasive action", "did an emergency stop", "had to emergency brake").
_ESCAPE_HEADS = frozenset(("action", "stop", "stops", "brake", "braking", "manoeuvre", "maneuver", "swerve"))


def _escape_noun(words: list[str], i: int) -> bool:
    """ "evasive" or "avoiding" before "action", or "emergency" before a stop, a brake or a manoeuvre,
    at ``i``: the one it is said of had to escape."""
    nxt = words[i + 1 : i + 2]
    if words[i] in ("evasive", "avoiding"):
        return nxt == ["action"]
    return words[i] == "emergency" and bool(nxt) and nxt[0] in _ESCAPE_HEADS


#: Verbs (lemmas) of an escape whose need, denied, leaves nothing forced ("didn't need to brake").
_ESCAPING = _EVADE | _BRAKE | frozenset(("slow", "react", "steer", "flinch", "avoid"))


def _need_denied(words: list[str], i: int) -> bool:
    """Whether the verb of escape at ``i`` is said as not needed ("didn't even have to brake", "I
    didn't need to slow", "never had to swerve", "no need to brake or swerve", "without having to
    brake", "nobody had to flinch"): a need before it, denied."""
    before = words[max(0, i - 6) : i]
    need = next(
        (k for k, x in enumerate(before) if x in ("need", "needs", "needed", "have", "has", "had", "having")), None
    )
    if need is None or "to" not in before[need + 1 :]:
        return False
    k = need - 1
    while k >= 0 and before[k] in ("even", "ever", "really", "actually", "once"):
        k -= 1
    return k >= 0 and before[k] in ("not", "never", "no", "without", "nobody", "no-one", "noone")


#: Verbs (lemmas) of a need or a compulsion whose complement is an act forced on its doer ("had to
#: swerve", "needed to brake hard", "was forced to", "obliged to").
_NEEDING = frozenset(("have", "need", "force", "oblige", "compel"))
#: Verbs (lemmas) that force an act on their object ("made me swerve", "forcing him to brake hard").
_CAUSING = frozenset(("make", "force", "cause", "oblige", "compel"))
#: Words of a condition, a counterfactual or a time to come: a need under one was not met ("would
#: need to brake", "might have to swerve", "if you have to stop", "will need to").
_UNREAL = _HYPOTHETICAL | frozenset(("will", "may", "shall", "unless", "in", "case"))


def _maker(words: list[str], i: int) -> int | None:
    """Where "make" stands before the bare verb at ``i`` with only its object between ("made me
    swerve", "made the poor cyclist brake hard"): the object was made to act; None if it does not."""
    for k in range(i - 2, max(-1, i - 5), -1):
        between = words[k + 1 : i]
        person = between[-1] in _PERSON_OBJECTS - {"one", "each", "it"} or _road_user_word(between[-1])
        if _lemmas(words[k]) & {"make"} and person and all(not _is_verb(x) or x in _PERSON_OBJECTS for x in between):
            return k
    return None


def _compelled(words: list[str], i: int) -> bool:
    """Whether the verb at ``i`` is an act its doer was made to do: the complement of a need ("had
    to", "needed to", "need to", "was forced to") or the object's act after a verb that causes it
    ("made me swerve", "forcing him to brake hard"), said of anyone, ego or not. Not when the need is
    under a condition, a counterfactual or a future ("would have had to", "might need to", "will
    need to"): nothing was forced yet."""
    k = None
    if words[i - 1 : i] == ["to"] and i >= 2 and _lemmas(words[i - 2]) & _NEEDING:
        k = i - 2  # ("had to swerve", "needed to brake hard", "was forced to")
    elif words[i - 1 : i] == ["to"] and i >= 3 and _lemmas(words[i - 3]) & _CAUSING:
        k = i - 3  # ("forcing me to brake", "forced the bus to swerve")
    else:
        k = _maker(words, i)  # ("made me swerve", "made the cyclist brake hard")
    if k is None or not _is_verb(words[k]):
        return False
    return not _scoped(words, k, _UNREAL, 4)


def _forced_stop(words: list[str], i: int, rest: list[str], sentence: list[str]) -> bool:
    """Whether the compelled verb at ``i`` is a plain brake or stop not made in a queue ("had to stop
    halfway", "the driver had to brake"; not "had to stop at the lights"): a stop the situation forced,
    which is no giving way, however softly it was made. Not a stop made to give way either: to let
    someone go ("had to stop to let her cross", "and let it go"), for a road user ("had to stop for
    the pedestrians"), or at a place of giving way ("at the give way line", "at the junction", a foot
    crossing in its sentence): a wait. ``rest``: its sentence after it; ``sentence``: all of it."""
    if _ego_acts(words, i) not in ("brake", "stop") or set(words[i + 1 : i + 5]) & _QUEUE:
        return False
    if any(_lemmas(x) & {"let"} for x in rest[:3]) or _lets_another_go(words, i, rest):
        return False  # ("had to stop to let a pedestrian cross", "had to stop for a cyclist")
    crossing = set(sentence) & (FOOT_CROSSINGS - {"pedestrian"})  # ("stepped onto the zebra so I had to stop")
    at = rest[:1] == ["at"] and set(rest[1:4]) & {"give", "junction", "crossing", "crossroads"}
    return not (crossing or at)


def _hortative(words: list[str], i: int) -> bool:
    """Whether "let" at ``i`` opens its clause with the narrator as its object ("Let us all take care",
    "let's be careful out there", read as "let the ego ..."), the clause opening its sentence (see the
    caller): an imperative of the first person plural, a wish said to the reader, not a road user let
    through ("he stopped and let us go" has its subject), nor a call to be let go ("Let us through!")."""
    us = 2 if words[1:3] == ["the", "ego"] else 1 if words[1:2] == ["us"] else 0
    return i == 0 and words[0] == "let" and us > 0 and not set(words[us + 1 : us + 2]) & _LET_GO


def _only_just(words: list[str], i: int) -> bool:
    """Whether "only" up to five words before the contact at ``i`` hedges it ("only just clipped him",
    "only narrowly missed", "the van only didn't hit me because ..."), not a contact made light of
    ("it was only a fender bender", "only a scratch on the bumper", "only a light tap")."""
    for k in range(max(0, i - 5), i):
        if words[k] == "only" and not (words[k + 1 : k + 2] and words[k + 1] in ("a", "an", "the", "some")):
            return True
    return False


def _contact_kind(words: list[str], i: int, clause: _Clause, sentence: list[str]) -> str | None:
    """What the contact stated at ``words[i]`` (a word :func:`_is_contact` accepts) says happened:
    "contact", "hedged" ("nearly hit", "would have hit"), "denied" ("did not hit", "no contact") or
    "required" (a contact a test says must not happen); None where it says nothing of the road users
    (a warning of what may happen to anyone, hitting the kerb while escaping someone). ``sentence``:
    its sentence's words up to the end of its clause."""
    if _escaping_into_furniture(words, i, sentence) or _predicted(words, i) or _named_as_a_risk(words, i):
        return None  # ("swerved to miss him and hit the kerb", "someone is going to get hit here")
    if _threatened(words, i):
        return "hedged"  # ("the ego must brake or they will collide": what the alternative would bring)
    if _supposed_event(words, i):
        return None  # ("the impact would occur at 50 %": an event supposed, not one that happened)
    before = sentence[: len(sentence) - len(words) + i]
    passive = _denied_after(words, i)  # ("collision narrowly avoided", "a crash was averted")
    hedged = _scoped(words, i, HEDGES | {"within"}, 5) or passive == "hedged" or _near_to(words, i)
    hedged = hedged or _near_as_nearly(words, i)
    hedged = hedged or _only_just(words, i) or _near_enough(words, i)
    hedged = hedged or _believed(words, i) or _in_question(words, i)
    hedged = hedged or (_contact_noun(words[i]) and only_thought_of(words, i))  # ("a crash is unthinkable")
    counterfactual = "have" in words[:i] and (
        _scoped(words, i, _HYPOTHETICAL, 3) or clause.after_if or _modal_perfect(words, i)
    )
    counterfactual = counterfactual or _past_condition(words, i)
    if hedged or counterfactual:
        return "hedged"
    if _wondered_at(words, i):
        return "hedged"  # ("how nobody got hit I'll never know": it came that close)
    if _denied_before(words, i) or _scoped(words, i, _HYPOTHETICAL, 2) or passive == "denied":
        # ("must overtake him and not touch him": the outcome the test wants, no contact)
        return "required" if _required(before) else "denied"
    return "contact"


#: Words that may stand between "had" and the verb of a past condition ("if I had actually hit him").
_BETWEEN_HAD = frozenset(("actually", "really", "ever", "just", "even", "then", "also", "already"))


def _past_condition(words: list[str], i: int) -> bool:
    """Whether the contact at ``i`` is the verb of a condition in the past perfect ("if I had hit the
    Fiesta", "if the van had clipped him", "had I hit him"): English's third conditional supposes what
    did not happen, as "would have hit" does. Not "if" after a verb of finding out ("stopped to see if
    I had hit her"), which asks whether it did."""
    k = i - 1
    while k >= 0 and words[k] in _BETWEEN_HAD:
        k -= 1
    if k >= 1 and words[k] in SUBJECT_PRONOUNS and words[k - 1] == "had":
        return k == 1 or words[k - 2] in CLAUSE_BREAKS or words[k - 2] in _BREAK_PUNCT  # ("had I hit him")
    if k < 1 or words[k] != "had":
        return False
    opener = next((j for j in range(k - 1, max(-1, k - 5), -1) if words[j] in ("if", "unless")), None)
    if opener is None or any(w in _BREAK_PUNCT for w in words[opener:k]):
        return False
    before = words[max(0, opener - 2) : opener]  # ("to see if", "asked me if", "can't say if")
    asked = any(w in _SURE or _lemmas(w) & _FINDING_OUT for w in before)
    return not asked  # ("got out to see if I had hit her": whether it happened, asked)


#: Verbs (lemmas) after which "if" asks whether something happened ("to see if I had hit her").
_FINDING_OUT = frozenset(("see", "check", "know", "ask", "wonder", "tell", "look", "find", "learn", "say", "remember"))


#: Verbs (lemmas) of knowing or understanding how something came about.
_KNOWING = frozenset(("know", "understand", "explain", "tell"))


def _wondered_at(words: list[str], i: int) -> bool:
    """Whether the contact at ``i``, denied in a "how" clause, is the object of a denied verb of
    knowing ("how nobody got hit I'll never know", "I don't know how he didn't hit me", "no idea how we
    didn't collide"): the writer wonders that it did not happen, which says it came very close. (The
    wh-clause ends the negation's scope: :func:`_denied_before` reads its own denial alone.)"""
    how = next((k for k in range(i - 1, -1, -1) if words[k] == "how"), None)
    if how is None or not _denied_before(words, i):
        return False  # ("I don't know how he hit me": the contact itself is told)
    knowing = [k for k, w in enumerate(words) if _lemmas(w) & _KNOWING and _is_verb(w)]
    denied = any(set(words[max(0, k - 3) : k]) & _NEGATORS for k in knowing)
    return denied or words[max(0, how - 2) : how] == ["no", "idea"]


def _near_as_nearly(words: list[str], i: int) -> bool:
    """Whether "near" stands right before the verb of contact at ``i`` ("near wiped out a biker", "he
    near hit me"): the adverb "nearly" in its older and dialect form, a hedge. After a determiner it is
    the adjective of a noun ("a near hit", "a near collision"), read as a near miss elsewhere."""
    if i == 0 or words[i - 1] != "near" or not _is_verb(words[i]) or words[i].endswith(("s", "ing")):
        return False
    return i < 2 or words[i - 2] not in _DETERMINERS  # (not "a near hit": the noun)


def _contact_noun(w: str) -> bool:
    """Whether ``w`` is a noun of contact or its plural ("a collision", "crashes")."""
    return w in _CONTACT_NOUNS or (w.endswith("s") and w[:-1] in _CONTACT_NOUNS)


def _supposed_event(words: list[str], i: int) -> bool:
    """Whether the noun of contact at ``i`` is the subject of a modal of supposition ("the impact
    would occur", "a collision could happen", "a crash might follow"): the event is supposed, not
    told. Not "should" or "will": a test's "collision should happen" is the outcome it requires; nor
    a modal perfect ("the crash could have killed my son", "the impact would have been worse"), which
    supposes what the contact that happened did or might have been."""
    noun = _contact_noun(words[i])
    perfect = words[i + 2 : i + 3] in (["have"], ["'ve"])
    return noun and words[i + 1 : i + 2] != [] and words[i + 1] in _MODALS - {"should"} and not perfect


def _near_enough(words: list[str], i: int) -> bool:
    """Whether "near enough" (almost) stands before the contact at ``i`` in its clause ("near enough
    had my first shunt", "near enough took my bumper off"); "near enough to touch" is a distance."""
    before = words[max(0, i - 5) : i]
    return any(before[k : k + 2] == ["near", "enough"] and before[k + 2 : k + 3] != ["to"] for k in range(len(before)))


#: Nouns of what may come: a contact noun as their "of" complement names a danger, not an event.
_POSSIBILITY = frozenset(
    ("risk", "risks", "danger", "dangers", "chance", "chances", "possibility", "threat", "likelihood", "probability")
)


def _named_as_a_risk(words: list[str], i: int) -> bool:
    """Whether the contact noun at ``i`` is the complement of a noun of possibility ("a risk of head-on
    collisions", "the danger of a crash"; an adjective or determiner between): what may happen in such
    a place, which says nothing of what happened in this scene."""
    k = next((k for k in range(i - 1, max(-1, i - 4), -1) if words[k] == "of"), None)
    return k is not None and k > 0 and words[k - 1] in _POSSIBILITY


#: Conjunctions of an alternative: what follows is what comes if the act before is not done.
_ALTERNATIVE = frozenset(("or", "otherwise", "else"))


def _threatened(words: list[str], i: int) -> bool:
    """Whether the contact at ``i`` is the consequence threatened by an alternative, a modal between
    ("must brake or they will collide", "swerve, otherwise we'd hit him"): it follows only if the act
    is not done, so it did not happen."""
    k = next((k for k in range(i - 1, -1, -1) if words[k] in _ALTERNATIVE), None)
    return k is not None and any(w in _MODALS | {"will", "may"} for w in words[k + 1 : i])


#: The answers of a form's field that deny what its label names ("Contact: none", "Collision: N").
_NO_VALUES = frozenset(("no", "none", "nil", "n", "0", "false", "zero", "nope", "negative", "nothing"))
#: Quantity words that, right before a noun of contact, count none of it ("zero contact", "0 collisions").
_NONE_OF = frozenset(("zero", "0", "nil"))
#: What ends a field's value: the end of its sentence or of its field.
_FIELD_ENDS = frozenset(".;!?,")


def _field_noun(w: str) -> bool:
    """Whether ``w`` is a noun of contact or of harm, the label of a form's field of the outcome
    ("Collision", "Contacts", "Injuries")."""
    return w in _CONTACT_NOUNS | _HARM_NOUNS or (w.endswith("s") and w[:-1] in _CONTACT_NOUNS)


def _fields_answered(tokens: list[str]) -> list[str]:
    """``tokens`` with a field that denies its contact said as a negation, word for word in place:
    "contact : none ." as "no contact . .", "0 collisions" as "no collisions". A form answers its
    field with a bare value after the colon, which the clauses would otherwise read apart (and "contact"
    alone as a contact). Only a value that ends its field is an answer ("collision : n a" is not
    applicable); a label that is a compound's first noun stays what it was ("collision warning : none")."""
    out = list(tokens)
    for k, w in enumerate(tokens):
        if not _field_noun(w):
            continue
        end = tokens[k + 3] if k + 3 < len(tokens) else "."
        if (
            tokens[k + 1 : k + 2] == [":"]
            and k + 2 < len(tokens)
            and tokens[k + 2] in _NO_VALUES
            and end in _FIELD_ENDS
        ):
            out[k : k + 3] = ["no", w, "."]  # ("Contact: none.", "collision: no")
        elif k > 0 and tokens[k - 1] in _NONE_OF:
            out[k - 1] = "no"  # ("zero contact", "0 collisions in 20 runs")
    return out


#: The labels of a field that rates the scenario as a whole ("Result: critical", "Criticality: high").
_VERDICT_LABELS = frozenset(
    ("result", "outcome", "expected", "expectation", "verdict", "intent", "class", "classification", "category",
     "criticality", "rating", "assessment", "rated")
)  # fmt: skip
#: What a test rates: "the scenario is critical", "this case is highly critical".
_RATED = frozenset(("scenario", "case", "test", "run", "manoeuvre", "maneuver", "event"))
#: Degree adverbs between a copula and "critical" ("is highly critical", "deemed safety-critical").
_CRITICAL_DEGREE = frozenset(("highly", "very", "really", "so", "quite", "extremely", "considered", "deemed", "rated",
                              "classed"))  # fmt: skip


def _rated_critical(tokens: list[str]) -> bool:
    """Whether the text rates its scenario critical, the class a test row or a requirement states: a
    cell or a sentence of its own ("| Critical |", "Critical."), the value of a verdict's field
    ("Result: critical"), the predicate of the scenario or the case ("the scenario is critical by
    construction"), or the label of one ("Critical scenario: ..."). Not "critical" said of something
    else ("in critical condition", "the critical moment", "it is critical that"), denied ("not
    critical") or a field's label answered ("Critical: no")."""
    for k, w in enumerate(tokens):
        if w != "critical":
            continue
        prev = tokens[k - 1] if k > 0 else "."
        nxt = tokens[k + 1] if k + 1 < len(tokens) else "."
        if nxt in _FIELD_ENDS and (
            prev in _FIELD_ENDS or (prev == ":" and tokens[k - 2 : k - 1] and tokens[k - 2] in _VERDICT_LABELS)
        ):
            return True  # ("| Critical |", "Result: critical.")
        if nxt in ("scenario", "case") and tokens[k + 2 : k + 3] in ([":"], ["."], [","], []):
            return True  # ("Critical scenario: ...", "This is a critical case.")
        j = k - 1
        while j >= 0 and tokens[j] in _CRITICAL_DEGREE:
            j -= 1
        if j >= 1 and tokens[j] in _COPULA and tokens[j - 1] in _RATED and nxt not in ("that", "to", "for"):
            return True  # ("the scenario is critical by construction")
    return False


#: Verbs (lemmas) and nouns of an emergency system's going off ("AEB triggered", "the AEB kicked in").
_TRIGGERING = frozenset(("trigger", "activate", "fire", "kick", "intervene", "engage", "deploy", "activation",
                         "intervention"))  # fmt: skip
#: What a criticality is said to be when the scene came close ("Criticality: high", "high criticality").
_HIGH = frozenset(("high", "severe", "extreme", "critical"))
#: Words between "criticality" and its value ("criticality: high", "criticality was very high").
_RATING_FILLERS = frozenset((":", "=", "-", "is", "was", "level", "rating", "very", "rated"))
#: Verbs (lemmas) a frightened heart does ("heart pounding", "my heart was racing").
_HEART_BEATING = frozenset(("pound", "race", "thump", "hammer", "pump"))
#: Words of a fright felt ("I was shaking", "left me shaken", "terrified").
_AFRAID = frozenset(("terrified", "petrified", "shaken", "shaking", "panicked", "panicking", "adrenaline"))
_NEGATING = frozenset(("no", "not", "never", "without", "nothing", "failed", "fails"))


def _emergency_said(tokens: list[str]) -> bool:
    """Whether the description says an emergency anywhere, not denied: an emergency brake that went
    off ("AEB triggered", "the emergency brake kicked in", "triggered the AEB", "AEB activation"), a
    criticality said high ("Criticality: high", "high criticality"), or fear ("heart pounding", "I was
    shaking", "terrified"). Alone it states no outcome; a stop with room to spare said with it was the
    end of an emergency stop (see :func:`decide`)."""
    for k, w in enumerate(tokens):
        if w in _EMERGENCY_BRAKES or (w == "emergency" and tokens[k + 1 : k + 2] in (["brake"], ["brakes"])):
            near = tokens[max(0, k - 3) : k] + tokens[k + 1 : k + 5]
            if any(_lemmas(x) & _TRIGGERING or x in _TRIGGERING for x in near) and not set(near) & _NEGATING:
                return True
        if w == "criticality":
            value = next((x for x in tokens[k + 1 : k + 5] if x not in _RATING_FILLERS), "")
            if value in _HIGH:
                return True  # ("Criticality: high")
        if w == "criticality" and tokens[k - 1 : k] == ["high"] and tokens[k - 2 : k - 1] not in (["not"], ["no"]):
            return True  # ("high criticality")
        if w == "heart" and any(_lemmas(x) & _HEART_BEATING for x in tokens[k + 1 : k + 4]):
            return True  # ("heart pounding", "my heart was racing")
        if w in _AFRAID and not set(tokens[max(0, k - 3) : k]) & _NEGATING:
            return True
    return False


def contacts_made(tokens: list[str]) -> list[int]:
    """The indices of the words of ``tokens`` (the reader's lowercased tokens) that state a contact
    between road users that happened: a verb or noun of contact whose object is a road user (not "hit
    the brakes", "tapped the horn", "touched 50"), neither denied ("did not hit", "without touching")
    nor hedged ("nearly clipped", "would have hit"). The one test of contact that the outcome and the
    readers of what follows a contact (a stop that is its aftermath) share."""
    out: list[int] = []
    cursor = 0
    sentence: list[str] = []
    tokens = _fields_answered(tokens)
    for clause in _clauses(tokens):
        words = clause.words
        at = next((k for k in range(cursor, len(tokens)) if tokens[k : k + len(words)] == words), cursor)
        cursor = at + len(words)
        sentence = words if clause.first_of_sentence else sentence + words
        for i in range(len(words)):
            if _is_contact(words, i) and _contact_kind(words, i, clause, sentence) == "contact":
                out.append(at + i)
    return out


#: Words that may open a verdict's clause before its negator ("there was no contact", "with no collision").
_VERDICT_OPENERS = frozenset(("there", "was", "were", "is", "be", "been", "had", "has", "with", "absolutely", "and",
                              "thankfully", "luckily", "fortunately", "so", "but"))  # fmt: skip
#: Words that open a denial of everyone, or one with its subject left out as a message does ("nobody
#: touched", "neither hit the other", "Never hit him.").
_NOBODY = frozenset(("nobody", "neither", "noone", "no-one", "none", "never"))
#: Words of degree that deny only how hard a contact was ("did not hit him hard", "no serious collision").
_GRADED = frozenset(("hard", "badly", "much", "properly", "fully", "squarely", "full", "head-on", "serious", "major",
                     "big", "real", "heavy", "significant", "proper", "bad", "fast", "that"))  # fmt: skip


def _verdict_denial(words: list[str], i: int, doer: str | None) -> bool:
    """Whether the contact at ``i``, denied, is the writer's verdict on the scene ("No contact.", "no
    collision occurred", "nobody touches", "I didn't hit him", "we never touched"): a negator on it with
    nothing before it but words of existence, or a denial of everyone, of the ego or of contact with the
    ego ("the van never touched us"). Not a denial said
    of a third road user ("the lorry behind pulled up without contact"), not a time before the impact
    ("braked 0.6 s before impact": no negator), nor one of degree only ("didn't hit him hard")."""
    neg = next((k for k in range(i - 1, max(-1, i - 4), -1) if words[k] in _NEGATORS), None)
    if neg is None or set(words[neg + 1 : i + 4]) & _GRADED:
        return False
    if words[neg] == "no" and all(w in _VERDICT_OPENERS for w in words[:neg]):
        return True  # ("No contact.", "there was no collision", "no contact occurred")
    if words[0] in _NOBODY or words[:2] == ["no", "one"] or doer == "ego":
        return True  # ("nobody touches", "I did not hit him", "Never touched him.")
    return words[i + 1 : i + 2] in (["me"], ["us"], ["ego"]) or words[i + 1 : i + 3] in (["the", "ego"], ["my", "car"])


def _overruled(cues: list[Cue], sentence_of: list[int], verdict: int | None) -> list[Cue]:
    """``cues`` with each contact said in a sentence before ``verdict`` (the last sentence whose verdict
    denies contact or names the scene a near miss) kept as ``overruled``: a writer who ends on "no
    contact" did not mean the earlier word of contact of this scene ("a crash on the ring road, so we
    went the back way", "the road was rammed", "risk of vans striking cyclists"). A contact in the
    verdict's own sentence or after it
    stands ("clipped my mirror, but no contact with him"; "no contact with the first, the second hit me")."""
    if verdict is None:
        return cues
    return [
        Cue("overruled", c.words)
        if c.kind in ("contact", "knock") and k < len(sentence_of) and sentence_of[k] < verdict
        else c
        for k, c in enumerate(cues)
    ]


def _holds(sentence: list[str], words: list[str]) -> bool:
    """Whether ``sentence`` holds the clause ``words`` as a run of its words."""
    return any(sentence[k : k + len(words)] == words for k in range(len(sentence) - len(words) + 1))


def outcome_cues(said: str, named: frozenset[str] = frozenset()) -> list[Cue]:
    """The statements of the outcome in ``said`` (the reader's normalised, lowercased tokens joined by
    spaces, contractions as "did not"), in text order; ``named``: the head words the reader named the
    story's road users by ("golf" of "a Golf pulled out"), none of them a thing hit."""
    return list(_KEPT.cues(said, named))


class _Asked(frozenset):
    """``named`` that records each word asked of it: the cues depend on ``named`` only through such
    questions, so cues read with one set hold for another that answers every asked word alike."""

    def __new__(cls, words: frozenset[str]) -> _Asked:
        probe = super().__new__(cls, words)
        probe.asked = set()
        return probe

    def __contains__(self, word: object) -> bool:
        self.asked.add(word)
        return super().__contains__(word)


class _KeptCues:
    """The cues of the last texts read, each with the ``named`` set they were read with and the words
    asked of it. A reading asks for one text's cues up to three times (its outcome, its stated intent,
    whether the ego evaded), with and without the road users' names; the names rarely change a cue, and
    reading the cues is a third of reading a text."""

    def __init__(self, size: int = 256) -> None:
        self._size = size
        self._kept: OrderedDict[str, list[tuple[frozenset[str], frozenset[str], tuple[Cue, ...]]]] = OrderedDict()
        self._lock = Lock()

    def cues(self, said: str, named: frozenset[str]) -> tuple[Cue, ...]:
        with self._lock:
            for known, asked, cues in self._kept.get(said, ()):
                if known & asked == named & asked:
                    self._kept.move_to_end(said)
                    return cues
        probe = _Asked(named)
        cues = _outcome_cues(said, probe)
        with self._lock:
            self._kept.setdefault(said, []).append((frozenset(named), frozenset(probe.asked), cues))
            self._kept.move_to_end(said)
            while len(self._kept) > self._size:
                self._kept.popitem(last=False)
        return cues


_KEPT = _KeptCues()


def _outcome_cues(said: str, named: frozenset[str]) -> tuple[Cue, ...]:
    """``outcome_cues`` read afresh (the cues are frozen: :class:`_KeptCues` hands them out again)."""
    tokens = _fields_answered(said.split())
    story = bool({"i", "we", "me", "my", "us", "our"} & set(tokens))
    cues: list[Cue] = []
    previous: str | None = None
    sentence: list[str] = []
    clauses = _clauses(tokens)
    raw = [ws for ws, _ in split(tokens, _BREAK_PUNCT - {","})]  # (its sentences with their conjunctions)
    said_in, cursor = -1, 0
    sentence_of: list[int] = []  # (the sentence each cue is said in)
    verdict: int | None = None  # (the last sentence that denies contact, or names a near miss, as its verdict)
    for n, clause in enumerate(clauses):
        words = clause.words
        ends_sentence = n + 1 == len(clauses) or clauses[n + 1].first_of_sentence
        if clause.first_of_sentence:
            said_in, cursor = min(said_in + 1, len(raw) - 1), 0
            # (a sentence of conjunctions alone, "and ." left of a heading "Van and cyclist", has no clause)
            said_in = next((s for s in range(said_in, len(raw)) if _holds(raw[s], words)), said_in)
        whole = raw[said_in] if raw else words
        at = next((k for k in range(cursor, len(whole)) if whole[k : k + len(words)] == words), None)
        if at is None:
            whole, at = words, 0  # (not found in its sentence: the clause is all that is known of it)
        cursor = at + len(words)
        sentence = words if clause.first_of_sentence else sentence + words
        own = _subject(words)
        clause.inherited = None if clause.first_of_sentence else previous
        previous = own or clause.inherited or ("ego" if story and clause.first_of_sentence else None)
        doer = previous  # (whose the clause's acts are: the ego's, someone else's, or not known)
        text = " ".join(words)

        def add(kind: str) -> None:
            cues.append(Cue(kind, text))  # noqa: B023 (the clause being read)
            sentence_of.append(said_in)  # noqa: B023 (the sentence it is said in)

        for i, w in enumerate(words):
            if _is_verb(w) and _lemmas(w) & _ESCAPING and _need_denied(words, i):
                add("unforced")  # ("didn't even have to brake", "no need to swerve": nothing forced)
                continue
            if doer == "other" and _kept_to_its_place(words, i):
                add("unforced")  # ("the rider never left the shoulder": no one came into the ego's way)
                continue
            if _seen_late(words, i, whole, at):
                add("late")  # ("didn't see him until Dad shouted": a near miss unless a safe pass is said)
                continue
            if _close_idiom(words, i, whole, at) or _fright(words, i):
                add("close")  # ("too close for comfort", "touch and go")
                continue
            if braking_sound(words, i) and not _denied_before(words, i):
                add("evade")  # ("tyres screeched", "stopped with a screech": someone's emergency stop)
                continue
            if (
                w.endswith("ing")
                and words[i + 1 : i + 2] == ["into"]
                and _near_to(words, i)
                and _into_road_user(words, i + 1)
            ):
                add("hedged")  # ("a split second from ploughing into the back of her")
                continue
            if _came_out_under_the_front(words, i):
                add("near")  # ("came out right under my bonnet": just in front of the ego)
                continue
            if _is_contact(words, i, named):
                kind = _contact_kind(words, i, clause, sentence)
                if kind == "contact" and knock_felt(words, i):
                    kind = "knock"  # (a light knock felt or heard: a contact a miss said outranks)
                if kind is not None:
                    add(kind)
                if kind == "denied" and _verdict_denial(words, i, doer):
                    verdict = said_in  # ("No contact.": the last word on the scene's outcome)
                continue
            if _near_noun(words, i):
                own = _after_contact_noun(words, i)  # ("no collision (near miss)": "no" is not said of it)
                denied = _denied_before(words[own:], i - own)
                add("safe" if denied else "near")  # ("no near miss": nothing close)
                if not denied and words[i + 1 : i + 2] not in (["misses"], ["calls"], ["shaves"], ["escapes"]):
                    verdict = said_in  # ("I've just had a near miss": it names the scene; "near misses" are many)
                continue
            if w.endswith("-free") and w[:-5] in _CONTACT_NOUNS | {"conflict", "incident", "drama", "problem"}:
                add("safe")  # ("a collision-free pass")
                continue
            if _negated_by_prefix(w):
                add("safe")  # ("a complete non-event", "a non-issue")
                continue
            if w == "within" and _within(words, i):
                add("near")  # ("came within a foot of my door")
                continue
            if (
                (w in _BAD or _lemmas(w) & _HARMED)
                and (_could_have_been_bad(words, i) or (w in _DISASTERS and _scoped(words, i, HEDGES, 3)))
                and not (w == "critical" and _denied_before(words, i))  # ("could never have been critical")
            ):
                add("hedged")  # ("could have been nasty", "she could have been killed": it was not)
                continue
            if _escape_noun(words, i) and (doer == "ego" or "had" in words[max(0, i - 5) : i]):
                add("evade")  # ("had to take evasive action", "I did an emergency stop")
                continue
            if _lemmas(w) & _HARMED and not w.endswith("ing") and _nobody_before(words, i):
                add("denied")  # ("..., nobody hurt", "No one injured."): a report's verdict without its verb
                continue
            if (
                _lemmas(w) & _HARMED
                and not w.endswith("ing")
                and _person_subject(words, i, clause.inherited)
                and not (_scoped(words, i, _HYPOTHETICAL, 4) or clause.after_if)  # ("before someone gets killed")
                and not _predicted(words, i)  # ("somebody is going to be killed there")
            ):
                if words[i - 1] in HEDGES:
                    add("hedged")  # ("the boy stepped back and was nearly killed": it was not)
                    continue
                add("denied" if _denied_before(words, i) else "contact")  # ("a cyclist was seriously injured")
                continue
            if w in _HARM_NOUNS and (_denied_before(words, i) or _scoped(words, i, ("without",), 3)):
                add("denied")  # ("no damage", "escaped serious injury": no harm said, not that all was well)
                continue
            if w in _HARM_NOUNS and _damage_to_a_vehicle(words, i) and not _denied_before(words, i):
                hypothetical = _modal_perfect(words, i) or _scoped(words, i, _HYPOTHETICAL, 4)
                add("hedged" if hypothetical else "contact")  # ("damage to my wing", "could have dented it")
                continue
            if w in _UNHURT and _person_subject(words, i, clause.inherited):
                add("denied")  # ("the kid was fine": unhurt, however close it was)
                continue
            if _averted(words, i, sentence[: len(sentence) - len(words) + i]):
                add("hedged" if _scoped(words, i, HEDGES, 3) else "denied")  # ("I braked and it was avoided")
                continue
            if _relief(words, i):
                add("lucky")
                continue
            if (
                _lemmas(w) & {"squeeze"}
                and _is_verb(w)
                and words[i + 1 : i + 2]
                and words[i + 1] in _SQUEEZE_BY
                and not forgone(words, i)
                and not _denied_before(words, i)  # ("he was not going to squeeze by": no such pass)
            ):
                add("close")  # ("squeezed past", "squeezed through between us": a pass with no room)
                continue
            if len(words) == 1 and w in HEDGES | {"just"} and ends_sentence and n > 0:
                add("hedged")  # ("Made it. Just.", "He got through. Barely.": a hedge of what was just told)
                continue
            if i == len(words) - 1 and clause.first_of_sentence and ends_sentence and _margin_alone(words):
                add("near")  # ("Inches.", "Literally centimetres!": a margin told as a sentence of its own)
                continue
            if len(words) == 1 and w in _IMPACT_SOUNDS and ends_sentence:
                add("contact")  # ("CRUNCH.", "too late - crunch.": the impact told by its sound, a clause of its own)
                continue
            if len(words) == 2 and words[0] == "all" and w in ("clear", "good", "fine", "ok", "okay", "well"):
                add("safe" if w == "clear" else "unharmed")  # ("All clear."; "all fine": how it left them)
            if words == [w] and w in _FINE and ends_sentence and not clause.first_of_sentence:
                add("unharmed")  # ("ego stops, ok.", "-> ok": a note's verdict after what happened)
            if _miss(words, i):
                by = "by" in words[i + 1 : i + 5]  # ("missed my handlebars by this much": told by its margin)
                add("contact" if _denied_before(words, i) and not by else "near")  # ("did not miss him")
                continue
            if _close_ttc(words, i):
                add("near")
                continue
            if w == "wide" and _passed_wide(sentence[: len(sentence) - len(words) + i], words[i + 1 :]):
                add("safe")
                continue
            margin = _margin(words, i, sentence[: len(sentence) - len(words)])
            if margin == "room" and _anothers_stop(words, i, clause.inherited, story, named):
                margin = None  # ("the bus stopped 4 m behind her, I was behind the bus": not the ego's margin)
            if margin == "room" and _hard_stop_said([x for ws in raw[:said_in] for x in ws]):
                margin = NEAR_MISS  # ("full braking at 8 m/s². ... stops 6.4 m short": an emergency stop's end)
            if margin is not None and margin == NEAR_MISS and w == "time" and _denied_before(words, i):
                add("contact")  # ("could not stop in time", "failed to pull up in time": it was not avoided)
            elif margin is not None:
                add("near" if margin == NEAR_MISS else margin if margin == "room" else "safe")
            hedge = w in HEDGES or (w == "just" and i > 0 and words[i - 1] == "only")
            if hedge and (_hedged_act(words, i) or _hedge_after_escape(words, i)):
                add("hedged")
            if w == "harm" and _denied_before(words, i):
                add("unharmed")  # ("no harm done": how it ended, not how close it was)
            elif w in _TROUBLE and words[max(0, i - 2) : i] == ["do", "not"]:
                pass  # ("don't worry": said to the reader, not of the scene)
            elif w in _TROUBLE | _FUSS and set(whole[at + i + 1 : at + i + 3]) & _UNTIL:
                pass  # ("zero issues until a van pulled out": trouble came after)
            elif w in _TROUBLE and (_denied_before(words, i) or _scoped(words, i, ("without", "zero"), 1)):
                add("safe")  # ("no issues", "zero drama")
            elif w in _FUSS and words[i - 1 : i] in (["no"], ["any"], ["without"]) and _denied_before(words, i):
                add("safe")  # ("no fuss", "without any bother", "no hassle"; not "didn't bother to look")
            went = w == "smoothly" and i > 0 and _lemmas(words[i - 1]) & {"go", "pass", "run"}  # ("it went smoothly")
            if (w in _SAFE_WORDS or went) and not _denied_before(words, i) and not _sign_off(words, i):
                # ("fine rain", "on a fine, dry evening": a word of the weather before its noun)
                paired = whole[at + i + 1 : at + i + 3]  # ("fine and dry": the weather, named with another)
                weather = w == "fine" and paired[:1] == ["and"] and _conditions(paired[1:])
                if not weather and not (
                    w == "fine" and (i + 1 < len(words) or words[i - 1 : i] in (["a"], ["an"], ["the"]))
                ):
                    add("unharmed" if w == "fine" else "safe")  # ("she's fine": how it left them)
            then = (
                words[i + 2]
                if i + 2 < len(words) and words[i + 1] == "else"
                else words[i + 1]
                if i + 1 < len(words)
                else ""
            )
            if (
                w == "nothing"
                and words[i - 1 : i] not in (["like"], ["if"])
                and ("ADJ" in _pos(then) or _lemmas(then) & {"happen", "occur"})
            ):
                add("unharmed")  # ("nothing happened", "Nothing dramatic": nothing of note)
            if w in _CLOSE and _predicate(words, i):
                add("safe" if _denied_before(words, i) else "close")  # ("nobody close"; "it was close")
            if _gone_before_arrival(whole, at + i):
                add("safe")  # ("he was gone before I got there": the way was clear when the ego came)
            if w in ("critical", "criticality") and _denied_before(words, i):
                add("safe")  # ("not critical", "nothing critical", "no criticality": nothing came close)
            before = whole[: at + i]  # (its sentence up to this word, with its conjunctions)
            if w == "clear" and i > 0 and words[i - 1] in _COPULA and set(before[-8:]) & _ONCE:
                add("safe")  # ("pulled out once the road was clear", "held back until it was clear")
                continue
            if w in ("close", "closely") and _passed_close(before, words[i + 1 : i + 3]):
                add("close")  # ("overtook us really close", "went by far too close")
                continue
            sky = words == ["clear"] and n > 0 and not clause.first_of_sentence and _conditions(clauses[n - 1].words)
            if (
                len(words) == 1
                and w in ("clean", "close", "tight")
                or (words == ["clear"] and ends_sentence and not sky)
            ):
                add("safe" if w in ("clean", "clear") else "close")  # (a one-word verdict: "Clean.", "but close")
            if _is_verb(w) and _planned_reaction(words, i, whole[at + i + 1 :]):
                add("yield")  # ("detected early, decelerated smoothly", "moved out early": no one forced)
            if _is_verb(w) and _hindsight(words, i):
                pass  # ("I should have waited": what was not done)
            elif _is_verb(w) and _compelled(words, i) and _ego_acts(words, i) == "evade":
                add("evade")  # (anyone forced to swerve: "he had to swerve round my bonnet", "made me brake hard")
            elif _is_verb(w) and _compelled(words, i) and _forced_stop(words, i, whole[at + i + 1 :], whole):
                add("forced")  # ("had to stop halfway", "the driver had to brake": forced on its doer, no giving way)
            elif clause.first_of_sentence and _hortative(words, i):
                pass  # ("Let us all take care": a wish said to the reader, no one let through)
            elif _is_verb(w) and _subject_is_ego(words, i, clause, story):
                act = _ego_acts(words, i)
                if act is None and _lets_another_go(words, i, whole[at + i + 1 :]):
                    act = "yield"  # ("I sat behind him", "we waved her across")
                if act is not None:
                    add(act)
            elif _is_verb(w) and _road_user_evades(words, i):
                add("escape")  # (a named road user's hard brake or swerve: "the Prius swerved", "SUT braked hard")
            elif _is_verb(w) and _escaped_on_foot(words, i):
                add("evade")  # (a person who had to spring clear: "she had to step back", "jumped out of the way")
            elif _lemmas(w) & {"let", "give", "yield"} and _is_verb(w) and not w.endswith("ing"):
                if _ego_acts(words, i) == "yield" and not _denied_before(words, i) and not _failure_to(words, i):
                    add("yield")  # (someone gives way or lets the other go: no conflict)
            elif _is_verb(w) and _lets_another_go(words, i, whole[at + i + 1 :]):
                add("yield")  # (anyone waits while another goes: "the bus waited behind me", "flashed us across")
            if (
                _lemmas(w) & {"avoid", "dodge", "evade"}
                and words[i + 1 : i + 2]
                and (words[i + 1] in _PERSON_OBJECTS - {"it", "one"} or words[i - 1 : i + 2] == ["to", w, "it"])
            ):  # (and a purpose: "... to avoid it")
                if not _denied_before(words, i):
                    add("evade")  # ("dived into the outside lane to avoid him")
                elif not (_modal_perfect(words, i) or clause.after_if):
                    add("contact")  # ("couldn't avoid him", "was unable to avoid her": two denials)
    cues = _overruled(cues, sentence_of, verdict)
    if _emergency_said(tokens):
        cues.append(Cue("alarm", "emergency"))  # (AEB triggered, high criticality, fear: see decide)
    if _rated_critical(tokens):
        cues.append(Cue("critical", "critical"))  # (the class a test states for its scenario)
    quiet = no_response_expected(tokens)
    if quiet:
        cues.append(Cue("unforced", quiet))  # (a test expects the ego's systems to stay quiet: nothing forced)
    designed = designed_outcome(tokens)
    if designed:
        cues.append(Cue(DESIGNED + designed, "designed"))  # (the class a test or study designs its event for)
    return tuple(cues)


#: What a road user that has left the way is, or has done ("was gone", "was already across", "had cleared").
_CLEARED = frozenset(("gone", "across", "past", "through", "clear", "cleared", "crossed", "passed", "over"))
#: The same said as a phrase ("she was already on the other side").
_CLEARED_PHRASES = (("on", "the", "other", "side"),)
#: Verbs (lemmas) of coming to where the other had been ("before I got there", "when we arrived").
_ARRIVING = frozenset(("get", "arrive", "reach", "come"))
#: Adverbs between the auxiliary and what the road user had become ("was long gone", "was already across").
_BY_THEN = frozenset(("already", "long", "well", "safely", "just", "all"))
#: The auxiliaries a road user's having left the way is said with ("he was gone", "the bus had cleared").
_HAD_LEFT = frozenset(("was", "were", "had", "'d", "is", "are", "'s"))


def _cleared_at(whole: list[str], k: int) -> int | None:
    """Where a word or phrase of having left the way that ends at ``k`` of ``whole`` begins ("gone",
    "on the other side"), or None."""
    if k >= len(whole):
        return None
    if whole[k] in _CLEARED:
        return k
    return next((k + 1 - len(p) for p in _CLEARED_PHRASES if tuple(whole[k + 1 - len(p) : k + 1]) == p), None)


def _by_the_time(words: list[str]) -> int | None:
    """Where the clause after "by the time" begins in ``words`` ("by the time I got there"), or None."""
    return next((t + 3 for t in range(len(words) - 2) if words[t : t + 3] == ["by", "the", "time"]), None)


def _ego_arrives(words: list[str]) -> bool:
    """Whether ``words`` open with the ego and a verb of arriving right after it ("I got there", "we arrived")."""
    return bool(words) and words[0] in _EGO_HEADS and any(_is_verb(x) and _lemmas(x) & _ARRIVING for x in words[1:4])


def _gone_before_arrival(whole: list[str], k: int) -> bool:
    """Whether the word at ``k`` of the sentence ``whole`` ends what says that another road user, its
    subject (a third person or a road user's noun), had left the way before the ego came to it ("he
    was gone before I got there", "she was already on the other side when we arrived", "by the time we
    got there the bus had cleared"): the two never met, a safe pass. Not "was gone before I could
    brake" (the ego did not arrive: it had no time to act)."""
    start = _cleared_at(whole, k)
    if start is None:
        return False
    j = start - 1
    while j >= 0 and whole[j] in _BY_THEN:
        j -= 1
    if j < 1 or whole[j] not in _HAD_LEFT:
        return False
    subject = whole[j - 1]
    if subject not in SUBJECT_PRONOUNS - {"i", "we", "you"} and not _road_user_word(subject):
        return False
    earlier = whole[max(0, j - 9) : j - 1]  # ("by the time I got there she was gone")
    t = _by_the_time(earlier)
    if t is not None and _ego_arrives(earlier[t:]):
        return True
    after = whole[k + 1 : k + 9]  # ("he was gone before I got there", "... by the time we arrived")
    at = next((n + 1 for n, x in enumerate(after) if x in ("before", "when")), _by_the_time(after))
    return at is not None and _ego_arrives(after[at:])


@lru_cache(maxsize=1)
def _condition_words() -> frozenset[str]:
    """The one-word names of the weather and the time of day in the lexicon ("dry", "overcast", "dusk")."""
    phrases = [p for ps in (*L.WEATHER.values(), *L.TIMES.values()) for p in ps]
    return frozenset(p for p in phrases if " " not in p)


def _conditions(words: list[str]) -> bool:
    """Whether the clause ``words`` only names the weather or the time of day ("Morning", "dry, bright"):
    a "clear" listed after it is the sky ("Morning, clear."), not a verdict on the pass ("Clear.")."""
    return bool(words) and all(w in _condition_words() for w in words)


#: Conjunctions of a time reached ("went once it was clear", "passed when the road was clear").
_ONCE = frozenset(("once", "until", "till", "when", "after"))
#: The particles of squeezing by someone ("squeezed past", "squeezed through").
_SQUEEZE_BY = frozenset(("past", "by", "through", "between", "round", "around"))


#: Verbs (lemmas) of staying put for someone ("waited for her", "sat behind him", "stopped while she crossed").
_STAYING = frozenset(("wait", "sit", "stop", "pause", "hold", "hang", "idle", "stay"))
#: What may stand between such a verb and whom it stays for ("sat there patiently while ...").
_STAYING_FILLERS = frozenset(("there", "back", "tight", "put", "so", "just", "still", "quietly", "and"))
#: Conjunctions that set the other's move beside the stay ("waited while she crossed", "until he'd gone").
_WHILE = frozenset(("while", "whilst", "as", "until", "till"))
#: Words of a queue: staying in one, or behind one, is waiting one's turn in traffic, not giving way.
_QUEUE = frozenset(("queue", "queues", "traffic", "line", "jam", "tailback", "lights", "light", "signal", "signals"))
#: Verbs (lemmas) of a signal to go ("waved me through", "flashed us across", "beckoned her over").
_SIGNALLING = frozenset(("wave", "flash", "beckon", "signal", "motion", "gesture"))
#: Where a signal sends the one it is given to.
_ONWARD = frozenset(("through", "across", "on", "out", "past", "by", "ahead", "over", "forward", "round", "around"))
#: Verbs (lemmas) of another's going by or across, after a conjunction of time ("while Mrs Reid crossed").
_GOING_BY = frozenset(("cross", "pass", "go", "walk", "ride", "cycle", "come", "get", "squeeze", "overtake", "clear"))


def _lets_another_go(words: list[str], i: int, rest: list[str]) -> bool:
    """Whether the verb at ``i`` (a finite verb, not denied) stays put for another road user or sends
    one on: a stay for a road user ("waited for him", "stopped for the kids"), behind one ("sat behind
    the cyclist", "waited behind me instead of squeezing past") or while one moves ("just sat there
    while a lady crossed"), or a signal that sends a person on ("waved me through", "flashed us
    across"). ``rest``: its sentence after it, conjunctions kept. Whoever does it, it is giving way.
    Not a participle ("a man waiting to cross" is where he is), a stay in a queue or at the lights
    (one's turn, not another's), nor a stay for something else ("waited for a gap"). A stay behind
    someone or something until another has gone by ("stays behind the cyclist until the oncoming car has
    passed") waits for that other, and so does a slowing until another has ("slows behind the walker
    until the lorry has passed")."""
    w = words[i]
    if w.endswith("ing") or _denied_before(words, i) or forgone(words, i):
        return False  # ("waiting at the corner", "didn't wait for me", "instead of waiting")
    lem = _lemmas(w)
    if lem & _SIGNALLING:
        k = 1 if rest[:1] in (["the"], ["a"]) else 0
        return len(rest) > k + 1 and names_road_user(rest[k : k + 1]) and rest[k + 1] in _ONWARD
    held = bool(lem & {"slow"}) and bool(set(rest[:6]) & {"until", "till"})  # ("slows until the lorry has passed")
    if not (lem & _STAYING or held) or set(rest[:8]) & _QUEUE:
        return False
    k = 0
    while k < len(rest) and (rest[k] in _STAYING_FILLERS or (rest[k].endswith("ly") and rest[k] != "only")):
        k += 1
    nxt, obj = (rest[k], rest[k + 1 : k + 5]) if k < len(rest) else ("", [])
    if nxt in ("for", "behind") and names_road_user(obj[:3]):
        return True  # ("waited for him"; not "waited for a gap")
    if nxt == "behind":
        k = next((j for j in range(k + 1, min(len(rest), k + 6)) if rest[j] in _WHILE), None)
        if k is None:
            return False
        nxt, obj = rest[k], rest[k + 1 : k + 5]  # ("stayed behind until the oncoming car had passed")
    if nxt in _WHILE and obj:
        moved = any(_is_verb(x) and _lemmas(x) & _GOING_BY for x in obj[1:4])  # ("while Mrs Reid crossed")
        return obj[0] in SUBJECT_PRONOUNS or names_road_user(obj[:3]) or moved  # ("while she crossed")
    return False


#: The last words of the lexicon's names for the ego's vehicle ("SUT", "the test vehicle", "host").
_EGO_NOUN_HEADS = frozenset(p.split()[-1] for p in L.EGO_NOUNS) - _PERSON_OBJECTS


#: Verbs (lemmas) of a person's own quick move on foot ("jumped back", "stepped aside", "dived clear").
_ON_FOOT_MOVES = frozenset(("jump", "leap", "dive", "step", "hop", "spring", "scramble", "get", "throw"))
#: Words after such a move that take its doer away from a path ("back", "aside", "clear").
_AWAY = frozenset(("back", "aside", "clear", "sideways", "backwards"))


#: Words between a subject and its move ("had to", "was forced to", "all had to"): the auxiliaries and
#: adverbs a subject and its verb take (:data:`_BETWEEN`), and a forced or shared move's own.
_TO_THE_MOVE = _BETWEEN | {"forced", "all"}


def _vehicle_subject(words: list[str], i: int) -> bool:
    """Whether the subject right before the move at ``i`` (past "had to" and the like) is a vehicle ("the
    lorry had to get out of the way", "cars had to"): a vehicle making way, no one on foot."""
    j = i - 1
    while j >= 0 and (words[j] in _TO_THE_MOVE or words[j].endswith("ly")):
        j -= 1
    return j >= 0 and (words[j] in _SHOVED_VEHICLES or bool(_lemmas(words[j]) & _SHOVED_VEHICLES))


def _out_of_the_way(after: list[str]) -> bool:
    """Whether ``after`` opens with "out of the way" or "out of its/his/her/their/my way"."""
    return after[:2] == ["out", "of"] and after[3:4] == ["way"] and after[2] in _POSSESSIVES | {"the"}


def _escaped_on_foot(words: list[str], i: int) -> bool:
    """Whether the verb at ``i`` is a person's escape on foot: out of the way ("jumped out of the
    way", "had to get out of his way"), or back or aside when forced to ("had to step back", "was
    forced to jump clear"). Why: a walker or rider who has to spring clear was nearly met, as the
    ego's swerve says it nearly met someone. Not one denied or under a condition ("didn't have to
    step back", "would have had to jump out of the way"), nor a move by choice ("stepped back to let
    me through": no "had to")."""
    if not _lemmas(words[i]) & _ON_FOOT_MOVES or _denied_before(words, i) or _scoped(words, i, _UNREAL, 4):
        return False
    if set(words[:i]) & (_NEGATORS | _NOBODY) or _vehicle_subject(words, i):
        return False  # ("Nobody had to step back", "without anyone having to"; "the bus had to get out of the way")
    after = words[i + 1 : i + 6]
    if _out_of_the_way(after):
        return True
    return bool(after[:1]) and after[0] in _AWAY and _compelled(words, i)


def _road_user_evades(words: list[str], i: int) -> bool:
    """Whether the finite verb at ``i`` is a hard brake or a swerve ("brakes hard", "stood on the
    brakes", "swerved") whose subject, right before it, is a road user named by its noun or the ego
    named by its vehicle or its learner driver ("the Tesla brakes HARD", "the bus driver slammed on",
    "SUT braked hard", "Applicant braked firmly"): one party's escape from the other, whichever of the
    two it is. Not a participle or an infinitive
    ("a car braking hard", "to brake hard": no act said), nor one denied or under a condition
    ("the van never braked", "if the cyclist had swerved")."""
    if words[i].endswith("ing") or words[i - 1 : i] == ["to"] or _denied_before(words, i):
        return False
    if _scoped(words, i, _HYPOTHETICAL, 4) or _ego_acts(words, i) != "evade":
        return False
    rest = words[i + 1 : i + 5]
    if any(x in _PATH_WORDS and rest[k + 1 : k + 3] and set(rest[k + 1 : k + 3]) & _NOT_ROAD_USERS
           for k, x in enumerate(rest)):  # fmt: skip
        return False  # ("the taxi swerved round a pothole": no road user escaped)
    j = i - 1
    while j >= 0 and (words[j] in _BETWEEN or words[j].endswith("ly")):
        j -= 1
    return j >= 0 and (_road_user_word(words[j]) or words[j] in _EGO_NOUN_HEADS or words[j] in V.LEARNER)


#: Verbs (lemmas) of easing off or making room for another ("slowed", "decelerated", "moved over").
_EASING = frozenset(("slow", "decelerate", "ease", "move", "steer", "detect", "brake"))
#: Adverbs of a reaction made in good time and without force: planned, not forced.
_PLANNED = frozenset(("early", "smoothly", "gradually", "progressively", "gently"))


def _planned_reaction(words: list[str], i: int, later: list[str] | tuple[str, ...] = ()) -> bool:
    """Whether the finite verb at ``i`` is a reaction made early or smoothly: a verb of easing off,
    making room or perceiving with such an adverb in the words after it ("detected early",
    "decelerated smoothly to 5 km/h", "moved out to lane 2 early", "spotted him early"). Whoever
    makes it, a reaction in good time is no escape: giving way, a safe pass unless more is said. Not
    denied, not a participle ("slowing gently" says how it went on) nor under a condition, nor with a
    hard brake or a swerve later in its sentence (``later``: "moved into my lane early and then
    slammed on its brakes")."""
    w = words[i]
    if any(_is_verb(x) and _lemmas(x) & _EVADE for x in later) or (
        set(later) & _HARD and any(_lemmas(x) & _BRAKE for x in later)
    ):
        return False
    if w.endswith("ing") or not _lemmas(w) & (_EASING | _PERCEIVING) or _denied_before(words, i):
        return False
    if _lemmas(w) & {"brake"} and words[i - 1 : i] in (["who"], ["which"], ["that"]):
        return False  # ("saw a van cut in front of a cyclist, who braked gently": a scene only watched)
    if i > 0 and (words[i - 1] in _DETERMINERS or words[i - 1] in _POSSESSIVES):
        return False  # ("the move", "my slow start": a noun)
    if _scoped(words, i, _HYPOTHETICAL, 4) or _modal_perfect(words, i):
        return False  # ("should have slowed early", "if it had braked smoothly")
    return bool(set(words[i + 1 : i + 6]) & _PLANNED)


def _hindsight(words: list[str], i: int) -> bool:
    """Whether the verb at ``i`` is under a modal of hindsight ("should have waited", "should've
    waited", "could have given way", "ought to have"): said, not done; "should brake" in a test's
    wording is what it requires, and is read as such."""
    before = words[max(0, i - 3) : i]
    if words[i - 1 : i] == ["should"] and words[i].endswith(("ed", "en")):
        return True  # ("I should've waited", its "'ve" dropped)
    return "have" in before and bool(set(before) & {"could", "would", "might", "should", "ought"})


def decide(cues: list[Cue], sudden: bool = False, intruded: bool = False, entered: bool = False) -> str | None:
    """The intent the cues state. A class the text designs its event for (see :mod:`.designed_outcome`)
    is the intent, whatever else is said. A scenario a test rates critical is ``critical``, whatever else
    is said but a contact (a contact is what happened, a rating only how close it came); otherwise a
    contact anywhere is a collision; a hedge, a miss, a small margin
    or a close call a near miss; then a stated safe pass; a denied contact is a near miss unless the
    ego only gave way; the ego's evasion alone a near miss, its giving way alone a safe pass.
    ``sudden``: a road user's act is said to be sudden ("shot out", "suddenly swerved"); then the
    ego's plain stop or brake, with nothing else said, is what it was forced to do: a near miss. That
    everyone was fine or nothing happened says how it ended: after a sudden act or the ego's braking
    or evasion it was a near miss avoided ("he shot out, I stood on the brakes, he's fine"); alone, a
    safe pass. ``intruded``: a road user is read cutting into the ego's lane or turning into its way;
    then the ego's brake (not a stop, which may be a wait), with nothing else said, is what that forced
    on it ("he cut across in front of me. I braked, he went"): a near miss. ``entered``: a road user is
    read coming into another's path (crossing, cutting in, turning across, running the red, coming the
    wrong way); then a named road user's hard brake or swerve (an ``escape``) is one party escaping the
    other, as the ego's evasion is ("a rider ran the red and the Tesla braked hard"); without one, a
    hard brake is the lead vehicle's own act ("the lead car brakes hard"), no escape. An ``alarm``
    (an emergency said anywhere: :func:`_emergency_said`) makes a roomy stop a near miss."""
    designed = [c.kind[len(DESIGNED) :] for c in cues if c.kind.startswith(DESIGNED)]
    if designed:
        return designed[-1]  # (the event's class as designed, over how one run of it is told)
    kinds = {c.kind for c in cues}
    if "knock" in kinds:
        kinds.discard("knock")  # (a light knock felt or heard is a contact, unless a miss or a safe pass is
        if not kinds & {"near", "safe"}:  # said: "I felt a tap but it was just a pothole; he passed safely")
            kinds.add("contact")
    if "escape" in kinds:
        kinds.discard("escape")
        if entered:
            kinds.add("evade")
    if "forced" in kinds:  # (a brake or stop someone had to make: the escape from one who came into the way)
        kinds = (kinds - {"forced"}) | ({"evade"} if entered and not kinds & {"safe", "yield"} else {"brake"})
    if "critical" in kinds and "contact" not in kinds:
        return CRITICAL  # (a test's own rating of its scenario, over what its wording suggests)
    if "room" in kinds:  # (a stop with several metres left: room to spare, unless it was an emergency)
        kinds.discard("room")
        if "alarm" in kinds:
            kinds.add("near")  # ("stops 5 m short. AEB triggered.": the end of an emergency stop)
        elif not kinds & {"evade", "lucky", "late"}:
            kinds.add("safe")
    kinds.discard("alarm")  # (alone, an emergency said only weighs a roomy stop)
    if "unharmed" in kinds:  # (nobody hurt, nothing happened: how it ended, not how close it was)
        kinds.discard("unharmed")
        forced = sudden or intruded or kinds & {"evade", "brake"}
        kinds.add("evade" if forced and not kinds & {"safe", "yield"} else "safe")
    if sudden and kinds & {"stop", "brake"} and not kinds & {"contact", "safe", "yield", "required", "near"}:
        kinds.add("evade")  # ("a kid shot out in front of me and I just stopped")
    if intruded and "brake" in kinds and not kinds & {"contact", "safe", "yield", "required", "near", "stop"}:
        kinds.add("evade")  # ("a van cut in ahead of me and I hit the brakes")
    if "stop" in kinds:
        kinds = (kinds - {"stop"}) | {"yield"}  # (otherwise a plain stop gives way)
    if "contact" in kinds:
        return COLLISION
    if kinds & {"hedged", "near", "close"}:
        return NEAR_MISS
    if "safe" in kinds or ("unforced" in kinds and not kinds & {"evade", "brake", "lucky"}):
        return SAFE  # (or no escape needed: "didn't even have to brake")
    if kinds & {"lucky", "late"}:
        return NEAR_MISS  # (relief at luck, or the other seen late, and no wide margin said: it was close)
    if "required" in kinds and not kinds & {"evade", "brake", "denied"}:
        return SAFE  # (no contact, as the test requires, and nothing forced)
    if "denied" in kinds or "required" in kinds:
        return SAFE if "yield" in kinds and not kinds & {"evade", "brake"} else NEAR_MISS
    if "evade" in kinds:
        return NEAR_MISS
    if "yield" in kinds and "brake" not in kinds:
        return SAFE
    return None


def stated_intent(said: str) -> str | None:
    """``collision``, ``near_miss``, ``safe`` or None, from the reader's normalised, lowercased tokens
    joined by spaces (contractions as "did not")."""
    return decide(outcome_cues(said))


#: Verbs a writer wishes a reader to go on safe with ("stay safe", "drive safely", "get home safe").
_WISHING = frozenset(("stay", "be", "keep", "drive", "ride", "cycle", "travel", "get", "go", "walk", "arrive", "scoot"))
#: Words of a path: an imperative with one is an instruction about someone ("pass the cyclist safely").
_PATH_WORDS = frozenset(("past", "round", "around", "by", "through", "behind", "over", "across", "beside"))


def _sign_off(words: list[str], i: int) -> bool:
    """Whether a word of safety at ``i`` is a wish to the reader, a post's sign-off ("Stay safe guys",
    "Drive safe out there, everyone", "ride safely all"): its clause opens with the bare verb of it, and
    only whom it is wished to follows (no path, no noun it qualifies: "drive safely past the cyclist"
    and "keep a safe distance" are instructions, and "the cyclist stayed safe" has its subject)."""
    if i == 0 or i > 2 or words[0] not in _WISHING or words[0] not in _pos(words[0]).get("VERB", (words[0],)):
        return False
    rest = words[i + 1 :]
    return len(rest) <= 3 and not set(rest) & _PATH_WORDS and not (rest and rest[0] in _SPACING)


#: The nouns "safe" qualifies in an instruction about spacing ("keep safe distance", "stay safe gap").
_SPACING = frozenset(("distance", "gap", "margin", "clearance", "speed", "pass", "space", "room", "berth", "following"))


#: Words after "no issues" that say trouble came after all ("no issues until a van pulled out").
_UNTIL = frozenset(("until", "till", "til", "then"))


#: Words that say the pass was safe, wherever they stand ("passes safely", "a comfortable pass").
_SAFE_WORDS = frozenset(("safe", "safely", "uneventful", "uneventfully", "fine", "comfortably"))
#: A time to collision said as its least value: below this it was a near miss.
_TTC_WORDS = frozenset(("ttc", "time-to-collision"))
_LOWEST = frozenset(("minimum", "min", "lowest", "dropped", "drops", "fell", "falls", "below", "under"))


def _close_ttc(words: list[str], i: int) -> bool:
    """ "minimum TTC 0.8 s", "the TTC dropped to 0.9 s": the least time to collision, under 1.5 s."""
    if words[i] not in _TTC_WORDS and not (words[i] == "collision" and words[i - 2 : i] == ["time", "to"]):
        return False
    window = words[max(0, i - 3) : i + 6]
    if not set(window) & _LOWEST:
        return False
    values = [_number(w) for w in words[i + 1 : i + 6]]
    return any(v is not None and v < 1.5 for v in values)


_COPULA = frozenset(("is", "was", "were", "be", "been", "being", "are", "'s", "it's", "its", "got", "nobody", "no"))
_DEGREE = frozenset(
    ("very", "really", "so", "too", "quite", "pretty", "a", "bit", "little", "rather", "extremely", "one")
)


def _predicate(words: list[str], i: int) -> bool:
    """Whether a word of closeness at ``i`` is said of the situation, after a copula, and ends its
    clause ("it was close", "but it was dangerous", "nobody close"); not "pulls in too close ahead"."""
    if i + 1 < len(words) and words[i + 1] not in ("one", "call", "thing"):
        return False
    j = i - 1
    while j >= 0 and words[j] in _DEGREE:
        j -= 1
    return j >= 0 and words[j] in _COPULA


#: Verbs (lemmas) of getting out of someone's way, which a hedge after them narrows ("avoided it narrowly").
_ESCAPES = frozenset(("avoid", "miss", "escape", "dodge", "evade", "clear", "pass", "stop"))


def _hedge_after_escape(words: list[str], i: int) -> bool:
    """A hedge at ``i`` after a verb of escaping in its clause ("avoiding it narrowly", "missed the
    cyclist only just", "stopped barely"): the escape was only just made, a near miss."""
    return any(_is_verb(x) and _lemmas(x) & _ESCAPES for x in words[max(0, i - 4) : i])


def _hedged_act(words: list[str], i: int) -> bool:
    """A hedge before a verb that acts on someone ("nearly took my bumper off", "almost wiped us
    out", "almost flattened a jogger"), or before a stop ("only just stopped", "barely stopped in
    time")."""
    after = words[i + 1 : i + 5]
    if not after or not _is_verb(after[0]) or after[0].endswith("ing"):
        return False  # ("barely crawling": how fast, not what happened)
    if _lemmas(after[0]) & {"stop", "avoid", "manage", "make", "get"}:
        return True
    if set(after[1:]) & (_PERSON_OBJECTS - {"one", "each"} | _POSSESSIVES):
        return True
    moving = _lemmas(after[0]) & _motion_verbs() - _CONTACT_VERBS - _PHRASAL_CONTACT - {"run"}
    obj = words[i + 2 : i + 8]
    rider = obj[obj.index("on") + 1 :] if "on" in obj[:3] else []  # ("a lad on a moped": the moped's rider)
    return not moving and (names_road_user(obj) or names_road_user(rider))  # (not "almost overtook him")


@lru_cache(maxsize=1)
def _motion_verbs() -> frozenset[str]:
    """The first words of the lexicon's behaviours ("overtake", "pass", "follow"): a road user as the
    object of one of these, hedged, is a move nearly made ("almost overtook a cyclist"), not a blow."""
    return frozenset(p.split()[0] for ps in L.BEHAVIOUR_VERBS.values() for p in ps)
