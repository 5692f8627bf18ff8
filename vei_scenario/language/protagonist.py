"""The vehicle a third-person report is about, when nothing else in it names the ego.

A news item, a witness statement, an incident log, council minutes or an exam question is told about
one vehicle without calling it the ego: "the Toyota braked but struck the scooter", "a bus entering
from the next arm pulled out across the front of the cab. Driver braked hard", "A car travels along a
straight road at 20 m/s. A pedestrian steps off the kerb 40 m ahead". That vehicle is the ego, and
listing it as another road user as well would give the scenario a road user too many and lose the
ego's speed.

:func:`frame` finds it by what the text says of each road user it names, grouped into referents (a
"the" mention is the earlier one it repeats a word of: "a silver Toyota Corolla ... the Toyota"):

- it has a speed of its own ("travelling north at about 40 mph", ", which was doing about 20 mph,");
- it reacts: it is the subject of a verb of braking, stopping or swerving ("the Corsa swerved",
  "Driver braked hard", "the driver stopped");
- another road user is placed by it: its path, front or side ("into the path of the Toyota", "across
  the front of the cab", "from the Civic's right", "into the van's lane", "towards the car").

The motor vehicle with the most of these, one of them a speed or a reaction, is the ego when no
other motor vehicle has as many and no walker or rider has more, or as many and is named first (a
rider with a speed of their own, overtaken by a car that has none, is the one the text is told from,
not the car). Two that tie are told apart only where one reacts and the other is named only as the
side the first came from or stopped short of ("A black SUV ran the red. A taxi, which was
approaching from the SUV's right, braked to a halt"): whose side the taxi came from says nothing of
whom the story is told from, and its braking for the one that crossed its way does.
A report's bare "driver" ("Driver braked hard", "The driver stopped") is the driver of the vehicle
introduced as known (a field value, "the") or of the only motor vehicle named; with no such vehicle
it is the ego on its own. A parked or placed vehicle ("a parked van", "the car ahead") is never the
ego. The word classes here are small and closed (verbs of reacting, nouns of a vehicle's sides);
which words name road users comes from the reader's lexicon.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from vei_scenario.language.discourse import CONTACT, PERCEIVE, is_singular
from vei_scenario.language.ego import (
    AT_WHEEL,
    BE,
    BETWEEN,
    DEFINITE,
    FIRST_PERSON,
    INDEFINITE,
    NARRATOR_INVOLVED,
    PLACED,
    SPEED_UNITS,
    VEHICLES,
    is_modifier_noun,
    lemma_in,
    names_ego,
    placed_by_word,
    road_users,
    sentence_span,
    stands_parked,
)
from vei_scenario.language.function_words import DETERMINERS
from vei_scenario.language.lemmas import lemmas
from vei_scenario.language.lexicon import PRESSED, PRESSING

#: Verbs of the reaction a report gives the vehicle it is about (lemmas), a closed class.
REACTING = frozenset({"brake", "stop", "swerve", "slow", "steer", "halt", "decelerate", "skid", "stamp"})
#: The nouns of the stop a verb of motion comes to ("eased to a stop", "came to a standstill").
STOP_NOUNS = frozenset({"stop", "halt", "standstill"})
#: Words that may stand between "to a" and the stop ("to a full stop", "to a dead halt").
WHOLE_STOP = frozenset({"full", "complete", "dead", "sudden", "quick", "rapid", "abrupt"})
#: Words that may stand between a road user and its reaction ("braked hard", "had to stop", "was
#: forced to swerve", "then braked"): auxiliaries, "to" and adverbs.
BEFORE_VERB = frozenset(
    {"had", "has", "have", "was", "were", "is", "to", "then", "just", "only", "forced", "able", "managed", "also"}
)
#: Nouns of a road user's own space that another is placed by ("the path of the van", "the front of
#: the cab", "the rear of the car").
OWN_SPACE = frozenset({"path", "front", "rear", "back", "side", "nose", "way", "lane"})
#: Auxiliaries, passive or perfect, and an adverb between, before a participle ("was struck", "got
#: clipped", "had just been hit"); :data:`PASSIVE_VOICE` tells which of them make it passive.
BEFORE_PARTICIPLE = BE | {"has", "had", "have", "got", "gets", "get", "just"}
#: The auxiliaries that make the participle after them passive ("was hit", "got clipped"; "had hit" is
#: active).
PASSIVE_VOICE = BE | {"got", "gets", "get"}
#: Prepositions that place another road user by this one ("came towards the car").
TOWARDS = frozenset({"towards", "toward"})


@dataclass
class _Referent:
    """One road user as the text repeats it: its mentions and the evidence it is the one told about."""

    kind: str
    mentions: list = field(default_factory=list)
    words: set[str] = field(default_factory=set)
    speed: bool = False
    reacts: bool = False
    placed_by: bool = False
    struck: bool = False  # the subject of a passive of contact: "was struck by", "got rear-ended"
    known: bool = False  # introduced as known: bare ("Cab 22") or with "the"
    #: Placed by as a path, front or lane another got into ("into the path of the Toyota"), not only as
    #: where another came from: see :func:`_reactor_among`.
    placed_in_way: bool = False
    #: The referents said to come from its side or to stop short of it ("a taxi approaching from the
    #: SUV's right": the taxi, on the SUV).
    origin_of: list = field(default_factory=list)
    #: It reacts (brakes, stops, swerves) at all, whoever is named before its verb ("A bus braked hard",
    #: "ran the red and braked"); :attr:`reacts` counts only a reaction after someone to react to.
    brakes: bool = False

    @property
    def score(self) -> int:
        return self.speed + self.reacts + self.placed_by + self.struck


def _past_aside(tokens: list[str], k: int, relative_only: bool = False) -> int:
    """Past a relative aside after a mention (", which she estimated to be doing 20 mph,", or one a
    participle opens: ", travelling at 25 mph,"): where the clause resumes, else ``k``."""
    if tokens[k : k + 1] == [","] and tokens[k + 1 : k + 2]:
        end = sentence_span(tokens, k)[1]
        close = next((c for c in range(k + 2, end) if tokens[c] == ","), None)
        relative = tokens[k + 1] in ("which", "who", "that") or reduced_relative(tokens[k + 1])
        if close is not None and (relative or (close - k <= 7 and not relative_only)):  # (", a 54-year-old woman,")
            return close + 1
    return k


#: Words that end the relative clause a mention opens without commas before a verb of its own could
#: follow ("a taxi approaching from the SUV's right braked": "braked" is the taxi's; "... right and a bus
#: braked" is not).
_CLAUSE_ENDS = frozenset(
    {",", ";", ":", ".", "!", "?", "and", "but", "or", "when", "as", "while", "which", "who", "that"}
)


def _past_bare_relative(tokens: list[str], k: int) -> int:
    """Where a verb of reacting stands past a relative clause said without commas right after a
    mention ("a taxi approaching from the SUV's right braked", "a car which was coming from the
    lorry's right braked hard"), else 0. The clause is a subject relative ("which"/"who"/"that" with a
    verb of its own, or a verb's -ing form), and nothing that ends a clause or another verb stands
    between it and the reaction ("a taxi that the bus braked for" is the bus's braking)."""
    if k >= len(tokens):
        return 0
    if tokens[k] in ("which", "who", "that"):
        j = k + 1
        while j < len(tokens) and tokens[j] in BEFORE_VERB:
            j += 1
        if j == k + 1 or j >= len(tokens) or "VERB" not in lemmas(tokens[j]):
            return 0  # (an object relative, "that the bus braked for", or no verb of its own)
    elif tokens[k].isalpha() and reduced_relative(tokens[k]):
        j = k
    else:
        return 0
    for m in range(j + 1, min(len(tokens), j + 12)):
        if tokens[m - 1] not in DEFINITE | INDEFINITE and (v := verb_of_reacting(tokens, m)):
            return v  # (not a noun after its article: "pulling away from a stop")
        w = tokens[m]
        if w in _CLAUSE_ENDS or (w.isalpha() and set(lemmas(w)) <= {"VERB", "AUX"} and "VERB" in lemmas(w)):
            return 0  # (another clause, or a verb that is not a reaction: "hit it and a bus braked")
    return 0


def reduced_relative(word: str) -> bool:
    """Whether ``word`` opens a reduced relative clause, an aside said of the noun before it as "which
    was ..." would be: a verb's -ing form (", travelling at 25 mph,", ", proceeding on a green signal
    at about 40 mph,")."""
    return word.endswith("ing") and "VERB" in lemmas(word)


def _has_speed(tokens: list[str], p, nxt: int) -> bool:
    """A speed follows the mention in its sentence before anyone else is named, not one it changes to
    ("slows to 20 km/h")."""
    end = min(sentence_span(tokens, p.end)[1], nxt)
    aside = _past_aside(tokens, p.end, relative_only=True)
    if aside == p.end and tokens[p.end : p.end + 1] == [","]:
        return False  # (not its own: "a stopped truck, 80 km/h" in a terse line is the ego's speed)
    if aside != p.end:
        end = max(end, aside)
    return any(
        w in SPEED_UNITS and "to" not in tokens[max(p.end, k - 3) : k] for k, w in enumerate(tokens[:end]) if k >= p.end
    )


def _reacts(tokens: list[str], p, others: list[int], first: bool = False) -> bool:
    """The mention is the subject of a verb of reacting, past auxiliaries, adverbs and an aside; or,
    ``first`` in its sentence, of one its sentence joins on with "and"/"but" ("a bus entering the
    roundabout failed to see a cyclist and braked hard"). A reaction is to someone: another road
    user (starting at one of ``others``) is named before the verb ("The bus stops at a stop and a
    pedestrian walks out" is the bus's own stop, no reaction)."""
    return any(o < v for v in _verbs_of_reacting(tokens, p, first) for o in others)


def _verbs_of_reacting(tokens: list[str], p, first: bool = False) -> list[int]:
    """Where the verbs of reacting the mention is the subject of stand (see :func:`_reacts`): right
    after it, past auxiliaries, adverbs and an aside with commas or a relative clause without them;
    and, ``first`` in its sentence, one its sentence joins on with "and"/"but"."""
    at = []
    if first:
        end = sentence_span(tokens, p.end)[1]
        at = [v for k in range(p.end, end) if tokens[k] in ("and", "but") and (v := verb_of_reacting(tokens, k + 1))]
    aside = _past_aside(tokens, p.end)
    if v := verb_of_reacting(tokens, aside) or (aside == p.end and _past_bare_relative(tokens, p.end)):
        at.append(v)
    return at


def verb_of_reacting(tokens: list[str], k: int) -> int:
    """Where a verb of reacting stands at ``k``, past auxiliaries and adverbs, else 0."""
    for _ in range(4):
        if k >= len(tokens):
            return 0
        w = tokens[k]
        if w in BEFORE_VERB or (w.endswith("ly") and "ADV" in lemmas(w)):
            k += 1
            continue
        verbs = lemmas(w).get("VERB", ())
        said = any(x in REACTING for x in verbs) or _to_a_stop(tokens, k + 1)
        return k if verbs and (said or (PRESSING & set(verbs) and _the_brakes(tokens, k + 1))) else 0
    return 0


def _the_brakes(tokens: list[str], k: int) -> bool:
    """Whether what a verb of pressing says from ``k`` on is the brakes: "on" with its object left
    unsaid ("slammed on and missed him", "had to slam on."), or the brakes themselves past "on" and a
    determiner ("hit the brakes", "stomped on her brakes", "stood on everything"). A verb of pressing
    with anything else after it ("slammed into the kerb", "hit the cyclist", "stood on the verge") is
    no braking."""
    if tokens[k : k + 1] == ["on"]:
        k += 1
        if k >= len(tokens) or tokens[k] in _CLAUSE_ENDS:
            return True
    while k < len(tokens) and tokens[k] in DETERMINERS:
        k += 1
    return k < len(tokens) and tokens[k] in PRESSED


def _to_a_stop(tokens: list[str], k: int) -> bool:
    """Whether a verb of motion is said to end at ``k`` in a stop ("eased to a stop", "came to a
    standstill", "rolled to a dead halt"): it stops, whatever verb says how. A stop that names a
    thing after it ("up to a stop sign") is a place."""
    if tokens[k : k + 2] != ["to", "a"]:
        return False
    k += 2
    while k < len(tokens) and tokens[k] in WHOLE_STOP:
        k += 1
    if k >= len(tokens) or tokens[k] not in STOP_NOUNS:
        return False
    after = set(lemmas(tokens[k + 1])) if k + 1 < len(tokens) else set()
    return "NOUN" not in after or bool(after & {"ADJ", "ADV"})  # (no noun it names: "stop sign")


def _struck(tokens: list[str], p) -> bool:
    """The mention is the subject of a verb of contact in the passive ("the car, proceeding on a green
    signal, was struck by a lorry", "Dad's car got rear-ended", "the van was clipped"): another road
    user acted on it, and a report puts what it is about first, as the subject it tells of."""
    k, last_auxiliary = _past_aside(tokens, p.end), ""
    while k < len(tokens) and tokens[k] in BEFORE_PARTICIPLE:
        last_auxiliary = tokens[k] if tokens[k] != "just" else last_auxiliary
        k += 1
    if last_auxiliary not in PASSIVE_VOICE or k >= len(tokens) or tokens[k].endswith("ing"):
        return False  # ("had hit a cyclist": the perfect, active)
    head, _, last = tokens[k].rpartition("-")  # ("rear-ended": "rear-" and "ended")
    return any((f"{head}-{v}" if head else v) in CONTACT for v in lemmas(last).get("VERB", ()))


def _placed_by(tokens: list[str], p) -> bool:
    """Another road user is placed by this one: its path, front, lane ("into the path of the Toyota",
    "the van's lane", "from the Civic's right") or "towards" it."""
    before = tokens[p.start - 1] if p.start else ""
    if before in TOWARDS:
        return True
    if before == "of" and p.start >= 2 and tokens[p.start - 2] in OWN_SPACE:
        return True
    return tokens[p.end : p.end + 1] == ["'s"]


def _origin_of_another(tokens: list[str], p) -> bool:
    """The mention places another road user only as where that one came from or stopped: "from the
    SUV's right", "from the van's nearside", "just short of the bus's door" (a possessive right after
    "from" or "short of" and its article). That says which way the other approached, or how near it
    came, not that anyone got into this one's path, front or lane."""
    k = p.start - 1
    while k >= 0 and tokens[k] in DEFINITE:
        k -= 1
    if tokens[p.end : p.end + 1] != ["'s"] or k < 0:
        return False
    return tokens[k] == "from" or (tokens[k] == "of" and k >= 1 and tokens[k - 1] == "short")


def _reactor_among(tied: list[_Referent]) -> _Referent | None:
    """Of motor vehicles ``tied`` on evidence, the one the story happens to, where that can be told:
    the only one that reacts (brakes, stops, swerves) while each other is placed by only as where
    that one came from or stopped ("a taxi, approaching from the SUV's right, braked to a halt": the
    SUV is placed by, as the taxi's origin, and never as a path, front or lane) and has no speed,
    braking (any verb of reacting, "ran the red and braked") or blow of its own. A road user's
    approach named by another's side says nothing of whom the story is told from; a reaction to the
    one that crossed its way does. Else None: two that brake, a path, front or lane said of one, or
    a reaction by someone other than the one said to come from the side ("A taxi came from the SUV's
    right. A bus braked") stay a tie."""
    reacting = [r for r in tied if r.reacts]
    if len(reacting) != 1:
        return None
    reactor = reacting[0]
    others = [r for r in tied if r is not reactor]
    if all(
        r.placed_by
        and not r.placed_in_way
        and any(o is reactor for o in r.origin_of)
        and not (r.speed or r.brakes or r.struck)
        for r in others
    ):
        return reactor
    return None


def _placed_by_unsaid(tokens: list[str], p, nxt: int) -> bool:
    """The mention is placed by someone the text leaves unsaid: a word of place in it ("a lead van")
    or in its clause with no one after it ("brakes hard 20 m ahead", "is coming up behind")."""
    if any(w in PLACED for w in tokens[p.start : p.end]):
        return True
    end = min(sentence_span(tokens, p.end)[1], nxt)
    return any(tokens[k] in ("ahead", "behind") and not _preposition_with_object(tokens, k) for k in range(p.end, end))


def _preposition_with_object(tokens: list[str], k: int) -> bool:
    """Whether "ahead"/"behind" at ``k`` is a preposition whose object is said ("behind a bicyclist",
    "ahead of the van", "behind him"): it places by that one, not by someone left unsaid ("brakes
    hard 20 m ahead")."""
    nxt = tokens[k + 1 : k + 2]
    if nxt in (["of"], ["it"], ["him"], ["her"], ["them"]):
        return True
    if tokens[k] != "behind" or not nxt:
        return False
    return nxt[0] in DEFINITE or nxt[0] in INDEFINITE  # ("behind a bicyclist": an article opens its object)


def _referents(tokens: list[str], users, vehicles: frozenset[str]) -> tuple[list[_Referent], _Referent | None]:
    """The road users of ``users`` grouped by the referent they repeat, and the bare report's
    driver ("Driver braked", "the driver stopped") as its own referent (None when not said)."""
    out: list[_Referent] = []
    driver: _Referent | None = None
    for p in users:
        if tokens[p.end : p.end + 1] == [":"] or (tokens[p.end - 1] in AT_WHEEL and is_modifier_noun(tokens, p)):
            continue  # (a field's name, "Vehicle: Cab 22", or a modifier, "driver statement")
        words = [w for w in tokens[p.head : p.end] if w.isalpha()]
        last = tokens[p.end - 1]
        if last in AT_WHEEL and p.end - p.head == 1 and p.det in ("", "the") and p.kind in vehicles:
            if tokens[p.end : p.end + 1] == ["of"] or tokens[p.start - 1 : p.start] == ["'s"]:
                continue  # ("the driver of the Yaris", "the SUV's driver": the Yaris, the SUV, read at their own)
            driver = driver or _Referent("driver", known=True)
            driver.mentions.append(p)
            continue
        by_vehicle = last in AT_WHEEL  # ("the bus driver": the bus, whatever type "driver" gave the phrase)
        if by_vehicle and not _drives_vehicle(tokens, p, vehicles):
            if p.kind in vehicles:
                continue
            by_vehicle = False  # ("one e-scooter rider": a rider, someone the report's vehicle meets)
        if by_vehicle:
            words = words[:-1]
            last = words[-1]
        same = None
        if p.det not in INDEFINITE:
            same = next(
                (r for r in reversed(out) if (r.kind == p.kind or by_vehicle) and last in r.words),
                None,
            )
            if same is None:
                kin = [r for r in out if r.kind == p.kind]
                same = kin[0] if len(kin) == 1 and p.det in DEFINITE and p.end - p.head == 1 else None
        if same is None:
            same = _Referent(p.kind, known=p.det not in INDEFINITE)
            out.append(same)
        same.mentions.append(p)
        same.words.update(words)
    return out, driver


def _drives_vehicle(tokens: list[str], p, vehicles: frozenset[str]) -> bool:
    """The mention is a vehicle's driver named by the vehicle ("the bus driver", "our van driver"):
    what that driver does (braking, a speed) is the vehicle's, as "the bus braked" would say."""
    words = [w for w in tokens[p.head : p.end] if w.isalpha()]
    return p.kind in vehicles and tokens[p.end - 1] == "driver" and len(words) >= 2 and words[-2] not in AT_WHEEL


def _said_of(tokens: list[str], p, referents: list[_Referent]) -> _Referent | None:
    """The referent whose mention last comes before ``p`` in its sentence: the one a place said by
    ``p`` ("from the SUV's right") is said of ("a taxi approaching from the SUV's right")."""
    start = sentence_span(tokens, p.start)[0]
    before = [(q.start, o) for o in referents for q in o.mentions if start <= q.start and q.end <= p.start]
    return max(before, key=lambda x: x[0])[1] if before else None


def _evidence(tokens: list[str], users, r: _Referent, referents: list[_Referent]) -> None:
    """What the text says of ``r``: its speed, its reaction to another of ``referents``, whether
    another road user is placed by it (and, where only as the origin of one, which one)."""
    others = [q.start for o in referents if o is not r for q in o.mentions]
    for p in r.mentions:
        nxt = next((q.start for q in users if q.start >= p.end), len(tokens))
        of = p.start >= 2 and tokens[p.start - 1] == "of" and tokens[p.start - 2] == "driver"
        r.speed |= not _origin_of_another(tokens, p) and _has_speed(tokens, p, nxt)  # (not "from the SUV's left at 20")
        s = p.start
        while s > 0 and tokens[s - 1] not in (".", ";", "!", "?"):
            s -= 1
        first = not any(s <= q.start < p.start for q in users)
        r.reacts |= _reacts(tokens, p, others, first=first)
        r.brakes |= bool(_verbs_of_reacting(tokens, p, first=first))
        placed = not of and _placed_by(tokens, p)
        r.placed_by |= placed
        if placed and _origin_of_another(tokens, p):
            r.origin_of.append(_said_of(tokens, p, referents))
        else:
            r.placed_in_way |= placed
        r.struck |= not of and _struck(tokens, p)


def _narrator_only_watches(tokens: list[str]) -> bool:
    """The writer is in the text only as one who saw it ("just saw a lad on a scooter ...", "I watched
    a van clip a cyclist", "we'd just seen ...", "I was outside the shop"): every "I"/"we" is the
    subject of a verb of perceiving, or is outside, and nothing puts the writer in the traffic ("me",
    "my", "us", "our"). Such a writer is a witness, and the report is about a vehicle in it."""
    said = [k for k, w in enumerate(tokens) if w in FIRST_PERSON]
    if not said or NARRATOR_INVOLVED & set(tokens):
        return False
    if any(
        w in ("ahead", "behind", "front") and tokens[k + 1 : k + 2] not in (["of"], ["it"], ["him"], ["her"], ["them"])
        for k, w in enumerate(tokens)
    ):
        return False  # (someone placed by the writer, "the car in front": the writer is in the traffic)
    for k in said:
        j = k + 1
        while j < len(tokens) and (tokens[j] in BETWEEN or tokens[j] in ("'ve", "'m", "'re")):
            j += 1
        w = tokens[j] if j < len(tokens) else ""
        if not (w == "outside" or (w.isalpha() and "VERB" in lemmas(w) and lemma_in(w, PERCEIVE))):
            return False
    return True


def without_witness(tokens: list[str], dropped: list[str]) -> list[str]:
    """``tokens`` without the writer's "I"/"we" where the writer only watched (see
    :func:`_narrator_only_watches`): "I saw a lad run the red and the bus driver braked" is told as
    "saw a lad ...", a report about the bus, not a story of the writer's own driving."""
    if not _narrator_only_watches(tokens):
        return tokens
    dropped.extend(w for w in tokens if w in FIRST_PERSON)
    return [w for w in tokens if w not in FIRST_PERSON]


def frame(tokens: list[str], kind_at, known, dropped: list[str]) -> list[str]:
    """``tokens`` with the vehicle a third-person report is about said "the ego" (see the module's
    docstring), and its bare driver too; unchanged where no vehicle stands out."""
    if names_ego(tokens, kind_at, known):
        return tokens
    users = [p for p in road_users(tokens, kind_at, known) if p.kind != "ego"]
    referents, driver = _referents(tokens, users, VEHICLES)
    witnessed = bool(FIRST_PERSON & set(dropped))  # (a witness's "I" gone: see without_witness)
    for r in [*referents, *([driver] if driver else [])]:
        _evidence(tokens, users, r, referents)
        r.struck &= not witnessed  # ("I saw a car get hit by a bus": the witness rules read it)
    motor = [
        r
        for r in referents
        if r.kind in VEHICLES
        and any(is_singular(tokens[p.end - 1]) for p in r.mentions)
        and not any(
            placed_by_word(tokens, p)
            or _placed_by_unsaid(tokens, p, next((q.start for q in users if q.start >= p.end), len(tokens)))
            or stands_parked(tokens, p)
            for p in r.mentions
        )
    ]
    owner = None
    if driver is not None:
        home = [r for r in motor if r.known] or (motor if len(motor) == 1 else [])
        if len(home) == 1:  # (the driver of the report's own vehicle)
            owner = home[0]
            home[0].speed |= driver.speed
            home[0].reacts |= driver.reacts
            home[0].placed_by |= driver.placed_by
        else:
            motor.append(driver)
    if not motor:
        return tokens
    best = max(motor, key=lambda r: r.score)
    tied = [r for r in motor if r.score == best.score]
    if len(tied) > 1:  # (a tie, unless one reacts to another's approach)
        best = _reactor_among(tied)
        if best is None:
            return tokens
    if best.score < 1:
        return tokens
    first = min(p.start for p in best.mentions)
    if any((r.score, first) > (best.score, r.mentions[0].start) for r in referents if r.kind not in VEHICLES):
        return tokens  # (a walker or rider told about as much, and named first, is the one told from)
    if not (best.speed or best.reacts or best.struck):
        return tokens  # (only placed by: "in front of a car" is said of any road user the ego meets)
    if not any(r is not best for r in referents):
        return tokens  # (no one else to meet: "The lead car brakes" is met by an ego the text leaves unsaid)
    targets = list(best.mentions)
    if driver is not None and owner is best:
        targets += driver.mentions  # (its driver, merged into it above)
    out = list(tokens)
    for p in sorted(targets, key=lambda p: p.start, reverse=True):
        start = p.start
        if start >= 3 and out[start - 1] == "of" and out[start - 2] == "driver" and out[start - 3] == "the":
            start -= 3  # ("the driver of the Yaris": the Yaris)
        dropped.extend(w for w in out[start : p.end] if w.isalpha() and w not in ("the", "a", "an"))
        out[start : p.end] = ["the", "ego"]
    return out
