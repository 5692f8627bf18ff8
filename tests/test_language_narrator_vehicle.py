"""Which road user is the ego when the writer is in it or tests it (vei_scenario.language.
narrator_vehicle): the vehicle a first-person narrator drives, tests or introduces themselves by is
the ego (its speed the ego's), never one more actor; the others stay actors."""

from __future__ import annotations

import pytest
from reading_of import ego_kph as _ego_kph
from reading_of import kinds as _kinds


# A vehicle a first-person text names with "the" and never introduces, not placed relative to
# anyone and not meeting the narrator in its clause, is the narrator's own: the writer knows it.
@pytest.mark.parametrize(
    "text, kinds, kph",
    [
        (
            "We brought the saloon up to 50 km/h and pointed the car at a pedestrian dummy crossing from "
            "the left. The brakes came on late.",
            ["pedestrian"],
            50.0,
        ),
        (
            "Second run of the morning. A bicycle target crosses from the right at 15 km/h, the van "
            "approaching at 40 km/h, and we stopped a metre short of it.",
            ["bicycle"],
            40.0,
        ),
        (
            "A child dummy steps out from the kerb on the left at 5 km/h, the estate car arriving at 25 km/h. "
            "We stopped in time.",
            ["pedestrian"],
            25.0,
        ),
        (
            "I was on the ring road at 50 mph when a hatchback cut in front of me and the whole van shook.",
            ["car"],
            80.5,
        ),
        (
            "Night call-out, we were running at 40 mph when a pedestrian walked out from the left right in "
            "front of the fire engine.",
            ["pedestrian"],
            64.4,
        ),
        (
            "Our crew were doing 30 mph on the bypass when a cyclist swung out ahead of the minibus.",
            ["bicycle"],
            48.3,
        ),
        (
            "I'd hired a van for the move. I was driving it at 30 mph down the high street when a cyclist "
            "pulled out from a side road on the left.",
            ["bicycle"],
            48.3,
        ),
        (
            "Got a scooter from the rack by the station and was riding it at 15 km/h when a pedestrian "
            "stepped out from the right.",
            ["pedestrian"],
            15.0,
        ),
    ],
)
def test_a_first_person_texts_own_unintroduced_vehicle_is_the_ego(text, kinds, kph):
    assert _kinds(text) == kinds
    assert _ego_kph(text) == kph


# A crew's vehicle ("we") that someone crosses in front of is the crew's, and so is its driver.
@pytest.mark.parametrize(
    "text, kinds",
    [
        (
            "We were heading back at 40 km/h when a pedestrian stepped out right in front of the tanker. "
            "Driver stopped hard.",
            ["pedestrian"],
        ),
        (
            "Returning to base at 30 mph, we had a cyclist cut across the path of the minibus. The driver braked.",
            ["bicycle"],
        ),
        (
            "Report, ambulance 3. We were returning at 30 mph when a cyclist swerved in front of the ambulance. "
            "Driver braked.",
            ["bicycle"],
        ),
        (
            "We were towing at 20 mph when a jogger ran out ahead of the recovery truck, and the driver swerved.",
            ["pedestrian"],
        ),
    ],
)
def test_a_crews_vehicle_and_its_driver_are_the_ego(text, kinds):
    assert _kinds(text) == kinds


# Near misses: a vehicle introduced with "a", placed, followed, a test's target, or one that meets
# the narrator in its clause is someone else, as is any vehicle met by a narrator on a bicycle.
@pytest.mark.parametrize(
    "text, kinds",
    [
        ("We were behind a hatchback at 40 km/h that braked hard.", ["car"]),
        ("A car pulled out in front of our van at 30 mph.", ["car"]),
        ("I was cycling at 20 km/h when the van pulled out in front of me.", ["van"]),
        ("We were following the bus at 30 km/h when it stopped suddenly.", ["truck"]),
        ("We drove at 50 km/h towards the target car, which braked hard ahead of us.", ["car"]),
        ("I was doing 30 mph and the lorry pulled out of a side road on my left.", ["truck"]),
        ("A van was parked on the left. I watched it at 20 mph as a cyclist came past it.", ["van", "bicycle"]),
    ],
)
def test_a_vehicle_met_by_the_narrator_stays_a_road_user(text, kinds):
    assert _kinds(text) == kinds


