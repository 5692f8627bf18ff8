"""A writer on foot beside the road who tells what a vehicle and someone else did: a witness.

"I was on the pavement when the lights changed. The tipper pulled away and a scooter came
across from the right against the red", "I was walking my dog on the pavement. The blue Corsa came
past me and turned left, and a woman on a scooter rode into the side of it": a statement for the
police or an insurer, or a reply to a witness appeal. The writer is in the story only as the one who
saw it; the scenario is the vehicle's, as in a report with no narrator, and read with the writer's
"I" it would be the writer's own (their standing still the ego's, the vehicle one more road user).

It is told apart by the writer's part in the words, and by the story having a scene of its own:

- the writer walks (:func:`vei_scenario.language.narrator_outside.on_foot_verb`), or is somewhere
  only people on foot are ("was on the pavement", "on the verge", "in the bus shelter"; not "stood
  at the lights", "at the junction", "at the zebra" or "at the bus stop", where drivers stand and
  wait too; not one whose own vehicle is named, "in my car") and is in no vehicle of their own,
  at no wheel and with no speed (:func:`vei_scenario.language.narrator_outside.outside`; no verb of
  riding or driving, no number in their clause), and nothing is placed from them ("in front of
  me", "came past us": the one the scene is placed from is in it);
- the writer does not go into the road: not the subject of a verb of crossing or of stepping
  off or out ("I stepped off the kerb", "I was crossing the road": the walker a vehicle meets,
  :mod:`vei_scenario.language.writer_on_foot`), and nothing hits, misses or stops for them ("I was
  hit by its mirror", "it stopped for us");
- the story names at least two road users or people besides the writer, so that the vehicle has
  someone to meet: with one, the writer is the one it meets.

The writer's words are then left out, so the passes for a report with no narrator
(:func:`vei_scenario.language.protagonist.frame`) find the vehicle the story is about: their "I",
with what they were doing ("I was stood", "I was walking my dog"), but not where ("on the pavement
by the junction with Viaduct Road" still says a junction) nor what they saw or would say ("saw a
Corsa coming at about 30").
"""

from __future__ import annotations

from vei_scenario.language.discourse import PERCEIVE
from vei_scenario.language.ego import KindAt, Known, lemma_in, road_users
from vei_scenario.language.function_words import FIRST_PERSON
from vei_scenario.language.lemmas import lemmas
from vei_scenario.language.narrator_outside import on_foot_verb, outside
from vei_scenario.language.outcome import vehicle_part_word
from vei_scenario.language.vocabulary import GENDERED

#: Verbs (by lemma) of going into the road on foot: a writer who does is in the scene.
_INTO_THE_ROAD = frozenset({"cross", "step", "run", "dash", "dart", "jump"})
#: Verbs (by lemma) of going on wheels: a writer who does rides or drives in the scene.
_ON_WHEELS = frozenset({"ride", "cycle", "drive", "scoot", "pedal", "travel"})
#: Verbs (by lemma) a vehicle does to a person it meets: a writer as their object is in the scene.
_DONE_TO = frozenset({"hit", "miss", "strike", "clip", "knock", "stop", "brake", "swerve", "hoot", "beep", "wave"})
#: Verbs (by lemma) of saying or thinking: the writer's hedge ("I would say", "I think") is no act.
_SAYING = frozenset({"say", "think", "reckon", "believe", "guess", "suppose", "estimate", "know", "remember"})
#: The writer as a subject, and as an object.
_SUBJECTS = frozenset({"i", "we"})
_OBJECTS = frozenset({"me", "us"})
#: Words that place something from the writer ("ahead of me", "past us", "towards me").
_RELATIVE_TO = frozenset({"front", "ahead", "behind", "past", "towards", "toward", "at", "into", "beside", "by"})
#: Person nouns ("a lad", "a woman"), who are walkers when they act.
_PERSONS = frozenset().union(*GENDERED.values())
#: Words that end a writer's clause.
_CLAUSE_END = frozenset({".", ",", ";", ":", "!", "?", "and", "but", "when", "while", "as", "then"})
#: Prepositions that open where the writer was ("on the pavement", "by the zebra"): kept, as the place.
_WHERE = frozenset(
    {"at", "on", "by", "in", "near", "outside", "beside", "opposite", "next", "across", "from", "up", "behind"}
)
#: Words between a preposition and its place ("at the", "on my").
_ARTICLES = frozenset({"the", "a", "an", "my", "our", "this", "that"})
#: Places only people on foot are at (a closed class): a writer there is off the road. Not the
#: crossings of :data:`vei_scenario.language.narrator_outside.FOOT_PLACES` (a driver stops at a zebra)
#: nor a kerb but "on" it.
_WALKERS_PLACES = frozenset(
    {"pavement", "pavements", "footpath", "footway", "sidewalk", "sidewalks", "verge", "towpath", "footbridge"}
    | {"foot", "shelter", "doorway", "garden"}
)
_KERBS = frozenset({"kerb", "curb", "kerbside", "curbside"})
#: Verbs (by lemma) of standing, which drivers say of themselves too ("I was stood at the lights").
_STANDING = frozenset({"stand", "step"})


def _clause_end(tokens: list[str], start: int) -> int:
    """Where the clause going on at ``start`` ends (at a mark or a joining word, or the text's end)."""
    return next((j for j in range(start, len(tokens)) if tokens[j] in _CLAUSE_END), len(tokens))


