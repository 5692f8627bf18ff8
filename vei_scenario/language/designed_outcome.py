"""The outcome a test or a study designs its event for: "designed as a near miss", "scripted as a
near-crash", "intended to be only just avoidable", "intended as a low-criticality control event",
"no criticality intended", "the collision was unavoidable by design".

Why apart from the other statements of the outcome: a designed class is the scenario's own, as a test
row's rating is. What else the text tells of the event (a participant who "still clipped her", "three of
the 20 made soft contact", "a crash is not intended") says how some runs went or what is not wanted,
not what the scenario is; the outcome reader reads those words as it reads a story, and the design
decides over them."""

from __future__ import annotations

#: Participles of designing an event (lowercased tokens, as the reader has them).
_DESIGNING = frozenset(
    ("designed", "intended", "scripted", "planned", "meant", "parameterised", "parameterized", "tuned", "chosen",
     "configured", "set", "calibrated", "timed")
)  # fmt: skip
#: Participles of designing it again: the design said last of these wins over the first design.
_REDESIGNING = frozenset(
    ("redesigned", "re-designed", "rescripted", "re-scripted", "reparameterised", "re-parameterised",
     "reparameterized", "re-parameterized", "retuned", "re-tuned", "retimed", "re-timed", "replay", "replayed",
     "rerun", "re-run", "reran", "re-ran")
)  # fmt: skip
#: What may stand between a participle and its opening word: what is designed, as its object ("we
#: redesigned it as a collision test", "replay it as a crash").
_OBJECTS = frozenset(("it", "them", "this", "the", "event", "scenario", "case", "run", "test"))
#: Words after a contact noun that make it what a test is about, not the contact designed ("designed as
#: a collision avoidance test", "as a crash warning case").
_ABOUT = frozenset(("avoidance", "mitigation", "warning", "prevention", "alert", "risk", "imminent", "avoiding"))
#: Words that open what the design is for, after its participle ("designed as", "intended to be",
#: "tuned so that", "scripted such that").
_OPENING = frozenset(("as", "to", "so", "such"))
#: What is designed, when the design is the event's: the event, the scenario, its timing ("the timing
#: was tuned so that ..."), or nothing said (a participle opening its clause: "Designed as non-critical").
#: Not a pronoun: "It was meant to be a benign Sunday ride" opens a story, not a test.
_EVENTS = frozenset(
    ("event", "events", "scenario", "scenarios", "case", "cases", "test", "tests", "run", "runs", "trial", "trials",
     "conflict", "conflicts", "situation", "encounter", "interaction", "manoeuvre", "maneuver", "timing", "trigger",
     "parameters", "parameterisation", "parameterization", "condition", "block", "exposure")
)  # fmt: skip
#: Words between what is designed and the participle ("the event was deliberately designed").
_AUXILIARIES = frozenset(
    ("is", "was", "were", "are", "be", "been", "being", "has", "have", "had", "originally", "initially", "first",
     "deliberately", "specifically", "carefully", "also", "then", "later", "again")
)  # fmt: skip
#: Words that deny the design ("not designed as a near miss", "never intended to be").
_DENYING = frozenset(("not", "never", "no", "n't", "nor"))
#: Where what the design is for ends, and where a clause starts.
_ENDS = frozenset((".", ";", ":", ",", "(", ")", "!", "?", "|"))
#: How far on from the participle the class may stand (words).
_REACH = 10

NEAR, SAFE, CONTACT = "near_miss", "safe", "collision"
#: Phrases of a designed near miss or safe pass, as token tuples.
_CLASSES: tuple[tuple[tuple[str, ...], str], ...] = (
    (("near", "miss"), NEAR),
    (("near-miss",), NEAR),
    (("near", "crash"), NEAR),
    (("near-crash",), NEAR),
    (("near", "collision"), NEAR),
    (("near-collision",), NEAR),
    (("close", "call"), NEAR),
    (("just", "avoidable"), NEAR),
    (("barely", "avoidable"), NEAR),
    (("critical", "but", "solvable"), NEAR),
    (("critical", "but", "avoidable"), NEAR),
    (("non-critical",), SAFE),
    (("noncritical",), SAFE),
    (("uncritical",), SAFE),
    (("benign",), SAFE),
    (("low-criticality",), SAFE),
    (("low", "criticality"), SAFE),
    (("no", "criticality"), SAFE),
    (("not", "critical"), SAFE),
)
#: Nouns of contact: a designed one is one said unavoidable ("designed such that the collision was
#: unavoidable"); a contact noun alone is what a test is about ("to assess collision avoidance").
_CONTACTS = frozenset(("collision", "crash", "impact", "contact", "collisions", "crashes", "impacts"))
#: Words after which a class stands as the event's own, said backwards ("no criticality intended",
#: "impact was unavoidable by design").
_AFTER = (("intended",), ("by", "design"))


def _class_at(words: list[str], k: int) -> tuple[str, int] | None:
    """The designed class whose phrase starts at ``words[k]``, with the phrase's length."""
    for phrase, kind in _CLASSES:
        if tuple(words[k : k + len(phrase)]) == phrase:
            return kind, len(phrase)
    return None


def _window(tokens: list[str], start: int) -> list[str]:
    """The words from ``start`` on to the clause's end, at most ``_REACH``."""
    out: list[str] = []
    k = start
    while k < len(tokens) and tokens[k] not in _ENDS and len(out) < _REACH:
        out.append(tokens[k])
        k += 1
    return out


