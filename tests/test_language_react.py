"""Whose behaviour a verb is: the narrator's reactions and manoeuvres, said without a subject, are not
the road user's; a behaviour said not to be meant or not to happen is not read."""

from __future__ import annotations

import pytest

from vei_scenario.language.reader import read


def _behaviours(text: str) -> list[list[str]]:
    return [[b[0] for b in a.behaviours] for a in read(text).actors]


# --- a sentence with its subject left out, in a story told by its driver --------------------------------
@pytest.mark.parametrize(
    "text, expected",
    [
        # a reaction said as a modal and a verb with "the brakes" as its object
        ("A cyclist wobbled into my lane. Needed to stamp on the brakes.", [["cut_in"]]),
        ("A taxi veered into my lane ahead of me. Had to jump on the brakes.", [["cut_in"]]),
        ("A delivery van nosed into my lane. Managed to get on the brakes in time.", [["cut_in"]]),
        # the narrator passing a road user named before: that one just goes along
        (
            "I was driving at 50 km/h. A jogger was running along the left edge ahead. "
            "Waited for a gap and passed him wide.",
            [["along_road"]],
        ),
        (
            "I was cycling at 15 km/h. A woman was walking along the verge ahead of me. "
            "Rang my bell and overtook her slowly.",
            [["along_road"]],
        ),
        (
            "I was doing 40 km/h. A man was walking along the kerb on my left. "
            "Slowed right down and went past him carefully.",
            [["along_road"]],
        ),
    ],
    ids=["needed-to-stamp", "had-to-jump", "managed-to-get-on", "waited-passed-him", "overtook-her", "went-past"],
)
def test_a_sentence_without_its_subject_is_the_narrators(text, expected):
    assert _behaviours(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        # the road user's own braking, its subject named, stays its own
        ("The lorry in front of me slammed on its brakes.", [["sudden_stop"]]),
        ("I was at 40 km/h. The bus ahead of me jumped on its brakes.", [["sudden_stop"]]),
        # said in the third person with no subject: the road user's, not the narrator's
        ("A van pulled out in front of me. Brakes hard right after.", [["cut_in", "sudden_stop"]]),
        # told of someone else, not by its driver: a subject-less verb goes on with the road user
        ("A cyclist rides ahead of the ego. Then overtakes a parked car.", [["overtake"], ["stop"]]),
    ],
    ids=["lorry-own-brakes", "bus-own-brakes", "third-person", "not-first-person"],
)
def test_a_road_users_own_verb_stays_its_own(text, expected):
    assert _behaviours(text) == expected


# --- a behaviour said not to be meant or not to happen ----------------------------------------------
@pytest.mark.parametrize(
    "text, denied",
    [
        ("An e-scooter rides in the bike lane beside the ego at 15 km/h, no crossing intended.", "cross_in_front"),
        ("A cyclist rides on the cycle track next to us at 18 km/h with no intention of crossing.", "cross_in_front"),
        ("A pedestrian walks along the right verge towards the ego, showing no sign of crossing.", "cross_in_front"),
        ("A moped goes along the kerb ahead of the ego at 20 km/h, no overtaking.", "overtake"),
        ("The car in front drives on at 40 km/h, no braking at all.", "sudden_stop"),
    ],
    ids=["no-crossing-intended", "no-intention-of", "no-sign-of", "no-overtaking", "no-braking"],
)
def test_a_behaviour_said_not_to_happen_is_not_read(text, denied):
    read_ = _behaviours(text)
    assert len(read_) == 1 and denied not in read_[0]


@pytest.mark.parametrize(
    "text, expected",
    [
        # "no" that is not the verb's: a behaviour said after it is still read
        ("No lights on, a cyclist crosses in front of the ego.", "cross_in_front"),
        ("With no warning, the lorry ahead brakes hard.", "sudden_stop"),
        ("There was no time to react when a jogger ran across in front of me.", "cross_in_front"),
    ],
    ids=["no-lights", "no-warning", "no-time"],
)
def test_a_behaviour_after_an_unrelated_no_is_read(text, expected):
    read_ = _behaviours(text)
    assert any(expected in b for b in read_)


