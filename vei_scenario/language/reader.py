"""Reading a description as people write it: lemmas, synonyms, several actors per clause and sentence,
numbers bound to the actor they describe, sides resolved by what the actor does.

The text is cut into clauses (sentence ends, "then", "while"). Every word is matched, longest phrase
first, against the lexicon (:mod:`vocabulary` and :mod:`lexicon`) by its surface form or any of its
lemmas, so inflections need no entries. In a clause:

- an actor named at the start, or after a conjunction ("and a pedestrian ..."), is a *subject*: the
  behaviours that follow are its; an actor named after a preposition or a verb ("in front of the
  ego", "approaches a stationary car") is an *object*: it is created (if new) and takes the positions
  and numbers that follow it, but not the behaviours;
- "a car" is a new actor, "the car" / "it" the one already named, "two pedestrians" two actors that
  share what follows, "one ... the other" their members;
- speeds and distances go to the nearest actor named before them (not to an ego named after "of",
  "to", "behind": "12 m ahead of the ego at 50 km/h" is the lead car's speed, and the ego's too when
  its own is not said: the speed stands next to both);
- sides ("from the left") are resolved with the actor's first behaviour: the far kerb for a
  crossing, the left entrance for a red-light runner, the left lane for a cut-in.

Words that carry nothing the layers can hold are listed in :attr:`Reading.ignored`. A description is
refused only when something must be placed and cannot be: a behaviour with no actor, or an actor
whose only verb is unknown (that verb is named). A number with no unit it can read is listed too.
"""

from __future__ import annotations

import re
from collections import Counter
from copy import copy
from dataclasses import dataclass, field, fields, replace
from functools import lru_cache

from vei_scenario.language import (
    access_pull_out,
    across_alone,
    addressee,
    behind_a_thing,
    bystanders,
    crossing_reaction,
    crowds,
    discourse,
    ego,
    ego_double,
    ego_emerges,
    ego_speed,
    ego_turner,
    experiencer,
    follower_start,
    form_fields,
    from_cover,
    fronted_from,
    generic_ego,
    heading,
    heading_named,
    held_pass,
    junctions,
    kerb_crossing,
    kerb_ride,
    kind_in_general,
    lane_moves,
    lane_to_front,
    motion,
    named_riders,
    narrator_outside,
    narrator_ride,
    narrator_vehicle,
    no_lane_beside,
    norms,
    off_a_place,
    out_of_the_lane,
    owned_by_name,
    parked_rows,
    participle_aside,
    protagonist,
    pull_in_apart,
    report_vehicle,
    ring_entry,
    run_on,
    said_again,
    scene_pace,
    scenery,
    sides,
    start_gap,
    stopped_short,
    way_across,
    while_clause,
    whose_act,
    witness_on_foot,
    writer_on_foot,
)
from vei_scenario.language import lexicon as L
from vei_scenario.language import quantities as Q
from vei_scenario.language import settings as S
from vei_scenario.language import vocabulary as V
from vei_scenario.language.behaviours import BEHAVIOURS
from vei_scenario.language.clauses import sentence_start, sentence_stop
from vei_scenario.language.comment_clause import without_comment_clauses, without_comments_beside_speeds
from vei_scenario.language.elsewhere import stands_elsewhere
from vei_scenario.language.function_words import DETERMINERS, PHRASE_ENDS
from vei_scenario.language.gherkin_outline import filled_outline
from vei_scenario.language.lemmas import lemmas as _lemmas
from vei_scenario.language.light_verbs import LIGHT_VERBS, acts_said_as_nouns, set_aside
from vei_scenario.language.manner import apply_manner, stated_manner, tight_cut_ins
from vei_scenario.language.met_coming import met_coming, waits_facing
from vei_scenario.language.miles_english import road_called_by_its_limit, said_in_miles_english, told_in_miles_english
from vei_scenario.language.motion import (
    chains,
    destinations_not_origins,
    give_the_ego_the_way,
    head_on,
    into_the_ego_lane,
    on_the_footway,
    one_path,
    out_of_a_side_road,
    out_to_overtake,
    outcome_not_behaviour,
    participle_of_state,
    turn_across_side,
)
from vei_scenario.language.ncap import rewrite as ncap_rewrite
from vei_scenario.language.no_ones_place import without_places_of_no_one
from vei_scenario.language.normalise import (
    ANSWER_SAID,
    NUMBER_WORDS,
    ROUTE_SAID,
    abbreviation_points,
    normalise,
    plain_letters,
    route_answered,
    speed_answered,
)
from vei_scenario.language.object_participle import participle_phrase
from vei_scenario.language.outcome import decide, into_road_user, outcome_cues
from vei_scenario.language.phrasal_nouns import phrasal_compound
from vei_scenario.language.reading import ActorSpec, NotUnderstood, Reading
from vei_scenario.language.rear_end import rear_ender_behind
from vei_scenario.language.route import ego_route, instruction_at, turn_taken_at
from vei_scenario.language.said_again import plural
from vei_scenario.language.scene import only_the_scene, quoted_speakers
from vei_scenario.language.stated import (
    stated_clock,
    stated_heavy_rain,
    stated_lanes,
)
from vei_scenario.language.who import (
    DESCRIBING,
    agent_noun,
    closed_compound,
    counted_in_figures,
    lamps_not_signals,
    model_said_again,
    own_vehicles,
    proper_names,
    ridden_past_a_hedge,
    rider_noun,
    rides_next,
    shared_scooters,
    standing_names_a_kind,
    towed,
    unnamed_subjects,
    wala_riders,
)

_TOKEN = re.compile(r"\d+(?:\.\d+)?|km/h|m/s²|m/s2|m/s|[a-z][a-z\-]*(?:'[a-z]+)?|'s|[.;,!?:%]")
_TOKEN_BRACKETS = re.compile(_TOKEN.pattern + "|[()]")  # (for discourse: a name said in brackets)


#: The articles, one another's forms in a phrase.
_ARTICLES = discourse.ARTICLES


@lru_cache(maxsize=4096)
def forms(word: str) -> frozenset[str]:
    """The surface form of ``word`` and all its lemmas."""
    if word in _ARTICLES:  # ("pulls away from a bus stop" is the phrase "pull away from the bus stop")
        return _ARTICLES
    out = {word}
    for lemmas in _lemmas(word).values():
        out.update(lemmas)
    if not _lemmas(word) and word.endswith("s") and not word.endswith("ss") and len(word) > 3:
        out.add(word[:-1])  # ("escooters", "segways": a plural of a noun no dictionary has is its noun's)
    if "-" in word:  # "e-scooters", "pick-ups": the lemmas of the last part, joined again
        head, _, last = word.rpartition("-")
        out.update(f"{head}-{lemma}" for lemma in forms(last))
    return frozenset(out)


def _pos(word: str) -> set[str]:
    return set(_lemmas(word))


def _entries() -> dict[tuple[str, ...], tuple[str, object]]:
    """The phrase table: the lexicon's groups in order (a later group wins a phrase both name), then
    the vocabulary's phrases where the lexicon has none."""
    table: dict[tuple[str, ...], tuple[str, object]] = {}

    def put(phrases, slot, value, overwrite=True):
        for ph in phrases:
            key = tuple(ph.split())
            if overwrite or key not in table:
                table[key] = (slot, value)

    put(L.NOISE, "noise", None)
    for kind, words in L.ACTOR_NOUNS.items():
        put(words, "actor", kind)
    put(L.CAR_NOUNS, "actor", "car")
    put(L.EGO_NOUNS, "actor", "ego")
    put(V.PRONOUNS, "pronoun", None)
    put(L.MEMBERS, "member", None)
    put(L.COUNTS, "count", None)
    grouped = [
        ("map", L.MAPS),
        ("weather", L.WEATHER),
        ("time", L.TIMES),
        ("density", L.DENSITY),
        ("lanes", L.LANES),
        ("side", L.SIDES),
        ("lane_side", L.LANE_SIDES),
        ("kerb", [(None, L.KERB)]),
        ("kerb_side", [("right", L.NEARSIDE), ("left", L.FARSIDE)]),
        ("arm", [(None, L.JUNCTION_ARM)]),
        ("relation", L.RELATIONS),
        ("stationary", [(None, L.STATIONARY)]),
        ("criticality", L.CRITICALITY),
        ("intent", L.INTENTS),
        ("behaviour", [((name, {}), words) for name, words in L.BEHAVIOUR_VERBS.items()]),
        ("behaviour", [(("change_speed", {"speed_delta_mps": d}), w) for d, w in L.SPEED_CHANGE_VERBS.items()]),
        ("behaviour", [(("run_red_light", {}), L.RED_LIGHT)]),
        ("behaviour", [(("cut_in", {"from_side_road": 1.0}), L.SIDE_ROAD_EXITS)]),
        ("to_stop", [(None, L.TO_A_STOP)]),  # ("decelerates to a standstill": its change ends standing)
        ("wrong_way", [(None, L.WRONG_WAY)]),
        ("over_line", [(None, L.OVER_THE_LINE)]),
        ("returns", [(None, L.RETURNS)]),
        ("turn", L.TURNS),
    ]
    for slot, groups in grouped:
        for value, words in groups.items() if isinstance(groups, dict) else groups:
            put(words, slot, value)
    put(L.SEQUENCE, "sequence", None)
    put(L.PARALLEL, "parallel", None)
    # the vocabulary's phrases, where the lexicon has none
    for phrase, (k, v) in V.ACTORS.items():
        put([phrase], "actor", "ego" if k == "ego" else v, overwrite=False)
    for phrase, rel in V.RELATIONS.items():
        if rel.startswith("roadside"):  # "from the pavement": a kerb, its side said elsewhere or the near one
            put([phrase], "kerb_side" if "left" in phrase else "kerb", "left" if "left" in phrase else None, False)
        else:
            put([phrase], "relation", rel, overwrite=False)
    plain = [
        ("lanes", V.LANE_COUNTS),
        ("criticality", V.CRITICALITY),
        ("intent", V.INTENTS),
        ("behaviour", V.BEHAVIOURS),
        ("speed_word", V.SPEED_WORDS),
        ("ego_verb", {p: r for p, r in V.EGO_VERBS.items() if not p.startswith("ego ")}),  # (the ego on its own)
        ("sequence", dict.fromkeys(V.SEQUENCE_WORDS)),
        ("parallel", dict.fromkeys(V.PARALLEL_WORDS)),
    ]
    for slot, phrases in plain:
        for phrase, value in phrases.items():
            put([phrase], slot, value, overwrite=False)
    for route, words in L.EGO_ROUTES.items():
        put(words, "ego_verb", route, overwrite=False)
    return table


TABLE = _entries()
_BY_FIRST: dict[str, list[tuple[str, ...]]] = {}
for _key in sorted(TABLE, key=len, reverse=True):
    _BY_FIRST.setdefault(_key[0], []).append(_key)

#: Words that carry nothing on their own (articles, prepositions, auxiliaries, ...): never listed.
FUNCTION_WORDS = set(V.FILLER) | set(
    """a an the of in on at to and or then with is are was were be been being has have had do does did it its into
    onto from by for as this that these those which who whom whose while when after before so some there their
    where just but also very quite across through near next up down out off over toward towards around about
    any can could will would should may might must not no without within upon than like only even still yet
    again back along already now here ago 's i my me our we us you your they them he she him her his hers
    own same such each every all both either neither other another what whatever how why whether because until
    since though although if unless onto per via ego's car's vehicle's road's""".split()
)


@dataclass
class _Mention:
    slot: str
    value: object
    words: str
    start: int  # token index
    prev: str = ""  # the token before the phrase
    next_: str = ""  # the token after it
    end: int = 0  # token index after it
    det: str = ""  # the determiner right before it ("the", "a", ...)
    owners: tuple = ()  # a number's: the starts of the mentions its grammar says it of (quantities.owners)


@dataclass
class _Actor:
    kind: str
    relation: str | None = None
    side: str | None = None  # a bare left/right
    lane_side: str | None = None
    kerb: bool = False
    kerb_side: str | None = None
    arm: bool = False
    stationary: bool = False
    distance_m: float | None = None
    speed_mps: float | None = None
    behaviours: list = field(default_factory=list)  # (name, cfg, criticality, link)
    group: list | None = None  # the actors named together ("two cars")
    unknown: list = field(default_factory=list)  # verbs said of it that the lexicon does not know
    said: set = field(default_factory=set)  # every relation said of it ("towards us" and "in our lane")
    wrong_way: bool = False  # driving against the traffic where it is
    returns: bool = False  # it goes back (a wrong-way driver to its own side)
    crit: str | None = None  # the criticality its clause's wording gives, verbs or not
    parked: bool = False  # said to be parked (at the side of the road, unless put in a lane)
    double_parked: bool = False  # parked beside the parked ones: in the outer traffic lane
    out_of_place: bool = False  # said to come out of a place beside the road (a driveway, a stop, a gate)
    place: str | None = None  # the head noun of that place ("driveway", "gate", "stop", "park")
    far_side: bool = False  # said to come from the other side ("from the opposite side")
    left_the_kerb: bool = False  # its kerb side said as where it comes from ("off the pavement on the left")
    followed: bool = False  # the ego follows it ("Following a truck, ...")
    object_of: _Actor | None = None  # whose verb it is the object of ("overtakes a bus": the bus)
    goes_on: bool = False  # said not to give way, stop or slow ("does not yield", "fails to stop")
    refuses_way: bool = False  # said not to give way, the act itself ("does not give way", "fails to yield")
    same_way: bool = False  # its move said as one made going the ego's way ("cut me up")
    speed_to_mps: float | None = None  # the speed it changes to ("slows from 80 to 30 km/h": 30)
    accel_mps2: float | None = None  # how hard it changes speed ("brakes at 6 m/s²")
    toward: str | None = None  # the side it moves to ("merges right", "swerves left into our lane")
    goes_to: str | None = None  # the side or kerb said as where it goes ("ran off to the left", "to the left kerb")
    edge: str | None = None  # the side of the road's edge it is said at ("along the right-hand kerb"), no lane
    came_from: bool = False  # a kerb or side said as where it comes from ("walks from the far side")
    end_gap: str | None = None  # the behaviour its distance is the end gap of ("overtakes, 3 m to spare")
    gaps_said: list = field(default_factory=list)  # every distance said of it (start_gap.Said), in order
    word: str = ""  # the words it was first named by
    det: str = ""  # the determiner it was first named with ("a", "the", "our"; none: "Bus was doing 45")
    named_after: str = ""  # the word right before its first name ("other" in "the other driver")
    seen: bool = False  # first named as what someone sees ("saw the car hit a cyclist"): watched, from outside
    acted_on: bool = False  # the object of someone's verb ("overtakes a truck")
    pavement: bool = False  # said to be on a pavement (off the road), not in a cycle lane
    member_named: bool = False  # told apart from its group ("the first one", "the other")
    counted: bool = False  # named in a group a number counts ("two lads on scooters"), told apart or not
    named_end: int = -1  # where its first name ends in the scanned words (-1: not named there)
    stopped_short_m: float | None = None  # how far short of it the ego stopped ("I stopped 2 m short of him")
    hides: bool = False  # named as what someone comes out from behind or between
    passed: bool = False  # what the ego passes ("the ego overtakes her"): going along ahead of it
    has_way: bool = False  # going on while the ego gives way ("we yield; the van carries on")
    priority: bool = False  # already on the roundabout or the main road: going on is its right
    from_arm: bool = False  # said to come from or out of a junction arm ("from the side road on the left")
    takes_an_exit: bool = False  # an exit said as the arm it takes ("takes the exit on the left"): it leaves
    beside: bool = False  # said to be on a side of the ego ("a cyclist on my left"), not to come from one
    moves_out: bool = False  # its crossing is said with "out" ("swung out", "pulled out")
    pulled_out: bool = False  # its move is a pull-out of a side road ("came out of", "emerged from")
    goes_over: bool = False  # said to go on over or through ("carried on across", "went straight over")
    straight_on: bool = False  # its way through said straight on ("carried straight on past me")
    went_by: bool = False  # its verb of passing has no object ("the van has passed", "a lorry went by")
    along: bool = False  # said to go along the road or its edge ("rides along the kerb", "same direction")
    across: bool = False  # its move into a lane is said with "across" ("cut across to the right")
    own_lane: bool = False  # in a lane of its own beside the ego's ("in the cycle lane on our right")
    from_cover: bool = False  # said to come out from behind or between something ("from behind a bus")
    cover: _Actor | None = None  # the road user it comes out from behind or between ("from behind the van")
    speed_at: int | None = None  # where its speed was said in the scanned words (None: not said there)


#: Euro NCAP's names of its test scenarios ("Car-to-Car Rear stationary", "Car-to-Pedestrian Nearside
#: Child"): the ego car to its target, where the target is and what it does.
_NCAP_NAME = re.compile(
    r"\b(?:car|vehicle)[- ]to[- ](car|vehicle|pedestrian|bicyclist|cyclist|motorcyclist|motorcycle)"
    r"(?:[- ](rear|nearside|farside|far-side|near-side|longitudinal|front|turn[- ]across[- ]path))?"
    r"(?:[- ](stationary|moving|braking|adult|child))?\b"
)


def _ncap_said(m: re.Match) -> str:
    """A Euro NCAP scenario name said in the words the reader knows; a speed right after it is the
    ego's (the protocol names the test by the vehicle under test's speed: "CCRs at 50 km/h")."""
    said = _ncap_target(m)
    return f"{said}; the ego drives" if re.match(r"\s*,?\s*at\s+\d", m.string[m.end() :]) else said


def _ncap_target(m: re.Match) -> str:
    target, where, what = m.group(1), (m.group(2) or "").replace("-", "").replace(" ", ""), m.group(3) or ""
    who = f"a {what} {target}" if what in ("adult", "child") else f"a {target}"
    if where in ("nearside", "farside"):
        side = "right" if where == "nearside" else "left"
        return f"{who} crosses from the {side}"
    if where == "longitudinal":
        return f"{who} ahead goes along the road"
    if where == "rear" or what in ("stationary", "moving", "braking"):
        return {"stationary": f"a stationary {target} ahead", "braking": f"{who} ahead brakes hard"}.get(
            what, f"{who} ahead drives on"
        )
    return who


def _single_kind(word: str) -> str | None:
    """The road-user type ``word`` alone (or its lemma: "trucks") names, or None (for :mod:`who`)."""
    for w in sorted(forms(word), key=lambda f: f != word):
        slot, value = TABLE.get((w,), (None, None))
        if slot == "actor":
            return str(value)
    return None


def _slot_of(key: tuple[str, ...]) -> str | None:
    """The slot of phrase ``key``; of a single word, of its lemma where the word itself has none."""
    if key in TABLE or len(key) > 1:
        return TABLE.get(key, (None,))[0]
    return next((TABLE[(w,)][0] for w in sorted(forms(key[0])) if (w,) in TABLE), None)


def _actor_word(word: str) -> bool:
    """Whether ``word`` alone names a road user other than the ego."""
    return any(TABLE.get((w,), ("",))[0] == "actor" and TABLE[(w,)][1] != "ego" for w in forms(word))


def _actor_noun_in(phrase: str) -> str | None:
    """The road-user noun a phrase ends in ("white transit van": "van"), or None."""
    for word in reversed(re.findall(r"[a-z][a-z-]*", phrase)):
        if _actor_word(word):
            return word
    return None


@lru_cache(maxsize=1)
def _speller():
    from vei_scenario.language.spelling import Speller

    # (and the outcome's words, read from the whole text)
    outcome = {"collision", "collide", "crash", "accident", "contact", "afternoon", "morning", "evening", "night"}
    return Speller(
        {w for key in TABLE for w in key} | FUNCTION_WORDS | outcome | NUMBER_WORDS | set(L.VEHICLE_SIZE_WORDS)
    )


#: The slots whose single words may be written shortened ("e-scoot", "oncmg", "rdbt"): nouns of road
#: users and places, and where one is. Not verbs: a shortened verb is most often its noun ("smooth decel").
_SHORTENED_SLOTS = frozenset(("actor", "relation", "map", "arm", "kerb"))


@lru_cache(maxsize=1)
def _shorthand():
    from vei_scenario.language.lemmas import english
    from vei_scenario.language.shorthand import Shorthand

    return Shorthand(
        {
            key[0]: meaning
            for key, meaning in TABLE.items()
            if len(key) == 1
            and meaning[0] in _SHORTENED_SLOTS
            and key[0] not in FUNCTION_WORDS
            and english(key[0].rsplit("-", 1)[-1])  # (English words: "samokat" is no one's shorthand)
        }
    )


def _written_in_lower_case(text: str) -> frozenset[str]:
    """The words ``text`` writes only in lower case (a word also written with capitals may be a name or
    an acronym: "Min", "ACC")."""
    lower, other = set(), set()
    for w in re.findall(r"[A-Za-z][A-Za-z-]*", text):
        (lower if w.islower() else other).add(w.lower())
    return frozenset(lower - other)


@lru_cache(maxsize=64)
def _normalised(text: str) -> str:
    """``text`` lowercased and normalised as :func:`_tokens` reads it (cached: a reading tokenises its
    text several ways, all from this)."""
    text = abbreviation_points(text).lower().replace("\u2019", "'").replace("’", "'")
    text = Q.ranges(normalise(Q.citations(text), _actor_noun_in))
    text = ncap_rewrite(text, _actor_word)
    return _NCAP_NAME.sub(_ncap_said, text)


#: Words of standing still after "'m" / "'re", which keep their verb: "we're stopped" is a state, where
#: "we stopped" would be a stop made.
_STATES = frozenset(("stopped", "stationary", "stood", "parked", "halted", "fully", "completely", "already"))


def _tokens(text: str, spell: bool = True, brackets: bool = False) -> list[str]:
    """The words of ``text`` as the reader reads them (normalised; a misspelt word as the word it is
    one slip from, unless ``spell`` is false or the text writes the word only with its own capital,
    a name: "Hanley Rd" is no "Harley"; brackets kept as words if ``brackets``)."""
    names = proper_names(text) if spell else frozenset()
    raw, text = text, _normalised(text)
    out = []
    found = (_TOKEN_BRACKETS if brackets else _TOKEN).findall(text)
    for k, tok in enumerate(found):
        if tok.endswith("'d") and len(tok) > 2 and found[k + 1 : k + 2] == ["have"] and found[k + 2 : k + 3] != ["to"]:
            out += [tok[:-2], "would"]  # ("I'd have hit him": "would have"; not "I'd have to say": a manner of saying)
        elif tok.endswith("'s") and len(tok) > 2:
            out += [tok[:-2], "'s"]
        elif "'" in tok and tok.split("'", 1)[1] == "t":  # "doesn't", "won't", "can't": the verb, then "not"
            stem = tok.split("'", 1)[0]
            out += [_CONTRACTED.get(stem, stem[:-1] if stem.endswith("n") else stem), "not"]
        elif "'" in tok and tok.split("'", 1)[1] in ("re", "m") and found[k + 1 : k + 2] and found[k + 1] in _STATES:
            out += [tok.split("'", 1)[0], "am" if tok.endswith("'m") else "are"]  # ("we're stopped": a state)
        elif "'" in tok and tok.split("'", 1)[1] in ("re", "m", "ve", "ll", "d"):
            out.append(tok.split("'", 1)[0])  # "we're": "we" (the rest carries nothing here)
        elif tok.endswith("'") or tok in ("'",):
            continue
        else:  # ("rush-hour", "mid-afternoon": a setting's words)
            for word in S.compound_words(tok, _slot_of):
                out.extend([word] if (word,) in TABLE else closed_compound(word, _single_kind))
    if spell:
        out = [tok if tok in names else _speller().correct(tok) for tok in out]
        lower = _written_in_lower_case(raw)
        known = _speller().words  # (a word the reader has, "four", shortens nothing)
        out = [_shorthand().expand(tok) if tok in lower and tok not in known else tok for tok in out]
    out = lamps_not_signals(out, lambda w: w.isalpha() and w not in FUNCTION_WORDS)
    return own_vehicles(out, _kind_at, lambda w: w.isalpha() and w not in FUNCTION_WORDS and not _known([w], 0))


#: Contractions whose verb is not the word before "n't" less its "n".
_CONTRACTED = {"won": "will", "can": "can", "shan": "shall", "ain": "is"}
#: Words that deny the verb after them ("does not stop", "never yields", "fails to give way"), and the
#: words that may stand between (auxiliaries, adverbs, "to").
_NEGATORS = {"not", "never", "fail", "fails", "failed", "failing", "refuse", "refuses", "refused", "refusing",
             "without"}  # fmt: skip
_BETWEEN = {"does", "do", "did", "will", "would", "is", "are", "was", "were", "can", "could", "should", "to",
            "even", "just", "simply", "then", "really", "quite", "bother", "bothers", "bothered", "manage",
            "manages"}  # fmt: skip
#: What a road user does instead of a behaviour it is said not to do: one that does not give way goes
#: (as "fails to yield" reads), one that does not stop, brake or slow carries on, one that does not go
#: on stops; not crossing is holding back for the ego, giving way; any other denied behaviour leaves
#: it carrying on.
_DENIED = {"give_way": ("cut_in", {}), "keep_going": ("stop", {}), "cross_in_front": ("give_way", {})}
#: Denied behaviours whose denial holds the road user back: it does not go on.
_HELD_BACK = frozenset(("keep_going", "cross_in_front"))


def _denied(tokens: list[str], i: int) -> bool:
    """Whether the phrase at ``i`` is denied by a negator before it (past auxiliaries and adverbs), or
    by "too ... to" ("is going too fast to stop": it does not stop)."""
    if i >= 3 and tokens[i - 1] == "to" and tokens[i - 3] == "too":
        return True
    j = i - 1
    while j >= 0 and (tokens[j] in _BETWEEN or _adverb(tokens[j])) and tokens[j] not in _NEGATORS:
        j -= 1
    return j >= 0 and tokens[j] in _NEGATORS


def _match(tokens: list[str], i: int):
    """For each form of the word at ``i``, the longest phrase starting with it that the text holds."""
    for w in forms(tokens[i]):
        for key in _BY_FIRST.get(w, ()):
            if i + len(key) <= len(tokens) and all(_fits(k, tokens[i + j], j) for j, k in enumerate(key)):
                yield key
                break


#: Possessives that stand where a phrase has an article ("slams on his brakes", "runs her red").
_POSSESSIVE_WORDS = frozenset({"his", "her", "their", "its", "my", "our", "your"})


def _fits(word: str, token: str, j: int) -> bool:
    """Whether phrase word ``word`` (its ``j``-th) matches ``token``: one of its forms, or, inside a
    phrase, a possessive where the phrase has an article."""
    return word in forms(token) or (j > 0 and word in _ARTICLES and token in _POSSESSIVE_WORDS)


#: Prepositions that name a place as a landmark ("just after the exit"), not where a road user comes from.
_LANDMARK_PREPOSITIONS = frozenset({"after", "before", "past", "beyond", "near", "by", "beside", "opposite"})
#: Words before a place named after a road user ("at the bus stop", "near a taxi rank").
_PLACE_PREPOSITIONS = {"at", "to", "near", "by", "from", "behind", "past", "towards", "toward", "in", "on", "into",
                       "onto", "beside", "outside", "opposite", "before", "after", "of", "off", "around", "across",
                       "along", "approaching", "leaving", "reaching"}  # fmt: skip


#: Words after which an article opens a new subject ("... and a unicorn runs out"), not an object.
_OPENERS = {
    "",
    ".",
    "?",
    "!",
    ";",
    ",",
    ":",
    "and",
    "then",
    "when",
    "while",
    "as",
    "but",
    "suddenly",
    "until",
    "before",
    "after",
}


def _does_next(tokens: list[str], i: int) -> bool:
    """Whether a behaviour (or an adverb then one) starts at ``i``."""
    if i < len(tokens) and _adverb(tokens[i]):
        i += 1
    key = _best(tokens, i) if i < len(tokens) else None
    return key is not None and TABLE[key][0] in ("behaviour", "ego_verb", "turn")


def _named_again_then_acts(mentions, k: int, tokens: list[str]) -> bool:
    """Whether mention ``k``, between commas right after a road user named with "a", is that road user
    named again because a verb of what it does follows it ("a van, a white Transit, pulled out", "a
    Micra - a MICRA - undertakes me"), or a participle or place of its own does ("a scooter, an electric
    scooter, riding toward me", "a car, a silver hatchback, coming at me"), said with an article right
    after the comma: a list goes on with another name, "and" or "plus". The one before may have words
    of its own between its article and its noun ("a rental scooter, a Bird, was riding", "a silver car,
    a Toyota, pulled out")."""
    return (
        k >= 2
        and mentions[k - 2].slot == "actor"
        and (mentions[k - 2].det in ("a", "an") or _phrase_det(tokens, mentions[k - 2].start) in ("a", "an"))
        and tokens[mentions[k - 1].start + 1 : mentions[k - 1].start + 2] in (["a"], ["an"])
        and k + 2 < len(mentions)
        and mentions[k + 2].slot in _WHAT_ONE_DOES
    )


#: Mentions that say what a road user does or where it goes (a verb, a turn, a way, a place).
_WHAT_ONE_DOES = frozenset({"behaviour", "turn", "wrong_way", "relation", "ego_verb"})


def _definite_before(mentions, k: int) -> bool:
    """Whether the road user named last before mention ``k`` was named definitely ("the car ahead, a
    taxi, ...": an apposition; "a van, a car, ...": a list)."""
    for m in reversed(mentions[:k]):
        if m.slot == "actor":
            return m.det in ("the", "this", "that", "our", "my", "its")
    return False


def _does_soon(tokens: list[str], i: int) -> bool:
    """Whether a behaviour starts at ``i`` or after a short phrase describing who does it ("a mum with
    a buggy steps out"), before the clause ends."""
    for k in range(i, min(i + 6, len(tokens))):
        if tokens[k] in ".;,!?:" or (k > i and tokens[k] in L.CONJUNCTIONS) or (k > i and _actor_at(tokens, k)):
            return False
        if _does_next(tokens, k):
            return True
        if k + 1 < len(tokens) and tokens[k + 1] in _MOTION_PARTICLES and _verb_before(tokens[k], tokens[k + 1]):
            return True  # (a verb the reader reads through a plain one: "swings across")
    return False


def _acts_at(tokens: list[str], i: int) -> bool:
    """Whether what someone does starts at ``i``, right after their noun: a behaviour, a verb the reader
    lacks and then one ("shot off the kerb"), or a phrase saying who they are and then one ("in black
    walked out"). A verb of saying or sending ("says unit 22 came off", "sent me down") is no deed."""
    if i >= len(tokens):
        return False
    return _does_next(tokens, i) or _does_next(tokens, i + 1) or (tokens[i] in DESCRIBING and _does_soon(tokens, i))


#: What may end a heading that names a crossing ("Mill Lane crossing.", "Station Road crossing, 8am:").
_HEADING_ENDS = frozenset((".", ",", ":", ";", "!", "?", "-", "—"))


#: Words after "a pedestrian crossing" that say where a person crosses, not what the crossing is.
_WHERE_ONE_CROSSES = (["in"], ["from"], ["towards"], ["toward"], ["into"], ["against"], ["between"], ["behind"])


def _struck_someone(verb: str) -> bool:
    """Whether ``verb``, right before "a pedestrian crossing ...", is a verb of hitting, missing or
    seeing someone ("struck", "hit", "saw"; not "there is a pedestrian crossing in front of the school")."""
    said = {lemma for found in _lemmas(verb).values() for lemma in found}
    return bool(said & {"strike", "hit", "miss", "see", "spot", "notice", "knock", "clip", "avoid"})


def _crossing_named_as_a_place(tokens: list[str], i: int) -> bool:
    """Whether "crossing" at ``i`` is the head of a place's name said on its own ("Canal Street towpath
    crossing.", "School crossing, 8am:"): a noun that names no road user right before it, and the
    heading's end right after. Why: read as the verb it made a road user named later cross twice, from
    no side, and put it on the other kerb. Not after a road user ("Two kids crossing.": they cross)."""
    if tokens[i] != "crossing" or not i or (i + 1 < len(tokens) and tokens[i + 1] not in _HEADING_ENDS):
        return False
    before, pos = tokens[i - 1], _pos(tokens[i - 1])
    named = "NOUN" in pos or (not pos and before.isalpha())  # (a name the lexicon lacks: "towpath")
    return named and before not in FUNCTION_WORDS and not _actor_at(tokens, i - 1)


