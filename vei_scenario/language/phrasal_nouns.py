"""Nouns made of a phrasal verb and its particle ("a turn-across", "the pull-out", "his cut-across"):
English makes the name of an act from the verb and its particle joined by a hyphen, and a writer names
what a road user did by that noun ("oncoming van turn-across at the junction", "did a pull-out right in
front of me"). Written apart, the two words are the phrase the reader reads as that act.

Only a compound said as a road user's act is read so: right after the road user's noun or as the
object of a light verb ("made", "did", "pulled", "performed", "executed", "took"). One that names a place
("into the pull-in", "at the cross-over", "in the bus pull-in") is the place, and one that heads a report
("Late cut-out.") is its title, told after it.
"""

from __future__ import annotations

from collections.abc import Callable

from vei_scenario.language.lemmas import lemmas


def phrasal_compound(
    tokens: list[str],
    i: int,
    act_at: Callable[[list[str], int], int],
    said_as_an_act: Callable[[list[str], int], bool],
) -> list[str] | None:
    """The two words of a verb + particle compound at ``tokens[i]`` ("turn-across": "turn", "across"),
    or None. ``act_at(tokens, i)`` gives how many words from ``i`` the reader reads as a specific act
    (0: none); the compound is split only where it reads as none on its own and its two words, apart,
    read as one act of both of them (so "cut-in", which the reader knows, and "drop-off", whose two
    words name no act, stay as they are). ``said_as_an_act(tokens, i)``: whether ``tokens[i]`` stands
    where a road user's act is said (after its noun, or as a light verb's object)."""
    tok = tokens[i]
    if tok.count("-") != 1 or not all(tok.split("-")) or act_at(tokens, i):
        return None
    verb, particle = tok.split("-")
    if "VERB" not in lemmas(verb):
        return None
    apart = tokens[:i] + [verb, particle] + tokens[i + 1 :]
    if act_at(apart, i) < 2 or not said_as_an_act(tokens, i):
        return None
    return [verb, particle]
