"""A quotation in a text told in the third person (a news report, a letter about someone): its "I" is
the speaker the text names, not a narrator of its own (vei_scenario.language.scene.quoted_speakers)."""

from __future__ import annotations

import pytest
from reading_of import ego_kph, kinds

from vei_scenario.language.scene import quoted_speakers


@pytest.mark.parametrize(
    "text, expected_kinds, kph",
    [
        (
            "A girl stepped off the kerb on Hill Road in front of a bus. The bus driver, who was doing about 15 mph, "
            "stopped short. 'I never saw her until she was right in front of me,' he told reporters.",
            ["pedestrian"],
            24.1,
        ),
        (
            "A boy on a bike shot out of a driveway on Oak Lane. The driver of a taxi, who was going at around "
            '25 mph, braked and stopped a few feet from him. She said: "I don\'t know how I stopped in time."',
            ["bicycle"],
            40.2,
        ),
    ],
)
def test_a_quoted_i_is_the_speaker_of_a_third_person_text(text: str, expected_kinds: list[str], kph: float) -> None:
    assert kinds(text) == expected_kinds
    assert ego_kph(text) == kph


@pytest.mark.parametrize(
    "text",
    [
        # a narrator of the text's own: the quoted "I" stays where it is
        "I was doing 30 mph when a van pulled out. 'Sorry, I didn't see you,' he said.",
        # no speaker: a sign's words, not someone's report
        "The sticker on the van read 'I brake for nobody' and it pulled out.",
        # an apostrophe inside a word is no quotation mark
        "The driver's van, doing 20 mph, didn't stop. I saw it.",
    ],
)
def test_a_quotation_not_of_a_named_speaker_is_left_alone(text: str) -> None:
    assert quoted_speakers(text) == text


def test_the_quoted_first_person_takes_the_speakers_pronoun() -> None:
    said = quoted_speakers("The van stopped. 'We were lucky, my brakes held,' she said.")
    assert said == "The van stopped. 'they were lucky, her brakes held,' she said."
