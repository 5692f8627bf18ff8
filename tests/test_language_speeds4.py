"""A speed said in a participle phrase right after a road user who is the object of a verb or a
preposition ("I turned right across a cyclist approaching at 20 km/h") is that road user's: the phrase
modifies the noun it follows, whoever the clause's subject is. A speed said of the clause's subject,
or after an object with no participle ("I was behind this bus at 20 mph"), stays the subject's.

Every wording here is written for these tests (none is from a corpus)."""

from __future__ import annotations

import pytest

from vei_scenario.language.reader import read
from vei_scenario.language.rules_backend import layers_from_text


def _speeds(text: str) -> tuple[float | None, list[float | None]]:
    """The ego's speed and each road user's, in km/h to one decimal (None: not said)."""
    r = read(text)
    kph = lambda mps: None if mps is None else round(mps * 3.6, 1)  # noqa: E731
    return kph(r.ego_speed_mps), [kph(a.speed_mps) for a in r.actors]


@pytest.mark.parametrize(
    ("text", "kph"),
    [
        ("The test car turns left across a cyclist approaching at 20 km/h from the opposite direction.", 20),
        ("We were waiting to turn right across an oncoming van approaching at 50 km/h.", 50),  # (a report)
        ("The ego vehicle starts a right turn in front of a motorbike approaching at 60 km/h.", 60),  # (a spec)
        ("I turned right across a cyclist coming at 20 km/h.", 20),  # (a plain story)
        ("I turned right across a cyclist heading towards me at about 20 km/h.", 20),  # (with where it goes)
        ("I pulled out of the side road in front of a lorry closing fast at 40 mph.", 64.4),  # (British)
    ],
)
def test_a_speed_in_a_participle_after_an_object_is_the_objects(text, kph):
    ego, others = _speeds(text)
    assert others == [pytest.approx(kph, abs=0.2)]
    assert ego != pytest.approx(kph, abs=0.2)


def test_the_layers_carry_it_as_the_road_users_speed():
    layers = layers_from_text("The AV must not turn right across a motorcyclist approaching at 45 km/h.", 0)
    assert [round(a["speed_mps"] * 3.6) for a in layers["adversaries"]] == [45]


@pytest.mark.parametrize(
    ("text", "ego_kph"),
    [
        ("I was behind this bus at 20 mph when it stopped.", 32.2),  # (no participle: the subject's)
        ("The ego follows a lorry at 80 km/h.", 80),  # (the follower keeps it)
        ("I was approaching at 30 km/h when a cyclist came out of a side road.", 30),  # (the subject's own)
        ("I pulled out in front of a lorry, doing 40 mph.", 64.4),  # (an aside after a comma: the subject's)
    ],
)
def test_a_speed_of_the_subject_stays_the_subjects(text, ego_kph):
    ego, _ = _speeds(text)
    assert ego == pytest.approx(ego_kph, abs=0.2)


def test_a_participle_of_the_subject_keeps_its_speed():
    """The subject's own participle phrase ("a van approaching at 50 km/h hit ..."): still the van's."""
    ego, others = _speeds("A van approaching at 50 km/h pulled across in front of me.")
    assert others == [pytest.approx(50, abs=0.2)]


# A "while" clause inside a sentence is background: "then" and a verb with no subject after it go on
# from the main clause's subject, whose speed it is.
@pytest.mark.parametrize(
    ("text", "ego_kph", "other_kph"),
    [
        (
            "A van pulled out of a side road in front of me while I was doing 40 km/h, then crawled along at "
            "about 10 km/h.",
            40,
            10,
        ),  # (a plain story)
        (
            "Tractor came out of a field gate ahead of us while we were doing 50, then crawled along at 15 mph.",
            80.5,
            24.1,
        ),  # (British, the unit said after)
        (
            "The bus left the stop in front of the ego while the ego was travelling at 30 km/h, then moved off "
            "at 20 km/h.",
            30,
            20,
        ),  # (a test note)
    ],
)
def test_a_verb_after_a_while_clause_goes_on_from_the_main_subject(text, ego_kph, other_kph):
    ego, others = _speeds(text)
    assert ego == pytest.approx(ego_kph, abs=0.2)
    assert others == [pytest.approx(other_kph, abs=0.2)]


@pytest.mark.parametrize(
    "text",
    [
        "While I was doing 40 km/h, a van pulled out, then crawled along at 10 km/h.",  # (opens its sentence)
        "A van pulled out while I was doing 40 km/h, then I braked to 10 km/h.",  # (its own subject)
    ],
)
def test_a_while_clause_that_opens_its_sentence_or_a_new_subject_reads_as_before(text):
    ego, others = _speeds(text)
    assert ego == pytest.approx(40, abs=0.2)
    assert 40 not in [o and round(o) for o in others]