def _actor_at(tokens: list[str], i: int) -> bool:
    """Whether an actor's name starts at ``i`` (of any length: "bus" in "bus stops" too)."""
    return i < len(tokens) and any(
        TABLE[key][0] == "actor" and all(k in forms(tokens[i + j]) for j, k in enumerate(key))
        for w in forms(tokens[i])
        for key in _BY_FIRST.get(w, ())
        if i + len(key) <= len(tokens)
    )


def _best(tokens: list[str], i: int) -> tuple[str, ...] | None:
    """The longest phrase at ``i``; of equally long ones the one written as the text has it."""
    if not _starts_phrase(tokens[i]):
        return None
    return _best_in(tuple(tokens[i : i + _LONGEST_KEY]))


@lru_cache(maxsize=1 << 14)
def _starts_phrase(word: str) -> bool:
    """Whether a table phrase may start at ``word`` (one of its forms begins one). Most words begin
    none, and for them no phrase need be looked for in the words that follow."""
    return any(w in _BY_FIRST for w in forms(word))


#: The most words a table phrase has: what follows them cannot change the phrase found at a word.
_LONGEST_KEY = max(map(len, TABLE))


@lru_cache(maxsize=1 << 16)
def _best_in(window: tuple[str, ...]) -> tuple[str, ...] | None:
    """:func:`_best` at the start of ``window``, the words from there that a phrase can span. Why a
    cache: the rules ask what phrase stands at a word thousands of times a text, at the same words."""
    keys = list(_match(window, 0))
    if not keys:
        return None
    return max(keys, key=lambda k: (len(k), k == window[: len(k)], k))


_DETERMINERS = {"the", "a", "an", "its", "our", "my", "their", "his", "her", "this", "that", "another", "some"}


#: How many plain modifiers may stand between a road user's noun and the determiner of its phrase.
_MODIFIERS_BEFORE = 2


def _plain_modifier(word: str, read_words: bool = False) -> bool:
    """Whether ``word`` may stand inside a noun phrase between its determiner and its noun: an
    adjective, a participle or a noun used as one ("silver", "grey", "rental", "injured"), or a name
    no dictionary has ("Altima"); not a function word, a number, punctuation or a road user's noun
    (that one heads a phrase of its own), nor a word the reader reads as a place or a state
    ("oncoming", "lead", "parked"): in "the oncoming lorry" the place may pick the road user out
    as well as the mention before, and those words are left to the rules that read them."""
    if word in FUNCTION_WORDS or not word[:1].isalpha() or _actor_word(word) or (word,) in TABLE and not read_words:
        return False  # (a place or state the reader reads picks its road user out: "the oncoming lorry")
    pos = _pos(word)
    return not pos or bool(pos & {"ADJ", "NOUN"}) or word.endswith(("ing", "ed"))


#: Determiners that point back to one named before, read past a phrase's modifiers.
_POINTING_BACK = frozenset(("the", "this", "that", "its", "our", "my", "their", "his", "her"))


def _before_a_described_place(tokens: list[str], i: int) -> str | None:
    """The word before the noun phrase of a place at ``i`` whose determiner stands apart from its noun
    by a word or two that describe it ("off the dropped kerb", "along the busy pavement", "from the
    opposite footpath": "off", "along", "from"), or None where no such words stand between. Why: the
    preposition that governs the phrase says whether its road user comes off the place or goes along
    it, whatever the phrase says of the place; a verb right before the determiner ("hugging the kerb")
    is no describing word, and is left as it was."""
    j = i - 1
    while j > 0 and i - j <= _MODIFIERS_BEFORE and tokens[j] not in _DETERMINERS and _plain_modifier(tokens[j], True):
        j -= 1
    if j == i - 1 or j < 1 or tokens[j] not in _DETERMINERS:
        return None
    return tokens[j - 1]


def _phrase_determiner(tokens: list[str], i: int) -> str:
    """The determiner that points back from the start of the noun phrase of the road-user noun at
    ``i``, past a few plain modifiers ("the white van", "the injured cyclist", "this grey Golf"):
    whether it is said again is the phrase's, not only the word's right before it. Empty where none
    opens it. One that brings a road user in new ("a silver hatchback") is left to the word right
    before the noun, as the rules that tell a new road user from the ego's own vehicle read it ("A
    silver hatchback doing 40 braked when ...": the story's own vehicle)."""
    opener = _phrase_opener(tokens, i)
    return opener if opener in _POINTING_BACK else ""


def _word_before_phrase(tokens: list[str], i: int, describes) -> str:
    """The word before the noun phrase of the noun at ``i``, past up to :data:`_MODIFIERS_BEFORE` words
    for which ``describes`` holds; empty at the start of the text."""
    j = i - 1
    while j >= 0 and i - j <= _MODIFIERS_BEFORE and describes(tokens[j]):
        j -= 1
    return tokens[j] if j >= 0 else ""


def _phrase_opener(tokens: list[str], i: int, read_words: bool = False) -> str:
    """The word before the noun phrase of the noun at ``i``, past plain modifiers ("a skip lorry": "a"),
    and with ``read_words`` past the modifiers the reader reads as a place or a state too ("the oncoming
    lorry": "the")."""
    return _word_before_phrase(tokens, i, lambda word: _plain_modifier(word, read_words))


def _only_describes(word: str) -> bool:
    """Whether ``word`` can only describe a noun (an adjective, a noun used as one, a number), never
    be a verb or a determiner ("little", "white", "2"; not "drives", not "the")."""
    if word in _DETERMINERS:
        return False
    pos = _pos(word)
    return word.isdigit() or "ADJ" in pos or pos == {"NOUN"}


def _phrase_det(tokens: list[str], i: int) -> str:
    """The determiner of the noun phrase whose noun starts at token ``i``, past the words that only
    describe it ("a little girl", "the big white van", "my 2 kids": "a", "the", "my"); "" where there is
    none. Stricter than :func:`_phrase_opener`: it stops at a word that may be a verb ("drives the
    school van"), since a rewritten phrase must not lend a road user a determiner not its own."""
    opener = _word_before_phrase(tokens, i, _only_describes)
    return opener if opener in _DETERMINERS else ""


def _relation_length(tokens: list[str], k: int) -> int:
    """The length of the relation phrase the table lists at token ``k`` ("in front of us"), or 0."""
    key = _best(tokens, k) if k < len(tokens) else None
    return len(key) if key is not None and TABLE[key][0] == "relation" else 0


def _kind_at(tokens: list[str], i: int) -> tuple[str, int] | None:
    """The road-user type a phrase at ``i`` names and its length, or None (for :mod:`discourse`; also
    past the last word, where callers ask what follows a word that ends the text)."""
    if not 0 <= i < len(tokens) or not _starts_phrase(tokens[i]):
        return None
    return _kind_in(tuple(tokens[i : i + _LONGEST_KEY]))


@lru_cache(maxsize=1 << 16)
def _kind_in(window: tuple[str, ...]) -> tuple[str, int] | None:
    """:func:`_kind_at` at the start of ``window`` (cached as :func:`_best_in` is)."""
    key = _best_in(window)
    if key is not None and len(key) > 1 and TABLE[key][0] != "actor" and TABLE.get(key[:1], ("",))[0] == "actor":
        if window[len(key) - 1] == key[-1] + "s":  # ("the bus stops": the bus, then its verb, as scan reads it)
            key = key[:1]
    return (str(TABLE[key][1]), len(key)) if key is not None and TABLE[key][0] == "actor" else None


def _said_of_others(tokens: list[str], i: int) -> bool:
    """Whether the words at ``i`` name other road users or traffic, so that a place word right before
    them is their attribute ("oncoming traffic", "oncoming cars", "the oncoming lorry"), not a place of
    the road user the clause is about."""
    return i < len(tokens) and (tokens[i] in ego_speed.TRAFFIC or _kind_at(tokens, i) is not None)


def _known(tokens: list[str], i: int) -> bool:
    """Whether the reader has a phrase starting at ``i`` (for :mod:`discourse`)."""
    return _best(tokens, i) is not None


def _adverb(word: str) -> bool:
    return word.endswith("ly") or word in ("hard", "fast", "straight", "just", "then")


def _number(
    tokens: list[str], i: int, imperial: bool = False, metric: bool = False, narrated: bool = False
) -> tuple[str, float, int] | None:
    """(kind, value SI, tokens used) of a number at ``i``: a speed, a distance, or something to skip
    (``imperial``: the text measures lengths in feet or yards, so a bare speed is in mph; ``metric``: it
    is set where km/h is signed, so a bare speed is in km/h; ``narrated``: told in the first person)."""
    value = float(tokens[i])
    nxt = tokens[i + 1] if i + 1 < len(tokens) else ""
    if Q.crash_change_of_speed(tokens, i):  # ("delta-v V1 = 38 km/h": how hard it hit, no one's speed)
        return "skip", value, 2 if nxt in V.SPEED_UNITS else 1
    if Q.over_the_limit(tokens, i):  # ("8 mph over the limit": how far over, no one's speed)
        return "skip", value, 2 if nxt in V.SPEED_UNITS else 1
    if nxt in V.SPEED_UNITS and (changed := Q.from_one_speed_to_another(tokens, i)) is not None:
        if not changed[2]:  # ("accelerated from 20 mph to 40 mph": the speed it reached, when what follows happens)
            return "speed", changed[0], changed[1]
        return "speed_range", (value * V.SPEED_UNITS[nxt], changed[0]), changed[1]  # ("slowed from 55 mph to 20 mph")
    if nxt in V.SPEED_UNITS:
        return "speed", value * V.SPEED_UNITS[nxt], 2
    if nxt in ("m", "meters", "metres", "meter", "metre"):
        return "distance", value, 2
    if nxt == "car" and tokens[i + 2 : i + 3] in (["length"], ["lengths"]):  # "2 car lengths back"
        return "distance", value * Q.CAR_LENGTH_M, 3
    if nxt in ("m/s²", "m/s2"):  # "brakes at 6 m/s²": how hard
        return "accel", value, 2
    if (gap := Q.headway_m(tokens, i)) is not None:  # "a 2 s gap" at 72 km/h: 40 m
        return "distance", gap, 2
    if nxt in ("s", "sec", "seconds", "second", "g", "%", "deg", "degrees", "kg", "km"):
        return "skip", value, 2
    if Q.other_measure(tokens, i):  # ("50 cm to spare", "20 minutes later", "at 10 past 5"): no speed
        return "skip", value, 2
    if nxt in (":", "am", "pm", "hrs", "hours", "o'clock", "oclock"):  # ("about 6 pm", "at 07:50"): a time of day
        if nxt == ":" and i + 2 < len(tokens) and tokens[i + 2].isdigit():  # ("07:50", "07:50 hrs"; not what follows)
            return "skip", value, 4 if tokens[i + 3 : i + 4] in (["hrs"], ["hours"], ["am"], ["pm"]) else 3
        return "skip", value, 2
    if nxt in ("to", "-") and i + 3 < len(tokens) and re.fullmatch(r"\d+(?:\.\d+)?", tokens[i + 2]):
        unit = tokens[i + 3]
        if unit in V.SPEED_UNITS:  # "from 50 to 20 km/h": the speed, then the one it goes to
            return "speed_range", (value * V.SPEED_UNITS[unit], float(tokens[i + 2]) * V.SPEED_UNITS[unit]), 4
    if nxt == "down" and tokens[i + 2 : i + 3] == ["to"] and i + 4 < len(tokens) and Q.is_number(tokens[i + 3]):
        unit = tokens[i + 4]
        if unit in V.SPEED_UNITS:  # "70 down to 30 km/h": the speed it had, then the one it braked to
            return "speed_range", (value * V.SPEED_UNITS[unit], float(tokens[i + 3]) * V.SPEED_UNITS[unit]), 5
    if Q.number_speed(tokens, i):  # ("I was going 40 speed only", "at 60 speed on the flyover")
        return "speed", value * Q.carried_unit(tokens, i, imperial, metric, narrated), 2
    if Q.clock_hour(tokens, i):  # ("Today morning, around 7, ...", "at 9 last night"): an hour, no speed
        return "skip", value, 1
    if (count := counted_in_figures(tokens, i, _kind_at)) is not None:  # ("2 escooters riding side by side")
        return "count", count, 1
    if nxt in ("lanes", "lane") or (nxt == "-" and i + 2 < len(tokens) and tokens[i + 2] in ("lane", "lanes")):
        if value == int(value) and 1 <= value <= 8:  # "3 lanes", "a 2-lane road": lanes a direction
            return "lanes", int(value), 2 if nxt != "-" else 3
    if i >= 3 and tokens[i - 1] == "of" and tokens[i - 3] in ("lane", "lanes"):
        return "skip", value, 1  # ("in lane 1 of 3": how many lanes, no speed)
    if Q.of_a_total(tokens, i):  # ("Run 3 of about 6", "session 4 of 6": how many there are, no speed)
        return "skip", value, 1
    if Q.place_in_a_series(tokens, i):  # ("ACC at 3 of 5", "gap set to 3 (of 5)", "ACC at 3 bars": a setting)
        return "skip", value, 1
    prev = Q.before_hedge(tokens, i) if i > 0 else ""  # ("doing at least 70", "going well over 60")
    to_changed = tokens[i - 1] == "to" and _changes_speed_before(
        tokens, i - 1
    )  # ("speeds up to 80": the speed it reaches)
    at = prev in ("at", "doing", "about", "around", "of") or to_changed or Q.after_at(tokens, i) or Q.held_on(tokens, i)
    at = at or ego_speed.speedometer_reading(tokens, i)  # ("60 on the speedo", "the speedo said 45")
    at = at or ego_speed.bare_owned(tokens, i) or Q.after_speed_head(tokens, i)  # ("than my 70", "speed: 50")
    at = at or ego_speed.cruise_setting(tokens, i)  # ("Cruise set to 100")
    if at and _counted(nxt):
        return "skip", value, 1  # ("Of 63 crossings observed, none ...": how many, no speed)
    if at and 3 <= value <= 250:
        # "at 120", "at a steady 50": in the unit said before
        return "speed", value * Q.carried_unit(tokens, i, imperial, metric, narrated), 1
    ends = nxt in ("", ".", ",", ";", "!", "?", "and", "then", "when", "while", "but")
    hedged = prev != tokens[i - 1]  # ("going well over 60 passes me": a speed, however the clause goes on)
    going = prev in _MOTION_BEFORE_SPEED or Q.before_manner(tokens, i) in _MOTION_BEFORE_SPEED  # ("going slowly 20")
    where = going and nxt in Q.WHERE_AFTER_SPEED  # ("going 40 down the high street")
    if i == 1 and tokens[0] in _HEADING_VERBS:
        return "skip", value, 1  # ("Drive 3 - please read": the heading's number, no speed)
    going = going and not (prev in _DO and _another_occasion(tokens, i))  # ("I did 15 on that road once")
    if (going or Q.after_ego(tokens, i)) and 3 <= value <= 250 and (ends or hedged or where):
        return "speed", value * Q.carried_unit(tokens, i, imperial, metric, narrated), 1
    return "unknown", value, 1


#: The finite forms of "doing 50", and the words that, closing their clause, put it on another occasion
#: ("once", "before", "last year", "years ago", "usually"): a speed of a habit or of another day.
_DO = frozenset({"did", "does"})
_ANOTHER_OCCASION = frozenset({"once", "before", "ago", "usually", "normally", "often", "always", "sometimes"})
_LAST = frozenset({"last", "every"})


def _another_occasion(tokens: list[str], i: int) -> bool:
    """Whether the clause of the number at ``i`` ends with a time of another occasion ("I did 15 on that
    road once, and today ...", "we did 80 on the motorway last year, but ..."): not this story's speed.
    ("did 60 on the ring road once the lights changed": "once" opens a clause, and does not close it.)"""
    k = i + 1
    while k < len(tokens) and tokens[k] not in Q.NOTE_ENDS:
        k += 1
    return tokens[k - 1] in _ANOTHER_OCCASION or (k - i > 2 and tokens[k - 2] in _LAST)


def _counted(word: str) -> bool:
    """Whether ``word``, right after a bare number, is a plural noun the number counts ("63 crossings",
    "about 40 vehicles"): units of speed and length are read before."""
    found = _lemmas(word)
    return word.endswith("s") and "NOUN" in found and word not in found["NOUN"]


def _changes_speed_before(tokens: list[str], k: int) -> bool:
    """Whether a change of speed is said right before token ``k`` ("slows", "speeds up", "brakes")."""
    for start in range(max(k - 4, 0), k):
        key = _best(tokens, start)
        if key and start + len(key) == k and TABLE[key][0] == "behaviour":
            if TABLE[key][1][0] in ("change_speed", "sudden_stop", "stop"):
                return True
    return False


#: Verbs of going in the base form, which opening a text before a bare number name a numbered part of
#: it, a heading ("Drive 3 - please read", "Run 2:"), not a speed: a writer opening with their speed says
#: the verb's -ing or past form ("Driving 30, a kid ...", "Drove 40 down ...") or a unit.
_HEADING_VERBS = frozenset({"drive", "go", "travel", "run", "ride"})
#: Verbs of going after which a bare number is a speed ("the ego goes 50, ...", "driving 30 when"), and
#: "did"/"does", the finite forms of "doing 50" ("we did 40 along the main road", "he does 60 here").
_MOTION_BEFORE_SPEED = frozenset(
    "go goes going went drive drives driving drove travel travels travelling traveling travelled traveled did "
    "does".split()
)


#: The side a road user is on, seen from one that came from its other side.
_OTHER_SIDE = {"left": "right", "right": "left"}


def scan(text: str) -> tuple[list[tuple[str, list[_Mention]]], list[str], list, list[str]]:
    """(clauses as (link, mentions), ignored words, words read as others, the tokens the mentions
    index) of ``text``; a word that is only a verb and unknown stays in its clause as an
    ``unknown_verb`` mention."""
    return _scan(text)[:4]