def _writer_clauses(tokens: list[str]) -> list[list[str]]:
    """The words of each clause the writer is the subject of, from their "I"/"we" to its end."""
    out = []
    for k, w in enumerate(tokens):
        if w in _SUBJECTS:
            end = _clause_end(tokens, k + 1)
            out.append(tokens[k + 1 : end])
    return out


def _stands_on_foot(tokens: list[str]) -> bool:
    """Whether the writer is on foot off the road: the subject of a verb of walking ("I was walking the
    dog", "we were strolling"), or somewhere only people on foot are ("I was on the pavement", "we
    were on the verge", "I was in the bus shelter", "on the kerb"). Not "stood at the lights", "at
    the junction", "at the zebra" or "at the kerb": drivers stand and wait there too."""
    if any(on_foot_verb(tokens, k) and not lemma_in(tokens[k], _STANDING) for k in range(1, len(tokens))):
        return True
    for clause in _writer_clauses(tokens):
        for n, x in enumerate(clause[:8]):
            if x not in _WALKERS_PLACES and not (x in _KERBS and clause[n - 2 : n] in (["on", "the"], ["on"])):
                continue
            before = [y for y in clause[:n] if y not in _ARTICLES]
            if before[-1:] and before[-1] not in _WHERE and "NOUN" in lemmas(before[-1]):
                before = before[:-1]  # ("in the bus shelter", "on the grass verge": a noun before it)
            if before and before[-1] in _WHERE:
                return True  # ("I was on the pavement", "we were in the shelter"; not "I saw the pavement")
    return False


def _in_the_scene(tokens: list[str]) -> bool:
    """Whether the writer goes into the road, rides or drives, has a number in their clause (a speed of
    their own), or has something done to them or to their vehicle ("hit me", "clipped my mirror")."""
    for clause in _writer_clauses(tokens):
        if any(
            x.isalpha() and lemma_in(x, _INTO_THE_ROAD | _ON_WHEELS) and clause[n - 1 : n] != ["to"]
            for n, x in enumerate(clause[:5])
        ):
            return True  # ("I stepped off", "we were cycling"; not "waiting to cross": not yet)
        if any(x.isalpha() and lemma_in(x, _DONE_TO) for x in clause[:3]):
            return True  # ("I was hit by its mirror", "we got clipped")
        if any(x.isdigit() for x in clause):
            return True
    for k, w in enumerate(tokens):
        mine = w in ("my", "our") and vehicle_part_word(tokens[k + 1] if k + 1 < len(tokens) else "")
        before = tokens[max(0, k - 3) : k]
        if (w in _OBJECTS or mine) and any(x.isalpha() and lemma_in(x, _DONE_TO) for x in before):
            return True  # ("stopped for us", "hit my door": the writer's own vehicle)
        if w in _OBJECTS and set(before) & _RELATIVE_TO:
            return True  # ("in front of me", "came past me": the writer is where the scene is placed from)
    return False


def bystander(tokens: list[str], kind_at: KindAt, known: Known) -> bool:
    """Whether the writer of ``tokens`` (as scanned) only watched from beside the road (see the module)."""
    if not (_SUBJECTS & set(tokens)) or "ego" in tokens:
        return False  # (no writer, or one whose own vehicle is named: "in my car")
    if not _stands_on_foot(tokens) or not outside(tokens, kind_at, known):
        return False
    if _in_the_scene(tokens):
        return False
    named = {tokens[p.end - 1] for p in road_users(tokens, kind_at, known) if p.kind != "ego"}
    return len(named | (_PERSONS & set(tokens))) >= 2  # (a road user, or a person: "a lad ran out")


def _writers_words(tokens: list[str], k: int) -> tuple[int, int, int]:
    """The writer's own words that start at their "I" at ``k``, as (where the kept words start, where
    they end, where the clause ends): only the pronoun goes before a verb of perceiving or saying
    ("I saw ...", "I would say ..."); else what they were doing goes, but where they were stays ("I
    was stood | on the pavement by the junction"), up to a verb of theirs after it ("... | waiting to
    cross"), which goes too."""
    end = _clause_end(tokens, k + 1)
    j = k + 1
    while j < end and tokens[j] not in _WHERE:
        x = tokens[j]
        if x.isalpha() and lemma_in(x, PERCEIVE | _SAYING):
            return k + 1, end, end
        j += 1
    verb = next((v for v in range(j, end) if tokens[v].endswith("ing") and "VERB" in lemmas(tokens[v])), end)
    return j, verb, end


def without_writer(tokens: list[str], dropped: list[str]) -> list[str]:
    """``tokens`` without a bystander writer (see :func:`bystander`): their "I" with what they were
    doing, and the writer as an object or owner said "the witness" ("came past me": past someone who
    is no road user)."""
    out: list[str] = []
    k = 0
    while k < len(tokens):
        w = tokens[k]
        if w in _SUBJECTS:
            keep, stop, end = _writers_words(tokens, k)
            dropped.extend(tokens[k:keep] + tokens[stop:end])
            out += tokens[keep:stop]
            k = end
            continue
        if w in FIRST_PERSON:
            dropped.append(w)
            out += ["the", "witness"] if w in _OBJECTS else ["the"]
        else:
            out.append(w)
        k += 1
    return out
