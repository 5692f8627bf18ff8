"""The bicycle or e-scooter the narrator rides: the ego's own, no road user.

"I was on one of your e-scooters doing 20 km/h", "Took an e-scooter home from the station", "we were
on hire bikes", "I grabbed a Lime outside the station", "complaint about scooter 4471: I was riding it
when ...": a writer who rides names the bicycle or e-scooter under them like any other; read as one
more road user, it becomes an extra adversary that is really the ego.

It is told apart by what the reading holds: a road user of a kind a person rides (a bicycle, an
e-scooter) whose first mention is where the narrator is on it, takes it, or rides "it". Guards, each
with its reason:

- the narrator is the subject ("I", "we", or a diary's sentence with no subject): "a lad on a
  scooter" and "my son on his scooter" are someone else on it;
- nothing places it ("a scooter on my left", "came up behind", "ahead"): one placed relative to the
  narrator is beside them, not under them;
- no one watches it ("saw a cyclist"): a rider watched is seen from outside;
- it is not one of a group ("two lads on bikes"): the narrator rides one vehicle.
"""

from __future__ import annotations

from vei_scenario.language import discourse
from vei_scenario.language.ego import BETWEEN, FIRST_PERSON, HABIT, SENTENCE_END, KindAt, lemma_in, rider_noun
from vei_scenario.language.ego_double import take_as_ego, without_road_user
from vei_scenario.language.lemmas import lemmas
from vei_scenario.language.reading import Reading

#: Kinds of road user a person rides.
RIDDEN = frozenset({"bicycle", "e-scooter"})
#: Words between a verb or "on" and the vehicle it takes ("on one of your", "a hire"): articles,
#: owners and the modifiers that say whose or what kind of ride it is.
_BEFORE_NOUN = frozenset({"a", "an", "the", "one", "of", "my", "our", "your", "this", "that", "some", "own"}) | {
    "hire",
    "hired",
    "rental",
    "rented",
    "shared",
    "share",
    "electric",
    "push",
    "pedal",
    "new",
    "old",
}
#: Verbs (by lemma) whose object is the vehicle their subject rides or has for the ride.
_TAKING = frozenset({"ride", "take", "hire", "rent", "borrow", "grab", "unlock", "use", "book", "get"})
#: Words that open a clause: the subject of what follows comes after them.
_CLAUSE_OPEN = SENTENCE_END | {",", "and", "but", "then", "so"}


def _narrators(tokens: list[str], k: int) -> bool:
    """Whether the word at ``k`` (a verb or "on") is said of the narrator: "I", "we" or a narrator's
    auxiliary before it ("I was on", "we'd hired"), or it opens a sentence or clause with no subject
    ("Took an e-scooter home", "and was on a hire bike")."""
    f = k - 1
    while f >= 0 and (tokens[f] in BETWEEN or tokens[f] in HABIT):
        f -= 1
    return f < 0 or tokens[f] in FIRST_PERSON | _CLAUSE_OPEN


def _before(tokens: list[str], start: int) -> int:
    """The index of the word right before a mention that starts at ``start``, past its article, its
    owner and "one of" ("on one of your e-scooters": "on"); -1 where there is none."""
    j = start - 1
    while j >= 0 and tokens[j] in _BEFORE_NOUN:
        j -= 1
    return j


def _mentions(tokens: list[str], a, alone: bool, kind_at: KindAt) -> list[tuple[int, int]]:
    """Where road user ``a`` is named (start, end): its first mention and, where it is the only road
    user of its kind (``alone``), every phrase of its kind ("Scooter died mid-junction. I was on one
    of your e-scooters": the same scooter)."""
    spans = [(a.named_end - len(a.word.split()), a.named_end)]
    for i in range(len(tokens)) if alone else ():
        found = kind_at(tokens, i)
        if found is not None and found[0] == a.kind:
            spans.append((i, i + found[1]))
    return spans


def _ridden_it(tokens: list[str], a, others: list) -> bool:
    """Whether the narrator rides "it" in the next sentence or the same one ("... scooter 4471. I was
    riding it"), with no road user named between ``a`` and it (``others``: the other road users)."""
    end = next((k for k in range(a.named_end, len(tokens)) if tokens[k] in SENTENCE_END), len(tokens))
    end = next((k for k in range(end + 1, len(tokens)) if tokens[k] in SENTENCE_END), len(tokens))
    for k in range(a.named_end + 1, end):
        if tokens[k] != "it" or not lemma_in(tokens[k - 1], frozenset({"ride"})) or not _narrators(tokens, k - 1):
            continue
        return not any(a.named_end < o.named_end <= k for o in others)
    return False


