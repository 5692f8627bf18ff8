"""Which vehicle is the writer's own when the writer is in it or tests it.

A first-person writer names the vehicle they sit in as something both sides already know: "we
pointed the car at the dummy", "the van approaching at 40 km/h, and we stopped short", a heading
that introduces the writer ("Coach driver here.", "Bin lorry driver, early shift. I'm doing ..."),
a test rider the text makes the ego or calls ours ("Ego is a cyclist riding at 20 km/h", "our rider
on a hire bike"). Read as one more road user, that vehicle becomes an extra adversary that is
really the ego. :func:`frame` says it "the ego" (and every later "the <noun>" of it), the way
:func:`vei_scenario.language.ego.frame` does for an ego named by a role; the reader runs it
right after that (where the text names no ego otherwise, its rules find nothing to read).

It reads structure, not sentences: articles (a vehicle said with "the" and never introduced is
known to the writer), who is the subject or object of a clause, placement ("the van ahead" is
someone else's), whether a clause meets the narrator ("in front of me": someone else), and the
position of a heading. Its only word classes are small and closed: verbs of steering a vehicle and
the person-at-a-wheel nouns ("driver", "rider").
"""

from __future__ import annotations

from vei_scenario.language.discourse import DETERMINERS
from vei_scenario.language.ego import (
    AT_CONTROLS,
    AT_WHEEL,
    BE,
    BETWEEN,
    DEFINITE,
    FIRST_PERSON,
    INDEFINITE,
    PUNCT,
    SENTENCE_END,
    SPEED_UNITS,
    VEHICLES,
    KindAt,
    Known,
    as_ego,
    driver_is_ego,
    is_modifier_noun,
    kind_said_again,
    lemma_in,
    narrator_subject,
    placed_by_word,
    road_users,
    sentence_span,
)
from vei_scenario.language.ego_speed import impact_after_braking
from vei_scenario.language.lemmas import lemmas
from vei_scenario.language.lexicon import MOTOR_TWO_WHEELERS

#: First-person words that say someone meets the narrator ("in front of me", "my lane"): a vehicle
#: in such a clause is someone else's.
MEETS_NARRATOR = frozenset({"me", "us", "my", "our", "myself", "ourselves"})
#: Verbs whose object is the vehicle their subject steers (by lemma): what the narrator or the
#: narrator's system aims, points or stops is the narrator's vehicle.
STEERING = frozenset({"aim", "point", "steer", "drive", "park", "stop", "bring", "take", "put", "reverse", "pull"})
#: Words that end a clause before its subject.
CLAUSE_START = PUNCT | {"and", "but", "then", "while", "whilst", "when", "as", "-"}
#: Words of the narrator on foot or on a saddle: a vehicle the narrator has not named is then
#: someone else's ("I was cycling home when the van ...").
ON_FOOT = frozenset({"walk", "cycle", "jog", "run", "ride", "cross", "scoot", "push"})
#: Kinds of road user a person rides: a rider of one the text calls the ego or ours is the ego.
RIDERS = frozenset({"bicycle", "e-scooter"})
#: Prepositions that put someone inside a vehicle ("in the van", "aboard the bus").
INSIDE = frozenset({"in", "inside", "aboard"})
#: Third-person pronouns: someone else named before "in the <vehicle>" ("I saw him in the car").
OTHERS = frozenset({"he", "she", "they", "him", "her", "them", "someone", "somebody", "anyone"})
#: What a test puts in the ego's way: never the ego.
TEST_OBJECTS = frozenset({"target", "dummy", "gvt", "soft", "balloon"})


def _narrator_on_foot(tokens: list[str], kind_at: KindAt) -> bool:
    """Whether the narrator walks or rides ("I was cycling", "we walked", "on my bike")."""
    for k, w in enumerate(tokens):
        if w in ("my", "our") and k + 1 < len(tokens):
            found = kind_at(tokens, k + 1)
            if found is not None and found[0] in RIDERS:
                return True  # ("on my bike", "my scooter"; not "my kids")
        if w not in FIRST_PERSON:
            continue
        j = k + 1
        while j < len(tokens) and tokens[j] in BETWEEN:
            j += 1
        if j < len(tokens) and lemma_in(tokens[j], ON_FOOT):
            return True
    return False


