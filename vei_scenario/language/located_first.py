"""A clause that says where before who: "From the opposite direction comes an e-scooter", "Behind us
drove a van", "Out of the side road shot a kid on a scooter".

Why: English puts a place first and the road user after its verb when the place is what links the
clause to the story (locative inversion), and German, Dutch, Polish and Turkish do it far more, so
machine translations from them are full of it ("Before it drives the truck with 20 km/h", "At the
same time comes a vehicle of the oncoming traffic"). The reader takes a clause's subject from before
its verb; with the road user after the verb, a pronoun that follows ("... and at the crossing it turns
left") and a speed said with it ("with 20 km/h") go to whoever was the subject before. Said again in
the usual order ("an e-scooter comes from the opposite direction ...") the clause means the same and
reads as any other. A time said first ("at that moment came a cyclist") stays first; a relative clause
stays with its road user ("behind the bus was a cyclist who pulled out" → "a cyclist behind the bus
pulled out"); and a road user out of sight ("out of the fog came a lorry") is left as said, since in the
usual order it would read as pulling out of a side road.

Only an intransitive verb of coming, going or standing is turned round, so a clause that drops its
subject ("At the lights passed a cyclist", "On the way home followed a van": the narrator passed,
followed) is left alone. Verbs that also take an object ("drove a van", "rode a bike", "approached a
cyclist") are turned round only after a place said from someone's point of view ("behind us", "from
the left", "in front of the ego"), where no driver says what they drove.
"""

from __future__ import annotations

import re
from collections.abc import Callable

from vei_scenario.language.function_words import SUBJECT_PRONOUNS

#: Verbs of coming, appearing and standing: no object follows them, so a road user after one is its subject.
_INTRANSITIVE = (
    "come|comes|came|appear|appears|appeared|emerge|emerges|emerged|stand|stands|stood|wait|waits|waited|"
    "shoot|shoots|shot|dart|darts|darted|is|was|are|were"
)
#: Verbs that also take an object ("drove a van"): a road user after them is their subject only after a
#: place said from someone's point of view.
_TRANSITIVE = "drive|drives|drove|ride|rides|rode|follow|follows|followed|approach|approaches|approached|run|runs|ran"
#: Prepositions that open the place.
_OPENERS = (
    r"from|behind|before|in front of|ahead of|out of|next to|beside|alongside|towards|toward|opposite|on|in|at|"
    r"along|across|around|round|into|down|up|through|over|off"
)
#: Openers and words of the place that say it from someone's point of view.
_POINT_OF_VIEW = re.compile(
    r"^(?:from|behind|before|in front of|ahead of|next to|beside|alongside|towards|toward|opposite)\b"
    r"|\b(?:me|us|him|her|them|ego|left|right|opposite|oncoming)\b"
)
_DETERMINERS = frozenset({"a", "an", "the", "my", "our", "his", "her", "their", "its", "this", "that"})
_PREPOSITIONS = frozenset(
    "from behind before front of ahead out next to beside alongside towards toward opposite on in at along across "
    "around round into down up through over off with".split()
)
#: Where a road user comes out of sight from, not a place on the road ("out of nowhere came a van", "out of
#: the fog came a lorry"): said in the usual order the reader would take it for a side road it pulls out of.
_OUT_OF_SIGHT = re.compile(
    r"\bout of (?:nowhere|the (?:mist|fog|dark|darkness|gloom|murk|haze|smoke|spray|rain|night|shadows|blue|sun))\b"
)
#: A time said first, not a place: it stays first ("at that moment a cyclist came from behind").
_TIME = re.compile(
    r"(?:at|in)\s+(?:that|this|the\s+same|the|the\s+very|that\s+very)\s+(?:moment|time|point|instant|second)"
)
#: Who rides or drives the vehicle named before ("an e-scooter rider").
_RIDERS = frozenset({"rider", "riders", "driver", "drivers", "user", "users"})
#: Subjects of a clause of their own: "it" said after a relative pronoun makes it an object's ("which it hid").
_CLAUSE_SUBJECTS = SUBJECT_PRONOUNS | {"it"}
#: Words that give the place a subject or a verb of its own: then it is no place said first.
_SUBJECTS = _CLAUSE_SUBJECTS | {"there"}
#: A relative pronoun that opens a clause whose subject is the road user ("a cyclist who pulled out"), not
#: one with a subject of its own ("an e-scooter, which I did not see").
_RELATIVE = re.compile(rf"\s*,?\s*(?:who|which|that)\s+(?!(?:{'|'.join(sorted(_CLAUSE_SUBJECTS))})\b)")

