"""How aggressively a road user acts (its criticality: ``dangerous``, ``moderate`` or ``safe``), read
from the scales people state it on rather than from a list of phrases.

Three small closed scales carry it, each with its degree words and its negation:

* **closeness to the ego**: "close", "tight" (and "closer than I'd like"), graded by a degree word: a
  mild one ("a bit", "slightly", "a little") makes it moderate, a strong one ("very", "too",
  "dangerously") dangerous. Closeness to a place ("tight to the kerb", "close to the verge") is where a
  road user rides, not a margin to the ego;
* **the margin left**: a wide one ("plenty of room", "loads of space", "a good way ahead", "well
  clear", "well ahead of me") is safe; a wide one denied ("not much room") is dangerous;
* **timing**: "late" said of an act ("changed lane very late") is dangerous; "late morning" is a time;
* **where an act ends**: right at the ego ("cut straight in front of us", "swung directly across our
  bonnet", "went across my front bumper") is dangerous; the same words after a noun name where a road
  user stands ("the car directly in front of me"), and after a verb of standing where it waits.

A negator before a word of danger ("nothing dangerous", "not aggressive", "nothing crazy") denies the
danger: alone it leaves a safe pass, beside a mild closeness ("bit close but nothing crazy") a
moderate one. A level stated under a label ("Crit: high", "criticality low") is taken as said.
"""

from __future__ import annotations

from vei_scenario.language.clauses import split

DANGEROUS, MODERATE, SAFE = "dangerous", "moderate", "safe"

_CLOSE = frozenset(("close", "closer", "tight", "tighter", "near"))
#: Degree words below and above the plain meaning.
_MILD = frozenset(("bit", "little", "slightly", "somewhat", "fairly", "tad", "touch", "mildly", "reasonably"))
_STRONG = frozenset(("very", "too", "really", "so", "dangerously", "uncomfortably", "extremely", "way", "scarily",
                     "much", "far", "seriously", "properly", "incredibly", "terribly", "bloody"))  # fmt: skip
#: Places a road user keeps close to: its line, not a margin to the ego.
_PLACES = frozenset(("kerb", "curb", "verge", "edge", "side", "wall", "line", "centre", "center", "gutter", "hedge",
                     "pavement", "sidewalk", "shoulder", "fence", "barrier", "left", "right", "middle"))  # fmt: skip
_NEGATORS = frozenset(("no", "not", "never", "nothing", "none", "nowhere", "hardly", "without", "neither", "nor"))
#: Words of danger a negator denies ("nothing dangerous", "not aggressive", "nothing crazy").
_DANGER = frozenset(("dangerous", "dangerously", "aggressive", "aggressively", "reckless", "recklessly", "crazy",
                     "scary", "hairy", "mad", "wild", "dramatic", "alarming", "sketchy", "close", "sudden",
                     "risky", "frightening", "terrifying", "hectic"))  # fmt: skip
