"""A form's fields of witnesses and of injuries: road users named there do not act there.

Accident statements, police and insurers' forms and survey exports have a field for the witnesses
("Witness: driver of the tanker behind me, J. Barker", "Witnesses: 2 people at bus stop, details
taken", "Getuigen: tram driver stopped, name not known") and one for the injured ("Injuries: the
scooter rider, small cut on hand", "Gewonden: ja, the cyclist has light wound on the hand"). Read as
road users, those named there become adversaries of their own that do whatever the nearest verb
says: a witness watched the scene, and the injured is one of the parties named again.

A field is told by its label opening a line or sentence, then a colon; its value runs to the end of
its sentence. The label is a word for witness or for the injured, in English or in the languages of
the European accident statement as writers type them, with at most a word of what the field holds
("Witness details:", "Injured persons:"). A label that opens more than one turn, or a turn after a
question, is a transcript's speaker ("WITNESS: A taxi ran the red"), no field.

A field whose value tells a deed on the road ("Witness: the lorry ran the red light", "Injuries: the
cyclist fell off when he rode into my door": a verb of :data:`_DEEDS`) holds an account and stays.

- A witnesses' field's value is taken out where it names one road user (the witness), unless it
  holds an account: "Witness statement:" is no list of who saw it (its second word is not one of
  :data:`_LISTED`); a value that names two road users ("the hatchback was on the roundabout when a
  moped came in"), or none, or the writer as "I" or "we" is an account; and a value in which
  someone tells or sees what a road user did ("a man at the stop said the van went through red")
  carries that road user, which the rules for witnesses who speak read.
- An injuries' field's value is taken out where every kind of road user it names is named elsewhere
  in the text: it names the parties again. Where it is the only place a kind is named ("Injuries:
  scooter rider cut on chin", the rest saying only "B"), it is how the text names that party, and it
  stays.
"""

from __future__ import annotations

from collections.abc import Callable

from vei_scenario.language.ego import SENTENCE_END, lemma_in
from vei_scenario.language.lemmas import lemmas

#: Labels of a witnesses' field: English, and the European accident statement's Dutch, German,
#: Spanish, Italian and Portuguese field names.
_WITNESS = frozenset(
    {"witness", "witnesses", "getuige", "getuigen", "zeuge", "zeugen", "testigo", "testigos", "testimone",
     "testimoni", "testemunha", "testemunhas"}
)  # fmt: skip
#: Labels of an injuries' field, the same way.
_INJURED = frozenset(
    {"injuries", "injury", "injured", "inj", "casualties", "casualty", "gewonden", "verletzte", "verletzt",
     "heridos", "feriti", "feridos"}
)  # fmt: skip
#: A second word of the label that still names a list ("Witness details:", "Injured persons:").
_LISTED = frozenset(
    {"details", "detail", "name", "names", "contact", "contacts", "info", "present", "persons", "people"}
)
#: The writer as a subject: a value with one of these is the writer's account.
_WRITER = frozenset({"i", "we"})
#: Verbs (by lemma) of seeing or telling: after one, what a road user did is told.
_TELLING = frozenset({"say", "tell", "state", "see", "watch", "notice", "claim", "report", "confirm"})

KindAt = Callable[[list[str], int], "tuple[str, int] | None"]


def _named(tokens: list[str], kind_at: KindAt) -> list[str]:
    """The kinds of road user named in ``tokens``, one per mention, the ego's left out; a person and
    what they drive or ride ("driver of the tanker", "bus driver") are one mention."""
    kinds: list[str] = []
    k, joined_at = 0, -1
    while k < len(tokens):
        found = kind_at(tokens, k)
        if found is not None and found[0] != "ego" and k != joined_at:
            kinds.append(found[0])
        if found is not None:
            after = k + found[1]
            joined_at = after  # ("bus driver", "scooter rider": one person, by what they drive)
            if tokens[after : after + 1] == ["of"]:
                joined_at = after + 1 + (tokens[after + 1 : after + 2] in (["the"], ["a"], ["an"]))
        k += found[1] if found is not None else 1
    return kinds


