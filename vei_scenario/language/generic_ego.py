"""Which road user is the ego when the text speaks of drivers in general.

Road-safety officers, site notes and hotspot reports tell a scenario without a narrator or a named
test vehicle: "a driver heading uphill at about 40 mph comes up behind a cyclist", "Drivers doing the
20 limit have very little time to react", "a child running out on the driver's left". The driver
spoken of in general is the one whose view the scenario takes, the ego. Where such a driver does
something *to* someone in traffic named just as generally ("cutting across a vehicle already in the
outer lane", "head-on towards traffic in lane 1", "into the path of through traffic"), the report is
about what happens to that someone: it is the ego, and the driver is the road user that threatens it.

:func:`frame` says that road user "the ego", as :func:`vei_scenario.language.ego.frame` does for an
ego named by a role; it reads only where the text names no ego otherwise (no "I", "we", "you", ego
phrase or vehicle label). It knows two small closed classes of nouns: the persons at a wheel in
general, and the words for anyone in traffic.
"""

from __future__ import annotations

from vei_scenario.language.discourse import Phrase
from vei_scenario.language.ego import (
    BE,
    DEFINITE,
    INDEFINITE,
    SENTENCE_END,
    VEHICLES,
    KindAt,
    Known,
    lemma_in,
    names_ego,
    placed_by_word,
    road_users,
    sentence_span,
)
from vei_scenario.language.lemmas import lemmas

#: Persons at a wheel, said in general ("a driver", "drivers", "motorists").
DRIVERS = frozenset({"driver", "drivers", "motorist", "motorists"})
#: Words for anyone in traffic, no road user of their own kind: what a generic driver does to one of
#: them happens to the ego.
ANYONE = frozenset({"vehicle", "vehicles", "traffic", "motorist", "motorists", "driver", "drivers"})
#: Words that put the narrator in the scene as the one spoken to ("the car in front of you").
SECOND_PERSON = frozenset({"you", "your", "yourself"})
#: Verbs of a narrator who only reports or sees what drivers go through ("we have had three reports",
#: "we regularly see children stepping out"): such a narrator is no road user.
REPORTING = frozenset({"see", "watch", "notice", "observe", "hear", "receive", "record", "log"})
#: Verbs that report only with an account as their object ("we have had three reports", "I get
#: complaints"), not with a road user ("I had a driver pull out"), and those accounts.
HAVING = frozenset({"have", "get"})
ACCOUNTS = frozenset({"report", "complaint", "incident", "case", "call", "collision", "claim"})
#: First-person words that put the narrator in the traffic ("in front of me", "our lane").
INVOLVED = frozenset({"me", "us", "my", "our", "ego", "myself", "ourselves"})
#: Words before a driver that place it relative to someone whose view it is ("behind a driver",
#: "overtaking drivers"): a driver met, not the driver whose view the text takes.
MET = frozenset("behind ahead past following overtaking passing tailgating towards toward by after approaching".split())
#: Bare plurals of vehicles that open a sentence as traffic in general ("Cars coming down the hill").
MOVING_PLURALS = frozenset({"cars", "vehicles"})
#: Words of vehicles standing, not moving ("Cars were parked", "vehicles queuing").
STANDING = frozenset({"parked", "stationary", "stopped", "queuing", "queueing", "queued", "waiting", "standing"})
#: Words before a noun that make it someone besides a driver already named ("other drivers").
OTHER = frozenset({"other", "another"})


def _modifier(word: str) -> bool:
    """Whether ``word`` before a driver noun makes it one driver in particular ("a drunk driver", "the
    wrong-way driver", "safety driver"): an adjective or noun, not an article or adverb."""
    if word in DEFINITE | INDEFINITE or not word.replace("-", "").isalpha():
        return False
    pos = set(lemmas(word))
    return "-" in word or (bool({"ADJ", "NOUN"} & pos) and "ADV" not in pos)  # (not "about drivers")