#: Words of danger that say the class outright when not denied.
_SAID_DANGER = frozenset(("dangerous", "dangerously", "aggressive", "aggressively", "reckless", "recklessly"))
#: Quantities of a wide margin and what they measure ("plenty of room", "loads of space").
_WIDE = frozenset(("plenty", "loads", "lots", "heaps", "tons", "ample", "enough", "masses", "oodles"))
_ROOM = frozenset(("room", "space", "time", "distance", "gap", "margin", "clearance"))
#: Where a wide margin lies ("well ahead", "a good way in front", "well clear").
_AWAY = frozenset(("ahead", "clear", "back", "behind", "before", "away", "off", "short", "in", "out"))
_TIMES = frozenset(("morning", "afternoon", "evening", "night", "shift", "summer", "winter", "autumn", "spring"))
_LEVELS = {"high": DANGEROUS, "medium": MODERATE, "moderate": MODERATE, "mid": MODERATE, "low": SAFE}
_LABELS = frozenset(("crit", "criticality", "severity", "criticity"))
#: Words that end a clause: what one clause says on the scales is not said of the next.
BREAKS = frozenset(".;!?,") | {"but", "and", "then", "so", "though", "although", "because"}
#: Degree words of a place exactly there ("right in front", "straight across", "bang in front").
EXACTLY = frozenset(("right", "straight", "directly", "just", "bang", "smack", "slap", "dead", "square", "squarely"))
#: The ego as what an act ends at, and the parts of its vehicle an act crosses ("across our bonnet").
_EGO = frozenset(("me", "us", "ego", "i", "we"))
_EGO_PARTS = frozenset(("bonnet", "hood", "nose", "bumper", "bows", "front", "grille", "wheels", "wheel"))
_OURS = frozenset(("my", "our", "the"))
#: Verbs of standing or waiting: an act does not end where they stand.
_STANDING = frozenset(("stand", "stood", "stands", "standing", "wait", "waited", "waits", "waiting", "sat", "sits",
                       "sitting", "parked", "stopped", "is", "was", "were", "are", "queued", "queuing"))  # fmt: skip


def _closeness(words: list[str], i: int) -> str | None:
    """The class of a closeness word at ``i`` graded by its degree, "position" for closeness to a
    place, or None for a plain one (left to the lexicon's reading)."""
    after = words[i + 1 : i + 4]
    if after[:1] in (["to"], ["against"], ["along"]) and set(after[1:]) & _PLACES:
        return "position"  # ("tight to the curb", "close to the verge")
    before = words[max(0, i - 3) : i]
    if any(w in _NEGATORS for w in before):
        return None  # (read as a denied danger)
    if set(before) & _MILD and not set(before) & _STRONG - {"too"}:
        return MODERATE  # ("a bit close", "a little too close": the mild degree grades the excess)
    if set(before) & _STRONG:
        return DANGEROUS
    if words[i] in ("closer", "tighter") and "than" in after[:1]:
        return MODERATE  # ("closer than I'd like": more than wished, not an emergency)
    return None


def _denied_danger(words: list[str], i: int) -> bool:
    return words[i] in _DANGER and any(w in _NEGATORS for w in words[max(0, i - 3) : i])


def _margin(words: list[str], i: int) -> str | None:
    """A wide margin at ``i`` ("plenty of room", "a good way ahead", "well clear"): safe, or
    dangerous when denied ("not much room", "without enough space")."""
    w = words[i]
    nxt = words[i + 1] if i + 1 < len(words) else ""
    denied = any(x in _NEGATORS for x in words[max(0, i - 3) : i])
    if w in _WIDE and (nxt in _ROOM or (nxt == "of" and i + 2 < len(words) and words[i + 2] in _ROOM)):
        return DANGEROUS if denied else SAFE
    if w == "much" and nxt in _ROOM and denied:
        return DANGEROUS  # ("not much room")
    if w == "way" and i > 0 and words[i - 1] in ("good", "long", "fair") and nxt in _AWAY:
        return SAFE  # ("a good way ahead", "a long way off")
    if w in ("miles", "ages") and nxt in _AWAY:
        return SAFE  # ("miles ahead": a margin beyond measure)
    if w == "well" and nxt in _AWAY and not (nxt == "in" and words[i + 2 : i + 3] != ["front"]):
        return SAFE  # ("well ahead of me", "well clear", "well in front")
    return None


def _late(words: list[str], i: int) -> bool:
    """ "late" said of an act ("changes lane very late", "pulled out late"), not of a time of day."""
    if words[i] != "late":
        return False
    nxt = words[i + 1] if i + 1 < len(words) else ""
    return nxt not in _TIMES and not nxt.endswith("ish") and (i == 0 or words[i - 1] not in ("a", "the", "in"))


