"""The ego holding back behind a walker or rider and then passing it, told without naming the ego.

"A cyclist was riding along the kerb on our side, she held back at about 20 mph and only overtook once
it was clear", "Jogger along the left edge. Slowed, waited for a gap, then passed wide", "e-scooter
rider wobbling along the gutter, cand. held back behind, then overtook when clear": a driving lesson, a
debrief, a road-safety piece tells of the driver behind a walker or a rider who holds back and then
passes. The subject of those verbs is left out, or is a pronoun or a role the reader does not take for
the ego, so the reader gives the verbs to the road user named last: the one passed. Its reading then
holds back and overtakes no one, and the scenario plays a rider that brakes and then shoots past the
ego.

Told apart by what the reading holds: a walker or rider whose overtake of no one follows right after
its holding back (giving way, slowing, stopping, following), both said free of it (see
:func:`said_free`). Both are the ego's: the road user is what the ego passes, going along ahead of it.
Guards, each with its reason:

- only walkers and riders: they are slower than the one behind them; a motor vehicle that holds back
  and then passes is an ordinary overtaker (a car that waits for a gap and goes);
- the overtake has no object: one that passes someone ("overtook a parked van", "overtook me") is
  the road user's own, the writer said whom it passes;
- neither verb is said with a walker's or rider's noun, or "it", as its nearest subject ("the cyclist
  slowed and then overtook"): the writer said whose they are;
- the road user does not start behind the ego: one coming up from behind can slow and then pass it.
"""

from __future__ import annotations

from collections.abc import Callable

from vei_scenario.language.clauses import SENTENCE_END, sentence_start, sentence_stop
from vei_scenario.language.discourse import DETERMINERS, VULNERABLE

#: The mark a holding back or an overtake said free of the road user carries to the pass over the reading.
MARK = "_held_pass_free"
#: Behaviours of holding back behind someone: giving way, slowing, stopping, following.
HOLDS = frozenset(("give_way", "change_speed", "stop", "follow_vehicle"))
#: Pronouns that stand as a subject and name a person: the narrator, the one addressed, or one driver
#: ("she held back"). "They" is left out: it says again a pair or a group of riders as often as anyone.
_OTHER_SUBJECTS = frozenset(("i", "we", "you", "he", "she"))
#: Pronouns that may say the road user again: "it" (a bike, a scooter), "they" (a pair of riders).
_MAYBE_ITSELF = frozenset(("it", "they"))
#: Words that say a verb of passing has an object: a determiner, an object pronoun, the ego.
_OBJECT_OPENERS = DETERMINERS | frozenset(("me", "us", "him", "her", "them", "it", "you", "ego", "everyone"))
#: Particles between a verb of passing and its object ("went past her", "got round them").
_PARTICLES = frozenset(("past", "round", "around", "by", "beyond", "on", "up"))


def _has_object(after: list[str], kind_of: Callable[[str], str | None]) -> bool:
    """Whether the words right after a verb of passing (``after``) name whom it passes: a
    determiner, an object pronoun or a road user's noun, after a particle or not."""
    words = after[1:] if after[:1] and after[0] in _PARTICLES else after
    return bool(words) and (words[0] in _OBJECT_OPENERS or kind_of(words[0]) is not None)


def _someone_else_subject(before: list[str], kind_of: Callable[[str], str | None]) -> bool:
    """Whether the nearest naming word before a verb in its sentence (``before``) is someone other than
    a walker or rider: a motor vehicle or the ego by its noun, or a subject pronoun; with none, the
    subject is left out, and so is no walker's or rider's noun either. "It" or "they" may be the road
    user itself."""
    for word in reversed(before):
        if word in _OTHER_SUBJECTS:
            return True
        if word in _MAYBE_ITSELF:
            return False
        kind = kind_of(word)
        if kind is not None:
            return kind not in VULNERABLE
    return True


def said_free(
    name: str, tokens: list[str], start: int, end: int, kind: str, kind_of: Callable[[str], str | None]
) -> bool:
    """Whether behaviour ``name``, said in ``tokens[start:end]`` and given to a road user of ``kind``,
    may be the ego's holding back or passing: the road user is a walker or rider, the verb is one of
    holding back or an overtake of no one, and its nearest subject is not a walker's or rider's noun
    (``kind_of``: the road-user kind a word names, or None)."""
    if kind not in VULNERABLE or name not in HOLDS | {"overtake"}:
        return False
    if name == "overtake" and _has_object(tokens[end : end + 2], kind_of):
        return False
    return _someone_else_subject(tokens[sentence_start(tokens, start) : start], kind_of)


#: The mark of a holding back said with "behind" and no one after it ("held back behind, then
#: overtook"): "behind" there says where the one holding back is, not where the road user is.
BEHIND = 2.0


def mark(name: str, tokens: list[str], end: int, kind_of: Callable[[str], str | None]) -> float:
    """The mark of behaviour ``name`` said free (see :func:`said_free`), its verb ending at ``end`` in
    ``tokens``: :data:`BEHIND` for a holding back followed by "behind" with no one after it, else 1."""
    after = tokens[end : end + 2]
    alone = after[:1] == ["behind"] and not _has_object(after[1:], kind_of)
    return BEHIND if name in HOLDS and alone else 1.0


#: Where a marked behaviour was said: (start, end) of its words in the scanned tokens.
SPAN = "_held_pass_span"


def _unmarked(behaviour: tuple) -> tuple:
    """``behaviour`` (name, cfg, criticality, link) with the mark and its span taken off its parameters."""
    name, cfg, crit, link = behaviour
    return (name, {k: v for k, v in cfg.items() if k not in (MARK, SPAN)}, crit, link)


def said_within(tokens: list[str], span: tuple[int, int] | None, at: int | None) -> bool:
    """Whether token ``at`` lies in ``span`` (from the ego's first holding back to its pass) or after
    it in the pass's sentence ("held back at about 20 mph", "overtook when clear at ~20mph"): a speed
    said there is the ego's, whose the holding back and the pass are."""
    if span is None or at is None or at < span[0]:
        return False
    return at < sentence_stop(tokens, span[1], SENTENCE_END)


def egos_hold_and_pass(behaviours: list, behind: bool) -> tuple[list, tuple[int, int] | None, bool]:
    """``behaviours`` (name, cfg, criticality, link) of a road user without the ego's holding back and
    passing (marked holds right before a marked overtake: see the module's docstring), marks taken
    off; where such a hold and pass were said (from the first hold's start to the pass's end, or None
    where none was found: the road user is then one the ego passes); and whether one of those holds
    was said "behind" with no one after it (the road user's "behind" is then the ego's place).
    ``behind``: the road user is said behind the ego; then nothing is taken, unless "behind" was said
    only by such a hold."""
    out: list = []
    span: tuple[int, int] | None = None
    held_behind = False
    for b in behaviours:
        run = _held_run(out)
        by_hold = any(x[1].get(MARK) == BEHIND for x in run)
        if b[0] == "overtake" and b[1].get(MARK) and run and (by_hold or not behind):
            del out[len(out) - len(run) :]
            first, last = run[0][1].get(SPAN), b[1].get(SPAN)
            if first and last:
                span = (min(first[0], span[0]) if span else first[0], last[1])
            held_behind = held_behind or by_hold
            continue
        out.append(b)
    return [_unmarked(b) for b in out], span, held_behind


def _held_run(behaviours: list) -> list:
    """The marked holds at the end of ``behaviours``, in order."""
    k = len(behaviours)
    while k and behaviours[k - 1][0] in HOLDS and behaviours[k - 1][1].get(MARK):
        k -= 1
    return behaviours[k:]
