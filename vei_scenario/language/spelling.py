"""Misspelt words read as the word the reader knows that they are one slip away from.

People type fast ("stright road", "hevy trafic", "overtaeks", "roundabuot", "aftrenoon"). A word that
neither lemminflect's English dictionary nor the reader's own phrases know, and that is one edit (a
letter added, dropped, changed, or two neighbours swapped) from exactly one word the reader's phrases
use, or a form of one, is read as that word. A word any dictionary knows is never changed ("strait"
stays a strait), nor a word two edits from everything, nor one one edit from two different words
(unless only one of them is longer: a dropped letter is the commonest slip). The rule is the same for
every text, and the changes are reported as what the words were read as.
"""

from __future__ import annotations

from functools import lru_cache

from vei_scenario.language.lemmas import english, lemmas


def _edits1(word: str) -> set[str]:
    """Every string one edit from ``word`` (Norvig's enumeration, with transpositions)."""
    letters = "abcdefghijklmnopqrstuvwxyz-"
    splits = [(word[:i], word[i:]) for i in range(len(word) + 1)]
    deletes = {a + b[1:] for a, b in splits if b}
    swaps = {a + b[1] + b[0] + b[2:] for a, b in splits if len(b) > 1}
    replaces = {a + c + b[1:] for a, b in splits if b for c in letters}
    inserts = {a + c + b for a, b in splits for c in letters}
    return deletes | swaps | replaces | inserts


class Speller:
    """Corrects words against ``vocabulary`` (the reader's words and their inflected forms)."""

    def __init__(self, vocabulary: set[str]):
        from lemminflect import getAllInflections

        words = set(vocabulary)
        for w in vocabulary:
            for forms in getAllInflections(w).values():
                words.update(forms)
        self.words = frozenset(w for w in words if w.isalpha() or "-" in w)

    def _inflected_compound(self, word: str) -> bool:
        """Whether ``word`` is a hyphenated word whose last part is an inflected English word and that,
        with that part's lemma, is a known word ("e-scooters", "pick-ups"): an inflection, no slip. Read
        as the known word it would lose its number ("about e-scooters" is road users in general, "an
        e-scooter" one)."""
        head, _, last = word.rpartition("-")
        return bool(head) and any(f"{head}-{lemma}" in self.words for found in lemmas(last).values() for lemma in found)

    @lru_cache(maxsize=8192)  # noqa: B019 (one speller per process, its words fixed)
    def correct(self, word: str) -> str:
        """``word``, or the one known word it is a slip of."""
        if len(word) < 3 or not word.replace("-", "").isalpha() or word in self.words:
            return word
        if english(word) or self._inflected_compound(word):
            return word
        near = sorted(self.words & _edits1(word))
        if len(word) == 3:  # (three letters: only two neighbours swapped, "teh")
            near = [w for w in near if sorted(w) == sorted(word)]
        if len(near) > 1:  # (a letter dropped is the commonest slip: "rigt" is "right" before "rig")
            near = [w for w in near if len(w) > len(word)]
        return near[0] if len(near) == 1 else word