def _at_the_ego(words: list[str], i: int) -> bool:
    """An act that ends right at the ego, at ``i`` its place word: "in front of" or "across" the ego or a
    part of its vehicle, after a degree of exactness ("straight in front of us") or across a part of
    it ("across my front bumper"); not after a noun or a verb of standing ("the car directly in front
    of me", "stood right in front of us": where it is)."""
    w = words[i]
    if w == "in" and words[i + 1 : i + 3] == ["front", "of"]:
        after = words[i + 3 : i + 7]
    elif w == "across":
        after = words[i + 1 : i + 5]
    else:
        return False
    exact = i > 0 and words[i - 1] in EXACTLY
    k = i - 1 if exact else i
    prev = words[k - 1] if k > 0 else ""
    if not prev or prev in _STANDING or _noun_only(prev):
        return False
    at_ego = after[:1] and (after[0] in _EGO or (after[0] == "the" and after[1:2] == ["ego"]))
    ours = after[:1] and after[0] in _OURS and bool(set(after[1:4]) & _EGO_PARTS)
    return bool((exact and (at_ego or ours)) or (w == "across" and ours and after[0] != "the"))


def _noun_only(word: str) -> bool:
    """Whether ``word`` is only a noun (or unknown as a verb): what stands before a place phrase
    that says where a road user is ("the car directly in front of me")."""
    from vei_scenario.language.lemmas import lemmas

    found = lemmas(word)
    return bool(found) and "VERB" not in found and word not in ("out", "in", "back", "over", "off", "round")


#: Verbs of forcing: a road user that forces the ego into a reaction leaves it no choice.
_FORCING = frozenset(("force", "forces", "forced", "forcing"))
#: What a forced ego is forced into: a verb ("forcing me to brake") or a place ("forced us onto the verge").
_FORCED_INTO = frozenset(("to", "into", "onto", "off", "out", "across", "over", "up"))
#: Metre units (the reader gives feet and car lengths in metres) and the most left to spare that is a
#: dangerous margin: under a car's length and a half at any speed worth telling.
METRES = frozenset(("m", "metre", "metres", "meter", "meters"))
SMALL_SPARE_M = 5.0


def _forced_ego(words: list[str], i: int) -> bool:
    """ "forcing me to brake", "forced us onto the verge", "forces the ego into the next lane": the
    ego, as the object of a verb of forcing, made to react; not "forced its way through"."""
    if words[i] not in _FORCING:
        return False
    obj = words[i + 1 : i + 4]
    if obj[:1] and obj[0] in _EGO:
        return obj[1:2] != [] and obj[1] in _FORCED_INTO
    return obj[:2] == ["the", "ego"] and obj[2:3] != [] and obj[2] in _FORCED_INTO


def _small_spare(words: list[str], i: int) -> bool:
    """ "with about 3 metres to spare", "with 2 m to spare": a distance left to spare of a few metres
    (the number at ``i``); "with 40 metres to spare" is a wide margin."""
    try:
        value = float(words[i])
    except ValueError:
        return False
    return (
        words[i + 1 : i + 2] != []
        and words[i + 1] in METRES
        and words[i + 2 : i + 4] == ["to", "spare"]
        and (value <= SMALL_SPARE_M)
    )


def _labelled(tokens: list[str]) -> str | None:
    """A level under a label: "Crit: high", "criticality low", "severity: medium"."""
    for i, w in enumerate(tokens):
        if w in _LABELS:
            for x in tokens[i + 1 : i + 3]:
                if x in _LEVELS:
                    return _LEVELS[x]
                if x not in (":", "=", "-", "is"):
                    break
    return None