def _tells_of_a_road_user(value: list[str], kind_at: KindAt) -> bool:
    """Whether a verb of seeing or telling in ``value`` has a road user after it."""
    for k, word in enumerate(value):
        if lemma_in(word, _TELLING):
            return bool(_named(value[k + 1 :], kind_at))
    return False


#: Verbs (by lemma) of a road user's deed on the road: a field's value with one tells what happened.
_DEEDS = frozenset(("go", "run", "hit", "pull", "turn", "cross", "travel", "drive", "ride", "come", "cut", "overtake",
                    "swerve", "strike", "collide", "crash", "mount", "reverse", "jump", "step", "walk", "speed",
                    "race", "fly", "shoot", "knock", "brake", "fall", "veer", "dart", "emerge", "enter"))  # fmt: skip


def _noun_here(value: list[str], k: int) -> bool:
    """Whether the word at ``value[k]`` is a noun there, after an article, an owner or an adjective
    ("a small cut on the hand", "his fall"): no deed."""
    before = value[k - 1] if k > 0 else ""
    return before in _NOUN_OPENERS or "ADJ" in lemmas(before)


#: Words after which a verb's form is a noun.
_NOUN_OPENERS = frozenset(("a", "an", "the", "his", "her", "their", "my", "its", "our", "no", "minor", "bad"))


def _aside(tokens: list[str], label: str, value: list[str], start: int, end: int, kind_at: KindAt) -> bool:
    """Whether the field with ``label`` and ``value`` (at ``tokens[start:end]``) names no road user
    that acts (see the module's docstring)."""
    named = _named(value, kind_at)
    if any(lemma_in(w, _DEEDS) and not kind_at(value, k) and not _noun_here(value, k) for k, w in enumerate(value)):
        return False  # ("Witness: the lorry ran the red", "Injuries: the cyclist fell off when he rode into")
    if label in _WITNESS:
        return len(named) == 1 and not _WRITER & set(value) and not _tells_of_a_road_user(value, kind_at)
    return bool(named) and set(named) <= set(_named(tokens[:start] + tokens[end:], kind_at))


def without_aside_fields(tokens: list[str], kind_at: KindAt, dropped: list[str]) -> list[str]:
    """``tokens`` without the values of their witnesses' and injuries' fields where these name no road
    user that acts (see the module's docstring); the words taken out are added to ``dropped``, so the
    run says it did not use them. The witnesses go first: one named only there names no party."""
    return _without(_without(tokens, _WITNESS, kind_at, dropped), _INJURED, kind_at, dropped)


def _speaker(tokens: list[str], i: int, label: str) -> bool:
    """Whether ``label`` at ``tokens[i]`` names who speaks in a transcript, not a form's field: it
    labels more than one turn ("WITNESS: Evening. ... WITNESS: A taxi ran the red"), or its turn
    answers a question ("Q: And then? WITNESS: ...")."""
    labels = sum(
        1
        for k, w in enumerate(tokens[:-1])
        if w == label and tokens[k + 1] == ":" and (k == 0 or tokens[k - 1] in SENTENCE_END)
    )
    return labels > 1 or tokens[i - 1 : i] == ["?"]


def _without(tokens: list[str], labels: frozenset[str], kind_at: KindAt, dropped: list[str]) -> list[str]:
    """``tokens`` without the values of the fields labelled by one of ``labels`` that are aside."""
    out: list[str] = []
    i = 0
    while i < len(tokens):
        label = tokens[i]
        if (i == 0 or tokens[i - 1] in SENTENCE_END) and label in labels and not _speaker(tokens, i, label):
            colon = i + 1 + (tokens[i + 1 : i + 2] != [] and tokens[i + 1] in _LISTED)
            if tokens[colon : colon + 1] == [":"]:
                end = colon + 1
                while end < len(tokens) and tokens[end] not in SENTENCE_END:
                    end += 1
                if _aside(tokens, label, tokens[colon + 1 : end], i, end, kind_at):
                    dropped.extend(w for w in tokens[i:end] if w.isalpha())
                    i = end
                    continue
        out.append(label)
        i += 1
    return out
