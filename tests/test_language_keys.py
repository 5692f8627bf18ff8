"""The smaller keys a description states (intent, time of day, traffic, road, the ego's route), each
read from a construction, not from a sentence. Every group is one construction in wordings written for
it (none taken from a corpus), with near-misses that look alike and must not be read so."""

from __future__ import annotations

import pytest

from vei_scenario.language.outcome import stated_intent
from vei_scenario.language.reader import _tokens, read


def _intent(text: str) -> str | None:
    return stated_intent(" ".join(_tokens(text)))


@pytest.mark.parametrize(
    "text, intent",
    [
        ("A cyclist wobbled past and her pedal scraped my rear door.", "collision"),
        ("The courier's mirror clipped my elbow as he went by.", "collision"),
        ("As the moped squeezed through, its footrest scratched the wing.", "collision"),
        # near misses: a part that misses, or a thing that is no part of a road user
        ("The courier's mirror nearly clipped my elbow.", "near_miss"),
        ("The booking app crashed twice this morning.", None),
    ],
)
def test_a_part_of_a_road_user_as_the_subject_of_a_contact_is_a_collision(text, intent):
    """ "his handlebar scraped the door": what a road user touches with is the road user touching."""
    assert _intent(text) == intent


@pytest.mark.parametrize(
    "text, intent",
    [
        ("A jogger ran out, I swerved and mounted the kerb; I never touched her.", "near_miss"),
        ("I yanked the wheel to avoid the moped and struck a bollard.", "near_miss"),
        ("I dodged the cyclist and hit a lamppost instead.", "near_miss"),
        # near misses: a road user hit stays a collision, whatever else was hit
        ("I swerved round the cyclist and hit a parked car.", "collision"),
        ("The scooter rider bounced off the kerb and hit my door.", "collision"),
        ("The lorry lost grip, hit the wall and overturned.", "collision"),
    ],
)
def test_hitting_street_furniture_is_no_contact_with_a_road_user(text, intent):
    """A kerb, a bollard, a lamppost are not road users: escaping one road user into them is a near
    miss with that road user, not a collision."""
    assert _intent(text) == intent


@pytest.mark.parametrize(
    "text, intent",
    [
        ("At 40 mph that delay would certainly have meant striking the child.", "near_miss"),
        ("Someone is going to get hit on this bend.", None),
        ("One day a pedestrian is going to be killed at this crossing.", None),
        # near misses: the future said of a plan, not of a harm
        ("The lorry is going to hit the cyclist in this test.", "collision"),
        ("The van hit the rider; he was going to be late anyway.", "collision"),
    ],
)
def test_a_contact_under_would_have_or_going_to_did_not_happen(text, intent):
    """ "would still have meant hitting her", "somebody is going to be killed": a hypothetical or a
    prediction is no contact that happened (a test's "is going to hit" is what the scenario plays)."""
    assert _intent(text) == intent


@pytest.mark.parametrize(
    "text, intent",
    [
        ("The ego overtakes the horse rider with adequate lateral clearance.", "safe"),
        ("The van passes the jogger at a sufficient distance.", "safe"),
        ("The shuttle keeps a safe distance behind the scooter.", "safe"),
        # near misses: sufficiency denied, or a small margin
        ("The van passes the jogger without sufficient clearance.", None),
        ("The van passes the jogger with 30 cm clearance.", "near_miss"),
    ],
)
def test_a_sufficient_margin_is_a_safe_pass(text, intent):
    assert _intent(text) == intent


@pytest.mark.parametrize(
    "text, intent",
    [
        ("Pass the cyclist with three metres or more to spare.", "safe"),
        ("I went round the runner with 2 m to spare.", "safe"),
        ("The bus slid past the moped with 20 cm to spare.", "near_miss"),
        # near misses: no quantity (a near miss), or a time to spare
        ("The bus slid past the moped with not much to spare.", "near_miss"),
        ("The truck stopped with half a metre to spare.", "near_miss"),
        ("The overtaking coach got back in with 40 m to spare before the tractor.", "near_miss"),
    ],
)
def test_a_margin_to_spare_is_as_wide_as_its_quantity(text, intent):
    assert _intent(text) == intent


@pytest.mark.parametrize(
    "text, intent",
    [
        ("The quad bike crossed our path 2 m in front of the bumper.", "near_miss"),
        ("The horse stopped a metre ahead of my front wheel.", "near_miss"),
        ("The deer cleared the road a couple of metres ahead of our bonnet.", "near_miss"),
        # near misses: far ahead, or ahead of a place
        ("The quad bike crossed 40 m in front of the bumper.", None),
        ("The lorry stopped 2 m in front of the stop line.", None),
    ],
)
def test_a_small_distance_ahead_of_a_part_of_the_ego_is_a_near_miss(text, intent):
    assert _intent(text) == intent


