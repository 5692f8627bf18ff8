"""Whether a clause tells a road user's act as done: not under a counterfactual, in a yes/no question
about it, or in the passive.

A rule that reads an act from where a road user goes ("out of my lane", "behind me the whole way") or
from the one who let it go ("stopped for a man on the pavement to cross") reads the clause's verb as
the road user's own, done. Three structures say otherwise, whatever the words: a counterfactual ("I
would have stopped for him to cross", "if the van had moved out of my lane": what did not happen), a
yes/no question whose subject the road user is ("Was that van behind us the whole way?": it asserts
nothing), and a passive ("was pulled out of my lane by the tow truck": the road user is moved, and
the doer is another). Each test is the reader's own: :func:`ego_speed.counterfactual` for the
clause of what did not happen, :mod:`scene`'s openers of a question proper and
:data:`protagonist.PASSIVE_VOICE` for a passive.
"""

from __future__ import annotations

from vei_scenario.language.ego import SENTENCE_END
from vei_scenario.language.ego_speed import counterfactual
from vei_scenario.language.protagonist import PASSIVE_VOICE
from vei_scenario.language.scene import OPENERS, YES_NO_OPENERS

#: How many words may stand between a yes/no question's opening auxiliary and the head of its subject
#: ("Was the white car ...", "Did that big old van ...").
_SUBJECT_REACH = 4
#: Words that deny the condition of a counterfactual: "if I hadn't stopped for her to cross, ..." says
#: what did happen (as :mod:`scene` keeps it).
_DENIED = frozenset(("not", "n't", "never"))
#: Adverbs between a passive auxiliary and its participle ("was slowly pushed", "got just nudged").
_BETWEEN = frozenset(("just", "slowly", "suddenly", "then", "also", "gradually"))


def undone(tokens: list[str], i: int) -> bool:
    """Whether the word at ``tokens[i]`` is said in a clause of what did not happen
    (:func:`ego_speed.counterfactual`: "would have", "could have", "if ... had"), its condition not denied."""
    if not counterfactual(tokens, i):
        return False
    start = max((k + 1 for k in range(i) if tokens[k] in SENTENCE_END), default=0)
    return not (set(tokens[start:i]) & _DENIED and "if" in tokens[start:i])


def asked_of(tokens: list[str], i: int) -> bool:
    """Whether the noun (or pronoun) at ``tokens[i]`` is the subject of a yes/no question: its sentence
    ends with "?" and opens (past a word like "so") with an auxiliary or a modal, the noun at most
    :data:`_SUBJECT_REACH` words after it with no comma between ("Was that van behind us the whole
    way?", "Did the van drift out of my lane?"). A wh-question ("Why was the van behind us?") takes
    what it asks about as given, a statement asked back ("A van was behind us, wasn't it?") states it,
    and a request names its road user further on, in a clause of its own ("Can you make a scenario
    where a van follows me?")."""
    start = max((k + 1 for k in range(i) if tokens[k] in SENTENCE_END), default=0)
    end = next((k for k in range(i, len(tokens)) if tokens[k] in SENTENCE_END), len(tokens))
    if end >= len(tokens) or tokens[end] != "?":
        return False
    while start < i and tokens[start] in OPENERS:
        start += 1
    return tokens[start] in YES_NO_OPENERS and 0 < i - start <= _SUBJECT_REACH and "," not in tokens[start:i]


def passive_at(tokens: list[str], i: int) -> bool:
    """Whether the verb at ``tokens[i]`` is a participle after a passive auxiliary
    (:data:`protagonist.PASSIVE_VOICE`; "was pulled", "got pushed", "had been moved"), adverbs between."""
    if tokens[i].endswith("ing"):
        return False
    k = i - 1
    while k >= 0 and tokens[k] in _BETWEEN:
        k -= 1
    return k >= 0 and tokens[k] in PASSIVE_VOICE
