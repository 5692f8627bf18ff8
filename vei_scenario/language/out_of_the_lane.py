"""A road user that goes out of the ego's lane: a lane change, whatever the verb.

"The van in front moved out of my lane", "the lorry ahead drifted out of our lane", "the bus pulled
out of the ego's lane": where the move starts, the ego's own lane, says what it is, as "into my lane"
says a cut-in (:func:`motion.entering_the_ego_lane`). A road user that leaves the lane the ego drives
in was in it, ahead of the ego, and now goes along in the lane beside: a lane change, and, where
something stands in the lane it leaves ("..., revealing a stopped car"), the cut-out that shows it to
the ego (the reader's ``_cut_outs``). The verb only says how it went ("moved", "drifted", "pulled",
"slid"), which the reader would otherwise take as going on, or, for a verb it reads as a move sideways
of no stated direction ("drift", "pull out"), as a move in.

What keeps its reading: a verb said of the ego ("I moved out of my lane": the ego's own move); a walker
(who has no lane); a verb read as a move of its own (a stop, a turn, a crossing, a cut-out); "out of" a
lane that is not the ego's ("out of the bike lane into my lane", "out of the left lane"); a move out
made to overtake ("pulled out of my lane to overtake the lorry": the overtake is the move); a denied
move ("did not move out of my lane"); and a move not told as done (:mod:`not_told`): a counterfactual
("if the van ahead had moved out of my lane I would have been fine": it stayed), a question about the
road user ("Did the van drift out of my lane?") and a passive ("was pulled out of my lane by the tow
truck": it was moved).
"""

from __future__ import annotations

from dataclasses import replace

from vei_scenario.language.function_words import EGO_LANE_OWNERS
from vei_scenario.language.lemmas import lemmas
from vei_scenario.language.motion import subject_before
from vei_scenario.language.not_told import asked_of, passive_at, undone
from vei_scenario.language.settings import negated

#: Moves a verb may already be read as that say only that it goes, or goes sideways with no direction:
#: where it goes from says which.
_SAYS_ONLY_THAT_IT_MOVES = frozenset(("keep_going", "along_road", "cut_in"))
#: Adverbs and particles between a verb and "out of" ("moved slowly out of", "pulled right out of").
_ON_THE_WAY_OUT = frozenset(("suddenly", "quickly", "slowly", "gradually", "right", "just", "fully", "partly",
                             "over", "across", "abruptly", "sharply", "then"))  # fmt: skip
_EGO_OWNERS = EGO_LANE_OWNERS  # (after "out of": "my lane", "the ego's lane", "the ego lane")
#: Verbs of no motion, which "out of my lane" after them does not make a move ("was out of my lane").
_NOT_A_MOVE = frozenset(("be", "have", "do", "stay", "keep", "remain"))


def _out_of_the_ego_lane(tokens: list[str], j: int) -> int | None:
    """Where "out of" + the ego's lane ends when said right after the verb's phrase ending at ``tokens[j]``
    (a few adverbs or particles between), or None."""
    k = j
    while k < len(tokens) and tokens[k] in _ON_THE_WAY_OUT:
        k += 1
    if tokens[k : k + 2] == ["out", "of"]:
        k += 2
    elif not (k > 1 and tokens[k - 2 : k] == ["out", "of"]):
        return None  # (a verb read with its particles: "pulled out of" + the lane)
    for owner in _EGO_OWNERS:
        n = len(owner)
        if tuple(tokens[k : k + n]) == owner and tokens[k + n : k + n + 1] == ["lane"]:
            return k + n + 1
    return None


def leaving_the_ego_lane(clauses: list, tokens: list[str]) -> list:
    """``clauses`` with a road user's verb of going followed by "out of" + the ego's lane read as a lane
    change (see the module's docstring); ``tokens`` are the reader's tokens the mentions index."""
    out = []
    for link, mentions in clauses:
        kept = list(mentions)
        for k, m in enumerate(kept):
            if m.slot != "behaviour" or m.value[0] not in _SAYS_ONLY_THAT_IT_MOVES:
                continue
            verb = m.words.split()[0]
            verbs = set(lemmas(verb).get("VERB", ()))
            if not verbs or verbs & _NOT_A_MOVE or negated(tokens, m.start):
                continue
            if undone(tokens, m.start) or passive_at(tokens, m.start):
                continue  # ("if the van had moved out of my lane", "was pulled out of my lane by ...")
            if _out_of_the_ego_lane(tokens, m.end) is None:
                continue
            subject = subject_before(kept[:k])
            if subject is None or subject.value == "pedestrian" or asked_of(tokens, subject.start):
                continue
            if any(x.slot == "behaviour" and x.value[0] == "overtake" for x in kept[k + 1 :]):
                continue  # ("pulled out of my lane to overtake": the overtake is the move)
            kept[k] = replace(m, value=("change_lane", {}))
        out.append((link, kept))
    return out
