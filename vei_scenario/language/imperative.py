"""A line that tells the ego what to do, as a test case's title or step does ("Follow a decelerating
van", "Overtake a cyclist riding at the road edge", "Title: Approach a stationary lorry"), said with
its subject: "we follow a decelerating van".

Why: an imperative has no subject in its words; its doer is the one addressed, the vehicle under test.
Read as it stands, the road user after the verb is the only one named beside it and is taken for the
verb's doer ("a van that follows", "a cyclist that overtakes"). Only verbs of what the ego does to
another road user, and only where a road user (an article, a number) follows the verb: "Pass criteria"
and "Follow-up" are no commands."""

from __future__ import annotations

import re

#: Verbs of the ego's own act on the road user after them.
_EGO_ACTS = ("follow", "overtake", "pass", "approach", "undertake", "avoid", "detect")
#: Where a line's command starts: the text's start or a new line, after a case's identifier, a step's
#: number or bullet, or a label's colon.
_COMMAND = re.compile(
    r"(^|\n)([ \t]*(?:[a-z0-9_.-]*\d[a-z0-9_.-]*[ \t]+)?"  # (a case's identifier: "ACC-FOL-012  Follow ...")
    r"(?:(?:step\s*)?\d{1,2}[.):]\s*|[-*\u2022]\s*|[a-z][a-z ]{0,20}:\s*)?)"
    rf"({'|'.join(_EGO_ACTS)})(?=\s+(?:a|an|the|two|three)\s)"
)


def imperative_as_ego(text: str) -> str:
    """``text`` (lowercased) with each line's command to the ego given its subject ("we")."""
    return _COMMAND.sub(r"\1\2we \3", text)
