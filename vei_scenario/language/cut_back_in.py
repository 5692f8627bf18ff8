"""A sudden cut back in close in front of the ego, after an overtake of it: a cut-in after the overtake.

"Cut back", "swerve back" and the like the lexicon holds as a return: a road user getting back to the
lane it left, which for one coming the other way is its own side (a wrong-way overtaker pulling back
in). Said in the same chain as a pass of the ego ("came past on my right and cut straight back in front
of me", "undertook us and cut back into lane 4 directly in front of us"), with a verb of a sudden move
sideways and a place close in front of the ego, the return is into the ego's lane, right where the ego
is heading: the writer reports a cut-in, not only that the overtake ended.

A verb of a sudden move with "in again" ("swung in again right in front of me") is such a return too:
"again" after the particle says the road user is back in the lane it left.

Guards: a plain return ("pulled back in", "moved back", "pulled in again"), one that ends nowhere near
the ego ("cut back in well ahead"), one after a pass of someone else ("overtook the lorry and cut back in front of me":
the pass is not of the ego), or in a chain that says the road user comes the wrong way or names an
oncoming road user ("swerved back in front of me to avoid an oncoming car"), stays a return. So does
any return on a road said to have one lane each way ("one lane each way", "a single carriageway", "a
two-lane road"): there the overtaker has no lane of its own to stay in, and coming back in front of
the ego is how every overtake on it ends.
"""

from __future__ import annotations

from dataclasses import replace

from vei_scenario.language.lemmas import lemmas
from vei_scenario.language.pull_in_apart import ends_close_at_the_ego, sudden, too_soon
from vei_scenario.language.stated import stated_lanes


def _passes_the_ego(m, nxt) -> bool:
    """Whether ``m`` is a pass with the ego or no road user as its object ("came past me", "overtook
    us", "came past on my right"), not of someone else ("overtook the lorry")."""
    if m.slot != "behaviour" or m.value[0] != "overtake":
        return False
    return nxt is None or nxt.slot not in ("actor", "pronoun") or nxt.value == "ego" or nxt.start > m.end + 2


def _two_way(m) -> bool:
    """Whether ``m`` says its chain is on a road with traffic both ways: a road user coming the wrong
    way, or one oncoming ("to avoid an oncoming car": the usual reason for a hurried return)."""
    return m.slot == "wrong_way" or (m.slot == "relation" and m.value == "oncoming")


def _sudden_return(m, tokens: list[str]) -> bool:
    """Whether ``m`` is a return said with a verb of a sudden move sideways ("cut back", "swerved back"),
    or such a verb + "in again" ("swung in again"): "again" after the particle says the road user is
    back where it was, the lane it pulled out of, as "back in" does."""
    if m.slot == "returns":  # ("came back in way too early": a return before there was room is sudden too)
        return sudden(m.words.split()[0]) or too_soon(tokens, m.start)
    again = m.slot in ("unknown_verb", "behaviour") and tokens[m.end : m.end + 2] == ["in", "again"]
    return again and len(m.words.split()) == 1 and sudden(m.words)


def sudden_returns_at_the_ego(clauses: list, tokens: list[str]) -> list:
    """``clauses`` with a sudden return said after a pass of the ego in the same chain, ending close in
    front of the ego, read as a cut-in (see the module's docstring)."""
    one_lane = any(m.slot == "lanes" and m.value == 1 for _, mentions in clauses for m in mentions)
    if one_lane or stated_lanes(" ".join(tokens)) == 1:
        return clauses  # (the one lane each way: coming back in is the overtake's end)
    out = []
    for link, mentions in clauses:
        kept = list(mentions)
        passed = False
        if not any(_two_way(m) for m in mentions):
            for k, m in enumerate(kept):
                nxt = kept[k + 1] if k + 1 < len(kept) else None
                passed = passed or _passes_the_ego(m, nxt)
                if passed and _sudden_return(m, tokens) and "VERB" in lemmas(tokens[m.start]):
                    if ends_close_at_the_ego(tokens, m.start):
                        kept[k] = replace(m, slot="behaviour", value=("cut_in", {}))
        out.append((link, kept))
    return out
