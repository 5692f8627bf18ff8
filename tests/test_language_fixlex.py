"""A road user's word of many words is matched whole, but some rules read a kind word by its last word
alone (the vehicle that squealed its brakes, the head of a noun phrase). A phrase of another language
that ends in a word English uses everywhere ("xe o to", Vietnamese for a car, spelled without its
accents) would make that everyday word a vehicle: "to" after any verb became a vehicle that braked, and
a stated near miss was read as a collision. No kind's phrase may end in such a word."""

from __future__ import annotations

from vei_scenario.language import lexicon as L
from vei_scenario.language.function_words import ARTICLES, DETERMINERS, PHRASE_ENDS, SUBJECT_PRONOUNS

_EVERYDAY = PHRASE_ENDS | ARTICLES | DETERMINERS | SUBJECT_PRONOUNS | {"o", "is", "it", "so", "as", "or"}


def _phrases() -> list[str]:
    return list(L.CAR_NOUNS) + [p for ps in L.ACTOR_NOUNS.values() for p in ps]


def test_no_kind_phrase_ends_in_an_everyday_english_word():
    assert [p for p in _phrases() if " " in p and p.split()[-1] in _EVERYDAY] == []
