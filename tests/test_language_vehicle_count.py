"""How many vehicles a description names as road users: a test target said again as "the target" is
the one named before, a road named after "on the" is no car, a vehicle said to be absent ("not another
car for miles") is none, and an "estate" that is a place ("the industrial estate") is no car."""

from __future__ import annotations

from tests.reading_of import kinds


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
