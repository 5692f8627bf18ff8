"""A speed said in a participle phrase right after a road user who is the object of someone's verb or
preposition: the speed is that road user's.

Why: "I turned right across a cyclist approaching at 20 km/h", "the ego starts its turn in front of a
motorbike coming at 60 km/h", "we pulled out ahead of a lorry closing on us at 40 mph": English puts a
participle phrase right after the noun it modifies, so whoever the clause's subject is (the ego, here),
"approaching at 20 km/h" says how the cyclist comes, not how the subject goes. Without a participle, a
speed after the object of a preposition is the subject's ("I was behind this bus at 20 mph"), and
stays so.
"""

from __future__ import annotations

from vei_scenario.language.lemmas import lemmas

#: Words a participle of going may have between it and its speed: where it goes ("towards us", "up the
#: inside", "the other way"), "at", and a hedge on the number ("at about", "at maybe").
_PHRASE = frozenset(
    {"at", "about", "around", "roughly", "approximately", "approx", "maybe", "some", "~", "an", "estimated",
     "towards", "toward", "me", "us", "the", "ego", "up", "down", "along", "on", "in", "fast", "quickly",
     "straight", "head-on", "other", "way", "opposite", "direction"}
)  # fmt: skip
#: How many words such a phrase may run to between its participle and the speed.
_REACH = 5


def participle_phrase(tokens: list[str], after_noun: int, number: int) -> bool:
    """Whether the words from ``after_noun`` (right after a road user's name) up to the speed's number at
    ``number`` are a participle phrase of that road user: a verb's -ing form first ("approaching",
    "coming", "closing", "heading"), then only where it goes, "at" and a hedge ("approaching at 20 km/h",
    "heading towards us at about 30", "coming the other way at 50"). Not a comma or a conjunction
    between (", doing 40 mph": an aside the clause's grammar reads), nor a clause of its own."""
    if not after_noun < number <= after_noun + 1 + _REACH:
        return False
    first = tokens[after_noun]
    if not (first.endswith("ing") and len(first) > 4 and "VERB" in lemmas(first)):
        return False
    return all(w in _PHRASE for w in tokens[after_noun + 1 : number])
