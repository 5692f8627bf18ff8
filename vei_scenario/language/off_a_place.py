"""A walker or rider coming onto the road off a place beside it that the lexicon has no word for.

"A guy on a scooter shot off the promenade and across the road in front of us", "a rider came off the
churchyard path straight in front of his car", "a boy with an e-scooter came out from the shop lot in
front of us", "a jogger ran out of the car wash into my path": people name whatever is beside their
road (a promenade, a forecourt, a shared path, a churchyard, a lane between houses), and the reader
cannot know every such noun. What the sentence says is enough: a verb, a preposition of leaving
("off", "off of", "out of", "out from", "from") and a noun phrase, said of a walker or rider who then
comes onto the road (across it, into it, into someone's path, in front of someone). The noun phrase
is then where it comes onto the road from, and is read as the reader reads "the pavement" there: a
kerb it comes from (its side, if said, from what follows it).

What must not be read so: a noun the reader knows (a vehicle, a road user, the road or a junction:
"got off the bus", "fell off his scooter", "came off the roundabout"), a part of the road itself
("came off the bridge", "off the slip road"), a part of something else ("out of the back of a van"),
a place with no determiner ("came out of nowhere", "home from work": not a place beside this road),
a move along ("rode along the promenade", no leaving), and a leaving with no coming onto the road
after it in the same clause ("a family walking back from the beach": where they were, not a move
onto the road). A vehicle's subject is left alone: a vehicle coming out of a place joins the traffic,
which other passes read.
"""

from __future__ import annotations

from dataclasses import replace

from vei_scenario.language.lemmas import lemmas

#: Road users who come off a place beside the road onto it on foot or on two small wheels (or whose
#: kind the reader will take from what they do).
_WALKERS_AND_RIDERS = frozenset(("pedestrian", "bicycle", "e-scooter", "unknown"))
#: Mentions that stand for a road user named before (whose kind the reader settles later).
_STAND_INS = frozenset(("pronoun", "member"))
#: Articles, demonstratives and possessives: a place beside the road is named with one ("the promenade").
_DETERMINERS = frozenset(
    ("the", "a", "an", "this", "that", "these", "those", "his", "her", "their", "its", "our", "my", "your", "some")
)
#: Words between a verb and its preposition of leaving ("came flying out of", "shot straight off").
_MANNER = frozenset(("straight", "suddenly", "right", "just", "quickly", "then", "back", "down", "up", "over"))
#: The parts of the road itself, which one is on while driving: coming off them is no coming onto the road.
_ROAD_PARTS = frozenset(
    (
        "road",
        "roads",
        "street",
        "carriageway",
        "roadway",
        "highway",
        "motorway",
        "freeway",
        "expressway",
        "interstate",
        "bypass",
        "bridge",
        "flyover",
        "overpass",
        "underpass",
        "ramp",
        "slip",
        "sliproad",
        "roundabout",
        "rotary",
        "circle",
        "junction",
        "intersection",
        "crossroads",
        "exit",
        "bend",
        "corner",
        "hill",
        "tunnel",
        "lane",
        "lanes",
        "lights",
        "avenue",
        "boulevard",
        "track",
        "trail",
    )  # fmt: skip
)
#: Words that say where a road user goes is the road or someone's way on it ("into the road", "into its path").
_THE_WAY = frozenset(("road", "street", "carriageway", "roadway", "traffic", "path", "way", "lane", "lanes"))
#: Mentions that name a place or a road user: a noun phrase that runs on into one is that one's.
_NAMING = frozenset(("kerb", "kerb_side", "place", "map", "actor", "arm", "stationary", "lane_side", "waits"))
#: Prepositions of going on along a road ("on the road", "down the street"): already on it.
_ALONG_IT = frozenset(("on", "along", "down", "up"))
#: The words of a move onto the road in front of someone.
_IN_FRONT = (("in", "front"), ("ahead", "of"))


def _leaving_at(tokens: list[str], j: int) -> int | None:
    """Where the noun phrase starts after a preposition of leaving at ``tokens[j]`` ("off", "off of",
    "out of", "out from", "from"), or None."""
    if tokens[j] == "off":
        return j + 2 if tokens[j + 1 : j + 2] == ["of"] else j + 1
    if tokens[j] == "out" and tokens[j + 1 : j + 2] in (["of"], ["from"]):
        return j + 2
    if tokens[j] == "from" and (j == 0 or tokens[j - 1] != "out"):
        return j + 1
    return None


def _a_verb_before(tokens: list[str], j: int, verbs: set[int]) -> int | None:
    """Where the verb stands that the preposition of leaving at ``tokens[j]`` goes with ("came off",
    "shot straight off", "came flying out of"), past adverbs and a participle of manner, or None: a
    word the reader read as a verb (``verbs``) or one that is a verb in English."""
    i = j - 1
    while i >= 0 and (tokens[i] in _MANNER or (tokens[i].endswith("ing") and i - 1 in verbs)):
        i -= 1  # ("came flying out of": the verb is "came")
    if i < 0:
        return None
    return i if i in verbs or "VERB" in lemmas(tokens[i]) else None


