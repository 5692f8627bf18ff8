"""The other party of an accident statement named by its letter: "Vehicle B: Citroen Dispatch van, ...",
then "B reverses out of a driveway on my right".

The European Accident Statement (constat amiable, Unfallbericht, schadeformulier) names its two
vehicles A and B, and people who type theirs out keep the letters: a line per party opens with its
letter ("Vehicle A: me, Mazda 3", "B (Audi Q5 2-ABD-118): 7", "Voertuig B: fietser (cyclist)"), and the
sketch and remarks then say "B came out", "I hit B". The letter of the party that is not the writer is
that party's road user, as "V2" is in a police narrative; said as "the <noun>" its line names, the
reader takes what B does as that road user's ("the rider (B)" is that one already). The writer's labels
are the ego's ("Vehicle A: BMW 320d, driver: me" is no road user; "Circumstances A: 12 - was turning right"
is what the ego did); elsewhere the writer is "I", and a lowercased "a" cannot be told from the article.

Only a text that labels both letters at the start of a line (or after a heading's dash), one of them with
a word of the form's ("Vehicle", "Circumstances", "Fahrzeug" ...), is such a statement; the other letter is
the one whose label's line does not say the writer ("me", "mine", "I", "ich" ...), B where neither or both
do.
"""

from __future__ import annotations

import re
from collections.abc import Callable

from vei_scenario.language.vocabulary import GENERAL_VEHICLE

#: A party's label opening a line (or after a dash that ends its heading): its letter, after a word of the
#: form's for a vehicle, a driver or the boxes ticked, in the languages of the form, before a colon or an
#: equals sign, with an aside in brackets between ("A (me, Citroen C3): 6", "Circumstances B: 17").
_LABEL = re.compile(
    r"(?:^|(?<=\s[-\u2013\u2014]\s))[ \t]*(?:(?P<form>vehicle|veh\.?|v[ée]hicule|fahrzeug|voertuig|veicolo|"
    r"veh[íi]culo|pojazd|driver|party|conducteur|fahrer|bestuurder|conducente|conductor|kierowca|circumstances|"
    r"circonstances|umst(?:ä|ae)nde|omstandigheden|circostanze|circunstancias|boxes|remarks)[ \t]+)?"
    r"(?P<letter>[ab])[ \t]*(?P<aside>\([^)\n]*\))?[ \t]*[:=]",
    re.MULTILINE,
)
#: The writer's words in a label's line ("Vehicle A: me, ...", "A (mine)", "Fahrer: ich").
_WRITER = re.compile(r"\b(?:me|mine|myself|i|moi|ich|ik|io|yo)\b")
#: The letter alone in the text ("B reversed", "I hit B", "the B driver"), with a "the" before it, not a road's
#: class ("a B-road", "the B4521"), a shop ("B&Q"), one of a pair ("lane A/B") or an item ("b) it reversed").
_LETTER = r"(?<![\w'&/-])(the )?{}(?![\w'&/)-])"
#: Words before a letter that name no party but a place or a choice ("exit B", "from point A to point B").
_NOT_A_PARTY = frozenset(
    "point exit lane gate plan option junction side zone type class category section box route platform line "
    "terminal entrance car-park level block".split()
)


def _after_letter(text: str, m: re.Match) -> str:
    """What label ``m``'s line says after its letter (its aside too: "(me, Citroen C3): 6")."""
    end = text.find("\n", m.end())
    return text[m.end("letter") : end if end >= 0 else len(text)]


def _party_noun(line: str, known_noun: Callable[[str], str | None]) -> str | None:
    """The road user a party's line names: the first of its parts (between commas and brackets) that ends
    in a road user's noun, past a vehicle in general and one said not to be there ("no vehicle, it is an
    e-scooter")."""
    for part in re.split(r"[,()]", line):
        noun = known_noun(part)
        if noun and noun not in GENERAL_VEHICLE and not re.match(r"\s*(?:no|not|without)\b", part):
            return noun
    return None


def _said_as(text: str, letter: str, noun: str) -> str:
    """``text`` with the party's ``letter`` said as "the <noun>", where it is the party (:data:`_LETTER`)."""

    def party(m: re.Match) -> str:
        before = text[max(0, m.start() - 20) : m.start()].split()
        return m.group(0) if before and before[-1] in _NOT_A_PARTY else f"the {noun}"

    return re.sub(_LETTER.format(letter), party, text)


def lettered_parties(text: str, known_noun: Callable[[str], str | None]) -> str:
    """``text`` (lowercased, lines kept) with the other party's letter said as "the <noun>" its label's line
    names and the writer's labels as the ego's (:mod:`module docs <vei_scenario.language.lettered_parties>`);
    unchanged where the text is no statement by letters (no label says a vehicle, a driver or the boxes), the
    writer is B, or the other party's line names no road user (``known_noun(phrase)``: the road-user noun a
    phrase ends in)."""
    labels = list(_LABEL.finditer(text))
    if {m.group("letter") for m in labels} != {"a", "b"} or not any(m.group("form") for m in labels):
        return text  # ("A: the lead car brakes. B: it turns": a list of variants, or a dialogue's speakers)
    writers = {m.group("letter") for m in labels if _WRITER.search(_after_letter(text, m))}
    other = "a" if writers == {"b"} else "b"
    if other == "a":
        return text  # (the article "a" and the letter are one word once lowercased)
    said = (_after_letter(text, m) for m in labels if m.group("letter") == other)
    noun = next(filter(None, (_party_noun(line, known_noun) for line in said)), None)
    if noun is None:
        return text
    # the letter in brackets right after a road user's noun ("the rider (B) hurt his shoulder") says which
    # party that one is: the noun is already the party
    text = re.sub(rf"(?<=[a-z])[ \t]*\([ \t]*{other}[ \t]*\)", "", text)
    labels = list(_LABEL.finditer(text))
    out, pos = [], 0
    for m in labels:  # (the other's labels stay as written: only its letter elsewhere is the party)
        out.append(_said_as(text[pos : m.start()], other, noun))
        # the writer's label is the ego's ("Vehicle A: BMW 320d, driver: me", "Circumstances A: was turning
        # right": the ego's car and what the ego did)
        out.append(
            text[m.start() : m.end()] if m.group("letter") == other else "the ego" + text[m.end("letter") : m.end()]
        )
        pos = m.end()
    out.append(_said_as(text[pos:], other, noun))
    return "".join(out)