#: The verb (with its particle) and the word that opens the road user after it.
_VERB = rf"(?:{_INTRANSITIVE}|{_TRANSITIVE})(?:\s+(?:out|up|in|past|along))?"
_WHO_OPENS = r"(?:a|an|the|one|another|two|three|\d+)"
_CLAUSE = re.compile(
    rf"(?P<start>^|[.!?;:]\s+|,\s+(?:and\s+|then\s+|but\s+)?|\band\s+(?:then\s+)?)"
    rf"(?P<place>(?:suddenly\s+|then\s+)?(?:{_OPENERS})(?:\s+[\w'-]+){{1,7}}?)\s*,?\s+"
    rf"(?P<verb>{_VERB})\s+"
    rf"(?P<who>{_WHO_OPENS}\s+[^\s,.;:!?]+(?:\s+[^\s,.;:!?]+){{0,4}})"
)
_QUICK = re.compile(rf"\b{_VERB}\s+{_WHO_OPENS}\s")


def said_in_order(text: str, known_noun: Callable[[str], str | None]) -> str:
    """``text`` (lowercased) with each clause that says its place before its verb and a road user after
    it said with the road user first ("behind us drove a sprinter with small distance" → "a sprinter
    drove behind us with small distance"). ``known_noun(phrase)``: the road-user noun a phrase ends in."""
    if not _QUICK.search(text):  # (one quick pass first: most descriptions have no such clause)
        return text
    return _CLAUSE.sub(lambda m: _turned(m, known_noun), text)


def _turned(m: re.Match, known_noun: Callable[[str], str | None]) -> str:
    place, verb = m["place"], m["verb"]
    if not _a_place(place) or _OUT_OF_SIGHT.search(place):
        return m[0]
    adverb = re.match(r"(?:suddenly|then)\s+", place)  # (at most one: the clause's pattern allows one)
    adverbs = adverb[0] if adverb else ""
    bare = place[len(adverbs) :]
    if re.fullmatch(_TRANSITIVE, verb.split()[0]) and not _POINT_OF_VIEW.search(bare):
        return m[0]
    who = _road_user(m["who"], known_noun)
    if who is None:
        return m[0]
    rest = m["who"][len(who) :]
    relative = _RELATIVE.match(rest)
    if relative is None and re.match(r"\s*,?\s*(?:who|which|that)\b", m.string[m.end() :]) and not rest.strip():
        return m[0]  # (a clause about the road user beyond what was matched: left as said)
    if relative is not None:  # ("behind the bus was a cyclist who pulled out": "a cyclist behind the bus pulled out")
        what = rest[relative.end() :]
        if re.fullmatch(r"is|was|are|were", verb):
            return f"{m['start']}{adverbs}{who} {bare} {what}"
        return f"{m['start']}{adverbs}{who} {verb} {bare} and {what}"
    if _TIME.fullmatch(bare):
        return f"{m['start']}{place} {who} {verb}{rest}"  # ("at that moment a cyclist came from behind")
    bare = re.sub(r"^before (?=me\b|us\b|him\b|her\b|them\b|the ego\b)", "ahead of ", bare)
    return f"{m['start']}{adverbs}{who} {verb} {bare}{rest}"  # ("before me rode a cyclist": ahead of me)


def _a_place(place: str) -> bool:
    """Whether ``place`` is only a place: no subject of its own ("before it drives": "it" drives), and
    each determiner right after a preposition or the place's first word ("out of the side road on my
    left"; not "in the lane the car", where "the car" is a subject)."""
    words = place.split()
    if _SUBJECTS & set(words):
        return False
    for k, w in enumerate(words):
        if w in _DETERMINERS and k > 0 and words[k - 1] not in _PREPOSITIONS:
            return False
    return True


def _road_user(phrase: str, known_noun: Callable[[str], str | None]) -> str | None:
    """The shortest opening of ``phrase`` that ends in a road-user noun ("an e-scooter with 20 km/h":
    "an e-scooter"), with the vehicle its rider is on ("a woman on an e-scooter") and what it is of ("a
    vehicle of the oncoming traffic"); None when it names none."""
    words = phrase.split()
    for n in range(2, len(words) + 1):
        head = words[n - 1]
        if known_noun(head) == head:
            while n < len(words) and (known_noun(words[n]) == words[n] or words[n] in _RIDERS):
                n += 1  # ("an e-scooter rider")
            if words[n : n + 1] == ["on"]:
                for k in range(n + 2, min(n + 5, len(words)) + 1):
                    if known_noun(words[k - 1]) == words[k - 1]:
                        return " ".join(words[:k])
            if words[n : n + 2] in (["of", "the"], ["of", "a"]) and len(words) > n + 2:
                return " ".join(words[: n + 3])  # ("a vehicle of the oncoming traffic")
            return " ".join(words[:n])
    return None
