"""How many vehicles a description names as road users: a test target said again as "the target" is
the one named before; a road named after "on the" is no car; a vehicle said to be absent ("not another
car for miles") is none; a trailing vehicle opening a line is a second one; the vehicle of a pair label
in a first-person story is the narrator's; vehicles labelled in the plural are as many as their labels."""

from __future__ import annotations

import pytest

from tests.reading_of import ego_kph, kinds


def test_the_target_said_again_is_the_target_named_before() -> None:
    text = (
        "We run the pedestrian target across our path at 5 km/h while the test car approaches at 40 km/h; "
        "the brakes come on and the target walks clear."
    )
    assert kinds(text) == ["pedestrian"]


def test_the_target_said_again_after_an_e_scooter_target() -> None:
    text = (
        "Our car follows an e-scooter target at 50 km/h, the target doing 15 km/h ahead of us, and the system "
        "brakes and the car stops behind the target."
    )
    assert kinds(text) == ["e-scooter"]


def test_the_target_said_again_after_a_target_car_is_that_car() -> None:
    text = "The ego approaches a soft target car standing 30 m ahead at 40 km/h and stops just behind the target."
    assert kinds(text) == ["car"]


def test_a_target_car_named_after_a_pedestrian_target_is_a_second_road_user() -> None:
    text = (
        "A pedestrian target crosses 20 m ahead of the ego at 5 km/h, and then the target car in the next lane "
        "brakes hard."
    )
    assert kinds(text) == ["pedestrian", "car"]


def test_a_vehicle_said_to_be_absent_is_no_road_user() -> None:
    text = (
        "Quiet evening on the moor road, dry and hardly another van about. The one scare was a sheep that "
        "wandered across from the right."
    )
    assert kinds(text) == ["pedestrian"]


def test_not_another_car_for_miles_is_no_road_user() -> None:
    text = (
        "I'm driving down a dark lane, not a single car for miles, and a jogger is running towards me on my "
        "side of the road."
    )
    assert kinds(text) == ["pedestrian"]


def test_no_other_vehicles_about_is_no_road_user() -> None:
    text = "Motorway at 3am, no other vehicles about, when a lorry ahead of me brakes hard."
    assert kinds(text) == ["truck"]


def test_a_car_length_after_a_negation_is_still_a_distance() -> None:
    text = "A van pulls in not a car length ahead of me and brakes hard while I'm doing 50 km/h."
    assert kinds(text) == ["van"]


def test_a_car_that_does_not_stop_is_a_road_user() -> None:
    text = "I was crossing at the lights when a car did not stop and another car swerved round me."
    assert kinds(text) == ["car", "car"]


def test_a_name_after_on_the_is_a_road_not_a_car() -> None:
    text = "I was heading north on the Westlink at 80 km/h when a van from the left lane cut in front of me."
    assert kinds(text) == ["van"]


@pytest.mark.parametrize(
    "text",
    [
        "A man walked out in front of a bus on Mill Road and it stopped for him, the driver told the Gazette.",
        "A man walked out in front of a bus on Mill Road and it stopped for him, the driver said to the Gazette.",
    ],
)
def test_a_name_told_something_is_a_listener_not_a_car(text: str) -> None:
    assert kinds(text) == ["pedestrian"]


def test_a_name_a_road_user_is_told_of_is_still_a_car() -> None:
    text = "A man walked out in front of a bus on Mill Road and a silver Qashqai stopped behind it."
    assert kinds(text) == ["pedestrian", "car"]


def test_a_name_after_a_is_still_a_car() -> None:
    text = "I was heading north at 80 km/h when a silver Qashqai from the left lane cut in front of me."
    assert kinds(text) == ["car"]


def test_a_trailing_vehicle_opening_a_field_is_a_second_vehicle() -> None:
    text = "Ego 100 km/h | lead vehicle brakes hard, gap 25 m | trailing vehicle following at 1.5 s"
    assert kinds(text) == ["car", "car"]


def test_the_ego_following_a_vehicle_named_before_is_that_vehicle() -> None:
    text = "A vehicle ahead brakes hard 25 m in front of the ego; ego following vehicle at 1.5 s brakes too."
    assert kinds(text) == ["car"]


def test_the_lead_vehicle_said_again_as_lead_car_is_the_same() -> None:
    text = "Ego: 90 km/h, behind lead vehicle at 2 s\nLead car: brakes hard to a stop"
    assert kinds(text) == ["car"]


def test_the_vehicle_of_a_pair_label_is_the_narrators() -> None:
    text = (
        "VAN vs CYCLIST, helmet cam. Going about 30 km/h through the lights when the cyclist swerves out "
        "into my lane and clips my mirror."
    )
    assert kinds(text) == ["bicycle"]


def test_a_car_to_scooter_test_label_is_the_test_car() -> None:
    text = "Car-to-e-scooter run: the scooter target rides ahead of us at 15 km/h and we close in at 40."
    assert kinds(text) == ["e-scooter"]


def test_a_pair_label_where_the_narrator_rides_leaves_the_car_a_road_user() -> None:
    text = "Car vs bike on my commute. I was cycling at 20 km/h when the car pulled out of a side road into me."
    assert kinds(text)[0] == "car"  # (the car stays someone else's; the label's bike is the rider's own)


def test_a_4k_dashcam_is_no_speed() -> None:
    text = "VAN vs SCOOTER, 4K dashcam. Doing about 40 km/h when the scooter swerves into my lane."
    assert ego_kph(text) == 40.0
    assert kinds(text) == ["e-scooter"]


def test_vehicles_labelled_in_the_plural_are_as_many_as_their_labels() -> None:
    text = "A van 30 m ahead of the ego brakes hard. Cars 2 and 3 follow the ego at 1 s."
    assert kinds(text) == ["van", "car", "car"]


def test_three_labelled_trucks_in_the_plural() -> None:
    text = "The ego leads the convoy at 80 km/h. Trucks 2, 3 and 4 follow the ego at 1.5 s; a car cuts in ahead."
    assert sorted(kinds(text)) == ["car", "truck", "truck", "truck"]


def test_a_single_label_is_one_vehicle() -> None:
    text = "Car 2 follows the ego at 1 s while a cyclist crosses 30 m ahead."
    assert kinds(text) == ["car", "bicycle"]


def test_a_proper_name_one_slip_from_a_vehicle_word_stays_a_name() -> None:
    text = "I was going round the Hanley Rd roundabout at 15 mph when a cyclist came across from the right."
    assert kinds(text) == ["bicycle"]


def test_a_misspelt_word_in_lower_case_is_still_corrected() -> None:
    text = "I was going round the roundabout at 15 mph when a cyclsit came across from the right."
    assert kinds(text) == ["bicycle"]