def _unavoidable_contact(words: list[str]) -> bool:
    """A contact said unavoidable, not denied ("the impact was unavoidable"; not "an impact is not
    unavoidable")."""
    for k, w in enumerate(words):
        if w == "unavoidable" and set(words[:k]) & _CONTACTS and not set(words[:k]) & _DENYING:
            return True
    return False


def _forward(words: list[str]) -> str | None:
    """The class a design's purpose names, in the words after its opening word; none where a denial
    comes first ("intended to be not a near miss")."""
    if words[:1] == ["as"]:  # ("re-parameterised as a collision", "designed as a crash test")
        noun = 2 if words[1:2] in (["a"], ["an"]) else 1
        if words[noun : noun + 1] and words[noun] in _CONTACTS and not set(words[noun + 1 : noun + 2]) & _ABOUT:
            return CONTACT
    for k in range(len(words)):
        if words[k] in _DESIGNING | _REDESIGNING:
            break  # (another design's purpose: "... after being designed as a near miss")
        if words[k] in _DENYING and not _class_at(words, k):
            return None
        found = _class_at(words, k)
        if found:
            return found[0]
    return CONTACT if _unavoidable_contact(words) else None


def _of_the_event(tokens: list[str], i: int) -> bool:
    """Whether the participle at ``i`` designs the event: what it is said of is the event (the scenario,
    its timing, "it"), or nothing (it opens its clause), and no denial stands before it."""
    j = i - 1
    while j >= 0 and (tokens[j] in _AUXILIARIES or tokens[j] in _DENYING):
        if tokens[j] in _DENYING:
            return False  # ("the event was not designed as a near miss")
        j -= 1
    while j > 0 and any(c.isdigit() for c in tokens[j]):
        j -= 1  # (a named event: "Event 3 was scripted as ...", "scenario S2b")
    return j < 0 or tokens[j] in _ENDS or tokens[j] in _EVENTS


def _backward(tokens: list[str], i: int, after: tuple[str, ...]) -> str | None:
    """The class said just before "intended" or "by design" at ``i`` ("no criticality intended", "the
    impact was unavoidable by design"); not "benign as intended", "by design of the bumper"."""
    if after == ("by", "design") and tokens[i + 2 : i + 3] == ["of"]:
        return None
    j = i - 1
    while j >= 0 and tokens[j] in ("is", "was", "be", "been", "were", "are"):
        j -= 1
    if j < 0 or tokens[j] == "as":
        return None
    for phrase, kind in _CLASSES:
        n = len(phrase)
        if tuple(tokens[j + 1 - n : j + 1]) == phrase:
            return kind
    if tokens[j] == "unavoidable" and set(tokens[max(0, j - 3) : j]) & _CONTACTS:
        return CONTACT
    return None


#: Words that set what happened against what was designed ("but actually", "in fact", "in reality").
_CONTRASTS = (("actually",), ("in", "fact"), ("in", "reality"), ("turned", "out"), ("in", "practice"))


#: Words that set, in the design's own sentence, what happened against it.
_BUT = frozenset(("but", "yet", "although", "though", "however"))


def _contrast_at(tokens: list[str], k: int) -> bool:
    return any(tuple(tokens[k : k + len(c)]) == c for c in _CONTRASTS)


def designed_outcome(tokens: list[str]) -> str | None:
    """``near_miss``, ``safe`` or ``collision``: the class the text says its event is designed,
    scripted or intended to have; None where it says none, or two designs disagree (two events, or a
    design and a note against it) with no redesign said last. ``tokens``: the reader's lowercased
    tokens, punctuation apart."""
    designs: list[tuple[int, str, bool]] = []  # (where, the class, whether a redesign)
    for i, w in enumerate(tokens):
        for after in _AFTER:  # (said backwards: "no criticality intended")
            if tuple(tokens[i : i + len(after)]) == after:
                kind = _backward(tokens, i, after)
                if kind:
                    designs.append((i, kind, False))
        if w not in _DESIGNING | _REDESIGNING:
            continue
        again = w in _REDESIGNING
        o = i + 1
        while again and o < len(tokens) and o <= i + 2 and tokens[o] in _OBJECTS:
            o += 1  # ("we redesigned it as ...")
        if tokens[o : o + 1] and tokens[o] in _OPENING and (again or _of_the_event(tokens, i)):
            kind = _forward(_window(tokens, o))
            if kind:
                designs.append((i, kind, again))
    if not designs:
        return None
    first_design = designs[0][0]
    if any(_contrast_at(tokens, k) for k in range(first_design, len(tokens))):
        return None  # ("designed as a near miss but actually ended in a collision": what happened is told)
    end = next((k for k in range(first_design, len(tokens)) if tokens[k] in (".", "!", "?", ";")), len(tokens))
    if any(w in _BUT and tokens[k - 1] != "critical" for k, w in enumerate(tokens[first_design:end], first_design)):
        return None  # ("The run was set to be non-critical, but the ego still hit the target")
    again = [kind for _, kind, redesign in designs if redesign]
    if again:
        return again[-1]
    kinds = {kind for _, kind, _ in designs}
    return kinds.pop() if len(kinds) == 1 else None