def _scan(text: str) -> tuple[list[tuple[str, list[_Mention]]], list[str], list, list[str], bool]:
    """:func:`scan`, and whether the writer only watched from beside the road and was left out of the
    tokens (:mod:`vei_scenario.language.witness_on_foot`)."""
    tokens = _tokens(text, brackets=True)
    metric = Q.metric_country(tokens)  # ("in the ute": the ego's own, which framing names "the ego")
    clauses: list[tuple[str, list[_Mention]]] = [("sequence", [])]
    read_as: list[tuple[str, str]] = [
        (typed, read) for typed, read in zip(_tokens(text, spell=False, brackets=True), tokens) if typed != read
    ]
    framed: list[str] = []
    tokens = sides.place_sides_in_brackets(tokens)  # ("pulls out of stop (left)": on the left)
    tokens = wala_riders(tokens)  # ("one bike wala came wrong side": a motorcyclist)
    tokens = acts_said_as_nouns(tokens, _specific_act, _kind_at)  # ("made a sudden swerve into my lane": swerved)
    said = re.findall(r"[a-z']+|[.,;:!?]", text.lower())  # (as written: the tokens say "you are" as "i am")
    tokens = norms.without_norms(tokens, framed, said)  # ("but you still have to give way": a rule, no deed)
    tokens = addressee.spoken_to(tokens, _kind_at)  # ("To the jogger on Elm St - you ran across": the jogger)
    tokens = run_on.break_after_a_speed(tokens, _actor_at, FUNCTION_WORDS)  # ("20 mph a van pulled out")
    tokens = whose_act.unnamed_rider(tokens, _kind_at)  # ("car clipped rider": an e-scooter's rider)
    tokens = towed(tokens, _kind_at)  # ("a prime mover and trailer": one road user, before who is who)
    tokens = model_said_again(tokens, _kind_at, _known)  # ("a Honda Civic ... the Civic": the Honda)
    tokens = form_fields.without_aside_fields(tokens, _kind_at, framed)  # ("Witness: driver of the tanker behind")
    tokens = protagonist.without_witness(tokens, framed)  # ("I saw a lad run the red": a witness)
    bystander = witness_on_foot.bystander(tokens, _kind_at, _known)  # ("I was on the pavement ...": only saw it)
    tokens = witness_on_foot.without_writer(tokens, framed) if bystander else tokens
    tokens = ego.frame(tokens, _kind_at, _known, framed, protagonist.frame)  # (by a role, its driver, a witness)
    tokens = owned_by_name.frame(tokens, _kind_at, _known, framed)  # ("Lena's Mini", "the survey team's van")
    tokens = narrator_vehicle.frame(tokens, _kind_at, _known, framed)  # (the writer in it or testing it)
    tokens = generic_ego.frame(tokens, _kind_at, _known, framed)  # (the ego as drivers in general)
    tokens = ego_speed.at_the_limit(tokens)  # ("doing the 20 limit": at 20)
    tokens = ego_speed.the_limit_then_its_number(tokens)  # ("doing the limit, seventy, when": doing 70)
    tokens = without_comment_clauses(tokens)  # ("I reckon he was doing 90": he was doing 90)
    tokens = Q.without_guesses(tokens, _MOTION_BEFORE_SPEED)  # ("going, I don't know, 40": going 40)
    tokens = without_comments_beside_speeds(tokens)  # ("came out fast, I'd say 25 km/h": its 25 km/h)
    proper = proper_names(text)
    tokens = shared_scooters(tokens, proper, lambda w: "VERB" in _pos(w))  # ("a Lime came past": an e-scooter)
    tokens = named_riders.named_riders(
        tokens, text, proper, _kind_at, FUNCTION_WORDS.__contains__
    )  # ("Priya, who was riding": a cyclist)
    tokens, dropped = discourse.resolve(tokens, _kind_at, _known, proper)  # (who is who; words out)
    tokens = whose_act.ridden_one(tokens, _kind_at)  # ("E-scooters are everywhere. A kid on one shot out")
    tokens = whose_act.the_rider(tokens, _kind_at)  # ("a cyclist ... the rider brakes": the cyclist)
    tokens = whose_act.the_person_said_back(tokens, _kind_at)  # ("a cyclist ... the boy rode off": the cyclist)
    dropped = framed + dropped
    ignored: list[str] = [w for w in dropped if w not in FUNCTION_WORDS and w.isalpha()]
    left_hand, ring = sides.drives_on_left(tokens, text), "roundabout" in tokens
    imperial = Q.imperial_lengths(text.lower())  # ("ten feet ahead": a writer whose bare speeds are mph)
    imperial = imperial or Q.road_number_written_whole(text.lower())  # ("A46 towards Lincoln": a British road)
    imperial = imperial or Q.a_road_named(text.lower())  # ("on the A-road": a British road by its class)
    written = re.findall(r"[a-z]+|\d+", plain_letters(text.lower()))  # (as written, figures too, before any is read)
    imperial = imperial or said_in_miles_english(written)  # ("two hundred quid": British English)
    imperial = imperial or road_called_by_its_limit(tokens)  # ("doing 40 in a 30": a British town road)
    narrated = bystander or motion.told_in_the_first_person(text, tokens)  # (whose bare speeds are their signs')
    imperial = imperial or (narrated and told_in_miles_english(written, text))  # ("I was doing 20 ... the pavement")

    def ending_at(k: int) -> int | None:  # the start of the road-user mention whose last word is token k
        return next(
            (x.start for _, ms in clauses for x in ms if x.slot in ("actor", "pronoun") and x.end == k + 1), None
        )

    i = 0
    while i < len(tokens):
        if (split := motion.manner_compound(tokens, i, _specific_behaviour)) is not None:
            tokens[i : i + 1] = split  # ("hard-brakes": "brakes hard")
        elif (split := phrasal_compound(tokens, i, _specific_act, _act_of_a_road_user)) is not None:
            tokens[i : i + 1] = split  # ("a turn-across": "turn across")
        tok = tokens[i]
        j = i - 1  # the word before, past a determiner ("in front of the ego": "of")
        while j > 0 and tokens[j] in _DETERMINERS:
            j -= 1
        prev = tokens[j] if j >= 0 else ""
        det = tokens[i - 1] if i and tokens[i - 1] in _DETERMINERS else ""
        if tok in ".;!?":
            clauses.append(("sequence", []))
            i += 1
            continue
        if tok in (",", ":", "'s"):
            clauses[-1][1].append(_Mention("punct", tok, tok, i, prev))
            i += 1
            continue
        if re.fullmatch(r"\d+(?:\.\d+)?", tok) and not (sides.lanes_away(tokens, i) or S.lanes_moved(tokens, i)):
            # (not "2 lanes to our left", "moved over 1 lane": a place or a move, not the road's lanes)
            kind, value, used = _number(tokens, i, imperial, metric, narrated)
            words = " ".join(tokens[i : i + used])
            if kind in ("speed", "distance", "speed_range") and Q.lateral(tokens, i, used):
                kind = "skip"  # ("a lateral velocity of 1 m/s", "1.5 m clearance"): across the road, no travel
            if kind == "distance" and Q.a_size(tokens, i, used):
                kind = "skip"  # ("a pothole about a foot across"): how big a thing is, no gap
            if kind == "distance" and Q.a_stretch(tokens, i, used):
                kind = "skip"  # ("tailgated me for a good 300 m", "for 10 seconds"): how far or long, no gap
            unit = tokens[i + 1 : i + 2] != [] and tokens[i + 1] in V.SPEED_UNITS
            owners = Q.owners(tokens, i, unit, ending_at, lambda w: _pos(w) == {"NOUN"} and w not in FUNCTION_WORDS)
            if kind == "unknown":
                ignored.append(tok)
            elif kind == "speed_range":  # the speed it has, and (its own slot) the one it changes to
                clauses[-1][1].append(_Mention("speed", value[0], words, i, prev, end=i + used))
                clauses[-1][1].append(_Mention("speed_to", value[1], words, i, prev, end=i + used))
            elif kind != "skip":
                clauses[-1][1].append(_Mention(kind, value, words, i, prev, end=i + used, owners=owners))
            i += used
            continue
        side_at = _lane_to_side(tokens, i)
        if side_at is not None:  # "changes to the left lane": a lane change, and the side it moves to
            after = tokens[side_at + 2] if side_at + 2 < len(tokens) else ""
            words, side = " ".join(tokens[i:side_at]), tokens[side_at]
            clauses[-1][1].append(_Mention("behaviour", ("change_lane", {}), words, i, prev, side, side_at, det))
            clauses[-1][1].append(_Mention("toward", side, side, side_at, tokens[side_at - 1], after, side_at + 2))
            i = side_at + 2
            continue
        origin = sides.compass_origin_at(tokens, i)
        if origin is not None:  # "from the east arm": where it lies from the ego once the ego's heading is read
            clauses[-1][1].append(
                _Mention("origin", origin[:2], " ".join(tokens[i : origin[2]]), i, prev, end=origin[2])
            )
            i = origin[2]
            continue
        heading = sides.heading_at(tokens, i)
        if heading is not None:  # "eastbound", "heading north": related to the ego's heading once both are read
            clauses[-1][1].append(_Mention("heading", heading, tok, i, prev, end=i + 1))
            i += 1
            continue
        towards = sides.towards_in_ego_lane(tokens, i)
        if towards is not None:  # "coming on our lane", "heading at us": at the ego, in its lane
            words = " ".join(tokens[i:towards])
            clauses[-1][1].append(_Mention("relation", "oncoming", words, i, prev, end=towards, det=det))
            if sides.on_the_egos_line(tokens, i, towards):  # ("coming at us head-on": in the ego's lane)
                clauses[-1][1].append(_Mention("over_line", None, words, i, prev, end=towards))
            i = towards
            continue
        at_ego = sides.coming_at_the_ego(tokens, i)
        if at_ego is not None:  # "came round the corner towards me": past where it comes, at the ego
            words = " ".join(tokens[i:at_ego])
            clauses[-1][1].append(_Mention("relation", "oncoming", words, i, prev, end=at_ego, det=det))
            if sides.on_the_egos_line(tokens, i, at_ego):  # ("came straight at me": in the ego's lane)
                clauses[-1][1].append(_Mention("over_line", None, words, i, prev, end=at_ego))
            i = at_ego
            continue
        half = sides.on_the_egos_half(tokens, i, _actor_word)
        if half is not None:  # "on her side of the road": the ego's half, the ego told of in the third person
            words = " ".join([tok, "our", *tokens[half - 1 : half]]) if tokens[half - 1] == "lane" else ""
            words = words or " ".join([tok, "our", "side", "of", "the", "road"])
            clauses[-1][1].append(_Mention("relation", "ahead", words, i, prev, end=half, det=det))
            i = half
            continue
        middle = sides.in_the_middle_of_the_road(tokens, i)
        if middle is not None:  # "down the middle of the road": on the line between the two halves
            clauses[-1][1].append(_Mention("mid_road", None, " ".join(tokens[i:middle]), i, prev, end=middle))
            i = middle
            continue
        blind = sides.over_a_blind_place(tokens, i)
        if blind is not None:  # "came over the crest": into sight towards the ego (the place is read on)
            clauses[-1][1].append(_Mention("relation", "oncoming", tok, i, prev, end=blind, det=det))
            i = blind
            continue
        against = sides.the_other_direction(tokens, i)
        if against is not None:  # "in the contrary direction": it comes towards the ego
            words = " ".join(tokens[i:against])
            clauses[-1][1].append(_Mention("relation", "oncoming", words, i, prev, end=against, det=det))
            i = against
            continue
        if tok in ("left", "right") and len(_best(tokens, i) or ()) <= 1 and sides.not_a_side(tokens, i):
            ignored.append(tok)  # ("cut right across", "as we left the roundabout": no side)
            i += 1
            continue
        said = sides.phrase_at(tokens, i, left_hand, ring) or sides.named_road_at(tokens, i, proper)
        if said is not None:  # a lane, kerb or arm and its side ("in the offside lane", "a side road on my left")
            words = " ".join(tokens[said.start : said.end])
            nxt = tokens[said.end] if said.end < len(tokens) else ""
            if not said.mentions:
                ignored.extend(tokens[said.start : said.end])  # (a side of a vehicle: no place)
            for slot, value in said.mentions:
                clauses[-1][1].append(_Mention(slot, value, words, said.start, said.prep or prev, nxt, said.end, det))
            i = said.end
            continue
        key = _best(tokens, i)
        if key and len(key) > 1 and turn_taken_at(tokens, i):
            key = (tok,)  # ("hung a right in front of me": the turn, then where)
        if key and len(key) > 1 and TABLE[key][0] != "actor" and TABLE.get(key[:1], ("",))[0] == "actor":
            last = tokens[i + len(key) - 1]  # "the bus stops": the bus, then its verb ("at a bus stop": a place)
            verb = last != key[-1] and last == key[-1] + "s"  # "the bus stops"
            opens = prev in _OPENERS or (prev in _DETERMINERS and i == 1)  # (its sentence's subject)
            opens = opens or _someone_new_opens(tokens, i)  # ("Also one pedestrian crossing far ahead")
            # "A pedestrian crossing from the right ...", "also a pedestrian crossing the road" (its object)
            takes_object = tokens[i + len(key) : i + len(key) + 1] in (["the"], ["a"], ["an"], ["my"], ["our"])
            # ("struck a pedestrian crossing in the crosswalk": where the person crosses)
            struck = i > 1 and tokens[i - 1] in _DETERMINERS and _struck_someone(tokens[i - 2])
            where = tokens[i + len(key) : i + len(key) + 1]  # (or a road's name: "crossing Broadway")
            crosses = where in _WHERE_ONE_CROSSES or (where[:1] and where[0] in proper)
            takes_object = takes_object or (struck and crosses)
            participle = last.endswith("ing") and (opens or takes_object)
            if prev not in _PLACE_PREPOSITIONS and (verb or participle):
                key = key[:1]
        adverb = toward_at = None  # (toward_at: where the side it moves to is said)
        just_right = tokens[i + 1 : i + 2] == ["right"] and tokens[i + 2 : i + 3] and tokens[i + 2] in _RIGHT_BEFORE
        stressed = (not just_right or tokens[i + 2 : i + 3] == ["across"]) and i + 2 < len(tokens)
        stressed = stressed and sides.not_a_side(tokens, i + 1)  # ("rode right across": a stressed particle)
        just_right = just_right or stressed
        if (
            (key is None or len(key) == 1)
            and i + 2 < len(tokens)
            and tokens[i + 1] in ("left", "right")
            and not just_right
        ):
            # "swerves left into our lane": the verb's phrase around the side it moves to
            skipped = _best(tokens[: i + 1] + tokens[i + 2 :], i)
            if skipped is not None and len(skipped) > 1 and TABLE[skipped][0] == "behaviour":
                key, toward_at = skipped, i + 1
        if (key is None or len(key) == 1) and toward_at is None and stressed:
            # "pulled right out": the verb's phrase around a stressing "right"
            skipped = _best(tokens[: i + 1] + tokens[i + 2 :], i)
            if skipped is not None and len(skipped) > 1 and TABLE[skipped][0] == "behaviour":
                key, adverb = skipped, tokens[i + 1]
        if (key is None or len(key) == 1) and toward_at is None and i + 2 < len(tokens) and _adverb(tokens[i + 1]):
            # "walks slowly across": the phrase around an adverb, and the adverb on its own
            skipped = _best(tokens[: i + 1] + tokens[i + 2 :], i)
            if skipped is not None and len(skipped) > 1:
                key, adverb = skipped, tokens[i + 1]
        to_a_stop = _best(tokens, i + 1) if i + 1 < len(tokens) else None  # ("drew to a stop": no motion verb)
        to_a_stop = to_a_stop is not None and TABLE[to_a_stop][0] == "to_stop"
        if (
            key is None
            and tok not in FUNCTION_WORDS
            and i + 1 < len(tokens)
            and not to_a_stop
            and _verb_before(tok, tokens[i + 1], tuple(tokens[max(i - 2, 0) : i]))
            and not (tokens[i + 1] == "into" and into_road_user(tokens, i + 1))  # ("banged into my car": a hit)
            and not set(_lemmas(tok).get("VERB", ())) & _CARRYING  # ("taken to A&E", "towed away")
        ):
            # a verb the lexicon lacks, with where it goes ("swung into my lane", "bolted across the road"):
            # read as the plain motion verb with the same words, when that is a behaviour
            to_a_place = tokens[i + 1] in ("to", "in") and tokens[i + 2 : i + 3] and tokens[i + 2] in _DETERMINERS
            into = ["into"] if to_a_place else tokens[i + 1 : i + 2]  # ("changing to our lane", not "decides to")
            for plain in PLAIN_MOTION_VERBS:
                swapped = _best(tokens[:i] + [plain] + into + tokens[i + 2 :], i)
                if (
                    swapped is not None
                    and len(swapped) > 1
                    and TABLE[swapped][0] == "behaviour"
                    and TABLE[swapped][1][0] != "keep_going"  # (a specific behaviour, or nothing is read)
                ):
                    key = swapped
                    read_as.append((" ".join(tokens[i : i + len(swapped)]), " ".join(swapped)))
                    break
        if key is None and (tok == "must" or (tok in _MODAL_VERBS and tokens[i + 1 : i + 2] == ["to"])):
            clauses[-1][1].append(_Mention("modal", tok, tok, i, prev, end=i + 1))  # "it has to brake"
            i += 1
            continue
        if key is None and tok in L.CONJUNCTIONS and not Q.compared(tokens, i):  # ("the same lane as": no clause)
            clauses[-1][1].append(_Mention("conj", tok, tok, i, prev, end=i + 1))
            i += 1
            continue
        if key is None and tok in L.RELATIVE and tokens[i - 1 : i] and tokens[i - 1] in ("in", "at", "on", "during"):
            clauses[-1][1].append(_Mention("conj", tok, tok, i, prev, end=i + 1))  # "a test in which a truck ..."
            i += 1
            continue
        if key is None and tok in L.RELATIVE:
            clauses[-1][1].append(_Mention("relative", tok, tok, i, prev, end=i + 1))
            i += 1
            continue
        if key is None:
            if tok not in FUNCTION_WORDS:
                ignored.append(tok)
                pos = _pos(tok)
                after_actor = (
                    bool(clauses[-1][1]) and clauses[-1][1][-1].slot == "actor" and clauses[-1][1][-1].end == i
                )
                verb = "VERB" in pos and not pos & {"ADJ", "ADV"} and not tok.endswith(("ing", "ed"))
                if _after_article(tokens, i) or _counted_plural(tokens, i) or _before_auxiliary(tokens, i):
                    verb = False  # (in a noun phrase: "the petrol station" names a place, no verb)
                if _month_of_a_date(tokens, i):
                    verb = False  # ("On 3 March a bus pulled out": a date, not the verb "march")
                if i + 1 < len(tokens) and _modifies_actor(tokens, i + 1):
                    verb = False  # a word naming what kind before an actor ("a police car", "a Ford Transit van")
                elif _party_crossing(tokens, i):  # ("my son stepped out to cross": on foot, a walker)
                    if clauses[-1][1] and clauses[-1][1][-1].slot == "pronoun" and clauses[-1][1][-1].end == i:
                        clauses[-1][1].pop()  # ("her grandson": whose he is, no one acting)
                    clauses[-1][1].append(_Mention("actor", "pedestrian", tok, i, prev, end=i + 1, det=det))
                    ignored.pop()
                elif (
                    _new_unknown_subject(tokens, i)
                    and "VERB" not in pos
                    and _does_soon(tokens, i + 1)
                    and not rides_next(tokens, i + 1)  # ("a Voi rider": what is ridden, the rider the subject)
                ):
                    # "a unicorn runs out": someone the reader has no word for does something: a road
                    # user of its own (its kind read from what it does), not whoever was named last
                    clauses[-1][1].append(_Mention("actor", UNKNOWN_KIND, tok, i, prev, end=i + 1, det=det))
                    ignored.pop()
                if verb or (not pos and after_actor and tok.endswith("s")):  # (a word lemminflect lacks)
                    clauses[-1][1].append(_Mention("unknown_verb", tok, tok, i, prev, end=i + 1))
            i += 1
            continue
        slot, value = TABLE[key]
        if slot == "relation" and value == "oncoming" and sides.approaches_from(tokens, i, key):
            i += len(key)  # ("approaching from behind": where it comes from is said next)
            continue
        placed = sides.place_after_degree(tokens, i, key, _relation_length) if slot != "relation" else None
        if placed is not None:  # ("right in front of me": how exactly, and the place; "right ahead" too)
            if slot != "noise":
                clauses[-1][1].append(_Mention(slot, value, " ".join(key), i, prev, end=i + len(key)))
            rel = TABLE[_best(tokens, i + 1)][1]
            nxt = tokens[placed] if placed < len(tokens) else ""
            clauses[-1][1].append(_Mention("relation", rel, " ".join(tokens[i + 1 : placed]), i + 1, tok, nxt, placed))
            i = placed
            continue
        if (
            slot == "relation"
            and key[-1] == "at"
            and re.fullmatch(
                r"\d+(?:\.\d+)?", tokens[i + len(key) : i + len(key) + 1][0] if i + len(key) < len(tokens) else ""
            )
        ):
            i += len(key) - 1  # ("coming at 40 km/h": a speed, not at the ego)
            continue
        if slot == "weather" and S.superlative(tokens[i], key):
            ignored.append(tok)  # ("not the driver's finest moment", "the clearest view"): a comparison
            i += len(key)
            continue
        if slot in ("weather", "time", "density") and (
            S.negated(tokens, i) or (slot == "weather" and S.ended(tokens, i, len(key)))
        ):
            ignored.extend(tokens[i : i + len(key)])  # ("no rain, clear skies", "it wasn't dark yet"): denied
            i += len(key)
            continue
        before = tokens[i - 1] if i else ""
        attributive = before in _DETERMINERS or (before.isalpha() and before not in FUNCTION_WORDS)
        if (
            slot == "weather"
            and key[-1] in L.COLOURS
            and ((before in _DETERMINERS and _names_a_thing(tokens, i + 1)) or _actor_at(tokens, i + 1))
        ):  # "a grey Audi", "the grey one", "grey van ahead brakes": the colour of something, not the sky
            ignored.extend(key)
            i += len(key)
            continue
        if slot == "time" and S.time_in_a_name(tokens, i, len(key), proper):
            ignored.extend(key)  # ("along Sunset Blvd", "at Sunset & 3rd": a street's name, not the time)
            i += len(key)
            continue
        if slot == "time" and before in S.DEICTIC_DAYS:
            attributive = False  # ("last night cyclist blew the red": when, a time said without a full stop)
        if slot in ("weather", "time", "density", "map") and attributive and _modifies_actor(tokens, i + len(key)):
            # "a parked ice cream van", "a night bus": a word of the setting naming what kind of road user
            j = next(k for k in range(i + len(key), len(tokens)) if _actor_at(tokens, k))
            ignored.extend(tokens[i:j])
            last = clauses[-1][1][-1] if clauses[-1][1] else None
            if last is not None and last.end == i:  # ("parked" stands right before the road user it says)
                last.end = j
            i = j
            continue
        if slot == "arm" and i >= 2 and tokens[i - 1] == "'s" and _ends_with_ego(tokens[: i - 1]):
            ignored.extend(tokens[i : i + len(key)])  # "cuts across the ego's entry": the ego's arm, not its own
            i += len(key)
            continue
        if slot == "actor" and i + len(key) < len(tokens) and tokens[i + len(key)] in _PARTS:
            i += len(key) + 1  # "50 % of the vehicle width", "a car door": a part of one, not a road user
            continue
        if slot == "relation" and len(key) == 1 and (part := sides.end_of_a_flank_part(tokens, i)):
            ignored.extend(tokens[i:part])  # "into my rear passenger door": a part of the ego's flank, no place
            i = part
            continue
        if slot in ("side", "kerb_side", "lane_side") and (part := sides.part_after_side(tokens, i + len(key), _PARTS)):
            ignored.extend(tokens[i:part])  # "the nearside wing", "its offside front corner": a part of a vehicle
            i = part
            continue
        if slot == "actor" and value != "ego" and _predicate_of_ego(tokens, i):
            ignored.append(" ".join(tokens[i : i + len(key)]))  # "I was the designated driver": the ego
            i += len(key)
            continue
        noun_here = (
            tokens[i - 1 : i] in (["the"], ["a"], ["an"]) and "NOUN" in _pos(tok) and tok not in ("stop", "crossing")
        )
        braking = "brake" in forms(tok)  # ("slammed on its brakes": the braking, said with its brakes)
        if slot == "map" and tok in ("junction", "junctions") and junctions.numbered_on_a_motorway(tokens, i):
            ignored.extend(tokens[i : i + 2])  # ("near junction 27": a motorway's, by number)
            i += 2
            continue
        if slot == "behaviour" and tokens[i + len(key) : i + len(key) + 1] in (["line"], ["sign"], ["markings"]):
            # "at the give way line", "a stop sign": a junction's, no behaviour
            clauses[-1][1].append(_Mention("map", "crossroad", " ".join(tokens[i : i + len(key) + 1]), i, prev))
            i += len(key) + 1
            continue
        if slot == "behaviour" and key[0] == "stop" and junctions.ways_stop_at(tokens, i):
            # "an all-way stop", "the 4-way stop": a junction with stop signs on its arms, no behaviour
            clauses[-1][1].append(_Mention("map", "crossroad", " ".join(tokens[i - 1 : i + 1]), i - 1, prev, end=i + 1))
            i += 1
            continue
        if (
            slot == "behaviour"
            and value[0] == "run_red_light"
            and tokens[i - 1 : i] in (["light"], ["lights"], ["signal"])
        ):
            ignored.extend(tokens[i : i + len(key)])  # "approaching traffic lights on red": the light's state
            i += len(key)
            continue
        if slot == "behaviour" and _bare_noun(tokens, i, key):
            ignored.append(tok)  # "head-on crash.", ", crash", "Full brake.": what happened, said as a noun
            i += 1
            continue
        if slot == "behaviour" and len(key) == 1 and _crossing_named_as_a_place(tokens, i):
            ignored.append(tok)  # ("Canal Street towpath crossing." as a heading: where, not who crosses)
            i += 1
            continue
        if slot == "behaviour" and len(key) == 1 and (tokens[i - 1 : i] in _POSSESSIVES or noun_here) and not braking:
            ignored.append(tok)  # "missed his tailgate", "there is the crash": a thing, not a behaviour
            i += 1
            continue
        if key == ("stop",) and det:  # "the stop", "a stop": a bus stop, a place
            slot, value = "kerb", None
        elif tok == "crossing" and len(key) == 1 and det:  # "at the crossing": a junction, not someone crossing
            # (unless a zebra or pelican crossing was named, or a bend: then it is one beside the road)
            beside = S.foot_crossing_named_before(tokens, i) or S.bend_named(tokens)
            slot, value = ("kerb", None) if beside else ("map", "crossroad")
        elif slot in ("behaviour", "speed_word") and (said := " ".join(tokens[i : i + len(key)])) in V.SPEED_WORDS:
            if det and _actor_at(tokens, i + len(key)):  # "a slow truck": how fast it goes, not a slowing
                slot, value = "speed_adjective", V.SPEED_WORDS[said]  # (nor the subject's speed)
            elif slot == "behaviour" and (_after_copula(tokens, i) or lane_moves.slow_as_a_pace(tokens, i)):
                slot, value = "speed_word", V.SPEED_WORDS[said]  # "the truck is slow"
        if slot == "stationary" and tok == "standing" and standing_names_a_kind(tokens, i):
            i += 1  # ("a standing e-scooter", "the standing kind": a scooter's kind, no state)
            continue
        if slot == "behaviour" and (whose_act.not_meant(tokens, i) or set_aside(tokens, i)):
            ignored.append(" ".join(tokens[i : i + len(key)]))  # ("no intention of crossing", "rather than swerve")
            i += len(key)
            continue
        if slot == "behaviour" and _denied(tokens, i) and key[0] not in _NEGATORS:
            name, cfg = _DENIED.get(value[0], ("keep_going", {}))  # ("does not stop": it carries on)
            cfg = {**cfg, "_refused_way": 1.0} if value[0] == "give_way" else cfg  # (for ring_entry)
            held = {**cfg, "_still": 1.0} if value[0] == "keep_going" else cfg
            value = (name, {**cfg, "_denied": 1.0} if value[0] not in _HELD_BACK else held)
        used = len(key) + (1 if adverb or toward_at else 0)
        words = " ".join(tokens[i : i + used])
        nxt = tokens[i + used] if i + used < len(tokens) else ""
        after = tokens[i + used + 1] if i + used + 1 < len(tokens) else ""
        if slot == "behaviour" and value[0] in _SIDEWAYS and toward_at is None and nxt in ("left", "right"):
            if after not in _RIGHT_BEFORE and not sides.not_a_side(tokens, i + used):  # ("merges right from the
                # middle lane", not "cuts in right in front")
                toward_at = i + used
        if slot in ("sequence", "parallel") and (det or tokens[i + used : i + used + 1] == ["to"]):
            i += used  # "from the next entry", "next to me": a word of order before a noun or "to", no new clause
            continue
        if slot in ("sequence", "parallel"):
            clauses.append((slot, [_Mention("link", slot, words, i, prev, end=i + used)]))
        elif slot == "arm":  # ("came off at the first exit": "at", past the words of order)
            clauses[-1][1].append(_Mention(slot, value, words, i, sides.before_the_order(tokens, i) or prev, nxt,
                                           i + used, det))  # fmt: skip
        elif slot != "noise":
            det = det or (_phrase_determiner(tokens, i) if slot == "actor" else "")  # ("the injured cyclist")
            if slot in ("kerb", "kerb_side"):
                prev = _before_a_described_place(tokens, i) or prev  # ("off the dropped kerb": "off")
            if slot == "kerb_side":  # ("nearside", "the other side" read bare: the writer's near or far kerb)
                value = sides.kerb_side_of_the_writer(words, value, left_hand)
            clauses[-1][1].append(_Mention(slot, value, words, i, prev, nxt, i + used, det))
        if adverb is not None and (adverb,) in TABLE and TABLE[(adverb,)][0] in ("criticality", "speed_word"):
            a_slot, a_value = TABLE[(adverb,)]
            clauses[-1][1].append(_Mention(a_slot, a_value, adverb, i + 1, tok, end=i + 2))
        if slot == "relation" and value == "oncoming" and sides.on_the_egos_line(tokens, i, i + used):
            clauses[-1][1].append(_Mention("over_line", None, words, i, prev, end=i + used))  # ("came straight at")
        if toward_at is not None and slot == "behaviour":
            side = tokens[toward_at]
            clauses[-1][1].append(_Mention("toward", side, side, toward_at, tokens[toward_at - 1], end=toward_at + 1))
            used = max(used, toward_at + 1 - i)
        i += used
    return (
        [c for c in clauses if any(m.slot not in ("punct", "link") for m in c[1])],
        ignored,
        read_as,
        tokens,
        bystander,
    )


def _specific_act(tokens: list[str], i: int) -> int:
    """How many words from ``tokens[i]`` the lexicon reads as a specific behaviour or a turn (0: none)."""
    key = _best(tokens, i)
    return len(key) if key and TABLE[key][0] == "turn" else _specific_behaviour(tokens, i)


def _act_of_a_road_user(tokens: list[str], i: int) -> bool:
    """Whether the noun at ``i`` is said as what a road user does: right after the road user's noun
    ("oncoming van turn-across") or as the object of a light verb ("did a turn-across"), past its
    determiner and describing words. Not a noun governed by a preposition of place ("at the
    cross-over", "into the pull-in"), past a road user's word that only names the place ("in the bus
    pull-in"), nor one that names a heading ("Late cut-out."): that one is a
    place, or the title of what is told after it."""
    describes = lambda w: w in _DETERMINERS or _only_describes(w)  # noqa: E731
    before = _word_before_phrase(tokens, i, describes)
    if i > 0 and _actor_word(tokens[i - 1]):  # (unless the road user's word names the place: "in the bus pull-in")
        return _word_before_phrase(tokens, i - 1, describes) not in _PLACE_PREPOSITIONS
    return bool(set(_lemmas(before).get("VERB", ())) & LIGHT_VERBS)


def _specific_behaviour(tokens: list[str], i: int) -> int:
    """How many words from ``tokens[i]`` the lexicon reads as a behaviour other than going on (0: none)."""
    key = _best(tokens, i)
    return len(key) if key and TABLE[key][0] == "behaviour" and TABLE[key][1][0] != "keep_going" else 0


#: Verbs that with "to" say what someone must do ("it has to brake": a requirement, said of the ego).
_MODAL_VERBS = frozenset({"has", "have", "had", "needs", "need", "needed"})
_POSSESSIVES = (["his"], ["her"], ["its"], ["their"], ["my"], ["our"], ["your"])


def _ends_with_ego(tokens: list[str]) -> bool:
    """Whether ``tokens`` end with a name of the ego ("... the ego", "... the subject vehicle")."""
    return any(tuple(tokens[-len(p.split()) :]) == tuple(p.split()) for p in L.EGO_NOUNS)


def _bare_noun(tokens: list[str], i: int, key: tuple[str, ...]) -> bool:
    """Whether the one-word behaviour at ``i`` is a noun standing on its own at the end of a phrase,
    as notes and commentary say what happened ("head-on crash.", "night, T-bone crash", "Full brake."):
    uninflected, with a punctuation mark or the end after it, and before it a punctuation mark, the
    start, a hyphenated modifier or an adjective (no road user doing it)."""
    tok = tokens[i]
    if len(key) != 1 or "NOUN" not in _pos(tok) or tok not in _lemmas(tok).get("VERB", (tok,)):
        return False  # (an inflected verb is a verb: "a van ahead stops.")
    if i + 1 < len(tokens) and tokens[i + 1] not in ".;,!?:":
        return False
    if i == 0 or tokens[i - 1] in ".;,!?:":
        return True
    before = tokens[i - 1]
    if _actor_word(before) or before in FUNCTION_WORDS:
        return False
    return "-" in before or ("ADJ" in _pos(before) and _best(tokens, i - 1) is None)


def _predicate_of_ego(tokens: list[str], i: int) -> bool:
    """Whether the road-user noun at ``i`` says what the ego is ("I was the designated driver", "we
    are the lead car"): after the narrator, a copula and a determiner (and up to two more words)."""
    j = i - 1
    while j >= 0 and i - j <= 3 and tokens[j] not in _COPULAS:
        if tokens[j] not in _DETERMINERS and (tokens[j] in FUNCTION_WORDS or not tokens[j].isalpha()):
            return False
        j -= 1
    return j >= 1 and tokens[j] in _COPULAS and tokens[j - 1] in ("i", "we") and tokens[j + 1] in _DETERMINERS


#: Months whose name is also a verb.
_MONTH_VERBS = frozenset(("march",))
#: Day numbers written as ordinals ("3rd", "the 14th").
_ORDINAL = re.compile(r"^\d{1,2}(st|nd|rd|th)?$")


def _month_of_a_date(tokens: list[str], i: int) -> bool:
    """Whether ``tokens[i]`` is a month said with its day ("3 March", "March 3rd", "on the 3rd of
    March"): a date, no verb of anyone."""
    if tokens[i] not in _MONTH_VERBS:
        return False
    before = tokens[i - 2] if i >= 2 and tokens[i - 1] == "of" else (tokens[i - 1] if i else "")
    after = tokens[i + 1] if i + 1 < len(tokens) else ""
    return bool(_ORDINAL.match(before) or _ORDINAL.match(after))


def _after_article(tokens: list[str], i: int) -> bool:
    """Whether the word at ``i`` follows an article, past at most two words the reader has no entry
    for ("the petrol station", "a Ford Transit"): a name, not a verb."""
    j = i - 1
    while j >= 0 and i - j <= 3:
        if tokens[j] in ("a", "an", "the", "my", "our", "his", "her", "their", "its"):
            return True
        if tokens[j] in FUNCTION_WORDS or not tokens[j].isalpha() or _best(tokens, j) is not None:
            return False
        j -= 1
    return False


#: Quantifiers before a noun: a plural right after one is counted, so a noun ("on both sides").
_QUANTIFIERS = frozenset(("both", "each", "every", "either", "neither", "several", "many", "few", "all"))


def _counted_plural(tokens: list[str], i: int) -> bool:
    """Whether the word at ``i`` is a plural counted by the word before it ("both sides", "two sides",
    "several times"): a noun, not a verb said of whoever was named before it. (A verb after a floating
    quantifier has no -s: "they both stop".)"""
    before = tokens[i - 1] if i else ""
    counted = before in _QUANTIFIERS or before in NUMBER_WORDS or before.isdigit()
    return counted and tokens[i].endswith("s") and not tokens[i].endswith("ss")


#: Auxiliaries and verbs of saying: the word right before one is its subject, a noun ("Police have").
_AUXILIARIES = frozenset(("have", "has", "had", "are", "is", "was", "were", "will", "would", "said", "say"))


def _before_auxiliary(tokens: list[str], i: int) -> bool:
    """Whether the word at ``i`` stands right before an auxiliary or a verb of saying ("Police have
    arrested a man", "Witnesses said", "Residents are asking"): the subject of that verb, a noun; a
    finite verb is not followed by another."""
    return i + 1 < len(tokens) and tokens[i + 1] in _AUXILIARIES


def _counts_actor(mentions, k: int) -> bool:
    """Whether count ``mentions[k]`` stands before a road user's name, past words that describe it
    ("two parked vans"), not before anything else ("the middle lane of three, ...")."""
    end = mentions[k].end
    for m in mentions[k + 1 :]:
        if m.start - end > 1:
            return False
        if m.slot == "actor":
            return True
        if m.slot not in _POSITIONAL:
            return False
        end = m.end
    return False


def _new_unknown_subject(tokens: list[str], i: int) -> bool:
    """Whether the word at ``i`` names someone new at the start of a clause: "a", "an" or "one" before
    it ("one aunty was crossing", as people say "one" for "a"), past at most two words the reader has
    no entry for ("when a black BMW ..."), and a clause opening before that. A noun with an article
    right after it is no subject ("One day a heron ...": the day is when). After "had", "got", "let"
    or a verb of seeing ("she had a Voi rider swing off the path") it is the subject of the bare verb
    that follows, as a road user named there is (:mod:`experiencer`)."""
    if tokens[i + 1 : i + 2] and tokens[i + 1] in _DETERMINERS:
        return False
    j = i - 1
    while j >= 0 and i - j <= 3 and tokens[j] not in _NEW_ONE and _best(tokens, j) is None:
        if tokens[j] in FUNCTION_WORDS or not tokens[j].isalpha():
            return False
        j -= 1
    if j < 0 or tokens[j] not in _NEW_ONE:
        return False
    if tokens[j] == "one" and not _finite_next(tokens, i + 1):
        return False  # ("One motorist heading east tells us ...": one picked out of many, who reports)
    return _clause_opens_before(tokens, j) or experiencer.had_doing(tokens, j, i + 1)


#: Words a clause opens with before a new road user that is its subject ("Also a ...", "Plus one ...").
_ADDING = frozenset({"also", "plus", "and", "then", "next"})


#: Possessives that name one of someone's own people ("my son", "her grandson", "their daughter").
_OWNERS = frozenset(("my", "our", "his", "her", "their", "your"))


def _party_crossing(tokens: list[str], i: int) -> bool:
    """Whether the word at ``i`` is one of someone's own people (:data:`vocabulary.PARTY`: "my son",
    "her grandson", "our nan") who is the subject of a crossing on foot said next ("my son stepped
    out between parked cars", "her grandson was crossing with his cane"): a walker of the scene. Such
    a person who drives, rides along or does anything else is left to the readings of the narrator's
    party (the ego's driver, a passenger)."""
    if tokens[i] not in V.PARTY or not i or tokens[i - 1] not in _OWNERS:
        return False
    for k in range(i + 1, min(i + 8, len(tokens))):
        if tokens[k] in ".;!?:" or _actor_at(tokens, k):
            return False
        key = _best(tokens, k)
        if key is not None and TABLE[key][0] == "behaviour":
            value = TABLE[key][1]
            return (value[0] if isinstance(value, tuple) else value) == "cross_in_front"
    return False


def _someone_new_opens(tokens: list[str], i: int) -> bool:
    """Whether the road-user noun at ``i`` opens its clause as someone new: "one" before it after a
    clause opens ("Also one pedestrian crossing far ahead", "; one cyclist crossing ..."), as people
    count the road users of a scene, or "a" right after a word that adds one more ("Also a pedestrian
    crossing ahead"). A place is named with "a" after a verb or a preposition ("there is a pedestrian
    crossing", "near a pedestrian crossing") and hardly ever counted as "one" at a clause's start."""
    det = tokens[i - 1] if i else ""
    before = tokens[i - 2] if i > 1 else ""
    if det == "one":
        return before in _OPENERS or before in _ADDING
    return det in ("a", "an") and before in _ADDING


#: The words that name a motorbike as often as a pedal cycle ("bike" in Indian, and much other, English).
_EITHER_BIKE = frozenset({"bike", "bikes", "biker", "bikers"})
#: Faster than a pedal cyclist goes (m/s): 45 km/h; and the ego's speed above which a pedal cyclist does
#: not come past it (m/s): 35 km/h.
_CYCLIST_TOP_MPS = 12.5
_CYCLIST_PASSES_MPS = 9.7


def _at_a_motorbikes_pace(a: _Actor, ego_mps: float | None) -> bool:
    """Whether road user ``a``, named only "bike" or "biker", goes at a motorbike's pace, not a pedal
    cycle's: faster than a cyclist rides, or coming past the ego ("overtook me", "came from behind and
    cut in") while the ego drives faster than a cyclist can keep up with. An e-bike ("e" before "bike":
    "a kid on one of them e-bikes") is a pedal cycle's word however fast it goes."""
    if a.word not in _EITHER_BIKE or a.named_after == "e":
        return False
    if a.speed_mps is not None and a.speed_mps > _CYCLIST_TOP_MPS:
        return True
    names = {b[0] for b in a.behaviours}
    passes = "overtake" in names or ("cut_in" in names and ("behind" in a.said or a.relation == "behind"))
    return passes and ego_mps is not None and ego_mps > _CYCLIST_PASSES_MPS


def _finite_next(tokens: list[str], k: int) -> bool:
    """Whether the word at ``k`` is a finite verb, not a participle: "was", "is", or a verb read as a
    behaviour that does not end in -ing ("one aunty was crossing", "one granny stepped off")."""
    if k >= len(tokens):
        return False
    return tokens[k] in ("was", "is", "were", "are") or (_does_next(tokens, k) and not tokens[k].endswith("ing"))


#: Determiners that introduce someone new ("this", which may also point back, "this lad", "this
#: layout", is left out).
_NEW_ONE = frozenset({"a", "an", "another", "some", "one"})
#: Adverbs of time or sequence a clause may open with before its subject ("Yesterday a ...", "Then a ...").
_TIME_ADVERBS = frozenset({"yesterday", "today", "tonight", "then", "suddenly", "also", "now", "later", "once"})
#: Words that make a time adverbial of the noun after them ("last week", "one evening", "same time").
_TIME_OPENERS = frozenset({"last", "one", "this", "that", "next", "same"})


def _clause_opens_before(tokens: list[str], j: int) -> bool:
    """Whether a clause opens right before ``j``: after a mark or a conjunction, or past an adverbial of
    time it opens with ("Yesterday a ...", "Last week a ...", "One evening a ...")."""
    prev = tokens[j - 1] if j else ""
    if prev in _OPENERS:
        return True
    if prev in _TIME_ADVERBS:
        return (tokens[j - 2] if j > 1 else "") in _OPENERS
    if j > 1 and tokens[j - 2] in _TIME_OPENERS and "NOUN" in _pos(prev):
        return (tokens[j - 3] if j > 2 else "") in _OPENERS
    return False


def _names_a_thing(tokens: list[str], j: int) -> bool:
    """Whether the word at ``j`` is a noun the reader has no setting entry for ("Audi", "one"): a
    colour before it is that thing's colour."""
    if j >= len(tokens) or not tokens[j].isalpha():
        return False
    key = _best(tokens, j)
    return key is None or TABLE[key][0] == "actor" or tokens[j] == "one"


def _modifies_actor(tokens: list[str], j: int) -> bool:
    """Whether a road user's name follows at ``j``, past at most two words the reader has no entry
    for ("ice [cream] van"): the words before it then say what kind it is."""
    for k in range(j, min(j + 3, len(tokens))):
        if _actor_at(tokens, k):  # (not the ego: "in the roundabout my car drives ...")
            key = _best(tokens, k)
            return key is None or TABLE[key] != ("actor", "ego")
        if _best(tokens, k) is not None or tokens[k] in FUNCTION_WORDS or not tokens[k].isalpha():
            return False
    return False


#: Plain verbs of motion an unknown verb is read as, with the words after it ("swung into": "move into").
PLAIN_MOTION_VERBS = ("move", "go", "walk")


#: Words of where a motion goes, after its verb ("into", "across", "out" ...).
_MOTION_PARTICLES = frozenset(
    "into to across out over in onto off through past away back towards toward round around from between".split()
)


#: Verbs (lemmas) of carrying someone or something: where they go is where it was carried ("rider
#: taken to A&E", "scooter taken out of service", "the car was towed away"), and verbs of looking or
#: signalling: where they go is where one looks or calls ("looked across at me", "checked over on
#: scene", "waved over"): no move of a road user's.
_CARRYING = frozenset(("take", "bring", "carry", "send", "tow", "ferry", "airlift", "drag")) | L.LOOKING_OR_SIGNALLING


#: Verbs (lemmas) whose "to" + infinitive is the act itself, tried or meant ("tried to squeeze past").
_CATENATIVES = frozenset(("try", "attempt", "want", "decide", "manage", "start", "begin", "mean", "choose"))


def _verb_before(word: str, after: str, before: tuple[str, ...] = ()) -> bool:
    """Whether ``word`` reads as a verb of motion here: a verb (by lemminflect) that is not also a noun
    or adjective, or one that is but is followed by where it goes ("changing to our lane"), inflected
    or in the infinitive of an act tried or meant (``before``, the two words before it: "tried to
    squeeze past"; not one of purpose: "swings across to turn into a side street")."""
    pos = _pos(word)
    if "VERB" not in pos:
        return False
    moved = word.endswith(("ing", "ed", "s")) or _past(word)  # ("shot into the road": an irregular past)
    tried = len(before) == 2 and before[1] == "to" and bool(set(_lemmas(before[0]).get("VERB", ())) & _CATENATIVES)
    moved = moved or (tried and word in _lemmas(word).get("VERB", ()))
    return not pos & {"NOUN", "ADJ", "PROPN"} or (after in _MOTION_PARTICLES and moved)


