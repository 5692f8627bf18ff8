"""Which of the distances said of one road user is where it starts.

A writer puts a road user in the scene once ("a cyclist about 50 m ahead", "spawns 300 m ahead", "cuts
in with a 10 m gap") and may say more distances of it afterwards: a trigger point ("at 80 m it
swerves"), a threshold ("if you have not braked by 30 m"), a question about another value ("should I
make it 20 m?"), how far one can see ("invisible past 200 m"). Those are when something happens, not
where it starts. So the distance said in the first sentence that gives one, from the sentence that
names the road user on, is its start; a later sentence's distance only counts when none came before.
A distance said before the road user was named (a time gap to someone else, carried to the next one
named) gives way to one said with it; a distance after "by" is an amount (how far it drifted, missed,
or a point reached), not a place.
"""

from __future__ import annotations

from vei_scenario.language.clauses import sentence_start

#: one distance said of a road user: (where it starts in the scanned words, metres, the word before
#: it, the behaviour its distance is the end gap of)
Said = tuple[int, float, str, "str | None"]


def start_of(said: list[Said], words: list[str], named_end: int) -> Said | None:
    """The distance of ``said`` (in the order the reader took them) that is where the road user starts,
    or None where the reader's own choice (the last one taken) stands: one distance only, or none said
    from the sentence that names it on."""
    if len(said) < 2 or named_end <= 0:
        return None
    named_in = sentence_start(words, min(named_end, len(words)) - 1)
    placed = [(sentence_start(words, s[0]), s) for s in said if s[2] != "by"]
    placed = [(k, s) for k, s in placed if k >= named_in]
    if not placed:
        return None
    first = min(k for k, _ in placed)
    return [s for k, s in placed if k == first][-1]  # (within its sentence the reader's choice stands)
