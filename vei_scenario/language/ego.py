"""Which road user is the ego when the text names it by role or in the third person.

A description is told from one road user's point of view, but people often name that road user
without "I" or "the ego": a report names its own vehicle by a role ("Reporting vehicle: city shuttle
bus", "a taxi (reporting driver)", "Host vehicle is a 40 t truck") or by the person at its wheel ("a
word from Dave, who's driving a bin lorry", "Pupil approached the roundabout at 20 mph"); a narrator
names the vehicle they are in by getting into it or by a relative clause ("got back in the van", "the
bus I was driving"); a news report sets one vehicle against a walker or rider it struck ("a woman
riding an e-scooter was struck by a car"); an automated vehicle that meets the narrator ("a robotaxi
cut me up") is not the ego but another car. (A call sign that observes "the subject vehicle" is read
where the report's parties are, in :mod:`vei_scenario.language.normalise`; a narrator who only
watches, by discourse.)

:func:`frame` finds that road user by the structure that frames it and says it "the ego" (every
mention of it, "the bus", "the driver of the car", once it is known to be the ego), so the reader
reads one ego and the other road users as actors. Each rule reads only where the text names no ego
otherwise, except those that mark one named road user as the ego explicitly. It knows no content
words of its own beyond small closed classes (verbs of boarding and of contact; the roles a person
has in a driving lesson or a claim); which words name road users comes from the reader's lexicon
through ``kind_at``.
"""

from __future__ import annotations

from collections.abc import Callable
from functools import lru_cache

from vei_scenario.language.lemmas import lemmas
from vei_scenario.language.vocabulary import GENDERED, IN_LINE, LEARNER
from vei_scenario.language.vocabulary import PARTY as FAMILY

KindAt = Callable[[list[str], int], "tuple[str, int] | None"]
Known = Callable[[list[str], int], bool]
#: A rule that says "the ego" in ``tokens`` (same arguments as :func:`frame`).
Framer = Callable[[list[str], KindAt, Known, list[str]], list[str]]

VEHICLES = frozenset({"car", "van", "truck"})
DEFINITE = frozenset({"the", "that", "this"})
INDEFINITE = frozenset({"a", "an", "another", "some", "one"})
BE = frozenset({"am", "is", "are", "was", "were", "be", "been", "being"})
SENTENCE_END = frozenset({".", ";", "!", "?"})
PUNCT = SENTENCE_END | {",", ":"}
#: First-person subjects: a narrator who is in the scenario is the ego, one who only watches is not.
FIRST_PERSON = frozenset({"i", "we"})
#: The reader put in the scene ("Picture yourself driving a van"): at a wheel, as a narrator is.
YOU = frozenset({"you", "yourself"})
#: First-person words that put the narrator in the scene as someone met or moved ("came at me", "my lane").
NARRATOR_INVOLVED = frozenset({"me", "us", "my", "our", "ego"})
#: Auxiliaries and adverbs between a subject and its verb ("I had just seen", "we were all waiting").
BETWEEN = BE | {"had", "have", "has", "would", "could", "did", "just", "all", "both", "then", "also", "'d"}
#: Verbs of getting into a vehicle: what the narrator gets into is the narrator's vehicle.
BOARDING = frozenset({"get", "climb", "jump", "hop", "pile", "sit"})
#: Verbs of contact: the one vehicle that strikes a walker or rider in a news report is the ego.
CONTACT = frozenset({"hit", "strike", "collide", "clip", "knock", "plough", "mow", "crash"})
#: Words of driving a vehicle, after the person at its wheel ("Dave, who's driving a bin lorry").
DRIVING = frozenset({"driving", "drives", "drove", "driven"})
#: Roles of the party a claim is made for: always the one the statement is told for.
PARTY = frozenset({"client", "claimant", "insured", "policyholder", "complainant"})
#: Roles of the person a report is taken from ("Cust states ...", "RP traveling 65 mph", "Caller was
#: ..."): in a report told in the third person, the one the report is told for, as a party to a claim.
REPORTER = frozenset({"customer", "cust", "caller", "rp"})
#: The person at the wheel of a vehicle, in "the driver of the car" (that vehicle's mention).
AT_WHEEL = frozenset({"driver", "rider", "motorist"})
PRONOUNS = frozenset({"he", "she", "it", "they", "him", "her", "them", "who", "you", "one", "someone"})
SPEED_UNITS = frozenset({"mph", "km/h", "m/s"})
#: Words of where a vehicle is relative to another ("the car ahead", "parked cars"): not the ego.
PLACED = frozenset(
    {"ahead", "behind", "parked", "oncoming", "following", "alongside", "lead", "leading", "preceding", "trailing"}
)


def lemma_in(word: str, wanted: frozenset[str]) -> bool:
    return word in wanted or any(x in wanted for forms in lemmas(word).values() for x in forms)


def _ego_at(tokens: list[str], i: int, kind_at: KindAt) -> int:
    """The length of an ego phrase at ``i`` ("the ego", "reporting vehicle", "sut"), else 0."""
    found = kind_at(tokens, i)
    return found[1] if found is not None and found[0] == "ego" else 0


def names_ego(tokens: list[str], kind_at: KindAt, known: Known) -> bool:
    """Whether the text names its ego itself: an ego phrase, or a first-person word."""
    return bool((FIRST_PERSON | NARRATOR_INVOLVED) & set(tokens)) or any(
        p.kind == "ego" for p in road_users(tokens, kind_at, known)
    )


def road_users(tokens: list[str], kind_at: KindAt, known: Known) -> list:
    """The road-user phrases of ``tokens``, two vehicle nouns in a row as one ("an estate car")."""
    return _road_users_of(tuple(tokens), kind_at, known)


@lru_cache(maxsize=16)
def _road_users_of(tokens: tuple[str, ...], kind_at: KindAt, known: Known) -> tuple:
    """(Cached: the rules ask for the phrases of the same words several times.)"""
    from vei_scenario.language.discourse import Phrase, road_user_phrases

    out: list = []
    for p in road_user_phrases(list(tokens), kind_at, known):
        if out and out[-1].end == p.start and out[-1].kind in VEHICLES and p.kind in VEHICLES:
            q = out.pop()
            p = Phrase(q.start, q.head, p.end, q.det, p.kind)
        out.append(p)
    return tuple(out)


def _vehicle_phrases(tokens: list[str], kind_at: KindAt, known: Known) -> list:
    return [p for p in road_users(tokens, kind_at, known) if p.kind in VEHICLES]


#: Words that say the vehicle is only scenery or set beside someone else.
PARKED = frozenset({"parked", "stationary", "abandoned", "stopped", "stalled", "broken-down", "double-parked"})


def stands_parked(tokens: list[str], p) -> bool:
    """A word of standing still by the mention ("a parked van", "the bus, stationary,", "the cab was
    stopped"), not its verb of reacting ("the taxi stopped just in time", "the van driver stopped")."""
    near = tokens[max(p.start - 2, 0) : p.end + 2]
    if tokens[p.end : p.end + 1] == ["stopped"]:
        near = tokens[max(p.start - 2, 0) : p.end] + tokens[p.end + 1 : p.end + 2]
    return bool(PARKED & set(near))


def placed_by_word(tokens: list[str], p) -> bool:
    after = tokens[p.end : p.end + 2]
    before = tokens[p.start - 1] if p.start else ""
    return (
        (bool(after) and (after[0] in PLACED or after == ["in", "front"]))
        or before in PLACED | {"behind"}
        or any(w in PLACED for w in tokens[p.start : p.head])
    )


def _at_wheel(tokens: list[str], p) -> bool:
    """Whether ``p`` is "the driver" of a vehicle named elsewhere, no vehicle of its own."""
    return tokens[p.end - 1] in AT_WHEEL and p.det in DEFINITE


def _referents(tokens: list[str], phrases) -> dict[str, list]:
    """Vehicle mentions grouped by their head noun: one referent per noun, when it is introduced once
    (a second indefinite mention of the same noun is a second vehicle: the noun maps to None)."""
    out: dict[str, list] = {}
    for p in phrases:
        noun = tokens[p.end - 1]
        if noun in out and p.det in INDEFINITE:
            out[noun] = None
        elif out.get(noun, []) is not None:
            out.setdefault(noun, []).append(p)
    return out


def owner_before(tokens: list[str], p) -> str | None:
    """The word before the "'s" that owns the bare vehicle phrase ``p`` ("Mary" in "Mary's car", "Mary's
    grey car"), else None."""
    if p.det:
        return None
    s = p.start - 1
    while s >= p.start - 3 and s > 0 and tokens[s].isalpha() and tokens[s] not in DEFINITE | INDEFINITE:
        s -= 1
    return tokens[s - 1] if s >= 1 and tokens[s] == "'s" else None


def as_ego(
    tokens: list[str],
    kind_at: KindAt,
    known: Known,
    noun: str,
    dropped: list[str],
    only: bool = False,
    owner: frozenset[str] | None = None,
) -> list[str]:
    """``tokens`` with every definite or bare mention of the vehicle named by ``noun`` (its head) said
    "the ego", as is "the driver of" it, and where it is the ``only`` vehicle, "the driver"; an
    indefinite one ("another bus") is someone else, and so, where the ego's ``owner`` words are given,
    is one another owner's "'s" names ("Mary's car" where the ego is John's)."""
    out = list(tokens)
    for p in reversed(_vehicle_phrases(out, kind_at, known)):
        driver = only and _at_wheel(out, p) and out[p.end : p.end + 1] != ["of"]
        new = p.det in INDEFINITE and not (only and p.det in ("a", "an"))
        if (out[p.end - 1] != noun and not driver) or new or "other" in out[p.start : p.head]:
            continue
        if owner is not None and owner_before(out, p) not in owner | {None, "ego"}:
            continue  # ("John's car and Mary's car collided": Mary's is another car)
        start = p.start
        back = next((b for b in range(start - 1, max(start - 3, -1), -1) if out[b] in DEFINITE | INDEFINITE), None)
        if not p.det and back is not None and all(out[b].isalpha() for b in range(back, start)):
            start = back  # ("a grey estate car": its article before a word the reader reads otherwise)
        if out[start] in DEFINITE and any(w in IN_LINE - {"front", "rear"} for w in out[start : p.head]):
            continue  # ("the lead truck" when the ego is a truck too: the one in its line it is not)
        if start >= 3 and out[start - 1] == "of" and out[start - 2] in AT_WHEEL and out[start - 3] in DEFINITE:
            start -= 3  # ("the driver of the corsa": the corsa)
        dropped.extend(w for w in out[start : p.end] if w not in DEFINITE)
        out[start : p.end] = ["the", "ego"]
    return out


