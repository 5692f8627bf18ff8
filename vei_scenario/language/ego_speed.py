"""Which stated speed is the ego's, where the text says it by a limit or of traffic in general.

Two ways people give the ego's speed that no number grammar of one road user reads:

- by the limit it keeps to: "Drivers doing the 20 limit", "I was sitting at the 30 limit", "keeping
  to the 50 km/h limit": going at the limit is going at that speed (a limit said alone, "a 20 mph
  road", is only the road's, and the reader's settings read it);
- in a sentence that opens with a participle of driving and names no subject ("Coming round the
  roundabout at 15 mph, a van ...", "Towing a caravan at 80 km/h when ..."): whoever tells the story is
  the one driving, even where the road user named next is the grammatical subject;
- not by the speed it hits something at after it braked ("I braked but hit him at 10 mph", "struck it at
  an estimated 12 mph"): that is what was left of its speed, not the speed it came at;
- of traffic in general, in a text whose ego is someone in traffic in general ("Cars are usually
  doing around 20 mph on the roundabout", "Vehicles typically travel at 40 mph here"): the speed of
  the traffic is the ego's, as it is one of that traffic.
"""

from __future__ import annotations

from vei_scenario.language import lexicon as L
from vei_scenario.language import vocabulary as V
from vei_scenario.language.clauses import sentence_start, sentence_stop
from vei_scenario.language.ego import SENTENCE_END
from vei_scenario.language.function_words import ABOUT, FIRST_PERSON, SUBJECT_PRONOUNS
from vei_scenario.language.lemmas import lemmas
from vei_scenario.language.outcome import names_road_user
from vei_scenario.language.quantities import SPEED_HEADS, is_number

#: Words of going at a speed, before "the <number> limit" ("doing", "sitting at", "keeping to").
GOING = frozenset(
    "doing going driving travelling traveling moving riding sitting keeping sticking holding cruising".split()
)
#: Nouns that say road users in general in the plural: the traffic of a place.
TRAFFIC = frozenset({"cars", "vehicles", "drivers", "motorists", "traffic"})
#: Words between such a subject and its verb of going ("are usually", "typically", "tend to be").
_BETWEEN = frozenset(
    "are is were was usually typically normally generally often mostly still tend to be will all".split()
)
_HEDGES = ABOUT | {"at", "nearly", "some"}


def at_the_limit(tokens: list[str]) -> list[str]:
    """``tokens`` with "<going> (at|to) the <number> (<unit>) (speed) limit" said as "<going> (at|to)
    <number> (<unit>)": the speed the ego keeps, which the reader's numbers then read as any speed."""
    out = list(tokens)
    k = len(out) - 1
    while k >= 0:
        if out[k] != "limit":
            k -= 1
            continue
        end = k + 1
        j = k - (out[k - 1] == "speed")
        unit = j >= 1 and out[j - 1] in V.SPEED_UNITS
        n = j - 1 - unit
        if n >= 2 and is_number(out[n]) and out[n - 1] == "the":
            verb = n - 2 - (out[n - 2] in ("at", "to"))
            if verb >= 0 and out[verb] in GOING:
                out[n - 1 : end] = out[n : n + 1 + unit]
                k = n - 1
                continue
        k -= 1
    return out


#: Words between "the limit" and its number, or after the number ("the limit, 70,", "the limit (60)").
_ASIDE = frozenset({",", "(", ")", "-", ":"})
#: Words that end the phrase after the limit's number ("..., seventy, when", "(60) and").
_LIMIT_PHRASE_ENDS = frozenset({",", ")", ".", ";", "!", "?", "-", "when", "and", "but", "as", "while", "then", ""})


def the_limit_then_its_number(tokens: list[str]) -> list[str]:
    """``tokens`` with "<going> (at|to) the (speed) limit, <number> (<unit>)," said as "<going> at <number>
    (<unit>)": the limit the ego keeps to named, then its number in an aside ("I was doing the limit,
    seventy, when ...", "doing the speed limit (60) when ..."). Only where the number ends its aside: "the
    limit, 3 cars behind a truck" gives no number of the limit's."""
    out = list(tokens)
    k = len(out) - 1
    while k >= 2:
        if out[k] != "limit":
            k -= 1
            continue
        n = k + 1
        while n < len(out) and n <= k + 2 and out[n] in _ASIDE:
            n += 1
        unit = n + 1 < len(out) and out[n + 1] in V.SPEED_UNITS
        after = out[n + 1 + unit] if n + 1 + unit < len(out) else ""
        the = k - 1 - (out[k - 1] == "speed")
        verb = the - 1 - (out[the - 1] in ("at", "to"))
        if (
            n < len(out)
            and is_number(out[n])
            and after in _LIMIT_PHRASE_ENDS
            and out[the] == "the"
            and verb >= 0
            and out[verb] in GOING
        ):
            out[verb + 1 : n] = ["at"]  # ("sticking at 50": as any speed "at" says)
        k = verb if verb < k else k - 1
    return out


def of_traffic(tokens: list[str]) -> float | None:
    """The speed (m/s) said of traffic in general: a bare plural ("Cars", "Vehicles", "traffic") that
    opens its sentence or clause, its verb of going, then a number with its unit. None where none is
    said so (the speed of "the cars" or "two cars" is theirs)."""
    for k, w in enumerate(tokens):
        if w not in TRAFFIC or (k and tokens[k - 1] not in SENTENCE_END | {",", ":", "and"}):
            continue
        j = k + 1
        while j < len(tokens) and tokens[j] in _BETWEEN:
            j += 1
        if j >= len(tokens) or tokens[j] not in GOING | {"move", "travel", "go", "drive", "moves", "travels"}:
            continue
        j += 1
        while j < len(tokens) and tokens[j] in _HEDGES:
            j += 1
        if j + 1 < len(tokens) and is_number(tokens[j]) and tokens[j + 1] in V.SPEED_UNITS:
            return float(tokens[j]) * V.SPEED_UNITS[tokens[j + 1]]
    return None


