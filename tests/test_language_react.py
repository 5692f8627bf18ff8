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


# --- a fall after the road user's own move across or in front is how that move ended ----------------
@pytest.mark.parametrize(
    "text, expected",
    [
        ("A moped rider overtook us and moved back in front, then lost control and fell.", [["overtake"]]),
        ("Scooter kid swerved into my lane right in front of me; his wheel slipped and he fell.", [["cut_in"]]),
        ("An e-scooter rider shot across the road in front of me and fell off on the far side.", [["cross_in_front"]]),
        ("A cyclist pulled out in front of my car, wobbled and came down, no contact.", [["cut_in"]]),
        ("Bike fella cut in front of me from the left side. He fall down after, no injury.", [["cut_in"]]),
    ],
    ids=["overtook-then-fell", "swerved-in-he-fell", "crossed-fell-off", "pulled-out-came-down", "cut-in-fall-down"],
)
def test_a_fall_after_a_move_in_front_is_how_it_ended(text, expected):
    assert _behaviours(text) == expected


@pytest.mark.parametrize(
    "text",
    [
        "A cyclist riding ahead of me in my lane wobbled and fell off.",  # (no move before it)
        "A van cut in ahead of me. Further on, a cyclist ahead of the van fell off.",  # (someone else's fall)
        "A lorry overtook the cyclist and the cyclist fell off.",  # (the one overtaken falls)
    ],
    ids=["riding-ahead-fell", "another-road-user-falls", "the-overtaken-falls"],
)
def test_a_fall_with_no_move_of_its_own_before_it_stays(text):
    assert any("sudden_stop" in b for b in _behaviours(text))


# --- a person named by a name, not a road user: the verb is that person's, not the road user's ----------
@pytest.mark.parametrize(
    "text, expected",
    [
        # a learner or a driver named by name, never said to be in another vehicle: the ego's driver
        (
            "Second lesson with Ottilie, 30 mph on the ring road. A courier van drifted into our lane "
            "just ahead. Ottilie braked firmly and steered left, well done.",
            [["cut_in"]],
        ),
        (
            "Coaching ride with Bartek on the A-road at 45 mph. A pickup in the outside lane veered "
            "across into his lane. Bartek slowed hard and moved over.",
            [["cut_in"]],
        ),
        (
            "Evening drive with Nkechi at 40 mph. A jogger was running along the left verge ahead. "
            "Nkechi eased off and passed wide.",
            [["along_road"]],
        ),
    ],
    ids=["learner-braked-steered", "rider-slowed-moved-over", "learner-passed-wide"],
)
def test_a_named_person_who_is_no_road_user_does_not_lend_their_verb(text, expected):
    assert _behaviours(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        # a name said only where sentences start: a word no dictionary knows, said again as a subject
        (
            "Paul was driving at 20 mph when a child ran out from the right. Paul braked at once and stopped.",
            [["cross_in_front"]],
        ),
        (
            "Aisha was doing 30 km/h when a van pulled out of a side road on her left. Aisha braked hard.",
            [["turn_into"]],
        ),
        ("Chinedu was driving home at 40 km/h. An okada cut in front of him. Chinedu stopped dead.", [["cut_in"]]),
        ("Wei Ling was at 50 km/h on the expressway. A lorry cut in ahead of her. Wei Ling braked hard.", [["cut_in"]]),
        (
            "Siobhan, 19, on a test drive at 30 mph. A cyclist crossed in front. Siobhan stopped sharply.",
            [["cross_in_front"]],
        ),
    ],
    ids=["paul-braked", "aisha-braked-hard", "chinedu-stopped-dead", "two-word-name", "name-with-age"],
)
def test_a_name_said_at_sentence_starts_is_a_person_too(text, expected):
    assert _behaviours(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        # a road user's own word at a sentence's start keeps its verb, however tersely said
        (
            "We were doing 30. A van pulled out of a side road on the left. Van braked hard.",
            [["turn_into", "sudden_stop"]],
        ),
        ("I was doing 40 km/h. Lorry ahead of me braked hard.", [["sudden_stop"]]),
    ],
    ids=["van-braked", "lorry-braked"],
)
def test_a_road_users_word_at_a_sentence_start_keeps_its_verb(text, expected):
    assert _behaviours(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        # a brand or a road user said with an article is no person's name
        ("I was doing 50 km/h behind a Skoda. The Skoda braked hard.", [["sudden_stop"]]),
    ],
    ids=["the-brand"],
)
def test_a_name_bound_to_a_road_user_keeps_its_verb(text, expected):
    assert _behaviours(text) == expected