# A heading that introduces the writer by their vehicle or their role at its wheel, before a story
# told in the first person: that vehicle is the ego.
@pytest.mark.parametrize(
    "text, kinds, kph",
    [
        (
            "Bin lorry driver, early shift. I'm doing 15 mph when a cyclist comes off the pavement on my left.",
            ["bicycle"],
            24.1,
        ),
        (
            "Minicab, Friday night, I was at about 25 mph and a pedestrian stepped out from the right.",
            ["pedestrian"],
            40.2,
        ),
        (
            "Coach driver here. Cruising at 60 mph when a car cut in front of me and braked hard.",
            ["car"],
            96.6,
        ),
    ],
)
def test_a_heading_that_names_the_writers_vehicle_makes_it_the_ego(text, kinds, kph):
    assert _kinds(text) == kinds
    assert _ego_kph(text) == kph


@pytest.mark.parametrize(
    "text, kinds",
    [
        ("Van, no lights, came straight at me on my side of the road at 30 mph.", ["van"]),
        ("Bus, lane 2, braking hard in front of me at 20 mph.", ["truck"]),
    ],
)
def test_a_bare_vehicle_that_acts_is_no_heading(text, kinds):
    assert _kinds(text) == kinds


# A rider the text makes the ego ("the ego is a ... rider") or calls ours ("our rider", "rider on our
# scooter") is the ego, not an e-scooter or bicycle besides it.
@pytest.mark.parametrize(
    "text, kinds, kph",
    [
        ("Ego is a cyclist riding at 20 km/h; a van overtakes it and turns left across its path.", ["van"], 20.0),
        ("Our rider on a hire bike goes at 18 km/h when a bus pulls out of a stop ahead.", ["truck"], 18.0),
        (
            "Rider on our prototype e-scooter travels at 20 km/h and a pedestrian steps out from the right.",
            ["pedestrian"],
            20.0,
        ),
    ],
)
def test_a_rider_said_to_be_the_ego_or_ours_is_the_ego(text, kinds, kph):
    assert _kinds(text) == kinds
    assert _ego_kph(text) == kph


@pytest.mark.parametrize(
    "text, kinds",
    [
        ("The ego is a car length behind a cyclist riding at 20 km/h.", ["bicycle"]),
        ("A rider on a hire bike crosses in front of our car at 15 km/h.", ["bicycle"]),
    ],
)
def test_a_rider_not_said_to_be_ours_stays_a_road_user(text, kinds):
    assert _kinds(text) == kinds


# A story with its subject left out ("Was heading ...") told in the first person: the vehicle it
# is "in" is the narrator's.
@pytest.mark.parametrize(
    "text, kinds, kph",
    [
        (
            "Was driving to work in the minibus at 40 mph when a cyclist swerved out in front of me.",
            ["bicycle"],
            64.4,
        ),
        (
            "Been sitting at 50 mph in the pickup for miles, then a car pulled out of a lay-by ahead of me.",
            ["car"],
            80.5,
        ),
    ],
)
def test_a_subjectless_story_in_a_vehicle_is_the_narrators(text, kinds, kph):
    assert _kinds(text) == kinds
    assert _ego_kph(text) == kph


# Second person: "yourself driving a van" puts the reader at its wheel.
@pytest.mark.parametrize(
    "text, kinds",
    [
        ("Imagine yourself driving a van at 30 mph when a child runs out from the left.", ["pedestrian"]),
        ("Picture yourself riding a bus at 20 mph as a cyclist pulls out from the right.", ["bicycle"]),
        ("Picture yourself driving behind a van at 30 mph when it brakes hard.", ["van"]),
    ],
)
def test_yourself_at_the_wheel_is_the_ego(text, kinds):
    assert _kinds(text) == kinds


def test_a_vehicle_someone_else_rides_stays_theirs():
    assert "e-scooter" in _kinds("A teenager took an e-scooter and was riding it at 20 km/h when he hit my car.")


# A spec's ego field whose value is a vehicle named by its place in a line ("Ego: following
# truck"): that vehicle is the ego; the one it follows ("the lead truck") stays a road user.
@pytest.mark.parametrize(
    "text, kinds",
    [
        (
            "Ego: following van, 1 s behind the lead van, both at 60 km/h. A car cuts in between them from the left.",
            ["van", "car"],
        ),
        (
            "SUT: trailing bus at 40 km/h, 25 m behind the leading bus; a cyclist pulls out from the left.",
            ["truck", "bicycle"],
        ),
        ("Subject vehicle: lead truck at 80 km/h; a car ahead of it brakes hard.", ["car"]),
    ],
)
def test_an_ego_field_naming_a_vehicle_by_its_place_in_a_line(text, kinds):
    assert _kinds(text) == kinds