#: Verbs of going on foot or on a bike, or across: a sentence opening with one of their participles
#: ("Crossing the road at 6 km/h, a jogger ...") is about the road user it names next, as its grammar
#: says. Any other participle of going ("Heading home at 50 km/h, ...", "Crawling along at 10 mph when
#: ...") opens the narrator's drive, the way people tell it, whoever the sentence names next.
NOT_DRIVING = frozenset({"cross", "walk", "run", "jog", "ride", "cycle", "step", "scoot", "skate"})
#: Words that end such an opening phrase: a comma, a conjunction, the sentence's end.
_PHRASE_ENDS = frozenset({",", ";", ".", "!", "?", "and", "when", "while", "as", "but", "then"})
_OPENERS = SENTENCE_END | {":"}


def opening_participles(tokens: list[str], speeds: frozenset[int] | set[int] = frozenset()) -> dict[int, bool]:
    """The numbers said in a phrase that opens its sentence with a participle and no subject, by their
    index: True where the participle is of driving (the speed is the narrator's, the ego's), False
    for one of walking, riding or crossing ("Crossing the road at 6 km/h, a jogger ...": the speed of
    the one named next). ``speeds``: the indices the reader read as speeds, bare ones among them ("Doing
    about 20 down the high street, a lad ...": the narrator's, whatever sentence came before)."""
    out: dict[int, bool] = {}
    for k, w in enumerate(tokens):
        if not w.endswith("ing") or len(w) < 5 or (k and tokens[k - 1] not in _OPENERS):
            continue
        verbs = lemmas(w).get("VERB", ()) if lemmas(w) else (w[:-3],)  # ("pootling": a verb lemminflect lacks)
        if not verbs or "even" in verbs:  # ("Morning, ...", "Evening, ...": no participle)
            continue
        for j in range(k + 1, min(k + 14, len(tokens))):
            if tokens[j] in _PHRASE_ENDS:
                break
            if j in speeds or (is_number(tokens[j]) and j + 1 < len(tokens) and tokens[j + 1] in V.SPEED_UNITS):
                out[j] = not NOT_DRIVING & set(verbs)
    return out


#: Past participles of being held in traffic that open a narrator's sentence ("Stuck behind a bus").
_HELD = frozenset({"stuck", "sat", "sitting", "queued", "queueing", "queuing", "caught", "trapped", "boxed"})


def narrators_opening(tokens: list[str], i: int) -> bool:
    """Whether token ``i`` stands in a sentence that opens with a participle of driving or of being
    held in traffic and no subject ("Crawling behind a tractor at 15 mph, ...", "Stuck behind a lorry
    on the A30; ...", "Going round the roundabout behind a bus, ..."): the left-out subject is the
    narrator, the ego, as in :func:`opening_participles`. Not one of walking, riding or crossing
    ("Crossing behind a bus, a kid ...": the one named next)."""
    k = i
    while k > 0 and tokens[k - 1] not in _OPENERS:
        k -= 1
    if k >= i:
        return False
    w = tokens[k]
    if w in _HELD:
        return True
    verbs = set(lemmas(w).get("VERB", ()))
    participle = w.endswith("ing") and len(w) >= 5 and bool(verbs)
    return (participle or _past_verb(w)) and not (NOT_DRIVING | _FOLLOWING_VERBS) & verbs


#: Words that open a clause of its own inside a sentence ("Waited till a bus had gone", "... when a van
#: pulled out"): its speeds are its subject's, not those of the sentence's left-out subject.
_SUBORDINATORS = frozenset({"till", "until", "when", "while", "whilst", "as", "before", "after", "because", "since"})
#: Words that join one more verb to a sentence ("... and passed them", "..., then overtook it").
_JOINS = frozenset({",", "and", "but"})
#: Words after a comma that go on with the same verb's phrase ("on the M6, at 60", "..., doing 60").
_GOES_ON = frozenset({"at", "doing", "going", "travelling", "traveling", "about", "around", "still"})
#: Determiners after "by" that name an agent ("hit by a van", "overtaken by the bus"): a passive.
_AGENT_OPENERS = frozenset({"a", "an", "the", "some", "one", "this", "another"})


#: Verbs (lemmas) of following: the speed said with one is the followed road user's, and the ego's only
#: through it, as the reader's reading of following has it.
_FOLLOWING_VERBS = frozenset({"follow", "tail", "tailgate", "trail"})


def _past_verb(word: str) -> bool:
    """Whether ``word`` is only a verb in the past tense ("approached", "came", "waited"): not its
    plain form ("brake"), the third person ("brakes"), a participle of going on ("braking"), a word
    that is also a noun or an adjective ("left", "hit", "stuck": a sentence may open with those as such),
    nor an auxiliary ("Could you make one where ...", "Did a van ...": a question or a request)."""
    found = lemmas(word)
    verbs = found.get("VERB", ())
    return (
        bool(verbs)
        and word not in verbs
        and not word.endswith(("s", "ing"))
        and not {"NOUN", "ADJ", "AUX"} & set(found)
    )


