"""A length said without digits ("a metre", "half a metre", "a foot", "a couple of feet", "30 cm", "a
car length") is read as the same length in digits would be: the distance between a road user and the
ego where it says how near they came ("stopped a metre from him", "missed my bonnet by a couple of
feet", "with half a metre to spare"); and what is no such distance stays none (a foot on a pedal, a
width, a visibility, how far the ego went)."""

from __future__ import annotations

import pytest

from vei_scenario.language.layers import behaviour_nodes
from vei_scenario.language.normalise import normalise
from vei_scenario.language.reader import read
from vei_scenario.language.rules_backend import layers_from_text


def _gaps(text: str, kind: str) -> list[list[float]]:
    """For each road user of ``kind`` (seed 0): its start distance and every stated distance its
    behaviours carry."""
    out = []
    for adv in layers_from_text(text, 0)["adversaries"]:
        if adv["type"] != kind:
            continue
        said = [abs(float(adv["spawn"].get("longitudinal_m", float("nan"))))]
        for _, node in behaviour_nodes(adv["behaviour"]):
            said += [float(node["config"][k]) for k in ("gap_m", "distance_m") if k in node["config"]]
        out.append(said)
    return out


def _has(text: str, kind: str, gap: float) -> bool:
    return any(any(abs(g - gap) < 0.05 for g in said) for said in _gaps(text, kind))


@pytest.mark.parametrize(
    ("text", "kind", "gap"),
    [
        ("Doing 25 mph through the estate, a lad ran out between two vans. I stopped a metre from him.",
         "pedestrian", 1.0),
        ("We were on the school run at 20 mph and a girl on a scooter shot out from the left; stopped "
         "half a metre short of her.", "e-scooter", 0.5),
        ("At the lights a pickup ran the red from my right and missed my bonnet by a couple of feet.",
         "van", 0.61),
        ("I was driving at 30 mph when a jogger stepped off the kerb on the right. I stopped with about a "
         "foot to spare.", "pedestrian", 0.3),
        ("A cyclist rode out of a side street on my left without stopping; I braked hard and stopped 50 cm "
         "from his wheel.", "bicycle", 0.5),
        ("Going along at 40 km/h a woman walked out from behind a bus, and I pulled up a car length from "
         "her.", "pedestrian", 4.5),
        ("At 30 km/h a boy ran into the road from the right. Missed him by a metre tops.", "pedestrian", 1.0),
        ("A pickup ran the red light from my left while I was going straight through with my kids in the car. "
         "Missed my front end by a foot.", "van", 0.3),
    ],
)  # fmt: skip
def test_a_length_said_in_words_is_how_near_the_road_user_came(text: str, kind: str, gap: float) -> None:
    """The length in words is read as the digits would be: the crosser's distance from the ego."""
    assert _has(text, kind, gap), _gaps(text, kind)


@pytest.mark.parametrize(
    ("said", "digits"),
    [
        ("stopped a metre from him", "stopped 1 metre from him"),
        ("half a meter to spare", "0.5 meter to spare"),
        ("missed us by a foot", "missed us by 0.3 m"),
        ("a couple of metres short", "2 metres short"),
        ("maybe 20cm between us", "about 0.2 m between us"),
        ("two car lengths back", "2 car lengths back"),
        ("a car length and a half back", "1.5 car lengths back"),
    ],
)
def test_a_length_in_words_is_said_in_digits(said: str, digits: str) -> None:
    assert digits in normalise(said)


@pytest.mark.parametrize(
    "said",
    [
        "she put a foot down to steady the scooter",
        "he had a foot on the brake",
        "i went on foot",
        "a six-foot hedge hid the junction",
        "the parking meter by the kerb",
        "a van pulled out of a yard on the left",
    ],
)
def test_a_foot_or_meter_that_measures_nothing_stays_a_word(said: str) -> None:
    """A foot on a pedal or on the ground, a parking meter and a builder's yard are things, not lengths."""
    text = normalise(said)
    assert " m " not in f" {text} " and "0.3" not in text, text


@pytest.mark.parametrize(
    ("text", "kind", "length"),
    [
        ("Visibility was down to about 50 metres in the fog when a cyclist came towards me.", "bicycle", 50.0),
        ("In the fog a cyclist came towards me a metre from the kerb.", "bicycle", 1.0),
        ("I'd gone a couple of metres past the junction when a car came out of a side road on my left.", "car", 2.0),
        ("A bus was waiting at the stop with a metre gap between it and the kerb, and a boy ran out in "
         "front of it.", "pedestrian", 1.0),
        ("I was riding at 20 km/h and a van came towards me and passed with half a metre to spare.", "van", 0.5),
        ("The van in front swerved round a pothole about a foot across and I hit it at 30 mph.", "van", 0.3),
    ],
)  # fmt: skip
def test_a_length_of_no_gap_to_the_ego_stays_none(text: str, kind: str, length: float) -> None:
    """A visibility, a place from the kerb, the ego's own travel, a width between others, the room a pass
    was made with (side by side, across the road) and the size of a thing are no road user's gap."""
    assert _gaps(text, kind) and not _has(text, kind, length), _gaps(text, kind)


# a length after "for" is how far someone went ("for a good 200 m"), as a time after "for" is how long:
# neither is a gap; a gap said beside it stays
@pytest.mark.parametrize(
    "text, gap",
    [
        ("I followed a cyclist at about 15 mph, no more than 2 m behind him for a good 200 m.", 2.0),
        ("A van tailgated me for 300 metres, then overtook.", None),
        ("An e-scooter 30 m ahead of us rode along in front for about 400 m.", 30.0),
        ("A lorry sat on my bumper for 10 seconds and then overtook.", None),
        ("I passed the cyclist aiming for 1.5 m of clearance at 30 km/h.", 1.5),
    ],
)
def test_a_stretch_gone_along_is_no_gap(text, gap):
    assert [a.distance_m for a in read(text).actors] == [gap]