# --- a road user at the side that swerves out into the road before the ego ----------------------------
@pytest.mark.parametrize(
    "text",
    [
        "A cyclist in the bike lane on my right swerved out into the road right in front of me.",
        "An e-scooter rider on the cycle track beside us veers out into the carriageway just ahead of us.",
        "A cyclist at the kerb on the left wobbles out into the traffic right in front of the ego.",
        "An e-scooter in the cycle lane on my right swerves out just in front of me.",
    ],
    ids=["bike-lane-into-road", "cycle-track-into-carriageway", "kerb-into-traffic", "cycle-lane-in-front"],
)
def test_a_swerve_out_from_the_side_before_the_ego_enters_its_path(text):
    read_ = _behaviours(text)
    assert read_[0][:1] in (["cut_in"], ["cross_in_front"])  # (into the ego's path, either way)


@pytest.mark.parametrize(
    "text, expected",
    [
        # out of the lane with nothing said of the ego's path: a move aside, not into it
        ("A cyclist in the bike lane on my right swerved out to avoid a pothole.", "cut_in"),
        # a lead car in the ego's lane swerving out: not from the side of the road
        ("On the motorway the car in front of me swerved out into the outside lane.", "cut_in"),
    ],
    ids=["avoids-a-pothole", "lead-car-swerves-out"],
)
def test_a_swerve_out_not_from_the_side_into_the_ego_path_is_no_cut_in(text, expected):
    assert expected not in _behaviours(text)[0]


# --- a run-on sentence: "had to" with its subject left out starts the narrator's own clause --------------
@pytest.mark.parametrize(
    "text, expected",
    [
        ("so a van pulled out of a side road right in front of me had to brake hard", [["turn_into"]]),
        ("this cyclist swung into my lane just ahead of us had to jam on the brakes", [["cut_in"]]),
        ("i was doing 40 and a taxi nosed into my lane no signal nothing needed to slow right down", [["cut_in"]]),
        ("a bus pulled out from the stop in front of me, had to stamp on the brakes", [["cut_in"]]),
    ],
    ids=["van-had-to-brake", "cyclist-had-to-jam", "taxi-needed-to-slow", "bus-comma-had-to"],
)
def test_a_run_on_modal_without_its_subject_is_the_narrators(text, expected):
    assert _behaviours(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        # joined by "and", the road user goes on as the subject
        ("The bus cut in front of me and had to stop at the lights.", [["cut_in", "stop"]]),
        # the road user named right before the modal is its subject
        ("I was doing 30 mph when the cyclist ahead of me had to brake hard.", [["sudden_stop"]]),
    ],
    ids=["joined-by-and", "subject-before-modal"],
)
def test_a_modal_with_the_road_user_as_its_subject_stays_its_own(text, expected):
    assert _behaviours(text) == expected


# --- "the rider": the road user named before that rides, said again -----------------------------------
@pytest.mark.parametrize(
    "text, expected",
    [
        (
            "A cyclist rides 15 m ahead of the ego at 18 km/h; the ego follows at 30 km/h. "
            "After 4 s the rider makes an emergency stop.",
            [["sudden_stop"]],
        ),
        (
            "I was following a lad on an e-scooter at 25 km/h. Then the rider slammed on his brakes.",
            [["sudden_stop"]],
        ),
        (
            "An e-scooter rider is ahead of the AV in its lane; the AV keeps 20 m behind. This rider then stops hard.",
            [["sudden_stop"]],
        ),
    ],
    ids=["cyclist-then-the-rider", "lad-on-e-scooter", "this-rider"],
)
def test_the_rider_is_the_riding_road_user_named_before(text, expected):
    assert _behaviours(text) == expected


# --- a fall after contact is the outcome, not a second behaviour ----------------------------------------
@pytest.mark.parametrize(
    "text, expected",
    [
        ("A cyclist cut in front of the ego, clipped its bumper and fell off.", [["cut_in"]]),
        ("A cyclist cut in ahead of me, struck my wing mirror, falling into the road.", [["cut_in"]]),
        ("A moped cut in ahead of us and collided with our bumper, then fell over.", [["cut_in"]]),
    ],
    ids=["clipped-fell-off", "struck-falling", "collided-then-fell"],
)
def test_a_fall_after_contact_is_the_outcome(text, expected):
    assert _behaviours(text) == expected


def test_a_fall_with_no_contact_before_it_stays_a_behaviour():
    assert "sudden_stop" in _behaviours("The cyclist ahead of the ego falls off on the wet road.")[0]