def subjectless_sentences(tokens: list[str], speeds: set[int], road_users: set[int]) -> dict[int, bool]:
    """The speeds (by their index in ``speeds``) said in a sentence that opens with a verb in the past
    tense and no subject, and in the verbs joined to it ("Came round the bend at 40 km/h, ...", "Waited
    till it was clear and passed them wide doing about 60."): True, the speed of the one the sentence
    leaves out, who tells the story or whom the notes are about, as a participle that opens a sentence
    is (:func:`opening_participles`); False in a passive ("Overtaken at 90 km/h by a motorbike", "Hit
    from behind by a van doing 30"): the speed of the agent named after "by". A clause of its own inside
    the sentence ("till a bus pulled out at 30") keeps its speeds to its subject, and a participle right
    before a road user (``road_users``: the indices of the words that name one) is its modifier, not a
    verb ("Parked car pulls out at 20 km/h": the car's)."""
    out: dict[int, bool] = {}
    for k, w in enumerate(tokens):
        if (k and tokens[k - 1] not in _OPENERS) or k + 1 in road_users or not _past_verb(w):
            continue
        if _FOLLOWING_VERBS & set(lemmas(w).get("VERB", ())):
            continue  # ("Followed a bus at 30 mph": the bus's speed, which the one following keeps)
        found: list[int] = []
        passive, own = False, True
        for j in range(k + 1, min(k + 40, len(tokens))):
            t = tokens[j]
            if t in SENTENCE_END:
                break
            if t in _SUBORDINATORS:
                own = False
            elif t in _JOINS:
                after = tokens[j + 1] if j + 1 < len(tokens) else ""
                after = tokens[j + 2] if after == "then" and j + 2 < len(tokens) else after
                own = _past_verb(after) or (own and t == "," and after in _GOES_ON)
            elif own and t == "by" and j + 1 < len(tokens) and tokens[j + 1] in _AGENT_OPENERS:
                passive = True
            elif own and j in speeds:
                found.append(j)
        for j in found:
            out[j] = not passive
    return out


#: Words that open the clause of what happened while the ego went at a speed ("... at 30 km/h when a
#: taxi came in", "... at 50 as a cyclist pulled out").
_INTERRUPTED = frozenset({"when", "as", "while", "whilst", "till", "until"})
#: Forms of "be" and "have": a sentence with one before its speed has a subject and a verb of its own.
_FINITE = frozenset({"was", "were", "is", "are", "am", "'m", "'s", "'re", "be", "been", "had", "has", "have"})
#: How far into a sentence with no subject its speed may stand ("Already on the roundabout at about 20").
_SETTING_REACH = 10


def _no_subject_before(tokens: list[str], start: int, i: int, road_users: set[int]) -> bool:
    """Whether tokens ``start:i`` name no one and hold no verb: only a place, a time, an adverb ("Already
    on the roundabout", "On the M6", "Just past the school,"), no road user, pronoun nor verb of a subject."""
    for j in range(start, i):
        w = tokens[j]
        if j in road_users or w in _FINITE or w in SUBJECT_PRONOUNS or _past_verb(w):
            return False
        if j == start and w in _OPENING_SUBJECTS:
            return False  # ("It was at 40 when ...": its subject; "over it at 50" is an object)
        if w.endswith("ing") and "VERB" in lemmas(w):
            return False  # (a participle opening the sentence: :func:`opening_participles` reads it)
    return True


#: Words that are a sentence's subject where they open it ("It was at 40 ...", "There was a bus at 30").
_OPENING_SUBJECTS = frozenset({"it", "there", "this", "that", "one"})


def before_what_happened(tokens: list[str], speeds: set[int], road_users: set[int]) -> dict[int, bool]:
    """The speeds (by their index in ``speeds``) said in a sentence that opens with no subject and no
    verb, only where and how fast, before "when"/"as"/"while" and what happened ("Already on the
    roundabout at about 20 mph when an SUV comes in from the left", "On the M6 at 70 when a van swerved
    across", "Just past the school, maybe 30 km/h, when a kid rode out"): True, the speed of the one the
    sentence leaves out, the narrator, as a subjectless opening phrase is (:func:`opening_participles`);
    the one named after "when" is who interrupts it. Not where a road user or a verb comes before the
    speed ("A car at 40 mph when ...": the car's), nor without a clause after it ("At 40 km/h the van
    pulled out": the van's)."""
    out: dict[int, bool] = {}
    for i in sorted(speeds):
        start = i
        while start > 0 and tokens[start - 1] not in _OPENERS:
            start -= 1
        if i - start > _SETTING_REACH or not _no_subject_before(tokens, start, i, road_users):
            continue
        k = i + 1 + (i + 1 < len(tokens) and tokens[i + 1] in V.SPEED_UNITS)
        k += k < len(tokens) and tokens[k] == ","
        if k < len(tokens) and tokens[k] in _INTERRUPTED:
            out[i] = True
    return out


#: Words between a subject and its verb of going ("was", "had been", "was still", "was only", "was probably").
_AUX = frozenset(
    {"was", "were", "is", "are", "had", "has", "been", "still", "just", "only", "probably", "maybe", "already",
     "possibly", "likely", "definitely", "barely", "hardly", "easily"}
)  # fmt: skip
#: Words right before "my"/"our" that make the party member named after them an object, not the subject
#: of the verb that follows ("in front of my husband was ...", "behind our dad"): prepositions.
_OBJECT_OF = frozenset(L.OBJECT_PREPOSITIONS) | {
    "in", "on", "like", "about", "over", "under", "through", "across", "along", "up", "down", "off", "against",
    "after", "before", "beside", "besides", "unlike", "'s",
}  # fmt: skip


def _party_member(tokens: list[str], k: int, covered: set[int]) -> int:
    """The index after a person of the narrator's party named at ``k`` ("Dad", "my husband", "Emeka":
    a name no dictionary knows), 0 where none is named there or the reader reads the words as anything."""
    j = k + (tokens[k] in ("my", "our"))
    if j >= len(tokens) or j in covered or not tokens[j].isalpha():
        return 0
    if tokens[j] in V.PARTY or (j == k and not lemmas(tokens[j])):
        return j + 1
    return 0


def _party_subject(tokens: list[str], k: int, covered: set[int]) -> tuple[int, bool]:
    """(the index after a person of the narrator's party who is the subject of what follows, named at
    ``k``; whether they open their clause): one opening a sentence ("Dad was ...", "Jen, driving ..."),
    or "my"/"our" and the person anywhere but after a preposition ("Last night my son was driving",
    "On Friday our daughter was going": a time before the subject leaves it the subject; "in front of my
    husband was a van": the object). (0, False) where none is."""
    opens = not k or tokens[k - 1] in _OPENERS
    if not opens and (tokens[k] not in _OWNERS or tokens[k - 1] in _OBJECT_OF):
        return 0, False
    return _party_member(tokens, k, covered), opens