def test_an_ego_field_that_places_the_ego_names_no_vehicle():
    assert _kinds("Ego: following a truck at 80 km/h; the truck brakes hard.") == ["truck"]


# "In/on the <vehicle>" with no one but the narrator before it in its sentence (a subjectless
# fragment, an adverb, or the narrator as subject past the narrator's own people) puts the narrator
# in it: the vehicle is the narrator's, the ego, never one more actor ("on" only for a two-wheeler).
@pytest.mark.parametrize(
    "text, kinds",
    [
        (
            "Back at work in the van on Monday, misty. A lad on a bike rode out from the left in front of me. "
            "I was doing 20 mph and stopped.",
            ["bicycle"],
        ),
        (
            "I take my kids to school most days, normally in the hatchback, and today a dog ran across from "
            "the right just ahead of us at 25 km/h.",
            ["pedestrian"],
        ),
        (
            "Commuting is hair-raising on the motorbike. Yesterday a taxi pulled out from a side road on my "
            "left and I had to swerve.",
            ["car"],
        ),
        (
            "Out early on the moped, a jogger stepped off the kerb on the right in front of me and I braked.",
            ["pedestrian"],
        ),
    ],
)
def test_the_vehicle_the_narrator_is_in_is_the_ego(text, kinds):
    assert _kinds(text) == kinds


@pytest.mark.parametrize(
    "text, kinds",
    [
        # someone else is in it: a road user right before the preposition
        ("I was waiting to turn when a woman in the van pulled out from the right in front of me.", ["van"]),
        # introduced before with "a": someone else's
        (
            "A taxi stopped ahead of me. I was doing 20 mph and a cyclist swerved out from behind the taxi.",
            ["car", "bicycle"],
        ),
        # placed: the car in front is someone else's
        (
            "Sat at the lights, the car in front of me rolled back and a cyclist ran the red from my right.",
            ["car", "bicycle"],
        ),
        # the narrator on foot: the moped is the lad's, and as the one vehicle that meets a writer on
        # foot it is the ego; the writer is the walker it meets
        ("I was walking to work and a lad on the moped mounted the kerb ahead of me.", ["pedestrian"]),
        # the one vehicle a walking writer sees a cyclist swerve in front of is the ego
        ("I was walking at 5 km/h when a cyclist swerved in front of the bus ahead.", ["bicycle"]),
    ],
)
def test_a_vehicle_someone_else_is_in_stays_theirs(text, kinds):
    assert sorted(_kinds(text)) == sorted(kinds)


def test_a_relative_clause_after_the_narrators_vehicle_is_no_compound():
    text = (
        "Most evenings I drive home on the A30, usually in the old Volvo which still runs fine. Last night a "
        "deer jumped out from the left ahead of me."
    )
    assert _kinds(text) == ["pedestrian"]


# A user story names the writer by a role ("As a van driver doing 40 mph ..., I want ..."): the role
# is the narrator, the ego, and the vehicle it names (or "the car" of a driver) is the ego's; "as"
# that opens a clause with a verb of its own ("As a van pulled out ...") is "while", someone else.
@pytest.mark.parametrize(
    "text, kinds, kph",
    [
        (
            "As a van driver doing 40 mph on a dual carriageway, I want the van to slow down when a car cuts "
            "in from the left lane.",
            ["car"],
            64.4,
        ),
        (
            "As a bus driver pulling away from a stop at 15 km/h, I want a warning when a cyclist overtakes "
            "the bus on the right.",
            ["bicycle"],
            15.0,
        ),
        (
            "As a commuter driving at 30 mph, I want the car to brake for a child who runs out from the left.",
            ["pedestrian"],
            48.3,
        ),
        (
            "As a driver doing 20 mph, we need the system to stop the car when a cyclist swerves into our lane.",
            ["bicycle"],
            32.2,
        ),
    ],
)
def test_a_user_storys_role_is_the_ego(text, kinds, kph):
    assert (_kinds(text), _ego_kph(text)) == (kinds, kph)


@pytest.mark.parametrize(
    "text, kinds",
    [
        ("As a cyclist passed me at 20 mph, I braked.", ["bicycle"]),
        ("As a van pulled out in front of me at 20 mph, I braked hard.", ["van"]),
    ],
)
def test_as_with_a_verb_of_its_own_is_someone_else(text, kinds):
    assert _kinds(text) == kinds
