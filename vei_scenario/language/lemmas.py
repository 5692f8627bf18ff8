"""English lemmas by part of speech, from lemminflect, looked up once per word.

Every part of the reader that asks what a word is (a verb's lemma, a known English word, a singular
noun) asks here, so a word is looked up once per process however many parts ask. The dictionaries
returned are shared: read them, never change them.
"""

from __future__ import annotations

from functools import lru_cache


@lru_cache(maxsize=16384)
def lemmas(word: str) -> dict[str, tuple[str, ...]]:
    """lemminflect's lemmas of ``word`` by part of speech (``{}`` for a word it does not know)."""
    from lemminflect import getAllLemmas

    return getAllLemmas(word)


def english(word: str) -> bool:
    """Whether lemminflect knows ``word`` as an English word."""
    return bool(lemmas(word))