def _going_verb(word: str) -> bool:
    """Whether ``word`` is a verb of going at a speed or of doing one ("doing 40"). Not one of following
    ("My wife was following a lorry at 90 km/h"): that speed is the followed one's as well, which this
    reading, giving it to the ego alone, would take from it."""
    return bool((_GOING_LEMMAS | {"do"}) & set(lemmas(word).get("VERB", ())))


def _phrase_speeds(tokens: list[str], j: int, speeds: set[int]) -> list[int]:
    """The speeds (indices in ``speeds``) in the phrase of the verb at ``j``: up to its end, and a note
    set off by a comma right after it ("driving home, maybe 25 km/h, when ...")."""
    out = []
    for n in range(j + 1, min(j + 12, len(tokens))):
        if tokens[n] == ",":
            note = n + 1
            while note < len(tokens) and tokens[note] in _NOTE_HEDGES | {"like", "at", "doing"}:
                note += 1
            if note in speeds:
                out.append(note)
            break
        if tokens[n] in _PHRASE_ENDS:
            break
        if n in speeds:
            out.append(n)
    return out


def party_at_the_wheel(
    tokens: list[str], speeds: set[int], covered: set[int], told_first: bool = False
) -> dict[int, bool]:
    """The speeds (by their index in ``speeds``) said of one of the narrator's party who is the subject
    of a verb of going ("Dad was driving at around 80 km/h", "My husband was doing about 70", "Last night
    my son was driving home, maybe 25 km/h, ...", "Mum was probably going 30 mph"), or who opens a
    sentence with such a verb in an aside ("Jen, driving to work at 30 km/h, had to brake"), in a story
    told in the first person: that person drives the car the narrator is in, the ego, so the speed is
    the ego's, not that of the road user named before. Words the reader reads as a road user or anything
    else (``covered``) name no such person. The first person as written counts too (``told_first``): "a
    truck crossed in front of our car. Rohit was driving at 50" has none left in ``tokens`` once "our
    car" is read as the ego."""
    out: dict[int, bool] = {}
    if not told_first and not FIRST_PERSON & set(tokens):
        return out
    for k in range(len(tokens)):
        j, opens = _party_subject(tokens, k, covered)
        if not j:
            continue
        if opens and tokens[j : j + 1] == [","]:
            j += 1  # ("Jen, driving to work at 30 km/h, ...": an aside of the subject's going)
            if j >= len(tokens) or not tokens[j].endswith("ing"):
                continue
        while j < len(tokens) and tokens[j] in _AUX:
            j += 1
        if j >= len(tokens) or not _going_verb(tokens[j]):
            continue
        for n in _phrase_speeds(tokens, j, speeds):
            out[n] = True
    return out


#: Nouns of a formation that goes at one speed, the ego in it ("platoon speed 80 km/h", "group speed 25").
GROUPS = frozenset({"platoon", "convoy", "group", "peloton", "column", "formation"})
#: Words between "<group> speed" and its number ("is", ":", "of about").
_SPEED_LINKS = frozenset({"is", "was", "of", ":", "=", "at", "about", "around", "roughly", "approximately", "~"})
#: Verbs (lemmas) and prepositions by which the ego meets a formation from outside ("overtakes the
#: convoy", "approaches the platoon", "behind the group"): its speed is then not the ego's.
_MEETING = frozenset({"overtake", "pass", "approach", "catch", "reach", "follow", "meet", "join", "pull"})
_OUTSIDE = frozenset({"behind", "towards", "toward", "past", "alongside", "into"})


def _met_from_outside(tokens: list[str], k: int) -> bool:
    """Whether the formation named at ``k`` is something met from outside ("overtakes the convoy",
    "approaches the platoon from behind", "behind the group")."""
    j = k - 1
    while j >= 0 and tokens[j] in ("the", "a", "this", "that", "truck", "lorry", "car", "bike", "cycling"):
        j -= 1
    return j >= 0 and (tokens[j] in _OUTSIDE or bool(_MEETING & set(lemmas(tokens[j]).get("VERB", ()))))


def group_speeds(tokens: list[str], speeds: set[int]) -> dict[int, bool]:
    """The speeds (by their index in ``speeds``) said of a formation the ego goes in ("Platoon speed 80
    km/h", "group speed about 25 km/h", "the speed of the platoon is 85 km/h"): True, one formation
    goes at one speed, the ego's; none where the text has the ego meet the formation from outside
    ("The ego overtakes the convoy"), whose speed is then the others'."""
    out: dict[int, bool] = {}
    groups = [k for k, w in enumerate(tokens) if w in GROUPS]
    if not groups or any(_met_from_outside(tokens, k) for k in groups):
        return out
    for k in groups:
        if k + 1 < len(tokens) and tokens[k + 1] == "speed":
            j = k + 2
        elif k >= 3 and tokens[k - 3 : k - 1] == ["speed", "of"]:
            j = k + 1
        else:
            continue
        while j < len(tokens) and tokens[j] in _SPEED_LINKS:
            j += 1
        if j in speeds:
            out[j] = True
    return out


#: The ego's own dial: what it reads is the ego's speed ("the speedo said 45", "60 on the speedo").
SPEEDOMETERS = frozenset({"speedo", "speedometer", "speedometre", "dial", "clock"})
#: Verbs (lemmas) of a dial's reading ("said", "showed", "was reading", "registered").
_READING = frozenset({"say", "show", "read", "register", "display", "hit", "sit"})


