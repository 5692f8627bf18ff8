"""Traffic coming the other way said in general: a bare plural of vehicles (no article, no count) that
comes the other way or is "oncoming" is the stream of traffic that keeps the ego where it is, scenery
of the road, no road user of the scene, where the text names another road user it is about. Said by
many kinds of writer (a voice note, a text, a police log, a driving instructor, a test spec), with
near misses that look alike and must keep their road user."""

from __future__ import annotations

import pytest

from tests.reading_of import kinds


@pytest.mark.parametrize(
    "text, expected",
    [
        # (an Australian voice note)
        (
            "Stuck behind a bloke on a scooter in the ute at 20 km/h, couldn't get round him cos there's cars "
            "coming the other way the whole time.",
            ["e-scooter"],
        ),
        # (a British text message)
        ("Sat behind a cyclist at 15 mph for ages, couldn't overtake as cars kept coming the other way.", ["bicycle"]),
        # (an American driver)
        ("I followed a cyclist at 20 mph and could not pass because of oncoming cars.", ["bicycle"]),
        # (a test spec)
        (
            "The ego follows a cyclist at 25 km/h and may not overtake while vehicles approach in the "
            "opposite direction.",
            ["bicycle"],
        ),
        # (an Indian report)
        ("I was behind one cyclist at 20 kmph, could not overtake since trucks were coming towards us.", ["bicycle"]),
        # (a Singaporean text)
        (
            "Behind one cyclist at 20 km/h lah, cannot overtake, got lorries coming from the other direction.",
            ["bicycle"],
        ),
    ],
)
def test_bare_plural_traffic_coming_the_other_way_is_no_road_user(text, expected):
    assert kinds(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        # (a counted plural is so many road users)
        ("I was doing 30 mph when two cars coming the other way swerved into my lane.", ["car", "car"]),
        # (one car coming the other way is a road user)
        ("I was behind a cyclist at 20 mph when a car coming the other way cut the corner.", ["bicycle", "car"]),
        # (the only road user the text names is the scene's)
        ("At 40 mph on the bend, oncoming cars kept drifting over the centre line at me.", ["car"]),
    ],
)
def test_counted_single_or_only_oncoming_vehicles_stay_road_users(text, expected):
    assert kinds(text) == expected


# a place said after a road user's second verb, in a clause that names it no more ("..., then overtook and
# cut in in front of me because a lorry ..."), is where that road user went: the one named after the
# "because" or "as" only comes the other way (no wrong-way driver of it)
CUT_IN_BEFORE_ONCOMING = [
    "A BMW tailgated me for miles, then overtook and cut in ahead of me because a van was coming the other way.",
    "Some idiot in a Golf was right up my backside, then overtook and swerved back in in front of me as a lorry "
    "was coming towards us.",
    "A bakkie tailgated us for ages, then passed and cut in ahead of us because a taxi was approaching.",
    "Danfo was tailgating us for long, then overtake and enter in front of us because trailer was coming from "
    "the other side.",
    "SUV tailgating ego for 2 km, then overtakes and pulls in ahead of ego since a truck is coming the other way.",
    "A Merc rode my bumper for two miles, then overtook me and cut in ahead of me because a bus was coming the "
    "other way.",
]


@pytest.mark.parametrize("text", CUT_IN_BEFORE_ONCOMING)
def test_the_oncoming_vehicle_an_overtaker_cuts_in_for_goes_its_way(text):
    from vei_scenario.language.reader import read

    r = read(text)
    oncoming = [a for a in r.actors if a.relation == "oncoming"]
    assert oncoming, [(a.kind, a.relation, [b[0] for b in a.behaviours]) for a in r.actors]
    assert all("wrong_way" not in [b[0] for b in a.behaviours] for a in oncoming)
    assert any("overtake" in [b[0] for b in a.behaviours] for a in r.actors if a not in oncoming)


# near misses: one that comes the other way into the ego's lane is still a wrong-way driver
WRONG_WAY_AFTER_A_TAILGATER = [
    "A BMW tailgated me for miles, then a van coming the other way drifted into my lane.",
    "A van was right up my backside, then an oncoming lorry came into my lane head-on.",
]


@pytest.mark.parametrize("text", WRONG_WAY_AFTER_A_TAILGATER)
def test_an_oncoming_vehicle_into_the_ego_lane_after_a_tailgater_comes_the_wrong_way(text):
    from vei_scenario.language.reader import read

    names = [[b[0] for b in a.behaviours] for a in read(text).actors]
    assert any("wrong_way" in n for n in names), names


# near misses: "oncoming" said of the traffic after the second verb describes that traffic, not where the
# road user went ("cut in ... to avoid oncoming traffic"): the overtaker keeps its overtake
OVERTAKER_AVOIDS_ONCOMING_TRAFFIC = [
    "A hatchback came up behind, overtook me and then cut in sharply in front of me to avoid oncoming traffic.",
    "Cars often pass the bus and then dive back in ahead of it because of oncoming cars.",
    "The van overtook us and swung back in right in front of us to dodge oncoming vehicles.",
    "A taxi overtook us and then cut in ahead of us to avoid the oncoming lorries.",
    "Some lads in a Corsa overtook and pulled in tight ahead of me, what with all the oncoming cars.",
]


@pytest.mark.parametrize("text", OVERTAKER_AVOIDS_ONCOMING_TRAFFIC)
def test_oncoming_said_of_the_traffic_is_not_where_the_overtaker_went(text):
    from vei_scenario.language.reader import read

    first = read(text).actors[0]
    names = [b[0] for b in first.behaviours]
    assert first.relation != "oncoming" and "wrong_way" not in names, (first.relation, names)
