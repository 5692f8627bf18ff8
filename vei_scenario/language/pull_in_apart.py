"""A pull-in in front of the ego told in a sentence of its own after an overtake: a cut-in of its own.

"A car overtook me and cut back in" tells one manoeuvre in one chain of clauses: an overtake ends by
getting back into the lane it left, and the pull-in only says how it ends (the reader folds it into
the overtake). Told in a sentence of its own, with the ego named as where it ends ("The estate
swerves in two metres in front of our bonnet", "Then it dived in front of my car"), the writer
reports the pull-in as an event the ego met: a road user coming into its lane close in front of it,
a cut-in after the overtake.

Guards: in the same sentence the pull-in stays the overtake's end; a pull-in that names no ego after
its verb ("the van pulled back in": an oncoming overtaker back to its own side) stays folded. A return
said with "back" ("cut back in") the reader holds as a return, not a cut-in: it stays the overtake's.
"""

from __future__ import annotations

from vei_scenario.language.clauses import sentence_start, sentence_stop
from vei_scenario.language.discourse import FIRST_PERSON

#: The mark an overtake or a cut-in carries to the tidying of a road user's behaviours: where its sentence starts.
SENTENCE = "_sentence_start"
#: The mark a cut-in carries when the ego is named after its verb in its sentence (where it ends).
AT_EGO = "_at_the_ego"
#: Words that name the ego after a verb: the narrator's object and possessive forms, or the ego itself.
_EGO_AFTER = (FIRST_PERSON - {"i", "we"}) | {"ego"}
#: How many words after a pull-in's verb may say where it ends ("in about two metres in front of our").
_WHERE_IT_ENDS = 10


def _ends_at_the_ego(tokens: list[str], end: int) -> bool:
    """Whether the ego is named within a few words after a verb ending at ``tokens[end]``, in its
    sentence: where the move ends ("in front of me", "on my nose", "ahead of the ego")."""
    return any(t in _EGO_AFTER for t in tokens[end : min(sentence_stop(tokens, end), end + _WHERE_IT_ENDS)])


def mark(name: str, cfg: dict, tokens: list[str], start: int, end: int) -> None:
    """Mark on ``cfg`` (an overtake's or a cut-in's, said at ``tokens[start:end]``) the sentence it is
    told in, and for a cut-in whether the ego is named after it in that sentence."""
    if name not in ("overtake", "cut_in"):
        return
    cfg[SENTENCE] = sentence_start(tokens, start)
    if name == "cut_in":
        cfg[AT_EGO] = _ends_at_the_ego(tokens, end)


def told_apart(overtake_cfg: dict, cut_in_cfg: dict) -> bool:
    """Whether a cut-in said right after an overtake is a move of its own: told in a later sentence,
    ending in front of the ego (see the module's docstring)."""
    first, then = overtake_cfg.get(SENTENCE), cut_in_cfg.get(SENTENCE)
    return first is not None and then is not None and then > first and bool(cut_in_cfg.get(AT_EGO))


def unmarked(cfg: dict) -> dict:
    """``cfg`` without the marks of this module."""
    return {k: v for k, v in cfg.items() if k not in (SENTENCE, AT_EGO)}