def _marked(tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """A vehicle marked as the ego: with an ego phrase in brackets after it ("a Prius taxi (reporting
    driver)", "the white van (ego)"), or as the value of an ego phrase's field or copula ("Reporting
    vehicle: city shuttle bus", "Host vehicle is a 40 t truck"): that vehicle is the ego, and so is
    every later "the bus"."""
    if not any(p.kind == "ego" for p in road_users(tokens, kind_at, known)):
        return tokens
    tokens = _ego_bracketed(tokens, kind_at, known, dropped)
    for p in _vehicle_phrases(tokens, kind_at, known):
        noun = tokens[p.end - 1]
        label = tokens[p.end : p.end + 2]
        if len(label) == 2 and label[1] == "(" and (label[0].isdigit() or (len(label[0]) == 1 and label[0].isalpha())):
            close = next((k for k in range(p.end + 2, min(p.end + 7, len(tokens))) if tokens[k] == ")"), None)
            inner = [w for w in tokens[p.end + 2 : close] if w not in DEFINITE] if close else []
            if inner and _ego_at(inner, 0, kind_at) == len(inner):  # "Car C (the test vehicle)": the label
                dropped.extend(w for w in tokens[p.head : close + 1] if w.isalpha() and w not in DEFINITE | {"ego"})
                out = [*tokens[: p.start], "the", "ego", *tokens[close + 1 :]]
                return _marked(_label_as_ego(out, [noun, label[0]]), kind_at, known, dropped)
        if tokens[p.end : p.end + 1] == ["("]:
            close = next((k for k in range(p.end + 1, min(p.end + 6, len(tokens))) if tokens[k] == ")"), None)
            inner = [w for w in tokens[p.end + 1 : close] if w not in DEFINITE] if close else []
            if inner and _ego_at(inner, 0, kind_at) == len(inner):
                dropped.extend(w for w in tokens[p.start : close + 1] if w.isalpha() and w not in DEFINITE)
                out = [*tokens[: p.start], "the", "ego", *tokens[close + 1 :]]
                return _marked(as_ego(out, kind_at, known, noun, dropped), kind_at, known, dropped)
        # "<ego phrase> : / is a <modifiers> <vehicle>": where its value starts, past its article
        j = p.head
        j -= j > 0 and tokens[j - 1] in IN_LINE  # ("Ego: following truck": its place in a line of vehicles)
        while j > 0 and (
            tokens[j - 1].replace(".", "").isdigit() or (tokens[j - 1].isalpha() and not known(tokens, j - 1))
        ):
            j -= 1
        j -= j > 0 and tokens[j - 1] in ("a", "an")
        marker = j - 1
        if marker < 1 or p.head - j > 4 or (tokens[marker] != ":" and tokens[marker] not in BE):
            continue
        ego_end = next((k for k in range(max(marker - 3, 0), marker) if k + _ego_at(tokens, k, kind_at) == marker), 0)
        if not _ego_at(tokens, ego_end, kind_at) or tokens[ego_end] in FIRST_PERSON:
            continue
        if tokens[p.end : p.end + 1] and (tokens[p.end] in PLACED or tokens[p.end].startswith("length")):
            continue  # ("the ego is a car length behind")
        end = p.end + (tokens[marker] == ":" and tokens[p.end : p.end + 1] == [","])
        dropped.extend(w for w in tokens[j : p.end] if w.isalpha() and w not in ("a", "an"))
        out = tokens[:j] + tokens[end:]
        return _marked(as_ego(out, kind_at, known, noun, dropped), kind_at, known, dropped)
    return tokens


#: Words between two names of one vehicle in brackets ("(rigid HGV, skip lorry)", "(bus or coach)").
_SAID_AGAIN = frozenset((",", "or", "/"))


def _ego_bracketed(tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """ "The test vehicle (an Iveco tipper) ...", "Host vehicle (a minibus) ...": brackets right after
    an ego phrase that hold only a vehicle (its article, its make or model, its modifiers; or several
    names of it: "(rigid HGV, skip lorry)") say what the ego is; they go, and every later "the tipper"
    is the ego. Brackets that hold anything else ("(following a van)", "(in lane 2)") stay."""
    for p in road_users(tokens, kind_at, known):
        if p.kind != "ego" or tokens[p.end : p.end + 1] != ["("]:
            continue
        close = next((k for k in range(p.end + 1, min(p.end + 8, len(tokens))) if tokens[k] == ")"), None)
        inside = [q for q in road_users(tokens, kind_at, known) if close and p.end < q.start < close]
        if close is None or not inside or any(q.kind not in VEHICLES for q in inside) or inside[-1].end != close:
            continue
        starts = [p.end + 1] + [q.end for q in inside[:-1]]  # ("(rigid HGV, skip lorry)": one said twice)
        if any(
            not (
                w in INDEFINITE
                or w.replace(".", "").isdigit()
                or (w.isalpha() and not known(tokens, j))
                or (n > 0 and w in _SAID_AGAIN)
            )
            for n, (start, q) in enumerate(zip(starts, inside))
            for j, w in enumerate(tokens[start : q.head], start)
        ):
            continue
        q = inside[-1]
        dropped.extend(w for w in tokens[p.end + 1 : close] if w.isalpha() and w not in INDEFINITE)
        out = [*tokens[: p.end], *tokens[close + 1 :]]
        return as_ego(out, kind_at, known, tokens[q.end - 1], dropped)
    return tokens


def _label_as_ego(tokens: list[str], label: list[str]) -> list[str]:
    """``tokens`` with every mention of a vehicle's ``label`` ("car c", "the van b") said "the ego"."""
    out: list[str] = []
    k = 0
    while k < len(tokens):
        if tokens[k : k + 2] == label:
            if out and out[-1] in DEFINITE:
                out.pop()
            out += ["the", "ego"]
            k += 2
            continue
        out.append(tokens[k])
        k += 1
    return out


def _marked_person(tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """A person named and marked as the ego in brackets ("Maria (the ego driver) proceeds", "Tom (ego)"):
    the ego, wherever the name is said again."""
    for k in range(len(tokens) - 2):
        if tokens[k + 1] != "(" or _person_end(tokens, k, kind_at, known) != k + 1:
            continue
        close = next((c for c in range(k + 2, min(k + 7, len(tokens))) if tokens[c] == ")"), None)
        inner = [w for w in tokens[k + 2 : close] if w not in DEFINITE] if close else []
        n = _ego_at(inner, 0, kind_at) if inner else 0
        if not n or inner[n:] not in ([], ["driver"], ["rider"]):
            continue
        name = tokens[k]
        dropped.append(name)
        out = [*tokens[:k], "the", "ego", *tokens[close + 1 :]]
        return [x for w in out for x in (["the", "ego"] if w == name else [w])]
    return tokens


def _designated(tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """A vehicle designated as the ego ("with the policyholder's car as the ego", "Treat the taxi as the
    ego."): that vehicle, every "the <noun>" of it and its owner wherever named are the ego; the words
    that designate it go. "as the ego approached" (a clause of time) designates nothing."""
    for k in range(1, len(tokens)):
        n = 3 if tokens[k : k + 3] == ["as", "the", "ego"] else 2 if tokens[k : k + 2] == ["as", "ego"] else 0
        if not n or (k + n < len(tokens) and tokens[k + n] not in PUNCT):
            continue
        p = next((q for q in _vehicle_phrases(tokens, kind_at, known) if q.end == k), None)
        if p is None:
            continue
        noun, start = tokens[p.end - 1], p.start
        owner: list[str] = []
        if start >= 2 and tokens[start - 1] == "'s" and tokens[start - 2].isalpha():
            owner, start = [tokens[start - 2]], start - 2
            start -= start > 0 and tokens[start - 1] in DEFINITE | {"our", "my"}
        s, e = sentence_span(tokens, k)
        others = [q for q in road_users(tokens, kind_at, known) if s <= q.start < e and q.start != p.start]
        cut = (s, e + (e < len(tokens))) if not others else (start, k + n)
        dropped.extend(w for w in tokens[cut[0] : cut[1]] if w.isalpha() and w not in DEFINITE | {"ego"})
        out = [*tokens[: cut[0]], *([] if not others else ["the", "ego"]), *tokens[cut[1] :]]
        if owner and owner[0] not in ("ego",):
            said: list[str] = []
            for i, w in enumerate(out):
                if w == owner[0] and not (i and out[i - 1] in INDEFINITE):
                    if said and said[-1] in DEFINITE | {"our", "my"}:
                        said.pop()
                    said += ["the", "ego"]
                    continue
                said.append(w)
            out = said
        out = as_ego(out, kind_at, known, noun, dropped)
        return driver_is_ego(out, kind_at, known, dropped)
    return tokens


def _met_by_narrator(tokens: list[str], kind_at: KindAt, known: Known) -> list[str]:
    """ "a robotaxi cut me up", "a self-driving car pulled out in front of us": an ego phrase new to
    the text ("a"/"an") that meets the narrator in its sentence is another road user, a car (the
    narrator is the ego); "the robotaxi" after it is that car."""
    out = list(tokens)
    for p in reversed(road_users(tokens, kind_at, known)):
        if p.kind != "ego" or p.det not in ("a", "an") or tokens[p.head] in FIRST_PERSON | NARRATOR_INVOLVED:
            continue
        e = p.end
        while e < len(tokens) and tokens[e] not in SENTENCE_END:
            e += 1
        if not {"me", "us", "my", "our"} & set(tokens[p.end : e]):
            continue
        said = tokens[p.head : p.end]
        k = p.end
        while k <= len(out) - len(said):  # (its later mentions: that car)
            if out[k : k + len(said)] == said and out[k - 1] in DEFINITE:
                out[k : k + len(said)] = ["car"]
            k += 1
        out[p.start : p.end] = ["a", "car"]
    return out


def _person_end(tokens: list[str], i: int, kind_at: KindAt, known: Known) -> int | None:
    """Where a person's name or role that may stand at a wheel, starting at ``i``, ends: a name the
    reader has no phrase for ("Dave"), or a person's noun with "the" or none ("the pupil"), not one
    with "a" (someone new: another road user)."""
    w = tokens[i]
    if i and tokens[i - 1] in INDEFINITE:
        return None
    found = kind_at(tokens, i)
    if found is not None:
        return i + found[1] if found[0] == "pedestrian" else None
    name = w.isalpha() and not known(tokens, i) and w not in BE | PRONOUNS and not {"ADV", "ADJ"} & set(lemmas(w))
    return i + 1 if name else None


def _named_in(tokens: list[str], k: int, kind_at: KindAt, known: Known) -> bool:
    """Whether the "in" at ``k`` puts a person just named in a vehicle ("Darren, in the van doing 15
    mph", "Keith in the artic", "Priya, in one of the Corollas"): "the" (or "one of the") and a
    vehicle phrase right after it that is no modifier of a place ("in the bus lane", "in the car
    park") and not placed relative to someone ("in the van ahead": someone else's)."""
    j = k + 1 + 2 * (tokens[k + 1 : k + 4] == ["one", "of", "the"])
    if tokens[j : j + 1] != ["the"]:
        return False
    p = next((q for q in _vehicle_phrases(tokens, kind_at, known) if q.start in (j, j + 1)), None)
    if p is None or placed_by_word(tokens, p):
        return False
    after = tokens[p.end] if p.end < len(tokens) else ""
    return not (after.isalpha() and after in lemmas(after).get("NOUN", ()))  # ("in the car park")


def _at_the_wheel(tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """ "a word from Dave, who's driving a bin lorry", "the pupil, driving the school's hatchback",
    "Caller rides a moped", "Resident was on her motorbike", "Neighbour (retired, drives a camper)":
    the person at the wheel or on the saddle and the vehicle are the ego (the vehicle named once, its
    person after). A person named by a road-user noun ("the boy riding his bike") rides as a road
    user: only a name or a role may ride a bicycle or e-scooter that is the ego."""
    for k, w in enumerate(tokens):
        inside = w in ("in", "on") and tokens[k + 1 : k + 2] in (["his"], ["her"], ["their"])
        named_in = w == "in" and not inside and _named_in(tokens, k, kind_at, known)
        inside = inside or named_in
        if w not in DRIVING | RIDES and not inside:
            continue
        start = k  # the person, past ", who is"
        start -= start > 0 and tokens[start - 1] in BE | {"'s"}
        start -= start > 0 and tokens[start - 1] == "who"
        relative = start < k
        start -= start > 0 and tokens[start - 1] == ","
        end = start
        person = next(
            (s for s in range(max(start - 2, 0), start) if _person_end(tokens, s, kind_at, known) == end), None
        )
        if person is None and not inside and (opening := _bracket_opening(tokens, k)) is not None:
            start = end = k - (tokens[k - 1] == ",")  # ("Neighbour (retired, drives a camper)": the comma goes)
            person = opening - 1 if _person_end(tokens, opening - 1, kind_at, known) == opening else None
            relative = True
        if person is None or (named_in and kind_at(tokens, person) is not None):
            continue  # (a name, not a role, in "the" vehicle: "the boy in the car" is a passenger)
        opens = not person or tokens[person - 1] in CLAUSE_OPENING | DEFINITE
        if (w in RIDES or w == "on") and not opens:
            continue  # (the subject of its clause only: "in the bus lane on his bicycle" is no person's)
        j = k + 1 + (k + 1 < len(tokens) and tokens[k + 1] in DEFINITE | INDEFINITE | {"his", "her", "their"})
        if tokens[k + 1 : k + 4] == ["one", "of", "the"]:
            j = k + 4  # ("in one of the Corollas")
        head = next((h for h in range(j, min(j + 3, len(tokens))) if kind_at(tokens, h) is not None), None)
        found = kind_at(tokens, head) if head is not None else None
        kinds = VEHICLES if kind_at(tokens, person) is not None else RIDDEN
        if found is None or found[0] not in kinds or any(known(tokens, h) for h in range(j, head)):
            continue
        if found[0] not in VEHICLES and rider_noun(tokens[head]):
            continue  # ("Dave was riding behind a cyclist")
        name = tokens[person:end]
        whole = next((q.end for q in _vehicle_phrases(tokens, kind_at, known) if q.start <= head < q.end), 0)
        cut = (end if relative else k + (not inside), max(head + found[1], whole))  # ("her own Nissan Micra")
        dropped.extend(x for x in tokens[cut[0] : cut[1]] if x.isalpha())
        out = tokens[: cut[0]] + tokens[cut[1] :]
        said: list[str] = []
        i = 0
        while i < len(out):  # the person, wherever named again, is the ego
            if out[i : i + len(name)] == name and (not i or out[i - 1] not in INDEFINITE):
                if said and said[-1] in DEFINITE:
                    said.pop()
                said += ["the", "ego"]
                i += len(name)
                continue
            said.append(out[i])
            i += 1
        if found[0] in VEHICLES:  # ("passenger in the blue Transit van ... the van (driver) braked")
            noun = tokens[cut[1] - 1]
            said = as_ego(said, kind_at, known, noun, dropped)
            for i in range(len(said) - 3, -1, -1):
                if said[i : i + 3] == ["the", noun, "driver"]:
                    said[i : i + 3] = ["the", "ego"]
        owner = tokens[k + 1] if k + 1 < len(tokens) and tokens[k + 1] in PRONOUNS_OF else None
        owner = owner or owner_by_pronouns(said)
        return pronouns_as_ego(said, owner, kind_at, known) if owner else said
    return tokens


#: Forms of "ride": a person who rides a vehicle is on it.
RIDES = frozenset({"ride", "rides", "riding", "rode", "ridden"})


def rider_noun(word: str) -> bool:
    """Whether ``word`` names the person on a bicycle or e-scooter ("cyclist", "rider"), not the
    machine: a person can ride a bike, not a cyclist."""
    return word.endswith(("ist", "ists", "rider", "riders"))


def _bracket_opening(tokens: list[str], k: int) -> int | None:
    """Where the brackets that hold the word at ``k`` open, when they open right after a word and hold
    only a few words of detail before it ("Neighbour (retired, drives ..."): else None."""
    b = next((b for b in range(k - 1, max(k - 6, 0), -1) if tokens[b] in ("(", ")")), None)
    return b if b is not None and tokens[b] == "(" and b >= 1 else None


def owner_by_pronouns(tokens: list[str]) -> str | None:
    """The possessive ("her", "his") of the first subject pronoun after "the ego" in ``tokens``
    ("Caller rides a moped. She says she was doing ... missed him"): the person named with no pronoun
    of their own is the subject the story goes on with. None where no person of that gender could be
    it but someone named before it ("a boy ran out and he ..."), or where none is said."""
    first = next((i for i in range(len(tokens) - 1) if tokens[i : i + 2] == ["the", "ego"]), len(tokens))
    for i in range(first, len(tokens)):
        owner = next((g for g, forms in PRONOUNS_OF.items() if tokens[i] == forms[0]), None)
        if owner is not None:
            return None if any(w in GENDERED[owner] for w in tokens[first:i]) else owner
    return None


#: The pronouns ("she", "her") that a possessive ("driving her car") gives its owner: subject,
#: object. Only the gendered ones: "they" may be any group of road users.
PRONOUNS_OF = {"her": ("she", "her"), "his": ("he", "him")}


def pronouns_as_ego(tokens: list[str], owner: str, kind_at: KindAt, known: Known) -> list[str]:
    """``tokens`` (a named driver already said "the ego") with the driver's pronouns after the ego
    said "the ego" too ("a van pulled out in front of her. She braked hard": the ego's reaction, not
    the van's), where no other person of that gender is named ("a girl ran out ... she stopped");
    "her" before a noun is the ego's ("her mirror")."""
    subject, obj = PRONOUNS_OF[owner]
    if any(w in GENDERED[owner] for w in _story(tokens, kind_at, known)):
        return tokens  # (another person of that gender in the story; "Watch it, lads" is an aside)
    first = next((i for i in range(len(tokens) - 1) if tokens[i : i + 2] == ["the", "ego"]), None)
    if first is None:
        return tokens
    users = road_users(tokens, kind_at, known)
    out = tokens[: first + 2]
    for i in range(first + 2, len(tokens)):
        w, nxt = tokens[i], tokens[i + 1] if i + 1 < len(tokens) else ""
        last = next((q for q in reversed(users) if q.end <= i), None)
        other = GENDERED["his" if owner == "her" else "her"]
        if (
            w == subject
            and last is not None
            and last.kind not in VEHICLES | {"ego"}
            and not other & set(tokens[last.start : last.end])
        ):
            out.append(w)  # (a walker or rider just named may be "he": "a cyclist pulled out; he fell")
        elif w == subject or (w == obj and w != owner):
            out += ["the", "ego"]
        elif w == owner == obj and not (nxt.isalpha() and "NOUN" in lemmas(nxt) and nxt not in BETWEEN):
            out += ["the", "ego"]  # ("in front of her": the object, no possessive)
        else:
            out.append(w)
    return out


#: Words that open a clause of driving that has no subject of its own ("while driving her car, she").
SUBORDINATORS = frozenset({"while", "whilst", "when"})


def _driving_subject(tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """ "while driving her own car along Victoria Road at 20 mph, she had to brake", "Driving his lorry
    out of the depot, he met ...": a clause of driving with no subject of its own, opening its
    sentence or after "while"/"when", has the subject of the clause it leads into; where that is the
    pronoun its possessive gives ("her" car: "she"), that person drives: the vehicle is the ego (it
    goes, the verb stays with its speed), and so are that pronoun and the later ones of its owner."""
    for k, w in enumerate(tokens):
        if w not in DRIVING or k + 1 >= len(tokens) or tokens[k + 1] not in PRONOUNS_OF:
            continue
        before = tokens[k - 1] if k else ""
        if before not in SUBORDINATORS and k and before not in CLAUSE_OPENING | {"that"}:
            continue
        p = next((q for q in _vehicle_phrases(tokens, kind_at, known) if k + 1 < q.end <= k + 5), None)
        if p is None or placed_by_word(tokens, p) or any(x not in OWNING and known(tokens, j) for j, x in
                                                  enumerate(tokens[k + 1 : p.start], k + 1)):  # fmt: skip
            continue
        _, e = sentence_span(tokens, k)
        comma = next((c for c in range(p.end, e) if tokens[c] == ","), None)
        owner = tokens[k + 1]
        if comma is None or tokens[comma + 1 : comma + 2] != [PRONOUNS_OF[owner][0]]:
            continue
        dropped.extend(x for x in tokens[k + 1 : p.end] if x.isalpha() and x not in OWNING)
        out = [*tokens[: k + 1], *tokens[p.end : comma + 1], "the", "ego", *tokens[comma + 2 :]]
        return pronouns_as_ego(out, owner, kind_at, known)
    return tokens


def _news_driver(tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """A news report about a driver ("A taxi driver has been praised ...", "The driver of a delivery
    van, who was doing 20 mph, braked ..."): the driver, the subject opening its clause, named with
    their vehicle, is the one the report follows when that vehicle has a speed of its own (right
    after the driver, before anyone else is named: ", who was doing 20 mph"; or at a later "the
    <noun>": "the lorry, travelling at 50 mph"). That vehicle is the ego, and so is every later
    "the" mention of it and of the same kind of vehicle no "a" introduces ("the HGV")."""
    users = road_users(tokens, kind_at, known)
    for n, p in enumerate(users):
        if tokens[p.end - 1] != "driver" or (p.start and tokens[p.start - 1] not in CLAUSE_OPENING):
            continue
        if p.end - p.head == 2 and (found := kind_at(tokens, p.end - 2)) is not None and found[0] in VEHICLES:
            vehicle, end = tokens[p.end - 2], p.end  # ("a lorry driver")
        elif tokens[p.end : p.end + 1] == ["of"] and n + 1 < len(users) and users[n + 1].start == p.end + 1:
            q = users[n + 1]  # ("the driver of a delivery van")
            if q.kind not in VEHICLES or placed_by_word(tokens, q):
                return tokens
            vehicle, end = tokens[q.end - 1], q.end
        else:
            return tokens  # (only the first driver named, as the story's subject)
        kind = kind_at(tokens, tokens.index(vehicle, p.start))[0]  # type: ignore[index]
        later = [q for q in users if q.start >= end]
        if any(q.det in INDEFINITE and tokens[q.end - 1] == vehicle for q in later):
            return tokens  # (another vehicle of that name)
        new = {tokens[q.end - 1] for q in later if q.det in INDEFINITE}
        spans = [(end, next((q.start for q in later), len(tokens)))]
        spans += [  # ("the lorry, travelling at 50 mph", "the cab, going at 25 mph")
            (q.end, next((r.start for r in later if r.start >= q.end), len(tokens)))
            for q in later
            if q.det == "the" and q.kind == kind and tokens[q.end - 1] not in new and tokens[q.end : q.end + 1] == [","]
        ]
        if not any(any(w in SPEED_UNITS for w in tokens[a : min(b, sentence_span(tokens, a)[1])]) for a, b in spans):
            return tokens
        dropped.extend(w for w in tokens[p.start : end] if w.isalpha() and w not in DEFINITE | INDEFINITE)
        out = [*tokens[: p.start], "the", "ego", *tokens[end:]]
        out = _introduced_as_ego(out, users[:n], vehicle, dropped)
        out = as_ego(out, kind_at, known, vehicle, dropped)
        same = {
            out[q.end - 1]
            for q in _vehicle_phrases(out, kind_at, known)
            if q.kind == kind and q.det == "the" and q.end - q.head == 1
        }
        for noun in sorted(same):
            if not any(q.det in INDEFINITE and out[q.end - 1] == noun for q in _vehicle_phrases(out, kind_at, known)):
                out = as_ego(out, kind_at, known, noun, dropped)
        return out
    return tokens


def _introduced_as_ego(tokens: list[str], before: list, noun: str, dropped: list[str]) -> list[str]:
    """``tokens`` with the one vehicle ``before`` introduced as new with ``noun`` in its name ("a Toyota
    Hilux rammed a trailer ... the Toyota driver, travelling at 100 km/h, ...") said "the ego": "the <noun>
    driver" points back to the vehicle "a <noun>" brought in, as any definite noun phrase does to its
    antecedent. With two such vehicles ("a Honda ... another Honda") which one is meant stays open."""
    new = [q for q in before if q.kind in VEHICLES and q.det in INDEFINITE and noun in tokens[q.head : q.end]]
    if len(new) != 1:
        return tokens
    q = new[0]
    dropped.extend(w for w in tokens[q.head : q.end] if w.isalpha())
    return [*tokens[: q.start], "the", "ego", *tokens[q.end :]]


#: Possessives a news report gives the driver it opens on ("his cab", "her van"), with the gender
#: of the pronouns that go on with that driver.
POSSESSIVES = frozenset(PRONOUNS_OF)


def _followed_driver(tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """ "A taxi driver has been cleared after a rider shot into the path of his cab. He was travelling
    at 20 mph", "A delivery driver ... after her van struck a woman": a report that opens on a driver
    (the first road user it names, the subject of its clause) and goes on with "his"/"her" vehicle
    follows that driver: the driver, that vehicle and the driver's pronouns are the ego, so a speed
    said of "he"/"she" is the ego's (where no one else of that gender is named). Where another motor
    vehicle is named before the possessive, or the driver is not the first road user named ("A
    cyclist was hurt when a van driver opened his door"), whose vehicle it is stays open and nothing
    is read."""
    users = road_users(tokens, kind_at, known)
    if not users or tokens[users[0].end - 1] not in ("driver", "motorist"):
        return tokens
    p = users[0]
    if p.start and tokens[p.start - 1] not in CLAUSE_OPENING | {"that"}:
        return tokens
    end = p.end
    if tokens[end : end + 1] == ["of"] and len(users) > 1 and users[1].start == end + 1:
        if users[1].kind not in VEHICLES or placed_by_word(tokens, users[1]):
            return tokens
        end = users[1].end  # ("the driver of a bin lorry")
    owned = next(
        (
            q
            for q in users
            if q.start >= end and q.det in POSSESSIVES and q.kind in VEHICLES and not placed_by_word(tokens, q)
        ),
        None,
    )
    if owned is None:
        return tokens
    owner = owned.det
    if any(q.kind in VEHICLES for q in users if end <= q.start < owned.start):
        return tokens  # (another motor vehicle named before "his van": whose van is open)
    dropped.extend(w for w in tokens[p.start : end] if w.isalpha() and w not in DEFINITE | INDEFINITE)
    out = list(tokens)
    for q in reversed(users):
        if q.start >= end and q.det == owner and q.kind in VEHICLES and not placed_by_word(tokens, q):
            dropped.extend(w for w in out[q.start + 1 : q.end] if w.isalpha())
            out[q.start : q.end] = ["the", "ego"]
    out[p.start : end] = ["the", "ego"]
    out = as_ego(out, kind_at, known, tokens[owned.end - 1], dropped)
    return pronouns_as_ego(out, owner, kind_at, known)


def _person_driving(tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """ "A pensioner was driving his estate at 30 mph when ...", "A Leeds woman who struck a cyclist
    while driving at 45 mph ...", "A farmer, 60, was driving along the lane": a person named by a
    noun of a person, the subject opening its clause, whose own verb (or relative clause) is one of
    driving, is at a wheel: that person is the ego, no walker, and so are the vehicle driven and the
    person's pronouns. "A woman was hit by a man driving a van" (no subject) or "a man walking his
    dog" (no driving) reads nothing."""
    for p in road_users(tokens, kind_at, known):
        start = next((b for b in (p.start - 1, p.start - 2) if b >= 0 and tokens[b] in ("a", "an", "the")), p.start)
        if p.det or not all(w.isalpha() for w in tokens[start : p.start]):
            start = p.start  # (its article and a word of where it is from: "a Leeds woman")
        if p.kind != "pedestrian" or (start and tokens[start - 1] not in CLAUSE_OPENING | {"that"}):
            continue
        k = _past_apposition(tokens, p.end)
        if tokens[k : k + 1] == ["who"]:  # (its relative clause, up to where it closes)
            k += 1
            _, e = sentence_span(tokens, k)
            e = next((c for c in range(k, e) if tokens[c] == ","), e)
            at = next(  # (its own driving: "who was driving", "who hit ... while driving", not "a van driving")
                (j for j in range(k, e) if tokens[j] in DRIVING and tokens[j - 1] in SUBORDINATORS | BE | {"who"}),
                None,
            )
        else:
            while k < len(tokens) and tokens[k] in BETWEEN:
                k += 1
            at = k if tokens[k : k + 1] and tokens[k] in DRIVING else None
        if at is None:
            continue
        noun = tokens[p.end - 1]
        owner = next((g for g, nouns in GENDERED.items() if noun in nouns), None)
        driven = next((q for q in road_users(tokens, kind_at, known) if at < q.start <= at + 4), None)
        out = list(tokens)
        if driven is not None and driven.kind in VEHICLES and out[at + 1] in OWNING | {"a", "an"}:
            owner = owner or (out[at + 1] if out[at + 1] in PRONOUNS_OF else None)
            dropped.extend(w for w in out[driven.start : driven.end] if w.isalpha() and w not in OWNING)
            out[driven.start : driven.end] = []
            out = as_ego(out, kind_at, known, tokens[driven.end - 1], dropped)
        dropped.extend(w for w in out[start : p.end] if w.isalpha() and w not in DEFINITE | INDEFINITE)
        out[start : p.end] = ["the", "ego"]
        return pronouns_as_ego(out, owner, kind_at, known) if owner else out
    return tokens


def _past_apposition(tokens: list[str], k: int) -> int:
    """Past an age or a short aside after a name (", 52,", ", a retired teacher,"): where its clause
    goes on, else ``k``."""
    if tokens[k : k + 1] != [","]:
        return k
    close = next((c for c in range(k + 1, min(k + 6, len(tokens))) if tokens[c] == ","), None)
    return close + 1 if close is not None else k


def _operator_fleet(tokens: list[str], kind_at: KindAt, known: Known) -> list[str]:
    """ "when two of our scooters came on from the next arm", "a van pulled out in front of our rider":
    where the only first-person word is "our" and each stands right before a walker or rider (a hire
    scheme's scooters, its riders), the writer is the operator, not in the scene: "our" is said
    "the", so the report is read in the third person. "our van", "our driver" (a vehicle or its
    driver) or any "I", "we", "me", "my" keeps the writer in the scene."""
    first = [k for k, w in enumerate(tokens) if w in FIRST_PERSON | NARRATOR_INVOLVED - {"ego"}]
    if not first or any(tokens[k] != "our" for k in first):
        return tokens
    users = {p.start: p for p in road_users(tokens, kind_at, known)}
    starts = {p.head: p for p in users.values()}
    for k in first:
        p = users.get(k) or users.get(k + 1) or starts.get(k + 1)
        if p is None or p.kind in VEHICLES | {"ego"} or tokens[p.end - 1] in AT_WHEEL:
            return tokens
    return ["the" if k in first else w for k, w in enumerate(tokens)]


def _labelled_driver(tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """ "Unit 7. Driver was doing 40 mph ...", "Vehicle: Cab 22 ... Driver braked hard": a log that names
    one vehicle by its label and then speaks of a bare "Driver" (no article, opening its clause, not
    "Driver of ...") speaks of that vehicle's own driver: the label, that driver and every later "the
    <noun>" of it are the ego, so the driver's speed is the ego's. With two labels ("Car 1 ... Car 2"),
    whose driver it is stays open; "a bus driver" or "the driver" is someone named otherwise."""
    from vei_scenario.language.discourse import label_noun_again, vehicle_labels

    labels = vehicle_labels(tokens, kind_at, known)
    if len({(n, m) for _, n, m in labels}) != 1:
        return tokens
    first, noun, mark = labels[0]
    bare = [
        k
        for k, w in enumerate(tokens)
        if w == "driver"
        and k > first + 1
        and tokens[k - 1] in CLAUSE_OPENING
        and tokens[k + 1 : k + 2] not in (["of"], [":"])
    ]
    if not bare:
        return tokens
    out = list(tokens)
    for k in reversed(bare):
        out[k : k + 1] = ["the", "ego"]
    dropped.extend(["driver"] * len(bare) + [noun, mark])
    out = label_noun_again(_label_as_ego(out, [noun, mark]), (noun, mark), [(noun, mark)])  # ("unit speed 54 mph")
    return as_ego(out, kind_at, known, noun, dropped)


def _role(tokens: list[str], kind_at: KindAt, named: frozenset[str] = LEARNER | PARTY) -> list[str]:
    """A person named by the role a driving lesson or a claim gives them ("Pupil approached the
    roundabout at 20 mph", "the policyholder was travelling"): a learner in a sentence that gives a
    road speed or who does what only a driver does ("Pupil eased off"), or a party to a claim, is the
    ego (each mention not introduced with "a"), unless what it does is a walker's ("we were doing 30
    km/h when the pupil ran out"). ``named``: the roles looked for."""
    out = list(tokens)
    roles = _reporters(tokens) if named & PARTY else set()
    for i, w in enumerate(tokens):
        if w not in named or (i and tokens[i - 1] in INDEFINITE):
            continue
        s, e = i, i
        while s > 0 and tokens[s - 1] not in SENTENCE_END:
            s -= 1
        while e < len(tokens) and tokens[e] not in SENTENCE_END:
            e += 1
        if _verb_after(tokens, i + 1, _ON_FOOT):
            continue  # (a pupil who runs out is a walker)
        if w in PARTY or any(u in SPEED_UNITS for u in tokens[s:e]) or _verb_after(tokens, i + 1, _AT_THE_CONTROLS):
            roles.add(w)
    if not roles:
        return tokens
    said: list[str] = []
    for i, w in enumerate(out):
        if w in roles and not (i and out[i - 1] in INDEFINITE):
            if said and said[-1] in DEFINITE | {"my", "our"}:
                said.pop()
            said += ["the", "ego"]
            continue
        said.append(w)
    return said


#: Verbs (lemmas) only the one at a vehicle's controls does: a learner who does one drives ("Pupil
#: eased off to about 30", "the candidate indicated and emerged"). Not "slow", "stop" or "pull", which a
#: pupil on foot does too.
_AT_THE_CONTROLS = frozenset(
    {"brake", "accelerate", "indicate", "signal", "steer", "overtake", "reverse", "stall", "park", "drive",
     "emerge", "merge", "ease", "decelerate"}
)  # fmt: skip


#: Verbs (lemmas) of a walker: a learner who does one is on foot.
_ON_FOOT = frozenset({"run", "walk", "step", "cross", "dash", "jog", "dart", "wander", "stroll", "hurry"})


def _verb_after(tokens: list[str], k: int, verbs: frozenset[str]) -> bool:
    """Whether the verb after the subject ending before ``k``, past its auxiliaries and adverbs ("had
    already", "then"), is one of ``verbs`` in a finite form ("braked", "had eased")."""
    while k < len(tokens) and (tokens[k] in BETWEEN or tokens[k] in ("already", "then", "quickly", "late")):
        k += 1
    if k >= len(tokens) or tokens[k].endswith("ing"):
        return False
    return bool(set(lemmas(tokens[k]).get("VERB", ())) & verbs)


def _reporters(tokens: list[str]) -> set[str]:
    """The roles of the person a third-person report is taken from ("Cust (Mr Patel) states he was
    driving", "RP following at approx 10 mph", "Caller was on the bypass"), each said at least once as
    a subject, right before a verb, an aggregate or a bracket. A text with a narrator of its own
    ("Customer service sent me a voucher") is told by that narrator; a role said with "a" or as a
    noun's modifier ("a caller", "customer service") is no subject."""
    if (FIRST_PERSON | NARRATOR_INVOLVED) & set(tokens):
        return set()
    found = set()
    for i, w in enumerate(tokens[:-1]):
        if w not in REPORTER or (i and tokens[i - 1] in INDEFINITE):
            continue
        nxt = tokens[i + 1]
        if nxt in ("(", ",") or {"VERB", "AUX"} & set(lemmas(nxt)) and "NOUN" not in lemmas(nxt):
            found.add(w)
        elif nxt.endswith("s") and "VERB" in lemmas(nxt) and i + 2 < len(tokens) and tokens[i + 2] not in PUNCT:
            found.add(w)  # ("RP states 3 subjects ...": a verb's third person, not a plural noun at a stop)
    return found


def _relative_own(tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """ "the bus I was driving", "the taxi we were in", "the van that I drive", "the e-scooter I
    rented", "the car we'd borrowed": a vehicle that a first-person relative clause puts the narrator
    in, at the wheel of, or in possession of is the narrator's, the ego ("the van I saw" is not)."""
    if not FIRST_PERSON & set(tokens):
        return tokens
    for p in road_users(tokens, kind_at, known):
        if p.kind not in RIDDEN:
            continue
        k = p.end + (tokens[p.end : p.end + 1] in (["that"], ["which"]))
        if tokens[k : k + 1] not in (["i"], ["we"]):
            continue
        k += 1
        while k < len(tokens) and tokens[k] in BETWEEN:
            k += 1
        verb = tokens[k] if k < len(tokens) else ""
        if verb not in DRIVING | {"in", "aboard"} and not lemma_in(verb, AT_CONTROLS | POSSESSING):
            continue
        end = k + 1
        noun = tokens[p.end - 1]
        dropped.extend(tokens[p.start : end])
        out = [*tokens[: p.start], "the", "ego", *tokens[end:]]
        return as_ego(out, kind_at, known, noun, dropped)
    return tokens


def _boarded(tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """ "I got back in the van", "we climbed into a minibus": what the narrator gets into is the
    narrator's vehicle, the ego (and so is every later "the van")."""
    if not (FIRST_PERSON | NARRATOR_INVOLVED) & set(tokens):
        return tokens
    for k, w in enumerate(tokens):
        if not lemma_in(w, BOARDING) or w in BE:
            continue
        s = k - 1
        while s >= 0 and tokens[s] in BETWEEN:
            s -= 1
        if s >= 0 and tokens[s] not in FIRST_PERSON | {",", "and"}:
            continue  # (someone else's verb: "the cyclist got in front")
        j = k + 1 + (k + 1 < len(tokens) and tokens[k + 1] in ("back", "straight"))
        if tokens[j : j + 1] not in (["in"], ["into"]):
            continue
        p = next((q for q in _vehicle_phrases(tokens, kind_at, known) if q.start == j + 1), None)
        if p is None or placed_by_word(tokens, p) or p.det not in DEFINITE | INDEFINITE | {""}:
            continue
        noun = tokens[p.end - 1]
        dropped.extend(tokens[p.start : p.end])
        out = [*tokens[: p.start], "the", "ego", *tokens[p.end :]]
        return as_ego(out, kind_at, known, noun, dropped)
    return tokens


def _one_vehicle(tokens: list[str], kind_at: KindAt, known: Known) -> tuple[str, list] | None:
    """The one vehicle a text names (its head noun and mentions), when it names one and another road
    user: not placed relative to someone ("the car ahead", "parked vans")."""
    phrases = [p for p in road_users(tokens, kind_at, known) if not _at_wheel(tokens, p) and p.kind != "ego"]
    vehicles = [p for p in phrases if p.kind in VEHICLES]
    if not vehicles or len(vehicles) == len(phrases):
        return None
    groups = _referents(tokens, vehicles)
    if len(groups) != 1 or None in groups.values() or any(placed_by_word(tokens, p) for p in vehicles):
        return None
    return next(iter(groups.items()))


def _struck(tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """A report in the third person of one vehicle that strikes a walker or rider ("a woman riding an
    e-scooter was struck by a car"; "the car hit the scooter"): that vehicle is the one the report
    is told from, the ego."""
    if not any(lemma_in(w, CONTACT) for w in tokens):
        return tokens
    one = _one_vehicle(tokens, kind_at, known)
    if one is None:
        return tokens
    from vei_scenario.language.discourse import hits_someone

    noun, mentions = one
    for k, w in enumerate(tokens):
        if not lemma_in(w, CONTACT):
            continue
        j = k + 1 + (tokens[k + 1 : k + 2] in (["down"], ["over"], ["off"]))
        if tokens[j : j + 1] != ["by"] and not hits_someone(tokens, k, kind_at):
            continue  # ("hit the brakes")
        s, e = k, k
        while s > 0 and tokens[s - 1] not in SENTENCE_END:
            s -= 1
        while e < len(tokens) and tokens[e] not in SENTENCE_END:
            e += 1
        if any(s <= p.start < e for p in mentions):  # ("struck by a car", "the van ... hit the man")
            return as_ego(tokens, kind_at, known, noun, dropped, only=True)
    return tokens


#: Words that may open the clause a told-from vehicle is the subject of (a field or heading before it:
#: "Near miss - prime mover turning", "7:15 am, ute doing 45 km/h").
CLAUSE_OPENING = PUNCT | {"-", "and"}


def sentence_span(tokens: list[str], i: int) -> tuple[int, int]:
    s, e = i, i
    while s > 0 and tokens[s - 1] not in SENTENCE_END:
        s -= 1
    while e < len(tokens) and tokens[e] not in SENTENCE_END:
        e += 1
    return s, e


def _own_speed(tokens: list[str], p, users) -> bool:
    """Whether the mention ``p`` opens its clause and a speed follows it there before anyone else is
    named ("ute doing 45 km/h", "Tanker was doing 50 km/h", "van turning L ... at approx 10 mph")."""
    start = p.start
    if start >= 2 and tokens[start - 1] == "'s" and tokens[start - 2].isalpha():  # ("Grandad's Volvo")
        start -= 2
        start -= start > 0 and tokens[start - 1] in DEFINITE
    for _ in range(2):  # (past its modifiers: "tipper truck", "company hatchback", "pool car")
        w = tokens[start - 1] if start else ""
        if w.isalpha() and w not in BE | PRONOUNS | FIRST_PERSON | NARRATOR_INVOLVED | DEFINITE | INDEFINITE:
            if not lemmas(w) or {"NOUN", "ADJ"} & set(lemmas(w)):
                start -= 1
    if start and tokens[start - 1] not in CLAUSE_OPENING:
        return False
    _, e = sentence_span(tokens, p.end)
    e = next((k for k in range(p.end, e) if tokens[k] == ","), e)  # (its clause: "Lead van brakes, 70 km/h")
    nxt = min((q.start for q in users if q.start >= p.end), default=e)
    return any(w in SPEED_UNITS for w in tokens[p.end : min(e, nxt)])


def _told_from(tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """A report told from a vehicle it never calls the ego ("Ute travelling at 60 km/h ...", "Pool car
    entering a roundabout at 20 km/h ... our driver had to stop", "Driver was sitting on 100 km/h"):
    the first vehicle named (before any mention of the ego), bare or with "the" and never with "a",
    not placed relative to someone, that opens a clause with its own speed in a sentence with no
    narrator in it, is the ego, and so is every later "the <noun>". A vehicle that meets the narrator
    in its sentence ("Bus pulled out in front of us") or any vehicle where the narrator or the ego
    has a speed of its own, is someone else."""
    from vei_scenario.language.discourse import is_singular, vehicle_labels

    if vehicle_labels(tokens, kind_at, known):
        return tokens  # (a report's labels say who the ego is: "Vehicle A was travelling ...")
    users = road_users(tokens, kind_at, known)
    first = next((p for p in users if p.kind in VEHICLES | {"ego"} and not _at_wheel(tokens, p)), None)
    if first is None or first.kind == "ego" or first.det not in ("", "the") or placed_by_word(tokens, first):
        return tokens
    owner = first.start >= 2 and tokens[first.start - 1] == "'s" and kind_at(tokens, first.start - 2) is None
    narrator = FIRST_PERSON | NARRATOR_INVOLVED
    for k, w in enumerate(tokens):  # (a narrator or an ego with a speed of its own is the ego)
        if w in narrator or w in {"ego", "host"}:
            s, e = sentence_span(tokens, k)
            if any(u in SPEED_UNITS for u in tokens[k:e]) and not any(k < q.start < e for q in users):
                return tokens
    noun = tokens[first.end - 1]
    mentions = _referents(tokens, [p for p in users if p.kind in VEHICLES]).get(noun)
    if not mentions or not any(p.det in ("", "the") and _own_speed(tokens, p, users) for p in mentions):
        return tokens
    if not is_singular(noun) or (first.start and tokens[first.start - 1] in ("both", "two", "all")):
        return tokens
    for p in mentions:  # (one that meets the narrator or the ego in its sentence is someone else)
        s, e = sentence_span(tokens, p.start)
        if narrator & set(tokens[s:e]) or any(q.kind == "ego" and s <= q.start < e for q in users):
            return tokens
    out = list(tokens)
    if owner:  # ("Grandad's Volvo": the owner's words go with it)
        start = first.start - 2 - (first.start > 2 and tokens[first.start - 3] in DEFINITE)
        dropped.extend(w for w in tokens[start : first.start] if w.isalpha() and w not in DEFINITE)
        out[start : first.start] = []
    out = as_ego(out, kind_at, known, noun, dropped)
    return driver_is_ego(out, kind_at, known, dropped)


def is_modifier_noun(tokens: list[str], p) -> bool:
    """Whether the noun after ``p`` makes it a modifier ("car park", "bus lane"), no vehicle."""
    w = tokens[p.end] if p.end < len(tokens) else ""
    return w.isalpha() and set(lemmas(w)) == {"NOUN"}


def _ego_aboard(tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """ "our driver was entering a roundabout in the Hilux", "I was heading home in my cab", "we came
    through in the minibus": a vehicle the ego's subject is in, in its own clause, is the ego's
    vehicle, the ego; so is every later "the <noun>", and "the driver" (no other motor vehicle named
    before it)."""
    users = road_users(tokens, kind_at, known)
    for k, w in enumerate(tokens):
        at = k - 1 if k and tokens[k - 1] == "the" else k  # (the subject's first word: "the ego")
        said = k + 1 < len(tokens) and tokens[k + 1] in BE  # (its verb follows: "Ref 2231 our driver was ...")
        if w not in ("ego", "i", "we") or (at and tokens[at - 1] not in CLAUSE_OPENING and not said):
            continue  # (not the subject: "a man alongside the ego in a lorry" is the man's lorry)
        _, e = sentence_span(tokens, k)
        nxt = next((q for q in users if q.start > k), None)
        if (
            nxt is None
            or nxt.start >= e
            or nxt.kind not in VEHICLES
            or placed_by_word(tokens, nxt)
            or is_modifier_noun(tokens, nxt)
        ):
            continue
        if tokens[nxt.start - 1] not in ("in", "inside", "aboard") or nxt.det not in {"", "a", "an"} | DEFINITE:
            continue
        if any(t in PUNCT for t in tokens[k : nxt.start]) or (w != "ego" and nxt.det in INDEFINITE):
            continue  # ("we were in a hire car, a Fiat": discourse reads the narrator's vehicle and its name)
        from vei_scenario.language.discourse import apposition_end

        noun = tokens[nxt.end - 1]
        end = apposition_end(tokens, nxt.end, kind_at, known) or nxt.end  # ("in the van, an old Ford,")
        dropped.extend(x for x in tokens[nxt.start - 1 : end] if x.isalpha())
        out = [*tokens[: nxt.start - 1], *tokens[end:]]
        out = kind_said_again(as_ego(out, kind_at, known, noun, dropped), nxt.kind, kind_at, known, dropped)
        return driver_is_ego(out, kind_at, known, dropped)
    return tokens


def kind_said_again(tokens: list[str], kind: str, kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """ "in the Transit ... in front of the van", "in the Hilux ... behind the pickup": once a vehicle
    named by its make, model or any noun is the ego, a later "the <noun>" of the same kind (another
    noun) is it again, where the text introduces no vehicle of that kind ("a van") and that one is
    not placed relative to someone ("the van ahead") nor a modifier ("the van driver"). One that opens
    its clause or meets the narrator there ("when the van pulled out at us") may be someone new."""
    users = road_users(tokens, kind_at, known)
    if any(q.kind == kind and q.det in INDEFINITE for q in users):
        return tokens
    first = next((q.start for q in users if q.kind == "ego"), None)
    out = list(tokens)
    for q in reversed(users):
        if first is None or q.start < first or q.kind != kind or q.det != "the":
            continue
        if (
            placed_by_word(out, q)
            or is_modifier_noun(out, q)
            or out[q.end : q.end + 1] in (["'s"], ["of"])
            or _at_wheel(out, q)
        ):
            continue
        if not q.start or out[q.start - 1] in CLAUSE_OPENING | SENTENCE_END | SUBORDINATORS | {"but", "then"}:
            continue  # (the subject of its own clause: "when the van pulled out" may be someone new)
        bounds = CLAUSE_OPENING | SENTENCE_END | SUBORDINATORS | {"but", "then", "so"}
        s = next((j + 1 for j in range(q.start - 1, -1, -1) if out[j] in bounds), 0)
        e = next((j for j in range(q.end, len(out)) if out[j] in bounds), len(out))
        if {"me", "us", "my", "our"} & set(out[s:e]):
            continue  # (it meets the narrator in its clause: "the van came at us")
        dropped.extend(w for w in out[q.start : q.end] if w not in DEFINITE)
        out[q.start : q.end] = ["the", "ego"]
    return out


#: Nouns that name the ego again once it is the vehicle a report is told from, while no other motor
#: vehicle has been named: its driver ("the driver", "Driver braked") and a general vehicle noun
#: ("in front of the vehicle", "behind the car").
SAID_AGAIN = {"driver": ("", "the"), "vehicle": ("the",), "car": ("the",)}


def driver_is_ego(tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """Once the ego is the vehicle a report is told from, "the driver" (or "driver") is its driver
    and "the vehicle" is it, until another motor vehicle is named: a walker or rider has no driver."""
    out = list(tokens)
    for p in reversed(road_users(out, kind_at, known)):
        noun = out[p.end - 1]
        if p.det not in SAID_AGAIN.get(noun, ()) or p.end - p.head != 1 or out[p.end : p.end + 1] == ["of"]:
            continue
        if (p.start and out[p.start - 1] == "'s") or placed_by_word(out, p):
            continue
        before = [
            q
            for q in road_users(out[: p.start], kind_at, known)
            if q.kind in VEHICLES and q.det not in SAID_AGAIN.get(out[q.end - 1], ()) and not placed_by_word(out, q)
        ]
        if before:
            continue
        dropped.extend(w for w in out[p.start : p.end] if w not in DEFINITE)
        out[p.start : p.end] = ["the", "ego"]
    return out


#: Verbs that give someone's account ("Driver states ...", "motorist reports ..."), a closed class.
REPORTS = frozenset(
    {"say", "state", "report", "claim", "tell", "explain", "allege", "estimate", "recall", "insist", "admit"}
)
#: Pronouns of the one whose account is given, as they stand in it: subject, object, possessive.
ACCOUNT_SUBJECT = frozenset({"they", "he", "she"})
ACCOUNT_OBJECT = frozenset({"them", "him"})
ACCOUNT_POSSESSIVE = frozenset({"their", "his"})
#: First-person words of a narrator at a wheel, whose story it is (a "we" of an operator is not one).
NARRATOR = frozenset({"i", "me", "my", "myself"})


def _reporter_at(tokens: list[str], k: int, kind_at: KindAt) -> tuple[int, str | None] | None:
    """Where the person at a wheel whose account the verb at ``k`` gives starts ("car driver", "the
    driver of a car", "Motorist", opening its clause), and the noun of that person's vehicle if said;
    None where the verb's subject is no such person."""
    j = k - 1
    while j >= 0 and tokens[j] in {"has", "had", "also", "later", "then"}:
        j -= 1
    vehicle = None
    if j >= 3 and tokens[j - 2] == "of" and (found := kind_at(tokens, j)) is not None and found[0] in VEHICLES:
        vehicle, j = tokens[j], j - 3 + (tokens[j - 1] not in DEFINITE | INDEFINITE)  # ("driver of a car")
    if j < 0 or tokens[j] not in AT_WHEEL:
        return None
    start = j
    if vehicle is None and start and (found := kind_at(tokens, start - 1)) is not None and found[0] in VEHICLES:
        vehicle, start = tokens[start - 1], start - 1  # ("car driver", "the cab driver")
    start -= start > 0 and tokens[start - 1] in DEFINITE | INDEFINITE
    return (start, vehicle) if not start or tokens[start - 1] in CLAUSE_OPENING else None


def _reported(tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """A report that gives the account of a person at a wheel ("Car driver says one of our scooters
    ...", "Driver states they were turning right at 15 mph", "the driver of a van reports that ..."):
    that person is the one the report is told from, the ego, and so are the pronouns that stand for
    them in the account (the subject right after the verb of saying: "says they were"; "them", "his"
    where the account's other road user acts on them: "in front of them"), every later bare or
    "the" mention of that person ("Driver braked") and their vehicle ("the car"). A text told by
    an "I" is that narrator's, whatever another driver says."""
    named = [p for p in road_users(tokens, kind_at, known) if p.kind == "ego" and tokens[p.start] not in ("us", "we")]
    if NARRATOR & set(tokens) or named:  # ("tells us": an operator's "we" only hears the account)
        return tokens
    at = next(
        (
            (k, found)
            for k, w in enumerate(tokens)
            if lemma_in(w, REPORTS) and (found := _reporter_at(tokens, k, kind_at))
        ),
        None,
    )
    if at is None:
        return tokens
    k, (start, vehicle) = at
    person = tokens[k - 1] if tokens[k - 1] in AT_WHEEL else next(w for w in tokens[start:k] if w in AT_WHEEL)
    dropped.extend(w for w in tokens[start:k] if w.isalpha() and w not in DEFINITE | INDEFINITE)
    out = [*tokens[:start], "the", "ego", *tokens[k:]]
    said: list[str] = []
    for i, w in enumerate(out):  # (the same person said again, bare or with "the")
        if w == person and (not i or out[i - 1] in CLAUSE_OPENING | {"the"}) and out[i + 1 : i + 2] != ["of"]:
            if said and said[-1] == "the":
                said.pop()
            said += ["the", "ego"]
            continue
        said.append(w)
    out = said
    for i in range(len(out) - 1, -1, -1):  # (the account's pronouns, in each sentence the ego tells)
        s, e = sentence_span(out, i)
        if out[i] not in ACCOUNT_SUBJECT | ACCOUNT_OBJECT | ACCOUNT_POSSESSIVE | {"her"} or out[s : s + 2] != [
            "the",
            "ego",
        ]:
            continue
        if not any(lemma_in(w, REPORTS) for w in out[s:i]):
            continue
        before = out[i - 1] if out[i - 1] != "that" else out[i - 2]
        nxt = out[i + 1] if i + 1 < len(out) else ""
        possessive = out[i] in ACCOUNT_POSSESSIVE or (out[i] == "her" and nxt.isalpha() and "NOUN" in lemmas(nxt))
        if out[i] in ACCOUNT_SUBJECT and not lemma_in(before, REPORTS):
            continue  # (a "he" of its own: the account's other road user)
        out[i : i + 1] = ["the", "ego", "'s"] if possessive else ["the", "ego"]
    if vehicle is not None:
        out = as_ego(out, kind_at, known, vehicle, dropped)
    return driver_is_ego(out, kind_at, known, dropped)


def _fleet_member(tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """ "Last week one of our vans was doing 30 mph ...", "One of our buses was pulling away ...": one
    vehicle of the writer's fleet, the subject of its clause, is the one the story follows, the ego
    (so are its later "the van" and "the driver"); said inside someone's account ("a cyclist says one
    of our vans pulled out") it is another road user, as a fleet said in the plural always is."""
    if NARRATOR & set(tokens) or any(p.kind == "ego" for p in road_users(tokens, kind_at, known)):
        return tokens
    for k in range(len(tokens) - 3):
        if tokens[k : k + 3] != ["one", "of", "our"]:
            continue
        p = next((q for q in _vehicle_phrases(tokens, kind_at, known) if k + 2 <= q.start <= k + 5), None)
        if p is not None and any(kind_at(tokens, j) is not None for j in range(k + 3, p.start)):
            p = None  # (past its modifiers only: "one of our 7.5-tonners")
        if p is None or p.end >= len(tokens) or not (tokens[p.end] in BE or "VERB" in lemmas(tokens[p.end])):
            continue
        s, _ = sentence_span(tokens, k)
        if any(lemma_in(w, REPORTS) for w in tokens[s:k]):
            continue  # (someone's account of our vehicle)
        plural = tokens[p.end - 1]
        noun = next(iter(lemmas(plural).get("NOUN", (plural,))))
        dropped.extend(w for w in tokens[k : p.end] if w.isalpha())
        out = [*tokens[:k], "the", "ego", *tokens[p.end :]]
        return driver_is_ego(as_ego(out, kind_at, known, noun, dropped), kind_at, known, dropped)
    return tokens


#: Words between "driving" and the vehicle driven ("driving her own car", "riding his works van").
OWNING = DEFINITE | INDEFINITE | {"his", "her", "their", "its", "own", "my", "our"}
#: Verbs whose object is the vehicle their subject is at the wheel or on the saddle of (by lemma).
AT_CONTROLS = frozenset({"drive", "ride"})
#: Adverbs of habit between a narrator and the verb ("I usually drive a tipper", "we still ride").
#: Verbs of having a vehicle to use (by lemma): what the narrator rents or owns is the narrator's.
POSSESSING = frozenset({"rent", "hire", "borrow", "own", "lease", "buy", "have"})
#: What can be driven or ridden: the object of such a verb is the vehicle, whatever its kind.
RIDDEN = VEHICLES | {"bicycle", "e-scooter"}
HABIT = frozenset({"usually", "normally", "always", "often", "mostly", "generally", "still", "now", "only"})


def narrator_subject(tokens: list[str], k: int) -> bool:
    """Whether the verb at ``k`` has a first-person subject ("I was driving", "we usually ride")."""
    f = k - 1
    while f >= 0 and (tokens[f] in BETWEEN or tokens[f] in HABIT):
        f -= 1
    return f >= 0 and tokens[f] in FIRST_PERSON | YOU


def _driving_ego(tokens: list[str], k: int) -> bool:
    """Whether the driving word at ``k`` is said of "the ego": right after it ("the ego was driving",
    "the ego, driving") or inside brackets that follow it ("Insured (Mr Jones, driving his van)"), or
    of a first-person narrator, its subject ("I was driving a pickup", "we usually drive a minibus")."""
    j = k - 1
    while j >= 0 and (tokens[j] in BETWEEN or tokens[j] == ","):
        j -= 1
    if j >= 1 and tokens[j - 1 : j + 1] == ["the", "ego"]:
        return True
    if narrator_subject(tokens, k):
        return True
    opening = next((b for b in range(k - 1, max(k - 12, -1), -1) if tokens[b] in ("(", ")")), None)
    return opening is not None and tokens[opening] == "(" and tokens[opening - 2 : opening] == ["the", "ego"]


def _owner_word(tokens: list[str], j: int) -> bool:
    """Whether token ``j`` names the owner of the vehicle after it ("my dad 's Corolla", "the
    company 's van"): a possessive "'s" or the word it follows. The vehicle is still the one driven."""
    return tokens[j] == "'s" or (tokens[j].isalpha() and tokens[j + 1 : j + 2] == ["'s"])


def _ego_drives(tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """ "The insured was driving a Ford Fiesta", "Claimant, driving her own Micra,", "Insured (Mr
    Jones, driving his works van)": the vehicle the ego drives or rides is its own, no road user; it
    goes (the verb stays, with the speed it may carry) and every later "the <noun>" is the ego."""
    if "ego" not in tokens and not (FIRST_PERSON | YOU) & set(tokens):
        return tokens
    for k, w in enumerate(tokens):
        driving = w in DRIVING | {"riding", "rode", "ridden"} or lemma_in(w, AT_CONTROLS)
        if not driving or not _driving_ego(tokens, k):
            continue
        p = next((q for q in road_users(tokens, kind_at, known) if k < q.start <= k + 4), None)
        kinds = RIDDEN if narrator_subject(tokens, k) else VEHICLES  # (a walker or rider is no one's vehicle)
        if p is None or p.kind not in kinds:
            continue
        if SUBORDINATORS & set(tokens[k + 1 : p.start]):
            continue  # ("I was driving when a cyclist overtook me": a clause of its own, no vehicle driven)
        if any(not (x in OWNING or _owner_word(tokens, j) or (x.isalpha() and not known(tokens, j))) for j, x in
               enumerate(tokens[k + 1 : p.start], k + 1)):  # fmt: skip
            continue
        noun, end = tokens[p.end - 1], p.end
        model = next((j for j in range(p.end, min(p.end + 3, len(tokens))) if tokens[j] in PUNCT | {")"}), None)
        if model is not None and all(
            x.isalnum() and not known(tokens, j) for j, x in enumerate(tokens[end:model], end)
        ):
            end = model  # (its model's name, up to where the phrase ends: "her own Honda Jazz,")
        dropped.extend(x for x in tokens[k + 1 : end] if x.isalpha() and x not in OWNING)
        out = as_ego([*tokens[: k + 1], *tokens[end:]], kind_at, known, noun, dropped)
        if "ego" not in tokens:  # (a narrator's story: "the driver" is someone else's)
            return out
        return driver_is_ego(out, kind_at, known, dropped)
    return tokens


def _narrator_in(tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """ "Doing 30 mph in the van down Corporation St ...", "Was heading home in the minibus ...", "let me
    through in the van": in a text told in the first person, "in the/my <vehicle>" (not placed: "in
    the van ahead") after a clause that opens with a participle and no subject, or right after "me",
    is the vehicle the narrator is in, the ego (so is every later "the van")."""
    if not (FIRST_PERSON | NARRATOR_INVOLVED) & set(tokens):
        return tokens
    users = road_users(tokens, kind_at, known)
    for p in _vehicle_phrases(tokens, kind_at, known):
        if p.start < 2 or tokens[p.start - 1] != "in" or p.det not in ("the", "my", "our") or placed_by_word(tokens, p):
            continue
        s, _ = sentence_span(tokens, p.start)
        while s < p.start - 2 and tokens[s] in BETWEEN:
            s += 1  # (its subject left out, its auxiliary said: "Was heading home in the ute")
        opening = tokens[s].endswith("ing") and "VERB" in lemmas(tokens[s]) and s < p.start - 1
        opening = opening and not any(s <= q.start < p.start for q in users)
        opening = opening and not any(t in PUNCT or t in FIRST_PERSON for t in tokens[s : p.start])
        after_me = bool({"me", "ego"} & set(tokens[max(p.start - 3, s) : p.start - 1]))
        if not (opening or after_me):
            continue
        noun = tokens[p.end - 1]
        dropped.extend(w for w in tokens[p.start - 1 : p.end] if w not in DEFINITE)
        out = [*tokens[: p.start - 1], *tokens[p.end :]]
        return as_ego(out, kind_at, known, noun, dropped)
    return tokens


def _story(tokens: list[str], kind_at: KindAt, known: Known) -> list[str]:
    """The sentences of ``tokens`` that tell the story: those that name a road user other than the ego
    or give a speed. A writer who says "I" or "you" only in the others ("Quick word before your
    shift", "Watch your mirrors") speaks in asides and is no road user of the story."""
    users = [p for p in road_users(tokens, kind_at, known) if p.kind != "ego"]
    out: list[str] = []
    k = 0
    while k < len(tokens):
        s, e = sentence_span(tokens, k)
        if any(s <= p.start < e for p in users) or any(w in SPEED_UNITS for w in tokens[s:e]):
            out += tokens[s : e + 1]
        k = e + 1
    return out


#: Words that make a vehicle the property of the writer's organisation ("the pool car", "our works
#: van", "the company minibus"), a small closed class.
ORGANISATION = frozenset({"fleet", "pool", "company", "works", "firm", "firm's", "company's"})


#: Verbs (lemmas) by which one of the narrator's party has a vehicle out ("Dad took the Volvo").
HAVING_OUT = frozenset({"take", "drive", "borrow", "have", "bring", "use"})
#: Possessives by which a narrator names one of their own party ("my dad", "your grandad", "our son").
PARTY_OWNERS = frozenset({"my", "our", "your"})
#: The party's words of each gender beyond :data:`GENDERED` ("my husband ... he braked").
PARTY_GENDERED = {
    "her": frozenset("wife missus mom mommy mummy mama mam grandma granny nan nana sister aunt auntie".split()),
    "his": frozenset("husband hubby daddy papa granddad grandpa brother uncle boyfriend grandson nephew".split()),
}


def _party_gender(word: str) -> str:
    """The possessive ("her", "his") of one of the narrator's party by what the narrator calls them
    ("my wife", "our son"), or "" where the word says no gender ("my partner", "our friend")."""
    return next((g for g in GENDERED if word in GENDERED[g] | PARTY_GENDERED[g]), "")


def _party_took(tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """ "My dad took the car into town. He was turning right ...", "your grandad had the Volvo out",
    "our son was driving my car": one of the narrator's party (a family word or a friend), opening its
    clause as the subject of a verb of having a vehicle out whose object is a vehicle named as known
    ("the", a possessive), has that vehicle as the ego: the story is told about it although the
    narrator's "my" keeps the text in the first person. "My dad took a taxi" (someone else's, new),
    "my mum had a bus pull out on her" or "my dad saw the car" read nothing."""
    for k, w in enumerate(tokens):
        if w not in FAMILY:
            continue
        s = k - (k > 0 and tokens[k - 1] in PARTY_OWNERS)
        if s and tokens[s - 1] not in CLAUSE_OPENING:
            continue
        j = k + 1
        while j < len(tokens) and tokens[j] in BETWEEN and tokens[j] not in ("had", "has", "have"):
            j += 1  # (an auxiliary, not "had" as the verb itself: "Mum had the car")
        if j >= len(tokens) or not HAVING_OUT & set(lemmas(tokens[j]).get("VERB", ())):
            continue
        if (
            tokens[j] in ("had", "has", "have")
            and j + 1 < len(tokens)
            and HAVING_OUT & set(lemmas(tokens[j + 1]).get("VERB", ()))
        ):
            j += 1  # ("had taken the car", "has borrowed my van")
        p = next((q for q in _vehicle_phrases(tokens, kind_at, known) if j < q.start <= j + 2), None)
        if p is None or p.kind not in VEHICLES or tokens[p.start] in INDEFINITE or placed_by_word(tokens, p):
            continue
        dropped.extend(x for x in tokens[p.start : p.end] if x.isalpha() and x not in OWNING)
        out = tokens[:s] + ["the", "ego"] + tokens[k + 1 : p.start] + tokens[p.end :]
        out = as_ego(out, kind_at, known, tokens[p.end - 1], dropped)
        at = s + 2 + (p.start - k - 1)
        for i in range(len(out) - 1, at - 1, -1):  # (the person named again: "Grandad's more shaken")
            if out[i] == w and out[i - 1] not in INDEFINITE:
                out[i - (out[i - 1] in PARTY_OWNERS | DEFINITE) : i + 1] = ["the", "ego"]
        owner = _party_gender(w)
        return pronouns_as_ego(out, owner, kind_at, known) if owner else out
    return tokens


#: Titles before a person's name ("Mrs Okafor's car", "Encik Azlan's taxi"): the name is a person's.
TITLES = frozenset({"mr", "mrs", "ms", "miss", "mx", "dr", "sir", "dame", "encik", "puan", "cik", "mdm", "madam"})
#: Words before a party word that make it someone else's ("his mum's car", "the boy's dad's van", "a
#: friend's car"): a determiner or another's possessive; a party word with none is called as a name.
_SOMEONE_ELSES = DEFINITE | INDEFINITE | frozenset({"his", "her", "their", "its", "'s", "whose", "which"})
#: The narrator as a road user of the story ("I", "me"), not only an owner ("my", "our").
NARRATOR_PERSON = frozenset({"i", "we", "me", "us", "myself", "ourselves"})


def _owner_phrase(tokens: list[str], p, kind_at: KindAt) -> tuple[int, str] | None:
    """(Where its owner's words start, the owner's pronoun possessive or "") for a vehicle named by a
    person who owns it: one of the narrator's party ("our son 's car", "my trainee 's van") or a name
    after a title ("Mrs Jean Hollis 's car"); None for any other vehicle ("the cyclist 's bike")."""
    if p.start < 2 or tokens[p.start - 1] != "'s" or p.det:
        return None
    o = p.start - 2
    if not tokens[o].isalpha() or kind_at(tokens, o) is not None:
        return None
    if o and tokens[o - 1] in PARTY_OWNERS:
        gender = _party_gender(tokens[o])
        return o - 1, gender
    if tokens[o] in FAMILY and not (o and tokens[o - 1] in _SOMEONE_ELSES):
        return o, _party_gender(tokens[o])  # ("Mum's hatchback", "Grandad's Volvo": the party named as a name)
    title = next((t for t in range(o - 1, max(o - 3, -1), -1) if tokens[t] in TITLES), None)
    if title is None or not all(w.isalpha() for w in tokens[title:o]):
        return None
    return title, "his" if tokens[title] in ("mr", "sir", "encik") else "her" if tokens[title] != "dr" else ""


def _owned_vehicle(tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """ "Our daughter's hatchback was clipped by a cyclist", "Mrs Okafor's car was struck by a lorry":
    where the narrator is no road user of the story (no "I", "we", "me", "us"; an owner's "my" or
    "our" only) and no ego is named, the first vehicle named by the person who owns it (see
    :func:`_owner_phrase`) is the vehicle the story happens to, the ego, and so are every later "the
    <noun>", its driver, the owner named again and their pronouns ("Our son was doing 25 mph", "she
    was pulling out"). A vehicle placed relative to someone or standing ("my neighbour's parked car",
    "Mr Tan's van was parked") stays as read, and so does every owned vehicle where the narrator is in
    the story ("I was behind Mr Tan's taxi")."""
    if NARRATOR_PERSON & set(tokens):
        return tokens
    written, tokens = tokens, _possessive_unmarked(tokens, kind_at)
    users = road_users(tokens, kind_at, known)
    if any(p.kind == "ego" for p in users) or len(users) < 2:
        return written

    for p in users:
        standing = p.kind not in VEHICLES or placed_by_word(tokens, p) or stands_parked(tokens, p)
        found = None if standing else _owner_phrase(tokens, p, kind_at)
        if found is None:
            continue
        start, gender = found
        owner = tokens[start : p.start - 1]
        noun = tokens[p.end - 1]
        dropped.extend(w for w in tokens[start : p.end] if w.isalpha() and w not in PARTY_OWNERS)
        out = [*tokens[:start], "the", "ego", *tokens[p.end :]]
        out = as_ego(out, kind_at, known, noun, dropped, owner=frozenset(owner))  # (not "Mr Tan's car")
        i = start + 2
        while i < len(out):  # (the owner named again: "Our son was going straight on")
            if out[i : i + len(owner)] == owner:
                out[i : i + len(owner)] = ["the", "ego"]
            i += 1
        out = driver_is_ego(out, kind_at, known, dropped)  # ("the driver waited": its driver)
        return pronouns_as_ego(out, gender, kind_at, known) if gender else out
    return written


def _possessive_unmarked(tokens: list[str], kind_at: KindAt) -> list[str]:
    """ "Dads car got rear-ended", "my sisters Fiesta": a family word ending in "s" right before a
    vehicle is its possessive with the apostrophe left out (a family word makes no compound with a
    vehicle noun), said "dad 's car" as :func:`_owner_phrase` reads an owner."""
    out: list[str] = []
    for k, w in enumerate(tokens):
        vehicle = kind_at(tokens, k + 1) if k + 1 < len(tokens) else None
        if w.endswith("s") and w[:-1] in FAMILY and vehicle is not None and vehicle[0] in VEHICLES:
            out += [w[:-1], "'s"]
            continue
        out.append(w)
    return out


def _organisation_vehicle(tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """ "the bus in front of the fleet car", "The works van was waiting at the lights", "our pool
    minibus": a vehicle the writer's organisation owns, said as known ("the", "our"), is the one a
    report is told from, the ego (and so is every later "the van"), the vehicle of a "we" or "I"
    telling it, where the text names no other ego. "A company van pulled out" (new) or "the fleet van
    ahead of me" (placed) is someone else's."""
    narrator = FIRST_PERSON | (NARRATOR_INVOLVED - {"ego"})
    if any(p.kind == "ego" and tokens[p.head] not in narrator for p in road_users(tokens, kind_at, known)):
        return tokens
    for p in _vehicle_phrases(tokens, kind_at, known):
        owned = [w for w in tokens[max(p.start - 1, 0) : p.head] if w in ORGANISATION]
        if not owned or p.det not in ("the", "our") or placed_by_word(tokens, p):
            continue
        noun = tokens[p.end - 1]
        dropped.extend(w for w in tokens[p.start : p.end] if w not in DEFINITE | {"our"})
        out = [*tokens[: p.start], "the", "ego", *tokens[p.end :]]
        return as_ego(out, kind_at, known, noun, dropped)
    return tokens


def frame(
    tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str], about: Framer | None = None
) -> list[str]:
    """``tokens`` framed (see :func:`_frame`), then "the driver" of an ego named by a role said the
    ego (see :func:`_role_driver`). ``about`` is the last resort for a report that names no ego
    (:func:`vei_scenario.language.protagonist.frame`, the vehicle the report is about); the caller
    passes it because that module builds on this one's phrases."""
    return _role_driver(_frame(tokens, kind_at, known, dropped, about), kind_at, known, dropped)


def _role_driver(tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """ "The test vehicle was moving ... A child ran out ... The driver swerved": where the ego is named
    by a role (not a narrator's pronoun), "the driver" said after it is the ego's driver until another
    motor vehicle is named, since walkers and riders have no driver (see :func:`driver_is_ego`)."""
    first = next((p for p in road_users(tokens, kind_at, known) if p.kind == "ego"), None)
    if first is None or any(w in FIRST_PERSON | NARRATOR_INVOLVED - {"ego"} for w in tokens):
        return tokens
    if any(p.kind in VEHICLES for p in road_users(tokens[: first.start], kind_at, known)):
        return tokens  # ("A lorry overtook the test vehicle. The driver ...": whose is unclear)
    from vei_scenario.language.discourse import apposition_end

    said = apposition_end(tokens, first.end, kind_at, known, most=5) or first.end  # (", a Skoda estate,")
    out = list(tokens)
    for p in reversed(road_users(out, kind_at, known)):
        if p.start < first.end or out[p.start : p.end] != ["the", "driver"] or out[p.end : p.end + 1] == ["of"]:
            continue
        if (p.start and out[p.start - 1] == "'s") or placed_by_word(out, p):
            continue
        users = road_users(out[: p.start], kind_at, known)
        if any(q.kind in VEHICLES and q.start >= said and out[q.start : q.end] != ["the", "driver"] for q in users):
            continue  # (a motor vehicle named before: the driver may be its)
        dropped.append("driver")
        out[p.start : p.end] = ["the", "ego"]
    return out


def _frame(
    tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str], about: Framer | None = None
) -> list[str]:
    """``tokens`` with the road user the text is told from said "the ego" where the text names it by
    a role, by its driver or in the third person (see the module's docstring); the words that only
    named it are added to ``dropped``. The reader runs it before :func:`discourse.resolve` (which this
    module's rules use the phrases of): before brackets go (an ego phrase in brackets marks the
    vehicle before it) and before riders are read (a named person at a wheel is the ego)."""
    tokens = _designated(tokens, kind_at, known, dropped)
    tokens = _met_by_narrator(tokens, kind_at, known)
    tokens = _marked(tokens, kind_at, known, dropped)
    tokens = _marked_person(tokens, kind_at, known, dropped)
    tokens = _relative_own(tokens, kind_at, known, dropped)
    tokens = _boarded(tokens, kind_at, known, dropped)
    tokens = _told_from(tokens, kind_at, known, dropped)
    tokens = _ego_aboard(tokens, kind_at, known, dropped)
    tokens = _narrator_in(tokens, kind_at, known, dropped)
    tokens = _organisation_vehicle(tokens, kind_at, known, dropped)
    tokens = _reported(tokens, kind_at, known, dropped)
    tokens = _fleet_member(tokens, kind_at, known, dropped)
    tokens = _ego_drives(tokens, kind_at, known, dropped)
    tokens = _party_took(tokens, kind_at, known, dropped)
    tokens = _owned_vehicle(tokens, kind_at, known, dropped)
    tokens = _operator_fleet(tokens, kind_at, known)
    if names_ego(tokens, kind_at, known):
        if names_ego(_story(tokens, kind_at, known), kind_at, known):
            return _role(tokens, kind_at, LEARNER)  # (the learner at the wheel of the car we are in)
        return _at_the_wheel(tokens, kind_at, known, dropped)  # (the writer only in asides)
    from vei_scenario.language.discourse import vehicle_labels

    tokens = _labelled_driver(tokens, kind_at, known, dropped)
    if names_ego(tokens, kind_at, known):
        return tokens
    if vehicle_labels(tokens, kind_at, known):
        return tokens  # (a report's labels say who the ego is)
    for third_person in (_at_the_wheel, _driving_subject, _news_driver, _followed_driver, _person_driving):
        tokens = third_person(tokens, kind_at, known, dropped)  # (the first that names the ego decides)
        if names_ego(tokens, kind_at, known):
            return tokens
    tokens = _role(tokens, kind_at)
    if names_ego(tokens, kind_at, known):
        return _ego_drives(tokens, kind_at, known, dropped)
    tokens = _struck(tokens, kind_at, known, dropped)
    if names_ego(tokens, kind_at, known):
        return tokens
    return tokens if about is None else about(tokens, kind_at, known, dropped)  # (the vehicle a report is about)
