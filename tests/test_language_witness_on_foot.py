"""A writer on foot beside the road who tells what a vehicle and someone else did is a witness: the
scenario is the vehicle's (its speed the ego's), and the writer's standing is no ego at rest."""

from __future__ import annotations

import pytest

from vei_scenario.language.reader import read


@pytest.mark.parametrize(
    ("text", "kind", "kph"),
    [
        (
            "I was standing on the pavement outside the library. A green Skoda was coming along at about "
            "25 mph. A boy on an electric scooter shot out from between two parked cars straight into the "
            "road. The Skoda braked hard and stopped just short of him.",
            "e-scooter",
            40.2,
        ),
        (
            "I am the above named person. I was walking my dog along the pavement on Mill Road. A white van "
            "was doing about 30 when a cyclist came out of Bridge Street on its left without stopping. The "
            "van swerved and missed him by a foot.",
            "bicycle",
            48.3,
        ),
        (
            "We were stood on the verge waiting to cross. A taxi was coming up the hill at about 20 mph and "
            "a boy ran straight out in front of it. The taxi stopped with inches to spare.",
            "pedestrian",
            32.2,
        ),
    ],
)
def test_the_vehicle_a_bystander_watched_is_the_ego(text, kind, kph):
    reading = read(text)
    assert [a.kind for a in reading.actors if a.speed_mps != 0.0] == [kind]
    assert reading.ego_speed_mps == pytest.approx(kph / 3.6, abs=0.3)


@pytest.mark.parametrize(
    "text",
    [
        "I was crossing at the lights when a van came past me at 30 and a cyclist pulled out of the side road.",
        "I was standing in the queue at the lights when the van behind hit my rear bumper. A cyclist saw it.",
        "I was walking along at about 4 mph when a van and a cyclist came past me.",
    ],
)
def test_a_writer_in_the_scene_is_no_bystander(text):
    from vei_scenario.language.reader import _kind_at, _known, _tokens
    from vei_scenario.language.witness_on_foot import bystander

    tokens = _tokens(text)
    assert not bystander(tokens, _kind_at, _known)


def test_a_writer_who_steps_out_is_the_walker_a_vehicle_meets():
    reading = read("I stepped off the kerb with my sign and a taxi went straight past me at 30.")
    assert [a.kind for a in reading.actors] == ["pedestrian"]


def test_a_bystanders_bare_speed_is_in_the_unit_of_their_signs():
    reading = read(
        "I was standing on the pavement outside the chemist. A white van was doing about 30 along the high "
        "street when a boy on a scooter shot out from the left. The van braked hard."
    )
    assert reading.ego_speed_mps == pytest.approx(30 * 0.44704, abs=0.05)  # ("pavement": British, mph)


@pytest.mark.parametrize(
    "text",
    [
        "I was stood at the red light in my car. The bus beside me moved off and a cyclist came from the left.",
        "I was stood at the junction waiting to turn out. The lorry swung left and a cyclist went down its inside.",
        "We were standing at the give way line when a taxi came round from the right and a scooter cut across.",
        "I was stood at the zebra letting an old man over when a van overtook me and a cyclist followed it.",
    ],
)
def test_a_driver_who_stands_at_the_lights_or_a_junction_stays_at_rest(text):
    assert read(text).ego_speed_mps == 0.0


def test_a_writer_something_is_done_to_is_no_bystander():
    from vei_scenario.language.reader import _kind_at, _known, _tokens
    from vei_scenario.language.witness_on_foot import bystander

    text = "I was walking on the pavement and I was hit by the van's mirror as it passed a cyclist."
    assert not bystander(_tokens(text), _kind_at, _known)
