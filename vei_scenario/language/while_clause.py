"""A clause opened by "while" inside a sentence is background: a verb after it that leaves its subject
out goes on from the sentence's main clause, not from the background's subject.

Why: "A lorry pulled out in front of me while I was doing 50, then crawled along at 15 mph": "then
crawled" is coordinated with "pulled out", the main verb, so the lorry crawls, and its 15 mph is the
lorry's, not the narrator's (whose 50 the "while" clause says). A reader that lets the subject named
last go on gives the lorry's speed and act to the narrator. Only where the "while" clause stands inside
its sentence, after a main clause, and names one subject: a sentence that opens with "While I was
waiting, a van pulled out, then ..." goes on from its main clause's subject, the one named last.

A narrator's main clause is often the background itself: "I was doing 30 while a cyclist rode along the
kerb, then swerved into my lane", "I kept my speed while ...": a main clause that only says the
narrator's speed or state (a form of "be" and a verb in -ing, or "kept") lets the "while" clause's
subject go on. Nor does the narrator go on into a verb said of the narrator ("..., then cut in front of
me", "into my lane"): no one does that to themself.
"""

from __future__ import annotations

from typing import Any

from vei_scenario.language.clauses import sentence_start, sentence_stop
from vei_scenario.language.ego import BE, FIRST_PERSON, NARRATOR_INVOLVED
from vei_scenario.language.lemmas import lemmas

#: What may stand right before the "while" of a clause that opens its sentence (no main clause before it).
_SENTENCE_OPENERS = frozenset({"", ".", "!", "?", ";", ":"})
#: Where a sentence ends, for the words of a clause up to it.
_SENTENCE_ENDS = frozenset({".", "!", "?", ";"})


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


def main_subject(subject: Any, tokens: list[str], at: int) -> Any:
    """The subject of the main clause before the "while" at token ``at`` that a "then" verb goes on
    from: ``subject`` (the reader's, the one named last), or None when that clause only says the
    narrator's speed or state ("I was doing 30", "I was cruising at 60", "I kept my speed", "following a
    bus" once the reader has taken the narrator's "I was"): then the "while" clause is what goes on."""
    words = tokens[sentence_start(tokens, at, _SENTENCE_ENDS) : at]
    if words and words[0].endswith("ing") and "VERB" in lemmas(words[0]) and "," not in words:
        return None  # ("I was following a bus", the narrator's words already read: "following a bus")
    if not words or words[0] not in FIRST_PERSON:
        return subject
    progressive = any(w in BE and nxt.endswith("ing") for w, nxt in zip(words, words[1:], strict=False))
    kept = len(words) > 1 and "keep" in lemmas(words[1]).get("VERB", ())
    return None if progressive or kept else subject


def goes_on_from_the_main_clause(
    mentions: list[Any], background: list[tuple[Any, str]], main: Any = None, tokens: list[str] | None = None
) -> bool:
    """Whether the clause ``mentions``, right after a "while" clause that named the one subject in
    ``background`` (its named road users and their roles), opens with "then" and a verb with its subject
    left out ("..., then crawled along at 15 mph"): that verb's subject is the main clause's, ``main``.
    Not where that is the narrator and the clause (in ``tokens``) is said of the narrator ("then cut in
    front of me", "into my lane")."""
    if not mentions or mentions[0].slot != "link" or mentions[0].value != "sequence":
        return False
    if sum(role == "subject" for _, role in background) != 1:
        return False
    if main == "ego" and tokens is not None:
        start = mentions[0].start
        if any(w in NARRATOR_INVOLVED for w in tokens[start : sentence_stop(tokens, start, _SENTENCE_ENDS)]):
            return False
    first = next((m for m in mentions[1:] if m.slot not in ("punct", "criticality")), None)
    return first is not None and first.slot not in ("actor", "pronoun", "count")