#: Verbs whose very wording is critical ("darts out", "tailgates"), unless the clause says otherwise.
VERB_CRITICALITY = {
    ("tailgate",): "dangerous",
    ("dart", "out"): "dangerous",
    ("dart", "across"): "dangerous",
    ("shoot", "out"): "dangerous",
    ("jump", "out"): "dangerous",
    ("run", "out"): "dangerous",
    ("slam", "on", "the", "brake"): "dangerous",
    ("slam", "the", "brake"): "dangerous",
    ("squeeze", "in"): "dangerous",
    ("barge", "in"): "dangerous",
    ("ride", "my", "bumper"): "dangerous",
    ("ride", "our", "bumper"): "dangerous",
    ("ride", "bumper"): "dangerous",
    ("brake", "gently"): "safe",
    ("ease", "off"): "safe",
    ("sprint", "across"): "dangerous",
    ("pop", "out"): "dangerous",
}
_POSITIONAL = (
    "relation", "side", "lane_side", "kerb", "kerb_side", "arm", "stationary", "wrong_way", "returns",
    "over_line", "speed_adjective", "toward", "place", "far_side", "mid_road",
)  # fmt: skip
_VERBS = ("behaviour", "turn", "unknown_verb", "ego_verb", "speed_word")


def _drop_label(clauses):
    """A test engineer's label before a colon ("CCRs:", "Cut-out:", "Car-to-pedestrian farside adult:")
    names the case, not its actors: what it says of actors is dropped, unless the text after it
    refers back to them ("Two cars: one ..., the other ...")."""
    if not clauses:
        return clauses
    out = []
    for k, (link, mentions) in enumerate(clauses):  # (each sentence may open with one: "Target: cyclist, ...")
        colon = next((j for j, m in enumerate(mentions) if m.slot == "punct" and m.value == ":"), None)
        if colon is None or (k and colon > 2) or any(m.slot in ("member", "pronoun") for m in mentions[colon:]):
            out.append((link, mentions))
            continue
        if {m.start for m in mentions[:colon]} & {o for m in mentions[colon:] for o in m.owners}:
            out.append((link, mentions))  # ("cyclist: 12 m ahead, 15 km/h, brakes"): a key whose values follow
            continue
        if _fronted_place(mentions[:colon]):
            out.append((link, mentions))  # ("FROM THE RIGHT: a rider blows through the red"): where it comes from
            continue
        dropped = ("actor", "behaviour", "relation", "side", "count", "unknown_verb") + _POSITIONAL
        head = [m for m in mentions[:colon] if m.slot not in dropped]
        out.append((link, head + mentions[colon + 1 :]))
    return out


#: Prepositions a place that opens a clause is said with ("From the right: ...", "Out of the side road: ...").
_FRONTING = frozenset({"from", "out", "off"})


def _fronted_place(head: list) -> bool:
    """Whether what stands before a colon is only a side said with a preposition of coming from ("FROM
    THE RIGHT:", "from my left:"). Why: a label names the case with a noun phrase ("Cut-out:", "Target
    cyclist:"); a prepositional phrase names none, it is fronted for the clause after the colon and says
    where that clause's road user comes from, as "From the right, a rider ..." does."""
    return bool(head) and all(m.slot == "side" and m.words.split()[0] in _FRONTING for m in head)


def _gap_holder(actors: list[_Actor]) -> _Actor:
    """The road user a gap said of the ego is to: the one named last, passing over what someone comes out
    from behind or between and parked ones that do nothing (yet): "a boy steps out from behind a parked
    van when the ego is 15 m away" is 15 m to the boy; the van is where he comes from. Only such ones
    named: the last of them (a parked car the ego nears before it pulls out). One standing in the road
    ("a scooter stopped in the lane") is no cover: it is what the ego comes up to."""
    acting = [a for a in actors if not (a.hides or (a.parked and not a.behaviours))]
    return (acting or actors)[-1]


def _comes_out_from(prev, m) -> bool:
    """Whether actor mention ``m`` names what someone comes out from behind, between or in front of
    ("from behind an ice-cream van", "out between parked cars", "from in front of the bus")."""
    if m.prev == "between":
        return True
    return (
        prev is not None
        and prev.slot == "relation"
        and 0 <= m.start - prev.end <= 3
        and (
            prev.words in ("from behind", "from in front of")
            or (prev.prev == "from" and prev.words in ("behind", "in front"))
        )
    )


#: Mentions of a description's settings (where, when, in what weather and traffic).
_SETTINGS = ("map", "weather", "time", "density", "lanes")


def _slows_from(a: _Actor, ego_mps: float | None, to_mps: float) -> float | None:
    """The speed the road user ``a`` goes at before it slows to ``to_mps``: its own said in figures
    ("the lorry at 56 mph ... brakes to 30 mph"), else the ego's where the ego is said to go faster
    than that and ``a`` is a vehicle the ego is said to follow ("ego follows a van at 100 km/h, the van
    slows to 60": what the ego follows goes its speed); None otherwise (the speed after "to" is then
    all that is said of its pace: "cuts in, then decelerates to 45 mph")."""
    if a.speed_mps is not None:
        return a.speed_mps if a.speed_mps >= 0 else None  # (a pace in words, "going slow", is no figure)
    paced = a.followed and ego_mps is not None and ego_mps <= FASTEST_MPS.get(a.kind, 1e9)
    return ego_mps if paced and ego_mps > to_mps else None


def _among_settings(mentions, k: int) -> bool:
    """Whether the speed ``mentions[k]`` stands alone between commas next to a setting, as terse notes
    give the test's speed ("car ahead swerves to reveal a stopped truck, 80 km/h, heavy rain")."""
    before = mentions[k - 1] if k else None
    after = mentions[k + 1] if k + 1 < len(mentions) else None
    if before is None or before.slot != "punct" or before.value != ",":
        return False
    if after is not None and not (after.slot == "punct" and after.value == ","):
        return False
    near = [mentions[j] for j in (k - 2, k + 2) if 0 <= j < len(mentions)]
    return any(x.slot in _SETTINGS for x in near)


def _generic_vehicle(a: _Actor) -> bool:
    """Whether ``a`` was named by a word for any vehicle ("a lead vehicle", "the other vehicle"): an
    apposition after it ("A lead vehicle, a light goods van, ...") says which, even after "a"."""
    return a.kind == "car" and a.word.split()[-1] in ("vehicle", "vehicles")


def _bare(m) -> bool:
    """Whether an actor is named as a test engineer's notes name it again: the singular noun alone,
    opening its sentence or clause, no article ("Cyclist turns left", "... because bus go slow")."""
    return m.start == 0 or m.prev in ("", ".", ";", ":", ",") + _CLAUSE_OPENERS


#: Words before a noun that tell one road user from another or count them: never a road user said again.
_TELLING_APART = frozenset(
    "one two three four five six seven eight nine ten other second third next last each every any no "
    "more several many few both all".split()
)


def _said_again_bare(tokens: list[str], m, nxt) -> bool:
    """Whether road-user mention ``m``, with no determiner, is a singular noun as notes and reports
    write one they have named before, without its article ("oncoming HGV ... into path of HGV",
    "collided with cyclist"): notes drop "the", and a singular count noun without any determiner is
    never new in them. Not one counted or told apart ("one car", "other car", "2nd van"), nor one
    placed right after its noun ("car from the right"), which may be another of its kind."""
    before = tokens[m.start - 1] if m.start else ""
    opener = _phrase_opener(tokens, m.start, True)  # ("round a skip lorry", "the oncoming car": not bare)
    placed = nxt is not None and nxt.start == m.end and nxt.slot in ("relation", "side", "lane")
    told_apart = before in _TELLING_APART or before[:1].isdigit() or opener in _DETERMINERS | _TELLING_APART
    return not plural(m.words.split()[-1]) and not told_apart and not placed


#: Words that open a clause, after which a noun without its article is the clause's subject.
_CLAUSE_OPENERS = ("because", "and", "but", "then", "so", "when", "while", "as", "until", "after", "before")


def _ego_following(clauses):
    """A description that opens with "Following a truck ..." (nobody named before it) is the ego's
    view: the ego follows, so what it follows is ahead of it. So is a sentence or a statement after a
    label's colon that opens so ("Driver statement: following a box van ...", "... . Following a bus
    on the ring road, ..."): an opening participle with no subject is the narrator's. Returns the
    clauses with that "following" read as "ahead", and whether it was so."""
    if not clauses:
        return clauses, False
    link, mentions = clauses[0]
    first = next((k for k, m in enumerate(mentions) if m.slot not in ("punct", "link")), None)
    if first is None or mentions[first].start != 0 or mentions[first].words not in ("following", "tailing"):
        return _opening_following(clauses)
    m = mentions[first]
    ahead = _Mention("relation", "ahead", m.words, m.start, m.prev, m.next_, m.end, m.det)
    return [(link, mentions[:first] + [ahead] + mentions[first + 1 :])] + clauses[1:], True


#: Tokens after which a participle opens a sentence or a statement.
_OPENS = frozenset({".", ":", "!", "?", ";"})


def _opening_following(clauses):
    """The clauses with "following" (or "tailing") read as "ahead" where it opens a sentence or follows
    a colon and a road user is named right after it ("Driver statement: following a box van"), and
    whether any was."""
    out, found = [], False
    for link, mentions in clauses:
        kept = list(mentions)
        for k, m in enumerate(kept[:-1]):
            who = kept[k + 1]
            opens = m.prev in _OPENS and not m.det and m.words in ("following", "tailing") and m.slot == "relation"
            if opens and who.slot == "actor" and who.value != "ego" and who.start <= m.end + 3:
                kept[k] = replace(m, value="ahead")
                found = True
        out.append((link, kept))
    return out, found


def _resolve_relation(a: _Actor, map_kind: str | None, left_hand: bool = False) -> str | None:
    """The spawn relation of an actor from what was said about where it is and what it does first.
    A kerb with no side said is the writer's near one (the left where traffic keeps left), and a
    vehicle at the far kerb drives the other way (:func:`sides.near_and_far`)."""
    near, far = sides.near_and_far(left_hand)
    first = a.behaviours[0][0] if a.behaviours else None
    junction = map_kind in ("crossroad", "roundabout")
    vehicle = a.kind in VEHICLES
    side = a.kerb_side or a.lane_side or a.side or (a.relation if a.relation in ("left", "right") else None)
    if first == "cross_in_front" and junctions.rides_across_from_an_arm(junction, a.kind, a.from_arm, a.kerb, side):
        return f"junction_{side}"  # ("a cyclist from the side road on the right crosses": out of that arm)
    if first == "cross_in_front" and not vehicle:  # a crossing starts at a kerb (at a junction too)
        side = sides.across_from(side, a.goes_to, a.kerb_side or a.lane_side)
        if side is None and a.relation and a.relation.startswith(("junction", "roadside")):
            side = a.relation.rsplit("_", 1)[1]
        return f"roadside_{side if side in ('left', 'right') else near}"
    if a.relation and a.relation.startswith(("junction", "roadside")):
        return a.relation
    if sides.opposite_approach(junction, a.kind, a.far_side, first):
        return "junction_opposite"
    rides = a.kind != "pedestrian"  # (a rider at a junction takes the road as a vehicle does)
    if facing := waits_facing(a.relation == "oncoming", first, rides, side, junction):
        return facing  # ("a bus coming the other way stopped and waved me on": where it comes from)
    if first == "give_way" or (junction and rides and a.goes_on and first == "cut_in" and a.relation != "oncoming"):
        # lets the ego pass (or is said not to): where their paths meet, in a side road or at the kerb
        where = "junction" if vehicle or (junction and not a.kerb) else "roadside"
        return f"{where}_{side if side in ('left', 'right') else near}"
    if kerb := sides.off_the_kerb(vehicle, a.came_from, a.kerb or bool(a.kerb_side), side, near):
        return kerb  # ("came off the pavement on my left at the exit": from that kerb, across the arm)
    if junction and a.arm and side in ("left", "right"):
        return f"junction_{side}"  # from the side road on the left: that arm, even if it approaches
    on_the_road = a.came_from and rides and not (a.kerb or a.kerb_side or a.lane_side)
    # with the way, or said to come from a side, "in front of us" is where it passes or goes, not where it starts
    said = a.said - {"ahead"} if a.has_way or (a.came_from and a.side in ("left", "right")) else a.said
    if arm := sides.arm_it_comes_from(junction, on_the_road, a.side, first, said):
        return arm  # ("at the T-junction a cyclist comes from the right")
    # at a junction what comes towards the ego comes from the arm said, else the opposite one (not one
    # walking along its kerb towards the ego)
    if a.relation == "oncoming" and junction and not sides.along_its_kerb(a.kind == "pedestrian", a.kerb, a.came_from):
        return f"junction_{side}" if side in ("left", "right") else "junction_opposite"
    if a.followed and first == "cut_in":
        return "ahead"  # the ego follows it in its lane: it pulls out of it, to the side said
    if a.relation == "oncoming" or (a.relation == "behind" and not ((a.lane_side or a.side) and first == "cut_in")):
        return a.relation
    if vehicle and a.kerb_side == far and not a.lane_side and first != "cross_in_front":
        return "oncoming"  # a vehicle on the far side of the road drives the other way
    if (
        junction
        and vehicle
        and side
        and (a.arm or a.stationary)
        and first in ("cut_in", "keep_going", "forced_turn", None)
    ):
        return f"junction_{side}"  # waiting at the junction on the left, then pulling out
    if first == "cross_in_front" and junction:
        return f"junction_{side or 'left'}"
    same_way = "ahead" in a.said and a.relation != "oncoming"  # ("in the same direction on the right": beside)
    if map_kind == "roundabout" and a.beside and not a.came_from and side and first in (None, "keep_going"):
        return side  # ("on the roundabout, a cyclist on my left carried on": going round beside the ego)
    if (
        first == "run_red_light"
        or (a.arm and junction)
        or (junction and first in (None, "keep_going") and a.side and not same_way)
    ):
        return f"junction_{side or 'left'}"
    lateral = first in ("cut_in", "overtake", "forced_turn", "follow_vehicle")
    if (
        a.kerb
        and not vehicle
        and (not (lateral and first != "forced_turn") or side is None or sides.at_the_edge(a.edge, a.lane_side, first))
    ):
        # (a rider cutting in from the cycle lane of a side said: from that lane; from a kerb: from its edge)
        return f"roadside_{side or near}"
    if sides.pulls_out_from_the_kerb(vehicle, a.stationary, a.kerb_side, a.lane_side, first):
        return f"roadside_{a.kerb_side}"  # ("a car parked at the kerb on the left pulled out": from that kerb)
    if side and (lateral or a.relation is None or a.lane_side):
        return side
    return a.relation or side or ("ahead" if a.followed else None)  # (the lead car: ahead in the ego's lane)


def _place_of_its_own(tokens: list[str], end: int, place_start: int) -> bool:
    """Whether a place named at ``place_start``, after a word of coming towards that ends at ``end``, is
    in a phrase of its own (a preposition between: "travelling in the opposite direction on Elm
    Street"): the road it comes along, not the place approached ("approaching the traffic lights")."""
    return any(w in PHRASE_ENDS for w in tokens[end:place_start])


#: The words of coming into sight over or round a place ("came over the crest"): oncoming, the place
#: after it the road's shape (:func:`sides.over_a_blind_place`).
_INTO_SIGHT = frozenset(("round", "around", "over"))


#: At most this many nouns the reader lacks are tried as the road user of a text that names none.
_UNNAMED_TRIES = 3


def read(text: str) -> Reading:
    """Parse ``text`` into a :class:`~vei_scenario.language.reading.Reading` (with ``ignored``
    words); raise :class:`~vei_scenario.language.reading.NotUnderstood` naming what cannot be placed.

    Where no road user is found, a noun the lexicon lacks that is the subject of a verb ("the rider
    shot off the kerb", "a figure in black walked out") is read as a road user of a general noun
    (:func:`who.unnamed_subjects`: of the first few, the first that gives its road users a behaviour);
    the noun is listed as not used."""
    text = plain_letters(text)  # ("piéton", "Fußgänger": the reader's words are plain letters)
    text = filled_outline(text)  # ("at <v_ego> km/h ... Examples: | v_ego | / | 70 |": at 70 km/h)
    answered = speed_answered(text, _actor_noun_in)  # ("How fast were you going? / C: Twenty.": the caller's speed)
    answered = route_answered(answered, _actor_noun_in)  # ("Which way were you going? / Left.": the ego's turn)
    reading = _read_answered(answered)
    if reading is not None and answered != text:  # (the words put in to say the answer are no words of the text)
        written = set(re.findall(r"[a-z]+", text.lower()))
        reading.ignored = [w for w in reading.ignored if w not in _ANSWER_WORDS or w in written]
    return reading


#: The words :func:`speed_answered` puts before an answer's number ("i was doing 30").
_ANSWER_WORDS = frozenset(ANSWER_SAID.split()) | {w for said in ROUTE_SAID.values() for w in said.split()}


def _read_answered(text: str) -> Reading:
    """:func:`read`'s work on ``text`` once its answers of speed are said as speeds: one reading, and where
    it finds no road user, the readings with an unnamed subject as one (:func:`who.unnamed_subjects`)."""
    try:
        reading, refused = _read(text), None
    except NotUnderstood as e:
        if e.missing != "road user":
            raise
        reading, refused = None, e
    if reading is not None and reading.actors:
        return reading
    candidates = unnamed_subjects(text, lambda w: _best([w], 0) is not None, _actor_word, _acts_at)
    for unnamed in candidates[:_UNNAMED_TRIES]:
        try:
            again = _read(unnamed[0])
        except NotUnderstood:
            again = None
        if again is not None and again.actors and all(a.behaviours for a in again.actors):
            again.ignored = list(dict.fromkeys([unnamed[1], *again.ignored]))
            return again
    if refused is not None:
        raise refused
    return reading