def speedometer_reading(tokens: list[str], i: int) -> bool:
    """Whether the number at ``i`` is what the ego's speedometer reads: "(the|my) speedo said (about)
    45", "the speedometer was showing 50", or "60 on the speedo" / "on the clock" (a bare number so
    said is a speed, as "at 60" is; a mileage is thousands and no speed)."""
    after = tokens[i + 1 : i + 4]
    if after[:1] == ["on"] and len(after) == 3 and after[1] in ("the", "my", "our") and after[2] in SPEEDOMETERS:
        return True
    j = i - 1
    while j >= 0 and tokens[j] in _NOTE_HEDGES | {"at", "just", "over", "under", "nearly"}:
        j -= 1
    k = j
    while k >= 0 and k > j - 3 and not _READING & set(lemmas(tokens[k]).get("VERB", ())):
        k -= 1  # (back over "was", "still": "was reading", "was still showing")
    if k < 0 or k <= j - 3:
        return False
    return any(tokens[n] in {"speedo", "speedometer", "speedometre"} for n in range(max(k - 3, 0), k))


#: Verbs of contact (lemmas): a speed said with one is the speed at impact.
CONTACT = frozenset({"hit", "strike", "collide", "clip", "knock", "crash", "smash", "plough", "rear-end", "ram"})
#: The test's names for the ego in engineers' and annotators' narratives ("SV brakes", "the VUT braked").
_SUBJECT_VEHICLES = frozenset({"sv", "vut"})
#: Who does the striking where it is the ego: the narrator, the ego, or no subject after a conjunction
#: ("braked but hit him"), which keeps the subject before it.
_EGO_STRIKER = frozenset({"i", "we", "ego", "and", "but", ",", "then"}) | _SUBJECT_VEHICLES
_ADVERBS = frozenset({"still", "then", "just", "eventually", "nevertheless", "finally", "only", "unfortunately"})
_AT_HEDGES = ABOUT | {"at", "an", "a", "estimated", "maybe", "some"}


#: Nouns of the moment two road users meet ("contact at 3 km/h", "impact at 20 mph"): a speed said "at" after one
#: is the speed of that moment, as one said after a verb of striking is.
IMPACT_NOUNS = frozenset({"contact", "impact", "collision"})


def named_as_impact_speed(tokens: list[str], i: int) -> bool:
    """Whether the speed at ``i`` is given under the name of the speed at impact ("Impact speed V1 approx.
    28 km/h", "collision speed: 20 km/h"): what was left at the moment of contact, after any braking, which
    is no speed a road user starts at where its speed before it is already said."""
    k = i - 1
    while k >= 0 and tokens[k] in _AT_HEDGES | {":", "was", "of"}:
        k -= 1
    for _ in range(4):  # (back over the road user it is said of, "V1", "the ego", where one is named)
        if k >= 1 and tokens[k] in SPEED_HEADS and tokens[k - 1] in IMPACT_NOUNS:
            return True
        k -= 1
    return False


def impact_after_braking(tokens: list[str], i: int) -> bool:
    """Whether the speed at ``i`` is one the ego hits something at ("we struck it at an estimated 12
    mph", "Ego brakes hard, contact at 3 km/h"), said after a braking ("the brakes came on", "I braked"):
    the speed left at impact, which is no speed the ego starts at."""
    struck = _struck_at(tokens, i)
    return struck is not None and any(_egos_braking(tokens, b) for b in range(struck[0]))


def impact_speed(tokens: list[str], i: int) -> bool:
    """Whether the speed at ``i`` is one the ego hits a road user at ("I hit him at maybe 15-20",
    "contact at 3 km/h"), braking said or not: below a speed of the ego said before it ("in the fast
    lane at 65 ... I couldn't stop and hit him at maybe 15-20"), it is what was left at impact, not the
    speed the ego goes at. Not a place hit ("hit the roundabout at 40")."""
    struck = _struck_at(tokens, i)
    if struck is None:
        return False
    contact, at = struck
    obj = tokens[contact + 1 : at]
    return tokens[contact] in IMPACT_NOUNS or obj[:1] in (["it"], ["them"]) or names_road_user(obj)


def struck_before(tokens: list[str], k: int) -> bool:
    """Whether a verb of contact with the ego named at token ``k`` stands within a few words before it in
    its clause ("a van hit the back of my car at 15 mph", "a cyclist smashed into us at 30"; not "debris
    hit the car beside me", another road user struck): the one who strikes the ego there goes at the
    speed said after it, and the ego, struck, need not ("I was stopped at the lights")."""
    verb = _contact_before(tokens, k)
    return verb is not None and not names_road_user(tokens[verb + 1 : k])  # (not "debris hit the car beside me")


def _contact_before(tokens: list[str], k: int) -> int | None:
    """Where the nearest verb of contact stands within five words before token ``k``, with no sentence end
    or comma between them; None where there is none."""
    for j in range(k - 1, max(k - 6, -1), -1):
        if tokens[j] in SENTENCE_END or tokens[j] == ",":
            return None
        if CONTACT & set(lemmas(tokens[j]).get("VERB", (tokens[j],))):
            return j
    return None


def _struck_at(tokens: list[str], i: int) -> tuple[int, int] | None:
    """Where the contact whose "at" the speed at ``i`` follows is said, the ego's verb of striking
    ("we struck it at", "I hit him at") or a noun of contact ("contact at"), and where that "at" is;
    None if there is none."""
    k = i - 1
    while k > 0 and tokens[k] in _AT_HEDGES and tokens[k] != "at":
        k -= 1
    if tokens[k] != "at":
        return None
    if k >= 1 and tokens[k - 1] in IMPACT_NOUNS:  # ("Ego brakes hard, contact at 3 km/h": the impact's speed)
        return k - 1, k
    verb = _contact_before(tokens, k)
    if verb is None:
        return None
    s = verb - 1
    while s > 0 and tokens[s] in _ADVERBS:
        s -= 1
    if s < 0 or tokens[s] not in _EGO_STRIKER:
        return None
    return verb, k


_EGO_WORDS = frozenset({"i", "we", "ego", "my", "our"})
#: Words after which such a name is no subject but where another is ("the car in front of the SV brakes").
_PLACED_BY = frozenset(
    {"of", "behind", "than", "to", "from", "with", "by", "past", "beside", "passing", "toward", "towards"}
)


