"""Where a road user starts relative to the ego when the text says where it goes or where it came
from rather than where it is: a crossing said to go to a side starts on the other one, whatever the
order of the side and the verb of crossing."""

import pytest

from vei_scenario.language.reader import read


def relation(text: str) -> str | None:
    return read(text).actors[0].relation


@pytest.mark.parametrize(
    "text",
    [
        "I was at 30 km/h when a dog ran off to the left across in front of my car.",
        "Doing 20 mph, a little boy ran over to the left, straight across in front of me.",
        "ego 40 kph. ped runs to the left across ego path",
        "A jogger bolted to the left, across in front of us, we were doing 25 mph.",
        "A man on foot shot off to the left straight across in front of my van, I was doing 25 mph.",
        "I was at 30 km/h when a kid ran across the road towards the left kerb.",
        "Going about 35 km/h, a man hurried across to the left-hand pavement right in front of me.",
    ],
)
def test_a_crossing_said_to_go_left_starts_on_the_right(text):
    assert relation(text) == "roadside_right"


@pytest.mark.parametrize(
    "text, expected",
    [
        # where it starts is said too: that side stands
        ("A kid dashed across from right to left in front of me at 30 km/h.", "roadside_right"),
        ("A cyclist from the left crossed to the right kerb in front of me. I was at 30 km/h.", "roadside_left"),
        ("A pedestrian on the right kerb walked across towards the left. Ego at 40 km/h.", "roadside_right"),
        # a side beside the ego or another road user is where it is, not where it goes
        ("A kid to my left ran out across the road. I was at 30 km/h.", "roadside_left"),
        (
            "A woman stepped out from the left, to the left of the bus, across my lane. I was at 30 km/h.",
            "roadside_left",
        ),
    ],
)
def test_where_a_crossing_starts_when_also_said(text, expected):
    assert relation(text) == expected


def _first(text: str) -> tuple[str | None, list[str]]:
    a = read(text).actors[0]
    return a.relation, [b[0] for b in a.behaviours]


@pytest.mark.parametrize(
    "text",
    [
        "I was doing 40 when a cyclist came up behind me and swung out round me.",
        "Then this lad on a scooter comes up behind me, swings out round me and clips my mirror.",
        "A cyclist came from behind me and pulled out around me. I was doing 20 mph.",
        "A bike rider behind me swerved out round my car, I was doing 25 km/h.",
        "A scooter rider came up from behind and nipped out around us, we were at 20 km/h.",
        "Ego at 30 km/h. A cyclist behind the ego pulls out around the ego.",
        "Cyclist came up behind us and swung out round us, we were doing 15 km/h",
    ],
)
def test_a_move_out_round_the_ego_from_behind_it_is_an_overtake(text):
    relation, behaviours = _first(text)
    assert relation == "behind"
    assert behaviours[-1] == "overtake"


@pytest.mark.parametrize(
    "text",
    [
        # coming towards the ego, a swerve round it is avoiding it, not passing it from behind
        "A cyclist coming towards me swerved round me. I was at 30 km/h.",
        # the ego is the one behind something
        "I was at 30 km/h behind a van when a cyclist swerved out round me.",
    ],
)
def test_a_swerve_round_the_ego_not_from_behind_is_no_overtake(text):
    relation, behaviours = (
        _first(text) if "behind a van" not in text else (None, [b[0] for b in read(text).actors[1].behaviours])
    )
    assert relation != "behind"
    assert "overtake" not in behaviours


@pytest.mark.parametrize(
    "text, expected",
    [
        ("A cyclist riding along the left kerb ahead of me pulled out into my lane. I was at 40 km/h.", "left"),
        ("I was at 30 mph. A cyclist hugging the left kerb swerved out into my lane.", "left"),
        ("A scooter rider on the right edge of the road veered into my lane ahead. I was at 30 km/h.", "right"),
        ("A lad on a bike was riding along the right-hand kerb and pulled out into my path. Ego 30 km/h.", "right"),
        ("ego 25 mph, bike at nearside kerb swings out into ego lane", "left"),
    ],
)
def test_a_rider_at_a_kerb_moving_out_starts_at_that_edge(text, expected):
    a = read(text).actors[0]
    start = a.relation
    if start == "ahead" and a.behaviours[0][0] == "along_road" and a.lateral_m:
        start = "roadside_left" if a.lateral_m > 0 else "roadside_right"  # (going along at that edge of the lane first)
    assert start == f"roadside_{expected}"