def _clause_start(tokens: list[str], i: int) -> bool:
    """Whether the phrase at ``i`` opens its clause (the subject of what follows)."""
    return i == 0 or tokens[i - 1] in CLAUSE_START | SENTENCE_END


def _clause(tokens: list[str], i: int) -> tuple[int, int]:
    """The clause around ``i``: from the last clause boundary before it to the end of its sentence
    (what the clause's subject does, and to whom, runs to there)."""
    s, e = sentence_span(tokens, i)
    b = next((k + 1 for k in range(i - 1, s - 1, -1) if tokens[k] in CLAUSE_START), s)
    return b, e


def _steered(tokens: list[str], p) -> bool:
    """Whether ``p`` is the object of a verb of steering said by the narrator or with no subject
    ("we aimed the car at", "pointed the van at", "the system stopped the car dead")."""
    if not p.start:
        return False
    verb = tokens[p.start - 1]
    return verb.isalpha() and "VERB" in lemmas(verb) and lemma_in(verb, STEERING)


def _own_speed(tokens: list[str], p, users) -> bool:
    """Whether a speed follows ``p`` in its clause before anyone else is named ("the van approaching
    at 40 km/h")."""
    _, e = sentence_span(tokens, p.end)
    e = next((k for k in range(p.end, e) if tokens[k] in PUNCT or tokens[k] in ("and", "but")), e)
    nxt = min((q.start for q in users if q.start >= p.end), default=e)
    return any(w in SPEED_UNITS for w in tokens[p.end : min(e, nxt)])


def narrator_speed(tokens: list[str], users) -> bool:
    """Whether the narrator has a speed of their own in ``tokens`` ("we were doing 40 km/h", "us at
    15 km/h"): a vehicle with a speed of its own beside it is someone else ("I was at 30 when the van
    doing 50 ...", "the coach was doing 40 when it pulled in; we were at 70")."""
    for k, w in enumerate(tokens):
        if w in FIRST_PERSON | {"us"}:
            s, e = sentence_span(tokens, k)
            e = next((q.start for q in users if k < q.start < e), e)
            if any(tokens[u] in SPEED_UNITS and not impact_after_braking(tokens, u - 1) for u in range(k, e)):
                return True  # (not the speed the narrator hits something at: "we struck it at 12 mph")
    return False


def _label(tokens: list[str], q) -> bool:
    """Whether ``q`` is a bare noun with a number, a call sign ("appliance 2", "unit 7"): no one new."""
    return not q.det and tokens[q.end : q.end + 1] != [] and tokens[q.end].isdigit()