def _read(text: str) -> Reading:
    """One reading of ``text`` as it is written (see :func:`read`)."""
    text = quoted_speakers(text)  # ("'I stopped in time,' she said": she stopped, no narrator of its own)
    text, aside = only_the_scene(text, lambda part: _actor_noun_in(part.lower()))  # (what is not the scene)
    clauses, ignored, read_as, scanned, bystander = _scan(text)
    ignored[:0] = [w for w in aside if w not in FUNCTION_WORDS]
    clauses = off_a_place.onto_the_road_off_a_place(clauses, scanned, FUNCTION_WORDS)  # ("shot off the promenade")
    set_by_the_ego = ego_speed.right_after_the_ego(clauses)  # ("lets the ego (50 km/h) pass"), as scanned
    shared_behind = False  # (the ego's speed is one it shares with a vehicle said behind it, not its own)
    clauses = lane_moves.before_as_a_place(clauses, scanned)  # ("the bus before ego car": in front of it)
    clauses = sides.narrator_lane(sides.relate_headings(clauses))
    clauses = sides.ego_follows(sides.numbered_lanes(clauses, sides.drives_on_left(scanned, text)))
    clauses = sides.into_the_ego_rear(experiencer.road_user_had_acting(clauses, scanned))
    clauses = rear_ender_behind(without_places_of_no_one(clauses, scanned))  # ("rear-ended me", "nothing ahead")
    clauses = out_of_a_side_road(
        destinations_not_origins(outcome_not_behaviour(_drop_label(clauses), scanned), scanned), scanned
    )
    tokens = _tokens(text)
    said = " ".join(tokens)  # (the whole text as the reader reads it, for what is stated of it as a whole)
    clauses = out_of_the_lane.leaving_the_ego_lane(into_the_ego_lane(clauses, scanned), scanned)  # ("out of my lane")
    clauses = out_to_overtake(participle_of_state(give_the_ego_the_way(clauses, scanned)))
    clauses = lane_to_front.into_the_lane_in_front(clauses, scanned)  # ("in the left lane came in front of me")
    clauses = way_across.to_the_other_side(way_across.over_the_road(clauses, scanned), scanned)  # ("over the road")
    clauses = across_alone.across_alone(clauses, scanned)  # ("out from between the vans, straight across")
    clauses = scenery.standing_there(chains(clauses, scanned), scanned)  # ("there's a car stopped dead")
    clauses = lane_moves.cut_up(clauses, scanned)  # ("cut me up": into the lane in front, not across)
    clauses = lane_moves.braking_after_a_cut_in(clauses, scanned)  # ("cut in and braked": how it settles)
    clauses = lane_moves.passing_each_other(clauses, scanned)  # (a meeting: no one overtakes)
    clauses = lane_moves.pulling_in_to_stop(clauses, scanned)  # ("the bus pulls in and stops": at the kerb)
    clauses = junctions.priority(junctions.crossings(clauses, scanned), scanned)
    clauses = ego_emerges.main_road_has_the_way(clauses, scanned)  # ("I pulled out; a car came from the right")
    clauses, ego_follows = _ego_following(clauses)
    r = Reading()
    actors: list[_Actor] = []
    subject: _Actor | str | None = None
    pending: list[_Mention] = []
    gaps_to_next: list[_Mention] = []  # (pending gaps said of the ego to the road user named next)
    last_group: list[_Actor] | None = None  # ("Two scooters ride ahead; one of them brakes": that pair)
    both_with_ego = False  # ("CCRb: both cars at 50 km/h ...": the ego is one of them)
    ego_is_a_person = False  # (the ego named as "I" or "we": "it" is then never the ego)
    first_person = motion.told_in_the_first_person(text, tokens)  # (the narrator's)
    narrators = whose_act.acts_not_the_subjects(clauses, scanned, first_person, text)  # ("Had to brake.": not theirs)
    bound: dict[str, _Actor | str] = {}  # "he"/"she" → whom it first named
    resolved: dict[int, _Actor | str] = {}  # a road-user mention's start → whom it names
    owned = {o for _, ms in clauses for x in ms for o in x.owners}  # mentions a number is said of
    ego_said: float | None = None  # the ego's speed as the grammar says it (no position rule overrides it)
    said_of: list[tuple[_Actor, str, float]] = []  # a road user's speed or gap as the grammar says it, likewise
    speeds = {m.start for _, ms in clauses for m in ms if m.slot == "speed"}
    road_users = {i for _, ms in clauses for m in ms if m.slot == "actor" for i in range(m.start, m.end)}
    opened = ego_speed.subjectless_sentences(scanned, speeds, road_users)  # ("Came round the bend at 40, ...")
    read_words = {i for _, ms in clauses for m in ms if m.slot != "unknown_verb" for i in range(m.start, m.end)}
    opened.update(
        ego_speed.party_at_the_wheel(scanned, speeds, read_words, motion.told_in_the_first_person(text, tokens))
    )  # ("Dad was driving at 80 km/h")
    egos_own = ego_speed.group_speeds(scanned, speeds)  # ("Platoon speed 80 km/h": the ego's formation)
    egos_own.update({i: True for i in speeds if ego_speed.speedometer_reading(scanned, i)})  # ("speedo said 45")
    egos_own.update({i: True for i in speeds if ego_speed.owned(scanned, i)})  # ("much faster than my 70")
    egos_own.update({i: True for i in speeds if ego_speed.cruise_setting(scanned, i)})  # ("cruise set to 100")
    limits = ego_speed.limits(scanned, speeds)  # ("doing 50 in a 60 km/h zone": the road's, no one's speed)
    limits_alone = ego_speed.limits_alone(scanned, speeds, limits)  # ("WE NEED A 20MPH LIMIT. A van ...")
    road_limit: float | None = None  # (the first of those: the ego's pace where nothing else gives one)
    opened.update(ego_speed.opening_participles(scanned, speeds))  # ("Heading home at 50 km/h, ...")
    opened.update(ego_speed.before_what_happened(scanned, speeds, road_users))  # ("On the M6 at 70 when ...")
    named: list[tuple[_Actor | str, str]] = []
    main_subject: _Actor | str | None = None  # the subject said before a "while" clause inside its sentence
    for link, mentions in clauses:
        if main_subject is not None and while_clause.goes_on_from_the_main_clause(
            mentions, named, main_subject, scanned
        ):
            subject = main_subject  # ("a van pulled out while I was doing 40, then crawled along": the van)
        main_subject = None
        if while_clause.inside_its_sentence(link, mentions):  # ("I was doing 30 while ...": none goes on)
            main_subject = while_clause.main_subject(subject, scanned, mentions[0].start)
        named = []  # (actor, role) in order: subject, prep, verb, participle
        clause_subject: _Actor | str | None = None
        added: list[tuple[_Actor, int]] = []  # behaviours added in this clause
        crit_here = next((m.value for m in mentions if m.slot == "criticality"), None)
        group: list[_Actor] | None = None
        joined: list[_Actor] = []
        passive: list[_Mention] = []
        count = 1
        expect_subject = True
        prev: _Mention | None = None
        ego_speed_said: _Mention | None = None  # a speed read as the ego's ahead of its turn
        one_of: int | None = None  # the start of the road user "one of" names ("one of the buses pulled out")
        reacting = False  # in a stretch of the narrator's reaction ("..., stopped 2 m short,")
        for k, m in enumerate(mentions):
            nxt = mentions[k + 1] if k + 1 < len(mentions) else None
            if m.slot == "punct":
                if m.value != "'s":
                    expect_subject = True
                    reacting = False
                prev = prev if m.value == "'s" else m
                continue
            if m.slot == "modal":
                continue
            if m.slot == "speed" and m.start in limits:
                if m.start in limits_alone and road_limit is None:
                    road_limit = m.value
                prev = m
                continue
            if m.slot == "speed" and ego_speed.counterfactual(scanned, m.start):
                ignored.append(m.words)  # ("had it been doing 30 mph, she would have cleared it": no one's)
                prev = m
                continue
            if m.slot == "speed" and (
                ego_speed.impact_after_braking(scanned, m.start)
                or (
                    r.ego_speed_mps is not None
                    and m.value < r.ego_speed_mps
                    and ego_speed.impact_speed(scanned, m.start)
                )
            ):
                ignored.append(m.words)  # ("I braked but hit him at 10 mph", "at 65 ... hit him at 15": left at impact)
                prev = m
                continue
            with_ego = m.slot == "speed" and ego_speed.said_with_the_ego(scanned, m.start, m.end)
            if with_ego and r.ego_speed_mps is None:
                r.ego_speed_mps = m.value  # ("cuts in front of my car, 20mph, ...": the narrator's speed)
                if with_ego == "note":
                    prev = m
                    continue
            if m.slot == "speed" and egos_own.get(m.start) and r.ego_speed_mps is None:
                r.ego_speed_mps = m.value  # ("Platoon speed 80 km/h", "the speedo said 45": not the one named last)
                prev = m
                continue
            whose = [resolved.get(o) if o != Q.UNNAMED else (actors[-1] if actors else None) for o in m.owners]
            if whose and None not in whose and not (m.slot == "distance" and "ego" in whose):
                for who in whose:  # ("van speed 60 km/h", "cyclist: 12 m ahead, 15 km/h"): whose its grammar says
                    if who == "ego" and m.slot == "speed":
                        if r.ego_speed_mps is not None and ego_speed.named_as_impact_speed(scanned, m.start):
                            ignored.append(m.words)  # ("V1 at 41 km/h ... Impact speed V1 approx. 28 km/h")
                            continue
                        r.ego_speed_mps = ego_said = m.value
                    elif who != "ego":
                        _apply(m, who, r, link, added)
                        said_of.append((who, m.slot, m.value))
                prev = m
                continue
            if m.slot in ("conj", "link"):
                expect_subject = True
                prev = m
                continue
            if m.slot == "speed" and opened.get(m.start) and r.ego_speed_mps is None:
                r.ego_speed_mps = m.value  # ("Heading home at 50 km/h, a van ...": the narrator's drive)
                prev = m
                continue
            if m.slot == "behaviour" and _ego_participle(prev, m, nxt):
                ego_speed_said = nxt  # "15 m ahead of the ego travelling at 40 km/h": the ego's motion and speed
                prev = m
                continue
            if m is ego_speed_said or (
                m.slot == "speed" and m.prev in MOTION_PARTICIPLES and _ego_named(prev) and m.start == prev.end + 1
            ):  # ("20 m in front of the ego doing 50 km/h")
                if r.ego_speed_mps is None:
                    r.ego_speed_mps = m.value
                prev = m
                continue
            if (
                m.slot == "relation"
                and m.value == "oncoming"
                and nxt is not None
                and nxt.slot == "map"
                and m.words not in _INTO_SIGHT
                and not _place_of_its_own(scanned, m.end, nxt.start)
            ):
                prev = m  # "approaching the traffic lights": the ego's approach to a place, no one oncoming
                continue
            if m.slot == "count":
                if not _counts_actor(mentions, k):
                    continue  # ("the middle lane of three": a count of no road user)
                count = L.COUNTS.get(m.words) or (int(m.value) if isinstance(m.value, int) else 2)
                if m.words == "both" and not actors:  # "both cars at 50 km/h" before anyone: the ego and one
                    count, both_with_ego = 1, True
                continue
            if m.slot == "relative" and m.words == "that" and nxt is not None and nxt.slot == "actor":
                if nxt.start - m.end <= 2 and nxt.value != "ego":  # "I want that the front car brakes": a new clause
                    expect_subject = True
                    prev = m
                    continue
            if m.slot == "relative":
                if named and named[-1][1] != "subject":  # "a child who steps out": the child acts
                    clause_subject = subject = named[-1][0]
                    named[-1] = (named[-1][0], "subject")
                prev = m
                continue
            if m.slot in ("actor", "pronoun", "member"):
                if m.slot == "actor" and prev is not None and prev.slot == "actor" and prev.end == m.start:
                    if prev.words == "target" and named and isinstance(named[-1][0], _Actor) and m.value != "ego":
                        named[-1][0].kind = str(m.value)  # "the target pedestrian": a walker
                    if prev.start in resolved:
                        resolved[m.start] = resolved[prev.start]
                    prev = m
                    continue  # "adult pedestrian", "bicycle courier", "target pedestrian (adult)": one actor
                after_verb = prev is not None and prev.slot in _VERBS
                if (m.prev in L.OBJECT_PREPOSITIONS and m.start != one_of) or m.next_ == "'s":
                    role = "prep"  # "in front of the ego", "the ego's lane"
                elif expect_subject or clause_subject is None:
                    role = "subject"
                else:
                    role = "verb"  # "approaches a stationary car"
                if m.slot == "pronoun":
                    if after_verb or m.prev in L.OBJECT_PREPOSITIONS:
                        if after_verb and subject == "ego" and actors and motion.passes(prev):
                            (bound.get(m.words) or actors[-1]).passed = True  # ("ego passes him")
                        prev = m
                        continue  # "overtakes it": an object already known
                    who = subject if subject is not None else "ego"
                    verb = next((x for x in mentions[k + 1 :] if x.slot not in ("criticality", "speed_word")), None)
                    modal = verb is not None and verb.slot == "modal"  # ("Ego at 100 km/h, it has to brake hard")
                    if who == "ego" and actors and verb is not None and verb.slot == "behaviour" and not modal:
                        # "as the ego approaches, it pulls out": what the ego does not do (the planner
                        # drives it) is the last road user's, unless that one stands and it is a slowing
                        still = actors[-1].stationary and verb.value[0] in ("stop", "sudden_stop", "change_speed")
                        who = who if still else actors[-1]
                    elif (
                        who == "ego"
                        and actors
                        and m.words == "it"
                        and ego_is_a_person
                        and verb is not None
                        and verb.slot in ("to_stop", "unknown_verb", "stationary")
                    ):
                        who = actors[-1]  # ("We were following the bus when it pulled to a stop", "it stopped": not us)
                    if discourse.others_named(m.words, who == "ego" and ego_is_a_person, group or last_group):
                        who = (group or last_group)[-1]  # ("I was at 40, they were doing 20": the group, not us)
                    if m.words in ("he", "she"):  # a person's pronoun names the same one all through a story
                        narrator = ego_is_a_person or _i_in_its_sentence(scanned, m.start)  # ("he was ... and I")
                        if who == "ego" and narrator and actors and m.words not in bound:
                            who = actors[-1]  # (the narrator is "I": "he" is someone else)
                        who = bound.setdefault(m.words, who)  # ("the driver said she ... She braked")
                    person = actors == [who] and who.kind in (*VULNERABLE, UNKNOWN_KIND)  # (him, her: no vehicle)
                    if person and crossing_reaction.stops_for_another(scanned, m.start):
                        who = "ego"  # ("a lad came off the kerb; it stopped and waited for him": not the lad)
                    role = "subject"
                elif m.slot == "member":
                    pool = group or last_group or []
                    if not pool:
                        one_of = _one_of(m, nxt)
                        continue
                    free = [a for a in pool if not a.behaviours and not a.member_named]
                    unnamed = [a for a in pool if not a.member_named]
                    words = m.words.split()
                    if any(w in ("first", "former") for w in words):
                        who = pool[0]
                    elif any(w in ("second", "latter") for w in words) and len(pool) > 1:
                        who = pool[1] if "second" in words else pool[-1]
                    else:  # ("the first one stops, the one in front of me brakes": the next not yet told)
                        told = unnamed and len(unnamed) < len(pool)  # (some told apart already)
                        who = free[0] if free else unnamed[0] if told else pool[-1]
                    who.member_named = True
                    for a in pool:  # from here on each member is told apart
                        a.group = None
                    role = "subject"
                elif m.value == "ego":
                    who = "ego"
                    ego_is_a_person = ego_is_a_person or m.words in ("i", "we", "me", "us")
                    count = 1  # ("overtakes both of us": the ego and the one named with it)
                else:
                    same = [a for a in actors if a.kind == m.value]
                    last = named[-1][0] if named and isinstance(named[-1][0], _Actor) else None
                    if (
                        last is not None
                        and (
                            m.det in ("a", "an")
                            or (not m.det and (_generic_vehicle(last) or _named_again_then_acts(mentions, k, scanned)))
                        )
                        and k > 0
                        and mentions[k - 1].slot == "punct"
                        and mentions[k - 1].value == ","
                        and nxt is not None
                        and nxt.slot == "punct"
                        and not (k + 2 < len(mentions) and mentions[k + 2].slot in ("conj", "actor", "count"))
                        and (
                            _definite_before(mentions, k)
                            or _generic_vehicle(last)
                            or _named_again_then_acts(mentions, k, scanned)
                        )
                        and (last.kind == m.value or (last.kind in VEHICLES and m.value in VEHICLES))
                    ):  # "the car ahead, a taxi, stops": the same one, said again (its kind the more exact)
                        last.kind = str(m.value) if last.kind == "car" else last.kind
                        prev = m
                        continue
                    elsewhere = (  # "the car in front stops, the driver behind us ...": another one
                        same
                        and nxt is not None
                        and nxt.slot == "relation"
                        and nxt.start == m.end
                        and nxt.value in ("ahead", "behind")
                        and ({"ahead", "behind"} - {nxt.value}) & same[-1].said
                    )
                    if m.start in owned and m.words in Q.ROLE_NOUNS and actors and m.det in ("", "the"):
                        who = actors[-1]  # ("a cyclist crosses ... Target speed: 15 km/h": the cyclist)
                    elif (
                        same
                        and not elsewhere
                        and (
                            m.det in ("the", "this", "that", "its", "our", "my")
                            or (not m.det and (_bare(m) or m.start in owned))  # ("speed of scooter 20 km/h")
                            or (not m.det and _said_again_bare(scanned, m, nxt))  # ("into path of HGV")
                        )
                    ):
                        who = same[-1]  # ("Target: cyclist, 30 m ahead. Cyclist turns left.": the same one)
                    elif (
                        role == "prep"
                        and m.det == "the"
                        and m.words in ("car", "vehicle")
                        and not any(a.kind in VEHICLES for a in actors)
                    ):  # "across in front of the car", no car named before: the one the story is told from
                        who = "ego"
                    elif (
                        (
                            (
                                m.value in ("bicycle", "e-scooter")
                                and (
                                    m.prev in ("on", "riding", "with")
                                    or ridden_past_a_hedge(  # ("a man on what looked like a rented e-scooter")
                                        scanned, m.start, lambda w: _only_describes(w) or _plain_modifier(w)
                                    )
                                )
                            )
                            or (m.value in VEHICLES and m.prev in ("in", "driving"))  # ("some idiot in a BMW")
                        )
                        and named
                        and isinstance(named[-1][0], _Actor)
                        and named[-1][0].kind == "pedestrian"
                    ):
                        who = named[-1][0]  # "a guy on an e-scooter": the rider is the e-scooter
                        for rider in who.group or [who]:  # ("two kids on e-scooters": each of them)
                            rider.kind = str(m.value)
                        prev = m
                        continue
                    else:
                        lead = m.prev in _LEADING or m.words.split()[0] in _LEADING  # ("the lead car": followed)
                        made = [
                            _Actor(
                                str(m.value),
                                wrong_way=m.words in L.WRONG_WAY_NOUNS,
                                followed=lead,
                                word=m.words,
                                det=_phrase_det(scanned, m.start),
                                named_after=m.prev,
                                seen=ego_double.perceived(m.prev),
                                named_end=m.end,
                            )
                            for _ in range(count)
                        ]
                        for a in made:
                            a.group = made if count > 1 else None
                            a.counted = count > 1
                            a.crit = "dangerous" if m.words in L.INSULTS else None  # ("some idiot ...")
                        actors.extend(made)
                        who = made[0]
                        group = made if count > 1 else group
                        last_group = made if count > 1 else last_group
                    count = 1
                if (
                    role == "subject"
                    and isinstance(who, _Actor)
                    and prev is not None
                    and ((prev.slot == "conj" and prev.value == "and") or (prev.slot == "punct" and prev.value == ","))
                    and named
                    and named[-1][1] == "subject"
                    and isinstance(named[-1][0], _Actor)
                    and named[-1][0] is not who
                    and not any(x is named[-1][0] for x, _ in added)
                    and not named[-1][0].stationary  # ("with parked cars, a jogger ran out": the cars stand)
                ):  # "a cyclist and a pedestrian both cross": one verb for both
                    pair = (named[-1][0].group or [named[-1][0]]) + [who]
                    for x in pair:
                        x.group = pair
                    joined.extend(pair)
                if passive and isinstance(who, _Actor) and motion.after_by(scanned, m.start):
                    for pm in passive:  # "the AV is tailgated by a sports car": the car tailgates
                        _apply(pm, who, r, link, added)
                    passive = []
                if (
                    isinstance(who, _Actor)
                    and who is not clause_subject
                    and (
                        _comes_out_from(prev, m)
                        or scenery.among_them(scanned, m.start)
                        or from_cover.out_of_cover(scanned, m.start, FUNCTION_WORDS)  # ("from behind a parked lorry")
                    )
                ):
                    for hider in who.group or [who]:  # ("from between two vans": both of them)
                        hider.hides = True  # ("darts out from behind an ice-cream van": what it comes out from)
                    if isinstance(clause_subject, _Actor) and from_cover.out_of_cover(scanned, m.start, FUNCTION_WORDS):
                        clause_subject.from_cover = True  # ("a man stepped from behind a bus": he comes out)
                        clause_subject.cover = clause_subject.cover or who
                if role == "verb" and isinstance(who, _Actor) and after_verb:
                    who.acted_on = True  # ("the ego is overtaking a truck": the truck is in the scene)
                if role == "verb" and isinstance(who, _Actor) and clause_subject == "ego" and motion.passes(prev):
                    who.passed = True  # ("the ego overtakes a cyclist")
                if role == "verb" and isinstance(who, _Actor) and isinstance(clause_subject, _Actor) and after_verb:
                    who.object_of = who.object_of or clause_subject
                elif (
                    isinstance(who, _Actor)
                    and isinstance(clause_subject, _Actor)
                    and who is not clause_subject
                    and _passed_object(scanned, mentions, k)
                ):  # ("overtook a slow lorry", "an overtake of a slow-moving HGV": what it passes)
                    who.acted_on = True
                    who.object_of = who.object_of or clause_subject
                named.append((who, role))
                resolved[m.start] = who
                if role == "subject":
                    if subject is None and isinstance(who, _Actor):
                        pending = _left_out_subjects_acts(pending, prev, r, link, added)
                    subject = clause_subject = who
                    seen = [a for a in actors if not a.stationary] or actors
                    pending = _walkers_do_not_turn(pending, who, r, link, added)
                    for p in pending:
                        # ("about 20 m away when I saw him": the ego has no gap to itself; the one seen has)
                        gap_of_seen = who == "ego" and p.slot == "distance" and seen
                        _apply(p, seen[-1] if gap_of_seen else who, r, link, added)
                    pending = []
                else:
                    keep = []
                    for p in pending:
                        if (p.slot in _POSITIONAL or any(p is g for g in gaps_to_next)) and who != "ego":
                            _apply(p, who, r, link, added)
                        else:
                            keep.append(p)
                    pending = keep
                expect_subject = False
                prev = m
                continue
            if (
                m.slot == "relation"
                and m.value == "behind"
                and isinstance(clause_subject, _Actor)
                and from_cover.leaves_cover(scanned, m.start, m.end)
                and not (nxt is not None and nxt.value == "ego" and nxt.start <= m.end + 2)
            ):  # ("a jogger came from behind a hedge": out of cover; "from behind me" is the ego's rear)
                clause_subject.from_cover = True
            if m.slot in ("map", "weather", "time", "density", "lanes", "intent"):
                _global(r, m)
                prev = m
                continue
            if m.slot == "criticality":
                if m.words.split()[-1] in L.CONJUNCTIONS:  # "well after": what follows has its own subject
                    expect_subject = True
                prev = m
                continue
            if m.slot == "behaviour" and m.next_ == "by" and nxt is not None and nxt.slot == "actor":
                if nxt.value == "ego" and nxt.start <= m.end + 2:  # "a cyclist overtaken by the ego": the ego's
                    prev = m
                    continue
            if m.slot in _VERBS and m.prev == "to" and _ego_named(prev) and prev.prev == "for":
                # "waits on the side road for me to pass": the ego passes; waiting for it is giving way
                if isinstance(clause_subject, _Actor) and clause_subject.stationary:
                    _apply(replace(m, slot="behaviour", value=("give_way", {})), clause_subject, r, link, added)
                ignored.append(m.words)
                prev = m
                continue
            if (
                m.slot in _VERBS
                and not named
                and participle_aside.said_of_the_subject_before(scanned, m.start, _actor_at)
            ):
                pending.append(m)  # ("The defendant, driving a van, moved ...": the van's driving, not the narrator's)
                prev = m
                continue
            if (
                first_person
                and subject is None
                and not named
                and m.slot in ("behaviour", "ego_verb")
                and (m.slot == "ego_verb" or m.value[0] == "keep_going" or motion.passes_someone(m, nxt))
            ):  # "Just cruising behind my mate's car at 60 mph": before anyone is named, the narrator drives
                clause_subject = subject = "ego"
                named.append(("ego", "subject"))
                expect_subject = False
                prev = m
                continue
            if m.slot in _VERBS and m.start in narrators and actors:
                ignored.append(m.words)  # ("Waited, then passed them wide.": the narrator's, not theirs)
                if narrators[m.start]:
                    actors[-1].passed = True
                reacting = not narrators[m.start]
                prev = m
                continue
            if m.slot == "turn" and instruction_at(scanned, m.start):
                _apply(m, "ego", r, link, added)  # ("please turn left when your light is green": the reader's)
                prev = m
                continue
            if m.slot in _VERBS:
                target = clause_subject
                if (
                    target == "ego"
                    and m.slot == "behaviour"
                    and m.value[0] == "follow_vehicle"
                    and _object_follows(mentions, k)
                ):  # "the ego follows a lead car": that car is ahead (as "the ego is following a bus" says)
                    pending.append(replace(m, slot="relation", value="ahead"))
                    prev = m
                    continue
                if (
                    target == "ego"
                    and actors
                    and motion.passes(m)
                    and prev is not None
                    and (_ego_named(prev) or prev.words in ("we", "i", "you"))
                    and prev.end >= m.start - 1
                    and not motion.passes_someone(m, nxt)
                    and m.next_ not in ("each", "one")  # ("we pass each other": both go on their way)
                    and "oncoming" not in actors[-1].said | {actors[-1].relation}
                ):
                    actors[-1].passed = True  # ("a jogger on the verge, ego passes": the one said before)
                if target == "ego" and m.slot == "behaviour" and m.prev in PASSIVE_AUXILIARIES:
                    passive.append(m)  # said of the ego in the passive: the doer follows after "by"
                    prev = m
                    continue
                placed_before = _placed_object_before(mentions, k)
                if prev is not None and (prev.slot == "actor" or placed_before) and named and named[-1][1] != "subject":
                    crossing_past = (  # ("comes out from in front of the bus crossing": the rider crosses)
                        m.slot == "behaviour"
                        and m.value[0] == "cross_in_front"
                        and isinstance(named[-1][0], _Actor)
                        and named[-1][0].kind in VEHICLES
                        and isinstance(clause_subject, _Actor)
                        and clause_subject.kind in VULNERABLE
                    )
                    if m.words.split()[0].endswith("ing") and not crossing_past:  # "an oncoming car travelling at 30"
                        named[-1] = (named[-1][0], "participle")
                        target = named[-1][0]
                    elif crossing_past:  # (and where it crosses from is the rider's too)
                        named.append((clause_subject, "participle"))
                if (
                    m.slot == "behaviour"
                    and m.value[0] == "stop"
                    and m.value[1].get("_still")
                    and named
                    and isinstance(named[-1][0], _Actor)
                    and named[-1][0].stationary
                ):  # "... was a broken-down car, not moving": the state of the one standing, named last
                    target = named[-1][0]
                if target is None and not named and subject is not None:
                    # nobody named yet in this clause: the subject goes on ("... while overtaking a
                    # bus": the bus is what it overtakes, not who)
                    target = clause_subject = subject
                if isinstance(target, _Actor) and _ego_reaction(mentions, k, target, first_person):
                    ignored.append(m.words)  # ("cuts in ahead, on the brakes, ...": the narrator brakes)
                    reacting = True
                    prev = m
                    continue
                if target is None:
                    if m.slot != "unknown_verb":  # (an unknown verb of nobody: listed as not used)
                        pending.append(m)
                    prev = m
                    continue
                _apply(m, target, r, link, added)
                # "waits until the AV has gone past": what follows the conjunction has its own subject
                expect_subject = m.words.split()[-1] in L.CONJUNCTIONS
                prev = m
                continue
            # positions, states, numbers: the actor they describe
            if (
                m.slot == "relation"
                and clause_subject == "ego"
                and m.next_ == "by"
                and nxt is not None
                and nxt.slot == "actor"
                and nxt.value != "ego"
            ):  # "the ego was struck from behind by a truck": where the truck comes from
                pending.append(m)
                prev = m
                continue
            if reacting and m.slot in ("distance", "speed", "accel"):
                ignored.append(m.words)  # ("stopped 2 m short": how the narrator's stop went)
                if m.slot == "distance" and actors:
                    _gap_holder(actors).stopped_short_m = m.value  # (how near it came: stopped_short)
                prev = m
                continue
            if (
                m.slot == "stationary"
                and isinstance(clause_subject, _Actor)
                and _ego_reaction(mentions, k, clause_subject, first_person)
            ):
                ignored.append(m.words)  # ("runs the red, stopped 2 m short": the narrator stopped)
                reacting = True
                prev = m
                continue
            before_actor = nxt is not None and nxt.slot in ("actor", "count") and nxt.start == m.end
            before_actor = before_actor or (  # ("a stationary foam target car": its state, past its modifiers)
                m.slot == "stationary"
                and nxt is not None
                and nxt.slot == "actor"
                and scenery.plain_modifiers(scanned, m.end, nxt.start, lambda w: w in FUNCTION_WORDS)
            )
            before_actor = before_actor or (  # (", from the opposite direction a scooter ...": its clause's)
                m.slot == "relation"
                and nxt is not None
                and nxt.slot == "actor"
                and fronted_from.fronted_before(
                    m.words,
                    m.end,
                    nxt.start,
                    scanned,
                    prev is not None and prev.slot == "punct" and prev.value == ",",
                    lambda w: w in _PLACE_PREPOSITIONS,  # ("from behind the bus": its object)
                )
            )
            if m.slot in _POSITIONAL and before_actor and not (nxt.slot == "actor" and nxt.value == "ego"):
                pending.append(m)  # an adjective before its actor ("an oncoming car")
            elif (
                (
                    clause_subject == "ego"
                    or _asked_how_far(scanned, m)
                    or _narrators_opening(scanned, mentions, k)
                    or _of_a_subject_not_placed(scanned, mentions, k)
                )
                and m.value in _SEEN_FROM_OBJECT
                and _object_follows(mentions, k)
            ):
                # "we drive behind a truck": where the truck is, seen from the ego, is the other way round
                pending.append(replace(m, value=_SEEN_FROM_OBJECT[m.value]))
            else:
                if m.slot == "speed":
                    _participle_of_object(named, mentions[:k], m, scanned)  # ("across a cyclist approaching at 20")
                who = _nearest(named, m)
                if sides.owners_side(m, prev) and isinstance(clause_subject, _Actor) and who is not clause_subject:
                    who = clause_subject  # ("a van came from the Civic's right": the van's side, not the Civic's)
                elif (
                    isinstance(clause_subject, _Actor)
                    and clause_subject.kind in VULNERABLE
                    and isinstance(who, _Actor)
                    and who is not clause_subject
                    and sides.crosses_from_beside_a_landmark(
                        m, clause_subject.behaviours, bool(named) and named[-1][0] is who and named[-1][1] != "subject"
                    )
                ):
                    who = clause_subject  # ("crossed in front of the bus from the left": she comes from the left)
                elif sides.owners_side(m, prev) and clause_subject == "ego" and m.value in _OTHER_SIDE:
                    # ("the ego came from the SUV's right": the SUV is on the ego's left)
                    m = replace(m, value=_OTHER_SIDE[m.value])
                if (
                    m.slot == "relation"
                    and isinstance(clause_subject, _Actor)
                    and lane_moves.after_a_second_verb(mentions, k)
                ):
                    who = clause_subject  # ("overtook a truck and came head-on at us": the overtaker's)
                gap_to = _gap_to(mentions, k) if who == "ego" and m.slot == "distance" else None
                if who == "ego" and m.slot == "distance" and clause_subject == "ego" and _stop_before(prev):
                    ignored.append(m.words)  # ("I stopped 2 m short of it": how the ego's stop went, no gap)
                    if actors:
                        _gap_holder(actors).stopped_short_m = m.value  # (how near it came: stopped_short)
                    prev = m
                    continue
                if gap_to == "road user":
                    pending.append(m)  # ("the ego at 30 km/h 15 m behind a bus": the gap to the bus, named next)
                    gaps_to_next.append(m)
                    prev = m
                    continue
                if gap_to == "place":
                    ignored.append(m.words)  # ("the ego is 20 m behind the stop line": no one's gap)
                    prev = m
                    continue
                if who == "ego" and m.slot == "distance" and actors:
                    who = _gap_holder(actors)  # a gap said of the ego is the gap to the road user named last
                if isinstance(clause_subject, _Actor) and _overtaken_coming(who, clause_subject, m):
                    _apply(m, who, r, link, added)  # (what it overtakes goes its way: towards the ego too)
                    who = clause_subject  # ("a lorry overtook a tractor and came towards us": the lorry)
                elif isinstance(clause_subject, _Actor) and (
                    _verb_after_and(prev, m) or _overtakers_return(prev, m, clause_subject)
                ):
                    who = clause_subject  # ("a lorry hit the barrier and came towards us": the lorry)
                if who is None and m.slot in ("speed", "distance") and isinstance(clause_subject, _Actor):
                    who = clause_subject  # "..., and then overtakes it at 25 km/h": the one who overtakes
                if who is None and m.slot in ("returns", "wrong_way") and isinstance(subject, _Actor):
                    who = subject  # "..., then cuts back": what it does, said without naming it again
                if (
                    who is None
                    and m.slot in ("kerb", "kerb_side")
                    and _from(m)
                    and not named
                    and isinstance(clause_subject, _Actor)
                ):  # "..., then went off the kerb and across": where the clause's subject, said before, leaves from
                    who = clause_subject
                if (
                    who is None
                    and m.slot == "relation"
                    and isinstance(subject, _Actor)
                    and any(x is subject for x, _ in added)
                    and not _said_of_others(scanned, m.end)  # (not "to avoid oncoming traffic": the traffic's)
                ):  # "..., then overtook and cut in in front of me because a van ...": where it went, its own
                    who = subject
                change = mentions[k - 2] if prev is not None and prev.slot == "accel" and k >= 2 else prev
                if (
                    m.slot == "speed"
                    and m.prev == "to"
                    and change is not None
                    and change.slot == "behaviour"
                    and change.value[0] in ("sudden_stop", "change_speed")
                    and isinstance(clause_subject, _Actor)
                    and clause_subject.behaviours
                    and _slows_from(clause_subject, r.ego_speed_mps, m.value) is not None
                ):  # "the lorry at 56 mph ... brakes (at 3 m/s²) to 30 mph": the speed it slows to, not a stop
                    a = clause_subject
                    a.speed_mps = _slows_from(a, r.ego_speed_mps, m.value)
                    name, cfg, crit, lk = a.behaviours[-1]
                    a.behaviours[-1] = ("change_speed", {k2: v for k2, v in cfg.items() if k2 == "_words"}, crit, lk)
                    a.speed_to_mps = m.value
                    prev = m
                    continue
                if m.slot == "speed" and r.ego_speed_mps is None and _among_settings(mentions, k):
                    r.ego_speed_mps = m.value  # ("... reveal a stopped truck, 80 km/h, heavy rain": the test's speed)
                    prev = m
                    continue
                too_fast = m.slot == "speed" and isinstance(who, _Actor) and m.value > FASTEST_MPS.get(who.kind, 1e9)
                too_fast = too_fast and not Q.drives(who)  # ("some lunatic overtook doing 70": a driver)
                ego_right_before = (
                    prev is not None and prev.slot == "actor" and prev.value == "ego" and prev.prev == "by"
                )
                if m.slot == "speed" and ego_right_before and _next_to_ego(prev, m) and r.ego_speed_mps is None:
                    r.ego_speed_mps = m.value  # "overtaken by the ego at 50 km/h": the ego's speed
                elif too_fast and r.ego_speed_mps is None:
                    # "a dog ran out in front of the car at 50 km/h": no walker goes that fast; the ego does
                    r.ego_speed_mps = m.value
                elif (
                    who is None
                    and m.slot == "speed"
                    and not actors
                    and r.ego_speed_mps is None
                    and opened.get(m.start, True)
                ):
                    r.ego_speed_mps = m.value  # "Motorway at 110 km/h, a lorry ...": before anyone, the ego's
                elif who is None:
                    pending.append(m)
                else:
                    # "a car 12 m ahead of the ego at 50 km/h": of both, unless its own was said ("a slow car")
                    of_both = (
                        m.slot == "speed" and isinstance(who, _Actor) and who.kind in VEHICLES
                        and who.speed_mps is None and r.ego_speed_mps is None and _next_to_ego(prev, m)
                        and not ego_speed.struck_before(scanned, prev.start)
                    )  # fmt: skip
                    own = m.slot == "speed" and any(x is who and k == "speed" for x, k, _ in said_of)
                    if own and r.ego_speed_mps is None and _next_to_ego(prev, m):
                        r.ego_speed_mps = m.value  # (its own said already: "... ahead of the ego at 50" is the ego's)
                    elif r.ego_speed_mps is None and _its_own_object(
                        m, who, clause_subject, named, scanned, first_person
                    ):
                        r.ego_speed_mps = m.value  # ("a kid shot out in front of me, hit him at 25": the narrator hit)
                    elif (
                        m.slot == "relation"
                        and m.value == "behind"
                        and isinstance(who, _Actor)
                        and behind_a_thing.behind_a_thing(scanned, m.words, m.start, m.end, road_users)
                    ):
                        who.said.add("near_other")  # ("a van stopped behind a fallen tree": not the ego's rear)
                    else:
                        _apply(m, who, r, link, added)
                    if isinstance(who, _Actor) and _in_front_of_the_ego(m, nxt, who.behaviours, mentions, scanned):
                        who.said.add("ego_behind")  # ("a bus in the left lane in front of us": the ego's lane)
                    if of_both:
                        r.ego_speed_mps = m.value
                        # ("a lorry coming up behind me at 20 mph": a follower's speed, which an ego said
                        # to wait at the lights does not share)
                        shared_behind = (prev.slot == "relation" and prev.value == "behind") or prev.prev == "behind"
            prev = m
        for a, i in added:
            name, cfg, _, lk = a.behaviours[i]
            words = cfg.pop("_words", "")
            a.moves_out = a.moves_out or (name == "cross_in_front" and "out" in words.split())
            a.along = a.along or (name == "keep_going" and kerb_ride.goes_along(words))
            end, start = cfg.pop("_end", len(scanned)), cfg.pop("_start", None)
            a.across = a.across or kerb_ride.said_across(name, words, scanned[end:][:2])
            # (said after its name: a fronted "Driving straight over the crossroads, ..." is the narrator's way)
            after_name = start is not None and 0 <= a.named_end <= start
            a.straight_on = a.straight_on or (after_name and junctions.says_straight_on(name, words, scanned[end:][:2]))
            if start is not None:
                pull_in_apart.mark(name, cfg, scanned, start, end)  # (whether a pull-in is told apart)
            if start is not None and crossing_reaction.said_free(
                name, cfg, scanned, start, end, lambda w, kind=a.kind: _single_kind(w) == kind
            ):
                cfg[crossing_reaction.MARK] = 1.0  # (dropped after a crossing, once its name is final)
            if start is not None and held_pass.said_free(name, scanned, start, end, a.kind, _single_kind):
                cfg[held_pass.MARK] = held_pass.mark(name, scanned, end, _single_kind)  # (maybe the ego's)
                cfg[held_pass.SPAN] = (start, end)
            if name == "sudden_stop" and len(words.split()) == 1 and "brake" in forms(words):
                cfg["_plain_brake"] = 1.0  # ("brakes": how hard, a stop said after it tells)
            a.goes_on = a.goes_on or bool(cfg.pop("_denied", None))
            a.same_way = a.same_way or bool(cfg.pop("_same_way", None))
            cfg.pop("_still", None)
            a.has_way = a.has_way or bool(cfg.pop("_has_way", None))
            a.priority = a.priority or bool(cfg.pop("_priority", None))
            a.refuses_way = a.refuses_way or bool(cfg.pop("_refused_way", None))
            a.behaviours[i] = (name, cfg, crit_here or _verb_criticality(words), lk)
        if crit_here:
            if not named and isinstance(subject, _Actor) and subject.crit is None:
                subject.crit = crit_here  # "... and then moves back with a tiny gap": still its clause
            for who, role in named:
                if isinstance(who, _Actor) and role in ("subject", "participle") and who.crit is None:
                    who.crit = crit_here
        if not named and actors and any(p.slot == "distance" for p in pending):
            # ("..., 40 m gap": to the one named last that moves; parked cars are where it comes from)
            moving = [a for a in actors if not a.stationary] or actors
            moving = [a for a in moving if a.behaviours] or moving  # (not one only named: "my kids in the car")
            for p in [p for p in pending if p.slot == "distance"]:
                _apply(p, moving[-1], r, link, added)
            pending = [p for p in pending if p.slot != "distance"]
        if not named and pending and any(p.slot == "speed" for p in pending) and r.ego_speed_mps is None:
            # "Going straight over the junction at 30 km/h while ...": a clause with nobody named is the ego's
            r.ego_speed_mps = next(p.value for p in pending if p.slot == "speed")
            pending = [p for p in pending if p.slot != "speed"]
        if not named and subject is None and any(p.slot in ("turn", "ego_verb") for p in pending):
            # "Turning left at the junction in the afternoon; a cyclist ...": a sentence that names nobody,
            # before anyone is named, is the narrator's
            pending = _given_to_the_ego(pending, [p for p in pending if p.slot in ("turn", "ego_verb")], r, link, added)
        for x in joined:
            x.group = None
        joined = []
    unplaced = [p.words for p in pending if p.slot in ("behaviour", "turn")]  # (said of nobody)
    if unplaced and not actors and any(p.slot == "behaviour" and p.value[0] in _DRIVEN for p in pending):
        # "cut-in on a busy highway at 100 km/h": what only a vehicle does names its vehicle, a car
        car = _Actor("car", word="car")
        actors.append(car)
        done: list = []
        for p in pending:
            if p.slot == "speed" and r.ego_speed_mps is None:
                r.ego_speed_mps = p.value  # (the one speed of a terse line is the test's, the ego's)
            elif p.slot != "speed":
                _apply(p, car, r, "sequence", done)
        for a, i in done:
            name, cfg, crit, lk = a.behaviours[i]
            a.behaviours[i] = (name, {k: v for k, v in cfg.items() if not k.startswith("_")}, crit, lk)
        pending, unplaced = [], []
    if unplaced and not actors:  # something is done, and nobody the reader can place does it
        raise NotUnderstood(list(dict.fromkeys(ignored))[:12], text, missing="road user")
    for a in actors:  # a lane said of both: the road user's side is where its lane is from the ego's
        a.lane_side = sides.beside(a.lane_side, r.ego_relation)
        a.lane_side = sides.lane_of_the_followed(a.lane_side, "ego_behind" in a.said and not a.toward, r.ego_relation)
    if both_with_ego and r.ego_speed_mps is None and actors and actors[0].speed_mps is not None:
        r.ego_speed_mps = actors[0].speed_mps  # (the speed said of both)
    if r.ego_speed_mps is None:
        r.ego_speed_mps = ego_speed.kept_by_a_follower(actors)  # ("a van tailgated me at 60 mph")
    if r.ego_speed_mps is None:
        r.ego_speed_mps = set_by_the_ego  # (read past with what the ego is let do)
    if (r.ego_speed_mps is None or shared_behind) and Q.ego_at_rest(clauses, scanned):
        # ("I was sat at the lights when ..."): the ego stands still, whatever speed a vehicle said next
        # to it has ("I was stopped at the red light when a van coming behind me at 15 mph hit my car")
        r.ego_speed_mps = 0.0
    if r.ego_speed_mps is None:
        r.ego_speed_mps = ego_speed.of_traffic(scanned)  # ("Cars are usually doing 20 mph here")
    ignored += unplaced
    for a in actors:
        _out_from_cover(a)
    _refuse_if_nothing_to_place(text, actors, clauses, ignored, scanned)
    _group_acts_as_one(actors)  # ("to find two joggers in the road running towards me": both run)
    if any(not _idle(a) for a in actors):  # people and vehicles only mentioned (passengers, a car in a
        idle = [a for a in actors if _idle(a)]  # story's aside) are no road users of the scenario
        actors = [a for a in actors if not _idle(a)]
        ignored += [a.word or a.kind for a in idle]
    actors, left_out = _the_most_a_scenario_holds(actors)
    ignored += left_out
    for a in actors:
        if a.kind == UNKNOWN_KIND:  # a road user the reader has no word for: its kind from what it does
            names = {b[0] for b in a.behaviours}
            a.kind = (
                "pedestrian" if names & {"cross_in_front", "along_road"} and not names & VEHICLE_BEHAVIOURS else "car"
            )
            noun = min(_lemmas(a.word or "").get("NOUN", (a.word or "",)))
            if rider_noun(noun):
                a.kind = "e-scooter"  # ("a rider swung out": who rides, the two-wheeler this reader is about)
            elif agent_noun(noun) and not names & VEHICLE_BEHAVIOURS:
                a.kind = "pedestrian"  # ("a punter stumbled out": who does a verb is a person, on foot)
        if a.kind == "pedestrian" and a.word in L.GENERIC_PERSONS:  # "the guy in front slammed on": a driver
            names = {b[0] for b in a.behaviours}
            if (a.wrong_way or names & set(L.DRIVER_BEHAVIOURS)) and not names & {"cross_in_front", "along_road"}:
                a.kind = "car"
        if a.kind == "bicycle" and _at_a_motorbikes_pace(a, r.ego_speed_mps):
            a.kind = "car"  # ("one bike fellow came from behind and cut in" at 40 kmph: a motorbike)
        if a.hides and a.kind in VEHICLES and not a.behaviours and a.speed_mps is None:
            a.stationary = a.parked = True  # (what someone steps out from behind stands there)
        said_by_noun = L.BEHAVIOUR_NOUNS.get(a.word)
        if said_by_noun and all(b[0] in ("keep_going", "cross_in_front") for b in a.behaviours):
            a.behaviours = [(said_by_noun, {}, None, "sequence")]  # ("a red-light runner from the left")
        if (
            not a.behaviours and not a.stationary and not a.wrong_way and a.unknown
        ):  # only a verb the reader has no word for: it goes on
            a.behaviours.append((motion.default_behaviour(a.kind), {}, None, "sequence"))
    for a in actors:  # ("a cyclist along the kerb; she held back, then overtook": the ego held back and passed)
        behind = a.relation == "behind" or "behind" in a.said
        a.behaviours, span, held_behind = held_pass.egos_hold_and_pass(a.behaviours, behind)
        a.passed = a.passed or span is not None
        if held_pass.said_within(scanned, span, a.speed_at) and a.speed_mps and a.speed_mps > 0:
            r.ego_speed_mps = r.ego_speed_mps or a.speed_mps  # ("she held back at about 20 mph": the ego's)
            a.speed_mps = None
        if held_behind:  # ("held back behind, then overtook": behind is where the ego held back)
            a.said.discard("behind")
            a.relation = None if a.relation == "behind" else a.relation
    for a in actors:  # "turns out of the junction": it comes from a side road
        for k, (_name, cfg, c, lk) in enumerate(a.behaviours):
            if cfg.pop("from_side_road", None):
                if a.kind == "pedestrian" or (a.kind in RIDERS and not a.arm):
                    # "a child emerges from between parked cars": a walker (or a rider, unless a side road
                    # is said) crosses
                    a.behaviours[k] = ("cross_in_front", cfg, c, lk)
                else:
                    a.arm = a.pulled_out = True
        if a.kind == "pedestrian":  # ("comes out of a side street and crosses": one crossing)
            a.behaviours = [b for k, b in enumerate(a.behaviours) if k == 0 or b[0] != a.behaviours[k - 1][0]]
    for a in actors:
        names = [b[0] for b in a.behaviours]
        if a.kind == "pedestrian" and "run_red_light" in names:  # a walker against red crosses the road
            a.behaviours = [("cross_in_front", *b[1:]) if b[0] == "run_red_light" else b for b in a.behaviours]
            a.behaviours = [b for k, b in enumerate(a.behaviours) if k == 0 or b[0] != a.behaviours[k - 1][0]]
        elif a.kind in VEHICLES and "cross_in_front" in names and a.moves_out and _ahead_first(a):
            # a vehicle said ahead of the ego that swings out is in the ego's road already: it moves out
            # of the ego's lane ("the car ahead of us swung out round it"), no crossing traffic
            a.behaviours = [("change_lane", *b[1:]) if b[0] == "cross_in_front" else b for b in a.behaviours]
        elif a.kind in VEHICLES and "cross_in_front" in names and not (a.kerb or a.kerb_side or a.lane_side):
            # a vehicle crossing the ego's road goes through a junction across its path
            a.behaviours = [("run_red_light", *b[1:]) if b[0] == "cross_in_front" else b for b in a.behaviours]
        elif a.kind in VEHICLES and "cross_in_front" in names and a.lane_side:
            # a vehicle moving across from a lane: into the ego's (what it does next, if said; going on
            # after it, "didn't stop", "drove on", says nothing of its own)
            rest = [b for b in a.behaviours if b[0] not in ("cross_in_front", "keep_going")]
            a.behaviours = rest or [("cut_in", *a.behaviours[0][1:])]
    r.ego_route = ego_route(tokens) or ego_route(scanned) or r.ego_route  # (a turn whose subject is the ego,
    # as written or as the ego is named once it is known: "Taxi (our driver) entering ... to go right")
    for a in actors:  # the ego turning towards the side a rider goes straight on: the rider goes its way
        if (
            r.ego_route in ("left", "right")
            and a.kind in RIDERS
            and (a.side or a.lane_side) == r.ego_route
            and [b[0] for b in a.behaviours] in ([], ["keep_going"])
        ):
            a.said.add("ahead")
    vehicles_giving_way = any(a.kind in VEHICLES and any(b[0] == "give_way" for b in a.behaviours) for a in actors)
    at_junction = any(b[0] in JUNCTION_BEHAVIOURS for a in actors for b in a.behaviours)
    if (
        (r.map_kind in (None, "straight") and r.ego_route in ("left", "right"))
        or (r.map_kind in (None, "straight") and (any(a.arm for a in actors) or vehicles_giving_way or at_junction))
        or (
            r.map_kind in (None, "straight", "curve")
            and (S.turns_into_a_road(text, said) or S.streets_meet(text, said))
        )
        or (r.map_kind == "curve" and r.ego_route in ("left", "right") and S.bend_only_a_corner(said))
    ):
        r.map_kind = "crossroad"  # the ego turns, or someone comes out of or waits in a side road: a junction
    junction = r.map_kind in ("crossroad", "roundabout")
    # (what the whole text says, read once for every road user's behaviours below)
    left_hand, across, signal = sides.drives_on_left(scanned, text), turn_across_side(text), junctions.signal_said(said)
    for a in actors:  # (of the distances said of it, the one where it is put in the scene)
        if (start := start_gap.start_of(a.gaps_said, scanned, a.named_end)) is not None:
            a.distance_m, a.end_gap = start[1], start[3]
    for a, slot, value in said_of:
        a.speed_mps, a.distance_m = (value, a.distance_m) if slot == "speed" else (a.speed_mps, value)
    for a in actors:
        spec = ActorSpec(a.kind)
        if (
            a.kind in VULNERABLE
            and a.along
            and not (a.came_from or a.pavement or a.stationary or a.lane_side or a.own_lane)
        ):
            side = a.kerb_side or a.side
            a.behaviours = kerb_ride.along_then_out(a.behaviours, a.across, side) or a.behaviours
        behaviours = _tidy(a)
        if a.kind == "pedestrian" and a.goes_on:  # a walker who does not give way or wait: crosses
            behaviours = [
                ("cross_in_front", c, k, lk) if n == "cut_in" else (n, c, k, lk) for n, c, k, lk in behaviours
            ]
            behaviours = [b for k, b in enumerate(behaviours) if k == 0 or b[0] != behaviours[k - 1][0]]
        if (
            a.kind == "pedestrian"
            and a.word not in L.GENERIC_PERSONS
            and behaviours[:1]
            and behaviours[0][0] in ("cut_in", "change_lane")
        ):  # "a dog bolted into the road": a walker (a child, an animal) moving into the road crosses it
            behaviours = [("cross_in_front", {}, *behaviours[0][2:])] + behaviours[1:]
        if a.kind == "pedestrian" and behaviours and behaviours[0][0] in VEHICLE_BEHAVIOURS:
            spec.kind = a.kind = "car"
        moving_out = behaviours and behaviours[0][0] == "cut_in" and a.followed
        if a.toward and behaviours:  # where it moves to: a lane change's direction, or a cut-in's far side
            if behaviours[0][0] in ("change_lane", "cut_out") or moving_out:
                origin = a.lane_side or a.side  # ("a truck in the right lane moves into the left lane": from there)
                a.lane_side, a.side = None, a.toward
                a.relation = sides.origin_lane(origin, a.relation) or a.relation
            elif kerb := sides.kerb_beside_lane(a.kerb, a.kerb_side, a.came_from, a.toward):
                a.kerb_side = kerb  # ("stepped off the verge into the right lane": that lane's kerb)
            elif not (a.lane_side or a.side or a.kerb_side):
                a.side = "left" if a.toward == "right" else "right"
        if behaviours and behaviours[0][0] == "change_lane" and sides.starts_in_lane(a.lane_side, a.side, a.toward):
            name, cfg, c, lk = behaviours[0]  # "a coach in the left lane moves over": from there, towards the ego
            behaviours[0] = (name, {**cfg, "direction": -1.0 if a.lane_side == "left" else 1.0}, c, lk)
        elif behaviours and (behaviours[0][0] in ("change_lane", "cut_out") or moving_out) and (a.lane_side or a.side):
            name, cfg, c, lk = behaviours[0]  # "moves over into the right lane": where to, not where from
            behaviours[0] = (name, {**cfg, "direction": 1.0 if (a.lane_side or a.side) == "left" else -1.0}, c, lk)
            a.lane_side = a.side = None
        classes = [b[2] for b in behaviours if b[2]] or ([a.crit] if a.crit else [])
        if classes:  # the tone of what it does carries over to its unqualified behaviours
            behaviours = [(n, c, k or classes[0], lk) for n, c, k, lk in behaviours]
        if not behaviours and a.stationary:
            behaviours = [("stop", {}, None, "sequence")]  # (standing: stopped, and stays so)
        if not behaviours:  # where it is said, but not what it does: it goes on
            behaviours = [("keep_going", {}, None, "sequence")]
        behaviours = motion.passed_goes_along(behaviours, a.passed)
        if a.passed and behaviours[0][0] == "along_road" and not (a.relation or a.said):
            a.said.add("ahead")  # (what the ego passes starts ahead of it)
        if a.accel_mps2 is not None:  # "at 6 m/s²": the deceleration or rate of what it does (within its range)
            behaviours = [(*_with_rate(n, c, a.accel_mps2), k, lk) for n, c, k, lk in behaviours]
        if a.speed_to_mps is not None and a.speed_mps is not None and a.speed_mps >= 0:  # "slows from 80 to 30"
            delta = a.speed_to_mps - a.speed_mps
            behaviours = [
                (n, {**c, "speed_delta_mps": delta} if n == "change_speed" else c, k, lk) for n, c, k, lk in behaviours
            ]
        if behaviours and behaviours[0][0] == "cut_in" and a.distance_m is not None:
            name, cfg, c, lk = behaviours[0]
            behaviours[0] = (name, {**cfg, "gap_m": a.distance_m}, c, lk)
        if a.end_gap and a.distance_m is not None:  # ("passes me and cuts back in 3 m ahead": its end gap)
            behaviours = [
                (n, {**c, "gap_m": a.distance_m} if n == a.end_gap else c, k, lk) for n, c, k, lk in behaviours
            ]
        if (
            a.kind in VULNERABLE
            and (a.relation or "").startswith("junction_")
            and not junction
            and all(b[0] == "keep_going" for b in behaviours)
        ):  # "a pedestrian crossing from the left" where there is no junction: it crosses from that kerb
            a.relation = "roadside_" + str(a.relation).rsplit("_", 1)[1]
            crit = next((b[2] for b in behaviours if b[2]), a.crit)
            behaviours = [("cross_in_front", {}, crit, "sequence")]
        if a.kind in RIDERS and junction and behaviours[:1] and behaviours[0][0] == "cut_in":
            if not (a.lane_side or a.followed or a.toward or "ahead" in a.said or a.goes_on or a.arm or a.same_way):
                # "an e-scooter cuts across at a junction": a rider crossing the ego's road
                behaviours = [("cross_in_front", {}, *behaviours[0][2:])] + behaviours[1:]
        overtaking = any(b[0] == "overtake" for b in behaviours)  # (it rides along, and out to pass)
        if a.kind in RIDERS and overtaking:
            behaviours = [b for b in behaviours if b[0] != "cross_in_front"] or behaviours  # ("... right into my path")
        joins = a.along or any(b[0] in _GOING_ON for b in behaviours[1:])  # (and rides on along the road)
        if (
            a.kind in RIDERS
            and (a.pavement or (a.out_of_place and not joins))
            and not overtaking
            and behaviours
            and (
                behaviours[0][0] in ("cut_in", "forced_turn")
                or (a.pavement and not joins and behaviours[0][0] == "cut_out")
            )
        ):
            # "riding on the sidewalk, then turning into the road before our car": it crosses into the path;
            # so does one coming out of a place beside the road ("out of a driveway", "out of a farm track and
            # across"), unless it then rides on along the road; a swerve on a pavement leaves no lane of
            # the road but the pavement ("swerved round a woman on the footpath and into the road")
            behaviours = [("cross_in_front", {}, *behaviours[0][2:])] + behaviours[1:]
        crossing_at = next((k for k, b in enumerate(behaviours) if b[0] == "cross_in_front"), None)
        before = {b[0] for b in behaviours[:crossing_at]} if crossing_at else set()
        along_first = a.along and all(b[0] == "along_road" for b in behaviours[:1])
        if (
            a.kind in VULNERABLE
            and crossing_at
            and before <= {"keep_going", "stop", "along_road", "keep_lane"}
            and not along_first  # (going along the edge, then across: both, see kerb_ride)
        ):
            behaviours = behaviours[crossing_at:]  # ("... stops; then crosses from the left"): from the kerb
        a.behaviours = behaviours
        a.kerb_side = a.kerb_side or from_cover.side_of_the_cover(a, a.cover)
        if a.relation is None and not a.said and met_coming(scanned, a.named_end):
            a.relation = "oncoming"  # ("we met a tractor coming up the lane": face to face)
            a.said.add("oncoming")
        spec.relation = _resolve_relation(a, r.map_kind, left_hand)
        spec.relation = sides.kerb_overtaker(
            spec.relation, behaviours, bool(a.side or a.kerb_side or a.lane_side), any(x.object_of is a for x in actors)
        )  # ("a kid in the bike lane overtook me": from behind)
        first_act = behaviours[0][0] if behaviours else None
        own_side = a.side or a.kerb_side or a.lane_side
        spec.relation = (
            junctions.crosses_the_arm_turned_into(a.kind, first_act, a.arm, a.from_arm, own_side, r.ego_route)
            or spec.relation
        )  # ("I turned left into it; a man was crossing the side road": on the left)
        said_arm = a.relation.rsplit("_", 1)[1] if a.relation in ("junction_left", "junction_right") else None
        off_road = bool(
            a.kerb or a.kerb_side or a.pavement or a.lane_side or a.stationary or a.goes_to or a.out_of_place
        )
        runs_red = any(b[0] == "run_red_light" for b in behaviours)  # (a red at the arm's stop line)
        if junction:
            spec.relation = (
                junctions.rides_through_from_a_side(
                    spec.relation, a.kind, first_act, said_arm or (a.side if runs_red else None), off_road, r.ego_route
                )
                or spec.relation
            )  # ("a cyclist came through from the right": along the crossing road, not off its kerb)
        if (
            junction
            and spec.relation in ("junction_left", "junction_right")
            and behaviours[:1]
            and (
                (behaviours[0][0] == "keep_going" and not a.stationary and not a.has_way)
                or (behaviours[0][0] == "cross_in_front" and a.kind in RIDERS)
            )
        ):  # entering the junction from a side road: across the ego's path
            if a.kind == "pedestrian":  # (on foot, from the kerb of that side: a walker does not drive an arm)
                spec.relation = "roadside_" + spec.relation.split("_")[1]
                behaviours[0] = ("cross_in_front", behaviours[0][1], behaviours[0][2], behaviours[0][3])
            else:
                behaviours[0] = ("run_red_light", behaviours[0][1], behaviours[0][2], behaviours[0][3])
        spec.behaviours = behaviours
        if (
            behaviours[:1]
            and behaviours[0][0] == "cut_in"
            and "behind" in a.said
            and spec.relation in ("left", "right")
            and a.speed_mps is None
        ):  # "comes up behind on the right and dives into our lane": it passes the ego first
            a.speed_mps = -V.SPEED_WORDS["fast"]
        spec.distance_m = a.distance_m
        spec.speed_mps = 0.0 if a.stationary and a.speed_mps is None else a.speed_mps
        passes_another = any(x.object_of is a for x in actors)  # ("pulled out to pass a truck": its own overtake)
        only_there = [b[0] for b in spec.behaviours] in ([], ["keep_going"])  # (nothing it does is said)
        going_on = [b[0] for b in spec.behaviours[:1]] != ["cut_in"]  # (not "doesn't yield": it takes the way)
        _specialise(a, spec, junction, left_hand, across, passes_another, signal)
        if a.kind in VEHICLES:  # ("pulled out of a driveway on the right": it turns into the road)
            spec.behaviours = access_pull_out.turns_in_from_an_access(a.place, spec.relation, spec.behaviours)
        spec.behaviours = junctions.through_from_opposite(
            spec.relation, spec.behaviours, said, passes_another, going_on
        )
        spec.behaviours = ring_entry.joins_the_ring(
            r.map_kind,
            signal,
            spec.relation,
            a.refuses_way,
            a.priority,
            a.takes_an_exit,
            spec.behaviours,
            said,
        )  # ("came onto the roundabout from the left without giving way": onto the ring, in front of the ego)
        if along_first and len(spec.behaviours) > 1 and spec.behaviours[0][0] == "along_road":
            kerb_ride.at_the_edge(spec, a.kerb_side or a.side or a.lane_side)
        if only_there and _waits_at_a_crossing(a, spec, said):
            spec.behaviours = [("cross_in_front", {}, *spec.behaviours[0][2:])]  # ("stopped at the zebra for a mum")
            spec.relation = spec.relation if spec.relation in ("roadside_left", "roadside_right") else "roadside_right"
        r.actors.append(spec)
    for spec in r.actors:  # ("pulled out in front of me. Braked": the ego's brake, not the road user's)
        spec.behaviours = crossing_reaction.drop_egos_reactions(spec.behaviours)
    for a, spec in zip(actors, r.actors):  # ("a boy ran out and I stopped 2 m short of him": how near it came)
        stopped_short.gap_from_the_stop(spec, a.stopped_short_m)
    for a, spec in zip(actors, r.actors):  # what an oncoming car overtakes comes towards the ego too
        k = next((k for k, x in enumerate(actors) if x is a.object_of), None)
        if (spec.relation is None or (a.relation is None and not a.said)) and k is not None:
            other = r.actors[k]
            along = [b[0] for b in spec.behaviours[:1]] == ["along_road"]
            if other.relation in ("oncoming", "junction_opposite") and along:
                spec.facing = "against"  # (a walker or rider along the road, ahead: coming the other way)
            elif other.relation in ("oncoming", "junction_opposite"):
                spec.relation = other.relation
    follower_start.starts_with_the_followed(actors, r.actors)  # ("... and a scooter came out right behind it")
    if ego_follows and actors and r.ego_speed_mps is None and actors[0].speed_mps:
        r.ego_speed_mps = actors[0].speed_mps  # "Following a truck at 60 km/h": both at that speed
    ego_named = ego_double.names_the_ego(text)  # ("... ahead of the ego": no other vehicle is taken for it)
    if not ego_named:  # (before a braking driver is taken for one to swerve round)
        actors = ego_double.merge_ego_driver(actors, r)  # ("Driver braked hard and our cases slid everywhere")
    from_cover.cover_stands(actors, r)  # ("ran out between parked cars ... the taxi stopped in time")
    parked_rows.rows_stand(actors, r, scanned)  # ("cars parked both sides, and a lad shot out": they stand)
    _parked(actors, r.actors)
    _cut_outs(
        r.actors,
        {k for k, a in enumerate(actors) if a.double_parked and a.kind in VEHICLES},
        {k for k, a in enumerate(actors) if a.followed},
        {k for k, a in enumerate(actors) if stands_elsewhere(scanned, a.named_end)},
    )
    _criticality_said_apart(clauses, r.actors)
    apply_manner(stated_manner(tokens), r.actors)  # (the scales of closeness, margin and timing)
    for spec in r.actors:
        spec.behaviours = _one_act_once(spec)
        before = spec.behaviours[0][0] if spec.behaviours else None
        spec.behaviours = one_path(spec, said, across)
        after = spec.behaviours[0][0] if spec.behaviours else None
        spec.relation = sides.overtaker_start(before, after, spec.relation)  # ("overtook me and turned left")
    if r.map_kind is None and any(s.relation == "junction_opposite" for s in r.actors):
        r.map_kind = "crossroad"
    r.ego_speed_mps = ego_said if ego_said is not None else r.ego_speed_mps
    r.ignored = list(dict.fromkeys(ignored))
    r.read_as = read_as
    user_names = proper_names(text) | {a.word.split()[-1] for a in actors if a.word}  # ("I hit the Golf": no thing)
    cues = outcome_cues(said, frozenset(user_names))
    sudden = any(  # ("shot out", "suddenly"; not going on as it was: "just carried on alongside")
        b[2] == "dangerous" and b[0] not in _GOING_ON for a in r.actors for b in a.behaviours
    )
    intruded = any(b[0] in _INTRUSIONS for a in r.actors for b in a.behaviours)  # ("cut in", "pulled out")
    entered = any(b[0] in _INTO_A_PATH for a in r.actors for b in a.behaviours)  # ("ran the red", "crossed")
    r.intent = decide(cues, sudden, intruded, entered)  # (the outcome reader alone decides contact: not "hit the horn")
    actors = said_again.merge_said_again(actors, r)  # ("a car ran the red. This guy in a red SUV ...": one)
    actors = heading_named.merge_heading_named(actors, r, scanned)  # ("Scenario: Van brakes. When a van ...")
    actors = heading.fold_told_again(actors, r, heading.heading_end(text, scanned, _tokens))  # (a title line)
    afoot = False  # (the writer on foot in the scene, in no vehicle of their own)
    if not ego_named:
        outside = bystander or narrator_outside.outside(scanned, _kind_at, _known)  # ("we watched ...", "my son ...")
        writer_only = outside and not ego_double.addressed(text)  # (their "I" names no ego; "you" still does)
        unnamed = ego_double.ego_unnamed(scanned, clauses, writer_only)  # (no narrator at a wheel, no phrase)
        actors = ego_double.merge_into_ego(actors, r, unnamed, scanned)  # ("Bus was doing 45")
        actors = ego_turner.merge_turner_into_ego(actors, r, unnamed)  # ("the test car turns right; a rider ...")
        actors = ego_turner.merge_overtaken_into_ego(actors, r, scanned)  # ("a cyclist overtaking the bus")
        phrase = ego_double.ego_phrase(clauses)  # ("the VUT": one brought in as new is someone else)
        phrase = phrase and not outside  # ("we are told ...": the writer, not an ego phrase)
        afoot = outside and narrator_outside.on_foot(scanned)  # ("I stepped off the kerb and a van went past me")
        actors = report_vehicle.merge_report_vehicle(actors, r, text, phrase, outside)  # ("a Fiesta driven by")
        actors = report_vehicle.merge_threatened_vehicle(actors, r, text, phrase)  # ("cut in in front of the car")
    actors = ego_double.drop_both_said_again(actors, r)  # ("a van cut the corner. Both drivers braked hard")
    actors = crowds.drop_crowds(actors, r)  # ("there were kids everywhere, and a cyclist pulled out")
    actors = crowds.drop_counts(actors, r, scanned)  # ("212 vehicles turned in and no conflicts were recorded")
    actors = kind_in_general.drop_kinds_in_general(actors, r, scanned)  # ("e-scooters are a menace. A rider shot out")
    actors = narrator_ride.drop_narrators_ride(actors, r, scanned, _kind_at)  # ("I was on one of your e-scooters")
    actors = writer_on_foot.the_writer_met(actors, r, scanned, afoot)  # ("I stepped out and a taxi went past me")
    actors = bystanders.drop_bystanders(actors, r)  # ("a car he loved ... a boy on a bike shot out")
    told = {w for cue in cues for w in cue.words.split()}  # (words the outcome was read from)
    r.ignored = [w for w in r.ignored if w not in told]
    if r.intent is None and not r.actors:
        r.intent = "safe"  # (nobody but the ego: nothing it could meet)
    tight_cut_ins(r.actors, r.ego_speed_mps, r.intent)  # ("cut in 5 m in front of me at 60 mph": dangerous)
    Q.struck_at_rest(r.actors, r.ego_speed_mps, r.intent)  # ("I was waiting at the lights when a van hit me")
    scene_pace.ego_at_the_scene_pace(r, any(a.passed for a in actors))  # ("he hit the scooter doing 30")
    if r.ego_speed_mps is None and r.scene_pace_mps is None and road_limit is not None:
        r.ego_speed_mps = road_limit  # ("The limit is 40. A cyclist doing 15 pulled out": at the road's limit)
    r.lanes = stated_lanes(said) or r.lanes
    oncoming = any(s.relation == "oncoming" or any(b[0] == "wrong_way" for b in s.behaviours) for s in r.actors)
    r.lanes = S.lanes_of_two_way_road(said, oncoming) or S.lanes_counted(said) or r.lanes
    r.lanes = max(r.lanes or 0, S.lanes_at_least(said) or 0) or r.lanes  # ("in lane 3": three at least)
    r.lanes = r.lanes or S.lanes_of_one_way_road(said)  # ("down the one-way street": one lane)
    no_lane_beside.to_the_edge(r)  # ("a cyclist on my left, one lane each way": at the kerb)
    if r.map_kind in (None, "straight"):
        r.map_kind = S.many_turns(said) or r.map_kind  # ("a small road with a lot of turns": a bend)
    if r.map_kind in (None, "straight") and S.signalled_junction(text, said):
        r.map_kind = "crossroad"  # ("ran the red", "at the Harbour Rd lights", "at Queen/Albert")
    talking = S.speakers(text)  # (a greeting opens a speaker's turn: "OFFICER: Evening.", not an answer)
    greeted = {
        m.start
        for _, ms in clauses
        for m in ms
        if m.slot == "time" and S.greeting(m.prev, m.words, m.next_, S.opens_a_turn(scanned, m.start, talking))
    }
    said_as = [
        (m.slot, m.words, m.value)
        for _, ms in clauses
        for m in ms
        if m.slot == "weather" or (m.slot == "time" and m.prev not in S.BOUNDS and m.start not in greeted)
    ] + [("time", words, clock) for words, clock in S.day_halves(said)]  # ("Tues AM": the morning)
    if greeted and not any(k == "time" for k, _, _ in said_as):
        r.time = None  # (the only part of the day said greets: "OFFICER: Evening. Do you know why ...")
    clocked = S.without_bounds(said)  # (the text's clocks of the time it happens)
    parts = [v for k, w, v in said_as if k == "time"]
    stamps = S.line_stamps(text)  # (when each line was said or logged: "[00:20:15] Ian: ... Dusk, ...")
    body = S.without_clocks(clocked, stamps)
    clock = S.dotted_clock(body) or stated_clock(body) or S.log_clock(text, _vehicle_word)
    clock = S.twelve_hour(clock, body, parts) or S.clock_in_words(body, parts)
    part = next((v for k, w, v in said_as if k == "time" and w not in S.TIME_HINTS), None)
    if (
        clock is None
        and (part is None or not S.running_time(stamps))
        and S.agrees(stamp := stated_clock(clocked), part)
    ):
        clock = stamp  # (a log's or a chat's stamp, within any part of the day said: when it happened)
    r.time = S.time_of_day([(w, v) for k, w, v in said_as if k == "time"], clock) or r.time
    plain = [(w, v) for k, w, v in said_as if k == "weather"]
    weather = S.weather_said([(m.words, m.value, m.prev) for _, ms in clauses for m in ms if m.slot == "weather"])
    if weather != plain:  # (a season or a past weather set aside: "foggy winter mornings", "wet after rain")
        r.weather = S.most_severe(weather)
    r.weather = S.sky_over_surface(weather) or r.weather or S.sunny(said)
    r.density = S.density(said, r.density)
    if r.weather in (None, "rain") and stated_heavy_rain(said):
        r.weather = "heavy_rain"
    return r