def _egos_braking(tokens: list[str], b: int) -> bool:
    """Whether ``tokens[b]`` is a braking of the ego: a brake word with the ego said before it in its
    sentence ("I braked", "we were braking", "my brakes"), or "The brakes" opening a sentence (the narrator's own;
    "the car in front braked" is not)."""
    if not tokens[b].startswith("brak") and "brake" not in lemmas(tokens[b]).get("VERB", ()):
        return False
    start = sentence_start(tokens, b, SENTENCE_END)
    if _EGO_WORDS & set(tokens[start:b]):  # ("I saw him late, braked, ...": the subject of its sentence)
        return True
    if any(tokens[k] == "subject" and (k == start or tokens[k - 1] == "the") for k in range(start, b)):
        return True  # ("(The) subject driver reacts late and brakes": the ego's driver, read as "subject")
    named = [k for k in range(start, b) if tokens[k] in _SUBJECT_VEHICLES]
    if named and not _PLACED_BY & set(tokens[max(start, named[0] - 3) : named[0]]):
        return True  # ("SV reacts late and brakes"; not "the POV ahead of the SV brakes": another's braking)
    return b >= 1 and tokens[b - 1] == "the" and (b == 1 or tokens[b - 2] in SENTENCE_END)


#: Words that name the ego as the object of a preposition ("in front of me", "into us", "ahead of the
#: ego"); "my"/"our" open a noun of the ego's ("my lane", "our front bumper").
_EGO_OBJECTS = frozenset({"me", "us", "ego"})
_EGO_OWNERS = frozenset({"my", "our"})
#: Prepositions whose object is where another road user goes relative to the ego ("into me", "across
#: my bonnet", "in front of us", "ahead of the ego"): a speed said with such a phrase is shared, the
#: two are in one place at it. (Not verbs: "overtook me at 25" is the overtaker's, faster than the ego.)
_TOWARDS = frozenset({"into", "across", "of", "onto", "at", "towards", "toward", "alongside", "beside"})
#: Prepositions that open a place phrase said between the ego and "at <speed>" ("into me on the M1 at 60").
_PLACE = frozenset({"on", "along", "in", "down", "up", "through", "near", "past", "over"})
#: Hedges before a bare speed ("about 30 km/h", "~40 mph").
_NOTE_HEDGES = ABOUT | {"approx", "maybe", "nearly", "~", "c", "ca"}
#: Marks that end a note ("..., 25 mph, ...", "... - 40 km/h - ...").
_NOTE_MARKS = frozenset({",", "-", "–", "—", ";", ".", "!", "?", "(", ")"})


def _ego_object_ending_at(tokens: list[str], k: int) -> bool:
    """Whether an ego reference that is the object of a preposition ends at token ``k``: "into me",
    "of us", "ahead of the ego (vehicle)", "across my bonnet", "into our front bumper"."""
    start = None
    if tokens[k] in _EGO_OBJECTS:
        start = k - (k >= 1 and tokens[k - 1] == "the")
    elif tokens[k] == "vehicle" and k >= 1 and tokens[k - 1] == "ego":
        start = k - 1 - (k >= 2 and tokens[k - 2] == "the")
    else:
        for j in range(k, max(k - 3, -1), -1):  # ("my lane", "my front bumper": up to two words after it)
            if tokens[j] in _EGO_OWNERS:
                start = j
                break
            if tokens[j] in _NOTE_MARKS or is_number(tokens[j]):
                return False
    return start is not None and start >= 1 and tokens[start - 1] in _TOWARDS


def said_with_the_ego(tokens: list[str], start: int, end: int) -> str | None:
    """Whether the speed of tokens ``start:end`` is said of the ego named just before it, as the
    object of a preposition of where another road user goes: "note" where it stands alone in a note
    with no verb right after the ego ("cuts in front of my car, 20mph, nearly hit him": how fast the
    narrator was going; the road user's own speed would follow its name, "a cyclist, 20 km/h, ..."),
    "place" where "at <speed>" follows the ego and the place it is on ("SWERVES INTO MY LANE ON THE M1 AT
    60MPH": the two are in one lane at it, so it is the ego's as well as the road user's); else None."""
    k = start - 1
    while k >= 0 and tokens[k] in _NOTE_HEDGES:
        k -= 1
    if k < 1:
        return None
    if tokens[k] in (",", "-", "–", "—"):
        ends = end >= len(tokens) or tokens[end] in _NOTE_MARKS
        if not ends or not _ego_object_ending_at(tokens, k - 1):
            return None
        return None if _goes_in_its_sentence(tokens, k) else "note"
    if tokens[k] != "at":
        return None
    for p in range(k - 1, max(k - 6, 0), -1):  # back over a place phrase ("on the M1", "on the ring road")
        if tokens[p] in _NOTE_MARKS:
            return None
        if tokens[p] in _PLACE and p + 1 < k:
            return "place" if _ego_object_ending_at(tokens, p - 1) else None
    return None


#: Verbs of going (lemmas): a clause that says how its subject goes ("a scooter was going slowly in front
#: of me, around 15 kmph") gives that subject's speed in a note after it, where a clause of an event
#: ("a bus pulls out in front of us, about 30 km/h") leaves the note to the narrator.
_GOING_LEMMAS = frozenset(
    {"go", "ride", "travel", "move", "drive", "cycle", "walk", "run", "jog", "scoot", "cruise", "roll", "trundle",
     "pootle", "crawl", "potter", "amble", "wobble", "head"}
)  # fmt: skip


#: Words after a verb of going that make it an event of entering ("moves into my lane", "rolls out").
_ENTERING = frozenset({"into", "across", "onto", "out", "off"})


def _goes_in_its_sentence(tokens: list[str], k: int) -> bool:
    """Whether a verb of going is said in the sentence before token ``k``, other than one of entering
    ("moves into my lane", "drives out in front of us": an event, as "cuts in" is)."""
    j = k - 1
    while j >= 0 and tokens[j] not in SENTENCE_END:
        entering = tokens[j + 1] in _ENTERING
        if not entering and _GOING_LEMMAS & set(lemmas(tokens[j]).get("VERB", ())):
            return True
        j -= 1
    return False