def _place_after(tokens: list[str], k: int, read: dict[int, str], function_words: frozenset[str]) -> int | None:
    """Where the noun phrase of an unread place that starts at ``tokens[k]`` ends (after its head), or
    None: a determiner, then at most three words none of which the reader read, ending in a noun (or a
    word no dictionary has: a name), that is no part of the road and not followed by "of" (a part of
    something else: "out of the back of a van")."""
    if k >= len(tokens) or tokens[k] not in _DETERMINERS:
        return None  # ("out of nowhere", "home from work": no place beside this road)
    end = k + 1
    while end < len(tokens) and end - k <= 3 and end not in read and tokens[end].isalpha():
        said = lemmas(tokens[end])
        if tokens[end] in function_words and not said.get("NOUN"):
            break
        if said and not set(said) & {"NOUN", "ADJ", "VERB"}:
            break
        end += 1
    if end == k + 1:
        return None
    head = tokens[end - 1]
    if head in _ROAD_PARTS or (lemmas(head) and "NOUN" not in lemmas(head)):
        return None
    if read.get(end) in _NAMING:
        return None  # (the phrase goes on as a place or road user the reader reads: "the school car park")
    if tokens[end : end + 1] == ["of"]:
        return None
    return end


def _onto_the_road(tokens: list[str], i: int, end: int) -> bool:
    """Whether the words from ``tokens[i]`` to ``tokens[end]`` say a move onto the road: across it,
    into it or into someone's way on it, or in front of someone ("and across the road", "straight
    into my path", "into the path of the car", "right in front of us"). Going on along the road said
    first ("rode out of the village on the road ahead of us") is riding on it, no move onto it."""
    for j in range(i, min(end, len(tokens))):
        if tokens[j] in _ALONG_IT and any(w in _THE_WAY for w in tokens[j + 1 : j + 3]):
            return False
        if tokens[j] == "across":
            return True
        if tuple(tokens[j : j + 2]) in _IN_FRONT:
            return True
        if tokens[j] in ("into", "onto"):
            ahead = tokens[j + 1 : j + 5]
            if any(w in _THE_WAY for w in ahead[:3]):
                return True
    return False


def _spans(clauses: list, tokens: list[str]) -> list[tuple[int, int]]:
    """The tokens each clause was read from, as (start, end): from the sentence end or link ("then",
    "while") before its first mention to the one after its last (the words the reader read nothing
    from lie between, and are the clause's too)."""
    opens = sorted({0, len(tokens)} | {i + 1 for i, t in enumerate(tokens) if t in ".;!?"})
    opens = sorted(set(opens) | {ms[0].start for _, ms in clauses if ms and ms[0].slot == "link"})
    spans = []
    for _, ms in clauses:
        first, last = min(x.start for x in ms), max(x.start for x in ms)
        spans.append((max(b for b in opens if b <= first), min((b for b in opens if b > last), default=len(tokens))))
    return spans


def _subject_of(mentions: list, k: int):
    """The road user the words at ``mentions[k]`` are said of: the last named before it in its
    clause (a road user, or a pronoun or "one" standing for one), or None."""
    return next((x for x in reversed(mentions[:k]) if x.slot in ("actor", *_STAND_INS)), None)


def onto_the_road_off_a_place(clauses: list, tokens: list[str], function_words: frozenset[str]) -> list:
    """``clauses`` with a walker's or rider's place of leaving that the reader has no word for (see
    the module) said as the kerb it comes from: a ``kerb`` mention over the noun phrase, its
    preposition "from" or "off", so the reader reads it as it reads "came off the pavement". Where the
    verb of leaving was not read, or read as a verb with no entry ("swung off the shared path"), it is
    read as a plain move."""
    out = []
    for (link, mentions), span in zip(clauses, _spans(clauses, tokens)):
        kept = list(mentions)
        read = {i: x.slot for x in mentions for i in range(x.start, max(x.end, x.start + 1))}
        verbs = {
            i
            for x in mentions
            if x.slot in ("behaviour", "ego_verb", "unknown_verb")
            for i in range(x.start, max(x.end, x.start + 1))
        }
        for j in range(*span):
            k = _leaving_at(tokens, j)
            if k is None or j in read:
                continue
            end = _place_after(tokens, k, read, function_words)
            verb = _a_verb_before(tokens, j, verbs) if end is not None else None
            if end is None or verb is None:
                continue
            at = sum(1 for x in kept if x.start < j)
            subject = _subject_of(kept, at)
            if subject is None or not (subject.value in _WALKERS_AND_RIDERS or subject.slot in _STAND_INS):
                continue
            nxt = next((x.start for x in kept[at:] if x.slot in ("actor", *_STAND_INS) and x.value != "ego"), None)
            if not _onto_the_road(tokens, end, len(tokens) if nxt is None else nxt):
                continue
            prep = "off" if tokens[j] == "off" else "from"
            like = subject
            place = replace(
                like,
                slot="kerb",
                value=None,
                words=" ".join(tokens[k:end]),
                start=k,
                end=end,
                prev=prep,
                next_=tokens[end] if end < len(tokens) else "",
                det=tokens[k],
                owners=(),
            )
            kept.insert(at, place)
            said = next((x for x in kept if x.start <= verb < max(x.end, x.start + 1)), None)
            if said is None or said.slot == "unknown_verb":  # ("swung off the shared path": a move)
                move = replace(place, slot="behaviour", value=("keep_going", {}), words=tokens[verb],
                               start=verb, end=verb + 1, prev=tokens[verb - 1] if verb else "", det="")  # fmt: skip
                if said is not None:
                    kept[kept.index(said)] = move
                else:
                    kept.insert(sum(1 for x in kept if x.start < verb), move)
            read.update(dict.fromkeys(range(k, end), "kerb"))
        out.append((link, kept))
    return out