#: Conjunctions that join two clauses each with a subject of its own ("turned left and a cyclist ...").
_JOINING = frozenset(("and", "but", "when", "then", "so"))


def _left_out_subjects_acts(pending: list, prev, r: Reading, link: str, added: list) -> list:
    """``pending`` with the finite verbs said before a joining conjunction that the first road user of
    the text follows put on the ego ("Hung a left onto Broadway and an e-scooter rider came at me",
    "Turned right at the lights but a van ..."): the clause before "and" had its own subject, left out,
    which cannot be the road user the clause after it opens with; before anyone is named it is the
    narrator. So is a participle of turning ("Turning left at the lights and a cyclist came up my
    inside"): a participle that opens a sentence says what its subject does, and the conjunction
    puts that subject before it; said with only a comma ("Turning left, a cyclist ...") it may be the
    road user's and stays pending."""
    if prev is None or prev.slot != "conj" or prev.value not in _JOINING:
        return pending
    mine = [
        p
        for p in pending
        if p.slot in ("turn", "behaviour", "ego_verb")
        and p.end <= prev.start
        and (not p.words.split()[0].endswith("ing") or p.slot == "turn")
    ]
    return _given_to_the_ego(pending, mine, r, link, added)


def _given_to_the_ego(pending: list, mine: list, r: Reading, link: str, added: list) -> list:
    """``pending`` less the mentions in ``mine``, each applied to the ego."""
    for p in mine:
        _apply(p, "ego", r, link, added)
    return [p for p in pending if all(p is not x for x in mine)]


def _walkers_do_not_turn(pending: list, who: _Actor | str, r: Reading, link: str, added: list) -> list:
    """``pending`` with a participle of turning that opened the sentence put on the ego when the subject
    its comma leads to is a walker ("Turning right into Elm Grove, a man was already crossing the side
    road"): a walker turns into no road, so the participle dangles, as notes let it, from the writer
    who drives. A rider or a vehicle may be the one turning ("Turning left, the cyclist wobbled") and
    keeps it."""
    if not isinstance(who, _Actor) or who.kind != "pedestrian":
        return pending
    mine = [p for p in pending if p.slot == "turn" and p.words.split()[0].endswith("ing")]
    return _given_to_the_ego(pending, mine, r, link, added)


def _ahead_first(a: _Actor) -> bool:
    """Whether road user ``a`` is said to be ahead of the ego before it moves ("the car ahead of us
    swung out"; not "swung out in front of us", where it ends)."""
    return a.relation == "ahead" and "ahead_first" in a.said


def _vehicle_word(word: str) -> bool:
    """Whether ``word`` names a vehicle or its make ("honda", "van"): a year before it is a model year."""
    return word in L.CAR_MAKES or word in L.TRUCK_MAKES or word in L.CAR_NOUNS or word in ("model", "year")


def _one_act_once(spec: ActorSpec) -> list:
    """Its behaviours with one act said twice read once: a walker or rider's crossing said again as
    coming "into the ego's path" (a cut-in is a lane change, which they do not make after crossing), a
    hard stop said again as "came to a complete stop", a run of the red said again, a crossing after
    giving way (behind the ego: give_way plays it so), a cut across the ego's lane to turn said as a
    cut-in first."""
    out: list = []
    for b in spec.behaviours:
        prev = out[-1][0] if out else None
        if prev == "cross_in_front" and b[0] == "cut_in" and spec.kind in VULNERABLE:
            continue
        if prev == "sudden_stop" and b[0] == "stop":
            continue
        if prev == b[0] == "run_red_light":  # ("ignores the red signal and shoots across": one run of one junction)
            continue
        if prev == "give_way" and b[0] == "cross_in_front":  # (giving way, it crosses behind the ego: one act)
            continue
        if prev == "cut_in" and b[0] == "forced_turn":  # ("cuts across in front of me to turn left": one act)
            out[-1] = b
            continue
        out.append(b)
    return out


def _criticality_said_apart(clauses, specs: list[ActorSpec]) -> None:
    """A manner said of the encounter in a clause of its own ("Ego passes with plenty of room", "the
    distance is only 5 m, too early"): with one road user in the scene and nothing said of how it moves,
    that manner is its (one class said, none contradicting it). A manner said in a clause that names
    another road user ("a bus behind me stopped safely") is that road user's, not the encounter's."""
    said = {
        m.value
        for _, mentions in clauses
        if not any(x.slot == "actor" and x.value != "ego" for x in mentions)
        for m in mentions
        if m.slot == "criticality"
    }
    acting = [s for s in specs if s.speed_mps != 0.0 or any(b[0] not in ("keep_going", "stop") for b in s.behaviours)]
    if len(said) != 1 or len(acting) != 1 or any(b[2] for b in acting[0].behaviours):
        return
    crit = said.pop()
    acting[0].behaviours = [(name, cfg, crit, link) for name, cfg, _, link in acting[0].behaviours]


#: What someone does when a road user comes into its path: braking, slowing, stopping.
_REACTIONS = ("sudden_stop", "stop", "change_speed")
#: Behaviours of a road user going on as it was: none is an act that can be sudden.
_GOING_ON = frozenset(("keep_going", "keep_lane", "along_road", "follow_vehicle"))
#: Acts that put a road user into the ego's lane or way from beside it or from another road: a brake
#: the ego makes beside one was forced on it.
_INTRUSIONS = frozenset(("cut_in", "turn_into", "forced_turn"))
#: Acts that bring a road user into another's path, not the hard brake or the swerve of one ahead.
_INTO_A_PATH = ego_double.IN_THE_PATH - {"sudden_stop", "cut_out"}
#: What someone does to get out of the way: swerving, dodging.
_EVASIONS = ("cut_in", "change_lane", "cut_out")
#: Behaviours only a vehicle does: said with no road user, a car does them.
_DRIVEN = ("cut_in", "overtake", "run_red_light", "turn_across", "turn_into", "wrong_way", "cut_out", "forced_turn",
           "follow_vehicle", "change_lane")  # fmt: skip