#: What a follower does that keeps it behind the ego: following, and going on ("never overtook").
_FOLLOWING = frozenset({"follow_vehicle", "keep_going"})


def kept_by_a_follower(actors) -> float | None:
    """The speed (m/s) of a road user that follows the ego ("a van tailgated me at 60 mph", "a lorry
    followed us closely at 80 km/h"): one that keeps behind the ego keeps its pace, so the speed said of
    it is the ego's too. None where no such follower has a speed, or where another road user is ahead
    (the follower may follow that one), or where it does more than follow ("follows the ego, then
    overtakes it at 25 km/h": the speed it overtakes at, faster). One that "never overtook" follows all
    the same: an overtake denied is read as going on. ``actors``: the reader's, with ``relation``,
    ``behaviours`` and ``speed_mps``."""
    if any(a.relation == "ahead" for a in actors):
        return None
    for a in actors:
        said = {b[0] for b in a.behaviours}
        only_follows = "follow_vehicle" in said and said <= _FOLLOWING
        if a.relation == "behind" and only_follows and a.speed_mps:
            return a.speed_mps
    return None


def right_after_the_ego(clauses) -> float | None:
    """The speed (m/s) said right after the ego's name with nothing between ("lets the ego (50 km/h)
    pass", "waits for the ego (30 km/h) to go past": the scanner reads brackets past), as the scanner
    found it: an aside that says how fast the ego goes, which a reading of what the ego is let do may
    read past. None where no speed follows the ego so. ``clauses``: the scanner's (link, mentions)."""
    for _, mentions in clauses:
        for before, m in zip(mentions, mentions[1:]):
            if before.slot == "actor" and before.value == "ego" and m.slot == "speed" and m.start == before.end:
                return m.value
    return None


#: Words before "my"/"our" and a bare number that make the number a speed compared with or kept to ("faster
#: than my 70", "at my 50", "double our 50", "kept pace with my 90").
_BEFORE_OWNED = frozenset(
    {"than", "at", "over", "under", "above", "below", "past", "beyond", "twice", "double", "with"}
)
_OWNERS = frozenset({"my", "our"})
#: Words after which a bare number ends its phrase ("than my 70, and ...", "our 50.").
_OWNED_ENDS = frozenset({"", ".", ",", ";", "!", "?", "and", "then", "when", "while", "but", "for", ")"})


def owned(tokens: list[str], i: int) -> bool:
    """Whether the speed at ``i`` is said as the ego's own, "my"/"our" right before it ("much faster than my 70",
    "well over my 80 km/h", "at double our 50"): the narrator's speed, however the sentence goes on about
    another road user. (A count or an age has no speed's unit nor a comparison before it: "my 2 kids".)"""
    return i >= 1 and tokens[i - 1] in _OWNERS


def bare_owned(tokens: list[str], i: int) -> bool:
    """Whether the bare number at ``i`` is a speed by the way the ego owns it: "my"/"our" before it, a
    comparison or "at" before that, and its phrase ending there ("faster than my 70, ...", "at our 50.")."""
    nxt = tokens[i + 1] if i + 1 < len(tokens) else ""
    return i >= 2 and owned(tokens, i) and tokens[i - 2] in _BEFORE_OWNED and nxt in _OWNED_ENDS


#: Nouns a speed with its unit names a limit of, after an article ("a 60 km/h zone", "the 40 mph limit").
_LIMITED = frozenset({"zone", "limit", "limits", "area", "road", "street", "stretch", "section", "sign"})
#: Of those nouns, the ones that name nothing but a limit: "<speed with its unit> zone" is one with no article.
_ONLY_LIMITS = frozenset({"zone", "limit", "limits"})
#: Words that bound the clause a counterfactual speed is said in ("..., had it been doing 30, ...").
_CLAUSE_BOUNDS = frozenset({".", ";", "!", "?", ",", "and", "but", "when", "so", "then", "while", "because"})
#: Modals of what would have happened or should have been ("would have stopped", "should have reduced").
_MODALS = frozenset({"would", "could", "should", "might", "ought"})
#: Modals of what ought to have been: "should have been doing 20" is a norm, not an estimate.
_NORMS = frozenset({"should", "ought"})


def counterfactual(tokens: list[str], i: int) -> bool:
    """Whether the speed at ``i`` is said in a clause of what did not happen: a condition ("had the car been
    travelling at 30 mph, ...", "if she had been doing 20"), or what would or should have been done
    ("a careful driver would have reduced speed to 20 mph", "he should have been doing 20 there", "at 20
    mph he could have stopped"). Why: an expert, a judge or a witness says what speed would have avoided
    the harm, and no one went at it. Not an estimate said with a modal ("he must have been doing 60",
    "she would have been doing about 40", "could have been going 50": someone's real speed, guessed), and
    not a plain past perfect ("I had been doing 50 before the lights") or "had" as a verb ("Had a fright
    coming home at 20 mph"), which have no "if" and no "had <subject> been"."""
    clause = tokens[sentence_start(tokens, i, _CLAUSE_BOUNDS) : sentence_stop(tokens, i, _CLAUSE_BOUNDS)]
    if clause[:1] == ["had"] and "been" in clause[2:5]:  # ("had the car been ...": not "Had a fright, doing 20")
        return True
    if "had" in clause and "if" in clause[: clause.index("had")]:
        return True
    for k, word in enumerate(clause[:-1]):
        have = k + 1 + (word == "ought" and clause[k + 1] == "to")
        if word not in _MODALS or have >= len(clause) or clause[have] != "have":
            continue
        guessed = clause[have + 1 : have + 2] == ["been"] and any(t in GOING for t in clause[have + 2 : have + 4])
        if not guessed or word in _NORMS:
            return True
    return False