@pytest.mark.parametrize(
    "text, intent",
    [
        ("Clipped it with my elbow as the bus pulled over.", "collision"),
        ("I caught him with my mirror as I went past.", "collision"),
        ("The lorry nicked me with its trailer.", "collision"),
        # near misses: caught sight, caught up with
        ("I caught him with my eyes just in time and braked.", None),
        ("I caught up with the cyclist at the lights.", None),
    ],
)
def test_touching_someone_with_a_part_is_a_collision(text, intent):
    """ "caught it with my knee": a verb of touching whose instrument is a part of a body or vehicle."""
    assert _intent(text) == intent


@pytest.mark.parametrize(
    "text, intent",
    [
        ("The minibus struck a 9-year-old boy at the gates.", "collision"),
        ("A van hit an 80-year-old pensioner on the zebra.", "collision"),
        ("CYCLIST STRUCK 5TH/ELM, AMBULANCE EN ROUTE.", "collision"),
        ("Jogger clipped at the crossing, minor injuries.", "collision"),
        # near misses: a speed or a number after the verb
        ("The motorbike hit 90 on the straight.", None),
        ("The van hit 50 mph before the bend.", None),
    ],
)
def test_an_age_or_a_place_after_a_contact_verb_keeps_the_contact(text, intent):
    """ "struck a 72-year-old woman" (an age in the object), "PED STRUCK 4TH/MARKET" (a report's
    passive without its auxiliary, then where): both are contacts; "hit 90" is a speed."""
    assert _intent(text) == intent


def _time(text: str) -> str | None:
    return read(text).time


@pytest.mark.parametrize(
    "text, clock",
    [
        ("2140 RP reports a cyclist riding without lights in the bus lane, RP passed at 25 mph.", "21:40"),
        ("0510 Unit 3 adv moped ran the red at Elm/3rd, unit braked at 30 mph.", "05:10"),
        ("Log:\n1415 Caller says a jogger stepped out in front of her car at 20 mph.", "14:15"),
        # near misses: a number inside a line, a quantity, a model year, a reference
        ("Event 2140: a cyclist crosses in front of the ego at 20 km/h.", None),
        ("2019 Honda Civic, doing 30 mph, when a jogger ran out in front of me.", None),
        ("1200 m ahead a cyclist crosses the road in front of the ego.", None),
    ],
)
def test_a_four_digit_clock_opening_a_log_line_is_the_time(text, clock):
    assert _time(text) == clock


@pytest.mark.parametrize(
    "text, time",
    [
        ("Afternoon drive, a cyclist swerved out in front of me at 30 mph. Jump to 0:55 for the moment.", "15:30"),
        ("Evening, a moped cut in front of me at 40 km/h. It happens at 1:12 in the video.", "20:00"),
        ("A cyclist pulled out in front of me at 20 mph; skip to 2:05.", None),
        # near misses: clocks of the day stay
        ("At 0:30 am a cyclist pulled out in front of me at 20 mph.", "00:30"),
        ("At 9:15 a moped cut in front of me at 40 km/h.", "09:15"),
    ],
)
def test_a_point_in_a_recording_is_no_time_of_day(text, time):
    assert _time(text) == time


@pytest.mark.parametrize(
    "text, time",
    [
        ("Good morning. Last night a cyclist with no lights pulled out in front of me at 30 mph.", "23:00"),
        ("Good evening all, this afternoon a jogger ran out in front of my car at 20 mph.", "15:30"),
        ("Good afternoon. A cyclist pulled out in front of me at 30 mph.", None),
        # near misses: the part of the day said of the event
        ("It was a good morning for a drive until a jogger ran out in front of me at 20 mph.", "08:30"),
        ("This morning a cyclist pulled out in front of me at 30 mph.", "08:30"),
    ],
)
def test_a_greeting_is_no_time_of_day(text, time):
    assert _time(text) == time


def _density(text: str) -> str | None:
    return read(text).density


@pytest.mark.parametrize(
    "text, density",
    [
        ("A cyclist crosses in front of the ego at 20 km/h. Do not add any background traffic.", "none"),
        ("A jogger steps out in front of the ego at 30 km/h; don't include other vehicles.", "none"),
        ("A deer runs out in front of the ego at 60 km/h. Nothing else on the road.", "none"),
        # near misses: other traffic asked for, or a thing added
        ("A cyclist crosses in front of the ego at 20 km/h. Add some background traffic.", None),
        ("A cyclist crosses in front of the ego at 20 km/h. Do not add rain.", None),
    ],
)
def test_traffic_left_out_by_the_request_is_none(text, density):
    assert _density(text) == density


@pytest.mark.parametrize(
    "text, density",
    [
        ("Crawling through stationary traffic at 10 mph when a moped squeezes in front of me.", "heavy"),
        ("Traffic flow was light. A van pulls out in front of the ego at 40 km/h.", "light"),
        ("Moderate volumes on the bypass; a lorry cuts in front of the ego at 80 km/h.", "moderate"),
        ("The circulation was really dense and a van cut in front of me at 30 km/h.", "heavy"),
        # near misses: a degree of something else
        ("Light rain. A van pulls out in front of the ego at 40 km/h.", None),
        ("A heavy lorry pulls out in front of the ego at 40 km/h.", None),
    ],
)
def test_a_degree_of_the_traffic_by_any_of_its_nouns(text, density):
    assert _density(text) == density