def manner_cues(tokens: list[str]) -> list[str]:
    """What each clause of ``tokens`` (the reader's normalised, lowercased tokens) says on the scales:
    a class, "position" or "denied" (a denied danger), in text order."""
    cues: list[str] = []
    for words, _ in split(tokens, BREAKS):
        for i, w in enumerate(words):
            if _denied_danger(words, i):
                cues.append("denied")
                continue
            if w in _SAID_DANGER:
                cues.append(DANGEROUS)  # (so that "aggressively, but well ahead" is no single class)
                continue
            if w in _CLOSE:
                found = _closeness(words, i)
                if found is not None:
                    cues.append(found)
                continue
            if _at_the_ego(words, i):
                cues.append(DANGEROUS)  # ("cut straight in front of us", "across our bonnet")
                continue
            if _forced_ego(words, i) or _small_spare(words, i):
                cues.append(DANGEROUS)  # ("forcing me to brake", "with 2 m to spare")
                continue
            margin = _margin(words, i)
            if margin is not None:
                cues.append(margin)
            elif _late(words, i) and any(x in _STRONG for x in words[max(0, i - 2) : i]):
                cues.append(DANGEROUS)  # ("very late", "too late")
    return cues


def stated_manner(tokens: list[str]) -> str | None:
    """The class the scales state for the encounter, or None when they say nothing or disagree: a
    label first; then a denied danger with a mild closeness is moderate, alone or with a wide margin
    safe; one class said (positions aside) is that class."""
    label = _labelled(tokens)
    if label is not None:
        return label
    cues = [c for c in manner_cues(tokens) if c != "position"]
    if not cues and _ego_evaded(tokens):
        return DANGEROUS  # (nothing said on the scales, but the ego had to brake hard or swerve)
    kinds = set(cues)
    if "denied" in kinds:
        rest = kinds - {"denied"}
        if rest <= {SAFE}:
            return SAFE
        if rest == {MODERATE}:
            return MODERATE
        return None
    return kinds.pop() if len(kinds) == 1 else None


def _ego_evaded(tokens: list[str]) -> bool:
    """Whether the text says the ego evaded ("I had to stamp on the brakes", "we braked sharply", "I
    swerved hard"), as the outcome reader reads it: an act that leaves the ego only an emergency
    reaction is a dangerous one, where no scale says how close it came. A wide margin said ("overtook
    me with room to spare") outranks it, as it does in the outcome ("brakes squealing for no reason")."""
    from vei_scenario.language.outcome import outcome_cues

    kinds = {c.kind for c in outcome_cues(" ".join(tokens))}
    return "evade" in kinds and "safe" not in kinds


def apply_manner(cls: str | None, specs: list) -> None:
    """Give the class the scales state to the one road user that acts (moves, or does more than go on
    or stop): the scales speak of the encounter, and with one road user in it, of that road user."""
    if cls is None:
        return
    acting = [s for s in specs if s.speed_mps != 0.0 or any(b[0] not in ("keep_going", "stop") for b in s.behaviours)]
    if len(acting) != 1:
        return
    acting[0].behaviours = [(name, cfg, cls, link) for name, cfg, _, link in acting[0].behaviours]


#: Below this time gap (s) a road user that cuts in leaves the ego no more than a reaction time: a
#: dangerous cut-in, whatever words say it.
TIGHT_HEADWAY_S = 1.0


def tight_cut_ins(specs: list, ego_speed_mps: float | None, intent: str | None) -> None:
    """Make dangerous a cut-in whose stated gap in front of the ego ("forces its way in about 20 feet
    in front of me") is under :data:`TIGHT_HEADWAY_S` at the ego's stated speed, where nothing else
    set its class: its numbers say how close it came. Not where the outcome is said to be safe, nor
    for a road user said to be faster than the ego (the gap it leaves opens)."""
    if not ego_speed_mps or ego_speed_mps <= 0.0 or intent == SAFE:
        return
    for spec in specs:
        if spec.speed_mps is not None and spec.speed_mps > ego_speed_mps:
            continue
        spec.behaviours = [
            (name, cfg, DANGEROUS, link)
            if name == "cut_in"
            and crit is None
            and 0.0 < float(cfg.get("gap_m", 1e9)) / ego_speed_mps < TIGHT_HEADWAY_S
            else (name, cfg, crit, link)
            for name, cfg, crit, link in spec.behaviours
        ]
