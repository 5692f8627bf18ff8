"""Who is who in a description: the ego and the other road users as discourse referents.

People name the same road user in many ways, name the ego in the third person, and name people and
vehicles that are no road users of the scenario at all. This module keeps a small model of referents
over the reader's words, built from the grammar that tells new from known, and then says each
referent the one way the reader reads it ("the ego", "a e-scooter", "the truck"), so the reader's
actors and the ego's speed follow the referents. It runs once on a description's words, before the
reader scans them (:func:`resolve`).

- **New or known.** An indefinite article opens a new referent ("a cyclist", "another cyclist"); a
  definite article, or a bare singular noun inside a clause, is the most recent one of its type ("ego
  stays behind cyclist", "the silver hatchback" → "the hatchback"); a definite general noun is the
  most recent vehicle ("the front vehicle" after "a coach" → "the truck"); an apposition (", a coach,")
  is the same one; a name in brackets is its name ("a passenger car (the challenger) ... challenger
  speed 90 km/h"), as is "speed of cyclist 15 km/h".
- **One road user, not two.** A person on or riding a vehicle is one rider of it ("a lad on one of
  those electric scooters"); a person pushing a bike is one walker; the driver of a vehicle is the
  vehicle ("the driver of the lorry ahead", "the van's driver").
- **The ego in the third person.** Vehicle labels ("Car 3 to control", "Vehicle A ... Vehicle B", "Car
  B (ego)"): the one marked as the ego, else (no ego named otherwise) number one or A, else the first;
  every other label is a road user of its noun's type. A vehicle in apposition to the ego ("V1, a Ford
  Focus,"); the narrator's vehicle named as one ("we were in a hire car", "car full of bags"); in a
  report that names no ego, the one motor vehicle set against a walker or rider ("car versus
  e-scooter ... car doing 20 mph", "Vehicle was turning right ..., pedestrian crossing"). A speed said
  of the ego and another together ("a van and I were both doing 70 km/h") is each one's.
- **Lists.** A road user as a field name ("cyclist: comes out from the left") is the subject of the
  value; lettered or numbered labels of a list ("actor A: motorbike ...", "actor B: oncoming car")
  each name a new road user, and the label said again is that one.
- **No road users.** A walker's companion ("a man with his dog", unless named again doing something),
  passengers and pets inside the vehicle ("kids bickering in the back"), the narrator's own people
  ("drove my kid to school"), a vehicle's load, and whoever arrives after a stated collision with
  someone named before it ("the ambulance came"). Their words are returned, to be listed as not used.
- **Names no dictionary knows.** What the ego follows or overtakes named by a make or model
  ("following a silver Astra") is a vehicle.

It knows no content words of its own: which words name road users (and of what type) comes from the
reader's lexicon through ``kind_at``; what it adds are closed classes of function words (articles,
possessives, pronouns, forms of "be", prepositions) and of a few verbs (of riding, following and
contact), and lemmas from lemminflect.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

from vei_scenario.language.function_words import (  # noqa: F401  (re-exported: the reader names them here)
    ARTICLES,
    BE,
    DEFINITE,
    DETERMINERS,
    FIRST_PERSON,
    INDEFINITE,
    POSSESSIVE,
)
from vei_scenario.language.lemmas import english, lemmas
from vei_scenario.language.lexicon import ANIMALS, MOTOR_TWO_WHEELERS, WALKER_PACED, WRONG_WAY_NOUNS
from vei_scenario.language.scenery import absent, vehicle_modifiers
from vei_scenario.language.vocabulary import GENERAL_VEHICLE, IN_LINE
from vei_scenario.language.who import (
    THINGS_FOR_VEHICLES,
    TRAVEL_VERBS,
    make_and_model,
    person_with_vehicle,
    travel_modes,
    vehicle_places,
    walker_places,
)

#: ``kind_at(tokens, i)``: the road-user type named by a phrase starting at ``i`` ("ego" for the ego)
#: and the phrase's length, or None when no road-user phrase starts there.
KindAt = Callable[[list[str], int], "tuple[str, int] | None"]
#: ``known(tokens, i)``: whether the reader has any phrase starting at ``i``.
Known = Callable[[list[str], int], bool]

PUNCT = frozenset({".", ";", "!", "?", ":", ","})
SENTENCE_END = frozenset({".", ";", "!", "?", ":"})
#: Prepositions that join a person to the vehicle it rides ("a lad on a scooter", "a kid astride a bike").
RIDING = frozenset({"on", "riding", "astride", "aboard", "in", "inside", "driving"})
#: Of those, the prepositions that put a person inside a motor vehicle ("a bloke in a white van").
INSIDE = frozenset({"in", "inside", "driving"})
VEHICLES = frozenset({"car", "van", "truck"})
VULNERABLE = frozenset({"pedestrian", "bicycle", "e-scooter"})
#: The words a report sets two parties against each other with ("car versus e-scooter").
VERSUS = frozenset({"versus", "vs", "v"})
#: The plain noun the reader reads for each type, to say a referent again as the reader reads it.
NOUN = {"car": "car", "van": "van", "truck": "truck", "bicycle": "cyclist", "e-scooter": "e-scooter",
        "pedestrian": "pedestrian"}  # fmt: skip
#: Words of where someone is relative to another, after a vehicle noun ("the car ahead"): that vehicle
#: is placed relative to the ego, so it is not the ego.
PLACED = frozenset({"ahead", "behind", "in", "parked", "oncoming", "following", "alongside", "beside", "next"})
#: Words naming a quantity after a referent ("speed of cyclist 15 km/h").
SPEED_NOUNS = frozenset({"speed", "velocity"})


@dataclass
class Referent:
    """One road user (or the ego) as the text names it."""

    kind: str
    noun: str  # the noun it was last named by


@dataclass
class Phrase:
    start: int  # its determiner, or its first word
    head: int  # the road-user phrase
    end: int  # after it
    det: str
    kind: str


def _phrase_at(tokens: list[str], i: int, kind_at: KindAt, known: Known, reach: int = 3) -> Phrase | None:
    """The noun phrase whose road-user noun starts at ``i``: its determiner (within ``reach`` words
    before, past modifiers the reader has no phrase for) and its type."""
    found = kind_at(tokens, i)
    if found is None:
        return None
    kind, n = found
    start, det = i, ""
    for j in range(i - 1, max(i - 1 - reach, -1), -1):
        w = tokens[j]
        if w in DETERMINERS:
            start, det = j, w
            break
        if w in PUNCT or not w.replace("-", "").isalpha() or (known(tokens, j) and w not in COLOURS):
            break
    return Phrase(start, i, i + n, det, kind)


def road_user_phrases(tokens: list[str], kind_at: KindAt, known: Known) -> list[Phrase]:
    out, i = [], 0
    while i < len(tokens):
        p = _phrase_at(tokens, i, kind_at, known)
        if p is None:
            i += 1
            continue
        out.append(p)
        i = p.end
    return out


def _unknown_person(tokens: list[str], i: int, known: Known) -> int | None:
    """Where the noun phrase ends at ``i`` begins, when it is a determiner and up to three words the
    reader has no phrase for ("some lad", "a pizza courier"), else None."""
    for j in range(i, max(i - 4, -1), -1):
        if tokens[j] in DETERMINERS:
            return j if j < i else None
        if tokens[j] in PUNCT or not tokens[j].replace("-", "").isalpha() or (j < i and known(tokens, j)):
            return None
    return None


#: Indefinite pronouns of one person, new to the story ("someone on a bike").
SOMEONE = frozenset({"someone", "somebody"})
#: Counts that open a noun phrase of several people ("two lads", "3 suspects"); one is no group.
_PEOPLE_COUNTS = frozenset("two three four five six seven eight nine ten several both".split())
#: Verbs that only help another verb ("has taught", "were seen"): no act of their own.
_HELPING = frozenset("be am is are was were been being have has had do does did will would can could may might "
                     "must shall should".split())  # fmt: skip


def _counted_people(tokens: list[str], i: int, known: Known) -> int | None:
    """Where "<count> [modifier] <plural noun>" ending at ``i`` begins, when the noun is a plural the
    reader has no phrase for ("two lads", "3 suspects", "two young couriers"), else None. Whether they
    are people is left to what follows: a vehicle they are on and a verb of theirs (:func:`_acts_next`)."""
    word = tokens[i]
    nouns = lemmas(word).get("NOUN", ())
    if not word.isalpha() or not nouns or word in nouns:
        return None  # (no plural noun)
    for j in range(i - 1, max(i - 3, -1), -1):
        w = tokens[j]
        if w in _PEOPLE_COUNTS or (w.isdigit() and int(w) > 1):
            return j
        if not w.isalpha() or known(tokens, j) or w in DETERMINERS:
            return None
    return None


def _acts_next(tokens: list[str], k: int) -> bool:
    """Whether the word at ``k`` is a verb of its own, not one that only helps another ("came", "rode",
    "riding"; not "has", "were"): the noun phrase before it is the subject that acts."""
    w = tokens[k] if k < len(tokens) else ""
    return w not in _HELPING and "VERB" in lemmas(w)


#: Where a person is, said between the person and the vehicle they ride or drive ("the guy behind me in
#: a pickup"): a closed class of place words, each with the words that may follow it before its object.
_PLACE_WORDS = {"ahead": ("of",), "behind": (), "alongside": (), "beside": (), "next": ("to",), "in": ("front", "of")}
#: The objects of such a place: the narrator or the ego (another road user there would be a third party).
_PLACE_OBJECTS = frozenset({"me", "us", "ego", "him", "her", "them"})


def _placement_end(tokens: list[str], i: int) -> int | None:
    """Where a placement of a person starting at ``i`` ends ("behind me", "ahead of us", "in front of
    the ego", "next to me"), or None."""
    after = _PLACE_WORDS.get(tokens[i]) if i < len(tokens) else None
    if after is None:
        return None
    j = i + 1
    for w in after:
        if j < len(tokens) and tokens[j] == w:
            j += 1
        elif w != "of" or tokens[i] != "ahead":  # ("ahead" alone is a place too: "a guy ahead on a bike")
            return None
    if j < len(tokens) and tokens[j] == "the":
        j += 1
    if j < len(tokens) and tokens[j] in _PLACE_OBJECTS:
        return j + 1
    return j if tokens[i] == "ahead" and j == i + 1 else None


def _placed_riders(tokens: list[str], kind_at: KindAt) -> list[str]:
    """ "the guy behind me in a pickup", "a woman ahead of us on a bicycle": a person, where they are,
    then the vehicle they are on or in, said as :func:`_riders` reads one rider ("the guy in a pickup
    behind me"). Only a walker's noun right before the place, and the preposition of riding right after
    it, move; what follows the preposition is left to :func:`_riders` to judge a vehicle or not."""
    out = list(tokens)
    for i in range(1, len(out)):
        found = kind_at(out, i - 1)
        if found is None or found != ("pedestrian", 1):
            continue
        end = _placement_end(out, i)
        if end is None or end >= len(out) or out[end] not in RIDING:
            continue
        k = end + 1  # the vehicle's phrase: a determiner, up to two modifiers, its noun
        k += 1 if k < len(out) and out[k] in DETERMINERS else 0
        head = next((h for h in range(k, min(k + 3, len(out))) if kind_at(out, h) is not None), None)
        if head is None or kind_at(out, head)[0] in ("pedestrian", "ego"):
            continue
        stop = head + kind_at(out, head)[1]
        out[i:stop] = out[end:stop] + out[i:end]
    return out


#: Words that count a plural: counted road users are so many road users ("two joggers"), no generality.
_COUNTED = frozenset("two three four five six seven eight nine ten both several couple pair".split())
#: Words before a plural that make it a place or scenery rather than road users in general.
#: (with the prepositions of place, :data:`_PLACE_BEFORE`)
_A_PLACE = frozenset({"between", "behind", "among", "amongst", "in", "beyond", "parked", "stationary"})
#: Words that end the clause a generic plural is the subject or object of.
_CLAUSE_ENDS = frozenset({"and", "but", "so", "which", "who", "while", "when", "whereas", "because"})


def _ridden_kind(tokens: list[str], p: Phrase, kind_at: KindAt) -> tuple[str, int]:
    """The type a person's phrase names and where it ends, counting what they ride ("teenagers on
    e-bikes", "a teenager on an e-bike": a bicycle's)."""
    k = p.end
    if p.kind != "pedestrian" or k >= len(tokens) or tokens[k] not in ("on", "riding"):
        return p.kind, p.end
    for h in range(k + 1, min(k + 4, len(tokens))):
        found = kind_at(tokens, h)
        if found is not None:
            return (found[0], h + found[1]) if found[0] not in ("pedestrian", "ego") else (p.kind, p.end)
    return p.kind, p.end


def told_in_the_past(tokens: list[str], k: int) -> bool:
    """Whether the verb at ``k``, right after a plural, tells what they did ("were running", "ran",
    "swerved"): those are road users of the event; road users in general do things in the present
    ("cyclists ride here") or may do them."""
    from lemminflect import getAllInflections

    w = tokens[k] if k < len(tokens) else ""
    if w in ("are", "am", "'re"):  # (present: "motorbikes are easy to miss"; "are riding" is these ones now)
        nxt = tokens[k + 1] if k + 1 < len(tokens) else ""
        return nxt.endswith("ing") and "VERB" in lemmas(nxt)
    verbs = lemmas(w).get("VERB", ())
    past = any(w in getAllInflections(v).get("VBD", ()) or w in getAllInflections(v).get("VBN", ()) for v in verbs)
    return w == "were" or (past and not w.endswith(("s", "ing")) and "NOUN" not in lemmas(w))


def _infinitive(tokens: list[str], j: int) -> bool:
    """Whether "to" at ``j`` marks an infinitive ("to pass cyclists"), not a place ("to town")."""
    nxt = tokens[j + 1] if j + 1 < len(tokens) else ""
    return tokens[j] == "to" and nxt in lemmas(nxt).get("VERB", ())


def _new_one(tokens: list[str], p: Phrase) -> bool:
    """Whether phrase ``p`` opens with "a" or "an", past up to two modifiers the reader has words for
    ("a racing bike", "a slow jogger"), with no clause mark between."""
    if p.det in ("a", "an") or tokens[p.head] in SOMEONE:
        return True
    for j in range(p.head - 1, max(p.head - 4, -1), -1):
        if tokens[j] in ("a", "an"):
            return True
        if tokens[j] in PUNCT or tokens[j] in DETERMINERS or tokens[j] in _CLAUSE_ENDS or not tokens[j].isalpha():
            return False
    return False


def _without_spans(tokens: list[str], spans: list[tuple[int, int]], dropped: list[str]) -> list[str]:
    """``tokens`` without the ``spans`` (start, stop), in text order and not overlapping, whose words
    are kept among those not used: a pass that decides what to leave out first, then leaves it out."""
    out = list(tokens)
    for start, stop in spans:
        dropped.extend(tokens[start:stop])
    for start, stop in reversed(spans):
        del out[start:stop]
    return out


def _generic_plurals(tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """ "We regularly see children stepping out ... Please simulate a child running out", "joggers often
    cross here; simulate a jogger crossing": a bare plural (no article, no count) says what road users
    of a type do in general; when the first road user of that type named after it is a new one ("a
    child"), that one is the scenario's, and the plural's clause is left out (listed as not used). A
    plural with nothing after it, or said again first as known ("the van"), is the road user itself."""
    phrases = road_user_phrases(tokens, kind_at, known)
    cut: list[tuple[int, int]] = []
    for n, p in enumerate(phrases):
        before = tokens[p.start - 1] if p.start else ""
        if cut and p.start < cut[-1][1]:
            continue  # (what a plural rides: "on e-bikes", inside the clause already left out)
        if p.det or p.kind == "ego" or is_singular(tokens[p.end - 1]) or before in _COUNTED or before.isdigit():
            continue
        if any(
            (w in _A_PLACE or w in _PLACE_BEFORE) and not _infinitive(tokens, j)
            for j, w in enumerate(tokens[max(p.start - 2, 0) : p.start], max(p.start - 2, 0))
        ):
            continue  # ("out from between parked cars": where someone is, not who; "to pass cyclists": a verb's)
        kind, end = _ridden_kind(tokens, p, kind_at)
        if told_in_the_past(tokens, end):
            continue  # ("joggers were running across in front of me": these ones, no road users in general)
        later = next(
            (q for q in phrases[n + 1 :] if q.start >= end and _ridden_kind(tokens, q, kind_at)[0] == kind), None
        )
        if later is None or not _new_one(tokens, later) or not is_singular(tokens[later.end - 1]):
            continue
        stop = end  # (to the clause's end, or a place: "stepping out between parked cars" keeps the cars)
        while stop < len(tokens) and not (
            tokens[stop] in PUNCT
            or tokens[stop] in _CLAUSE_ENDS
            or tokens[stop] in _A_PLACE
            or tokens[stop] in _PLACE_BEFORE
            or not tokens[stop].replace("-", "").isalpha()
        ):
            stop += 1
        cut.append((p.start, stop))
    return _without_spans(tokens, cut, dropped)


#: Verbs of coming after someone: "X, followed by Y, ..." names two road users going one after the other.
_COMING_AFTER = frozenset({"follow", "trail", "tail", "chase", "pursue", "accompany"})


def _followed_by(tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """ "A cyclist, closely followed by an e-scooter rider, comes off the towpath": a participle of
    coming after, set off by commas, says a second road user who does what the first does, behind it;
    said as "a cyclist and an e-scooter rider comes off ...", which the reader reads as two who share
    the verb. Only a new road user after "by" ("by a ...", not the ego), and no form of "be" before
    ("the cyclist was followed by a van": a clause of its own)."""
    out = list(tokens)
    i = 1
    while i + 2 < len(out):
        if out[i] != "," or kind_at(out, i - 1) is None or kind_at(out, i - 1)[0] == "ego":
            i += 1
            continue
        j = i + 1
        if j < len(out) and out[j].endswith("ly") and "ADV" in lemmas(out[j]):
            j += 1  # ("closely", "immediately")
        passive = j + 1 < len(out) and out[j + 1] == "by" and out[j].endswith("ed")
        if not passive or not (_COMING_AFTER & set(lemmas(out[j]).get("VERB", ()))):
            i += 1
            continue
        head = next((h for h in range(j + 3, min(j + 6, len(out))) if kind_at(out, h) is not None), None)
        q = _phrase_at(out, head, kind_at, known) if head is not None and out[j + 2] in ("a", "an") else None
        if q is None or q.start != j + 2 or q.kind == "ego" or q.end >= len(out) or out[q.end] != ",":
            i += 1
            continue
        dropped.extend(out[i + 1 : j + 2])
        out[i : q.end + 1] = ["and", *out[j + 2 : q.end]]
        i += 1
    return out


#: What "one of" picks a ridden vehicle out of ("one of the hire bikes", "one of them scooters").
_PICKED_OUT_OF = frozenset({"the", "those", "these", "them"})


def _riders(tokens: list[str], kind_at: KindAt, known: Known) -> list[str]:
    """ "a lad on a scooter", "a student on one of those hire bikes", "a woman riding a bike": one
    referent of the vehicle's type, said with the person's determiner."""
    tokens = list(tokens)  # (a vehicle picked out of many is said in the singular, below)
    out: list[str] = []
    i = 0
    while i < len(tokens):
        if tokens[i] not in RIDING or not out:
            out.append(tokens[i])
            i += 1
            continue
        going = _going_words(out, kind_at)  # ("a worker going home on e-scooter": the worker, not "home")
        person_start, counted = (None, False) if going else _person_before(out, kind_at, known)
        place: list[str] = []  # ("the guy in front in a red van": where the person is, said of the vehicle)
        n = _place_words(out) or going
        if person_start is None and n and len(out) > n:
            person_start, counted = _person_before(out[:-n], kind_at, known)
            place = out[-n:] if person_start is not None and not counted else []
            person_start = person_start if place else None
        opener = out[person_start] in DETERMINERS | SOMEONE or counted if person_start is not None else False
        if person_start is None or (not opener and person_start != len(out) - len(place) - 1):
            out.append(tokens[i])
            i += 1
            continue
        # the vehicle: [det | one of those] [up to two modifiers] a rideable noun
        j = i + 1
        picked = tokens[j : j + 2] == ["one", "of"] and j + 2 < len(tokens) and tokens[j + 2] in _PICKED_OUT_OF
        if picked:
            j += 3
        elif j < len(tokens) and tokens[j] in DETERMINERS:
            j += 1
        elif tokens[i] in INSIDE and not _two_wheeler_next(tokens, j, kind_at, known):
            out.append(tokens[i])  # ("a test in which a truck ...": no vehicle a person is in)
            i += 1
            continue
        head = next(
            (h for h in range(j, min(j + 3, len(tokens))) if kind_at(tokens, h) is not None),
            None,
        )
        ride = kind_at(tokens, head) if head is not None else None
        between_known = head is not None and any(known(tokens, h) for h in range(j, head))
        unfit = ("pedestrian", "ego") if tokens[i] in INSIDE else ("pedestrian", "truck", "ego")
        walker_paced = ride is not None and " ".join(tokens[head : head + ride[1]]) in WALKER_PACED
        if (
            ride is None
            or (ride[0] in unfit and not walker_paced)
            or between_known
            or (tokens[i] in INSIDE and _goes_on(tokens, head + ride[1], known))
        ):
            out.append(tokens[i])
            i += 1
            continue
        if counted and not _acts_next(tokens, head + ride[1]):
            out.append(tokens[i])  # ("two weeks on e-scooters has taught me": no riders, a time)
            i += 1
            continue
        if counted:  # ("two lads on e-scooters came ...": so many riders, counted as the vehicles)
            out[person_start:] = [out[person_start]]
            i = j
            continue
        if picked:  # ("a man on one of the hire e-scooters": one e-scooter, said as one)
            tokens[head + ride[1] - 1] = singular(tokens[head + ride[1] - 1])
        det = out[person_start] if out[person_start] in DETERMINERS else "a"  # ("guy on a moped": a rider)
        det = "a" if det in INDEFINITE | POSSESSIVE else det  # ("my mate on his bike": a rider)
        out[person_start:] = [det]
        if place:
            out.extend([*tokens[j : head + ride[1]], *place])
            j = head + ride[1]
        i = j
    return out


#: Words between a relative pronoun and its verb of riding: forms of "be" and "have", and adverbs of
#: habit ("who was riding", "that has been driving", "who always rides").
_RELATIVE_FILLERS = BE | frozenset({"has", "have", "had", "always", "usually", "often", "normally", "just", "still"})


def _rides_at(tokens: list[str], k: int) -> bool:
    """Whether ``tokens[k]`` is a form of a verb of riding ("rides", "rode", "driving", "drove") or
    "on", "aboard" (being on a vehicle)."""
    word = tokens[k]
    return word in ("on", "aboard") or (word.isalpha() and bool(set(lemmas(word).get("VERB", ())) & RIDE_VERBS))


def _vehicle_soon(tokens: list[str], k: int, kind_at: KindAt) -> bool:
    """Whether a vehicle's noun starts within four words after ``k``, before any mark."""
    for h in range(k, min(k + 4, len(tokens))):
        if tokens[h] in PUNCT:
            return False
        found = kind_at(tokens, h)
        if found is not None:
            return found[0] not in ("pedestrian", "ego")
    return False


def relative_riders(tokens: list[str], kind_at: KindAt) -> list[str]:
    """ "the boy who rides the blue scooter", "a woman that was driving a van", "the lad who was on the
    e-scooter": a relative clause of riding says the same as the participle ("the boy riding the blue
    scooter"), so the person and the vehicle are one road user, read by :func:`_riders`. Only "who" or
    "that" right after a word, then forms of "be"/"have" or adverbs of habit, then the verb; what
    follows the verb is left to :func:`_riders` (a vehicle must follow: "a man who was driving behind
    me" names none, and stays as it is)."""
    out: list[str] = []
    i = 0
    while i < len(tokens):
        if tokens[i] in ("who", "that") and out and out[-1].isalpha() and out[-1] not in PUNCT:
            k = i + 1
            while k < len(tokens) and k < i + 4 and tokens[k] in _RELATIVE_FILLERS:
                k += 1
            if k < len(tokens) and _rides_at(tokens, k) and _vehicle_soon(tokens, k + 1, kind_at):
                out.append("on" if tokens[k] in ("on", "aboard") else "riding")
                i = k + 1
                continue
        out.append(tokens[i])
        i += 1
    return out


#: Words right before the people one speaks to ("morning guys", "sorry folks", "thanks everyone", "you
#: guys"): greetings, apologies, thanks and calls for attention, a closed class.
_ADDRESSING = frozenset({"hi", "hello", "hey", "hiya", "morning", "afternoon", "evening", "sorry", "thanks",
                         "cheers", "okay", "ok", "alright", "look", "listen", "oh", "you", "dear"})  # fmt: skip


def _plural_noun(word: str) -> bool:
    """Whether ``word`` is a noun's plural ("guys", "gentlemen"), not its stem."""
    nouns = lemmas(word).get("NOUN", ()) if word.isalpha() else ()
    return bool(nouns) and word not in nouns


def _in_a_list(tokens: list[str], i: int, end: int, kind_at: KindAt) -> bool:
    """Whether the phrase ``tokens[i:end]`` is an item of a list of road users set off by commas ("a car,
    cyclists, a bus"): a road user's noun right before the comma before it or right after the one after."""
    before = i >= 2 and tokens[i - 1] == "," and kind_at(tokens, i - 2) is not None
    after = end + 1 < len(tokens) and tokens[end] == "," and kind_at(tokens, end + 1) is not None
    return before or after


def vocatives(tokens: list[str], kind_at: KindAt, dropped: list[str]) -> list[str]:
    """``tokens`` without the people a writer or speaker addresses ("Morning guys!", "sorry folks,",
    "..., ladies and gentlemen, ...", "five feet, you guys."): a bare plural of people (and one joined
    to it by "and") set off by marks, after a mark, the start, or a word of greeting, thanks or apology,
    is the audience, no road user. Not an item of a list of road users ("a car, cyclists, a bus"), nor
    people with a determiner, a count, or a verb right after them ("kids ran out")."""
    out: list[str] = []
    i = 0
    while i < len(tokens):
        found = kind_at(tokens, i)
        if found is None or found[0] != "pedestrian" or not _plural_noun(tokens[i + found[1] - 1]):
            out.append(tokens[i])
            i += 1
            continue
        end = i + found[1]
        if tokens[end : end + 1] == ["and"] and end + 1 < len(tokens) and _plural_noun(tokens[end + 1]):
            end += 2  # ("ladies and gentlemen")
        before = tokens[i - 1] if i else "."
        after = tokens[end] if end < len(tokens) else "."
        if before in PUNCT | _ADDRESSING and after in PUNCT and not _in_a_list(tokens, i, end, kind_at):
            dropped.extend(tokens[i:end])
            i = end
            continue
        out.append(tokens[i])
        i += 1
    return out


#: Where someone is, said right after their noun ("the guy in front", "a lad next to me").
_PLACE_PHRASES = (
    ("in", "front", "of", "me"), ("in", "front", "of", "us"), ("next", "to", "me"), ("next", "to", "us"),
    ("ahead", "of", "me"), ("ahead", "of", "us"), ("behind", "me"), ("behind", "us"), ("beside", "me"),
    ("beside", "us"), ("in", "front"), ("ahead",), ("behind",), ("alongside",), ("opposite",),
)  # fmt: skip


def _place_words(out: list[str]) -> int:
    """How many words at the end of ``out`` say where someone is ("in front", "behind me"), else 0."""
    return next((len(p) for p in _PLACE_PHRASES if tuple(out[-len(p) :]) == p), 0)


#: How many words back from "on" a participle of going may stand ("heading back to the depot on").
_GOING_SPAN = 6


def _going_words(out: list[str], kind_at: KindAt) -> int:
    """How many words at the end of ``out`` are a participle of going and where to ("going home",
    "heading back to the depot", "travelling to work"), else 0: said between a person and what they
    ride ("a worker going home on e-scooter"), they tell where the rider goes, not who rides. No mark
    and no road user's noun may stand among them ("a man crossing, then a bike")."""
    for back in range(1, min(_GOING_SPAN, len(out)) + 1):
        w = out[-back]
        if w in PUNCT or kind_at(out, len(out) - back) is not None:
            return 0
        if w.endswith("ing") and set(lemmas(w).get("VERB", ())) & TRAVEL_VERBS:
            return back
    return 0


def _person_before(out: list[str], kind_at: KindAt, known: Known) -> tuple[int | None, bool]:
    """Where the person whose noun ends ``out`` begins (a walker's noun, a word the reader lacks after
    a determiner, a count of people, "someone", or a bare person's noun opening a clause), and
    whether it is a count of people; (None, False) if no person ends it."""
    k = len(out) - 1
    for back in range(k, max(k - 3, -1), -1):
        found = kind_at(out, back)
        if found is not None and found[0] == "pedestrian" and back + found[1] == k + 1:
            p = _phrase_at(out, back, kind_at, known)
            if p is not None and p.det:  # (else a longer noun may end here: "an old man")
                return p.start, False
    person_start = None
    if not known(out, k):
        person_start = _unknown_person(out, k, known)
    if person_start is None and not known(out, k):
        person_start = _counted_people(out, k, known)
        if person_start is not None:
            return person_start, True
    if person_start is None and out[k] in SOMEONE:
        return k, False  # ("behind someone on a bike": a rider, new)
    if person_start is None:
        person_start = _bare_person(out, kind_at)
    return person_start, False


#: Words that make the vehicle after "on" one vehicle for all who ride it ("on one", "on a single").
_ONE_VEHICLE = (["one"], ["a", "single"], ["the", "same"], ["a"], ["an"])
#: Types of vehicle several people can ride at once, two-up.
_RIDDEN = frozenset({"bicycle", "e-scooter", "car"})


def _people_phrase_end(tokens: list[str], i: int, kind_at: KindAt, known: Known) -> int | None:
    """Where "<count> [modifier] <plural noun of people>" starting at ``i`` ends ("two kids", "three
    young lads"), or None: a person's plural, or a plural noun the reader has no phrase for."""
    w = tokens[i]
    if not (w in _PEOPLE_COUNTS or (w.isdigit() and int(w) > 1)):
        return None
    for h in range(i + 1, min(i + 4, len(tokens))):
        word = tokens[h]
        nouns = lemmas(word).get("NOUN", ())
        plural = word.isalpha() and bool(nouns) and word not in nouns
        found = kind_at(tokens, h)
        if plural and (found == ("pedestrian", 1) or (found is None and not known(tokens, h))):
            return h + 1
        if not word.isalpha() or found is not None or word in DETERMINERS or word in PUNCT:
            return None
    return None


def _last_ridden(tokens: list[str], i: int, kind_at: KindAt) -> str | None:
    """The singular noun of the last vehicle people ride named before ``i`` in its sentence, or None."""
    for h in range(i - 2, -1, -1):
        if tokens[h] in SENTENCE_END:
            return None
        found = kind_at(tokens, h)
        if found is not None and found[1] == 1 and found[0] in _RIDDEN and is_singular(tokens[h]):
            return tokens[h]
    return None


def shared_vehicles(tokens: list[str], kind_at: KindAt, known: Known) -> list[str]:
    """ "two kids on one e-scooter", "three lads on a single bike", "two girls on the same scooter":
    several people on one vehicle ride it together (two-up), one road user, said as that vehicle ("a
    e-scooter"). And "his mate on another" with no noun after it is on another of the vehicle just
    named ("on another bike"). Several people on vehicles ("two kids on e-scooters") stay so many."""
    out = list(tokens)
    i = 0
    while i < len(out):
        end = _people_phrase_end(out, i, kind_at, known)
        if end is not None and end < len(out) and out[end] in ("on", "riding"):
            one = next((o for o in _ONE_VEHICLE if out[end + 1 : end + 1 + len(o)] == o), None)
            at = end + 1 + len(one) if one is not None else len(out)
            found = kind_at(out, at) if at < len(out) else None
            if found is not None and found[0] in _RIDDEN and is_singular(out[at + found[1] - 1]):
                out[i:at] = ["a"]
        if out[i] == "another" and i and out[i - 1] in ("on", "riding") and kind_at(out, i + 1) is None:
            ridden = _last_ridden(out, i, kind_at)
            if ridden is not None:
                out.insert(i + 1, ridden)  # ("on another": another of the vehicle said before)
        i += 1
    return out


def _riders_own(tokens: list[str], kind_at: KindAt, known: Known) -> list[str]:
    """ "a cyclist on a racing bike", "an e-scooter rider on a hire scooter", "a motorcyclist on a big
    bike": a rider's noun already names what is ridden, so the vehicle after "on" or "riding" is theirs,
    one road user; its words go (they were read). Only a vehicle of the rider's own type, or "bike"
    under a motor two-wheeler's rider, after an article and up to two modifiers."""
    out = list(tokens)
    for p in reversed(road_user_phrases(tokens, kind_at, known)):
        if p.kind in ("pedestrian", "ego") or p.end + 1 >= len(out) or out[p.end] not in ("on", "riding"):
            continue
        j = p.end + 1
        if out[j : j + 3] in (["one", "of", "those"], ["one", "of", "these"]):
            j += 3
        elif out[j] in ("a", "an", "his", "her", "their"):
            j += 1
        else:
            continue
        head = next((h for h in range(j, min(j + 3, len(out))) if kind_at(out, h) is not None), None)
        if head is None or any(not out[h].isalpha() or out[h] in _NOT_MODIFIERS for h in range(j, head)):
            continue
        ride, n = kind_at(out, head)
        motor = " ".join(out[p.head : p.end]) in MOTOR_TWO_WHEELERS and out[head : head + n] == ["bike"]
        if ride == p.kind or motor:
            del out[p.end : head + n]
    return out


#: Words that end a vehicle's modifiers: a new clause or phrase, not a description.
_NOT_MODIFIERS = frozenset({"and", "or", "but", "then", "with", "of", "in", "on", "to", "from"})


def _two_wheeler_next(tokens: list[str], j: int, kind_at: KindAt, known: Known) -> bool:
    """Whether a bicycle's or an e-scooter's noun follows at ``j`` with no article, past up to two
    modifiers the reader has no phrase for: "a boy in bicycle", "one woman in electric scooter" (English
    of writers whose language has no articles, or says "in" where English says "on")."""
    for h in range(j, min(j + 3, len(tokens))):
        found = kind_at(tokens, h)
        if found is not None:
            return found[0] in ("bicycle", "e-scooter")
        if not tokens[h].isalpha() or known(tokens, h):
            return False
    return False


def _bare_person(out: list[str], kind_at: KindAt) -> int | None:
    """Where a person's noun with no determiner that opens a clause ends ``out`` ("Guy on a moped
    coming the wrong way", "..., bloke in a white van pulls out"), else None."""
    k = len(out) - 1
    found = kind_at(out, k)
    opens = k == 0 or out[k - 1] in PUNCT
    return k if found is not None and found == ("pedestrian", 1) and opens else None


def _goes_on(tokens: list[str], k: int, known: Known) -> bool:
    """Whether the noun phrase goes on past ``k`` with a noun the reader has no phrase for ("a baby in a
    car seat": the seat, not the car). An adverb is no noun ("a man in a van just pulled out": the van's
    phrase ends there). Nor is a verb inflected for its subject with a particle or preposition after it
    ("a guy in a Charger blows past me", "a lad in a Corsa tears off": the person's verb, though
    "blows" and "tears" are nouns too)."""
    if k >= len(tokens) or not tokens[k].isalpha() or known(tokens, k) or tokens[k] in PREPOSITIONS:
        return False
    pos = lemmas(tokens[k])
    return not ("ADV" in pos and "NOUN" not in pos) and not _verb_with_particle(tokens, k)


def _verb_with_particle(tokens: list[str], k: int) -> bool:
    """Whether the word at ``k`` is a verb inflected away from its stem ("blows", "whipped") with a
    particle or preposition right after it ("past", "across", "off"): a verb, even where the word
    can also be a plural noun."""
    stems = lemmas(tokens[k]).get("VERB", ())
    inflected = bool(stems) and tokens[k] not in stems and tokens[k].endswith(("s", "ed"))
    return inflected and k + 1 < len(tokens) and tokens[k + 1] in PREPOSITIONS | _PARTICLES


#: Animals: one led, walked or ridden by a person ("a man leading a horse", "a girl riding a pony") is
#: in that person's hands, one road user.
ANIMAL_WORDS = frozenset(ANIMALS) - {"animal"}


#: Verbs of riding: a person doing one of them to a vehicle rides it ("a woman riding a bike").
RIDE_VERBS = frozenset({"ride", "pedal", "drive", "scoot"})


def _by_its_object(tokens: list[str], j: int, head: int | None) -> bool:
    """Whether the vehicle's noun at ``head`` is the object of the verb whose words after it start at
    ``j``: no preposition of riding stands between ("pushing a bike" is; "going home on e-scooter" is
    not: there the person rides it, and a verb of going says where)."""
    return head is not None and not any(tokens[h] in RIDING for h in range(j, head))


def _pushed(tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """ "a man pushing a bike", "a girl wheeling her e-scooter": a walker with a vehicle in hand, one
    road user (a walker); any verb in -ing but a verb of riding puts the bike in the walker's hands.
    Only as the verb's object: a preposition of riding between them ("a worker going home on
    e-scooter", "a student heading to class on bike") puts the walker on it, a rider (:func:`_by_its_object`)."""
    out: list[str] = []
    i = 0
    while i < len(tokens):
        w = tokens[i]
        animal = i + 2 < len(tokens) and any(t in ANIMAL_WORDS for t in tokens[i + 1 : i + 3])
        if w.endswith("ing") and out and (animal or not _lemma_in(w, RIDE_VERBS)) and (animal or w not in RIDING):
            before = next((b for b in range(len(out) - 1, max(len(out) - 3, -1), -1) if kind_at(out, b)), None)
            person = kind_at(out, before) if before is not None else None
            j = i + 1 + (i + 1 < len(tokens) and tokens[i + 1] in DETERMINERS)
            head = next((h for h in range(j, min(j + 3, len(tokens))) if kind_at(tokens, h) is not None), None)
            thing = kind_at(tokens, head) if head is not None else None
            plain = head is not None and not any(known(tokens, h) for h in range(j, head))
            if (
                _by_its_object(tokens, j, head)
                and person is not None
                and person[0] == "pedestrian"
                and before + person[1] == len(out)
                and thing is not None
                and (thing[0] in ("bicycle", "e-scooter") or tokens[head] in ANIMAL_WORDS)
                and plain
            ):
                dropped.extend(tokens[i : head + thing[1]])
                i = head + thing[1]
                continue
        out.append(w)
        i += 1
    return out


def _person_at(tokens: list[str], i: int, kind_at: KindAt, known: Known) -> int:
    """The length of a noun for whoever is at the wheel or handlebars at ``i``: a road-user noun ("the
    driver", "the cyclist") or an agent noun the reader has no phrase for ("the rider", "the
    operator"), else 0."""
    found = kind_at(tokens, i)
    if found is not None:
        return found[1] if found[0] != "ego" else 0
    w = tokens[i]
    return 1 if w.endswith(("er", "or")) and w.isalpha() and not known(tokens, i) and _agent_noun(w) else 0


def _agent_noun(word: str) -> bool:
    """Whether ``word`` names who does a verb ("rider": ride, "operator": operate, "owner": own), not a
    thing or place ("corner", "border")."""
    stems = (word[:-1], word[:-2], word[:-2] + "e")
    return any(stem in lemmas(stem).get("VERB", ()) for stem in stems if len(stem) > 2)


def _vehicle_phrase_at(tokens: list[str], k: int, kind_at: KindAt, known: Known) -> Phrase | None:
    """The phrase of a motor vehicle that opens with its determiner at ``k`` ("the lorry ahead", "a
    moped", "her car"), else None (also where the vehicle's word only modifies a noun: "a car seat")."""
    if k >= len(tokens) or tokens[k] not in DETERMINERS:
        return None
    head = next((h for h in range(k + 1, min(k + 4, len(tokens))) if kind_at(tokens, h)), None)
    q = _phrase_at(tokens, head, kind_at, known) if head is not None else None
    if q is None or q.kind not in VEHICLES or q.start != k or _compound_head_at(tokens, q.end, known):
        return None
    return q


def _compound_head_at(tokens: list[str], k: int, known: Known) -> bool:
    """Whether the word at ``k`` is a noun that the vehicle's word before it only modifies ("a car seat",
    "a Tesco car uniform", "the van door", "a Nike car top"): a noun (or a word lemminflect calls an
    adjective only, "top") in its own form that the reader has no phrase for; a verb it knows ("cut")
    or an inflected verb ("shot", "stopped") goes on the sentence."""
    w = tokens[k] if k < len(tokens) else ""
    forms = lemmas(w)
    inflected_verb = any(v != w for v in forms.get("VERB", ()))  # ("shot", "noted": a verb's past goes on)
    return w in (*forms.get("NOUN", ()), *forms.get("ADJ", ())) and not inflected_verb and not known(tokens, k)


def _occupant_at(tokens: list[str], i: int, n: int, kind_at: KindAt) -> bool:
    """Whether the person's noun of ``n`` words at ``i`` is said to sit in a vehicle ("the man in the
    car", "a woman in a van"): a walker's noun (or an agent noun the reader has no phrase for) followed
    by "in". A road user's own vehicle noun ("the van in the car park") is no one sitting."""
    found = kind_at(tokens, i)
    return tokens[i + n : i + n + 1] == ["in"] and (found is None or found[0] == "pedestrian")


def _drivers(tokens: list[str], kind_at: KindAt, known: Known) -> list[str]:
    """ "the driver of the lorry ahead", "the rider of a moped", "the van's driver", "the man in the
    car": whoever is at the wheel of a vehicle or sits in it is the vehicle, one road user (said as the
    vehicle's phrase). A person in what is no motor vehicle ("a man in a wheelchair") is themselves."""
    out: list[str] = []
    i = 0
    while i < len(tokens):
        n = _person_at(tokens, i, kind_at, known) if out and out[-1] in DETERMINERS else 0
        if n and (tokens[i + n : i + n + 1] == ["of"] or _occupant_at(tokens, i, n, kind_at)):
            q = _vehicle_phrase_at(tokens, i + n + 1, kind_at, known)
            if q is not None:
                det = out.pop()  # (the person's article)
                i = q.start
                if det in DEFINITE | {"this"} and tokens[q.start] in ("a", "an"):
                    out.append(det)  # ("this guy in a red SUV": the one pointed back to, in its vehicle)
                    i += 1
                continue
        n = _person_at(tokens, i, kind_at, known)
        if n and len(out) >= 2 and out[-1] == "'s" and (kind_at(out, len(out) - 2) or ("", 0))[0] in VEHICLES:
            out.pop()  # ("the van's driver": the van)
            i += n
            continue
        out.append(tokens[i])
        i += 1
    return out


def _companions(tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """ "a woman with her dog": the walker is the road user; the one with it is not, unless it is
    named again (then it is a referent of its own from there: "the dog" is said "a dog")."""
    out: list[str] = []
    companions: set[str] = set()
    i = 0
    while i < len(tokens):
        if tokens[i] in companions and out and out[-1] in DEFINITE | POSSESSIVE:
            companions.discard(tokens[i])
            out[-1] = "an" if tokens[i][0] in "aeiou" else "a"
            out.append(tokens[i])
            i += 1
            continue
        if tokens[i] == "with" and out:
            before = next((b for b in range(len(out) - 1, max(len(out) - 3, -1), -1) if kind_at(out, b)), None)
            person = kind_at(out, before) if before is not None else None
            ends = person is not None and before + person[1] == len(out)
            j = i + 1
            if j < len(tokens) and tokens[j] in DETERMINERS:
                j += 1
            head = next((h for h in range(j, min(j + 3, len(tokens))) if kind_at(tokens, h) is not None), None)
            other = kind_at(tokens, head) if head is not None else None
            if ends and person[0] == "pedestrian" and other is not None and other[0] == "pedestrian":
                dropped.extend(tokens[j : head + other[1]])
                companions.add(tokens[head + other[1] - 1])
                i = head + other[1]
                continue
        out.append(tokens[i])
        i += 1
    return out


#: At most this many words in an apposition set off by commas ("my passenger, an old lady going home
#: from the theatre,").
_APPOSITION_WORDS = 10


def _companion_apposition(tokens: list[str], i: int, kind_at: KindAt) -> int | None:
    """Where the apposition after the narrator's "my/our <noun>" at ``i`` ends ("my passenger, an
    elderly lady going home from the theatre, ..."), when it is a new person set off by a comma: that
    person is the narrator's companion said again, no road user. The noun owned must be a person's or
    one the reader has no phrase for (not "on my left, a man ...": a side, and the man is new)."""
    if i + 3 >= len(tokens) or tokens[i + 2] != "," or tokens[i + 3] not in ("a", "an"):
        return None
    owned = kind_at(tokens, i + 1)
    if not (owned == ("pedestrian", 1) or (owned is None and "NOUN" in lemmas(tokens[i + 1]))):
        return None
    if tokens[i + 1] in ("left", "right", "side", "lane", "way"):
        return None
    person = next((h for h in range(i + 4, min(i + 7, len(tokens))) if kind_at(tokens, h) is not None), None)
    if person is None or kind_at(tokens, person)[0] != "pedestrian":
        return None
    close = next((k for k in range(person, min(person + _APPOSITION_WORDS, len(tokens))) if tokens[k] in PUNCT), None)
    return close if close is not None and tokens[close] == "," else None


def _narrators_people(tokens: list[str], kind_at: KindAt, dropped: list[str]) -> list[str]:
    """People and animals the narrator calls theirs ("drove my kid to school", "our dog in the back")
    travel with the ego or stay at home: no road users of the scenario; nor is a person set in
    apposition to one of them ("my passenger, an old lady going home,": :func:`_companion_apposition`)."""
    out: list[str] = []
    i = 0
    while i < len(tokens):
        if tokens[i] in ("my", "our") and (close := _companion_apposition(tokens, i, kind_at)) is not None:
            out.extend(tokens[i : i + 2])
            dropped.extend(tokens[i + 3 : close])
            i = close
            continue
        if tokens[i] in ("my", "our") and i + 1 < len(tokens):
            found = kind_at(tokens, i + 1)
            owner = found is not None and tokens[i + 1 + found[1] : i + 2 + found[1]] == ["'s"]  # ("my mate's car")
            if found is not None and found[0] == "pedestrian" and not owner:
                dropped.extend(tokens[i : i + 1 + found[1]])
                i += 1 + found[1]
                continue
        out.append(tokens[i])
        i += 1
    return out


#: Colours, a closed class: before a noun they are its modifiers ("a grey Audi"), whatever else the
#: reader reads them as alone ("grey" skies).
COLOURS = frozenset(
    "white black grey gray silver red blue green yellow orange brown purple pink gold beige maroon navy".split()
)
#: Shades, a closed class: before a colour they are part of it ("a dark blue Leaf"), whatever the reader
#: reads them as alone ("dark" evening, "light" traffic).
SHADES = frozenset({"dark", "light", "pale", "bright", "deep"})


def apposition_end(tokens: list[str], i: int, kind_at: KindAt, known: Known, most: int = 3) -> int | None:
    """Where an apposition starting at ``i`` ends (", a tiny Fiat," / "a battered old Ford"): an
    indefinite article, up to ``most`` words that are vehicle nouns or words the reader has no phrase
    for, then a punctuation mark or the end."""
    j = i + 1 if i < len(tokens) and tokens[i] == "," else i
    if j >= len(tokens) or tokens[j] not in ("a", "an"):
        return None
    for k in range(j + 1, min(j + most + 2, len(tokens) + 1)):
        if k == len(tokens) or tokens[k] in PUNCT:
            found = [kind_at(tokens, h) for h in range(j + 1, k)]
            if any(f is not None and f[0] not in VEHICLES for f in found):
                return None  # (", a cyclist, ...": someone else)
            return k if any(f is not None for f in found) or k > j + 1 else None
        nxt = tokens[k + 1] if k + 1 < len(tokens) else "."
        number = tokens[k].replace(".", "", 1).isdigit()  # ("a 2019 Honda", "a 7.5 t lorry")
        year = number and nxt.isalpha() and nxt not in UNITS_AFTER | SPEED_UNITS | {"kph", "kmh"}
        if year:
            continue
        modifier = (tokens[k] in COLOURS or (tokens[k] in SHADES and nxt in COLOURS)) and nxt not in PUNCT
        if not tokens[k].replace("-", "").isalpha() or (
            known(tokens, k) and kind_at(tokens, k) is None and not modifier
        ):
            return None  # (", a car ahead brakes": a clause of its own)
    return None


def _own_vehicle(tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """The narrator's vehicle named as a vehicle ("we were in a hire car", "car full of bags") is the
    ego; a second name of it in apposition is the same; what it is full of is no road user."""
    first_person = bool(FIRST_PERSON & set(tokens))
    out = list(tokens)
    i = 0
    while i < len(out):
        p = _phrase_at(out, i, kind_at, known)
        if p is None or p.kind not in VEHICLES:
            i += 1
            continue
        full = out[p.end : p.end + 2] == ["full", "of"]
        inside = first_person and p.det in ("a", "an", "my", "our") and p.start > 0 and out[p.start - 1] == "in"
        if inside:  # "in a hire car" said of the narrator being somewhere ("we were ... in a hire car")
            j = p.start - 2
            narrator = j >= 0 and out[j] in ("i", "we")  # ("I'm in a hatchback": its "'m" read past)
            while j >= 0 and out[j] not in SENTENCE_END and out[j] not in BE:
                j -= 1
            inside = narrator or (j >= 1 and out[j] in BE and out[j - 1] in ("i", "we"))
        if full:
            k = p.end + 2
            while k < len(out) and out[k] not in PUNCT:
                k += 1
            dropped.extend(out[p.end : k])
            del out[p.end : k]
        if inside or (full and first_person and p.det in ("", "my", "our")):
            dropped.extend(out[p.start : p.end])
            out[p.start : p.end] = ["the", "ego"]
            after = p.start + 2
            end = apposition_end(out, after, kind_at, known)
            if end is not None:
                dropped.extend(w for w in out[after:end] if w != ",")
                del out[after:end]
            i = p.start + 2
            continue
        i = p.end
    return out


def _plain_modifier(tokens: list[str], h: int, known: Known) -> bool:
    """Whether the word at ``h`` may stand before a vehicle's noun ("a 7.5 t", "a white", "a battered")."""
    w = tokens[h]
    return w.replace(".", "").isdigit() or (w.isalpha() and not known(tokens, h)) or w in COLOURS or w in UNITS_AFTER


def _ego_predicate(tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """ "The ego is a 7.5 t lorry", "host vehicle was a minibus": a vehicle said of the ego with a form of
    "be" says what the ego is, no second road user."""
    out = list(tokens)
    for e in range(len(out) - 3):
        ego = kind_at(out, e)
        if ego is None or ego[0] != "ego":
            continue
        i = e + ego[1] - 1  # (the ego's last word: "host vehicle")
        field = out[i + 1 : i + 2] == [":"]  # ("Reporting vehicle: city shuttle bus, ...")
        if i + 3 >= len(out) or not (field or (out[i + 1] in ("is", "was") and out[i + 2] in ("a", "an"))):
            continue
        first = i + 2 + (out[i + 2] in ("a", "an"))
        head = next((h for h in range(first, min(first + 4, len(out))) if kind_at(out, h)), None)
        q = _phrase_at(out, head, kind_at, known) if head is not None else None
        plain = all(_plain_modifier(out, h, known) for h in range(first, head or 0))
        if q is not None and q.kind in VEHICLES and plain:
            noun = out[q.head : q.end]
            dropped.extend(out[i + 2 : q.end])
            del out[i + 2 : q.end]  # ("the ego is turning left ...": what it does stays its)
            return _said_again_as_ego(out, i + 2, noun, kind_at, known, dropped)
    return out


#: Pronouns that speak of every or no person at all: what they "are" is a kind of person in general.
EVERYONE = frozenset({"everyone", "everybody", "anyone", "anybody", "nobody", "noone", "none"})
#: Modal verbs: what follows may happen, it is not told as what did.
_MODAL_VERBS = frozenset("will would could might may must can should shall".split())
#: Modal and negating words between such a pronoun and "be" ("anyone can be", "nobody is ever").
_MODAL_OR_NEGATING = _MODAL_VERBS | {"not", "ever", "always"}


def _what_everyone_is(tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """ "Not everyone is bad driver", "nobody is a perfect driver", "anyone can be a careless cyclist",
    "no one is the perfect motorist": a road user's noun said with "be" of a pronoun of every or no
    person is what people in general are, no road user of the scene; the noun and its modifiers are
    left out (listed as not used). A road user said of someone in the scene ("there is a van", "he was
    a cyclist") stays (the pronouns are a closed class)."""
    out = list(tokens)
    i = 0
    while i < len(out):
        if out[i] not in EVERYONE and out[i : i + 2] != ["no", "one"]:
            i += 1
            continue
        j = i + (2 if out[i] == "no" else 1)
        while j < len(out) and out[j] in _MODAL_OR_NEGATING:
            j += 1
        if j >= len(out) or out[j] not in BE:
            i = j
            continue
        first = j + 1 + (j + 1 < len(out) and out[j + 1] in DETERMINERS)
        head = next((h for h in range(first, min(first + 3, len(out))) if kind_at(out, h)), None)
        q = _phrase_at(out, head, kind_at, known) if head is not None else None
        if q is not None and q.kind != "ego" and all(_plain_modifier(out, h, known) for h in range(first, head)):
            dropped.extend(out[j + 1 : q.end])
            del out[j + 1 : q.end]
        i = j + 1
    return out


def _said_again_as_ego(tokens: list[str], start: int, noun: list[str], kind_at: KindAt, known: Known,
                       dropped: list[str]) -> list[str]:  # fmt: skip
    """``tokens`` with each "the <noun>" from ``start`` on said "the ego", until one is named new."""
    out = list(tokens)
    i = start
    while i < len(out):
        p = _phrase_at(out, i, kind_at, known)
        if p is None:
            i += 1
            continue
        if out[p.head : p.end] == noun and p.det in ("a", "an", "another"):
            break
        if out[p.head : p.end] == noun and p.det == "the":
            dropped.extend(out[p.start + 1 : p.end])
            out[p.start : p.end] = ["the", "ego"]
            i = p.start + 2
            continue
        i = p.end
    return out


def _ego_apposition(tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """ "the ego, an estate car, travels ...", "Vehicle 1 (V1), a Ford Focus, ...", "the host vehicle,
    a dark blue Nissan Leaf hatchback, ...": a vehicle said in apposition to the ego, by any of its
    names but a pronoun, is the ego, no second road user. A report describes its own vehicle at length
    (colour, make, model, body), so the apposition may run to five words; it must still close with a
    punctuation mark and name nothing but a vehicle, so ", a car overtakes" stays a clause."""
    out = list(tokens)
    i = 0
    while i + 1 < len(out):
        found = kind_at(out, i)
        n = found[1] if found is not None and found[0] == "ego" and out[i] not in PRONOUNS_EGO else 0
        end = None
        if n and i + n < len(out) and out[i + n] == ",":
            end = apposition_end(out, i + n, kind_at, known, most=5)
            end = _definite_apposition_end(out, i + n, kind_at, known) if end is None else end
            noun = _described_apposition(out, i + n, kind_at, known) if end is None else None
            if noun is not None:  # ("Vehicle 1, a car travelling east on Mill Rd, struck ...": the ego
                names = _vehicle_names(out, i + n + 1, noun, kind_at, known)  # travelling east, said once)
                dropped.extend(out[i + n + 1 : noun])
                del out[i + n + 1 : noun]
                out = _named_again_as_ego(out, i + n, names, kind_at, known, dropped)
        name = i - (i > 0 and out[i - 1] in DEFINITE)  # (where the ego's name starts: "the ego")
        before = _vehicle_before_ego(out, name, i + n, kind_at, known) if n and end is None else None
        if end is not None:
            names = _vehicle_names(out, i + n, end, kind_at, known)
            dropped.extend(out[i + n + 1 : end])
            del out[i + n : end]
            out = _named_again_as_ego(out, i + n, names, kind_at, known, dropped)
        elif before is not None:
            names = _vehicle_names(out, before, name - 1, kind_at, known)
            dropped.extend(out[before : name - 1])
            del out[before:name]  # ("a silver Tesla, the ego, rolls up": the ego, said once)
            i = before + i - name
            out = _named_again_as_ego(out, i + n, names, kind_at, known, dropped)
        i += max(n, 1)
    return out


#: Words that may open what a report says of its vehicle right after naming it in apposition to the
#: ego ("Vehicle 1, a car in lane 1 ...", "Unit 1, a pickup northbound ...").
_DESCRIBED_BY = frozenset(("in", "on", "along", "with", "from", "towards", "toward", "heading", "at"))


def _described_apposition(tokens: list[str], comma: int, kind_at: KindAt, known: Known) -> int | None:
    """Where the vehicle's noun phrase ends, in an apposition to the ego's name that goes on to say what
    that vehicle was doing ("Vehicle 1, a car travelling east on the A614, struck ...", "Unit 1, a
    passenger car northbound in the left lane, changed lanes"): after the comma at ``comma``, "a"/"an",
    a vehicle's noun phrase (as :func:`apposition_end` reads one), then a participle, a "-bound" heading
    or a preposition, and a comma closing it all before the sentence ends. The noun phrase is the ego
    named again; what follows it is said of the ego. None where it is anything else (", a car
    overtakes": a clause of its own; ", a cyclist riding ...": someone else)."""
    j = comma + 1
    if j >= len(tokens) or tokens[j] not in ("a", "an"):
        return None
    p = next((q for q in road_user_phrases(tokens[: j + 7], kind_at, known) if q.start == j), None)
    if p is None or p.kind not in VEHICLES or p.end >= len(tokens):
        return None
    nxt = tokens[p.end]
    participle = nxt.endswith(("ing", "ed", "en")) and "VERB" in lemmas(nxt)  # ("travelling", "stopped")
    participle = participle or nxt.endswith("bound") or nxt in _DESCRIBED_BY
    if not participle:
        return None
    for k in range(p.end + 1, len(tokens)):
        if tokens[k] in SENTENCE_END:
            return None
        if tokens[k] == ",":
            return p.end
    return None


def _vehicle_names(tokens: list[str], start: int, end: int, kind_at: KindAt, known: Known) -> tuple[str, set[str]]:
    """The kind of the vehicle said between ``start`` and ``end`` and the words of its noun ("a dark
    blue Passat": car, {"passat"}; "a red Polo car": car, {"polo", "car"}): what a later "the
    <noun>" repeats of it. Empty where no vehicle's noun is there."""
    phrases = [p for p in road_user_phrases(tokens[:end], kind_at, known) if p.start >= start]
    vehicle = next((p for p in reversed(phrases) if p.kind in VEHICLES), None)
    return ("", set()) if vehicle is None else (vehicle.kind, set(tokens[vehicle.head : vehicle.end]))


def _vehicle_before_ego(tokens: list[str], i: int, end: int, kind_at: KindAt, known: Known) -> int | None:
    """Where a vehicle said just before the ego's name (from ``i`` up to ``end``) starts, when the
    ego's name stands in apposition to it ("A silver Tesla, the ego, rolls up", "A red Polo, the
    subject vehicle, travels ..."): the vehicle, with "a"/"an", opens its sentence and ends at the
    comma before the ego's name, and a comma closes the name with no list after it ("a van, the ego,
    and a cyclist" is a list). The two name one vehicle, the ego."""
    if (
        i < 2
        or tokens[i - 1] != ","
        or tokens[end : end + 1] != [","]
        or tokens[end + 1 : end + 2] in (["and"], ["or"])
    ):
        return None
    phrases = road_user_phrases(tokens[: i - 1], kind_at, known)
    p = phrases[-1] if phrases else None
    if p is None or p.kind not in VEHICLES or p.end != i - 1 or p.det not in ("a", "an"):
        return None
    return p.start if p.start == 0 or tokens[p.start - 1] in SENTENCE_END | {":"} else None


def _named_again_as_ego(tokens: list[str], start: int, names: tuple[str, set[str]], kind_at: KindAt, known: Known,
                        dropped: list[str]) -> list[str]:  # fmt: skip
    """``tokens`` with each later "the <noun>" that repeats the ego's own vehicle (``names``: its kind
    and the words of its noun, "a blue Passat ... the Passat", "a red Polo car ... the car") said "the
    ego", until a vehicle of that kind is brought in ("a Golf", "another van"): a definite noun
    names again the one vehicle of its kind the text has introduced, and here that one is the ego.
    One placed by someone or in a lane ("the car ahead", "the Tesla from the next lane"), said to be
    another ("the other van", "the second Polo"), modifying a noun ("the car park") or owned ("the
    car's") is not it, nor one after several of the kind come in ("two vans wait ahead")."""
    kind, words = names
    out = list(tokens)
    for p in reversed(
        road_user_phrases(out[:start] + _until_one_is_new(out[start:], kind, kind_at, known), kind_at, known)
    ):
        said = out[p.head : p.end]
        if p.start < start or p.kind != kind or p.det != "the" or not set(said) <= words:
            continue
        after = out[p.end : p.end + 1]
        other = PLACED - {"in"} | OTHER | {"from"}  # ("the car ahead", "the other van", "the Tesla from ...")
        placed = set(after + out[p.start : p.head]) & other or out[p.end : p.end + 2] == ["in", "front"]
        lane = out[p.end : p.end + 4]  # ("the van in the left lane", "the Tesla from the next lane")
        in_a_lane = "lane" in lane and bool(set(lane) & _PLACEMENT_WORDS) and after != ["lane"]
        if placed or in_a_lane or after in (["'s"], ["of"]):
            continue  # (someone else, or something of it: "the car ahead", "the other van", "the car's")
        if after and after[0].isalpha() and set(lemmas(after[0])) == {"NOUN"}:
            continue  # (a modifier: "the car park")
        dropped.extend(said)
        out[p.start : p.end] = ["the", "ego"]
    return out


def _until_one_is_new(tokens: list[str], kind: str, kind_at: KindAt, known: Known) -> list[str]:
    """``tokens`` up to the first vehicle of ``kind`` brought in as new ("a Golf", "another van"), or
    several ("two vans", "vans are parked along the kerb", "the vans")."""
    new = next(
        (
            p.start
            for p in road_user_phrases(tokens, kind_at, known)
            if p.kind == kind and (p.det in INDEFINITE or _plural_noun(tokens[p.end - 1]))
        ),
        None,
    )
    return tokens if new is None else tokens[:new]


#: What a report says after the noun of the vehicle it examines ("the Transit under examination",
#: "the van in question", "the car involved"): closed endings that add no road user of their own.
SUBJECT_ENDINGS = (("under",), ("in", "question"), ("involved",), ("concerned",))


def _definite_apposition_end(tokens: list[str], i: int, kind_at: KindAt, known: Known) -> int | None:
    """Where an apposition with "the" after the ego's name ends (", the blue Ford Focus," / ", the
    Ford Transit under examination,"), as :func:`apposition_end` reads one with "a": it may end with
    a report's closed ending for the vehicle examined (:data:`SUBJECT_ENDINGS`), and a list ("the ego,
    the van, and a cyclist") is none."""
    if tokens[i : i + 2] != [",", "the"]:
        return None
    close = next((k for k in range(i + 2, min(i + 10, len(tokens))) if tokens[k] in PUNCT), None)
    if close is None or tokens[close] != "," or tokens[close + 1 : close + 2] in (["and"], ["or"]):
        return None
    words = tokens[i + 1 : close]
    for ending in SUBJECT_ENDINGS:
        at = next((k for k in range(2, len(words)) if tuple(words[k : k + len(ending)]) == ending), None)
        if at is not None and len(words) - at == len(ending) + (ending == ("under",)):
            words = words[:at]  # ("under examination": the one word after "under" too)
            break
    tail = [*words[1:], ","]
    swapped = [",", "a", *tail]
    end = apposition_end(swapped, 0, kind_at, known, most=5)
    return close if end == len(swapped) - 1 else None


#: The ego's pronouns, which take no apposition of a vehicle ("we, a family of four, ...").
PRONOUNS_EGO = frozenset({"i", "we", "me", "us"})


#: Words of a placement after a road user's noun ("the van behind me", "the lorry in the next lane").
_PLACEMENT_WORDS = frozenset({"front", "next", "left", "right", "other", "same", "inside", "outside", "middle"})


def _placement(words: list[str]) -> bool:
    """Whether ``words`` place a road user and say nothing it does ("behind me", "in the next lane",
    "ahead of us"): prepositions, determiners, pronouns and nouns, no verb."""
    if not 1 <= len(words) <= 5:
        return False
    for w in words:
        closed = w in PREPOSITIONS or w in DETERMINERS or w in PRONOUNS or w in PLACED or w in _PLACEMENT_WORDS
        if not closed and (not w.isalpha() or "VERB" in lemmas(w)):
            return False
    return True


def _placed_apposition(tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """ "The van behind me, a white Sprinter, ...", "the car ahead of us, a silver Octavia, ...": a vehicle
    said in apposition after a road user and its placement is that road user, no second one; where it
    names the type more exactly than a general noun ("the vehicle in front, a lorry,") its noun is used."""
    out = list(tokens)
    i = 0
    while i < len(out):
        p = _phrase_at(out, i, kind_at, known)
        if p is None or p.kind not in VEHICLES or p.det not in DEFINITE:
            i += 1
            continue
        comma = next((k for k in range(p.end, min(p.end + 6, len(out))) if out[k] in PUNCT), None)
        end = apposition_end(out, comma, kind_at, known) if comma is not None and out[comma] == "," else None
        if end is None or not _placement(out[p.end : comma]) or end >= len(out) or out[end] != ",":
            i = p.end
            continue
        q = next((x for x in road_user_phrases(out[comma + 1 : end], kind_at, known)), None)
        said = out[comma + 1 + q.head : comma + 1 + q.end] if q is not None else []
        dropped.extend(w for w in out[comma + 1 : end] if w != ",")
        del out[comma:end]
        if said and p.kind == "car" and q.kind != "car":
            out[p.head : p.end] = said
        i = p.end
    return out


#: Words between the ego and the vehicle it is in ("the ego was driving his Tesla", "the ego, in her van").
_AT_THE_WHEEL = frozenset({"driving", "in", "inside", "behind", "at", "wheel", "of", ","}) | BE


def _egos_vehicle(tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """The ego's own vehicle is the ego: "the ego's Fiesta" (the insured's, the claimant's) is said "the
    ego"; "the ego was driving his Tesla", "the ego, in her van," keep the ego and lose the vehicle; and
    the vehicle named so, named again with "the" ("the Fiesta, travelling at 30 mph, ..."), is the ego,
    until one of its kind is named new with "a"."""
    out = list(tokens)
    own: set[str] = set()
    i = 0
    while i < len(out):
        p = _phrase_at(out, i, kind_at, known)
        if p is None:
            i += 1
            continue
        noun = " ".join(out[p.head : p.end])
        if p.kind in VEHICLES and p.det in ("a", "an") and noun in own:
            own.discard(noun)  # (another one of the same make)
        elif p.kind in VEHICLES and p.det == "the" and noun in own:
            dropped.extend(out[p.start + 1 : p.end])
            out[p.start : p.end] = ["the", "ego"]
            i = p.start + 2
            continue
        elif p.kind == "ego":
            j = p.end
            if out[j : j + 1] == ["'s"]:  # ("the ego 's fiesta")
                q = _phrase_at(
                    out, next((h for h in range(j + 1, min(j + 4, len(out))) if kind_at(out, h)), j), kind_at, known
                )
                if q is not None and q.kind in VEHICLES and all(not known(out, h) for h in range(j + 1, q.head)):
                    own.add(" ".join(out[q.head : q.end]))
                    dropped.extend(out[j : q.end])
                    del out[j : q.end]
            else:
                k = j
                while k < min(j + 4, len(out)) and out[k] in _AT_THE_WHEEL:
                    k += 1
                if k > j and k < len(out) and out[k] in ("his", "her", "their", "its"):
                    head = next((h for h in range(k + 1, min(k + 4, len(out))) if kind_at(out, h)), None)
                    q = _phrase_at(out, head, kind_at, known) if head is not None else None
                    if q is not None and q.kind in VEHICLES and q.start == k:
                        own.add(" ".join(out[q.head : q.end]))
                        dropped.extend(out[k : q.end])
                        cut = k - 1 if out[k - 1] in ("in", "inside") else k  # ("in her van": where the ego is)
                        del out[cut : q.end]
        i = p.end
    return out


#: The places inside a vehicle where passengers and pets ride ("in the back", "on the back seat",
#: "in the boot", "in a carrier"): someone there travels with the ego, no road user.
INTERIOR = frozenset({"back", "boot", "trunk", "seat", "seats", "backseat", "carrier", "footwell", "cage", "crate",
                      "deck", "decks", "aisle", "cabin", "gangway", "compartment"})  # fmt: skip


def _passengers(tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """People and animals said to be inside the vehicle ("kids bickering in the back", "the cat in a
    carrier on the back seat") travel with the ego: no road users."""
    out = list(tokens)
    i = 0
    while i < len(out):
        p = _phrase_at(out, i, kind_at, known)
        if p is None or p.kind != "pedestrian":
            i += 1
            continue
        inside = False
        for k in range(p.end, min(p.end + 3, len(out))):
            if out[k] in PUNCT:
                break
            if out[k] in ("in", "on"):
                rest = out[k + 1 : k + 5]
                stop = next((n for n, w in enumerate(rest) if w in PUNCT), len(rest))
                inside = any(w in INTERIOR for w in rest[:stop][:3])
                break
        if inside and (p.det in DEFINITE or p.det == "" or p.det in POSSESSIVE or p.det in ("a", "an")):
            start = p.start - (p.start > 0 and out[p.start - 1].isdigit())
            dropped.extend(out[start : p.end])
            del out[start : p.end]
            i = start
            continue
        i = p.end
    return out


#: Verbs of perceiving: someone whose doing is only one of these watches the scene from outside it.
PERCEIVE = frozenset({"see", "watch", "witness", "film", "record", "notice", "observe"})
#: Verbs of telling: someone who only tells what happened ("a man at the bus stop said ...", "the
#: passenger states ...") is a witness too, as one who only saw it.
TELL = frozenset({"say", "state", "tell", "claim", "report", "confirm", "admit", "explain", "insist", "describe"})
_WITNESS_VERBS = PERCEIVE | TELL
#: Auxiliaries and forms of "have" and "do", which say no doing of their own.
_AUXILIARIES = frozenset({"have", "has", "had", "do", "does", "did", "will", "would", "could", "can", "must"})


def _verb_of(word: str) -> bool:
    return word.isalpha() and "VERB" in lemmas(word) and word not in BE and word not in _AUXILIARIES


def _only_perceives(tokens: list[str], start: int, kind_at: KindAt) -> int | None:
    """Where the perceiving verb is, when the first verb after a road user's phrase (``start``, past
    its modifiers and a relative pronoun) is one of perceiving or telling (:data:`TELL`: "a man at the
    bus stop said the cyclist never looked") and nothing after it in the sentence is
    a doing of its own ("a woman on the pavement filmed it", "a lady ... who saw the whole thing"); a
    verb after another road user is that one's ("watched as a cyclist swerved"). Else None."""
    k = start
    while k < len(tokens) and tokens[k] not in SENTENCE_END and tokens[k] != ",":
        w = tokens[k]
        if _lemma_in(w, _WITNESS_VERBS) and _verb_of(w):
            break
        found = kind_at(tokens, k)
        if found is not None:
            det = tokens[k - 1] in DETERMINERS
            if tokens[k - 1 - det] in PREPOSITIONS:  # ("waiting for the bus": an object)
                k += found[1]
                continue
            return None  # (someone else named first)
        modifier = "NOUN" in lemmas(w) or w.endswith("ing") or w in DETERMINERS or w in PRONOUNS
        if _verb_of(w) and not modifier:  # (nouns and participles modify: "at the bus stop", "waiting")
            return None
        k += 1
    if k >= len(tokens) or not _lemma_in(tokens[k], _WITNESS_VERBS):
        return None
    for j in range(k + 1, len(tokens)):
        w = tokens[j]
        if w in SENTENCE_END:
            break
        found = kind_at(tokens, j)
        if found is not None and found[0] != "ego":
            break  # (what follows is the other one's doing)
        noun = tokens[j - 1] in DETERMINERS or tokens[j - 1] in POSSESSIVE
        if _verb_of(w) and not noun and not _lemma_in(w, _WITNESS_VERBS):
            return None  # ("watched the traffic and then ran across": a road user)
    return k


def _witnesses(tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """Someone who only sees, watches, films, notices or tells ("a man at the bus stop watched it all", "there
    was a lady with a stroller on the sidewalk who saw the whole thing") is a witness, no road user: the
    phrase, with its number and modifiers, up to the verb of perceiving is taken out. Whoever also does
    something on the road ("a man who saw me coming stepped out anyway") stays."""
    out = list(tokens)
    i = 0
    while i < len(out):
        p = _phrase_at(out, i, kind_at, known)
        if p is None or p.kind == "ego" or (p.start > 0 and out[p.start - 1] in PREPOSITIONS):
            i += 1 if p is None else p.end - i  # (after a preposition it is no subject: "for the bus")
            continue
        k = _only_perceives(out, p.end, kind_at)
        if k is None:
            i = p.end
            continue
        start = p.start - (p.start > 0 and out[p.start - 1].isdigit())  # ("2 kids waiting ... noticed")
        dropped.extend(w for w in out[start : k + 1] if w.isalpha())
        del out[start : k + 1]
        i = start
    return out


#: Verbs of being somewhere on foot: a narrator doing one of them is no driver ("I was standing at the
#: bus stop", "walking my dog along the pavement, I ...").
ON_FOOT = frozenset({"stand", "wait", "walk", "sit", "jog", "stroll", "queue"})
#: Verbs a vehicle in a conflict does: the one that does one is the one the conflict is told from.
_REACTS = frozenset({"brake", "stop", "swerve", "skid", "slam", "slow", "hoot", "honk"})


def _narrator_frame(tokens: list[str], kind_at: KindAt) -> tuple[int, int] | None:
    """The span from the sentence's start to the narrator's verb of perceiving ("I was standing at the
    bus stop when I saw", "I was sitting outside and saw", "Walking my dog along the pavement, I
    watched"), when the narrator is on foot in it, else None."""
    for k, w in enumerate(tokens):
        if not (_lemma_in(w, PERCEIVE) and _verb_of(w)):
            continue
        start = max((j + 1 for j in range(k) if tokens[j] in (".", ";", "!", "?")), default=0)
        before = max((j + 1 for j in range(start - 1) if tokens[j] in (".", ";", "!", "?")), default=0)
        for first in (start, before):  # (the sentence, or the one before it: "I was waiting outside. I saw")
            said = tokens[first:k]
            others = any((kind_at(tokens, j) or ("ego",))[0] != "ego" for j in range(first, k))
            on_foot = any(_lemma_in(t, ON_FOOT) or t == "foot" for t in said)
            if ("i" in said or "we" in said) and not others and on_foot:
                return first, k
    return None


#: Participles that give a vehicle's speed after it ("a blue estate doing about 30 km/h").
_GOING = frozenset({"doing", "going", "travelling", "traveling", "driving", "moving"})


def _speed_after(tokens: list[str], i: int) -> int:
    """The end of a participle of going and its speed at ``i`` ("doing about 30 km/h"), else ``i``."""
    if i >= len(tokens) or tokens[i] not in _GOING:
        return i
    for j in range(i + 1, min(i + 5, len(tokens) - 1)):
        if tokens[j].replace(".", "").isdigit():
            return j + 2 if tokens[j + 1] in SPEED_UNITS else i
    return i


def _narrator_on_foot(tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """A narrator on foot who watches ("I was standing at the bus stop when I saw a boy on an e-scooter
    come out ... into the path of a silver Audi. The Audi ... braked") is no road user: the ego is the
    vehicle at the centre of the conflict: the one the other road user comes into the path or in front
    of, else the one that brakes, stops or swerves, else the only one. It is said "the ego" wherever it is
    named ("the Audi", "the driver"), and the narrator's frame up to the verb of seeing is taken out.
    A narrator who is in the traffic too ("in front of me", "my car") is left the ego."""
    if "ego" in tokens or "me" in tokens or "us" in tokens:
        return tokens
    frame = _narrator_frame(tokens, kind_at)
    if frame is None:
        return tokens
    phrases = [p for p in road_user_phrases(tokens, kind_at, known) if p.start > frame[1]]
    motor = [p for p in phrases if p.kind in VEHICLES and p.det in ("a", "an", "the", "")]
    if not motor or not any(p.kind not in VEHICLES and p.kind != "ego" for p in phrases):
        return tokens
    centre = next((p for p in motor if tokens[p.start - 2 : p.start] in (["path", "of"], ["front", "of"])), None)
    centre = centre or next(
        (p for p in motor if _lemma_in(tokens[p.end] if p.end < len(tokens) else "", _REACTS)), None
    )
    nouns = {" ".join(tokens[p.head : p.end]) for p in motor}
    if centre is None and len(nouns) == 1:
        centre = motor[0]
    if centre is None:
        return tokens
    noun = " ".join(tokens[centre.head : centre.end])
    centre = next(p for p in motor if " ".join(tokens[p.head : p.end]) == noun)  # (its first mention)
    out: list[str] = []
    i = 0
    while i < len(tokens):
        if frame[0] <= i <= frame[1]:  # (the narrator's words go; the scene's, "in the afternoon", stay)
            w = tokens[i]
            if w in FIRST_PERSON or w in BE or w in _AUXILIARIES or _lemma_in(w, ON_FOOT | PERCEIVE) or w == "when":
                dropped.append(w)
            else:
                out.append(w)
            i += 1
            continue
        p = next((x for x in phrases if x.start == i), None)
        again = p is not None and p.start >= centre.start and " ".join(tokens[p.head : p.end]) == noun
        driver = tokens[i : i + 2] == ["the", "driver"] and i > centre.start and tokens[i + 2 : i + 3] != ["of"]
        if p is not None and (p is centre or (again and p.det == "the")):
            dropped.extend(tokens[p.start : p.end])
            out += ["the", "ego"]
            i = p.end
            end = _speed_after(tokens, i)
            if end > i and p.start > 0 and tokens[p.start - 1] in PREPOSITIONS:  # ("in front of a van doing
                stop = next((k for k in range(end, len(tokens)) if tokens[k] in SENTENCE_END), len(tokens))
                out += tokens[end:stop] + [",", "the", "ego", "was"] + tokens[i:end]  # 30": the ego's speed)
                i = stop
            continue
        if driver:
            out += ["the", "ego"]
            i += 2
            continue
        out.append(tokens[i])
        i += 1
    return out


#: Verbs of contact: after a clause that says the collision, someone named for the first time arrives
#: in its aftermath ("the ambulance came", "the bus driver behind us stopped to help").
CONTACT = frozenset({"hit", "strike", "collide", "clip", "crash", "smash", "knock", "tag", "rear-end", "plough"})


def _lemma_in(word: str, wanted: frozenset[str]) -> bool:
    return word in wanted or any(x in wanted for forms in lemmas(word).values() for x in forms)


PRONOUNS = frozenset({"him", "her", "it", "them", "us", "me", "he", "she", "they", "we", "i"})


def hits_someone(tokens: list[str], k: int, kind_at: KindAt) -> bool:
    """Whether the contact verb at ``k`` says a collision: a road user, a pronoun or a possessive after
    it ("we hit him", "struck the cyclist", "clipped his back wheel"), or a verb that needs none ("we
    collided"); not "hit the brakes"."""
    if _lemma_in(tokens[k], frozenset({"collide", "crash"})):
        return True
    for j in range(k + 1, min(k + 4, len(tokens))):
        if tokens[j] in PUNCT:
            break
        if tokens[j] in PRONOUNS or tokens[j] in POSSESSIVE - {"my", "our", "your"} or kind_at(tokens, j):
            return True  # ("hit him", "clipped his back wheel", "struck the cyclist")
    return False


def _aftermath(tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """Road users first named with "the" (or bare) after the sentence that says the collision ("We hit
    him; he was talking when the ambulance came", "the bloke from the chippy came out") come in its
    aftermath: no road users of the scenario. One named with "a", one already named before, and one
    placed relative to someone ("the cyclist behind me swerved") stay."""
    from vei_scenario.language.stated import stated_outcome

    if stated_outcome(" ".join(tokens)) != "collision":
        return tokens  # ("a van nearly hit me. Then the cyclist behind it ...": no aftermath)
    contact = next(
        (k for k, w in enumerate(tokens) if _lemma_in(w, CONTACT) and hits_someone(tokens, k, kind_at)), None
    )
    if contact is None:
        return tokens
    end = next((k for k in range(contact, len(tokens)) if tokens[k] in (".", ";", "!", "?")), None)
    if end is None:
        return tokens
    before = {p.kind for p in road_user_phrases(tokens[:end], kind_at, known)}
    if not before - {"ego"}:
        return tokens  # ("We collided. The van had pulled out ...": the one hit, told after)
    out = tokens[: end + 1]
    i = end + 1
    while i < len(tokens):
        p = _phrase_at(tokens, i, kind_at, known)
        placed = p is not None and any(w in PLACED for w in tokens[p.end : p.end + 2])  # ("the cyclist behind me")
        if p is None or p.kind in before or p.kind == "ego" or p.det not in ("the", "") or placed:
            out.append(tokens[i])
            i += 1
            continue
        i = _drop_phrase(out, tokens, p, i, dropped)
    return out


def _drop_phrase(out: list[str], tokens: list[str], p: Phrase, i: int, dropped: list[str]) -> int:
    """Take the road-user phrase ``p`` out of ``out``, where a pass that copies the text word by word
    may have copied its article and modifiers already (``p.start < i``), and keep its words among those
    not used; the index after it."""
    if p.start < i:
        del out[len(out) - (i - p.start) :]
    dropped.extend(tokens[p.start : p.end])
    return p.end


#: What is said of those who answer a call after the event, right after their noun and a form of "be"
#: or with none ("Ambulance is on its way", "police cars were called", "fire crews en route").
_ON_THE_WAY = (("on", "its", "way"), ("on", "their", "way"), ("on", "the", "way"), ("en", "route"))
#: ... or called for, after a form of "be" ("was called", "were summoned").
_CALLED = (("called",), ("summoned",), ("sent", "for"), ("dispatched",))
_RESPONDING_BE = frozenset({"is", "are", "was", "were", "has", "have", "had", "been", "being", "now", "already"})
#: What may follow "on its way" that ends what is said of the one answering the call ("... on its way, and
#: ..."; not "on its way out of the junction when it pulled out").
_RESPONSE_ENDS = PUNCT | {"now", "and", "but", "soon", "too", "also"}


#: Words that make a vehicle's phrase one that answers a call ("ambulance", "fire engine", "police car",
#: "tow truck", "recovery truck", "breakdown truck").
_ANSWERING = frozenset({"ambulance", "ambulances", "fire", "police", "tow", "recovery", "breakdown", "rescue"})
#: Verbs whose object is a vehicle asked for or sent, not one on the road ("I'm sending an ambulance",
#: "can I get an ambulance", "do you want an ambulance", "I asked for a tow truck").
_ASK_FOR = frozenset(
    {"send", "dispatch", "get", "need", "want", "request", "call", "arrange", "order", "book", "summon", "ask"}
)
#: Words between such a verb and its object ("send you an ambulance", "ask for an ambulance").
_ASKED_BETWEEN = frozenset({"me", "us", "him", "her", "them", "you", "for"})
#: The determiners of a vehicle asked for: one not yet there ("an ambulance", "another", none). One named
#: with "the" is there already ("I needed the ambulance behind me to get through").
_ASKED_DETERMINERS = frozenset({"", "a", "an", "another", "one", "two", "some"})
#: Words after such a vehicle's noun that make it the service, not a vehicle ("Ambulance service, is the
#: patient breathing?", "ambulance control").
_SERVICE = frozenset({"service", "services", "control", "station", "dispatch", "line", "trust"})
#: Words after the vehicle that say it is somewhere on the road ("I've got an ambulance behind me", "we
#: need a fire engine past the cars"), not asked for.
_PLACED_AFTER = frozenset(
    "behind ahead beside in on up down along round around across over into out off next alongside coming trying "
    "past through".split()
)
#: How far back a call-taker's "Which service?" may stand before the answer that names one.
_SERVICE_ASKED = 8
#: The words of a call-taker's question after a service named as a greeting ("Ambulance, is the patient
#: breathing?", "Police, what's your emergency?").
_CALL_TAKERS = frozenset(
    {"is", "are", "what", "what's", "whats", "where", "where's", "how", "which", "can", "do", "tell"}
)


def _asked_for(tokens: list[str], p: Phrase) -> bool:
    """Whether ``p`` is a vehicle that answers a call, asked for or sent ("I'm sending an ambulance",
    "can I get an ambulance?", "do you need an ambulance", "I've got an ambulance started my way"), or
    named as its service ("Ambulance service, is the patient breathing?", "CT: Ambulance, what's the
    address?", "Which service? C: Ambulance."). Why: an emergency call and the statements after one
    name the vehicles that will come, which are no road users of what happened. One on the road stays
    ("an ambulance came through the red", "I've got an ambulance behind me", "Fire engine, blue lights
    on, came through the red", "I needed the ambulance behind me to get through")."""
    if not _ANSWERING & set(tokens[p.start : p.end]):
        return False
    after = tokens[p.end] if p.end < len(tokens) else ""
    if after in _SERVICE:
        return True
    if not p.det and (p.start == 0 or tokens[p.start - 1] in (":", ".", "?", "!", ";")):
        nxt = tokens[p.end + 1] if p.end + 1 < len(tokens) else ""
        asked = "service" in tokens[max(0, p.start - _SERVICE_ASKED) : p.start]  # ("Which service? C: Ambulance.")
        if (after == "," and nxt in _CALL_TAKERS) or (asked and after in ("", ".", "?", "!", "please", "and")):
            return True  # ("CT: Ambulance, is the patient breathing?", "C: Ambulance. And police.": the service)
    if p.det not in _ASKED_DETERMINERS or after in _PLACED_AFTER:
        return False
    k = p.start - 1
    while k >= 0 and k > p.start - 3 and tokens[k] in _ASKED_BETWEEN:
        k -= 1
    return k >= 0 and _lemma_in(tokens[k], _ASK_FOR)


def _responders(tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """A vehicle said to be on its way, called or sent for ("Ambulance is on its way.", "an ambulance was
    called", "two fire engines en route", "I'm sending an ambulance": :func:`_asked_for`) answers a call
    after what happened: no road user of the scene, with or without an article and whatever the
    outcome said. The rest of the sentence stays; a vehicle that does something on the road ("an
    ambulance on a blue light came through the red") is untouched."""
    out: list[str] = []
    i = 0
    while i < len(tokens):
        p = _phrase_at(tokens, i, kind_at, known)
        if p is None or p.kind in ("ego", "pedestrian"):
            out.append(tokens[i])
            i += 1
            continue
        j = p.end
        while j < len(tokens) and tokens[j] in _RESPONDING_BE:
            j += 1
        be = j > p.end
        way = next((len(r) for r in _ON_THE_WAY if tuple(tokens[j : j + len(r)]) == r), 0)
        way = way if j + way >= len(tokens) or tokens[j + way] in _RESPONSE_ENDS else 0
        called = be and any(tuple(tokens[j : j + len(r)]) == r for r in _CALLED)
        if not (way or called or _asked_for(tokens, p)):
            out.extend(tokens[i : p.end])
            i = p.end
            continue
        i = _drop_phrase(out, tokens, p, i, dropped)
    return out


#: Words that name a road user of no particular type: as a field's name, the one named before.
_ANY_ROAD_USER = frozenset({"target", "vehicle"})


def _field_names(tokens: list[str], kind_at: KindAt, known: Known) -> list[str]:
    """A road user as the name of a field ("cyclist: comes out from the left kerb", "van: 30 m ahead")
    is the subject of the field's value: "a cyclist comes out ..." ("the" if one was named before, and
    for a word that names no type, "target" or "vehicle", if any road user was). A field whose value
    names a road user ("Target: cyclist") is left as it is."""
    out: list[str] = []
    seen: set[str] = set()
    i = 0
    while i < len(tokens):
        opens = not out or out[-1] in SENTENCE_END
        found = kind_at(tokens, i)
        modifier = found is not None and not opens and _field_modifier(out, tokens, i, kind_at)
        if modifier:  # ("NPC car: oncoming, turns left": its one word before the noun goes with it)
            out.pop()
            opens = True
        if found is not None and not opens:
            seen.add(found[0])
            found = None
        if found is not None and found[0] != "ego" and tokens[i + found[1] : i + found[1] + 1] == [":"]:
            j = i + found[1] + 1
            value = tokens[j] if j < len(tokens) else ""
            said = value.replace(".", "").isdigit() or (
                value not in DETERMINERS and j < len(tokens) and known(tokens, j) and kind_at(tokens, j) is None
            )
            if said:
                named = found[0] in seen or (tokens[i + found[1] - 1] in _ANY_ROAD_USER and seen - {"ego"})
                out += ["the" if named else "a", *tokens[i - modifier : i + found[1]]]
                seen.add(found[0])
                i = j
                continue
        if modifier:
            out.append(tokens[i - 1])
        if found is not None:
            seen.add(found[0])
        out.append(tokens[i])
        i += 1
    return out


def _field_modifier(out: list[str], tokens: list[str], i: int, kind_at: KindAt) -> bool:
    """Whether the road user's noun at ``i`` names a field with one word before it that opens its line
    ("NPC car:", "Lead vehicle:", "Oncoming truck:", "Sim cyclist:"): a plain word that names no road
    user and is no article ("The car:", "A van:" are no field's name written so)."""
    if i < 1 or out[-1:] != [tokens[i - 1]] or not (len(out) == 1 or out[-2] in SENTENCE_END):
        return False
    word = tokens[i - 1]
    return word.isalpha() and word not in DETERMINERS and kind_at(tokens, i - 1) is None


def _letter_labels(tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """Labels of a list ("actor A: motorbike overtakes ...", "participant 2: oncoming car"): a word and
    a letter or number opening a line before a colon name the road user the line names, a new one
    ("a motorbike"); the label said elsewhere is that one ("the car"), or, before the line that
    defines it, a reference to one not yet placed (left out)."""
    defined: dict[tuple[str, str], tuple[int, str]] = {}  # label -> (where defined, its noun)
    for s in range(len(tokens) - 2):
        opens = s == 0 or tokens[s - 1] in SENTENCE_END
        w, letter = tokens[s], tokens[s + 1]
        is_label = (len(letter) == 1 and letter.isalpha()) or letter.isdigit()
        if opens and is_label and tokens[s + 2] == ":" and w.isalpha() and w != "ego":
            end = next((k for k in range(s + 3, len(tokens)) if tokens[k] in SENTENCE_END), len(tokens))
            first = next((p for p in road_user_phrases(tokens[s + 3 : end], kind_at, known) if p.kind != "ego"), None)
            if first is not None:
                defined[(w, letter)] = (s, NOUN.get(first.kind, first.kind))
    if not defined:
        return tokens
    out: list[str] = []
    i = 0
    while i < len(tokens):
        label = (tokens[i], tokens[i + 1]) if i + 1 < len(tokens) else None
        if label in defined:
            where, noun = defined[label]
            if i == where:  # the definition: the road user it names is a new one ("an oncoming car")
                i += 3
                end = next((k for k in range(i, len(tokens)) if tokens[k] in SENTENCE_END), len(tokens))
                first = next((p for p in road_user_phrases(tokens[i:end], kind_at, known) if p.kind != "ego"), None)
                if first is not None and not first.det and first.start <= 2:  # (past "oncoming", "parked")
                    out.append("an" if tokens[i][0] in "aeiou" else "a")
                continue
            if i > where:
                out += ["the", noun]
            else:
                dropped.extend(tokens[i : i + 2])
            i += 2
            continue
        out.append(tokens[i])
        i += 1
    return out


#: The closed class of prepositions and conjunctions that end a noun phrase ("a Corsa at 30 mph").
PREPOSITIONS = frozenset(
    "at on in through along down up with when and but for from to into past by near around as while behind "
    "ahead across over of then so because".split()
)
#: Adverb particles of phrasal verbs that PREPOSITIONS leaves out ("tears off", "pulls out").
_PARTICLES = frozenset({"off", "out", "round", "away", "back", "in", "onto", "under"})
#: Verbs whose object is a road user ("following a Corsa", "tailing a Qashqai", "overtook a Prius").
FOLLOWING = frozenset({"follow", "tail", "overtake", "trail"})


def _in_no_dictionary(word: str) -> bool:
    return word.isalpha() and not english(word)


def _followed_names(tokens: list[str], kind_at: KindAt, known: Known) -> list[str]:
    """What the ego follows or overtakes, named by a name no dictionary knows ("following a silver
    Astra", "tailing a Qashqai"), is a vehicle: a make or model; said with "car" after it, as the
    reader reads "a silver Astra car"."""
    out: list[str] = []
    i = 0
    while i < len(tokens):
        out.append(tokens[i])
        if _lemma_in(tokens[i], FOLLOWING) and i + 2 < len(tokens) and tokens[i + 1] in ("a", "an"):
            j = i + 2
            while j < i + 5 and j < len(tokens) and tokens[j].isalpha() and tokens[j] not in PREPOSITIONS:
                if kind_at(tokens, j) is not None:
                    break  # ("following a grey car": a road user the reader knows)
                j += 1
            ends = j == len(tokens) or tokens[j] in PREPOSITIONS or tokens[j] in PUNCT
            if j > i + 2 and ends and _in_no_dictionary(tokens[j - 1]) and not known(tokens, j - 1):
                out += [*tokens[i + 1 : j], "car"]
                i = j
                continue
        i += 1
    return out


SPEED_UNITS = frozenset({"km/h", "mph", "m/s"})


def _speed_of_both(tokens: list[str], kind_at: KindAt, known: Known) -> list[str]:
    """ "The ego and the lead car both travel at 60 km/h", "a van and I are both doing 70 km/h", "VUT and
    GVT both at 50 km/h": the speed is each one's. Said as the ego's speed first, then the other's
    sentence with its speed ("the ego drives at 60 km/h , the lead car travel at 60 km/h")."""
    if "both" not in tokens:
        return tokens
    b = tokens.index("both")
    speed = next((k for k in range(b + 1, min(b + 5, len(tokens) - 1)) if tokens[k + 1] in SPEED_UNITS), None)
    if speed is None or not tokens[speed].replace(".", "").isdigit():
        return tokens
    j = b - 1
    while j >= 0 and tokens[j] in BE:
        j -= 1
    phrases = [p for p in road_user_phrases(tokens[: j + 1], kind_at, known) if p.end > j + 1 - 6]
    if len(phrases) < 2 or phrases[-1].end != j + 1:
        return tokens
    first, second = phrases[-2], phrases[-1]
    between = tokens[first.end : second.start]  # ("the truck ahead and I": where it is, then "and")
    if not between or between[-1] != "and" or len(between) > 3 or any(w in PUNCT for w in between):
        return tokens
    if (first.kind == "ego") == (second.kind == "ego"):
        return tokens
    said = ["the", "ego", "drives", "at", tokens[speed], tokens[speed + 1], ","]
    other_words = tokens[second.start : second.end] if first.kind == "ego" else tokens[first.start : second.start - 1]
    rest = tokens[b + 1 :]
    if rest[0].replace(".", "").isdigit():
        rest = ["at", *rest]  # ("both 50 km/h")
    return tokens[: first.start] + said + other_words + rest


#: Words after a letter that show it is a label, not an article ("Vehicle A was ...", "Car B (ego)").
AFTER_LABEL = frozenset({"and", "then", "had", "has", "which", "who", "to", "calling", "(", ")"})
#: Units after which a number is a quantity, not a label ("car 3 m ahead").
UNITS_AFTER = frozenset({"m", "km/h", "mph", "m/s", "s", "%", "metres", "meters", "lanes", "lane", ":", "pm", "am"})


def vehicle_labels(tokens: list[str], kind_at: KindAt, known: Known) -> list[tuple[int, str, str]]:
    """Every vehicle label in ``tokens`` as (where, its noun, its letter or number): a vehicle noun or
    "unit" with no determiner, then a number no unit follows, or a letter ("Car A", "Vehicle B") when
    what follows cannot go on a noun phrase and another letter labels a vehicle too."""
    found = []
    for i in range(len(tokens) - 1):
        noun, mark = tokens[i], tokens[i + 1]
        kind = kind_at(tokens, i)
        vehicle = noun == "unit" or (kind is not None and kind[0] in VEHICLES and kind[1] == 1)
        if not vehicle or (i and tokens[i - 1] in DETERMINERS):
            continue
        after = tokens[i + 2] if i + 2 < len(tokens) else "."
        if mark.isdigit() and after not in UNITS_AFTER:
            found.append((i, noun, mark))
        elif len(mark) == 1 and mark.isalpha() and mark not in "iv":
            label_like = (
                after in PUNCT
                or after in BE
                or after in AFTER_LABEL
                or after == "the"
                or (known(tokens, i + 2) and kind_at(tokens, i + 2) is None)
            )
            if label_like:
                found.append((i, noun, mark))
    letters = {m for _, _, m in found if m.isalpha()}
    return [x for x in found if x[2].isdigit() or len(letters) > 1]


def _relative_of_ego(tokens: list[str]) -> list[str]:
    """ "... in front of the ego, which was doing 40 km/h": a relative clause right after the ego is said
    of the ego; said as a clause of its own with the ego as its subject ("..., the ego was doing ...")."""
    out: list[str] = []
    for k, w in enumerate(tokens):
        if w in ("which", "who", "that") and k >= 2 and tokens[k - 1] == "," and tokens[k - 2] == "ego":
            out += ["the", "ego"]
            continue
        out.append(w)
    return out


def _vehicle_labels(tokens: list[str], kind_at: KindAt, known: Known) -> list[str]:
    """Vehicle labels of a report ("Car 3 to control", "Vehicle A ... Vehicle B", "Car B (ego)"): the
    one marked as the ego ("Car B (ego)"), else, where the text names no ego otherwise, number one or
    A, else the first label, is the ego; each other label is a road user of its noun's type, "a van"
    where first named and "the van" after."""
    labels = vehicle_labels(tokens, kind_at, known)
    if not labels:
        return tokens
    names = [(noun, mark) for _, noun, mark in labels]
    marked = [
        (n, m) for i, n, m in labels if tokens[i + 2 : i + 3] == ["ego"] or tokens[i + 2 : i + 4] == ["the", "ego"]
    ]
    if marked:
        ego = marked[0]
    elif "ego" in tokens:  # (the ego is named otherwise: every label is another road user)
        ego = None
    else:
        ego = next((x for x in names if x[1] in ("1", "a")), names[0])
    out: list[str] = []
    seen: set[tuple[str, str]] = set()
    i = 0
    at = {k: (n, m) for k, n, m in labels}
    while i < len(tokens):
        if i in at:
            label = at[i]
            if label == ego:
                out += ["the", "ego"]
                i += 2
                i += 1 if tokens[i : i + 1] == ["ego"] else 2 if tokens[i : i + 2] == ["the", "ego"] else 0
                continue
            kind = kind_at(tokens, i)
            noun = NOUN.get(kind[0], "car") if kind is not None else "car"
            listed = _listed_marks(tokens, i)
            if listed:  # ("Trucks 2 and 3 follow": as many as their labels)
                out += [_COUNT_WORDS[min(listed, len(_COUNT_WORDS) - 1)], tokens[i]]
                i = _past_marks(tokens, i + 2)
                continue
            out += ["the" if label in seen else ("an" if noun[0] in "aeiou" else "a"), noun]
            seen.add(label)
            i += 2
            continue
        out.append(tokens[i])
        i += 1
    return label_noun_again(out, ego, names)


#: Counts in words, by value, as the reader reads a number of road users ("two trucks").
_COUNT_WORDS = ("", "one", "two", "three", "four", "five", "six")
#: Words that join the labels of a list ("2 and 3", "2, 3 and 4", "2-4", "B & C").
_MARK_JOINS = frozenset({"and", ",", "&", "to", "-"})


def _past_marks(tokens: list[str], k: int) -> int:
    """Where the list of labels going on at ``k`` (after the first: "and 3", ", 3 and 4") ends."""
    while k + 1 < len(tokens) and tokens[k] in _MARK_JOINS and (tokens[k + 1].isdigit() or len(tokens[k + 1]) == 1):
        k += 2
    return k


def _listed_marks(tokens: list[str], i: int) -> int:
    """How many vehicles a plural noun with a list of labels at ``i`` names ("trucks 2 and 3": two,
    "cars 2, 3 and 4": three, "vehicles 2-4": three), or 0 for a singular noun or a single label."""
    if is_singular(tokens[i]):
        return 0
    end = _past_marks(tokens, i + 2)
    marks = [t for t in tokens[i + 1 : end] if t not in _MARK_JOINS]
    if len(marks) < 2:
        return 0
    if tokens[i + 2] in ("to", "-") and all(m.isdigit() for m in marks[:2]):
        return max(int(marks[1]) - int(marks[0]) + 1, 2)  # ("vehicles 2-4": a range)
    return len(marks)


def label_noun_again(tokens: list[str], ego: tuple[str, str] | None, names: list[tuple[str, str]]) -> list[str]:
    """A log opened by its own vehicle's call sign ("Van 07 | ... van turning left", "Unit 14 ... unit
    speed 54 mph"): the noun of the ego's label said again bare or with "the" is the ego, where no other
    label has that noun and nothing introduces another of it ("a van")."""
    if ego is None or any(n_m[0] == ego[0] and n_m != ego for n_m in names):
        return tokens
    noun = ego[0]
    if any(tokens[k] == noun and k and tokens[k - 1] in INDEFINITE for k in range(len(tokens))):
        return tokens
    out: list[str] = []
    seen = False
    for k, w in enumerate(tokens):
        seen = seen or tokens[k : k + 2] == ["the", "ego"]
        if w == noun and seen and tokens[k + 1 : k + 2] != ["of"] and (not k or tokens[k - 1] not in POSSESSIVE):
            if out and out[-1] == "the":
                out.pop()
            out += ["the", "ego"]
            continue
        out.append(w)
    return out


def _ego_unnamed(tokens: list[str], kind_at: KindAt, known: Known) -> list[str]:
    """A text that names no ego, with a vulnerable road user and one motor vehicle named only bare or
    with "the" ("car versus e-scooter ... car doing about 20 mph", "Vehicle was turning right ...,
    pedestrian crossing"): that vehicle is the one the report is told from, the ego. A vehicle placed
    relative to something ("the car ahead", "parked cars") or named with "a" is another road user."""
    if any(t == "ego" or t in FIRST_PERSON for t in tokens):
        return tokens
    phrases = road_user_phrases(tokens, kind_at, known)
    if not any(p.kind in VULNERABLE for p in phrases):
        return tokens
    motor = [p for p in phrases if p.kind in VEHICLES]
    if not motor:
        return tokens
    nouns = {" ".join(tokens[p.head : p.end]) for p in motor}
    versus = any(
        (p.end < len(tokens) and tokens[p.end] in VERSUS) or (p.start and tokens[p.start - 1] in VERSUS) for p in motor
    )
    struck = any(  # ("hit by a car", "was knocked down by a van": the report's vehicle strikes)
        p.start
        and tokens[p.start - 1] == "by"
        and any(_lemma_in(t, CONTACT) for t in tokens[max(p.start - 4, 0) : p.start])
        for p in motor
    )
    if len(nouns) != 1 or not (versus or struck or nouns <= {"car", "vehicle"}):
        return tokens
    for p in motor:
        if (p.det not in ("", "the") and not (struck and p.det in ("a", "an"))) or p.end - p.head != 1:
            return tokens
        after = tokens[p.end] if p.end < len(tokens) else ""
        before = tokens[p.start - 1] if p.start else ""
        if after in PLACED or before in PLACED or before in ("between", "behind") or after in ("s", "park"):
            return tokens
    out = list(tokens)
    for p in reversed(motor):
        out[p.start : p.end] = ["the", "ego"]
    return out


def _last_vehicle_in_sentence(out: list[str], kind_at: KindAt) -> bool:
    """Whether the last road user named in the sentence so far, the ego aside, is a vehicle."""
    for j in range(len(out) - 1, -1, -1):
        if out[j] in SENTENCE_END:
            return False
        found = kind_at(out, j)
        if found is not None and found[0] != "ego":
            return found[0] in VEHICLES
    return False


def _participle(word: str) -> bool:
    """Whether ``word`` is a verb's participle ("heading", "doing", "loaded"): a non-finite form that
    can go on a noun phrase without opening a clause."""
    return word.endswith(("ing", "ed")) and _verb_of(word) and word not in lemmas(word).get("VERB", ())


def _participial_apposition(tokens: list[str], kind_at: KindAt, known: Known) -> list[str]:
    """ "An oncoming vehicle, a delivery van travelling at 70 km/h, drifts ...", "the car ahead, a taxi
    doing 40, brakes": an apposition whose noun goes on with a participle phrase is still the road user
    named before the comma, said as an apposition closed right after its noun (", a delivery van,
    travelling at 70 km/h, drifts"), which the reader already takes as the same one. Only when the road
    users are of one type or both motor vehicles, nothing in the participle phrase names another road user
    or a list ("and", "or"), and a verb follows its closing comma: the predicate of the sentence the two
    names share ("a car, a van turning left, and a cyclist": a list; "the car brakes, a cyclist coming the
    other way swerves": a clause of its own)."""
    out = list(tokens)
    i = 1
    while i < len(out):
        if out[i] != "," or i + 1 >= len(out) or out[i + 1] not in ("a", "an"):
            i += 1
            continue
        before = None  # (the road user before the comma, past a short placement: "a vehicle on our right")
        for b in range(i - 1, max(i - 6, -1), -1):
            if out[b] in PUNCT or kind_at(out, b) is not None:
                before = b if out[b] not in PUNCT else None
                break
        head = next((h for h in range(i + 2, min(i + 5, len(out))) if kind_at(out, h) is not None), None)
        if before is None or head is None or out[i + 2 : head] and any(w in PUNCT for w in out[i + 2 : head]):
            i += 1
            continue
        first, second = kind_at(out, before)[0], kind_at(out, head)[0]
        end = head + kind_at(out, head)[1]
        if not (first == second or (first in VEHICLES and second in VEHICLES)) or first == "ego":
            i += 1
            continue
        close = next((k for k in range(end, min(end + 10, len(out))) if out[k] in PUNCT), None)
        fits = (
            end < len(out)
            and _participle(out[end])
            and close is not None
            and out[close] == ","
            and close + 1 < len(out)
            and _verb_of(out[close + 1])
            and not any(kind_at(out, k) is not None or out[k] in ("and", "or") for k in range(end, close))
        )
        if fits:
            out.insert(end, ",")
        i = end
    return out


def _type_gloss(out: list[str], inner: list[str], kind_at: KindAt) -> list[str] | None:
    """What a bracket after a road user says when it only names that road user's type ("Vehicle B (white
    van)", "the other vehicle (a lorry)"): an apposition (", a white van ,") where it names a more exact
    vehicle than a general one, nothing (an empty list) where it names the same type, "wrong-way" where it
    names a wrong-way driver ("(ghost driver)": what it does); None where the bracket says anything else
    (another road user, "and", a verb)."""
    last = next((b for b in range(len(out) - 1, max(len(out) - 4, -1), -1) if kind_at(out, b)), None)
    outer = kind_at(out, last) if last is not None else None
    label = len(out) - 1 if out and (out[-1].isdigit() or len(out[-1]) == 1) else len(out)  # ("Vehicle B (...)")
    kind_of = inner[:2] == ["one", "of"] and inner[2:3] in (["those"], ["these"], ["the"])
    inner = inner[3:] if kind_of else inner  # ("(one of those 14-seater vans)": what kind it is)
    if outer is None or outer[0] == "ego" or last + outer[1] not in (label, len(out)) or not 1 <= len(inner) <= 4:
        return None
    if inner[0] in DEFINITE:  # ("(the obstacle)": a name, see _brackets)
        return None
    words = inner[1:] if inner[0] in ("a", "an") else inner
    head = next((h for h in range(len(words)) if kind_at(words, h) is not None), None)
    found = kind_at(words, head) if head is not None else None
    if found is None or head + found[1] != len(words):
        return None  # (the bracket must end in its first road-user noun)
    kind = found[0]
    if any(
        not (w.replace("-", "").isalpha() or (kind_of and w.isdigit()))
        or w in ("and", "or")
        or set(lemmas(w)) == {"VERB"}
        for w in words[:head]
    ):
        return None
    if " ".join(words) in WRONG_WAY_NOUNS:
        return ["wrong-way"]  # ("NPC sedan (wrong-way driver)": what it does, as the noun says it on its own)
    if kind == outer[0] or (kind == "car" and outer[0] in VEHICLES) or (kind_of and kind in VEHICLES):
        return []
    if outer[0] == "car" and kind in VEHICLES:
        return [",", "a", *words, ","]
    return None


#: The nouns of whoever is on or at a vehicle, said after its noun ("an e-scooter rider", "the van driver").
_AT_A_VEHICLE = frozenset({"rider", "riders", "driver", "drivers"})


def _who_rides(out: list[str], inner: list[str], kind_at: KindAt) -> bool:
    """Whether a bracket after a vehicle's noun (or its rider's, "an e-scooter rider (adult)", "motorbike
    rider (teenager)") says only who rides or drives it: a person's noun, words of no other road user,
    no verb and no "and". It describes that road user's rider; it is no second road user."""
    end = len(out) - (1 if out and out[-1] in _AT_A_VEHICLE else 0)
    outer = next(
        (
            kind_at(out, b)
            for b in range(end - 1, max(end - 3, -1), -1)
            if kind_at(out, b) and b + kind_at(out, b)[1] == end
        ),
        None,
    )
    if outer is None or outer[0] in ("pedestrian", "ego") or out[end - 1] in _GENERAL_HEADS:
        return False
    kinds = [kind_at(inner, h) for h in range(len(inner))]
    if not any(k is not None and k[0] == "pedestrian" for k in kinds):
        return False
    return all(k is None or k[0] == "pedestrian" for k in kinds) and not any(
        w in ("and", "or", "with") or set(lemmas(w)) == {"VERB"} for w in inner
    )


def _brackets(tokens: list[str], kind_at: KindAt, known: Known, names: dict[str, str], dropped: list[str]) -> list[str]:
    """Brackets go; a name given a road user in them ("a passenger car (the challenger)") is kept as a
    name of that referent, and the bracket is not read as a second road user."""
    out: list[str] = []
    i = 0
    while i < len(tokens):
        if tokens[i] == "(":
            close = next((k for k in range(i + 1, min(i + 9, len(tokens))) if tokens[k] == ")"), None)
            inner = tokens[i + 1 : close] if close is not None else []
            words = [w for w in inner if w not in DEFINITE]
            last = next((b for b in range(len(out) - 1, max(len(out) - 3, -1), -1) if kind_at(out, b)), None)
            kind = kind_at(out, last) if last is not None else None
            naming = (  # ("(the challenger)", "(the obstacle)": a definite name of the one just named)
                kind is not None
                and kind[0] != "ego"
                and last + kind[1] == len(out)
                and inner[:1] == ["the"]
                and len(words) == 1
                and words[0].isalpha()
                and kind_at(words, 0) in (None, (kind[0], 1), ("car", 1))  # (a general noun: "obstacle")
            )
            at_wheel = (  # ("a car ... (driver asleep)": its driver, no one else)
                close is not None and words[:1] in (["driver"], ["rider"]) and _last_vehicle_in_sentence(out, kind_at)
            )
            if at_wheel or (close is not None and _who_rides(out, inner, kind_at)):  # (or who rides it)
                dropped.extend(inner)
                i = close + 1
                continue
            gloss = _type_gloss(out, inner, kind_at) if close is not None else None
            if gloss is not None:  # ("Vehicle B (white van)", "the target (a hatchback)": its type)
                dropped.extend(w for w in inner if w not in gloss)
                out.extend(gloss)
                i = close + 1
                continue
            if naming:
                names[words[0]] = NOUN.get(kind[0], kind[0])
                dropped.extend(inner)
                i = close + 1
                continue
        if tokens[i] not in ("(", ")"):
            out.append(tokens[i])
        i += 1
    return out


def _named_speeds(tokens: list[str], kind_at: KindAt, known: Known, names: dict[str, str]) -> list[str]:
    """ "speed of cyclist 15 km/h", "velocity of the bus: 10 km/h", "challenger speed 90 km/h": the
    speed of the referent named, said as the reader reads a road user's speed ("the cyclist at ...")."""
    out: list[str] = []
    i = 0
    while i < len(tokens):
        t = tokens[i]
        if t in SPEED_NOUNS and i + 1 < len(tokens) and tokens[i + 1] == "of":
            j = i + 2 + (tokens[i + 2] in DEFINITE if i + 2 < len(tokens) else 0)
            found = kind_at(tokens, j) if j < len(tokens) else None
            named = j < len(tokens) and tokens[j] in names
            noun = tokens[j : j + found[1]] if found else [names[tokens[j]]] if named else None
            k = j + (found[1] if found else 1)
            k += k < len(tokens) and tokens[k] in ("is", "was", ":", "=")
            if noun is not None and k < len(tokens) and tokens[k].replace(".", "").isdigit():
                if noun == ["ego"]:
                    out += ["the", "ego", "drives", "at"]
                else:
                    out += ["the", *noun, "at"]
                i = k
                continue
        if t in names and i + 1 < len(tokens) and tokens[i + 1] in SPEED_NOUNS:
            k = i + 2 + (i + 2 < len(tokens) and tokens[i + 2] in ("is", "was", ":", "="))
            if k < len(tokens) and tokens[k].replace(".", "").isdigit():
                if out and out[-1] in DEFINITE:
                    out.pop()
                out += ["the", names[t], "at"]
                i = k
                continue
        if t in names and out and out[-1] in DEFINITE:
            out.append(names[t])
            i += 1
            continue
        out.append(t)
        i += 1
    return out


#: Words that set a road user apart from one of its type already named ("the other car", "a second cyclist").
OTHER = frozenset({"other", "second", "third", "fourth", "next", "another", "different", "further"})


def _mentions_again(tokens: list[str], kind_at: KindAt, known: Known) -> list[str]:
    """A road user named again with "the" is the most recent one of its type, said as the reader reads
    a known one: "the" right before its noun ("the silver hatchback" → "the hatchback"); a definite
    general noun ("the front vehicle") is the most recent vehicle, said by its type ("the truck" after
    "a coach"); a vehicle named again in apposition (", a coach,") is the same one, more exactly."""
    out = list(tokens)
    referents: list[Referent] = []
    i, last_end = 0, -1
    while i < len(out):
        p = _phrase_at(out, i, kind_at, known)
        if p is None:
            i += 1
            continue
        noun = " ".join(out[p.head : p.end])
        general = out[p.end - 1] in GENERAL_VEHICLE and p.kind == "car"
        apposition = (
            referents
            and p.det in ("a", "an")
            and p.start
            and out[p.start - 1] == ","
            and p.end < len(out)
            and out[p.end] == ","
            and last_end == p.start - 1
        )
        apart = any(w in OTHER for w in out[p.start : p.head])
        motor = _motorbike_again(out, p, referents)
        if p.kind == "ego":
            pass
        elif motor is not None and not apart:
            said = ["the", *motor.noun.split()]
            out[p.start : p.end] = said
            last_end = i = p.start + len(said)
            continue
        elif apposition and p.kind in VEHICLES and referents[-1].kind in VEHICLES:
            referents[-1].kind = p.kind if referents[-1].kind == "car" else referents[-1].kind
        elif p.det == "the" and not apart and (same := _target_again(out, p, referents)) is not None:
            out[p.start : p.end] = ["the", NOUN[same.kind]]
            last_end = i = p.start + 2
            continue
        elif p.det == "the" and not apart and referents:
            if general:
                same = next((r for r in reversed(referents) if r.kind in VEHICLES), None)
            else:
                same = next((r for r in reversed(referents) if r.kind == p.kind), None)
            if same is not None and (p.head > p.start + 1 or (general and same.kind != "car")):
                said = [NOUN[same.kind]] if general else out[p.head : p.end]
                out[p.start : p.end] = ["the", *said]
                last_end = p.start + 1 + len(said)
                i = last_end
                continue
            if same is None:
                referents.append(Referent(p.kind, noun))
        elif p.det == "" and referents and _bare_again(out, p, referents, kind_at):
            out.insert(p.start, "the")  # ("... ego stays behind cyclist": the cyclist named before)
            last_end = p.end + 1
            i = p.end + 1
            continue
        elif p.det in INDEFINITE or not referents or p.det == "":
            referents.append(Referent(p.kind, noun))
        last_end = p.end
        i = p.end
    return out


def _target_again(tokens: list[str], p: Phrase, referents: list[Referent]) -> Referent | None:
    """The road user a bare "the target" names again: in a test the targets are the road users, so
    it is the last one named as a target ("an e-scooter target ... the target"), else the last one
    named at all. "Target" names no type (the lexicon reads it as a car), so without this it would
    be a new car."""
    if tokens[p.start : p.end] != ["the", "target"] or not referents:
        return None
    named = [r for r in referents if r.kind in NOUN]
    return next((r for r in reversed(named) if r.noun.endswith("target")), named[-1] if named else None)


#: The nouns of a pedal cycle that also name a motor two-wheeler.
_BIKE = frozenset({"bike", "bikes"})


def _motorbike_again(tokens: list[str], p: Phrase, referents: list[Referent]) -> Referent | None:
    """The motor two-wheeler a known "bike" names ("a motorcyclist ... the bike stopped", "until bike has
    passed"): "bike" is as much a motorbike's word as a bicycle's, so said again with "the" or bare, where
    no pedal cycle was named, it is the last motor two-wheeler named. A new one ("a bike") is new."""
    if p.kind != "bicycle" or tokens[p.head : p.end] != ["bike"] or p.det not in ("the", ""):
        return None
    if p.head != p.start + bool(p.det) or any(r.kind == "bicycle" for r in referents):
        return None
    return next((r for r in reversed(referents) if r.noun in MOTOR_TWO_WHEELERS), None)


def is_singular(word: str) -> bool:
    """Whether ``word`` is no plural noun; a hyphenated word no dictionary has is as its last part is
    ("e-scooters", "pick-ups" are plurals)."""
    if not lemmas(word) and "-" in word:
        word = word.rpartition("-")[2]
    nouns = lemmas(word).get("NOUN")
    return not nouns or word in nouns


def singular(word: str) -> str:
    """``word`` as a singular noun: itself where it is no plural, else its noun lemma ("scooters" →
    "scooter"); a hyphenated word no dictionary has is so by its last part ("e-scooters" →
    "e-scooter")."""
    if is_singular(word):
        return word
    first, dash, last = word.rpartition("-")
    if dash and not lemmas(word):
        return f"{first}-{singular(last)}"
    return lemmas(word)["NOUN"][0]


def _new_in_line(tokens: list[str], start: int) -> bool:
    """Whether the bare noun at ``start`` opens its sentence or field with a word of a place in a line
    of vehicles the text has not said before ("Lead vehicle brakes. Trailing vehicle at 1.2 s"): a
    road user told apart from the one named before. "Following" is left out: opening a phrase it is
    as often the ego's verb (", following lead car at 2 s"); a place said before ("lead vehicle ...
    Lead car:") names that one again."""
    word = tokens[start - 1] if start else ""
    opens = start < 2 or tokens[start - 2] in SENTENCE_END
    return word in IN_LINE - {"following"} and opens and word not in tokens[: start - 1]


def _bare_again(tokens: list[str], p: Phrase, referents: list[Referent], kind_at: KindAt) -> bool:
    """Whether a bare singular noun inside a clause ("behind cyclist", "passes walker") names again the
    one of its type named before (a bare noun opening a clause the reader takes so already)."""
    before = tokens[p.start - 1] if p.start else ""
    clock = p.start >= 3 and before.isdigit() and tokens[p.start - 2] == ":" and tokens[p.start - 3].isdigit()
    if clock and p.head == p.start:  # ("14:34 lorry brakes": a log line opens with its clock)
        return p.kind != "ego" and any(r.kind == p.kind for r in referents)
    if p.head != p.start or before in PUNCT or before == "" or before.isdigit() or before in OTHER:
        return False
    if _new_in_line(tokens, p.start):
        return False  # ("| trailing vehicle following at 1.2 s": told apart by a place in the line new here)
    for j in range(p.start - 1, max(p.start - 4, -1), -1):  # ("a stationary car": its article before
        if tokens[j] in DETERMINERS:  # a word the reader knows; "the ego passes walker": another's)
            return False
        if tokens[j] in PUNCT or kind_at(tokens, j) is not None:
            break
    if before in ("and", "or", "versus", "vs", "v", "of") or not is_singular(tokens[p.end - 1]):
        return False  # ("a cyclist and pedestrian", "car versus cyclist": a list; "groups of cyclists")
    return p.kind != "ego" and any(r.kind == p.kind for r in referents)


#: Prepositions of place: a name after one of them and an article is a place ("past the Odeon").
_PLACE_BEFORE = frozenset(
    "at near past by outside opposite towards toward to from along across over under through round around "
    "onto off beside inside with up down".split()  # (and a companion's: "a man with a Labrador")
)
#: Names of days and months, a closed class: "a Saturday" is a day, no vehicle.
_CALENDAR = frozenset(
    "monday tuesday wednesday thursday friday saturday sunday january february march april may june july "
    "august september october november december".split()
)


def _owner_placed(tokens: list[str], s: int, proper: frozenset[str]) -> bool:
    """Whether the name that owns what follows the "'s" at ``s`` stands after a preposition of place
    ("outside St Mary's Infants", "past Hill Farm's Lodge"): then what it owns is a place too."""
    j = s - 1  # (past the name's words, at least one of them written with its capital: the speller may
    while j >= max(s - 4, 0) and tokens[j].isalpha() and tokens[j] not in _PLACE_BEFORE:  # have changed one)
        j -= 1
    named = any(w in proper for w in tokens[j + 1 : s])
    return named and j >= 0 and tokens[j] in _PLACE_BEFORE


#: Verbs of telling, whose object listens ("told the Echo"), and of speaking, whose listener follows "to"
#: ("speaking to the Post", "said to the Herald").
_TELLING = frozenset({"told", "tell", "tells", "telling", "informed", "inform", "informs"})
_SPEAKING = frozenset(
    {"spoke", "speak", "speaks", "speaking", "said", "says", "say", "talked", "talk", "talking", "wrote", "writing"}
)


def _told(tokens: list[str], j: int) -> bool:
    """Whether the determiner at ``j`` opens the one a verb of telling or speaking is addressed to ("she told
    the Echo", "speaking to the Post"): someone listening, a person or a paper, no vehicle."""
    if j > 0 and tokens[j - 1] in _TELLING:
        return True
    return j > 1 and tokens[j - 1] == "to" and tokens[j - 2] in _SPEAKING


def names_ending_in_a_walker(
    tokens: list[str], kind_at: KindAt, proper: frozenset[str], dropped: list[str]
) -> list[str]:
    """``tokens`` without a proper name whose last word is a person's or an animal's noun ("set off from
    the Green Man", "outside the Red Lion", "past the Black Horse"): words the text writes only with
    their own capital, two or more, name a pub, a street or a place, no one on foot. A capital person's
    noun on its own ("a Man ran out", shouting) is left as it is."""
    out: list[str] = []
    for i, w in enumerate(tokens):
        found = kind_at(tokens, i)
        named = found is not None and found == ("pedestrian", 1) and w in proper
        run = 0
        while named and run < len(out) and out[-1 - run] in proper and kind_at(out, len(out) - 1 - run) is None:
            run += 1
        if run:
            dropped.extend([*out[-run:], w])
            del out[-run:]
            continue
        out.append(w)
    return out


def _named_vehicles(tokens: list[str], kind_at: KindAt, known: Known, proper: frozenset[str]) -> list[str]:
    """A name written with its own capital that no lexicon has, in a vehicle's place ("a silver Mokka
    pulled out", "a kid in a red Mini", "a black Focus in the next lane"), is a car: said with "car"
    after it, as the reader reads "a silver Mokka car". Its place: after an article (and up to two
    colours or words the reader lacks), not after a preposition of place ("past the Odeon", "near the
    Crown") nor "on the", which names a road ("on the Westlink"), and ending the noun phrase: a verb, a
    preposition, a punctuation mark or the end follow, not another name ("the Red Lion") nor a noun the
    name only modifies ("a rider in a Deliveroo jacket", "a woman in a Tesco uniform")."""
    if not proper:
        return tokens
    out: list[str] = []
    for i, w in enumerate(tokens):
        out.append(w)
        if w not in proper or w in _CALENDAR or known(tokens, i) or kind_at(tokens, i) is not None:
            continue
        j = i - 1
        while j >= max(i - 3, 0) and tokens[j] not in DETERMINERS and tokens[j] != "'s":
            if tokens[j] in proper or not (tokens[j] in COLOURS or (tokens[j].isalpha() and not known(tokens, j))):
                break
            if tokens[j] in _PLACE_BEFORE or tokens[j] in PREPOSITIONS:
                break  # ("the red at Eglinton": the name is the preposition's object, a place)
            j -= 1
        if j < 0 or tokens[j] not in ("a", "an", "the", "his", "her", "their", "'s"):
            continue
        if j > 0 and (tokens[j - 1] in _PLACE_BEFORE or tokens[j - 1] in BE):  # (or said of something: "was a")
            continue
        if j > 0 and tokens[j - 1] == "on" and tokens[j] == "the":
            continue  # (a road: "on the Hume", "on the Westlink"; a ridden one is "on a Vespa", "on his")
        if tokens[j] == "'s" and _owner_placed(tokens, j, proper):  # ("outside St Mary's Infants": a place)
            continue
        if _told(tokens, j):
            continue  # (one listening: "she told the Echo", "speaking to the Post")
        nxt = tokens[i + 1] if i + 1 < len(tokens) else "."
        place = nxt in THINGS_FOR_VEHICLES  # ("out of the Engen garage": a place's brand, though "garage" is a verb)
        verb = _verb_of(nxt) and not _compound_head_at(tokens, i + 1, known)  # (not "a Deliveroo jacket")
        ends = nxt in PUNCT or nxt in PREPOSITIONS or (nxt not in proper and not place and verb)
        if ends and not (i and tokens[i - 1] in proper):
            out.append("car")
    return out


#: Nouns that say only that something is a road user ("target", "vehicle") or who is at its wheel
#: ("driver", "rider"): as the head of a compound they leave its type to the noun before them ("a bus
#: target" is a bus, "the lorry driver" the lorry).
_GENERAL_HEADS = _ANY_ROAD_USER | GENERAL_VEHICLE | frozenset({"driver", "drivers", "rider", "riders"})


def _compounds(tokens: list[str], kind_at: KindAt) -> list[str]:
    """ "a schoolboy cyclist", "a woman cyclist", "a girl pedestrian", "a bus target", "a child
    pedestrian target": road-user nouns back to back, with nothing between them, are one noun phrase,
    one road user (a noun before another modifies it: says who rides, or what a test target stands
    for). It is said by one of its nouns: the last vehicle's that names a type (not "target" or
    "vehicle"), whoever rides it ("an e-scooter guy": an e-scooter); with no vehicle, a walker's most
    exact noun, the first ("child", not "pedestrian"). Nouns apart
    ("a child and a cyclist", "the jogger, a cyclist") are two. The nouns left out were read, so they
    are not listed as words not used."""
    out: list[str] = []
    i = 0
    while i < len(tokens):
        run: list[tuple[int, int, str]] = []  # (start, end, kind) of each noun of the run
        k = i
        while k < len(tokens) and (found := kind_at(tokens, k)) is not None:
            run.append((k, k + found[1], found[0]))
            k += found[1]
        if len(run) < 2 or any(kind == "ego" for *_, kind in run):
            out.extend(tokens[i : max(k, i + 1)])
            i = max(k, i + 1)
            continue
        # (a phrase of general nouns names no type; "e-scooter rider" names its vehicle's)
        typed = [r for r in run if not set(tokens[r[0] : r[1]]) <= _GENERAL_HEADS] or run[:1]
        ridden = [r for r in typed if r[2] != "pedestrian"]
        chosen = ridden[-1] if ridden else typed[0]
        out.extend(tokens[chosen[0] : chosen[1]])
        i = k
    return out


def partitives(tokens: list[str], kind_at: KindAt) -> list[str]:
    """ "two of our scooters", "three of the cyclists in the group", "both of the joggers": a count of a
    definite or possessive plural is so many road users of that plural, said as a plain counted plural
    ("two scooters", "both" as "two"); the possessive is the speaker's fleet or group, not the
    narrator's vehicle (:func:`who.own_vehicles` leaves it)."""
    out = list(tokens)
    i = 0
    while i + 3 < len(out):
        count = out[i] in _COUNTED - {"several", "couple", "pair"} or (out[i].isdigit() and int(out[i]) > 1)
        if not count or out[i + 1] != "of" or out[i + 2] not in DEFINITE | POSSESSIVE:
            i += 1
            continue
        head = next((h for h in range(i + 3, min(i + 6, len(out))) if kind_at(out, h) is not None), None)
        end = head + kind_at(out, head)[1] if head is not None else 0
        if head is None or kind_at(out, head)[0] == "ego" or out[end : end + 1] == ["'s"]:  # ("of the car's")
            i += 1
            continue
        out[i : i + 3] = ["two" if out[i] == "both" else out[i]]
        i += 1
    return _one_of_many(out, kind_at)


def _one_of_many(tokens: list[str], kind_at: KindAt) -> list[str]:
    """ "one of the three lorries", "one of two vans": one picked out of a counted plural is the one
    road user that acts; the others are where it came from, said as one of that noun ("one lorry")."""
    out = list(tokens)
    i = 0
    while i + 4 < len(out):
        j = i + 2 + (out[i + 2] in DEFINITE)
        counted = j < len(out) and (out[j] in _COUNTED or (out[j].isdigit() and int(out[j]) > 1))
        if out[i] != "one" or out[i + 1] != "of" or not counted:
            i += 1
            continue
        found = kind_at(out, j + 1)
        nouns = lemmas(out[j + found[1]]).get("NOUN", ()) if found is not None else ()
        if found is None or found[0] in ("ego", "pedestrian") or found[1] != 1 or not nouns:
            i += 1
            continue
        out[i : j + 2] = ["one", nouns[0]]
        i += 1
    return out


#: Pronouns a count picks road users out of ("two of them", "one of those").
_PICKED_FROM = frozenset({"them", "those", "these"})


def _antecedent_plural(tokens: list[str], i: int, kind_at: KindAt, known: Known) -> tuple[str, int, int] | None:
    """(type, start, end) of the last road-user plural before ``i`` that no count or number goes with
    ("the hire scooters", "students riding e-scooters"), or None (also when the last one is counted:
    "two cyclists ... one of them" picks out of a group the reader already holds)."""
    phrases = [p for p in road_user_phrases(tokens[:i], kind_at, known) if p.kind != "ego"]
    if not phrases or is_singular(tokens[phrases[-1].end - 1]):
        return None
    last = phrases[-1]
    kind, end = _ridden_kind(tokens, last, kind_at)
    riders = phrases[-2] if len(phrases) > 1 else None
    if (
        riders is not None
        and riders.kind == "pedestrian"
        and (_ridden_kind(tokens, riders, kind_at)[1] == last.end or _ride_between(tokens, riders.end, last.start))
    ):  # ("people on e-scooters", "students have taken to riding e-scooters": the riders, of the vehicles' type)
        last = riders
    before = tokens[last.head - 1] if last.head else ""
    if before in _COUNTED or before.isdigit() or last.det in ("my", "our", "your"):
        return None
    return kind, last.head, end


def _ride_between(tokens: list[str], start: int, end: int) -> bool:
    """Whether a verb of riding stands between ``start`` and ``end``, in one clause ("students have taken
    to riding e-scooters"): the people before it ride what follows."""
    words = tokens[start:end]
    return not PUNCT & set(words) and any(RIDE_VERBS & set(lemmas(w).get("VERB", ())) for w in words)


def picked_out(tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """ "The hire scooters were out in force. Two of them went through the red": a count of "them" (or
    "those", "these") after a plural that no count goes with picks the road users out of a set of no
    stated size; those picked are the ones that act, said as so many of the plural's type ("two
    e-scooters"), and the set goes (listed as not used). One picked out is one road user, the one the
    set's own words told of too ("People on scooters run the red here; one of them hit me": one
    e-scooter that runs the red). A set with a count of its own ("two cyclists ... one of them") is the
    group the reader already holds, and stays."""
    out = list(tokens)
    i = len(out) - 3
    while i >= 0:
        w = out[i]
        count = w in _COUNTED - {"couple", "pair"} or w == "one" or (w.isdigit() and int(w) > 1)
        follows = out[i + 3] if i + 3 < len(out) else ""
        if not (count and out[i + 1] == "of" and out[i + 2] in _PICKED_FROM) or kind_at(out, i + 3) is not None:
            i -= 1  # (not "two of those vans": :func:`partitives` counts a plural said there)
            continue
        found = _antecedent_plural(out, i, kind_at, known)
        if found is None or follows in ("'s",):
            i -= 1
            continue
        kind, start, end = found
        if w == "one":  # the one picked is the one the set's words told of: the same road user
            out[i : i + 3] = ["the", NOUN[kind]]
            out[start:end] = ["a", NOUN[kind]]
        else:
            out[i : i + 3] = ["two" if w == "both" else w, NOUN[kind] + "s"]
            dropped.extend(out[start:end])
            del out[start:end]
        i = start - 1
    return out


#: Forms of "be" and "get" that make a present or future passive ("is hurt", "gets killed").
_NOT_PAST_PASSIVE = frozenset({"is", "gets", "get", "be", "'s"})


def _participle_next(tokens: list[str], k: int) -> bool:
    """Whether a past participle follows at ``k``, past adverbs ("seriously hurt", "killed")."""
    from lemminflect import getAllInflections

    while k < len(tokens) and tokens[k].endswith("ly") and "ADV" in lemmas(tokens[k]):
        k += 1
    w = tokens[k] if k < len(tokens) else ""
    forms = [getAllInflections(v, upos="VERB") for v in lemmas(w).get("VERB", ())]
    return any(w in f.get("VBN", f.get("VBD", ())) for f in forms)  # (lemminflect gives a VBN only where it differs)


#: Words that open a clause of what has not happened yet ("before a child is hurt", "until a rider gets killed").
_NOT_YET = frozenset({"before", "until", "till", "or"})


#: Verbs of harm done to someone, as lemmas ("hurt", "killed", "knocked down").
_HARM = CONTACT | frozenset({"injure", "hurt", "kill", "wound", "maim", "harm", "mow"})


def _harmed_at(tokens: list[str], k: int) -> bool:
    """Whether a participle of harm follows at ``k``, past adverbs ("seriously hurt", "killed")."""
    while k < len(tokens) and tokens[k].endswith("ly") and "ADV" in lemmas(tokens[k]):
        k += 1
    return k < len(tokens) and _participle_next(tokens, k) and _lemma_in(tokens[k], _HARM)


def _harm_may_come(tokens: list[str], k: int, not_yet: bool) -> bool:
    """Whether the words from ``k`` say harm that may come to whoever is named before them: a modal
    and a passive of harm ("will be killed", "could get hurt"), or, in a clause of what has not
    happened yet, such a passive in the present ("before a child is hurt"). Other passives ("could be
    seen crossing") tell what is so."""
    nxt = tokens[k] if k < len(tokens) else ""
    if nxt in _MODAL_VERBS:
        return tokens[k + 1 : k + 2] in (["be"], ["get"]) and _harmed_at(tokens, k + 2)
    return not_yet and nxt in _NOT_PAST_PASSIVE and _harmed_at(tokens, k + 1)


def _road_users_of_what_may_happen(tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """``tokens`` without a road user named new, with "a", in a warning of what may come to pass ("before a
    child is hurt", "a kid will get killed here one day"): a road user of no event, nobody of the scene
    (listed as not used). Said with "the" ("before the cyclist is overtaken") or told as an event ("a
    child was hurt", "a pedestrian will cross at 5 km/h"), it stays."""
    out = list(tokens)
    i = 0
    while i < len(out):
        p = _phrase_at(out, i, kind_at, known)
        if p is None or p.det not in ("a", "an") or p.kind == "ego":
            i += 1
            continue
        not_yet = p.start > 0 and out[p.start - 1] in _NOT_YET
        if _harm_may_come(out, p.end, not_yet):
            dropped.extend(out[p.start : p.end])
            del out[p.start : p.end]
            continue
        i = p.end
    return out


def what_may_happen(tokens: list[str], dropped: list[str]) -> list[str]:
    """``tokens`` without "someone" or "somebody" said of what may happen to them ("before someone is
    killed", "someone will get hurt", "somebody could have been injured", "somebody is going to be
    hurt"): a modal, a future, or a passive in the present, tells no event, so they are nobody of the
    scene (listed as not used). Told in the past ("someone was hit", "someone stepped out") or acting
    ("someone is crossing"), they are."""
    out: list[str] = []
    for i, w in enumerate(tokens):
        if w not in SOMEONE:
            out.append(w)
            continue
        nxt = tokens[i + 1] if i + 1 < len(tokens) else ""
        passive = nxt in _NOT_PAST_PASSIVE and _participle_next(tokens, i + 2)
        future = nxt in ("is", "'s") and tokens[i + 2 : i + 4] == ["going", "to"]  # ("is going to be killed")
        if nxt in _MODAL_VERBS or passive or future:
            dropped.append(w)
            continue
        out.append(w)
    return out


#: Nouns of several people that are no plural form ("people", "folk").
_PEOPLE = frozenset({"people", "folk", "folks"})


def _others_named(tokens: list[str], p: Phrase, kind_at: KindAt, known: Known) -> bool:
    """Whether a road user other than the ego is named outside the phrase ``p``."""
    return any(q.kind != "ego" and q.head != p.head for q in road_user_phrases(tokens, kind_at, known))


def _people_in_general(tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """ "Police are urging drivers to slow down", "campaigners want cyclists to wear lights": a bare plural
    (no article, no count) followed by "to" and a verb is whom someone asks, warns or wants to do
    something: road users in general, none of the scene; so is one of a kind ("catch such people",
    "action on such riders"); the plural is left out (listed as not used).
    A counted or definite plural ("two cyclists tried to pass", "the drivers tried to stop") and a
    place ("a cyclist to my left") stay."""
    out = list(tokens)
    i = 0
    while i < len(out):
        p = _phrase_at(out, i, kind_at, known)
        if p is None:
            i += 1
            continue
        before = out[p.start - 1] if p.start else ""
        nxt = out[p.end + 1] if p.end + 1 < len(out) else ""
        bare = not p.det and p.kind != "ego"
        plural = not is_singular(out[p.end - 1])
        general = bare and (
            (
                plural
                and before not in _COUNTED
                and not before.isdigit()
                and out[p.end : p.end + 1] == ["to"]
                and nxt in lemmas(nxt).get("VERB", ())
            )
            or (
                (plural or out[p.end - 1] in _PEOPLE)
                and "such" in out[max(p.start - 3, 0) : p.start]
                and _others_named(out, p, kind_at, known)
            )
        )
        if general:
            dropped.extend(out[p.start : p.end])
            del out[p.start : p.end]
            continue
        i = p.end
    return out


def _others_in_general(tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """ "he and other drivers had to pull out", "so other cars had to brake too": "other" before a bare
    plural (no article, no count) sets the road users of the event against everyone else on the road:
    people in general, none of the scene; "other" and the plural are left out (listed as not used).
    A counted or definite group ("two other cyclists", "the other joggers") is so many road users, and
    the plural stays when it is the only road user the text names."""
    phrases = road_user_phrases(tokens, kind_at, known)
    cut: list[tuple[int, int]] = []
    for p in phrases:
        o = next((j for j in range(p.head, max(p.head - 3, -1), -1) if tokens[j] == "other"), None)
        if o is None or p.kind == "ego" or is_singular(tokens[p.end - 1]) or not tokens[p.end - 1].isalpha():
            continue
        before = tokens[o - 1] if o else ""
        if before in _COUNTED or before.isdigit() or before in DEFINITE or before in POSSESSIVE:
            continue
        if any(not tokens[j].isalpha() for j in range(o + 1, p.head)):
            continue
        if not any(q.kind != "ego" for q in phrases if q.head != p.head):
            continue  # (the only road user named: it is the scene's)
        cut.append((o, p.end))
    return _without_spans(tokens, cut, dropped)


#: Words before a plural that say it comes the other way ("oncoming cars", "opposing traffic").
_ONCOMING_BEFORE = frozenset({"oncoming", "opposing", "approaching"})
#: Words after a plural, in its clause, that say it comes the other way ("coming the other way",
#: "approach in the opposite direction", "coming towards us").
_ONCOMING_AFTER = frozenset({"other", "opposite", "towards", "toward"})


def _oncoming_plural(tokens: list[str], p: Phrase) -> bool:
    """Whether the plural ``p`` is said to come the other way: "oncoming" before it, or, within its
    clause's next few words, "the other way", "the opposite direction", "towards"."""
    if p.start and tokens[p.start - 1] in _ONCOMING_BEFORE or tokens[p.start] in _ONCOMING_BEFORE:
        return True
    for w in tokens[p.end : p.end + 6]:
        if w in PUNCT or w in _CLAUSE_ENDS:
            return False
        if w in _ONCOMING_AFTER:
            return True
    return False


def _oncoming_traffic(tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """ "couldn't get past cos there's cars coming the other way", "could not overtake because of
    oncoming cars": a bare plural of vehicles (no article, no count) that comes the other way is the
    stream of traffic that holds the ego back, scenery of the road, where the text names another road
    user it is about; the plural and the rest of its clause are left out (listed as not used). A
    counted or definite plural ("two cars coming the other way") or a single vehicle is a road user,
    and the plural stays when it is the only road user the text names."""
    phrases = road_user_phrases(tokens, kind_at, known)
    cut: list[tuple[int, int]] = []
    for p in phrases:
        before = tokens[p.start - 1] if p.start else ""
        if (
            p.det
            or p.kind in ("ego", "pedestrian")
            or is_singular(tokens[p.end - 1])
            or not tokens[p.end - 1].isalpha()
        ):
            continue
        if before in _COUNTED or before.isdigit() or before in POSSESSIVE or not _oncoming_plural(tokens, p):
            continue
        if not any(q.kind not in ("ego", p.kind) for q in phrases if q.head != p.head):
            continue  # (no other road user named: the plural is the scene's)
        start = p.start - (before in _ONCOMING_BEFORE)
        stop = p.end
        while stop < len(tokens) and not (tokens[stop] in PUNCT or tokens[stop] in _CLAUSE_ENDS):
            stop += 1
        cut.append((start, stop))
    return _without_spans(tokens, cut, dropped)


#: Marks that end a heading: the end of its line or sentence (a colon goes on with a label's value).
_HEADING_ENDS = frozenset({".", "!", "?"})


def _finite(word: str) -> bool:
    """Whether ``word`` is a verb inflected for a subject ("pulls", "swerved"), which makes a sentence;
    a bare stem ("merge", "swerve") or an -ing form names an event, as headings do."""
    return _verb_of(word) and not word.endswith("ing") and word not in lemmas(word).get("VERB", ())


def _heading(tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """ "E-scooter cut-in on urban straight", "AEB validation - e-scooter crossing at urban junction": a
    first line written as a heading (no article, no pronoun, no inflected verb) names the
    scenario; a road user it names bare is the one the text goes on to introduce with "a" or "an" ("an
    e-scooter, starts in the left lane ..."), one road user, so the heading's noun is left out (listed
    as not used) and what the heading says of the setting stays. A first sentence with an article or
    a verb ("Cyclist pulls out ...", "A van brakes.") is no heading."""
    end = next((k for k, w in enumerate(tokens) if w in _HEADING_ENDS), None)
    if end is None or end + 1 >= len(tokens):
        return tokens
    head = tokens[:end]
    if any(w in DETERMINERS or w in PRONOUNS or w in FIRST_PERSON or w in BE or _finite(w) for w in head):
        return tokens
    later = [p for p in road_user_phrases(tokens[end:], kind_at, known) if p.det in ("a", "an")]
    out = list(tokens)
    for p in reversed(road_user_phrases(head, kind_at, known)):
        if p.kind != "ego" and not p.det and any(q.kind == p.kind for q in later):
            dropped.extend(out[p.head : p.end])
            del out[p.head : p.end]
    return out


#: Words after which a possessive vehicle is the subject of a clause ("when their car ran into ...") or
#: holds its people ("three people in their car"), not a place someone is or goes ("out of her car").
_OWN_VEHICLE_OPENS = frozenset(
    "when after as and but then while because before until so once where in inside , ; :".split()
)


def _modifies(word: str) -> bool:
    """Whether ``word`` can stand before a person's noun in its phrase: an article, a count, an
    adjective (no verb, no punctuation)."""
    return word in DETERMINERS or word in _COUNTED or word.isdigit() or (word.isalpha() and not _verb_of(word))


def _occupants(tokens: list[str], kind_at: KindAt, dropped: list[str]) -> list[str]:
    """ "Three people were injured when their car ran into a lorry", "a man escaped unhurt after his van
    overturned": the people whose own vehicle ("their car", "his van") does something in the same
    sentence are its occupants, that vehicle, no walkers; their phrase (with its count) is left out
    (listed as not used). Only the nearest walker's phrase before the possessive, with no other road
    user between; and only where the vehicle opens a clause or holds them ("in their car"): a person
    who leaves or goes to their vehicle ("got out of her car and walked across") is a walker."""
    out = list(tokens)
    for p in range(len(out) - 1, 0, -1):
        if out[p] not in ("their", "his", "her") or out[p - 1] not in _OWN_VEHICLE_OPENS:
            continue
        owned = next((h for h in range(p + 1, min(p + 4, len(out))) if kind_at(out, h) is not None), None)
        if (
            owned is None
            or kind_at(out, owned)[0] in ("pedestrian", "ego")
            or any(w in PUNCT for w in out[p + 1 : owned])
        ):
            continue
        person = None
        for b in range(p - 1, -1, -1):
            if out[b] in SENTENCE_END:
                break
            if (found := kind_at(out, b)) is not None:
                person = (b, found) if found[0] == "pedestrian" and b + found[1] <= p else None
                break
        if person is None:
            continue
        b, (_, n) = person
        start = b  # (back over its count, article and up to two modifiers: "three young people")
        while start > max(b - 3, 0) and _modifies(out[start - 1]):
            start -= 1
        dropped.extend(out[start : b + n])
        del out[start : b + n]
    return out


def _only_a_verb(word: str) -> bool:
    """Whether ``word`` can only be a verb ("stepped", "overtook"), not also a noun or an adjective
    ("phone", "aged"): such a word opens a clause."""
    return _verb_of(word) and not {"NOUN", "ADJ"} & set(lemmas(word))


def _driver_apposition(tokens: list[str], kind_at: KindAt, dropped: list[str]) -> list[str]:
    """ "the driver of the pickup, an elderly man, pulled out", "the motorcyclist, a man in his
    fifties, overtook me": a person set in apposition to a vehicle (an indefinite walker's noun with its
    modifiers between commas, the sentence's verb right after) says who drives it, no road user of its
    own; the apposition is left out (listed as not used). A person whose own verb follows ("I passed
    the bus, a man stepped out ...") opens a clause of their own and stays."""
    out = list(tokens)
    i = 1
    while i + 2 < len(out):
        vehicle = next((b for b in range(i - 1, max(i - 4, -1), -1) if (f := kind_at(out, b)) and b + f[1] == i), None)
        if (
            out[i] != ","
            or out[i + 1] not in ("a", "an")
            or vehicle is None
            or kind_at(out, vehicle)[0] not in VEHICLES
        ):
            i += 1
            continue
        head = next((h for h in range(i + 2, min(i + 6, len(out))) if kind_at(out, h) is not None), None)
        close = next((k for k in range(i + 2, min(i + 12, len(out))) if out[k] in PUNCT), None)
        fits = (
            head is not None
            and close is not None
            and head < close
            and kind_at(out, head)[0] == "pedestrian"
            and out[close] == ","
            and close + 1 < len(out)
            and _verb_of(out[close + 1])
            and not any(
                kind_at(out, k) is not None or out[k] in ("and", "or") or _only_a_verb(out[k])
                for k in [*range(i + 2, head), *range(head + kind_at(out, head)[1], close)]
            )
        )
        if fits:
            dropped.extend(out[i + 1 : close])
            del out[i:close]
        i += 1
    return out


#: Words that may describe a person set in apposition to a road user by what they wear, hold or look
#: like ("bloke in a hi-vis", "young guy with headphones", "woman wearing a long coat", "lad of about
#: 16, no helmet"); a word of placement ("behind", "next to") says where someone else is instead.
_DESCRIBING = frozenset(
    {"in", "with", "on", "without", "of", "no", "about", "wearing", "carrying", "holding", "dressed"}
)
#: Where a person set off by commas is instead someone placed apart from the road user.
_PLACING = frozenset({"behind", "beside", "near", "next", "ahead", "across", "from", "at", "by", "towards", "between"})


def _kind_follows(tokens: list[str], k: int, kind_at: KindAt) -> bool:
    """Whether a road user is named at ``k``; nothing is named past the end of the text (a rider
    described at the very end: "..., bloke in a hi-vis")."""
    return k < len(tokens) and kind_at(tokens, k) is not None


def _describes(tokens: list[str], start: int, end: int, kind_at: KindAt) -> bool:
    """Whether ``tokens[start:end]`` only describe a person (clothes, what they carry, their age):
    no road user, no placement, no verb of their own but the closed verbs of wearing and holding."""
    for w in tokens[start:end]:
        if w in _DESCRIBING or w in DETERMINERS or not w.replace("-", "").isalpha():
            continue
        if w in _PLACING or w in _PLACEMENT_WORDS or w in ("and", "or") or w in BE:
            return False
        if _verb_of(w) and (_only_a_verb(w) or w.endswith(("ing", "ed"))):
            return False
    return not any(kind_at(tokens, k) is not None for k in range(start, end))


def _person_apposition(tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """ "There's an e-scooter in front, bloke in a hi-vis, about 15 m ahead", "a moped came off the kerb,
    young guy with headphones, right in front of me": a person said bare (no article, the way a note or
    a spoken story drops it) between commas after a rider's or driver's road user in the same sentence,
    described by what they wear or look like, is who rides or drives it, no road user of their own; the
    apposition is left out (listed as not used). A person with a verb or a placement of their own ("a
    bus stopped, man got off", "a car parked, child behind it") or one item of a list ("a van, woman
    in a coat, and a cyclist") stays."""
    out = list(tokens)
    i = 1
    while i + 2 < len(out):
        if out[i] != "," or out[i + 1] in DETERMINERS:
            i += 1
            continue
        head = next((h for h in range(i + 1, min(i + 4, len(out))) if kind_at(out, h) is not None), None)
        found = kind_at(out, head) if head is not None else None
        close = next((k for k in range(i + 1, min(i + 10, len(out))) if out[k] in PUNCT), len(out))
        ridden = None
        for b in range(i - 1, -1, -1):  # the road user said last before the comma, in the same sentence
            if out[b] in SENTENCE_END:
                break
            if (f := kind_at(out, b)) is not None and f[0] != "ego" and out[b] not in PRONOUNS:
                ridden = f[0]
                break
        after = out[close + 1] if close + 1 < len(out) else "."
        fits = (
            found is not None
            and found[0] == "pedestrian"
            and ridden is not None
            and ridden != "pedestrian"
            and head + found[1] <= close
            and all(w.isalpha() and not known(out, k) for k, w in enumerate(out[i + 1 : head], i + 1))
            and _describes(out, head + found[1], close, kind_at)
            and after not in ("and", "or")
            and not _kind_follows(out, close + 1 + (after in DETERMINERS), kind_at)
        )
        if fits:
            dropped.extend(out[i + 1 : close])
            del out[i:close]
        i += 1
    return out


def resolve(
    tokens: list[str], kind_at: KindAt, known: Known, proper: frozenset[str] = frozenset()
) -> tuple[list[str], list[str]]:
    """``tokens`` with every road user said the one way the reader reads it (see the module's
    docstring), and the words taken out (to be reported as not used).

    The order matters: labels and bracketed names first (they say who the ego is and what a name
    stands for), then what makes two mentions one road user, then what is no road user at all, then
    the ego of a report that names none (once the scenery is gone), and last the speeds bound to
    referents and the mentions said again (over the referents that remain). ``proper`` are the words
    the text writes with their own capital (:func:`who.proper_names`)."""
    dropped: list[str] = []
    names: dict[str, str] = {}
    tokens = person_with_vehicle(make_and_model(tokens, kind_at, known), kind_at)
    tokens = walker_places(vehicle_places(travel_modes(tokens, kind_at), kind_at), kind_at)
    tokens = _named_vehicles(names_ending_in_a_walker(tokens, kind_at, proper, dropped), kind_at, known, proper)
    tokens = _brackets(tokens, kind_at, known, names, dropped)
    tokens = _compounds(tokens, kind_at)
    tokens = absent(vehicle_modifiers(tokens, kind_at, dropped), kind_at, dropped)
    tokens = partitives(tokens, kind_at)
    tokens = picked_out(tokens, kind_at, known, dropped)
    tokens = _participial_apposition(tokens, kind_at, known)
    tokens = _vehicle_labels(tokens, kind_at, known)
    tokens = _letter_labels(tokens, kind_at, known, dropped)
    tokens = _field_names(tokens, kind_at, known)
    tokens = _heading(tokens, kind_at, known, dropped)  # (after the labels: "Actor 1: e-scooter")
    tokens = vocatives(tokens, kind_at, dropped)
    tokens = _generic_plurals(tokens, kind_at, known, dropped)
    tokens = _followed_by(tokens, kind_at, known, dropped)
    tokens = shared_vehicles(tokens, kind_at, known)
    tokens = _placed_riders(relative_riders(tokens, kind_at), kind_at)
    tokens = _riders_own(_riders(tokens, kind_at, known), kind_at, known)
    tokens = _pushed(tokens, kind_at, known, dropped)
    tokens = _drivers(tokens, kind_at, known)
    tokens = _driver_apposition(tokens, kind_at, dropped)
    tokens = _person_apposition(tokens, kind_at, known, dropped)
    tokens = _companions(tokens, kind_at, known, dropped)
    tokens = _occupants(tokens, kind_at, dropped)
    tokens = _followed_names(tokens, kind_at, known)
    tokens = _own_vehicle(tokens, kind_at, known, dropped)
    tokens = _narrators_people(tokens, kind_at, dropped)
    tokens = _passengers(tokens, kind_at, known, dropped)
    tokens = _witnesses(tokens, kind_at, known, dropped)
    tokens = _road_users_of_what_may_happen(what_may_happen(tokens, dropped), kind_at, known, dropped)
    tokens = _people_in_general(tokens, kind_at, known, dropped)
    tokens = _others_in_general(tokens, kind_at, known, dropped)
    tokens = _oncoming_traffic(tokens, kind_at, known, dropped)
    tokens = _narrator_on_foot(tokens, kind_at, known, dropped)
    tokens = _ego_apposition(tokens, kind_at, known, dropped)
    tokens = _ego_predicate(tokens, kind_at, known, dropped)
    tokens = _what_everyone_is(tokens, kind_at, known, dropped)
    tokens = _placed_apposition(tokens, kind_at, known, dropped)
    tokens = _egos_vehicle(tokens, kind_at, known, dropped)
    tokens = _responders(_aftermath(tokens, kind_at, known, dropped), kind_at, known, dropped)
    tokens = _ego_unnamed(tokens, kind_at, known)
    tokens = _named_speeds(tokens, kind_at, known, names)
    tokens = _speed_of_both(tokens, kind_at, known)
    tokens = _relative_of_ego(tokens)
    tokens = _mentions_again(_theirs_named_before(tokens, kind_at, known), kind_at, known)
    return tokens, dropped


#: A third person's possessive before what they ride or drive ("his bike", "her car", "their van").
_THIRD_PERSONS_OWN = frozenset(("his", "her", "their"))
#: Kinds of what a rider named before rides ("a cyclist ... his bike"). A car is not among them: "his
#: car" is as often the narrator's client's ("My insured ... struck the passenger side of his car").
_RIDDEN = frozenset(("bicycle", "e-scooter"))


def _theirs_named_before(tokens: list[str], kind_at: KindAt, known: Known) -> list[str]:
    """ "A cyclist swerved in front of us. His bike was a metre from the bumper", "an artic cut in; his
    trailer was 8 m ahead": a two-wheeler (or a trailer) said with a third person's possessive, of the
    kind of a road user named before it, is that road user's own (said with "the", as a known one is),
    not one more. A vehicle of a kind nobody before is ("a man ... his van") stays its own, and so do a
    walker's animal ("a jogger with her dog") and a car ("his car" may be the narrator's client's)."""
    out = list(tokens)
    named: set[str] = set()
    for p in road_user_phrases(tokens, kind_at, known):
        ridden = p.kind in _RIDDEN or tokens[p.head : p.end] == ["trailer"]
        if p.det in _THIRD_PERSONS_OWN and p.start == p.head - 1 and p.kind in named and ridden:
            out[p.start] = "the"
        named.add(p.kind)
    return out


def others_named(pronoun: str, narrator_subject: bool, group: list | None) -> bool:
    """Whether "they" said where the narrator ("I", "we") is the clause's subject so far names the group
    of road users said before ("two e-scooters ahead ... I'm going 40 km/h, they're doing around 20"):
    a narrator's own party is "we", so "they" is the others; and a group was named to be them."""
    return pronoun == "they" and narrator_subject and bool(group)