def _map(text: str) -> str | None:
    return read(text).map_kind


@pytest.mark.parametrize(
    "text, kind",
    [
        ("A cyclist blew the red at Kingsway, right across in front of me at 30 km/h.", "crossroad"),
        ("CYCLIST STRUCK AT PARK/9TH, driver doing 25 mph.", "crossroad"),
        ("At the Harbour Rd lights a cyclist pulled out in front of me at 20 mph.", "crossroad"),
        ("A moped jumped the red near Oak St and cut in front of me at 30 mph.", "crossroad"),
        ("Doing 20 mph by the King/Queen St junction when a jogger ran out in front of me.", "crossroad"),
        # near misses: a red at a foot crossing, units and shorthand with a slash, a red thing
        ("At the pelican crossing a jogger ran the red in front of me at 20 mph.", None),
        ("A cyclist crossed in front of me at 30 km/h and 8 m/s.", None),
        ("A van with a red roof cut in front of me at 30 mph.", None),
    ],
)
def test_a_signalled_or_named_intersection_is_a_crossroad(text, kind):
    """Running a red light, lights named by their street ("the Harbour Rd lights") and two streets
    written with a slash ("Queen/Albert", "4TH/MARKET"): the road has a junction there."""
    assert _map(text) == kind


def _route(text: str) -> str | None:
    from vei_scenario.language.route import ego_route

    return ego_route(_tokens(text))


@pytest.mark.parametrize(
    "text, route",
    [
        ("I was making right on the green arrow when a cyclist came through.", "right"),
        ("We made left onto Pine St and a jogger stepped out.", "left"),
        ("Caller is driver of vehicle 1, was making left at the signal, pedestrian in crosswalk.", "left"),
        ("Witness is the ego vehicle, was making right at the signal.", "right"),
        # near misses: another's turn, a lane, a choice
        ("The van was making left on green when it hit the cyclist.", None),
        ("I was making right decisions all day until a cyclist cut across me.", None),
        ("I took the left lane and a van cut in front of me.", None),
    ],
)
def test_a_bare_direction_after_make_is_the_turn(text, route):
    """ "making left on green": the American shorthand of "making a left", its article left out."""
    assert _route(text) == route


def _kph(mps: float | None) -> float | None:
    return None if mps is None else round(mps * 3.6, 1)


@pytest.mark.parametrize(
    "text, start, end",
    [
        ("I'm following a lorry at 80 km/h on the dual carriageway and the lorry brakes to 50 km/h.", 80, 50),
        ("Ego follows a bus at 40 mph; the bus then slows down to 20 mph for a stop.", 64.4, 32.2),
        ("We are following a car at 60 km/h when the car decelerates to 30 km/h.", 60, 30),
        # near misses: its own speed said, one the ego does not follow, or an ego no faster
        ("I'm following a truck doing 70 km/h at 80 km/h, and it slows to 50 km/h.", 70, 50),
        ("I am at 100 km/h when a car cuts in ahead of me and then slows to 60 km/h.", 60, None),
        ("I was doing 20 km/h following a van, and the van slowed to 30 km/h.", 30, None),
    ],
)
def test_a_slowing_to_a_speed_starts_at_the_ego_s_where_none_of_its_own_is_said(text, start, end):
    """ "follows a van at 100, the van slows to 60": the speed after "slows to" is where the slowing
    ends, never the speed it goes at; with none of its own said, a vehicle the ego keeps pace with
    goes at the ego's speed before it slows."""
    actor = read(text).actors[0]
    assert _kph(actor.speed_mps) == start
    if end is not None:
        delta = [c["speed_delta_mps"] for n, c, *_ in actor.behaviours if n == "change_speed"]
        assert delta and round(start + delta[0] * 3.6, 1) == end


@pytest.mark.parametrize(
    "text, kind, speed",
    [
        ("A tractor came out of a farm gate ahead of me and then crawled along at 12 mph.", "truck", 19.3),
        ("The bin lorry in front was crawling along at about 10 km/h.", "truck", 10),
        ("The van ahead of us crept along at 15 mph the whole way.", "van", 24.1),
        ("There was a cyclist dawdling along in front of me at 8 mph.", "bicycle", 12.9),
        # near misses: traffic that crawls is no road user, and the ego's own crawl is the ego's
        ("Traffic was crawling along at 10 mph when a cyclist cut in front of me.", "bicycle", None),
    ],
)
def test_a_verb_of_going_slowly_gives_its_subject_s_speed(text, kind, speed):
    """ "crawled along at 15 mph", "crept along": a road user going slowly still goes, at the speed
    said after it, as after "trundled along"."""
    actor = read(text).actors[0]
    assert (actor.kind, _kph(actor.speed_mps)) == (kind, speed)


def test_crawling_traffic_is_no_road_user_and_gives_the_ego_its_speed():
    """ "traffic was crawling along at 10 mph": the traffic's pace, the ego's in it; no road user."""
    reading = read("Traffic was crawling along at 10 mph when a cyclist cut in front of me.")
    assert [a.kind for a in reading.actors] == ["bicycle"]
    assert _kph(reading.ego_speed_mps) == 16.1
