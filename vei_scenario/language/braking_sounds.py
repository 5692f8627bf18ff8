"""The sound of a hard brake told as what happened ("tyres screeched", "with a screech of brakes",
"Screeeech."): the noise locked or skidding tyres make is heard only when someone brakes as hard as
they can, so a text that tells it tells an emergency stop, whoever made it.

A screech is that sound in any use. A squeal is a braking sound only said of tyres, brakes or wheels
("brakes squealing", "a squeal of tyres"): children and pigs squeal too. Sound words are often spelt
drawn out ("SKREEEECH"), which no dictionary knows, so the drawn-out spellings are matched by their
shape.
"""

from __future__ import annotations

import re

from vei_scenario.language.lemmas import lemmas

#: What squeals when a vehicle brakes hard.
_BRAKING_PARTS = frozenset(("tyres", "tyre", "tires", "tire", "brakes", "brake", "wheels", "wheel", "rubber"))
#: A screech spelt as it sounds, its vowel drawn out ("screeeech", "skreeeeech", "scrEEEch" lowercased).
_DRAWN_OUT_SCREECH = re.compile(r"s[ck]r+e{2,}ch(ed|es|ing)?")
_DRAWN_OUT_SQUEAL = re.compile(r"squea+l(ed|s|ing)?")


def _lemma_of(word: str, lemma: str, drawn_out: re.Pattern[str]) -> bool:
    """Whether ``word`` is a form of ``lemma`` or its drawn-out spelling."""
    return any(lemma in forms for forms in lemmas(word).values()) or drawn_out.fullmatch(word) is not None


def braking_sound(words: list[str], i: int) -> bool:
    """Whether ``words[i]`` tells the sound of a hard brake: a screech, or a squeal of tyres or brakes
    said in its clause."""
    w = words[i]
    if _lemma_of(w, "screech", _DRAWN_OUT_SCREECH):
        return True
    return _lemma_of(w, "squeal", _DRAWN_OUT_SQUEAL) and bool(_BRAKING_PARTS & set(words))