def _rides_here(tokens: list[str], start: int) -> bool:
    """Whether the mention that starts at ``start`` is the narrator on it or taking it ("I was on one
    of your e-scooters", "Took an e-scooter home", "I grabbed a Lime")."""
    j = _before(tokens, start)
    if j >= 1 and tokens[j] == "on" and tokens[j - 1] not in _CLAUSE_OPEN:
        return _narrators(tokens, j)  # (not an opening "On a scooter, a lad ...": someone else on it)
    verb = tokens[j] if j >= 0 else ""
    return verb.isalpha() and "VERB" in lemmas(verb) and lemma_in(verb, _TAKING) and _narrators(tokens, j)


#: Verbs (by lemma) of the narrator riding with no object said: the ride is the narrator's own.
_RIDING = frozenset({"ride", "cycle", "scoot", "pedal", "bike"})
#: Prepositions between a verb and the ride it is done to ("came off the bike", "fell from the scooter").
_OFF = frozenset({"off", "from", "over", "onto", "on"})


def _narrator_rides(tokens: list[str]) -> bool:
    """Whether the narrator rides in ``tokens`` ("I was cycling home", "riding down the hill", a ride
    the reader has already made the ego: "on my moped", said "on ego")."""
    if any(tokens[k : k + 2] == ["on", "ego"] for k in range(len(tokens) - 1)):
        return True
    return any(lemma_in(w, _RIDING) and "VERB" in lemmas(w) and _narrators(tokens, k) for k, w in enumerate(tokens))


def _the_ride(tokens: list[str], a) -> bool:
    """Whether road user ``a``, first said with "the" and never introduced, is what the narrator does
    something to ("Scratched the bike", "I came off the bike"): a writer who rides names their own
    ride as known; someone else's would be introduced ("a lad on a bike") or be the subject."""
    j = _before(tokens, a.named_end - len(a.word.split()))
    if a.det != "the" or j < 0 or tokens[j] in _CLAUSE_OPEN:
        return False
    j -= j > 0 and tokens[j] in _OFF
    verb = tokens[j]
    return verb.isalpha() and "VERB" in lemmas(verb) and _narrators(tokens, j) and _narrator_rides(tokens)


def _narrators_ride(tokens: list[str], a, others: list, kind_at: KindAt) -> bool:
    """Whether road user ``a`` is the narrator's ride: named where the narrator is on it or takes it,
    or ridden as "it" right after its first mention (``others``: the other road users)."""
    if a.named_end < 0:
        return False
    alone = not any(o.kind == a.kind for o in others)
    for start, end in _mentions(tokens, a, alone, kind_at):
        if not rider_noun(tokens[end - 1]) and _rides_here(tokens, start):
            return True  # (the machine, not its rider: "I nearly took a cyclist out")
    if alone and not rider_noun(a.word.split()[-1]) and _the_ride(tokens, a):
        return True
    return _ridden_it(tokens, a, others)


def _free(a, spec) -> bool:
    """Whether nothing sets road user ``spec`` (gathered as ``a``) apart from the narrator's ride:
    placed, watched, in a group, parked."""
    return not (
        a.seen
        or a.said
        or a.side
        or a.lane_side
        or a.kerb_side
        or a.from_arm
        or a.beside
        or a.group
        or a.counted
        or a.parked
        or a.followed
        or a.passed
        or a.object_of
    )


def drop_narrators_ride(actors: list, reading: Reading, tokens: list[str], kind_at: KindAt) -> list:
    """Take out of ``reading`` the bicycle or e-scooter the narrator rides (see the module): the ego,
    its speed the ego's where none was read. ``actors`` are what the reader gathered of its road users,
    in the same order, ``tokens`` the words they were read from, ``kind_at`` what kind a phrase names.
    Returns ``actors`` without it."""
    if not discourse.FIRST_PERSON & set(tokens) or len(reading.actors) < 2:
        return actors
    for k, (a, spec) in enumerate(zip(actors, reading.actors)):
        if spec.kind not in RIDDEN or not _free(a, spec):
            continue
        if _narrators_ride(tokens, a, [o for o in actors if o is not a], kind_at) and take_as_ego(reading, k):
            return without_road_user(actors, reading, k)
    return actors
