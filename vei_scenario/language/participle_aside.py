"""A participle set off by commas after its subject ("The defendant, driving a Scania HGV in the offside
lane, moved into the nearside lane"): English puts what a person was doing, and so the vehicle they
were in, between the subject and its verb, and the verb after the closing comma is still that
subject's. The person is the road user the vehicle is: what the sentence's verb says, it does.

The reader otherwise takes a participle of driving that opens a clause with nobody named as the
narrator's own ("Just cruising behind my mate's car at 60"). The aside is known by its frame: the
sentence opens with a noun phrase (an article and its noun), a comma, the participle with a road user
as its object, a closing comma, and a verb. A time said first ("This morning, driving a hire van, I
saw ...") has no verb after the closing comma, so the narrator keeps it.
"""

from __future__ import annotations

from collections.abc import Callable

from vei_scenario.language.clauses import sentence_start, sentence_stop
from vei_scenario.language.discourse import ARTICLES, DETERMINERS, PRONOUNS
from vei_scenario.language.lemmas import lemmas

#: How many words the subject's noun phrase may have, its article included ("the other motorist").
_SUBJECT_WORDS = (2, 4)
#: How many words may stand between the participle and its road user ("driving a Scania HGV").
_TO_THE_OBJECT = 3
#: A relative clause said in place of the bare participle (", who was driving a van,").
_RELATIVE = (("who", "was"), ("who", "is"))
#: Words that open a noun phrase or stand for one: after the closing comma they start a new subject.
_NOT_A_VERB = DETERMINERS | PRONOUNS | {"you"}


def _comma_before(tokens: list[str], i: int) -> int | None:
    """Where the comma that opens the aside of the participle at ``tokens[i]`` is, or None."""
    if i >= 1 and tokens[i - 1] == ",":
        return i - 1
    if i >= 3 and tokens[i - 3] == "," and tuple(tokens[i - 2 : i]) in _RELATIVE:
        return i - 3
    return None


def said_of_the_subject_before(tokens: list[str], i: int, road_user_at: Callable[[list[str], int], bool]) -> bool:
    """Whether the participle at ``tokens[i]`` is an aside between its sentence's subject and verb
    ("The defendant, driving a Scania HGV, moved into ..."): said of that subject, not the narrator.
    ``road_user_at(tokens, j)``: whether a road user's name starts at ``j``."""
    opening = _comma_before(tokens, i)
    if opening is None:
        return False
    start = sentence_start(tokens, opening)
    low, high = _SUBJECT_WORDS
    if tokens[start] not in ARTICLES or not low <= opening - start <= high:
        return False
    if not any(road_user_at(tokens, j) for j in range(i + 1, i + 2 + _TO_THE_OBJECT)):
        return False
    stop = sentence_stop(tokens, i)
    closing = next((k for k in range(i + 1, stop) if tokens[k] == ","), None)
    if closing is None or closing + 1 >= stop:
        return False
    verb = tokens[closing + 1]
    return verb not in _NOT_A_VERB and "VERB" in lemmas(verb)