# --- a verb of causing with its object: the infinitive is the object's, not the subject's ---------------
@pytest.mark.parametrize(
    "text, expected",
    [
        (
            "Our driver was doing 25 mph when a coach overtook on the hill and pulled in sharply, "
            "forcing him to brake.",
            [["overtake"]],
        ),
        ("A delivery van swung into the lane right in front of her, causing her to stamp on the brakes.", [["cut_in"]]),
        ("At 30 km/h a pickup nosed into our lane ahead and made us stop dead.", [["cut_in"]]),
    ],
    ids=["forcing-him-to-brake", "causing-her-to-stamp", "made-us-stop"],
)
def test_what_a_road_user_makes_someone_do_is_not_its_own(text, expected):
    assert _behaviours(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        # the subject itself forced: the infinitive is its own
        ("The van ahead of me was forced to stop by the lights.", [["stop"]]),
        # forcing its way, then its own braking as a finite verb
        ("A moped cut into my lane ahead, forcing its way in, then braked hard.", [["cut_in", "sudden_stop"]]),
    ],
    ids=["was-forced-to-stop", "forced-its-way-then-braked"],
)
def test_a_road_users_own_verb_after_forcing_stays_its_own(text, expected):
    assert _behaviours(text) == expected


# --- "had to" opening a sentence with no subject, in a story told of the ego's driver -------------------
@pytest.mark.parametrize(
    "text",
    [
        "Our member was riding at 40 mph when a lorry swept past him and cut in. Had to brake hard, no contact.",
        "The driver was doing 30 mph when a taxi swung out of a side road on the left. Had to stamp on the brakes.",
        "She was cycling at 15 mph when a van squeezed past her and pulled in. Needed to brake sharply.",
    ],
    ids=["member-had-to-brake", "driver-had-to-stamp", "she-needed-to-brake"],
)
def test_an_opening_modal_without_subject_is_the_protagonists(text):
    assert "sudden_stop" not in _behaviours(text)[0]


# --- "no" with a modifier before a behaviour noun denies it ---------------------------------------------
@pytest.mark.parametrize(
    "text, denied",
    [
        (
            "A pedestrian crossed from the left in front of the car at 30 km/h. No pre-impact braking was seen.",
            "sudden_stop",
        ),
        ("A cyclist rode out of a driveway ahead of the ego; no sudden swerving, no harsh braking.", "sudden_stop"),
        ("The bus ahead moved off from the stop; there was no late braking.", "sudden_stop"),
    ],
    ids=["no-pre-impact-braking", "no-harsh-braking", "no-late-braking"],
)
def test_no_with_a_modifier_denies_the_behaviour_noun(text, denied):
    assert all(denied not in b for b in _behaviours(text))


def test_a_road_user_with_no_lights_braking_still_brakes():
    assert "sudden_stop" in _behaviours("A cyclist with no lights braking suddenly in front of me.")[0]


# --- crashing into someone is the contact, the outcome, not a behaviour ---------------------------------
@pytest.mark.parametrize(
    "text, expected",
    [
        ("A moped pulled out of a side road on the left and smashed into the side of my car.", [["turn_into"]]),
        ("A motorbike came the wrong way round the bend and crashed head-on into my car.", [["wrong_way"]]),
        ("A van cut into my lane ahead and collided with the front of the bus.", [["cut_in"]]),
    ],
    ids=["smashed-into-side", "crashed-head-on-into", "collided-with-front"],
)
def test_crashing_into_a_road_user_is_the_outcome(text, expected):
    assert _behaviours(text) == expected


def test_a_crash_with_nothing_hit_stays_a_fall():
    assert "sudden_stop" in _behaviours("The e-scooter rider ahead of the ego crashes on the wet road.")[0]


def test_a_named_rider_said_in_apposition_keeps_its_verb():
    text = "A cyclist, Hendrik, was riding ahead of the ego at 20 km/h. Hendrik braked hard."
    assert _behaviours(text) == [["sudden_stop"]]


# --- a swerve round the ego is avoiding it and going on, not a lane change -----------------------------
@pytest.mark.parametrize(
    "text",
    [
        "I was turning left at 15 km/h when a cyclist coming the other way had to swerve round my bonnet.",
        "We were reversing out of a drive at 5 km/h when a moped swerved round us and rode off.",
        "The AV pulls out of the junction at 10 km/h and an e-scooter rider swerves around the front of the AV.",
    ],
    ids=["round-my-bonnet", "round-us", "around-the-front-of-the-av"],
)
def test_a_swerve_round_the_ego_goes_on(text):
    assert _behaviours(text)[0] == ["keep_going"]