#: Words that give a limit its number after it ("a limit of 40", "cut the limit to 20 mph", "the limit is 30").
_LIMIT_VALUE = frozenset({"of", "to", "is", "was", "at", ":"})
#: How many words may stand between "limit" and the word giving its number ("the speed limit on Kirkby
#: Road to 20 mph", "the limit here is 30").
_LIMIT_REACH = 6


def limit_number_after(tokens: list[str], i: int) -> bool:
    """Whether the speed at ``i`` is the number a limit named before it is given ("a speed limit of 30 mph",
    "reduce the limit on the high road to 20mph", "the limit there is 50"): within its clause, with no
    verb of going before the limit ("doing the limit of 30", "keeping to the limit of 40" say the ego's
    own speed, which :func:`at_the_limit` reads)."""
    if i < 2 or tokens[i - 1] not in _LIMIT_VALUE:
        return False
    for k in range(i - 2, max(i - 2 - _LIMIT_REACH, -1), -1):
        if tokens[k] in SENTENCE_END or tokens[k] == "," or tokens[k] in GOING:
            return False
        if tokens[k] in ("limit", "limits"):
            return not (k >= 2 and (tokens[k - 2] in GOING or tokens[k - 3 : k - 2] and tokens[k - 3] in GOING))
    return False


def limits(tokens: list[str], speeds: set[int]) -> set[int]:
    """The speeds (by their index in ``speeds``) that name a road's limit ("in a 60 km/h zone", "on a 40 mph
    road", "the 30 mph speed limit", "a limit of 20 mph") in a text that says another speed, in the same
    sentence or in any other: someone goes at that other speed, and the limit is the road's, no one's
    speed ("I was doing 50 in a 60 km/h zone": 50; "WE NEED A 20MPH LIMIT. A van came past at 34 mph":
    34). Why the whole text: a limit is a fact of the road, said in a title, a complaint or an aside
    wherever the writer likes, and the speed someone was going is said where the story is. A limit said
    alone, with no other speed, stays a speed (the reader reads it as the speed traffic keeps there)."""
    named = set()
    for i in speeds:
        end = i + 1 + (i + 1 < len(tokens) and tokens[i + 1] in V.SPEED_UNITS)
        end += end < len(tokens) and tokens[end] == "speed"
        if i and tokens[i - 1] in ("a", "an", "the") and end < len(tokens) and tokens[end] in _LIMITED:
            named.add(i)
        elif end < len(tokens) and tokens[end] in _ONLY_LIMITS and tokens[i + 1] in V.SPEED_UNITS:
            named.add(i)  # ("Route: Elm St, 35 mph zone, traveling ~30": a note drops the article)
        elif limit_number_after(tokens, i):
            named.add(i)
    return named if speeds - named else set()


def limits_alone(tokens: list[str], speeds: set[int], skipped: set[int]) -> set[int]:
    """Of the ``skipped`` limits (:func:`limits`), those with no other speed in their sentence ("WE NEED
    A 20MPH LIMIT.", "The limit is 40."): the road's limit, which the ego keeps where nothing else in
    the reading gives its pace (no speed said of it, no one speed of the scene); a limit said beside
    another speed ("doing 50 in a 60 zone") is only the road's."""
    out = set()
    for i in skipped:
        start, stop = sentence_start(tokens, i, SENTENCE_END), sentence_stop(tokens, i, SENTENCE_END)
        if not any(start <= j < stop for j in speeds - skipped):
            out.add(i)
    return out


#: Words between "cruise" and the speed it is set to ("cruise control set to 100", "cruise was on 90").
_CRUISE_LINKS = frozenset({"control", "set", "to", "at", "on", "was", "is", "about", "around", "just"})


def cruise_setting(tokens: list[str], i: int) -> bool:
    """Whether the number at ``i`` is what the ego's cruise control is set to ("Cruise set to 100", "had the
    cruise on 90", "cruise control at 80 km/h"): the speed the ego keeps. Not another road user's ("a van
    on cruise control at 90": one named before "on")."""
    k = i - 1
    while k > 0 and k >= i - 4 and tokens[k] in _CRUISE_LINKS:
        k -= 1
    if k < 0 or k == i - 1 or tokens[k] != "cruise":
        return False
    return not (k >= 1 and tokens[k - 1] == "on")


#: Object pronouns: one right after a verb is what the verb acts on ("hit him", "rear-ended it").
_OBJECT_PRONOUNS = frozenset({"him", "her", "it", "them"})
#: Verbs (lemmas) whose object does what the words after it say: of seeing, of measuring, of letting
#: ("saw him doing 35", "clocked it at 50 mph", "let her go at 20"): the speed is the object's own.
_OBJECT_ACTS = frozenset(
    {"see", "watch", "notice", "spot", "clock", "catch", "time", "measure", "film", "record", "hear", "find",
     "get", "have", "let", "make", "keep", "leave", "want", "need", "help", "follow", "tail", "trail", "tailgate"}
)  # fmt: skip
#: Words between an object and the speed said of its verb's subject ("at an estimated", "doing about").
_BEFORE_SPEED = _AT_HEDGES | _NOTE_HEDGES | {"doing", "going", "travelling", "traveling", "only", "just"}


def after_a_verbs_object(tokens: list[str], i: int) -> bool:
    """Whether the speed at ``i`` is said right after a verb and its object pronoun ("hit him at 20 mph",
    "rear-ended it at about 30 mph", "t-boned him doing 40"): how fast the verb's subject went, not the
    object. Not after a verb whose object does what follows ("saw him doing 35", "clocked it at 50",
    "followed it at 60": the object's own speed, or both)."""
    k = i - 1
    while k >= 0 and tokens[k] in _BEFORE_SPEED:
        k -= 1
    if k < 1 or k == i - 1 or tokens[k] not in _OBJECT_PRONOUNS:
        return False
    verb = tokens[k - 1]
    found = lemmas(verb)
    verbs = set(found.get("VERB", ())) if found else ({verb[:-2]} if verb.endswith("ed") else set())
    return bool(verbs) and not verbs & _OBJECT_ACTS