def _unintroduced(tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """A vehicle a first-person text says with "the" and never introduces is the narrator's own
    when the text shows it is ("We pointed the car at a dummy", "the van approaching at 40 km/h,
    and we stopped"): the object of a verb of steering, or the subject of its clause with a speed
    of its own where the narrator has none. One placed relative to someone ("the van ahead"), of a
    kind introduced before ("a hatchback ... the car"), a test's target, a numbered bus, or one in a
    clause that meets the narrator ("the van pulled out in front of me") is someone else; so is
    every vehicle where the narrator walks or rides."""
    words = set(tokens)
    first_person = bool(FIRST_PERSON & words or {"us", "our"} & words)
    if not (first_person or _log(tokens)) or "ego" in words:
        return tokens
    if _narrator_on_foot(tokens, kind_at):
        return tokens
    users = road_users(tokens, kind_at, known)
    if any(p.det in ("my", "our") and p.kind in VEHICLES for p in users):
        return tokens  # (the narrator's vehicle is named as theirs)
    for n, p in enumerate(users):
        if p.kind not in VEHICLES or p.det != "the" or placed_by_word(tokens, p) or is_modifier_noun(tokens, p):
            continue
        said = tokens[p.start : p.end + 1]
        if any(w in TEST_OBJECTS or w.isdigit() or w in ("number", "other") for w in said):
            continue
        if tokens[p.end : p.end + 1] == ["'s"] or any(q.kind == p.kind and not _label(tokens, q) for q in users[:n]):
            continue  # (an owner's, or one of a kind named before: "a hatchback ... the car")
        b, e = _clause(tokens, p.start)
        steered = _steered(tokens, p)  # (what the narrator steers may well go at "our lane")
        if not first_person:  # (a log's "brought the tram to a stop": the writer's, where no one else steers)
            if not (steered and _steered_unsaid(tokens, p, users)):
                continue
        subject = _clause_start(tokens, p.start) and _own_speed(tokens, p, users)
        subject = subject and not MEETS_NARRATOR & set(tokens[b:e]) and not narrator_speed(tokens, users)
        landmark = tokens[max(p.start - 2, 0) : p.start] in (["front", "of"], ["ahead", "of"], ["path", "of"])
        # (what someone crosses in front of is where the writer is; what shakes is what the writer feels)
        if not (steered or subject or landmark or _shaken(tokens, p) or _acts_by_itself(tokens, p, users[n:])):
            continue
        noun = tokens[p.end - 1]
        dropped.extend(w for w in tokens[p.start : p.end] if w not in DEFINITE)
        out = as_ego([*tokens[: p.start], "the", "ego", *tokens[p.end :]], kind_at, known, noun, dropped)
        out = _kind_again(out, p.kind, kind_at, known, dropped)
        return driver_is_ego(out, kind_at, known, dropped) if {"we", "us", "our"} & words else out
    return tokens


#: Words that end a clause a vehicle acts "by itself" in ("the car braked by itself and ...").
_CLAUSE_END = PUNCT | {"and", "but", "then", "when", "while", "so"}
#: Phrases that say a vehicle did something with no one doing it ("braked by itself", "stopped on its
#: own", "steered automatically"): its own automation, which only the writer of its own car tells.
BY_ITSELF = (("by", "itself"), ("on", "its", "own"), ("of", "its", "own", "accord"), ("automatically",))


def _acts_by_itself(tokens: list[str], p, later) -> bool:
    """Whether the vehicle ``p``, or a later "the" mention of its kind (the make first, then "the
    car"), opens its clause and does something by itself there ("the car just braked by itself",
    "the van stopped on its own", "the Tesla steered automatically"): a first-person writer tells
    that of the car they sit in. One of a kind introduced anywhere ("a car") is someone else's."""
    if any(q.kind == p.kind and q.det in INDEFINITE for q in later):
        return False
    for q in later:
        if q.kind != p.kind or q.det != "the" or placed_by_word(tokens, q) or not _clause_start(tokens, q.start):
            continue
        e = next((k for k in range(q.end, len(tokens)) if tokens[k] in _CLAUSE_END), len(tokens))
        clause = tokens[q.end : e]
        if any(tuple(clause[k : k + len(b)]) == b for b in BY_ITSELF for k in range(len(clause))):
            return True
    return False


#: Verbs (by lemma) of a vehicle shaken by what passes it or by the wind: what the writer feels of the
#: vehicle they sit in ("the whole car shook", "the van rocked in its wake").
SHAKEN = frozenset({"shake", "wobble", "rock", "shudder", "sway", "judder", "lurch", "buffet", "vibrate", "jolt",
                    "tremble", "rattle", "bounce"})  # fmt: skip
#: Hedges and adverbs between such a vehicle and its verb ("the car sort of wobbled", "the van really shook").
_HEDGES = frozenset({"sort", "kind", "of", "just", "really", "actually", "literally", "a", "bit", "little"})


def _shaken(tokens: list[str], p) -> bool:
    """Whether ``p`` opens its clause and its verb, past hedges, is one of being shaken (:data:`SHAKEN`):
    "and the whole car sort of wobbled", "the van rocked in its wake"."""
    if not _clause_start(tokens, p.start):
        return False
    k = p.end
    while k < min(p.end + 3, len(tokens)) and (tokens[k] in _HEDGES or tokens[k].endswith("ly")):
        k += 1
    return k < len(tokens) and "VERB" in lemmas(tokens[k]) and lemma_in(tokens[k], SHAKEN)


def _subjectless(tokens: list[str], s: int) -> bool:
    """Whether the sentence starting at ``s`` opens with a verb, its subject left unsaid as a log, a
    diary or a spoken note leaves out "I" ("Braked hard and ...", "Departing the stop at 15 km/h")."""
    w = tokens[s] if s < len(tokens) else ""
    pos = lemmas(w)
    return w.isalpha() and "VERB" in pos and not {"NOUN", "PROPN", "ADJ", "ADV"} & set(pos)


def _log(tokens: list[str]) -> bool:
    """Whether some sentence of ``tokens`` leaves its subject unsaid (:func:`_subjectless`): a writer
    who never says "I" but writes as the one at the wheel."""
    return any(_subjectless(tokens, k) for k in range(len(tokens)) if k == 0 or tokens[k - 1] in SENTENCE_END)


def _steered_unsaid(tokens: list[str], p, users) -> bool:
    """Whether the verb of steering before ``p`` is said with no subject: its sentence opens with a
    verb and no one who could be at a wheel (a vehicle, its driver) is named between ("Sounded the
    horn and stopped the bus", "Slowed as a kid ran out, pulled the lorry over"; not "a bus pulled
    out and its driver stopped the bus")."""
    s, _ = sentence_span(tokens, p.start)
    if not _subjectless(tokens, s):
        return False
    between = [q for q in users if s <= q.start < p.start - 1]
    return not any(q.kind in VEHICLES or tokens[q.end - 1] in AT_WHEEL for q in between)


def _kind_again(tokens: list[str], kind: str, kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """ "We brought the saloon up to 50 km/h and pointed the car at ...": once the narrator's vehicle
    is the ego, a later "the <noun>" of its kind is it again, until a vehicle of that kind is
    introduced ("a car")."""
    for q in road_users(tokens, kind_at, known):
        if q.kind == kind and q.det in INDEFINITE:
            return tokens
        if q.kind == kind and q.det == "the" and not placed_by_word(tokens, q) and not is_modifier_noun(tokens, q):
            out = as_ego(tokens, kind_at, known, tokens[q.end - 1], dropped)
            return tokens if out == tokens else _kind_again(out, kind, kind_at, known, dropped)
    return tokens


def _verb_of_its_own(word: str) -> bool:
    """Whether ``word`` can only be a verb, or is a form of "be": a phrase that reaches one has a
    predicate of its own, so it is no heading or role of the narrator's ("Van, no lights, came at me")."""
    pos = set(lemmas(word))
    return word.isalpha() and ("VERB" in pos and not pos & {"NOUN", "ADJ"} or word in BE)


def _heading(tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """ "Coach driver here. Cruising at 60 mph ...", "Courier van, dual carriageway, I'm in the left
    lane ...": a text that opens with a bare vehicle (or its driver) standing alone, as a heading
    ("here", or a comma or full stop with no verb of its own after it), and tells its story in the
    first person, introduces the writer by it: that vehicle is the ego, and so is every later
    "the <noun>". "Van, no lights, came straight at me" (a verb follows) is a road user."""
    if not (FIRST_PERSON | MEETS_NARRATOR) & set(tokens) or "ego" in tokens:
        return tokens
    chain = []  # (the nouns of the heading back to back: "courier van", "tanker driver")
    for q in road_users(tokens, kind_at, known):
        if q.start != (chain[-1].end if chain else 0) or q.det:
            break
        chain.append(q)
    vehicles = [q for q in chain if q.kind in VEHICLES]
    if not vehicles or any(q.kind not in VEHICLES | {"pedestrian"} for q in chain):
        return tokens
    end, noun = chain[-1].end, tokens[vehicles[-1].end - 1]
    here = tokens[end : end + 1] == ["here"]
    if not here and tokens[end : end + 1] not in ([","], ["."], [":"], ["-"]):
        return tokens
    if not here:  # (no verb of its own before the narrator speaks: "Van, no lights, came at me")
        _, e = sentence_span(tokens, end)
        stop = next((k for k in range(end, e) if tokens[k] in FIRST_PERSON), e)
        if any(_verb_of_its_own(tokens[k]) for k in range(end + 1, stop)):
            return tokens
    cut = end + here
    dropped.extend(w for w in tokens[:cut] if w.isalpha())
    out = tokens[cut:]
    while out and out[0] in PUNCT:
        out = out[1:]
    return as_ego(out, kind_at, known, noun, dropped)


#: Words that join the two parties of a pair label ("car vs scooter", "car-to-pedestrian").
PAIRED = frozenset({"vs", "versus", "v", "to"})


def _pair_label(tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """ "CAR vs SCOOTER, dashcam. Doing 35 km/h when the scooter drifts into my lane", "Van v cyclist
    (helmet cam): ...": a first sentence that opens with a pair label, two bare road users joined by
    "vs" or "to", names the two parties; where the story is told from a seat in the first of them (a
    motor vehicle, first-person words, the narrator not on foot or on a saddle) that vehicle is the
    writer's own, the ego, and so is every later "the <noun>" of it. A label whose vehicle the text
    then introduces ("a car hit a boy") or whose two parties are of one kind is left as it is."""
    if not (FIRST_PERSON | MEETS_NARRATOR) & set(tokens) or "ego" in tokens or _narrator_on_foot(tokens, kind_at):
        return tokens
    users = road_users(tokens, kind_at, known)
    if len(users) < 2:
        return tokens
    p, q = users[0], users[1]
    label = p.start == 0 and not p.det and not q.det and tokens[p.end : q.start] in [[w] for w in PAIRED]
    _, e = sentence_span(tokens, 0)
    if not label or p.kind not in VEHICLES or q.kind == p.kind or q.end > e:
        return tokens
    if any(r.kind == p.kind and r.det in INDEFINITE for r in users[2:]):
        return tokens
    noun = tokens[p.end - 1]
    dropped.extend(tokens[p.start : p.end])
    out = [*tokens[: p.start], "the", "ego", *tokens[p.end :]]
    return kind_said_again(as_ego(out, kind_at, known, noun, dropped), p.kind, kind_at, known, dropped)


def _ego_rider(tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """ "Ego is a cyclist riding at 20 km/h", "the ego is a shared e-scooter rider", "Our rider on a
    hire bike", "rider on our Gen-3 scooter": a rider the text says is the ego or calls ours is the
    ego, not a bicycle or e-scooter besides it; so is every later "the rider" ("the cyclist").
    "The ego is a car length behind a cyclist" says where the ego is, not what."""
    users = road_users(tokens, kind_at, known)
    for k in range(len(tokens) - 2):
        found = kind_at(tokens, k)
        cut = None  # (start, end, what is said instead, the noun it is said again by)
        if found is not None and found[0] == "ego" and tokens[k] not in ("i", "we", "me", "us"):
            j = k + found[1]
            q = next((q for q in users if j + 2 <= q.head <= j + 5), None)
            if tokens[j : j + 1] and tokens[j] in BE and tokens[j + 1] in ("a", "an") and q is not None:
                if q.kind in RIDERS and q.start <= j + 2 and not placed_by_word(tokens, q):
                    cut = (j, q.end, [], tokens[q.end - 1])
        elif tokens[k] in ("our", "my") and tokens[k + 1] in AT_WHEEL and tokens[k + 2] == "on":
            q = next((q for q in users if q.start == k + 3), None)
            if q is not None and q.kind in RIDERS:
                cut = (k, q.end, ["the", "ego"], tokens[k + 1])  # ("our rider on a hire bike")
        elif tokens[k] in AT_WHEEL and tokens[k + 1] == "on" and tokens[k + 2] in ("our", "my"):
            q = next((q for q in users if k + 2 <= q.start <= k + 5 and not PUNCT & set(tokens[k : q.start])), None)
            if q is not None and q.kind in RIDERS:
                start = k - (k > 0 and tokens[k - 1] in DEFINITE | INDEFINITE)
                cut = (start, q.end, ["the", "ego"], tokens[k])  # ("rider on our prototype e-scooter")
        if cut is None:
            continue
        a, b, said, rider = cut
        dropped.extend(w for w in tokens[a:b] if w.isalpha() and w not in INDEFINITE | DEFINITE | {"our", "my"})
        return _riders_as_ego([*tokens[:a], *said, *tokens[b:]], rider)
    return tokens


def _riders_as_ego(tokens: list[str], rider: str) -> list[str]:
    """``tokens`` with every "the <rider>" said "the ego" (and a bare one opening a clause)."""
    out: list[str] = []
    for i, w in enumerate(tokens):
        if w == rider and out and out[-1] == "the":
            out[-1:] = ["the", "ego"]
            continue
        if w == rider and (not i or tokens[i - 1] in CLAUSE_START | SENTENCE_END):
            out += ["the", "ego"]
            continue
        out.append(w)
    return out


def _driven_it(tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """ "Got a scooter from the rack and was riding it at 15 km/h", "I'd hired a van. I was driving
    it ...": what "it" stands for after a verb of driving or riding said by the narrator is the last
    vehicle named before it (not placed relative to someone): the narrator's, the ego; so is every
    later "the <noun>" of it."""
    users = road_users(tokens, kind_at, known)
    for k in range(1, len(tokens)):
        if tokens[k] != "it" or not lemma_in(tokens[k - 1], AT_CONTROLS) or "VERB" not in lemmas(tokens[k - 1]):
            continue
        verb = k - 1
        p = next((q for q in reversed(users) if q.end <= verb), None)
        s = sentence_span(tokens, verb)[0]  # (or a diary's sentence with no subject: "Got a scooter and was riding it")
        opens = tokens[s].isalpha() and "VERB" in lemmas(tokens[s]) and not {"NOUN", "PROPN"} & set(lemmas(tokens[s]))
        subjectless = opens and not any(s <= q.start < verb and q is not p for q in users)
        told = narrator_subject(tokens, verb) or subjectless
        if not told or p is None or p.kind not in VEHICLES | RIDERS or placed_by_word(tokens, p):
            continue
        if sentence_span(tokens, p.start)[0] < sentence_span(tokens, sentence_span(tokens, verb)[0] - 1)[0]:
            continue  # (named two sentences before or more: "it" may be anything since)
        noun = tokens[p.end - 1]
        dropped.extend(w for w in tokens[p.start : p.end] if w not in DEFINITE | INDEFINITE)
        out = [*tokens[: p.start], "the", "ego", *tokens[p.end : k], *tokens[k + 1 :]]
        return _riders_as_ego(out, noun)
    return tokens


#: Verbs (by lemma) a writer says of the vehicle they steer, its article left out ("I stop car", "we
#: slowed van right down"): the verbs of steering and slowing.
STEERED_BARE = STEERING | {"slow", "halt"}


def _steered_bare(tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """ "I stop car let him go past", "I stopped vehicle immediately", "we slowed van right down": a
    writer who leaves out articles (as many Englishes do) says the vehicle they steer bare, right
    after their verb; that vehicle is theirs, the ego. It goes (the verb stays, the narrator's), and
    so does every later "the <noun>" of it. Said of someone else ("the man stopped car") or with an
    article ("I stopped a car") it is no business of this rule."""
    for k, w in enumerate(tokens[:-1]):
        if not w.isalpha() or "VERB" not in lemmas(w) or not lemma_in(w, STEERED_BARE):
            continue
        if not narrator_subject(tokens, k):
            continue
        found = kind_at(tokens, k + 1)
        noun = tokens[k + 1]
        if found is None or found[0] not in VEHICLES or found[1] != 1 or noun not in lemmas(noun).get("NOUN", ()):
            continue  # (one noun, in the singular: "I stopped cars" is no vehicle of the writer's)
        nxt = tokens[k + 2] if k + 2 < len(tokens) else ""
        if nxt.isalpha() and set(lemmas(nxt)) == {"NOUN"}:
            continue  # (a modifier: "I stopped car park traffic")
        dropped.append(noun)
        return as_ego([*tokens[: k + 1], *tokens[k + 2 :]], kind_at, known, noun, dropped)
    return tokens


def _aboard(tokens: list[str], p) -> bool:
    """Whether the preposition before ``p`` puts someone in or on it: "in"/"inside"/"aboard" any
    vehicle, "on" only a motor two-wheeler ("on the moped"; "on the car" is on its roof)."""
    prep = tokens[p.start - 1] if p.start else ""
    named = " ".join(tokens[p.head : p.end])
    return prep in INSIDE or (prep == "on" and (named in MOTOR_TWO_WHEELERS or tokens[p.end - 1] in MOTOR_TWO_WHEELERS))


def _narrator_aboard(tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """ "On shift in the car at 7am, a jogger ran out", "I do the run most weekends, usually in the old
    estate", "Commuting is scary on the moped": in a first-person text, a vehicle said with "the" (never
    introduced with "a" before) that a preposition puts someone in, where no one but the narrator is
    named before it in its sentence (past the narrator's own people: "my kids"), is the vehicle the
    narrator is in, the ego; so is every later "the <noun>". "A woman in the van", "I saw him in the
    car", "the car in front", "the van's mirror" and a narrator on foot are someone else's."""
    if not (FIRST_PERSON | MEETS_NARRATOR) & set(tokens) or "ego" in tokens or _narrator_on_foot(tokens, kind_at):
        return tokens
    users = road_users(tokens, kind_at, known)
    for n, p in enumerate(users):
        if p.kind not in VEHICLES or p.det != "the" or not _aboard(tokens, p) or placed_by_word(tokens, p):
            continue
        relative = tokens[p.end : p.end + 1] in (["which"], ["that"], ["where"])  # (no compound: "the camry which")
        if is_modifier_noun(tokens, p) and not relative or tokens[p.end : p.end + 1] == ["'s"]:
            continue  # ("in the car park", "in the van's mirror")
        if any(q.kind == p.kind and q.det in INDEFINITE for q in users[:n]):
            continue  # (introduced before: "a taxi stopped ... in the taxi")
        s, _ = sentence_span(tokens, p.start)
        before = [q for q in users[:n] if q.start >= s]
        if any(q.kind != "ego" and not (tokens[q.start] in ("my", "our") and q.kind not in VEHICLES) for q in before):
            continue  # (someone else is in it: "a woman in the van")
        if OTHERS & set(tokens[s : p.start]):
            continue
        noun = tokens[p.end - 1]
        dropped.extend(w for w in tokens[p.start - 1 : p.end] if w not in DEFINITE)
        out = [*tokens[: p.start - 1], *tokens[p.end :]]
        return kind_said_again(as_ego(out, kind_at, known, noun, dropped), p.kind, kind_at, known, dropped)
    return tokens


def _narrator_after_role(tokens: list[str], end: int) -> int | None:
    """Where "I" or "we", the subject of the main clause, follows a role "as a <road user>" ending at
    ``end``, or None. The role is set off by a comma ("As a driver who has done this for years, I ...")
    or, as people also write it, by nothing ("As a taxi driver I see ...", "As a bus driver of twenty
    years I would ask ..."); then no verb of its own may come between, or the "as" clause has a
    predicate and is no role: "As a van pulled out I braked" (the van's act, "as" is "while")."""
    _, e = sentence_span(tokens, end)
    comma = next((j for j in range(end, e) if tokens[j] == ","), None)
    if comma is not None and tokens[comma + 1 : comma + 2] in (["i"], ["we"]):
        return comma + 1
    relative = False  # (after "who"/"that" a verb is the relative clause's: "As a cyclist who rides daily I")
    for j in range(end, comma if comma is not None else e):
        if tokens[j] in ("i", "we"):
            return j
        relative = relative or tokens[j] in ("who", "that")
        if _verb_of_its_own(tokens[j]) or not relative and _verb_after_a_phrase(tokens, j):
            return None
    return None


#: Words that open a noun phrase in a role's phrase ("in a hurry", "on his phone", "of twenty years").
_PHRASE_OPENERS = DETERMINERS | {"on", "in", "at", "with", "of"}


def _verb_after_a_phrase(tokens: list[str], j: int) -> bool:
    """Whether ``tokens[j]``, a word that may be a verb or a noun ("cut", "cuts"), is a verb after the
    phrase a role goes on with ("As a taxi driver in a hurry cut in I braked"): not the noun that
    heads a phrase opened before it ("in a hurry", "on his phone") nor the last noun before "I" ("on
    the school run I"), nor a participle ("pulling away")."""
    word = tokens[j]
    if not word.isalpha() or word.endswith("ing") or "VERB" not in lemmas(word):
        return False
    return tokens[j - 1] not in _PHRASE_OPENERS and tokens[j + 1 : j + 2] not in (["i"], ["we"])


#: At most this many words of a name between a role's vehicle and its driver ("a Bus Eireann driver").
_ROLE_NAME_WORDS = 2


def _role_end(tokens: list[str], p, users, kind_at: KindAt) -> int:
    """Where the role "a <vehicle> ... driver" whose first road-user phrase is ``p`` ends: past a person
    at the wheel ("driver", "rider") that follows it with only words of a name the reader has no phrase
    for between ("a Bus Eireann driver", "a Dublin Bus driver": an operator's name), else where ``p``
    ends. The driver and the vehicle are one role, the narrator's."""
    at_wheel = next((q for q in users if p.end < q.start <= p.end + _ROLE_NAME_WORDS), None)
    if at_wheel is None or tokens[at_wheel.head : at_wheel.end] not in ([w] for w in AT_WHEEL):
        return p.end
    between = range(p.end, at_wheel.start)
    return at_wheel.end if all(tokens[j].isalpha() and kind_at(tokens, j) is None for j in between) else p.end


def _user_story(tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """ "As a driver travelling at 50 km/h, I want ...", "As a bus driver pulling away from a stop,
    we need ...", "As a taxi driver of ten years I ...": a clause that opens with "as a <road user>"
    and no verb of its own (a participle, a phrase of its own or a comma follows), before a main clause
    whose subject is "I" or "we" (:func:`_narrator_after_role`), names the narrator by a role:
    that road user is the ego, its speed the ego's, and the vehicle the role names (a driver's car)
    is the ego again later ("I want the van to slow down"). "As a van pulled out, I braked" ("as" is
    "while": the van has a verb of its own) is someone else."""
    users = road_users(tokens, kind_at, known)
    for p in users:
        k = p.start - 1
        if k < 0 or tokens[k] != "as" or p.det not in ("a", "an") or (k and tokens[k - 1] not in CLAUSE_START):
            continue
        end = _role_end(tokens, p, users, kind_at)
        nxt = tokens[end] if end < len(tokens) else ""
        participle = nxt.endswith("ing") and "VERB" in lemmas(nxt)
        if not (participle or nxt in PUNCT or nxt in ("who", "on", "in", "at", "with", "of", "i", "we")):
            continue
        subject = _narrator_after_role(tokens, end)
        if subject is None:
            continue
        if any(q.start < subject and q.start >= end and q.kind != "ego" for q in users):
            continue  # (someone else named in the role's clause: "As a driver behind a bus, ...")
        kind = next(
            (kind_at(tokens, j)[0] for j in range(p.start, end) if (kind_at(tokens, j) or ("",))[0] in VEHICLES),
            None,
        )
        if kind is None or tokens[p.head : end] == ["driver"]:
            kind = "car" if p.kind in VEHICLES or (participle and lemma_in(nxt, frozenset({"drive"}))) else kind
        dropped.extend(w for w in tokens[k:end] if w not in INDEFINITE)
        out = [*tokens[:k], "the", "ego", *tokens[end:]]
        return out if kind is None else kind_said_again(out, kind, kind_at, known, dropped)
    return tokens


def frame(tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """``tokens`` with the writer's own vehicle said "the ego" where the writer is in it or tests it
    (see the module's docstring); the words that only named it are added to ``dropped``."""
    tokens = _ego_rider(tokens, kind_at, known, dropped)
    tokens = _user_story(tokens, kind_at, known, dropped)
    tokens = _driven_it(tokens, kind_at, known, dropped)
    tokens = _steered_bare(tokens, kind_at, known, dropped)
    tokens = _heading(_pair_label(tokens, kind_at, known, dropped), kind_at, known, dropped)
    tokens = _narrator_aboard(tokens, kind_at, known, dropped)
    return _unintroduced(tokens, kind_at, known, dropped)