@pytest.mark.parametrize(
    "text, expected",
    [
        # round something standing in its lane: the lead moves out and reveals it
        ("On the motorway the car in front of me swerved round a broken-down van in our lane.", "cut_out"),
        # round another road user named: not the ego
        ("A cyclist swerved round the front of the bus and into my lane.", "change_lane"),
    ],
    ids=["round-a-broken-down-van", "round-the-bus"],
)
def test_a_swerve_round_something_else_is_no_going_on(text, expected):
    assert _behaviours(text)[0][0] == expected


# --- a clause of the narrator's own inside a sentence without its subject does not end the narrator's ---
@pytest.mark.parametrize(
    "text, expected",
    [
        (
            "I was doing 50 km/h. A jogger was running along the left verge ahead. "
            "Hung back until I could see the road was empty and went past him wide.",
            [["along_road"]],
        ),
        (
            "I was riding at 25 km/h. Two joggers were running along the verge ahead of me. "
            "Slowed right down until we were past the bend and overtook them.",
            [["along_road"], ["along_road"]],
        ),
        (
            "I was cycling at 20 km/h. A man was walking along the kerb in front of me. "
            "Waited until I was sure and overtook him.",
            [["along_road"]],
        ),
    ],
    ids=["hung-back-until-i", "slowed-until-we", "waited-until-i"],
)
def test_the_narrators_subordinate_clause_keeps_the_sentence_the_narrators(text, expected):
    assert _behaviours(text) == expected


# --- a stop after a verb of touching is the aftermath only when a road user was touched ----------------
@pytest.mark.parametrize(
    "text, expected",
    [
        # the verb of contact has something else as its object: the stop after it is the road user's
        ("I hit the brakes and the taxi in front of me stopped at the lights.", [["stop"]]),
        ("I tapped my horn, and then the minibus ahead of me pulled up at the kerb.", [["stop"]]),
        ("We touched 60 km/h before the tractor in front of us stopped at the gate.", [["stop"]]),
        # the contact is denied or only nearly happened: nothing ended in it
        ("The car in front of me did not hit anyone; it stopped at the zebra crossing.", [["stop"]]),
    ],
    ids=["hit-the-brakes", "tapped-the-horn", "touched-a-speed", "did-not-hit"],
)
def test_a_stop_after_a_touch_of_no_road_user_is_the_road_users(text, expected):
    assert _behaviours(text) == expected


@pytest.mark.parametrize(
    "text",
    [
        "A courier van clipped my wing mirror and stopped about twenty metres further on.",
        "The moped tapped my rear bumper, then stopped a little way up the road.",
        "A taxi bumped into the back of my car. It stopped a few metres later.",
    ],
    ids=["clipped-mirror", "tapped-bumper", "bumped-into"],
)
def test_a_stop_after_touching_a_road_user_is_the_aftermath(text):
    assert all("stop" not in b for b in _behaviours(text))


@pytest.mark.parametrize(
    "text, expected",
    [
        # a stop said as what came first is the contact's cause, the road user's own act
        ("I rear-ended the taxi ahead when it stopped at the lights.", [["stop"]]),
        ("We shunted a hatchback at the junction; it had stopped very suddenly right ahead of us.", [["sudden_stop"]]),
        ("I rear-ended the taxi ahead when it stopped sharply at the lights.", [["sudden_stop"]]),
    ],
    ids=["when-it-stopped", "had-stopped", "stopped-sharply"],
)
def test_a_stop_said_as_the_contacts_cause_stays_the_road_users(text, expected):
    assert _behaviours(text) == expected


# --- a subject the reader reads as no road user: its reaction is not the road user's ------------------
@pytest.mark.parametrize(
    "text, expected",
    [
        ("A jogger stepped off the right kerb in front of the shuttle. Controller braked hard.", [["cross_in_front"]]),
        ("A moped cut in ahead of the test car at 40 km/h. The autopilot slowed sharply.", [["cut_in"]]),
        ("A child ran out into the road ahead of us. Trainee stopped dead, 3 m short.", [["cross_in_front"]]),
        ("A cyclist swung out into our lane ahead. Our software then braked to a standstill.", [["cut_in"]]),
    ],
    ids=["controller", "the-autopilot", "trainee-stopped", "our-software"],
)
def test_a_reaction_of_a_subject_that_is_no_road_user_is_not_the_road_users(text, expected):
    assert _behaviours(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        # the subject is a road user, or none is said: the road user's own
        (
            "A jogger stepped off the right kerb in front of the shuttle. Jogger stopped dead.",
            [["cross_in_front", "sudden_stop"]],
        ),
        ("A moped cut in ahead of the test car. Then braked sharply.", [["cut_in", "sudden_stop"]]),
        # a noun that is not a subject: a time said before the road user's own verb
        (
            "A van pulled out of a side road ahead of us. Seconds later the van braked hard.",
            [["turn_into", "sudden_stop"]],
        ),
    ],
    ids=["jogger-stopped", "then-braked", "seconds-later"],
)
def test_a_reaction_of_the_road_user_or_of_no_subject_stays_its_own(text, expected):
    assert _behaviours(text) == expected