#: Behaviours that bring a road user into the ego's path: what follows them unattributed is a reaction.
_CONFLICTS = ("cross_in_front", "run_red_light", "cut_in", "wrong_way", "turn_across", "turn_into", "overtake",
              "forced_turn")  # fmt: skip


def _past(word: str) -> bool:
    """Whether ``word`` is a verb in the past tense ("slowed", "braked", "stopped")."""
    lemmas = _lemmas(word).get("VERB", ())
    return bool(lemmas) and word not in lemmas and not word.endswith(("s", "ing"))


def _ego_reaction(mentions, k: int, a: _Actor, first_person: bool = False) -> bool:
    """Whether braking or stopping ``mentions[k]`` is the narrator's reaction to road user ``a`` rather
    than ``a``'s own: said after a comma with nobody named ("drifts into our lane, on the brakes, he
    misses us", "comes off the pavement, braking, braking ... contact"), not as a finite verb
    ("then brakes hard" stays its own), once ``a`` has already come into the ego's path; or, in a
    story told in the first person, opening a sentence with no subject in the past tense or the
    plain form ("Slowed down, gave her loads of space.", "Stopped.", "Slow and easy."), not the third
    person ("Brakes hard." stays the road user's)."""
    m = mentions[k]
    opening = not any(x.slot in ("actor", "pronoun", "member") for x in mentions[:k])  # (nobody named before it)
    if m.slot == "behaviour":
        verb = m.words.split()[0]
        said_alone = first_person and opening and (_past(verb) or not verb.endswith("s"))
        joined = any(x.slot in ("link", "conj") and x.words.split()[-1] in ("then", "and") for x in mentions[:k])
        said_alone = said_alone and not joined  # ("... into my lane and then braked": its)
        if said_alone and m.value[0] in _REACTIONS + _EVASIONS:
            return True  # "Slowed down, gave her loads of space.": a diary's sentence without its "I"
        if m.value[0] not in _REACTIONS:
            return False
        if not (verb.endswith("ing") or m.prev == "on"):
            return False
    elif m.slot != "stationary" or m.words not in ("stopped", "stopping"):
        return False
    elif first_person and opening:
        return True  # ("Full brake. Stopped.")
    j = k - 1
    while j >= 0 and mentions[j].slot in ("criticality", "speed_word"):
        j -= 1
    if j < 0 or mentions[j].slot != "punct" or mentions[j].value != ",":
        return False
    came_in = a.came_from and a.kind in VULNERABLE  # (a walker or rider coming off the kerb)
    return came_in or any(b[0] in _CONFLICTS for b in a.behaviours)


def _out_from_cover(a: _Actor) -> None:
    """A walker or rider said to come out from behind or between something, of whom nothing says more
    than that it goes, crosses from the kerb (:mod:`from_cover`); so does one said to come out from
    cover or off the kerb of whom nothing more is said than brakes said free of it, which are the
    ego's (:mod:`kerb_crossing`). "Behind" said there is where it hid, not a place behind the ego
    ("stepped from behind a bus")."""
    quiet = not (a.along or a.stationary or a.passed or a.wrong_way or a.followed or a.own_lane)
    off_the_side = a.from_cover or (a.kerb and a.came_from)
    at_the_ego = a.relation == "oncoming" or "oncoming" in a.said  # ("... and ran down the road towards us")
    braked = (
        kerb_crossing.crossing_then_brakes(a.kind, a.behaviours, quiet and not at_the_ego, bool(a.unknown))
        if off_the_side
        else None
    )
    if braked:  # ("came out between parked cars, I braked": its crossing, then the ego's brake)
        a.behaviours = braked
    elif a.from_cover and from_cover.crosses_from_cover(a.kind, a.behaviours, quiet):
        link = a.behaviours[0][3] if a.behaviours else "sequence"
        a.behaviours = [("cross_in_front", {}, None, link)]
    else:
        return
    a.said.discard("behind")
    if a.relation == "behind":
        a.relation = None


def _group_acts_as_one(actors: list[_Actor]) -> None:
    """Give each member of a group of whom nothing is said what is said of a member that acts. Why: a
    group is named in one phrase ("two joggers", "a couple of kids"), and what the phrase's verb or
    place says is said of all of them; a clause that hands it to the first member alone must not leave
    the others idle, to be dropped as only mentioned."""
    for a in actors:
        acting = next((m for m in a.group or [] if m is not a and not _idle(m)), None)
        if acting is None or not _idle(a):
            continue
        for f in fields(_Actor):
            if f.name not in ("group", "word", "det", "named_after", "member_named"):
                value = getattr(acting, f.name)
                setattr(a, f.name, copy(value) if isinstance(value, (list, set, dict)) else value)


def _the_most_a_scenario_holds(actors: list[_Actor]) -> tuple[list[_Actor], list[str]]:
    """The road users a scenario holds (``MAX_ACTORS``) and the words of those left out. A long text
    names more people and vehicles than act in it (a forum post's setup, a queue): the ones that move
    are kept first, then those said to do what the reader has no behaviour for, then those only standing
    (:func:`_standing_rank`), each group in the order the text names them, and the rest are said to be
    not used rather than the whole description refused."""
    if len(actors) <= MAX_ACTORS:
        return actors, []
    ranked = sorted(range(len(actors)), key=lambda i: (_standing_rank(actors[i]), i))
    kept = sorted(ranked[:MAX_ACTORS])
    left = Counter(actors[i].word or actors[i].kind for i in sorted(ranked[MAX_ACTORS:]))
    named = ", ".join(word if n == 1 else f"{word} ({n})" for word, n in left.items())
    return [actors[i] for i in kept], [f"{len(actors)} road users, a scenario holds {MAX_ACTORS}: {named}"]


def _standing_rank(a: _Actor) -> int:
    """How little ``a`` does: 0 a manoeuvre ("pulled out in front of me"), 1 only going on, 2 nothing the
    reader has a behaviour for (what it does is told otherwise: "the moped hit her"), 3 only standing or
    waiting ("a bus, two taxis ... were all waiting")."""
    names = {b[0] for b in a.behaviours}
    if names - {"stop", "keep_going", "along_road", "keep_lane"} and not a.parked:
        return 0  # (a manoeuvre: "a tractor pulled out in front of me")
    if names - {"stop"} and not a.parked:
        return 1
    return 3 if names or a.stationary or a.parked else 2


def _idle(a: _Actor) -> bool:
    """Whether nothing is said of ``a`` but its name (and verbs the reader has no word for)."""
    return not (
        a.behaviours or a.stationary or a.speed_mps is not None or a.distance_m is not None or a.relation
        or a.said or a.wrong_way or a.side or a.kerb or a.lane_side or a.kerb_side or a.arm or a.followed
        or a.parked or a.object_of is not None or a.acted_on
    )  # fmt: skip


def _refuse_if_nothing_to_place(
    text: str, actors: list[_Actor], clauses, ignored: list[str], tokens: list[str]
) -> None:
    """Refuse only what cannot become a scenario: no road user at all (not even the ego) and nothing
    else read, or road users of which nothing at all says what they do or where they are (the
    refusal names what is missing and the words not used). Anything else is read as far as it goes."""
    unused = list(dict.fromkeys(ignored))
    mentions = [m for _, ms in clauses for m in ms]
    if not actors:  # a scene with nobody in it ("It was raining on Tuesday.") names no road user, not even the ego
        said = any((m.slot == "actor" and m.value == "ego") or m.slot in _EGO_SAID for m in mentions)
        if not said:
            raise NotUnderstood(unused[:12], text, missing="road user")
        return
    verbs = any(m.slot in _VERBS for m in mentions)
    described = any(
        a.behaviours or a.stationary or a.unknown or a.speed_mps is not None or a.relation or a.said or a.wrong_way
        or a.side or a.kerb or a.lane_side or a.distance_m is not None or a.arm
        for a in actors
    )  # fmt: skip
    if not (verbs or described):
        if any(m.slot == "intent" for m in mentions) or _did_something(mentions, tokens, set(unused)):
            for a in actors:  # ("a van nicked my mirror", "was clipped by"): it did something; its kind's commonest
                a.behaviours.append((motion.default_behaviour(a.kind), {}, None, "sequence"))
            return
        if _on_the_road(mentions):
            for a in actors:  # ("Dog on the carriageway. Ego at 60 km/h."): it is there, in the ego's way
                a.stationary = True
            return
        kinds = ", ".join(dict.fromkeys("road user" if a.kind == UNKNOWN_KIND else a.kind for a in actors))
        raise NotUnderstood(unused[:12], text, missing="behaviour", of=kinds)


#: What says something of the ego where it is not named: its speed, its verbs, a turn ("Driving at 50
#: km/h in fog", "turning left at the lights").
_EGO_SAID = frozenset(("ego_verb", "speed", "speed_word", "behaviour", "turn", "to_stop"))


#: Verbs that only carry another ("was", "had", "did"): no deed of their own.
_CARRIERS = frozenset(
    "am is are was were be been being have has had having do does did will would can could shall should may might"
    " must".split()
)


def _on_the_road(mentions) -> bool:
    """Whether a road user is said to be on or in the road with no verb ("dog on the carriageway",
    "a sofa in the road"): the road named right after it, after "on" or "in"."""
    return any(
        m.slot == "actor" and m.value != "ego" and n.slot == "map" and n.prev in ("on", "in")
        for m, n in zip(mentions, mentions[1:])
    )


def _did_something(mentions, tokens: list[str], unused: set[str]) -> bool:
    """Whether a verb the reader has no behaviour for follows the first road user named, as its
    subject's deed ("a van nicked my mirror", "a kid legged it across"): an inflected verb, or a word in
    -ed right after the road user. A participle before it ("a tired cyclist") describes, it does not act."""
    first = next((m for m in mentions if m.slot == "actor" and m.value != "ego"), None)
    if first is None:
        return False
    after = [(k, w) for k, w in enumerate(tokens) if k >= first.end and w in unused]
    if any(_inflected_verb(w) or (k == first.end and w.endswith("ed") and len(w) > 4) for k, w in after):
        return True
    return _done_to(first, tokens, unused)


#: Articles that open an object noun phrase, and particles that may stand between a verb and it.
_OBJECT_ARTICLES = frozenset({"a", "an", "the", "this", "that", "some"})
_PARTICLES = frozenset({"down", "over", "out", "into", "up", "off"})


def _done_to(first, tokens: list[str], unused: set[str]) -> bool:
    """Whether a verb the reader has no behaviour for takes the first road user named as its object
    ("almost flattened an e-scooter rider", "nudged a cyclist at the lights", "mowed down a walker"):
    something was done to it, so it was there, in the ego's way, and a scenario can be made of it. The
    verb must stand before the road user's article, a particle between at most: a participle after the
    article ("a flattened cyclist") describes it. A terse note leaves the article out where the verb's
    subject stands right before it ("ego clipped e-scooter at roundabout")."""
    k = first.start - 1
    if k < 1:
        return False
    if tokens[k] not in _OBJECT_ARTICLES:
        subject = tokens[k - 1] == "ego" or _actor_word(tokens[k - 1])
        return subject and tokens[k] in unused and _inflected_verb(tokens[k])
    k -= 1
    while k >= 0 and tokens[k] in _PARTICLES:
        k -= 1
    return k >= 0 and tokens[k] in unused and _inflected_verb(tokens[k])


def _inflected_verb(word: str) -> bool:
    """Whether ``word`` is a verb in an inflected form ("nicked", "tapping", "t-boned", "side-swiped":
    the last part of a compound), not a carrier: a word that is a verb only in its plain form ("wet",
    "mirror") is more likely a noun or an adjective."""
    last = word.rpartition("-")[2]
    verb = _lemmas(last).get("VERB", ())
    return bool(verb) and word not in _CARRIERS and (last not in verb or last.endswith("ing"))


#: Adversaries a scenario holds (the layers schema's limit).
MAX_ACTORS = 8
#: The fastest a road user of a kind goes on its own (m/s): a faster speed said beside it is the ego's.
FASTEST_MPS = {"pedestrian": 4.5, "bicycle": 14.0, "e-scooter": 12.0}
#: Kerb words off the road: a rider there entering the road crosses into the ego's path from that side.
PAVEMENT_WORDS = ("pavement", "sidewalk", "footpath", "footway", "kerb", "curb")
#: Behaviours that happen only at a junction: a description with one of them is set at a crossroad
#: (unless it says a roundabout).
JUNCTION_BEHAVIOURS = ("run_red_light", "turn_across", "turn_into", "forced_turn")
#: The kind of a road user named by a word the reader does not know, until what it does tells.
UNKNOWN_KIND = "unknown"
VULNERABLE = ("pedestrian", "bicycle", "e-scooter")
VEHICLES = ("car", "van", "truck")
RIDERS = ("bicycle", "e-scooter")
#: Words before a verb that make it passive ("is tailgated", "gets cut off").
PASSIVE_AUXILIARIES = {"is", "are", "was", "were", "be", "been", "being", "get", "gets", "got", "getting"}


#: Places where people on foot cross the road, by the words that name them ("the zebra", "a crosswalk").
_WALKERS_CROSSINGS = (
    "pedestrian crossing", "zebra crossing", "zebra", "pelican crossing", "puffin crossing", "toucan crossing",
    "crosswalk", "crossing", "school crossing",
)  # fmt: skip


def _waits_at_a_crossing(a: _Actor, spec: ActorSpec, said: str) -> bool:
    """Whether walker ``a``, of whom nothing is said but that someone stops, waits or gives way for them
    (the caller has seen no verb of theirs: "stopped at the zebra for a mum with a pushchair", "waited at
    the crosswalk for an old man", "gave way to a pedestrian at the crossing"), is someone crossing at
    the walkers' crossing the text names: that is what they are waited for. Not one placed behind or
    beside the ego, passed, or said to stand still."""
    if a.kind != "pedestrian" or a.stationary or a.passed or a.wrong_way:
        return False
    if [b[0] for b in spec.behaviours] not in (["keep_going"], ["along_road"]) or spec.speed_mps == 0.0:
        return False
    if spec.relation not in (None, "ahead", "roadside_left", "roadside_right") or a.said - {"ahead"}:
        return False
    waited_for = re.search(rf"\b(?:for|way to) (?:\S+ ){{0,3}}{re.escape(a.word)}\b", said) if a.word else None
    return waited_for is not None and any(f" {w} " in f" {said} " for w in _WALKERS_CROSSINGS)


#: Words after a verb of passing that say it has no object ("the van passed, then ...", "passed safely").
_NO_OBJECT = frozenset(("", ".", ",", ";", ":", "!", "?", "and", "then", "but", "so", "when", "while", "as", "after",
                        "before", "without", "safely", "slowly", "at", "with", "in", "on", "by"))  # fmt: skip
#: The writer's words for the ego as the object of a verb of passing: a road user coming the other way
#: that "passed us" meets the ego in its own lane, as one that "went by" does (not the ego's lane: no
#: overtake of anyone).
_THE_EGO_AS_OBJECT = frozenset(("me", "us"))
#: Verbs (lemmas) that with no object say a road user going by ("the van passed", "a lorry went past").
_GOING_BY = frozenset(("pass", "go", "come", "drive", "ride"))


def _going_by(words: str) -> bool:
    """Whether a verb of passing said as ``words`` has nothing after it but "by" or "past" ("the van
    has passed", "a lorry passes by", "the bus went past"): said of a road user coming the other way
    that passes no one named, it goes by in its own lane, no overtake into the ego's lane ("pulled out
    to overtake" stays one)."""
    said = words.split()
    verbs = set(_lemmas(said[0]).get("VERB", ())) if said else set()
    return ("pass" in verbs and said[1:] == []) or bool(verbs & _GOING_BY and said[1:] in (["by"], ["past"]))


def _specialise(
    a: _Actor,
    spec: ActorSpec,
    junction: bool,
    left_hand: bool = False,
    across: str = "left",
    passes_another: bool = True,
    signal_said: bool = False,
) -> None:
    """The behaviours that what was said around the verbs makes specific: a left turn by someone
    coming the other way is a turn across the ego's path; pulling out of a side road is turning into
    the ego's road; a vehicle driving at the ego in its lane is a wrong-way driver; a walker or rider
    who just goes on, goes along the road."""
    in_its_path = a.wrong_way or bool({"ahead", "in_ego_lane"} & a.said)  # ("approaching head-on in my lane")
    if spec.relation == "oncoming" and a.went_by and not passes_another and not in_its_path:
        by = [("keep_lane", *b[1:]) if b[0] == "overtake" else b for b in spec.behaviours]
        spec.behaviours = [b for k, b in enumerate(by) if not (k and b[0] == by[k - 1][0] == "keep_lane")]
    names = [b[0] for b in spec.behaviours]
    first = names[0] if names else None
    vehicle = a.kind in VEHICLES
    crit = next((b[2] for b in spec.behaviours if b[2]), a.crit)
    link = spec.behaviours[0][3] if spec.behaviours else "sequence"
    # across the road where traffic keeps right; a writer who keeps left puts a rider on the far (right)
    # kerb that swerves in beside the ego going its way (a vehicle there is oncoming: _resolve_relation)
    far_kerb = a.kerb_side == "left" and not left_hand and not a.lane_side
    towards = "oncoming" in a.said or spec.relation in ("oncoming", "junction_opposite") or far_kerb
    if (
        first == "forced_turn"
        and spec.behaviours[0][1].get("turn") == across  # (left; right where traffic keeps left)
        and (spec.relation in ("oncoming", "junction_opposite") or "oncoming" in a.said)
    ):
        spec.relation = "junction_opposite"
        same = ("cut_in", "cross_in_front", "run_red_light", "keep_going")  # ("... and crossed into our path")
        spec.behaviours = [("turn_across", {}, crit, link)] + [b for b in spec.behaviours[1:] if b[0] not in same]
        return
    # (a stop said free of it, told after it, is the ego's reaction to it: crossing_reaction drops it)
    unreacted = [b[0] for b in spec.behaviours if not b[1].get(crossing_reaction.MARK)]
    unreacted = unreacted or names[:1] and ["keep_going"]  # (nothing of its own but coming on)
    if a.kind != "pedestrian" and motion.comes_head_on(unreacted, a.wrong_way, a.said, passes_another, a.returns):
        # (a vehicle seen coming from the other way drifts over into the ego's lane; a rider rides in it)
        in_lane = a.kind in RIDERS or sides.starts_in_ego_lane(a.said)
        spec.behaviours = [("wrong_way", {"returns": 1.0} if a.returns else {}, crit, link)]
        spec.relation, spec.facing = ("ahead", "against") if in_lane else ("oncoming", None)
        if spec.speed_mps == 0.0:  # (it comes at the ego: a standstill read on it is someone else's)
            spec.speed_mps = None  # ("the van came at him on his side. He stopped; the van pulled back in")
        return
    if (
        junction
        and a.kind != "pedestrian"
        and a.goes_on
        and not a.priority  # (already on the roundabout: going on without slowing is its right)
        and first in ("cut_in", "keep_going")
        and spec.relation in ("junction_left", "junction_right", "junction_opposite")
        and not junctions.pulls_out_to_join(a.pulled_out, a.goes_over, names, spec.relation, signal_said)
    ):  # does not give way or stop at the junction: straight through it, timed to meet the ego's path
        spec.behaviours = [("run_red_light", {}, crit or "dangerous", link)] + spec.behaviours[1:]
        return
    if first == "give_way" and spec.relation in ("junction_left", "junction_right") and "follow_vehicle" in names:
        # lets the ego pass, then follows it: it turns into the ego's road behind it
        name, cfg, c, lk = spec.behaviours[0]
        spec.behaviours[0] = (name, {**cfg, "turn": "right" if spec.relation == "junction_right" else "left"}, c, lk)
        return
    if spec.relation in ("junction_left", "junction_right") and (vehicle or a.kind in RIDERS):
        if any(n in ("cut_in", "forced_turn") for n in names):  # (a car, or a bike out of a driveway)
            rest = [b for b in spec.behaviours if b[0] not in ("cut_in", "forced_turn", "cross_in_front", "keep_going")]
            spec.behaviours = [("turn_into", {}, crit, link)] + rest
            spec.speed_mps = None if not a.speed_mps else a.speed_mps
        return
    if (
        (
            vehicle
            # (an oncoming rider swerving in; one riding the wrong way, not on a path or lane of its own,
            # swerving or in a lane of the road said: "going the wrong way in the fast lane")
            or (
                a.kind in RIDERS
                and (towards or a.wrong_way and not (a.pavement or a.own_lane))
                and (first in ("cut_in", "change_lane") or (a.wrong_way and a.lane_side is not None))
            )
        )
        and not junction
        and (
            a.wrong_way
            or ("ahead" in a.said and towards and "keep_lane" not in names)  # (not "keeps to its lane")
            or (towards and first in ("cut_in", "change_lane"))
            or (spec.relation == "oncoming" and first == "overtake")  # (overtaking into the ego's lane)
        )
    ):
        returns = a.returns or first == "overtake" or any(n in ("change_lane", "cut_in") for n in names[1:])
        in_lane = (a.wrong_way or "ahead" in a.said) and first != "overtake"  # (an overtaker starts in its lane)
        in_lane = in_lane and sides.starts_in_ego_lane(a.said)
        cfg = {"returns": 1.0} if returns else {}
        rest = [b for b in spec.behaviours if b[0] not in ("cut_in", "change_lane", "keep_going", "overtake")]
        spec.behaviours = [("wrong_way", cfg, crit, link)] + rest
        spec.relation = "ahead" if in_lane else "oncoming"
        spec.facing = "against" if in_lane else None
        return
    if (
        a.kind in VULNERABLE
        and names == ["keep_going"]
        and a.came_from
        and not a.stationary
        and spec.relation in (None, "ahead", "left", "right", "roadside_right", "roadside_left")
    ):  # "walks from the far side": from a kerb across the road, as a walker or rider going on from one does
        side = a.kerb_side or a.side or (spec.relation or "").removeprefix("roadside_")
        spec.relation = f"roadside_{side if side in ('left', 'right') else 'right'}"
        spec.behaviours = [("cross_in_front", {}, crit, link)]
        return
    if (
        a.kind in VULNERABLE
        and spec.behaviours
        and set(names) <= {"keep_going", "keep_lane", *(("along_road",) if a.passed else ())}
        and spec.speed_mps != 0.0
        and not sides.comes_onto_the_road(a.out_of_place, spec.relation)
        and spec.relation in (None, "ahead", "oncoming", "roadside_right", "roadside_left", "behind")
        and not (junction and spec.relation is None and not (a.kind in RIDERS and a.wrong_way))
    ):
        spec.behaviours = [("along_road", {}, crit, link)]
        spec.facing = "against" if towards or a.wrong_way else None  # ("rides against the traffic")
        if spec.relation == "behind":
            spec.facing = None
        side = a.kerb_side or a.lane_side or a.side
        if a.kerb or (spec.relation or "").startswith("roadside") or side in ("left", "right"):
            # at the edge of the lane on the side said ("along the kerb on our left", "on the right side")
            # (a kerb with no side: the right edge, which the layers' right-hand road keeps clear of the
            # lane beside it; relation and start stay the writer's near kerb's)
            left = side == "left" or (side is None and spec.relation == "roadside_left" and not a.kerb)
            spec.lateral_m = kerb_ride.EDGE_OFFSET_M if left else -kerb_ride.EDGE_OFFSET_M
            spec.beside = a.beside or a.own_lane  # ("on my left", "in the cycle lane": not in the ego's lane)
        spec.relation = "ahead" if spec.relation != "behind" else "behind"
        spec.behaviours = head_on(spec, a.kind in RIDERS and a.wrong_way)


def _gets_up(m) -> bool:
    """Whether return ``m`` is getting back up or on ("fell off and got back up", "got back on his
    bike"): standing up or remounting, not going back to its side of the road."""
    return m.words.split()[0] in ("get", "got", "gets", "getting") and m.next_ in ("up", "on")


#: Prepositions that say an arm is where a road user comes out of ("from the exit", "off the slip").
_OUT_OF_AN_ARM = frozenset(("from", "out", "off"))


def _from(m) -> bool:
    """Whether place mention ``m`` says where its road user comes from ("from the far side", "came off
    the sidewalk")."""
    return m.prev in ("from", "off") or m.words.startswith(("from ", "off "))


def _parked(actors: list[_Actor], specs: list[ActorSpec]) -> None:
    """Vehicles parked at the side of the road (standing, said to be on a side or at the kerb, not
    in a lane of the ego's) stand beyond the kerb, where they hide someone who crosses from there;
    a crossing whose side is only said of the parked vehicles ("from between two parked vans on the
    left") starts from that side. Parked vehicles of no side said do not outvote those of a side said
    ("between parked cars ... from behind a parked van on the left": from the left)."""
    parked_sides, sides_said = [], set()
    for a, spec in zip(actors, specs):
        if a.kind not in VEHICLES or spec.speed_mps != 0.0:
            continue
        if any(b[0] not in ("keep_going", "stop") for b in spec.behaviours):
            continue  # it pulls out, turns ...: it stands in its lane first
        side = a.kerb_side or a.side or a.lane_side or (spec.relation if spec.relation in ("left", "right") else None)
        if spec.relation in ("left", "right", None) and (side or a.kerb or a.parked) and (a.parked or not a.lane_side):
            spec.relation = f"roadside_{side or 'right'}"
            parked_sides.append(side or "right")
            sides_said |= {side} if side in ("left", "right") else set()
    if len(sides_said) == 1:
        parked_sides = [*sides_said]
    if len(set(parked_sides)) != 1:
        return
    for a, spec in zip(actors, specs):
        own_side = a.kerb_side or a.side or a.lane_side
        crossing = spec.behaviours and spec.behaviours[0][0] in ("cross_in_front", "give_way")
        if a.kind in VULNERABLE and crossing and own_side is None and (spec.relation or "").startswith("roadside"):
            spec.relation = f"roadside_{parked_sides[0]}"


def _cut_outs(
    specs: list[ActorSpec],
    double_parked: set[int] = frozenset(),
    followed: set[int] = frozenset(),
    elsewhere: set[int] = frozenset(),
) -> None:
    """A vehicle ahead that swerves out of the lane while something stands in it (or "swerves round"
    it) reveals that to the ego: a cut-out, with the standing actor as its obstacle. Without
    anything standing, a swerve out is a lane change. A road user in the lane that stops (brakes to
    a standstill) stands there as well (:func:`motion.stops_in_the_lane`), and so does a vehicle
    ``double_parked`` (by index): parked beside the parked cars, it stands in the traffic lane, whatever
    side of the road it is on. Of two standing, the one that swerves (:func:`_swerve_at`) moves, and a vehicle
    the ego follows (``followed``, by index) swerves out of the ego's lane, ahead, whatever side the
    lane it moves into gave it. What stands in a lane said by its side is revealed only if it stands
    there now, on the ego's road: not one ``elsewhere`` (by index; :mod:`elsewhere`: on another
    carriageway or a slip road, at another time, or since taken away)."""
    standing = [
        k
        for k, s in enumerate(specs)
        if motion.stops_in_the_lane(s, specs) or (k in double_parked and s.speed_mps == 0.0 and len(specs) > 1)
    ]
    still = [k for k in standing if _swerve_at(specs[k]) is None]  # (of two standing, the one that swerves moves)
    standing = still or standing
    beside = [  # standing in a lane said by its side ("stood there in lane 1"): the ego's, if the lead left it
        k
        for k, s in enumerate(specs)
        if s.relation in ("left", "right")
        and k not in elsewhere
        and motion.stops_in_the_lane(replace(s, relation=None), specs)
        and _swerve_at(s) is None
    ]
    for k, s in enumerate(specs):
        if not (standing or beside) or not s.behaviours or s.kind not in VEHICLES or k in standing:
            continue
        at = _swerve_at(s)
        if at is None:
            continue
        name, cfg, crit, link = s.behaviours[at]
        passes = name in ("cut_in", "overtake") and s.relation in (None, "ahead")  # ("pulls out to pass a parked van")
        swerves = name in ("cut_out", "change_lane") or passes or (name == "cut_in" and k in followed)
        in_egos_lane = k in followed or s.relation == "ahead"  # (followed, or said ahead of the ego)
        obstacle = standing[0] if standing else _left_behind(cfg, [j for j in beside if j != k], specs, in_egos_lane)
        if swerves and obstacle is not None and (s.relation in (None, "ahead", "behind") or k in followed):
            direction = {key: v for key, v in cfg.items() if key == "direction"}
            s.behaviours = [("cut_out", direction, crit, link)] + _after_the_swerve(s.behaviours[at + 1 :])
            s.relation, s.obstacle = "ahead", obstacle
            s.speed_mps = None if s.speed_mps == 0.0 else s.speed_mps  # (the standstill said is the obstacle's)
            specs[obstacle].relation = "ahead"
            specs[obstacle].behaviours = motion.standing_still(specs[obstacle])
    for s in specs:  # a swerve with nothing to swerve round is a lane change
        if s.obstacle is None:
            s.behaviours = [("change_lane", *b[1:]) if b[0] == "cut_out" else b for b in s.behaviours]


#: What a lead does before it swerves that is only going along in front of the ego ("the ego follows
#: a lead vehicle at 60 km/h ...; the lead vehicle changes lanes").
_GOING_ALONG = frozenset(("follow_vehicle", "keep_going", "keep_lane"))
#: A lead's moves out of the ego's lane: a lane change, a swerve round, a pull-out (one it passes with,
#: or one out of the lane the ego follows it in).
_MOVES_OUT = frozenset(("change_lane", "cut_out", "cut_in", "overtake"))


def _swerve_at(spec: ActorSpec) -> int | None:
    """The index of the behaviour with which ``spec`` moves out of the lane: its first act, or its
    first after acts of only going along (a lead followed, then swerving, still swerves); None when it
    does not move out. A road user that moves out is moving, so it is never what stands in the lane."""
    for i, b in enumerate(spec.behaviours):
        if b[0] in _MOVES_OUT:
            return i
        if b[0] not in _GOING_ALONG:
            return None
    return None


def _left_behind(cfg: dict, beside: list[int], specs: list[ActorSpec], in_egos_lane: bool) -> int | None:
    """Of the road users ``beside`` (indices) that stand in a lane said by its side, the one in the lane
    a lead in the ego's lane swerves out of (``cfg``: its move's config). A lead is in the ego's lane
    when the ego follows it, or when it is said ahead of the ego with no lane of its own ("the car
    ahead swerved into the right lane, revealing a mattress lying in the left lane"): the reading
    places such a lead in the ego's lane, so the lane it leaves is the ego's. One on the side the lead
    moves to stands in the lane it moves into, not in its way, so the side it moves to must be read; a
    lead said in a lane beside the ego's may leave a lane that is not the ego's."""
    to = {1.0: "left", -1.0: "right"}.get(float(cfg.get("direction", 0.0)))
    if not in_egos_lane or to is None:
        return None  # (moved "into lane 2": which side it leaves is not read)
    return next((j for j in beside if specs[j].relation != to), None)


def _after_the_swerve(rest: list) -> list:
    """What a lead does after its cut-out, less a stop: once it is out of the lane, the stop said for
    the revealed obstacle ("had about 20 metres to stop", "braked hard") is the ego's, which faces it."""
    return [b for b in rest if b[0] not in ("stop", "sudden_stop")]


def _one_of(m, nxt) -> int | None:
    """The start of the road user a member word with no group before it picks out ("one of the buses
    pulled out", "one of your drivers braked", "one of them scooters cut in"): that road user is the
    clause's subject, not an object of "of"; None when no road user follows "of"."""
    if m.next_ != "of" or nxt is None or nxt.slot != "actor" or nxt.value == "ego" or nxt.prev != "of":
        return None
    return nxt.start if nxt.start - m.end <= 3 else None


def _verb_criticality(words: str) -> str | None:
    toks = words.split()
    for key, cls in VERB_CRITICALITY.items():
        if len(key) <= len(toks) and all(k in forms(t) for k, t in zip(key, toks)):
            return cls
    return None