def _opening_participle(tokens: list[str], k: int) -> bool:
    """Whether ``tokens[k]`` is a participle that opens its sentence with no subject ("Following a
    driver ...", "Approaching drivers ..."): the narrator's doing, whose object is someone met."""
    return tokens[k].endswith("ing") and (k == 0 or tokens[k - 1] in SENTENCE_END)


def _traffic_subject(tokens: list[str], k: int) -> bool:
    """Whether the bare plural at ``k`` ("Cars coming down the hill ...", "Vehicles leaving the
    roundabout ...") opens its sentence as traffic in general on the move: not standing ("Cars were
    parked on both sides")."""
    if tokens[k] not in MOVING_PLURALS or (k and tokens[k - 1] not in SENTENCE_END | {":"}):
        return False
    j = k + 1
    while j < len(tokens) and tokens[j] in BE:
        j += 1
    return j < len(tokens) and tokens[j] not in STANDING and ("VERB" in lemmas(tokens[j]))


def _generic_drivers(tokens: list[str], kind_at: KindAt, known: Known) -> list:
    """The phrases naming a driver in general: the person-at-a-wheel noun alone ("a driver", "the
    driver", "drivers"), not a vehicle's driver ("the bus driver", "the driver of the van") nor
    someone besides ("other drivers")."""
    out = []
    for p in road_users(tokens, kind_at, known):
        if p.end - p.head != 1 or tokens[p.end : p.end + 1] == ["of"]:
            continue
        if tokens[p.head] not in DRIVERS and not _traffic_subject(tokens, p.head):
            continue
        before = tokens[p.head - 1] if p.head else ""
        if before in OTHER or (p.head and kind_at(tokens, p.head - 1) is not None) or _modifier(before):
            continue
        det = tokens[p.head - 1] if p.head and tokens[p.head - 1] in DEFINITE | INDEFINITE else ""
        start = p.head - bool(det)
        if start and (tokens[start - 1] in MET or _opening_participle(tokens, start - 1)):
            continue  # ("Following a driver who brakes": the driver met)
        out.append(Phrase(start, p.head, p.end, det, p.kind))  # (its own article only)
    return out


def _anyone_met(tokens: list[str], start: int, end: int) -> tuple[int, int] | None:
    """Where, between ``start`` and ``end``, someone in traffic said in general is the object of what
    the driver does ("cutting across a vehicle", "towards traffic in lane 1", "the path of through
    traffic"): its phrase (with its determiner and one modifier), else None. A noun that opens a
    clause (after "and", a comma) is a subject of its own, not what is met."""
    for k in range(start, end):
        if tokens[k] not in ANYONE:
            continue
        s = k
        if s > start and tokens[s - 1] in INDEFINITE | OTHER:
            s -= 1
        elif s > start + 1 and tokens[s - 2] in INDEFINITE and tokens[s - 1].isalpha():
            s -= 2  # ("a slower vehicle")
        elif tokens[s - 1] in ("through", "oncoming", "other"):
            s -= 1  # ("through traffic")
        elif tokens[s - 1] == "the":
            continue  # (one already named)
        before = tokens[s - 1] if s else ""
        if before.isalpha() and before not in ("and", "or", "but", "while", "then"):
            return s, k + 1
    return None


def _only_reports(tokens: list[str]) -> bool:
    """Whether every "I"/"we" of the text is a narrator who only reports or sees (its next words hold
    a verb of :data:`REPORTING`, not "had to ..."), and nothing puts the narrator in the traffic."""
    if INVOLVED & set(tokens):
        return False
    said = [k for k, w in enumerate(tokens) if w in ("i", "we")]
    for k in said:
        after = tokens[k + 1 : k + 4]
        account = any(lemma_in(w, HAVING) for w in after) and any(lemma_in(w, ACCOUNTS) for w in tokens[k + 1 : k + 6])
        if "to" in after[:3] or not (account or any(lemma_in(w, REPORTING) for w in after)):
            return False
    return bool(said)