# --- a title and a word name a person, whatever the word reads as alone --------------------------------
@pytest.mark.parametrize(
    "text, expected",
    [
        (
            "A lad on a scooter shot out of a driveway in front of the coach. Mr Jones braked hard.",
            [["cross_in_front"]],
        ),
        ("A cyclist swerved out in front of the minibus. Mrs Ones stopped dead.", [["change_lane"]]),
        ("A jogger stepped out in front of the school bus. Dr Way slowed sharply and stopped.", [["cross_in_front"]]),
    ],
    ids=["mr-jones", "mrs-ones", "dr-way"],
)
def test_a_titled_name_is_a_person_not_the_road_user(text, expected):
    assert _behaviours(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        (
            "A kid on a bike veers out across the road ahead of the test car. The examiner's braking decides it.",
            [["cross_in_front"]],
        ),
        (
            "A moped cuts in ahead of the shuttle at 30 km/h; the controller's hard braking is what we test.",
            [["cut_in"]],
        ),
        (
            "A jogger steps off the kerb in front of the ego. Leave the planner's emergency stop to the sim.",
            [["cross_in_front"]],
        ),
    ],
    ids=["drivers-braking", "controllers-braking", "planners-stop"],
)
def test_a_reaction_owned_by_a_subject_that_is_no_road_user_is_not_the_road_users(text, expected):
    assert _behaviours(text) == expected


def test_a_reaction_owned_by_the_road_user_stays_its_own():
    text = "A moped cuts in ahead of the shuttle at 30 km/h and the moped's hard braking ends it."
    assert _behaviours(text) == [["cut_in", "sudden_stop"]]


# --- "it stopped" in a story told by "I": "it" is the road user, never the narrator ----------------------
@pytest.mark.parametrize(
    "text, expected",
    [
        ("I was behind a van, it stopped for no reason.", [["stop"]]),
        ("We followed a tractor for a mile and then it stopped in the lane.", [["stop"]]),
        ("I was queuing behind a bus when it stopped at the shelter.", [["stop"]]),
    ],
    ids=["behind-a-van", "followed-a-tractor", "queuing-behind-a-bus"],
)
def test_it_stopped_in_a_first_person_story_is_the_road_users_stop(text, expected):
    assert _behaviours(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        ("A cyclist came up on my left at the lights. I stopped and he went past.", [["keep_going"]]),
        ("I stopped at the junction and a cyclist went past; it was raining.", [["keep_going"]]),
        ("The scooter braked and stopped at the line.", [["stop"]]),
    ],
    ids=["i-stopped-he-went-past", "it-was-raining", "scooter-braked-and-stopped"],
)
def test_the_narrators_stop_is_not_the_road_users(text, expected):
    assert _behaviours(text) == expected


# --- a verb with an object and "to": the infinitive is the object's act ---------------------------------
@pytest.mark.parametrize(
    "text, expected",
    [
        (
            "A pedestrian steps off the left kerb 30 m ahead of the ego at 5 km/h. We expect the ego to stop.",
            [["cross_in_front"]],
        ),
        ("A cyclist cuts in ahead of the AV. The test wants the AV to brake hard.", [["cut_in"]]),
        ("A van cuts in front of the ego car. It requires the ego to slow down to 20 km/h.", [["cut_in"]]),
    ],
    ids=["expect-the-ego-to-stop", "wants-the-av-to-brake", "requires-the-ego-to-slow"],
)
def test_the_infinitive_after_the_ego_as_object_is_the_egos(text, expected):
    assert _behaviours(text) == expected


def test_the_infinitive_after_a_road_user_as_object_is_its_own():
    text = "The ego drives at 40 km/h behind a cyclist. The test wants the cyclist to brake hard."
    assert _behaviours(text) == [["sudden_stop"]]


def test_a_vehicle_owned_by_a_person_keeps_its_verb():
    assert "cut_in" in _behaviours("The plumber's van cut in right in front of us at 30 mph.")[0]