#: Behaviours only a vehicle shows: a "guy" who tailgates drives a car.
VEHICLE_BEHAVIOURS = {
    "follow_vehicle",
    "overtake",
    "cut_in",
    "run_red_light",
    "forced_turn",
    "change_lane",
    "turn_into",
}


#: The parameter each behaviour takes "at N m/s²" as (its range: the behaviour's own, vei behaviours -v).
_RATES = {"sudden_stop": "decel_mps2", "stop": "decel_mps2", "change_speed": "rate_mps2"}


def _with_rate(name: str, cfg: dict, rate: float) -> tuple[str, dict]:
    """The behaviour with the stated acceleration as its rate, within its range: a stop said harder
    than a comfortable one (the stop's most, 4 m/s²) is a hard stop; road friction bounds every one."""
    if name == "stop" and abs(rate) > BEHAVIOURS["stop"].PARAMETERS[_RATES["stop"]].high:
        name = "sudden_stop"
    if name not in _RATES:
        return name, cfg
    key = _RATES[name]
    p = BEHAVIOURS[name].PARAMETERS[key]
    return name, {**cfg, key: min(max(abs(rate), p.low), p.high)}


def _tidy(a: _Actor) -> list:
    """The actor's behaviours as the layers take them: redundant ones merged."""
    out = []
    behaviours = []
    for k, (name, cfg, crit, lk) in enumerate(a.behaviours):
        plain = cfg.pop("_plain_brake", None)
        after = a.behaviours[k + 1][0] if k + 1 < len(a.behaviours) else None
        if plain and after in ("stop", "sudden_stop"):
            continue  # "brakes and stops normally": the stop says how
        if name == "stop" and crit == "dangerous" and not a.stationary:
            name = "sudden_stop"  # "decelerates abruptly to a standstill", "stops suddenly": a hard stop
        behaviours.append((name, cfg, crit, lk))
    for b in behaviours:
        apart = out and pull_in_apart.told_apart(out[-1][1], b[1])  # (a sentence of its own, at the ego)
        if out and b[0] == "cut_in" and out[-1][0] == "overtake" and not apart:
            name, cfg, crit, lk = out[-1]  # an overtake ends by cutting back in: "cuts in sharply" is how
            out[-1] = (name, cfg, crit or b[2], lk)
            continue
        out.append(b)
    out = [(name, pull_in_apart.unmarked(cfg), crit, lk) for name, cfg, crit, lk in out]
    if a.kind != "pedestrian" and any(b[0] == "run_red_light" for b in out):
        out = [b for b in out if b[0] != "cross_in_front"]  # crossing against red is the red-light run
    if a.straight_on:  # ("jumped the lights and carried straight on": the run's way, the text's, not the builder's)
        out = [(n, {**c, "turn": "straight"}, k, lk) if n == "run_red_light" else (n, c, k, lk) for n, c, k, lk in out]
    if any(b[0] == "give_way" for b in out):  # "stops at the line and waits for us": giving way stops
        out = [
            b for k, b in enumerate(out) if not (b[0] == "stop" and k + 1 < len(out) and out[k + 1][0] == "give_way")
        ]
    for k in range(1, len(out)):  # having let the ego pass, it crosses at once (behind it)
        if out[k][0] == "cross_in_front" and out[k - 1][0] == "give_way":
            name, cfg, crit, lk = out[k]
            out[k] = (name, {**cfg, "immediately": 1.0}, crit, lk)
    if len(out) > 1:  # "rides ahead and then stops": going on first adds nothing
        out = [b for b in out if b[0] != "keep_going"] or out[:1]
    return out


#: Parts and measures of a vehicle: "vehicle width", "car door" name no road user.
_PARTS = {"width", "length", "overlap", "centreline", "centerline", "door", "doors", "bumper", "mirror", "bonnet",
          "hood", "boot", "trunk", "wheel", "wheels", "wing", "headlight", "headlamp", "panel", "corner",
          "windscreen", "windshield", "tailgate", "fender", "quarter"}  # fmt: skip
#: Behaviours that move a road user sideways: a bare "left"/"right" right after them is where it moves to.
_SIDEWAYS = ("cut_in", "change_lane", "cut_out", "cross_in_front")
#: Words that make a road user the one the ego follows ("the lead car", "a preceding truck").
_LEADING = frozenset({"lead", "leading", "preceding"})
#: Verbs of moving across lanes (lemmas) and the prepositions of where to: "changes to the left lane".
_LANE_VERBS = frozenset({"change", "move", "switch", "pull", "merge", "swerve", "veer", "drift", "steer", "cut", "go"})
_INTO = frozenset({"to", "into", "onto", "in"})


def _lane_to_side(tokens: list[str], i: int) -> int | None:
    """Where the side is said when ``tokens[i:]`` reads "<verb> [over] to/into the left/right lane" (a
    lane change towards that side), else None. Not "into the left lane of the ego": that names a lane
    by the ego's."""
    if not (forms(tokens[i]) & _LANE_VERBS):
        return None
    j = i + 1 + (tokens[i + 1 : i + 2] == ["over"])
    if tokens[j : j + 1] and tokens[j] in _INTO and tokens[j + 1 : j + 2] == ["the"]:
        side = j + 2
        if tokens[side : side + 2] in (["left", "lane"], ["right", "lane"]) and tokens[side + 2 : side + 3] != ["of"]:
            return side
    return None


#: Words after which "right" means "just" ("cuts in right in front of us"), not a side: those of the
#: noise phrases ("right ahead", "right away") and a few more; or it names a lane or side ("right lane").
_RIGHT_BEFORE = {p.split()[1] for p in L.NOISE if p.startswith("right ")} | {
    "before", "after", "at", "by", "across", "lane", "lanes", "side", "hand"}  # fmt: skip
#: Verbs that say what something is: an adjective after them describes it ("the truck is slow").
_COPULAS = {"is", "are", "was", "were", "be", "being", "seems", "looks"}
_INTENSIFIERS = {"very", "quite", "rather", "really", "extremely", "so", "too", "pretty"}


def _after_copula(tokens: list[str], i: int) -> bool:
    """Whether the word at ``i`` follows a copula, past intensifiers ("is very slow")."""
    j = i - 1
    while j >= 0 and tokens[j] in _INTENSIFIERS:
        j -= 1
    return j >= 0 and tokens[j] in _COPULAS


#: A relation said of the ego towards another road user ("the ego is behind a truck"), as that one's place.
_SEEN_FROM_OBJECT = {"behind": "ahead", "ahead": "behind"}


def _verb_after_and(prev, m) -> bool:
    """Whether relation ``m`` opens with a verb of coming at the ego right after "and" ("... and came
    towards us", "... and came head-on at us"): a second verb of the clause's subject, whose object
    (named last: "was overtaking a tractor and came ...") is not the one that comes."""
    if m.slot != "relation" or m.value != "oncoming" or prev is None or prev.slot != "conj":
        return False
    return prev.words == "and" and _inflected_verb(m.words.split()[0])


def _overtakers_return(prev, m, subject: _Actor) -> bool:
    """Whether return ``m`` is said right after "and" in a clause whose subject overtakes ("tried to
    squeeze past, met an oncoming van and had to cut back in"): going back to its lane is the
    overtaker's second verb, not what the road user it meets (named last) does."""
    if m.slot != "returns" or prev is None or prev.slot != "conj" or prev.words != "and":
        return False
    return any(b[0] == "overtake" for b in subject.behaviours)


def _overtaken_coming(who, subject: _Actor, m) -> bool:
    """Whether relation ``m``, coming at the ego, is said right after what the clause's subject overtakes
    ("a truck was overtaking another truck, head-on towards us"): the overtaker is the one that comes
    on the ego's side (what it overtakes comes the same way, and is read so from it)."""
    if m.slot != "relation" or m.value != "oncoming" or not isinstance(who, _Actor) or who.object_of is not subject:
        return False
    return any(b[0] == "overtake" for b in subject.behaviours)


#: Words asking how near: "how far", "how close".
_HOW_NEAR = frozenset({"far", "close", "near", "long"})


def _narrators_opening(tokens: list[str], mentions, k: int) -> bool:
    """Whether relation ``mentions[k]`` is said in a sentence that opens with the narrator's
    participle and names no one before it ("Crawling behind a tractor ...", "Stuck behind a bus"):
    said of the ego, so the road user named after it is the other way round ("behind a tractor":
    the tractor is ahead)."""
    if mentions[k].slot != "relation" or any(x.slot in ("actor", "member", "count") for x in mentions[:k]):
        return False
    return ego_speed.narrators_opening(tokens, mentions[k].start)


#: Forms of "be" between a subject and where it is ("my wife was following a lorry").
_BE_FORMS = frozenset({"is", "are", "was", "were"})


def _of_a_subject_not_placed(tokens: list[str], mentions, k: int) -> bool:
    """Whether relation ``mentions[k]`` is said, after a form of "be", of a subject the reader places as no
    road user, with no one named before it in its clause ("My wife was following a lorry", "Dad was
    behind a bus"): the person the story follows, at the wheel, as "I was behind the bus" is the
    narrator; the road user named after it is the other way round from them (the lorry is ahead)."""
    m = mentions[k]
    if m.slot != "relation" or any(x.slot in ("actor", "pronoun", "member", "count") for x in mentions[:k]):
        return False
    subject = tokens[m.start - 2] if m.start >= 2 else ""
    return tokens[m.start - 1] in _BE_FORMS and subject.isalpha() and subject not in FUNCTION_WORDS


def _asked_how_far(tokens: list[str], m) -> bool:
    """Whether relation ``m`` is asked of someone named after it ("How far behind the bus were you?"):
    "how far" or "how close" right before it. The one asked, after the verb, is where the relation
    says, and the road user named as its object is the other way round from it, as in "I was behind
    the bus"."""
    k = m.start
    return k >= 2 and tokens[k - 1] in _HOW_NEAR and tokens[k - 2] == "how"


def _stop_before(prev) -> bool:
    """Whether mention ``prev`` is a stop ("stopped", "pulled up", "braked to a stop"): a distance right
    after the ego's stop says where it stopped, short of someone, not where that someone was."""
    if prev is None:
        return False
    return prev.slot in ("stationary", "to_stop") or (
        prev.slot == "behaviour" and prev.value[0] in ("stop", "sudden_stop")
    )


def _gap_to(mentions, k: int) -> str | None:
    """What distance ``mentions[k]``, said of the ego, measures to when a preposition of place follows it
    ("15 m behind", "10 m ahead of", "20 m in front of"): "road user" where a road user is its object,
    named right after it; "place" where a place of the road is ("behind the stop line"); else None.
    Why: "<ego> N m behind <road user>" states the gap from the ego's side, before the road user is
    named, so the one named last before it is not the one it is said of."""
    if k + 1 >= len(mentions):
        return None
    rel = mentions[k + 1]
    if rel.slot != "relation" or rel.value not in ("behind", "ahead") or rel.start != mentions[k].end:
        return None
    after = mentions[k + 2] if k + 2 < len(mentions) else None
    end = rel.end + (1 if rel.next_ == "of" else 0)
    if after is None or after.start > end + 3:  # (its object: an article and up to two words before the noun)
        return None
    if after.slot == "actor" and after.value != "ego":
        return "road user"
    return "place" if after.slot == "map" else None


def _object_follows(mentions, k: int) -> bool:
    """Whether relation ``mentions[k]`` is a preposition (or a verb: "follows") whose object is a road
    user named right after it (past a determiner and speed adjectives: "behind a slower van"), not the ego."""
    m, end = mentions[k], mentions[k].end
    if m.slot not in ("relation", "behaviour") or any(w in L.EGO_NOUNS for w in m.words.split()):
        return False
    end += 1 if m.next_ == "of" else 0  # ("ahead of a motorcycle")
    for x in mentions[k + 1 :]:
        if x.slot == "punct" and x.value == "'s" and x.start <= end + 2:
            end = x.start + 1  # ("behind my mate's car": whose it is, then the car)
            continue
        if x.start > end + 1:
            return False
        if x.slot == "actor":
            return x.value != "ego"
        if x.slot != "speed_adjective":
            return False
        end = x.end
    return False


def _ego_named(prev) -> bool:
    """Whether mention ``prev`` names the ego: as itself, or at the end of a relation ("ahead of the ego")."""
    if prev is None:
        return False
    if prev.slot == "actor":
        return prev.value == "ego"
    words = prev.words.split()
    return prev.slot == "relation" and any(" ".join(words[-k:]) in L.EGO_NOUNS for k in (1, 2, 3))


#: How the ego ends a relation phrase said of it ("in front of us", "ahead of the ego").
_OF_THE_EGO = ("of me", "of us", "of the ego", "of ego")


def _in_front_of_the_ego(m, nxt, behaviours: list, mentions: list, tokens: list[str]) -> bool:
    """Whether relation mention ``m`` puts its road user in front of the ego itself ("in front of
    me", "ahead of us", "ahead" then the ego named right after "of", or the ego told of as "her" or
    "him": "the lorry in front of her in lane 1") said together with its lane, next to it either side
    ("in the left lane right in front of us", "ahead of me in lane 1"), and not where a cut-in or
    overtake ends (:func:`sides.where_it_ends`). Why: one place said twice, the ego is in that lane
    too, behind it, as when the ego follows it (:func:`sides.lane_of_the_followed`); a lane said apart
    from it ("the car in the lane to my right suddenly cuts across in front of me") is where it was
    before it moved."""
    if m.slot != "relation" or m.value != "ahead" or sides.where_it_ends(m.value, behaviours):
        return False
    right_after = nxt is not None and m.next_ == "of" and nxt.start == m.end + 1
    if m.words.endswith(_OF_THE_EGO):
        ego_end = m.end
    elif right_after and nxt.slot == "actor" and nxt.value == "ego":
        ego_end = nxt.end
    elif right_after and nxt.slot == "pronoun" and sides.told_of_the_ego(tokens, nxt.start):
        ego_end = nxt.end  # ("in front of her": the ego a report tells of in the third person)
    else:
        return False
    lanes = (x for x in mentions if x.slot == "lane_side")
    return any(x.end <= m.start <= x.end + 1 or ego_end <= x.start <= ego_end + 2 for x in lanes)  # ("me in the")


def _its_own_object(m, who, clause_subject, named, tokens: list[str], first_person: bool) -> bool:
    """Whether speed ``m``, which the reading would give to ``who``, the subject of its clause and the
    road user named last, is said after a verb and an object pronoun, which can then only be ``who`` ("a
    scooter pulled out in front of me, hit him at 20 mph", "bus braked in front of me, rear-ended it at 15
    mph"): no road user is the object of its own verb ("himself" would say so), so the verb's left-out
    subject is the narrator, in a story told from the ego's side, and the speed theirs. Not where another
    road user was named after ``who`` (``named``: who the clause has named, with their roles; the ego aside): the
    pronoun may be that one ("a van swerved round a walker and hit him at 30": the van hit)."""
    return (
        m.slot == "speed"
        and isinstance(who, _Actor)
        and who is clause_subject
        and next((x for x, _ in reversed(named) if isinstance(x, _Actor)), who) is who
        and first_person
        and ego_speed.after_a_verbs_object(tokens, m.start)
    )


def _next_to_ego(prev, m) -> bool:
    """Whether mention ``m`` follows the ego named after a preposition with at most "at" between ("ahead
    of the ego at 50 km/h"): a speed there reads as the ego's as well as the vehicle's before it."""
    if prev is None or prev.end + (1 if m.prev == "at" else 0) != m.start:
        return False
    return _ego_named(prev)


#: Participles that say how fast whoever is named before them goes ("the ego doing 50 km/h").
MOTION_PARTICIPLES = frozenset(
    {"doing", "travelling", "traveling", "driving", "going", "moving", "cruising", "running"}
)


def _ego_participle(prev, m, nxt) -> bool:
    """Whether behaviour ``m`` is a participle of the ego named in a relation just before it, followed by
    a speed ("15 m ahead of the ego travelling at 40 km/h"): the ego's motion, not the road user's."""
    return (
        prev is not None and prev.slot in ("relation", "actor") and _ego_named(prev) and m.start == prev.end
        and m.words in MOTION_PARTICIPLES and nxt is not None and nxt.slot == "speed"
        and nxt.start - m.end <= (1 if nxt.prev == "at" else 0)
    )  # fmt: skip


def _i_in_its_sentence(tokens: list[str], i: int) -> bool:
    """Whether the narrator says "I" in the sentence of token ``i`` ("Passed a rider, he was pootling along
    and I gave him room"): a "he" or "she" beside the narrator's "I" is someone else, even before the
    narrator has said "I"; a story about "Sam" that quotes him elsewhere tells nothing of this one."""
    return "i" in tokens[sentence_start(tokens, i) : sentence_stop(tokens, i)]


#: What places a road user, said right after it ("a cyclist 45 m ahead"): how far, and which way from the ego.
_PLACEMENTS = frozenset({"distance", "relation"})


def _placed_object_before(mentions, k: int) -> bool:
    """Whether the mention at ``k`` follows a road user and the place said of it, with no verb between ("I
    notice a cyclist 45 m ahead, moving at 20 km/h", "a bus 60 m ahead travelling at 40 km/h"): a participle
    there still describes that road user, as it does right after its name ("a cyclist moving at 20 km/h").
    A comma between is passed only after such a place: "I passed a cyclist, doing 50" may be either's."""
    j = k - 1
    if j >= 0 and mentions[j].slot == "punct" and mentions[j].words == ",":
        j -= 1
    placed = j
    while j >= 0 and mentions[j].slot in _PLACEMENTS:
        j -= 1
    return j < placed and j >= 0 and mentions[j].slot == "actor" and mentions[j].value != "ego"


#: Words that may stand between a verb or noun of passing and what it passes ("overtook a", "an overtake of the").
_BEFORE_THE_PASSED = DETERMINERS | {"of"}


def _passed_object(tokens: list[str], mentions, k: int) -> bool:
    """Whether the road user named by ``mentions[k]`` is what a verb or noun of passing right before it
    passes, past the speed adjectives of its noun phrase ("overtook a slow lorry") or the "of" of a noun
    of passing ("commenced an overtake of a slow-moving HGV"): the object, as right after the verb
    ("overtook a lorry"), which the speed adjective or the noun's "of" hides from a reading of the mention
    right before it."""
    j, start = k - 1, mentions[k].start
    while j >= 0 and mentions[j].slot == "speed_adjective" and mentions[j].end >= start - 1:
        start, j = mentions[j].start, j - 1
    if j < 0:
        return False
    between = tokens[mentions[j].end : start]
    if j == k - 1 and "of" not in between:
        return False  # (nothing hidden between: the plain object is read where it is named)
    return motion.passes(mentions[j]) and len(between) <= 3 and all(w in _BEFORE_THE_PASSED for w in between)


def _nearest(named, m):
    """The actor a position or number describes: the last one named before it, passing over an ego
    named after a preposition ("ahead of the ego"), and for a speed an actor that stands or the
    object of the subject's verb ("the ego follows a lorry at 80 km/h" is the ego's speed)."""
    for who, role in reversed(named):
        if who == "ego" and role != "subject":
            continue
        if m.slot == "speed" and isinstance(who, _Actor) and (who.stationary or role == "verb"):
            continue
        if m.slot == "speed" and role == "prep" and ("ego", "subject") in named:
            continue  # ("I was behind this bus at 20 mph": the ego's, as "the ego follows a bus at 20 mph")
        placed = m.slot == "distance" or (m.slot == "relation" and m.value in ("ahead", "behind"))
        hidden_by = isinstance(who, _Actor) and (who.parked or who.hides)
        if placed and hidden_by and role != "subject" and _subject_actor(named):
            continue  # ("runs out between parked cars, 12 m ahead": where the one running out is)
        return who
    return None


def _participle_of_object(named: list, before: list, m, tokens: list[str]) -> None:
    """Make the road user named last before the speed ``m`` (``before``: its clause's mentions before it)
    the owner of the participle phrase the speed is said in, where it is not its clause's subject
    ("I turned across a cyclist approaching at 20 km/h": the cyclist's, see :mod:`object_participle`)."""
    noun = next((x for x in reversed(before) if x.slot == "actor" and x.value != "ego"), None)
    if noun is None or not participle_phrase(tokens, noun.end, m.start):
        return
    k = next((k for k in range(len(named) - 1, -1, -1) if isinstance(named[k][0], _Actor)), None)
    if k is not None and named[k][1] != "subject":
        named[k] = (named[k][0], "participle")


def _subject_actor(named) -> bool:
    """Whether a road user other than the ego is the subject of the clause ``named`` comes from."""
    return any(isinstance(who, _Actor) and role == "subject" for who, role in named)


#: Weather words by how much they change a drive: precipitation and fog over cloud over clear.
WEATHER_SEVERITY = {"clear": 0, "cloudy": 1, "rain": 2, "fog": 2, "snow": 3, "heavy_rain": 3}


def _global(r, m) -> None:
    if m.slot == "map":  # (a roundabout has crossings: "on the crossing after the exit" leaves it one)
        junction = r.map_kind in ("crossroad", "roundabout")  # ("at the crossroads ... round the corner": its corner)
        if not (r.map_kind and m.value == "straight") and not (junction and m.value in ("crossroad", "curve")):
            r.map_kind = m.value
    elif m.slot == "weather":  # the most severe said, of equals the first ("grey, drizzly": rain)
        if r.weather is None or WEATHER_SEVERITY.get(str(m.value), 0) > WEATHER_SEVERITY.get(r.weather, 0):
            r.weather = m.value
    elif m.slot == "time" and not S.greeting(
        m.prev, m.words, m.next_
    ):  # (the first said: "at dusk ... in dark clothing")
        r.time = r.time or m.value
    elif m.slot == "density":  # (the first said: a later "stop-and-go" in an aside does not override)
        r.density = r.density or m.value
    elif m.slot == "lanes":
        r.lanes = int(m.value)
    # (an "intent" mention is read, so not an unused word, but the outcome reader decides the intent)


#: Verbs (lemmas) of keeping to a place: "to" after them says where one stays, not where one goes.
_KEEP_TO = frozenset(("keep", "stick", "hold", "stay", "cling", "hug"))


def _verb_with_to(a: _Actor) -> bool:
    """Whether the last verb read of ``a`` is one of keeping to a place ("keeping to", "sticking
    to"): the side or kerb after it is where it keeps, not where it goes."""
    words = str(a.behaviours[-1][1].get("_words") or "").split() if a.behaviours else []
    return bool(words) and bool(set(_lemmas(words[0]).get("VERB", ())) & _KEEP_TO)


def _apply(m, who, r, link, added) -> None:
    """Put mention ``m`` on ``who`` (the ego, or an actor and the actors named with it)."""
    targets = who.group if isinstance(who, _Actor) and who.group else [who]
    for a in targets:
        if a == "ego":
            if m.slot == "speed":
                r.ego_speed_mps = m.value
            elif m.slot in ("turn", "ego_verb") and m.value:
                r.ego_route = m.value
            elif m.slot == "behaviour" and m.value[0] == "keep_going" and "straight" in m.words:
                r.ego_route = "straight"
            elif m.slot == "behaviour" and m.value[0] == "forced_turn":
                r.ego_route = m.value[1].get("turn", "right")
            elif m.slot == "lane_side":  # (the lane it starts in: the first said)
                r.ego_relation = r.ego_relation or m.value
            elif m.slot == "side":
                r.ego_relation = m.value
            continue
        if m.slot == "behaviour":
            name, cfg = m.value
            if any(w in _NEGATORS for w in m.words.split()):
                a.goes_on = True  # ("fails to yield", "does not give way": one phrase, and it goes on)
                a.refuses_way = a.refuses_way or name == _DENIED["give_way"][0]  # (the lexicon's "fail to yield")
            a.goes_over = a.goes_over or junctions.goes_on_over(name, m.words, [m.next_])  # (said twice too)
            if a.behaviours and a.behaviours[-1][0] == name and name != "change_speed":
                a.goes_on = a.goes_on or bool(cfg.get("_denied"))  # ("enters and fails to yield": it goes)
                a.has_way = a.has_way or bool(cfg.get("_has_way"))  # ("going round ... we yield; it goes on")
                a.priority = a.priority or bool(cfg.get("_priority"))
                a.refuses_way = a.refuses_way or bool(cfg.get("_refused_way"))
                continue  # ("brakes ... and stops": said twice over)
            said = m.words if not _adverb(m.next_) else f"{m.words} {m.next_}"  # ("brakes moderately")
            by = m.next_ in _NO_OBJECT or m.next_ in _THE_EGO_AS_OBJECT  # ("went by", "passed us")
            a.went_by = a.went_by or (name == "overtake" and _going_by(m.words) and by)
            if name == "follow_vehicle" and m.next_ in ("it", "him", "her", "them"):
                a.said.add("behind_other")  # ("a cyclist followed it out": behind another road user)
            elif name == "follow_vehicle":
                a.said.add("follows_other")  # (whom: the road user its verb takes as object, if any)
            a.behaviours.append(
                (name, dict(cfg, _words=said, _end=m.end, _start=m.start), None, link if not added else "sequence")
            )
            added.append((a, len(a.behaviours) - 1))
        elif m.slot == "turn":
            a.behaviours.append(("forced_turn", {"turn": m.value, "_words": m.words}, None, link))
            added.append((a, len(a.behaviours) - 1))
        elif m.slot == "ego_verb" and m.value in ("left", "right"):  # "an oncoming car turns left"
            a.behaviours.append(("forced_turn", {"turn": m.value, "_words": m.words}, None, link))
            added.append((a, len(a.behaviours) - 1))
        elif m.slot == "ego_verb":  # a motion verb said of an actor: it goes on
            if not a.behaviours:
                a.behaviours.append(("keep_going", {"_words": m.words}, None, link))
                added.append((a, len(a.behaviours) - 1))
        elif m.slot == "unknown_verb":
            a.unknown.append(m.words)
        elif m.slot == "speed":
            a.speed_mps, a.speed_at = m.value, m.start
        elif m.slot == "speed_to":
            a.speed_to_mps = m.value
        elif m.slot == "accel":
            a.accel_mps2 = m.value
        elif m.slot == "to_stop" and not a.behaviours:  # "it pulled gently to a stop": it stops
            a.behaviours.append(("stop", {"_words": m.words}, None, link))
            added.append((a, len(a.behaviours) - 1))
        elif m.slot == "to_stop" and a.behaviours and a.behaviours[-1][0] == "change_speed":
            name, cfg, crit, lk = a.behaviours[-1]  # "decelerates to a standstill": a stop
            a.behaviours[-1] = ("stop", {"_words": cfg.get("_words", "")}, crit, lk)
        elif m.slot in ("speed_word", "speed_adjective"):
            a.speed_mps = -float(m.value) if a.speed_mps is None else a.speed_mps
        elif m.slot == "distance":
            a.distance_m = m.value
            a.end_gap = sides.gap_where_it_ends(a.behaviours)
            a.gaps_said.append((m.start, m.value, m.prev, a.end_gap))
        elif m.slot == "relation" and m.value in ("ahead", "behind") and m.next_ in ("it", "him", "her", "them"):
            a.said.add("near_other")  # "a car behind it swerves": behind another road user, not the ego
            if m.value == "behind":
                a.said.add("behind_other")  # (where it starts is where that one does: follower_start)
        elif m.slot == "relation" and sides.lane_it_passes_in(m.value, m.words, m.next_, a.said):
            a.said.add("passes_oncoming")  # ("a car from behind overtakes us in the oncoming lane")
        elif m.slot == "relation" and sides.waits_elsewhere(m.value, m.prev, a.lane_side):
            pass  # ("a lorry in the left lane overtook the bus waiting at the stop": the bus's place)
        elif m.slot == "relation" and sides.where_it_ends(m.value, a.behaviours):
            a.said.add("in_front")  # "cuts in 10 m ahead": where it cuts in, not where it starts
        elif m.slot == "relation":
            a.said.add(m.value)
            a.along = a.along or (m.value == "ahead" and kerb_ride.same_heading(m.words))
            if m.value == "ahead" and not a.behaviours:
                a.said.add("ahead_first")  # ("the car ahead of us swung out": where it is before it moves)
            if m.value == "ahead" and (
                motion.in_the_ego_lane(m.words) or motion.its_lane_the_egos(m.words, m.prev, a.said)
            ):
                a.said.add("in_ego_lane")  # ("in my lane", "towards the ego in its lane": the ego's own lane)
            a.followed = a.followed or (m.value == "ahead" and m.words in ("following", "tailing"))
            if m.value == "ahead" and m.words in ("following", "tailing", "behind"):
                a.said.add("ego_behind")  # ("following a van", "we were behind a van": in the ego's lane)
            if a.relation is None or m.value == "oncoming" or sides.out_of_a_place_ahead(a.relation, m.value, a.place):
                a.relation = m.value
        elif m.slot == "wrong_way":
            a.wrong_way = True
        elif m.slot == "mid_road":
            a.said.add("mid_road")  # (on the line between the halves: the ego's too, for one coming at it)
        elif m.slot == "over_line":
            a.said.add("in_ego_lane")  # (partly in the other way's lane: the ego's, for one coming at it)
        elif m.slot == "returns" and not _gets_up(m):
            a.returns = True
        elif m.slot == "side":
            a.goes_to = a.goes_to or (
                None if _verb_with_to(a) else sides.where_it_goes(m.value, m.words, m.prev, m.next_)
            )
            a.side = a.side or sides.crossing_from(m.value, m.words, m.prev, m.next_, a.behaviours)
            a.came_from = a.came_from or _from(m)
            a.beside = a.beside or sides.on_the_ego_side(m.words)
        elif m.slot == "toward":
            a.toward = m.value
        elif m.slot == "lane_side":  # (the lane it starts in: the first said)
            a.lane_side = a.lane_side or m.value
        elif (
            m.slot in ("kerb", "kerb_side")
            and m.prev == "at"
            and sides.arm_is_where_it_acts("at", a.said, a.behaviours)
        ):
            pass  # ("the scooter ahead stops at the zebra crossing": where it stops, a landmark)
        elif m.slot == "kerb":
            a.kerb = True
            a.along = a.along or kerb_ride.along_the_edge(m.prev)
            a.own_lane = a.own_lane or "lane" in m.words.split()
            a.pavement = a.pavement or on_the_footway(m)
            a.came_from = a.came_from or _from(m)
        elif m.slot == "place":
            a.out_of_place = True
            a.place = a.place or m.value
        elif m.slot == "far_side":
            a.far_side = True
        elif m.slot == "kerb_side" and sides.travels_on_the_wrong_side(a.kind, m.words, m.next_):
            a.wrong_way = True  # ("a biker came from wrong side, straight towards my car")
        elif m.slot == "kerb_side" and sides.where_it_goes(m.value, m.words, m.prev, m.next_) and not _verb_with_to(a):
            a.goes_to = a.goes_to or m.value  # ("ran across towards the left kerb": where it ends, not starts)
        elif m.slot == "kerb_side" and a.left_the_kerb and not _from(m):
            pass  # ("came off the pavement on the left ... to his mates on the other side": where it comes from)
        elif m.slot == "kerb_side":
            a.kerb, a.kerb_side = True, m.value
            a.left_the_kerb = _from(m)
            a.along = a.along or kerb_ride.along_the_edge(m.prev)
            a.own_lane = a.own_lane or "lane" in m.words.split()
            a.edge = a.edge or (None if "lane" in m.words.split() else m.value)  # (a cycle lane is a lane)
            a.came_from = a.came_from or _from(m)
        elif (
            m.slot == "arm"
            and m.prev not in _LANDMARK_PREPOSITIONS
            and not sides.arm_is_where_it_acts(m.prev, a.said, a.behaviours)
            and not (a.lane_side and m.prev not in _OUT_OF_AN_ARM)  # ("in the right lane ... at the exit, it swerves")
        ):
            a.arm = True  # (not "on the crossing just after the exit": a landmark, not where it comes from)
            a.from_arm = a.from_arm or m.prev in ("from", "out")  # (not "over the mouth of the side road")
            a.takes_an_exit = a.takes_an_exit or ("exit" in m.words.split() and m.prev not in _OUT_OF_AN_ARM)
        elif m.slot == "stationary":
            a.stationary = True
            a.parked = a.parked or m.words.split()[0] in ("parked", "park", "double-parked", "double")
            a.double_parked = a.double_parked or m.words.split()[0] in ("double-parked", "double")
