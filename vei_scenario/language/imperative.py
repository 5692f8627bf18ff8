"""A line that tells the ego what to do, as a test case's title or step does ("Follow a decelerating
van", "Overtake a cyclist riding at the road edge", "Title: Approach a stationary lorry"), said with
its subject: "the ego follows a decelerating van".

Why: an imperative has no subject in its words; its doer is the one addressed, the vehicle under test.
Read as it stands, the road user after the verb is the only one named beside it and is taken for the
verb's doer ("a van that follows", "a cyclist that overtakes"). Only verbs of what the ego does to
another road user, and only where a road user (an article, a number) follows the verb: "Pass criteria"
and "Follow-up" are no commands."""

from __future__ import annotations

import re
from functools import lru_cache

from vei_scenario.language import lexicon as L

#: Verbs of the ego's own act on the road user after them.
_EGO_ACTS = ("follow", "overtake", "pass", "approach", "undertake")
#: Labels of a test case's lines whose command is the ego's ("Title: Follow a van", "Step 2: overtake
#: ..."); a road user's name as a label ("Cyclist: pass the ego") gives that road user its command.
_LABELS = (
    "title", "name", "summary", "objective", "goal", "purpose", "test", "test case", "case", "scenario",
    "scenario outline",
    "description", "task", "action", "procedure", "ego", "vut", "sut", "step", r"step\s*\d{1,2}",
)  # fmt: skip
#: Where a line's command starts: the text's start, or a line after a line that ends a sentence or a
#: label (not a line of prose wrapped mid-sentence), after a case's identifier, a step's number or a
#: bullet, or one of :data:`_LABELS` and its colon.
_COMMAND = re.compile(
    r"(\A(?:[ \t]*@[^\n]*\n)*|[.:!?][ \t]*\n|\n[ \t]*\n|\n[ \t]*@[^\n]*\n)"  # (after Gherkin tags too)
    r"([ \t]*(?:[a-z0-9_.-]*\d[a-z0-9_.-]*[ \t]+)?"  # (a case's identifier: "ACC-FOL-012  Follow ...")
    rf"(?:(?:step\s*)?\d{{1,2}}[.):]\s*|[-*\u2022]\s*|(?:{'|'.join(_LABELS)})\s*:\s*)?)"
    rf"({'|'.join(_EGO_ACTS)})(\s+(?:a|an|the|two|three)\s+((?:[a-z'-]+\s+){{0,3}}[a-z'-]+))",
)
#: The command's verb as the ego's ("the ego follows a van").
_THIRD_PERSON = {"follow": "follows", "overtake": "overtakes", "pass": "passes", "approach": "approaches",
                 "undertake": "undertakes"}  # fmt: skip


@lru_cache(maxsize=1)
def _road_user_nouns() -> frozenset[str]:
    """The last words of the lexicon's road-user nouns ("van", "cyclist", "rider")."""
    phrases = [p for words in L.ACTOR_NOUNS.values() for p in words] + list(L.CAR_NOUNS)
    return frozenset(p.split()[-1] for p in phrases)


def _command(m: re.Match) -> str:
    words = m.group(5).split()
    if not set(words) & _road_user_nouns():
        return m.group(0)  # ("Follow the signs for the A38": no road user it is done to)
    return f"{m.group(1)}{m.group(2)}the ego {_THIRD_PERSON[m.group(3)]}{m.group(4)}"


def imperative_as_ego(text: str) -> str:
    """``text`` (lowercased) with each line's command to the ego on a road user given its subject:
    "the ego follows a decelerating van"."""
    return _COMMAND.sub(_command, text)
