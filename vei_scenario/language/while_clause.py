"""A clause opened by "while" inside a sentence is background: a verb after it that leaves its subject
out goes on from the sentence's main clause, not from the background's subject.

Why: "A lorry pulled out in front of me while I was doing 50, then crawled along at 15 mph": "then
crawled" is coordinated with "pulled out", the main verb, so the lorry crawls, and its 15 mph is the
lorry's, not the narrator's (whose 50 the "while" clause says). A reader that lets the subject named
last go on gives the lorry's speed and act to the narrator. Only where the "while" clause stands inside
its sentence, after a main clause, and names one subject: a sentence that opens with "While I was
waiting, a van pulled out, then ..." goes on from its main clause's subject, the one named last.
"""

from __future__ import annotations

from typing import Any

#: What may stand right before the "while" of a clause that opens its sentence (no main clause before it).
_SENTENCE_OPENERS = frozenset({"", ".", "!", "?", ";", ":"})


def inside_its_sentence(link: str, mentions: list[Any]) -> bool:
    """Whether the clause ``mentions`` (the reader's, ``link`` its kind) is a "while" clause after a main
    clause of its own sentence ("..., while I was doing 50"): its first mention is the word that links it,
    with no sentence's end right before it."""
    return (
        link == "parallel"
        and bool(mentions)
        and mentions[0].slot == "link"
        and mentions[0].prev not in _SENTENCE_OPENERS
    )


def goes_on_from_the_main_clause(mentions: list[Any], background: list[tuple[Any, str]]) -> bool:
    """Whether the clause ``mentions``, right after a "while" clause that named the one subject in
    ``background`` (its named road users and their roles), opens with "then" and a verb with its subject
    left out ("..., then crawled along at 15 mph"): that verb's subject is the main clause's."""
    if not mentions or mentions[0].slot != "link" or mentions[0].value != "sequence":
        return False
    if sum(role == "subject" for _, role in background) != 1:
        return False
    first = next((m for m in mentions[1:] if m.slot not in ("punct", "criticality")), None)
    return first is not None and first.slot not in ("actor", "pronoun", "count")