def _own_vehicles(tokens: list[str], kind_at: KindAt, known: Known, drivers: list) -> list:
    """The vehicles of ``tokens`` a driver could be at the wheel of: not the drivers themselves, nor
    vehicles placed as scenery ("parked cars", "the car ahead"). Where there is none, "the driver"
    can only be the driver spoken of in general ("a child runs out on the driver's left")."""
    heads = {p.head for p in drivers}
    return [
        p
        for p in road_users(tokens, kind_at, known)
        if p.kind in VEHICLES
        and p.head not in heads
        and tokens[p.end - 1] not in DRIVERS
        and not placed_by_word(tokens, p)
    ]


#: Words that name the ego after "in front of" / "ahead of" ("the car in front of you").
EGO_WORDS = frozenset({"you", "i", "me", "us", "ego"})
#: Vehicle and driver nouns a follower is named by ("the following driver", "the following car").
FOLLOWERS = frozenset({"driver", "car", "vehicle", "motorist"})


def _ahead_of_ego(tokens: list[str], k: int) -> bool:
    """Whether "in front of" / "ahead of" at ``k`` places someone right ahead of the ego ("in front of
    you", "ahead of the ego")."""
    if tokens[k : k + 2] not in (["in", "front"], ["ahead", "of"]):
        return False
    j = k + 2 + (tokens[k + 1] == "front" and tokens[k + 2 : k + 3] == ["of"])
    j += tokens[j : j + 1] == ["the"]
    return tokens[j : j + 1] != [] and tokens[j] in EGO_WORDS


def _follower_of_lead(tokens: list[str], dropped: list[str]) -> list[str]:
    """ "The car in front of you swerves out round the van, and the following driver is faced with a
    stationary van": once a road user is said to be right ahead of the ego, "the following driver"
    (car, vehicle) is the one following it, the ego."""
    lead = next((k for k in range(len(tokens) - 2) if _ahead_of_ego(tokens, k)), None)
    if lead is None:
        return tokens
    out = list(tokens)
    for k in range(len(out) - 2, lead, -1):
        if out[k - 1 : k + 1] == ["the", "following"] and out[k + 1] in FOLLOWERS:
            dropped.extend(out[k : k + 2])
            out[k - 1 : k + 2] = ["the", "ego"]
    return out


def frame(tokens: list[str], kind_at: KindAt, known: Known, dropped: list[str]) -> list[str]:
    """``tokens`` with the ego of a text that speaks of drivers in general said "the ego" (see the
    module's docstring): the first generic driver, or what it does something to; the words that only
    named it are added to ``dropped``."""
    tokens = _follower_of_lead(tokens, dropped)
    if (names_ego(tokens, kind_at, known) and not _only_reports(tokens)) or SECOND_PERSON & set(tokens):
        return tokens
    from vei_scenario.language.discourse import vehicle_labels

    drivers = _generic_drivers(tokens, kind_at, known)
    lone = not _own_vehicles(tokens, kind_at, known, drivers)
    first = next((p for p in drivers if lone or p.det not in DEFINITE), None)
    if first is None or vehicle_labels(tokens, kind_at, known):
        return tokens  # ("a van pulls out and the driver brakes": that van's driver)
    drivers = [p for p in drivers if lone or p.start >= first.start]
    met = _anyone_met(tokens, first.end, sentence_span(tokens, first.end)[1])
    if met is not None:
        dropped.extend(w for w in tokens[met[0] : met[1]] if w not in INDEFINITE)
        return [*tokens[: met[0]], "the", "ego", *tokens[met[1] :]]
    out = list(tokens)
    for p in reversed(drivers):
        if p.det in INDEFINITE and p is not first:
            continue  # (a second driver new to the text is someone else)
        dropped.extend(w for w in tokens[p.head : p.end])
        out[p.start : p.end] = ["the", "ego"]
    return out
