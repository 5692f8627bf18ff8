"""A negation whose verb is left out: "the truck behind does not → we get rear-ended", "I stopped,
he did not". An auxiliary "do" with "not" and no verb after it stands for the verb said before
("does not [stop in time]"); what follows belongs to another clause even where the writer put no
punctuation between them, so the negation denies nothing that follows it.
"""

from __future__ import annotations

#: The forms of "do" that carry a negation.
_DO = frozenset(("do", "does", "did"))
#: Words that open a noun phrase or are a subject: no verb follows "not" when one of these does.
_PHRASE_OPENERS = frozenset(
    ("the", "a", "an", "my", "our", "his", "her", "their", "its", "your", "this", "that", "these", "those",
     "i", "we", "he", "she", "they", "you", "ego")
)  # fmt: skip


def elliptical_negation(words: list[str], k: int) -> bool:
    """Whether the negator at ``k`` is "do not" with its verb left out: a form of "do" before it and
    the start of a noun phrase or a subject right after it."""
    return (
        words[k] == "not" and k > 0 and words[k - 1] in _DO and k + 1 < len(words) and words[k + 1] in _PHRASE_OPENERS
    )