def test_a_rider_in_a_cycle_lane_moving_out_starts_in_that_lane():
    assert relation("A cyclist in the cycle lane on the right pulled out into my lane. I was at 40 km/h.") == "right"


@pytest.mark.parametrize(
    "text",
    [
        "I was at 40 km/h. A biker came from wrong side, straight towards my car.",
        "Driving at 40 kmph, one auto rickshaw coming from wrong side nearly hit me.",
        "I was at 40 km/h. A biker was coming wrong side straight at me.",
        "I was doing 30 km/h and a scooty fellow came from the wrong side and brushed my mirror.",
        "Ego 40 km/h; motorcyclist riding wrong side towards ego.",
    ],
)
def test_a_rider_or_driver_from_the_wrong_side_comes_head_on(text):
    a = read(text).actors[0]
    assert a.relation in ("ahead", "oncoming")
    assert [b[0] for b in a.behaviours] == ["wrong_way"]


@pytest.mark.parametrize(
    "text",
    [
        "I was at 40 km/h. A pedestrian stepped out from the wrong side of the bus.",
        "I was at 40 km/h. A pedestrian walked out from the wrong side into my path.",
    ],
)
def test_a_walker_from_the_wrong_side_crosses(text):
    assert [b[0] for b in read(text).actors[0].behaviours] == ["cross_in_front"]


@pytest.mark.parametrize(
    "text",
    [
        "Going round the roundabout at 20 mph behind a bus, the bus braked hard.",
        "Crawling behind a tractor at 15 mph, it suddenly stopped.",
        "Stuck behind a lorry at 30 mph on the A road; it braked hard.",
        "Driving behind a van at 40 km/h when the van braked.",
        "Approaching the lights behind a cyclist at 20 mph, the cyclist wobbled and fell.",
        "Sat behind a bus doing 20, it pulled in sharply and stopped.",
    ],
)
def test_a_road_user_the_narrators_opening_phrase_is_behind_is_ahead(text):
    assert relation(text) == "ahead"


@pytest.mark.parametrize(
    "text",
    [
        # the phrase is the walker's (crossing), or the road user named first is the one behind
        "Crossing behind a bus, a kid ran out in front of me. I was at 30 km/h.",
        "Heading home at 50 km/h. A van behind me flashed and overtook.",
    ],
)
def test_behind_said_of_someone_else_keeps_its_place(text):
    assert relation(text) == "behind"


@pytest.mark.parametrize(
    "text",
    [
        "I was doing 50 mph when a van came over the crest in the middle of the road.",
        "A tractor came round the corner. I was at 40 mph.",
        "A lorry had just come round the blind bend on my side. Ego 50 km/h.",
        "a car coming around the sharp bend hit me, i was doin 40",
        "Ego 70 km/h on a rural road; a motorcyclist comes over the brow of the hill.",
    ],
)
def test_one_coming_over_a_crest_or_round_a_bend_comes_towards_the_ego(text):
    a = read(text).actors[0]
    assert a.relation == "oncoming" or (a.relation == "ahead" and a.facing == "against")


@pytest.mark.parametrize(
    "text",
    [
        # the narrator comes round the bend: the road user found there does not come towards it
        "As I came over the crest, a tractor was stopped in the road. I was at 50 mph.",
        "Doing 60 km/h, came round the bend and a deer was standing there.",
        # from a side road, or behind the ego
        "A cyclist came round the corner from the side road. I was at 30 km/h.",
        "A motorbike came round the bend behind me and overtook. I was at 50 km/h.",
    ],
)
def test_coming_round_a_bend_said_otherwise_is_not_oncoming(text):
    assert relation(text) != "oncoming"
