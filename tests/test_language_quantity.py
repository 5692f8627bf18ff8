"""How near the ego came to a road user that crossed its path is that road user's gap: the distance
the ego stopped short of it ("I stopped 2 m short of him") where nothing else says where it was. A road
user going along the ego's road keeps no such gap (it started elsewhere), and a distance said of the
road user itself wins over the stop."""

import pytest

from vei_scenario.language.reader import read
from vei_scenario.language.rules_backend import layers_from_text


def _gaps(text: str) -> list[tuple[str, float | None]]:
    return [(a.behaviours[0][0], a.distance_m) for a in read(text).actors]


@pytest.mark.parametrize(
    ("text", "behaviour", "gap"),
    [
        # a driver's post: someone on foot out from behind a bus
        ("A girl dashed out from behind a bus and I stopped 3 m short of her.", "cross_in_front", 3.0),
        # a side-street pull-out, told in two clauses
        (
            "A delivery van nosed out of a side street on my right; I braked and stopped 2 m short of it.",
            "turn_into",
            2.0,
        ),
        # a red-light runner, the narrator in the plural
        ("A moped ran the red light from the left and we stopped about 4 metres short of it.", "run_red_light", 4.0),
        # a test note in the third person
        ("A jogger crosses from the left and the ego stops 1.5 m short of him.", "cross_in_front", 1.5),
        # feet, as a British witness measures
        (
            "A lad on a bike shot across the road in front of me and I stopped about 6 feet from him.",
            "cross_in_front",
            1.8,
        ),
    ],
    ids=["girl-bus", "van-side-street", "moped-red", "ego-third", "feet"],
)
def test_where_the_ego_stopped_short_of_a_crosser_is_its_gap(text, behaviour, gap):
    [(did, distance)] = _gaps(text)
    assert did == behaviour
    assert distance == pytest.approx(gap, abs=0.1)


@pytest.mark.parametrize(
    ("text", "gap"),
    [
        # a lead vehicle that brakes: it started ahead, not where the ego stopped behind it
        ("The lorry in front braked hard and I stopped 2 m short of it.", None),
        # a cut-in: the stop says how the ego's braking went
        ("A taxi swung into my lane right in front of me and I stopped 3 m short of it.", None),
        # a distance said of the crosser itself wins
        ("A boy ran out about 15 m ahead of me and I stopped 2 m short of him.", 15.0),
    ],
    ids=["lead-brakes", "cut-in", "own-distance"],
)
def test_the_stop_gives_no_gap_where_it_is_no_crossing_or_one_is_said(text, gap):
    [(_, distance)] = _gaps(text)
    assert distance == (None if gap is None else pytest.approx(gap, abs=0.1))


def test_the_crossing_is_timed_to_the_stop_distance_in_the_layers():
    """The layers keep the distance as the crossing's own: in the ego's lane when the ego is that far."""
    layers = layers_from_text("A girl dashed out from behind a bus and I stopped 3 m short of her.", 0)
    [walker] = [a for a in layers["adversaries"] if a["type"] == "pedestrian"]
    config = walker["behaviour"]["config"]
    assert config["distance_m"] == pytest.approx(3.0)
