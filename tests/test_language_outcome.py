"""The outcome a description states, read from the structure of its clauses
(:mod:`vei_scenario.language.outcome`). Each group is one construction, in wordings written for it
(none taken from a corpus)."""

from __future__ import annotations

import pytest

from vei_scenario.language.outcome import outcome_cues, stated_intent
from vei_scenario.language.reader import _tokens, read


def _intent(text: str) -> str | None:
    return stated_intent(" ".join(_tokens(text)))


def _case(group: dict[str, list[str]]):
    return [(text, intent) for intent, texts in group.items() for text in texts]


# a verb of contact, in any tense or voice, or a noun of one: a collision
CONTACT = {
    "collision": [
        "The moped was rammed by a van at the lights.",
        "A jogger got sideswiped by the bus.",
        "I grazed the cyclist with my wing mirror.",
        "The delivery bike clipped our front wing as it passed.",
        "The tram ploughed into the back of the taxi.",
        "I rolled into the side of her at walking pace.",
        "Report: lorry vs cyclist at the lights, ambulance requested.",
        "There was a sickening thud and the scooter went under the car.",
        "The lorry swiped my wing mirror.",
        "A van shunted us from behind at the lights.",
        "The motorbike wiped out the cyclist.",
        "The e-bike rider was thrown over the bonnet.",
    ],
}
# a contact denied in its clause, or hedged: not a collision
DENIED_OR_HEDGED = {
    "near_miss": [
        "I stood on the brakes and never touched him.",
        "We dodged left without touching the skateboarder.",
        "The ego braked hard, so no collision occurred.",
        "The bus nearly flattened us.",
        "The ego narrowly avoided hitting the pram.",
        "That courier almost wiped me out on the bend.",
    ],
}
# two denials cancel: the contact happened
DOUBLE_DENIAL = {
    "collision": [
        "The taxi was unable to avoid a crash with the moped.",
        "Our car could not avoid the collision with the jogger.",
        "The minibus failed to prevent an impact with the rider.",
    ],
}
# a verb of missing with someone as its object, or a small margin: a near miss
MISS_AND_MARGIN = {
    "near_miss": [
        "He missed my mirror by a hand's width.",
        "The two scooters missed one another somehow.",
        "I pulled up a few centimetres short of the pram.",
        "The ego came to a halt three feet from her.",
        "Honestly, it was tight.",
    ],
}
# trouble denied, or someone giving way with nothing else said: a safe pass
SAFE = {
    "safe": [
        "The bus pulled out well ahead. No dramas at all.",
        "Nothing untoward happened at the roundabout.",
        "The tractor waited at the gate and let me through.",
        "I hung back behind the horse riders until the lane widened.",
        "The van moved over with loads of space to spare.",
    ],
}
# the ego's evasion, with no contact said: a near miss
EVASION = {
    "near_miss": [
        "A lorry drifted across, I veered onto the verge.",
        "The cyclist wobbled out and we swerved hard right.",
        "Yanked the wheel and got round my neighbour's pushchair somehow.",
        "The van kept coming as if nothing happened, so I had to dodge him.",
    ],
}
# what would have happened, or came within a margin of happening: a near miss
COUNTERFACTUAL = {
    "near_miss": [
        "The kid came within a metre of hitting her.",
        "If I had not swerved, I would have hit him.",
        "If the ego hadn't braked, it'd have struck the jogger.",
        "The van stopped inches from my door.",
        "I only just got out of the way.",
        "The ego stops half a metre before the child.",
        "Expected outcome: minimum TTC 0.8 s.",
        "The TTC dropped to 0.9 s as the van merged.",
        "The lowest time to collision was 1.1 s.",
    ],
}
# what is denied of a near miss, or free of trouble, is a safe pass
SAFE_FORMS = {
    "safe": [
        "All clear.",
        "No near miss, no collision, nothing.",
        "A collision-free pass of the cyclist, please.",
        "The ego passes the horse riders comfortably.",
        "The cut-in goes smoothly.",
    ],
}
# a body thrown onto or off the ego's parts was hit
THROWN = {
    "collision": [
        "He bounced off my bonnet and landed in the road.",
        "The cyclist rolled over the windscreen.",
        "The jogger slid across the hood and over the roof.",
    ],
}
# nothing about the outcome is said: none is assumed
UNSAID = {
    None: [
        "A cyclist rides ahead of the ego at 20 km/h.",
        "The ego hits 50 km/h just before the junction.",
        "Traffic was slow because of a tube strike, and a van cut in ahead.",
        "A car pulls into my lane about 30 m ahead.",
        "Keep the time-to-collision above 2 s while the van merges.",
        "A truck ahead of the ego brakes sharply.",
        "The van behind tailgated me way too close.",
        "The lorry pulled off the hard shoulder ahead of us.",
        "Trigger the van when the time-to-collision reaches 1.5 s.",
        "A bus ahead pulls in smoothly at its stop.",
    ],
}


# a noun of an event or of trouble negated by its prefix ("non-"): nothing happens, a safe pass
NEGATED_BY_PREFIX = {
    "safe": [
        "The tractor pulling out should be a total non-event for the driver.",
        "Make the cyclist's crossing a nonevent, please.",
        "For the ego this merge is a non-issue.",
    ],
}
# a phrasal verb of contact (verb + out/down/over) with a road user as its object; hedged, a near miss
PHRASAL_CONTACT = {
    "collision": [
        "The van took out a cyclist at the lights.",
        "A lorry knocked the jogger over on the zebra.",
        "The taxi took the scooter rider out on the bend.",
    ],
    "near_miss": [
        "Honestly I very nearly took out a dog walker this morning.",
        "That bus almost took me out at the roundabout.",
        "The moped nearly knocked over a pensioner.",
    ],
    None: [
        "The courier took out his phone at the lights.",
        "She took out a loan for the van.",
    ],
}
# a road user sent flying by a blow, or landing on the ego's parts: a contact
SENT_FLYING = {
    "collision": [
        "The taxi sent the jogger flying at the crossing.",
        "A lorry clipped the scooter and sent its rider sprawling.",
        "The kid landed on my bonnet after running out.",
    ],
    None: ["The wind sent leaves flying across the road."],
}
# "a near thing": a near miss
NEAR_THING = {
    "near_miss": [
        "That was a near thing with the scooter.",
        "The bus pulled out, a near thing for the cyclist.",
        "Very near thing at the lights with a moped.",
    ],
}
# a verb of touching whose object is a part of a vehicle: a contact
PART_CONTACT = {
    "collision": [
        "The cyclist's pedal caught my rear door as he squeezed past.",
        "His handlebar caught the wing mirror of the taxi.",
        "Then the moped nicked our back bumper.",
    ],
    None: [
        "I caught sight of the scooter in my mirror.",
        "We caught up with the tractor on the hill.",
    ],
}
# a contact noun as the subject of a passive denying verb ("collision avoided"): denied or hedged
PASSIVE_DENIAL = {
    "near_miss": [
        "Ego swerves, crash only just averted.",
        "The lorry braked; a collision was narrowly prevented.",
        "Contact barely avoided as the bus pulled in.",
    ],
}
# a denied act of stopping in time: it could not be avoided, a collision
DENIED_STOP_IN_TIME = {
    "collision": [
        "The jogger stepped off the kerb and the taxi could not stop in time.",
        "A dog ran out, and the bus was unable to brake in time.",
        "The van failed to pull up in time behind the scooter.",
    ],
}
# a road user lets the ego finish what it does: it gives way, a safe pass
LETS_THE_EGO = {
    "safe": [
        "The cyclist waits at the corner and lets the ego finish its turn.",
        "A jogger pauses on the verge and lets me clear the bridge.",
        "The pedestrian holds back and lets us complete the manoeuvre.",
    ],
}
# the ego pausing for someone, with nothing else said: a safe pass
PAUSING = {
    "safe": [
        "I paused for the cyclist to clear the junction.",
        "The ego pauses at the line while the pedestrian crosses.",
        "We paused until the horse had gone by.",
    ],
}
# the direction of a turn into a place is no verb ("turned left into it"): no contact; the ego waits
TURN_INTO_A_PLACE = {
    "safe": [
        "A woman with a pram crossed the lane as we turned right into it, so we waited for her.",
        "I turned left into it and waited while the boy crossed.",
        "A dog was in the car park as I swung left into it, I stopped and let it pass.",
    ],
}
# a motion towards the ego that only begins ("starts drifting into me"): not a contact
BEGUN_MOTION = {
    "near_miss": [
        "The coach began sliding over into us on the bend, so I swerved.",
        "A van started edging into me at the lights and I braked hard.",
        "The tractor started veering into us and I dodged onto the verge.",
    ],
}


@pytest.mark.parametrize(
    "text, intent",
    _case(NEGATED_BY_PREFIX)
    + _case(SENT_FLYING)
    + _case(NEAR_THING)
    + _case(PHRASAL_CONTACT)
    + _case(PART_CONTACT)
    + _case(PASSIVE_DENIAL)
    + _case(DENIED_STOP_IN_TIME)
    + _case(LETS_THE_EGO)
    + _case(PAUSING)
    + _case(TURN_INTO_A_PLACE)
    + _case(BEGUN_MOTION),
)
def test_outcome_constructions_of_wish_and_event(text, intent):
    assert _intent(text) == intent, outcome_cues(" ".join(_tokens(text)))


@pytest.mark.parametrize(
    "text, intent",
    _case(CONTACT)
    + _case(DENIED_OR_HEDGED)
    + _case(DOUBLE_DENIAL)
    + _case(MISS_AND_MARGIN)
    + _case(SAFE)
    + _case(EVASION)
    + _case(COUNTERFACTUAL)
    + _case(SAFE_FORMS)
    + _case(THROWN)
    + _case(UNSAID),
)
def test_the_outcome_is_read_from_the_clause(text, intent):
    assert _intent(text) == intent, outcome_cues(" ".join(_tokens(text)))


def test_contact_after_a_near_miss_is_a_collision():
    assert _intent("He missed the first scooter by inches but then struck the second one.") == "collision"


def test_a_negation_ends_with_its_clause():
    # ("not" denies the stop; the contact after "and" stands)
    assert _intent("The lorry did not stop and hit the cyclist.") == "collision"


def test_each_cue_names_the_clause_it_was_read_from():
    cues = outcome_cues(" ".join(_tokens("The van braked late, but no contact.")))
    assert [(c.kind, c.words) for c in cues] == [("denied", "no contact")]


def test_the_reader_takes_the_stated_outcome():
    assert read("A rider on an e-scooter shoots out from the left and I tag him at 20 km/h.").intent == "collision"
    assert read("A cyclist crosses ahead from the left; the ego waits and lets him go.").intent == "safe"


# a weather word before its noun ("on a fine, dry evening") describes the day, not how things went
@pytest.mark.parametrize(
    "text, intent",
    [
        ("On a fine, dry evening a van cuts in front of the ego.", None),
        ("A fine clear day; a moped pulls out of a drive ahead of me.", None),
        ("A van cut in on a fine morning but it was fine.", "safe"),
    ],
    ids=["fine-dry-evening", "fine-clear-day", "it-was-fine"],
)
def test_fine_before_its_noun_is_the_weather_not_a_verdict(text, intent):
    assert _intent(text) == intent


# a stop short by a wide margin ("well short") is a safe stop; by a small one a near miss
@pytest.mark.parametrize(
    "text, intent",
    [
        ("The bus pulled up well short of the jogger.", "safe"),
        ("I came to a halt comfortably short of the pram.", "safe"),
        ("We stopped a long way short of the cyclist.", "safe"),
        ("I stopped just short of the jogger.", "near_miss"),
        ("I pulled up a foot short of her.", "near_miss"),
    ],
    ids=["well-short", "comfortably-short", "long-way-short", "just-short", "foot-short"],
)
def test_a_stop_short_by_a_wide_margin_is_safe(text, intent):
    assert _intent(text) == intent


# "wipe out" with no one as its object is a fall, not a contact
@pytest.mark.parametrize(
    "text, intent",
    [
        ("A moped wiped out on the wet cobbles ahead of me.", None),
        ("The cyclist wipes out just ahead of the ego, no contact.", "near_miss"),
        ("The van wiped the rider out at the junction.", "collision"),
    ],
    ids=["moped-wiped-out", "wipes-out-no-contact", "wiped-the-rider-out"],
)
def test_wiping_out_alone_is_a_fall(text, intent):
    assert _intent(text) == intent


# the ego forced off its line ("had to mount the verge to avoid it"): a near miss
@pytest.mark.parametrize(
    "text, intent",
    [
        ("A tractor came round wide and I had to mount the verge to avoid it.", "near_miss"),
        ("The lorry strayed over the line; we were forced onto the grass to avoid it.", "near_miss"),
        ("A van came at us in our lane so I had to go up on the kerb.", "near_miss"),
        ("A tractor came round the bend and I had to wait for it.", "safe"),
    ],
    ids=["mount-the-verge", "forced-onto-grass", "up-on-the-kerb", "had-to-wait"],
)
def test_the_ego_forced_off_its_line_is_a_near_miss(text, intent):
    assert _intent(text) == intent


# a contact denied as what the test requires ("must not touch him") states the safe outcome wanted
@pytest.mark.parametrize(
    "text, intent",
    [
        ("The ego has to pass the jogger and must not touch her.", "safe"),
        ("The test car should get by the scooter without hitting it.", "safe"),
        ("Ego needs to overtake the rider and not make contact.", "safe"),
        ("The van must not have seen me and nearly hit me.", "near_miss"),
        ("I braked hard and stopped; no contact.", "near_miss"),
    ],
    ids=["must-not-touch", "should-without-hitting", "needs-to-not-contact", "must-not-have-seen", "braked-hard"],
)
def test_a_contact_denied_as_a_requirement_is_a_safe_outcome(text, intent):
    assert _intent(text) == intent


# passing wide of someone is a safe pass
@pytest.mark.parametrize(
    "text, intent",
    [
        ("The learner overtook the cyclist nice and wide.", "safe"),
        ("We went round the jogger wide.", "safe"),
        ("A wide load overtook me and cut in.", None),
    ],
    ids=["overtook-wide", "went-round-wide", "wide-load"],
)
def test_passing_wide_is_a_safe_pass(text, intent):
    assert _intent(text) == intent


# a one-word verdict ends its sentence ("Clear." after the event); in a list of notes ("Clear, 3 pm") it is the sky
@pytest.mark.parametrize(
    "text, intent",
    [
        ("A van cut in ahead of the test car and braked. No contact. Clear, dry, 4 pm.", "near_miss"),
        ("Sunny, clear, light traffic; a moped pulls out in front of me.", None),
        ("A cyclist waited at the kerb and the ego went by. Clear.", "safe"),
    ],
    ids=["clear-in-notes", "clear-in-a-list", "clear-verdict"],
)
def test_a_one_word_verdict_ends_its_sentence(text, intent):
    assert _intent(text) == intent


# a pass with a strong degree of closeness ("passed so close", "overtook far too close"): a near miss
@pytest.mark.parametrize(
    "text, intent",
    [
        ("A taxi overtook us really close on the bridge.", "near_miss"),
        ("The lorry went by me far too close, then pulled in.", "near_miss"),
        ("A van squeezed past so close that I felt the wind.", "near_miss"),
        ("The cyclist rode too close to the kerb and a car passed him.", None),
    ],
    ids=["overtook-really-close", "went-by-too-close", "squeezed-so-close", "close-to-the-kerb"],
)
def test_a_pass_said_too_close_is_a_near_miss(text, intent):
    assert _intent(text) == intent


# going only once the way is clear is a safe pass
@pytest.mark.parametrize(
    "text, intent",
    [
        ("The learner only pulled out once the road was clear.", "safe"),
        ("The bus held back until it was clear, then overtook the cyclist.", "safe"),
        ("It was clear and bright when a van cut across in front of me.", None),
    ],
    ids=["once-the-road-was-clear", "until-it-was-clear", "clear-and-bright"],
)
def test_going_once_the_way_is_clear_is_safe(text, intent):
    assert _intent(text) == intent


# meeting someone head-on is a collision; coming head-on is only a direction
@pytest.mark.parametrize(
    "text, intent",
    [
        ("On the bend the van met the tractor head-on.", "collision"),
        ("They met head on in the middle of the bridge.", "collision"),
        ("A lorry came head-on towards us in our lane.", None),
    ],
    ids=["met-the-tractor-head-on", "met-head-on", "came-head-on"],
)
def test_meeting_head_on_is_a_collision(text, intent):
    assert _intent(text) == intent


@pytest.mark.parametrize(
    "text, intent",
    [
        ("I overtook the tractor and then my phone app crashed twice.", None),
        ("The cyclist swerved round the bin lorry; later the booking website crashed.", None),
        ("A moped pulled out in front of us and the dashcam software crashed.", None),
        ("The van turned into the side road and crashed.", "collision"),  # (a road user crashing)
        ("Two scooters collided outside the station.", "collision"),
    ],
)
def test_a_crash_said_of_a_thing_that_is_no_road_user_is_not_a_contact(text, intent):
    assert _intent(text) == intent


@pytest.mark.parametrize(
    "text, intent",
    [
        ("A moped overtook and swung across my bonnet into the petrol station.", None),
        ("The jogger ran across the front of the bus.", None),
        ("The cyclist darted across my bumper to reach the cycle path.", None),
        ("The rider slid across my bonnet.", "collision"),  # (a body thrown over it)
        ("She bounced off the windscreen of the taxi.", "collision"),
    ],
)
def test_across_a_vehicle_part_after_a_verb_of_going_is_a_path_not_a_contact(text, intent):
    assert _intent(text) == intent


@pytest.mark.parametrize(
    "text, intent",
    [
        ("A lad on a bike pulled out of the car park, straight into my passenger door.", "collision"),
        ("The scooter came off the kerb and smack into the side of the bus.", "collision"),
        ("The van reversed out. Right into the back of my car.", "collision"),
        ("Then the moped came through the gap and under the front of the lorry.", "collision"),
        ("A cyclist rode under the nearside front wheel of the tipper.", "collision"),
        ("A moped came out of the side road and straight into my lane.", None),  # (a place)
        ("The cyclist rode under the railway bridge and into the junction.", None),
    ],
)
def test_a_verbless_into_or_under_a_vehicle_part_is_a_contact(text, intent):
    assert _intent(text) == intent


@pytest.mark.parametrize(
    "text, intent",
    [
        ("A jogger ran out and I stopped only feet from her.", "near_miss"),
        ("The bus braked and pulled up mere inches from the cyclist.", "near_miss"),
        ("A scooter cut in barely 2 m in front of us.", "near_miss"),
        ("The hatchback merged back about one metre ahead of me.", "near_miss"),
        ("The van cut in 30 m in front of us.", None),
        ("The lorry stopped 2 m in front of the stop line.", None),
    ],
)
def test_a_small_distance_from_the_other_is_a_near_miss(text, intent):
    assert _intent(text) == intent


@pytest.mark.parametrize(
    "text, intent",
    [
        ("Outcome: ego stops, no crash (close call).", "near_miss"),
        ("Pass criteria: no impact (near miss acceptable).", "near_miss"),
        ("The car behind braked, no collision, no near miss.", "safe"),
    ],
)
def test_a_negation_governs_its_noun_phrase_not_one_after_it(text, intent):
    assert _intent(text) == intent


@pytest.mark.parametrize(
    "text, intent",
    [
        ("The moped waited at the give way line. No interaction with the ego.", "safe"),
        ("A lorry changed lanes two lanes over, with no interaction at all.", "safe"),
        ("The cyclist had an interaction with the bus driver.", None),
    ],
)
def test_no_interaction_is_a_safe_pass(text, intent):
    assert _intent(text) == intent


@pytest.mark.parametrize(
    "text, intent",
    [
        ("A pedestrian was killed when a bus mounted the pavement.", "collision"),
        ("Two cyclists were badly hurt after a van turned across them.", "collision"),
        ("The scooter rider got injured when the taxi pulled out.", "collision"),
        ("Nobody was injured, the moped braked in time.", "near_miss"),
        ("The cyclist escaped injury when the van stopped short of him.", "near_miss"),
        ("My knee was injured last year so I drive an automatic.", None),
    ],
)
def test_a_road_user_injured_is_a_collision(text, intent):
    assert _intent(text) == intent


@pytest.mark.parametrize(
    "text, intent",
    [
        ("A cyclist came at me on the narrow lane and squeezed by.", "near_miss"),
        ("The taxi squeezed through between me and the parked van.", "near_miss"),
        ("A moped squeezed past us on the bridge.", "near_miss"),
        ("I squeezed the brake lever gently and the bus pulled away.", None),
        ("We squeezed in a coffee before the moped overtook us.", None),
    ],
)
def test_squeezing_past_is_a_tight_pass(text, intent):
    assert _intent(text) == intent


@pytest.mark.parametrize(
    "text, intent",
    [
        ("The jogger stepped out. I should have waited. He had to jump back onto the kerb.", "near_miss"),
        ("A van turned across me. I could have given way. He had to swerve round my bumper. No contact.", "near_miss"),
        ("I waited for the moped to pass.", "safe"),
    ],
)
def test_a_yield_under_a_modal_of_hindsight_did_not_happen(text, intent):
    assert _intent(text) == intent


@pytest.mark.parametrize(
    "text, intent",
    [
        ("A boy on a bike came off the path and I had to stop dead. The boy was fine.", "near_miss"),
        ("The pram rolled into the road, I stopped dead. The baby was okay.", "near_miss"),
        ("The scooter rider swerved and clipped my mirror. She was fine.", "collision"),
        ("The cyclist kept to the kerb and the pass was fine.", "safe"),
    ],
)
def test_a_person_said_fine_is_unhurt_not_a_safe_pass(text, intent):
    assert _intent(text) == intent


@pytest.mark.parametrize(
    "text, intent",
    [
        ("The bus pulled out on me. No damage, just a fright.", "near_miss"),
        ("A cyclist swung out in front of the van, no injuries.", "near_miss"),
        ("The moped scraped along my door. No injuries.", "collision"),
    ],
)
def test_no_damage_or_injury_denies_a_contact(text, intent):
    assert _intent(text) == intent


@pytest.mark.parametrize(
    "text, intent",
    [
        ("The jogger darted out and I stamped on the brakes. Stopped in time. Just.", "near_miss"),
        ("Lorry drifted over into my lane. Made it. Just!", "near_miss"),
        ("It was just a normal day when the cyclist turned left.", None),
    ],
)
def test_just_as_a_sentence_of_its_own_is_barely(text, intent):
    assert _intent(text) == intent


@pytest.mark.parametrize(
    "text, intent",
    [
        ("Server crashed overnight; a cyclist passed the van wide.", "safe"),
        ("Laptop crashed. Next run: the moped cuts in and clips the ego.", "collision"),
        ("Van crashed.", "collision"),
        ("We need the cyclist to cross late. The ego should brake hard and avoid contact.", "near_miss"),
        ("Slow down there before someone gets killed; a van nearly hit me.", "near_miss"),
    ],
)
def test_bare_subjects_and_modals_of_requirement(text, intent):
    assert _intent(text) == intent


@pytest.mark.parametrize(
    "text, intent",
    [
        ("Both riders wobble, nobody hits anybody.", "near_miss"),
        ("Someone crashed into the back of the bus.", "collision"),
    ],
)
def test_indefinite_pronoun_subjects_are_people(text, intent):
    assert _intent(text) == intent


@pytest.mark.parametrize(
    "text, intent",
    [
        ("I still can't work out how I stopped in time for the jogger.", "near_miss"),
        ("No idea how I missed the scooter, honestly.", "near_miss"),
        ("I do not know why she did not hit the van.", "near_miss"),
        # near misses of the construction: the negation is the clause's own
        ("The moped did not hit the kerb-side jogger.", "near_miss"),
        ("I did not see the cyclist and hit him.", "collision"),
    ],
)
def test_a_negation_stops_at_a_wh_complement(text, intent):
    """ "don't know how I stopped in time": the negation is of knowing, not of what is known."""
    assert _intent(text) == intent


@pytest.mark.parametrize(
    "text, intent",
    [
        ("Rather than hitting the scooter, the bus driver swerved onto the verge.", "near_miss"),
        ("I waited behind the cyclist instead of squeezing through.", "safe"),
        ("Instead of nipping past the jogger, I held back until the road was clear.", "safe"),
        # near misses: what is done, with the alternative set aside after it
        ("Instead of waiting, the van squeezed past me.", "near_miss"),
        ("The cyclist hit my door rather than the kerb.", "collision"),
    ],
)
def test_what_is_done_instead_of_is_not_done(text, intent):
    """ "instead of squeezing past", "rather than hitting him": the alternative set aside did not happen."""
    assert _intent(text) == intent


@pytest.mark.parametrize(
    "text, intent",
    [
        ("A moped cut across the tram tracks in front of us, nobody hurt.", "near_miss"),
        ("The lorry cut across the roundabout in front of me. No one injured.", "near_miss"),
        ("Van and cyclist at the lights, no-one hurt.", "near_miss"),
        # near misses: harm stated, or a verb with its object
        ("Two people hurt after the bus hit a car.", "collision"),
    ],
)
def test_nobody_hurt_without_its_auxiliary_denies_harm(text, intent):
    assert _intent(text) == intent


@pytest.mark.parametrize(
    "text, intent",
    [
        ("We both pulled up with a metre or so between us.", "near_miss"),
        ("The cyclist and I ended up 2 metres apart, both stopped.", "near_miss"),
        ("The bus stopped with a metre in it.", "near_miss"),
        # near misses: spacing of a formation, or a margin that is wide
        ("Two scooters ride 2 metres apart along the kerb; the ego overtakes them.", None),
        ("The buses stopped 20 metres apart.", None),
    ],
)
def test_a_small_distance_between_the_two_after_a_stop_is_a_near_miss(text, intent):
    assert _intent(text) == intent


@pytest.mark.parametrize(
    "text, intent",
    [
        ("The kid darts out from behind a parked car and I pull up in good time.", "safe"),
        ("A jogger steps off the kerb; the ego brakes and stops in plenty of time.", "safe"),
        ("The cyclist swerves into my lane but I stop in time with plenty of room.", "safe"),
        ("A pram rolls off the kerb and I stop in time with a comfortable margin.", "safe"),
        # near misses: in time and no more
        ("I only just stopped in time.", "near_miss"),
        ("A child ran out and I stopped in time.", "near_miss"),
    ],
)
def test_a_stop_in_good_time_or_with_a_wide_margin_is_safe(text, intent):
    assert _intent(text) == intent


@pytest.mark.parametrize(
    "text, intent",
    [
        ("At the zebra the ego gives priority to the scooter rider.", "safe"),
        ("I gave the cyclist priority and she crossed.", "safe"),
        ("The ego vehicle gives precedence to the tram.", "safe"),
        # near misses: priority denied, or something else given
        ("The van does not give priority and cuts across the ego.", None),
        ("The ego gives a wave to the cyclist.", None),
    ],
)
def test_giving_priority_is_giving_way(text, intent):
    assert _intent(text) == intent


@pytest.mark.parametrize(
    "text, intent",
    [
        ("A dog bolted across the lane in front of me, lucky I'd slowed down.", "near_miss"),
        ("Thankfully I was going slowly when the kid on the scooter shot out of the alley.", "near_miss"),
        ("Luckily the boy on the bike looked up just as I came round the corner.", "near_miss"),
        # near misses: luck with a wide pass, a lucky thing, or luck over a contact
        ("Luckily there was plenty of room and I passed the horse wide.", "safe"),
        ("A cyclist with a lucky charm on his bars crosses in front of the ego.", None),
        ("Fortunately the van clipped my mirror.", "collision"),
    ],
)
def test_relief_at_luck_is_a_close_call(text, intent):
    """ "so lucky I was only doing 20", "thankfully I'd slowed": relief says it was close."""
    assert _intent(text) == intent


@pytest.mark.parametrize(
    "text, intent",
    [
        ("The taxi and the moped came together at the lights.", "collision"),
        ("A tram and a cyclist came together on the crossing; rider down.", "collision"),
        ("They came together right at the mouth of the junction.", "collision"),
        # near misses: hedged or denied
        ("The van and the bus nearly came together at the exit.", "near_miss"),
        ("The van and the scooter did not come together, but it was close.", "near_miss"),
    ],
)
def test_two_road_users_coming_together_is_a_collision(text, intent):
    assert _intent(text) == intent


@pytest.mark.parametrize(
    "text, intent",
    [
        (
            "Notes of the crash investigation unit: a cyclist swerved out ahead of the ego, which braked. "
            "Near miss, no contact.",
            "near_miss",
        ),
        ("Accident response crew, 40 mph. A van pulled out in front of us; we braked and missed it.", "near_miss"),
        (
            "Collision statistics for the junction are poor. Today a moped cut in front of the ego, which "
            "swerved; no contact.",
            "near_miss",
        ),
    ],
    ids=["crash-investigation", "accident-response", "collision-statistics"],
)
def test_a_contact_noun_that_modifies_another_noun_states_no_contact(text, intent):
    assert stated_intent(" ".join(_tokens(text))) == intent


@pytest.mark.parametrize(
    "text",
    [
        "A crash yesterday on the A3: a car pulled out in front of me.",
        "The collision happened when a van pulled out in front of the ego.",
        "There was an accident, cyclist against car, as the cyclist crossed in front of the ego.",
    ],
    ids=["crash-yesterday", "collision-happened", "accident-comma"],
)
def test_a_contact_noun_said_as_the_event_is_a_collision(text):
    assert stated_intent(" ".join(_tokens(text))) == "collision"


@pytest.mark.parametrize(
    "text",
    [
        "A cyclist came out of a side road on my left and I hit the horn.",
        "The taxi stopped dead and the moped rider behind hit his horn.",
        "A dog ran across in front of the bus and the driver hit the brakes.",
        "Gran took me out for a lesson and a jogger stepped out ahead; I braked and stopped.",
        "My instructor took us out driving, and a van cut in front of us, so I braked.",
    ],
    ids=["hit-horn", "hit-his-horn", "hit-brakes", "took-out-for", "took-out-driving"],
)
def test_the_outcome_reader_alone_decides_contact(text):
    assert read(text).intent != "collision"


@pytest.mark.parametrize(
    "text, intent",
    [
        ("The delivery van started edging over and I leaned on the horn; it swerved back just in time.", "near_miss"),
        ("A bus pulled out and we got past in the nick of time.", "near_miss"),
        ("The test requires the ego to avoid the jogger narrowly.", "near_miss"),
        ("I missed the skateboarder only just.", "near_miss"),
        ("I was very nearly hit by a reversing taxi.", "near_miss"),
        ("Lorry drifted across, no hit.", "near_miss"),
        ("Courier bike hit rear door of the taxi.", "collision"),
        ("Van hit cyclist at the lights.", "collision"),
        ("A moped ran the red and the two collided.", "collision"),
        ("A moped ran the red and both collided.", "collision"),
        ("A lorry took the cyclist out at the lights.", "collision"),
    ],
)
def test_contact_said_tersely_or_hedged_after_its_verb(text, intent):
    assert _intent(text) == intent
    assert read(text).intent == intent


@pytest.mark.parametrize(
    "text, intent",
    [
        ("We got to the lights just in time to see a van cut in front of a cyclist, who braked gently.", None),
        ("A bus strike meant the roads were quiet, and a cyclist passed me wide.", "safe"),
        ("It was a hit, the music was loud, and a cyclist passed me wide.", "safe"),
    ],
)
def test_near_miss_negatives_of_terse_contact(text, intent):
    assert read(text).intent == intent


@pytest.mark.parametrize(
    "text, intent",
    [
        ("almost flattened a lad on a moped this morning", "near_miss"),
        ("We very nearly killed a pedestrian at the lights.", "near_miss"),
        ("The bus almost overtook a cyclist but stayed behind.", None),
        ("I almost followed the cyclist into the junction.", None),
    ],
)
def test_a_hedged_blow_to_a_road_user_is_a_near_miss(text, intent):
    assert read(text).intent == intent


@pytest.mark.parametrize(
    "text, intent",
    [
        ("A boy on a bike suddenly darted out between parked cars and I just stopped.", "near_miss"),
        ("Out of nowhere a moped shot out of a driveway; I braked.", "near_miss"),
        ("A woman walked slowly across ahead of me and I stopped.", "safe"),
        ("A boy on a bike suddenly darted out and I waited for him to cross.", "safe"),
    ],
    ids=["darted-stopped", "shot-out-braked", "slow-walk-stopped", "darted-waited"],
)
def test_a_plain_stop_after_a_sudden_act_is_a_near_miss(text, intent):
    assert read(text).intent == intent


@pytest.mark.parametrize(
    "text, intent",
    [
        ("I spotted the jogger just in time and braked.", None),
        ("The lorry drifted over and I got out of its way just in time.", "near_miss"),
    ],
)
def test_seen_just_in_time_is_no_escape(text, intent):
    assert _intent(text) == intent


@pytest.mark.parametrize(
    "text, intent",
    [
        ("A lad on a scooter shot out of a car park, I slammed the anchors on. He's fine.", "near_miss"),
        ("Some kid darted out from behind a van and I had to swerve. Nothing happened in the end.", "near_miss"),
        ("Out of nowhere a taxi cut across my bonnet, I braked hard, we're all fine.", "near_miss"),
        ("A cyclist rode along beside me for a mile. Nothing happened.", "safe"),
        ("The van just carried on alongside me the whole way, nothing happened, a dull trip.", "safe"),
        ("A woman crossed at the zebra, I waited for her, she's fine.", "safe"),
        ("A boy ran out, I braked, and he hit my wing. He's fine though.", "collision"),
    ],
    ids=[
        "shot-out-fine",
        "darted-nothing",
        "cut-across-fine",
        "along-nothing",
        "alongside-fine",
        "waited-fine",
        "hit-fine",
    ],
)
def test_fine_after_a_forced_escape_is_a_near_miss(text, intent):
    """That everyone was fine, or nothing happened, says how it ended: after a sudden act or the ego's
    hard braking or swerve it was a near miss avoided; with nothing forced, a safe pass."""
    assert read(text).intent == intent


# a contact verb whose object is the ego's own vehicle ("hit my car", read as the ego): a collision
@pytest.mark.parametrize(
    "text, intent",
    [
        ("A taxi went through on red and hit my car.", "collision"),
        ("Some idiot in a ute hit my car at the lights.", "collision"),
        ("A bakkie jumped the robot and struck our car broadside.", "collision"),
        ("Then the tipper truck hit my van from behind.", "collision"),
        ("An okada came from nowhere and hit my vehicle.", "collision"),
        ("The lorry nearly hit my car.", "near_miss"),
        ("The bus did not hit my car, it stopped in time.", "near_miss"),
        ("I hit the brakes and my car stopped short of the bike.", "near_miss"),
    ],
    ids=["taxi", "ute", "bakkie", "tipper", "okada", "nearly", "did-not", "hit-the-brakes"],
)
def test_a_contact_with_the_egos_vehicle_is_a_collision(text, intent):
    assert _intent(text) == intent


# "how close he came to going under", "came close to ending up under": what someone came near to did
# not happen, a near miss, however many words stand between the nearness and the contact
@pytest.mark.parametrize(
    "text, intent",
    [
        ("He has no idea how close he came to going under my wheels.", "near_miss"),
        ("The kid came close to ending up under the bus.", "near_miss"),
        ("She came so near to going into the side of the lorry.", "near_miss"),
        ("We got very close to crashing into the van.", "near_miss"),
        ("He came close to hitting the scooter.", "near_miss"),
        ("He went under the wheels of the lorry.", "collision"),
        ("The cyclist came close and then went into the side of the van.", "collision"),
    ],
    ids=["how-close-came", "came-close-ending-up", "came-near", "got-close", "plain", "went-under", "came-close-then"],
)
def test_a_contact_someone_came_close_to_is_a_near_miss(text, intent):
    assert _intent(text) == intent


# "no harm done", "no harm came of it" says how it ended: after a forced stop or swerve a near miss, alone
# a safe pass
@pytest.mark.parametrize(
    "text, intent",
    [
        ("A lad shot out on a scooter and I had to brake hard. No harm done.", "near_miss"),
        ("I had to swerve round the rider, but no harm done.", "near_miss"),
        ("The driver had to stop sharply for the kid. No harm came of it, thankfully.", "near_miss"),
        ("I slammed on the brakes; no harm done though.", "near_miss"),
        ("I waited for the pedestrian to cross. No harm done.", "safe"),
        ("The bus crept past the cyclist, no harm done.", "safe"),
    ],
    ids=["brake-hard", "swerve", "stop-sharply", "slammed", "waited", "crept"],
)
def test_no_harm_done_says_how_it_ended(text, intent):
    assert read(text).intent == intent


# an evasive act someone was made to do, whoever it is ("needed to swerve", "made me brake hard",
# "was forced to"), is a near miss; a plain stop or brake that was needed is not, and a need under a
# condition, a counterfactual or a future was never met
@pytest.mark.parametrize(
    "text, intent",
    [
        ("The bus pulled out and the cyclist needed to swerve.", "near_miss"),
        ("Lorry jammed its brakes, driver need to swerve to the next lane.", "near_miss"),
        ("The moped rider was forced to brake hard when the taxi turned.", "near_miss"),
        ("Some idiot pulled out of the side road and made me swerve.", "near_miss"),
        ("The van cut across, forcing me to brake sharply.", "near_miss"),
        ("The scooter came straight at us, the rider had to slam on the brakes.", "near_miss"),
        ("The pickup swung out and made the cyclist brake hard.", "near_miss"),
        ("The e-bike was obliged to veer onto the pavement.", "near_miss"),
    ],
    ids=["needed-to", "need-to", "forced-to", "made-me", "forcing-me-to", "had-to-slam", "made-the-cyclist", "obliged"],
)
def test_an_evasion_someone_was_made_to_do_is_a_near_miss(text, intent):
    assert _intent(text) == intent


@pytest.mark.parametrize(
    "text, intent",
    [
        ("The lights changed and the cyclist needed to brake.", None),
        ("The courier had to stop for the red light.", None),
        ("A rider might need to brake hard on this bend.", None),
        ("Where the lane narrows, riders may have to swerve round the potholes.", None),
        ("The noise of the lorry made me brake.", None),
        ("The van driver made a U-turn and braked hard.", None),
        ("The bus pulled out, forcing me to brake hard, and hit the cyclist.", "collision"),
    ],
    ids=["plain-brake", "plain-stop", "might-need", "may-have-to", "made-plain-brake", "made-a-turn", "contact"],
)
def test_a_need_that_was_no_evasion_is_not_a_near_miss(text, intent):
    assert _intent(text) == intent


# a margin said as the width of a car, a van, a lorry or a whole lane, or a wide gap, is a pass with room
@pytest.mark.parametrize(
    "text, intent",
    [
        ("Then the coach overtook the cyclist leaving a full car's width.", "safe"),
        ("Gave the lad on the bike a good car's width as I went by.", "safe"),
        ("The minibus went round her with a whole lane to herself, a lorry width to spare.", "safe"),
        ("The taxi driver gave the rider a whole lane.", "safe"),
        ("I overtook the jogger with a car width between us.", "safe"),
        ("Eventually went past him with a really wide gap.", "safe"),
        ("The van passed with a generous gap to the scooter.", "safe"),
    ],
    ids=[
        "leaving-car-width",
        "gave-car-width",
        "lorry-width-to-spare",
        "whole-lane",
        "car-width-between",
        "wide-gap",
        "generous-gap",
    ],  # fmt: skip
)
def test_a_margin_as_wide_as_a_vehicle_is_a_safe_pass(text, intent):
    assert _intent(text) == intent


@pytest.mark.parametrize(
    "text, intent",
    [
        ("The van passed me with less than a car's width.", None),
        ("He overtook leaving barely a car's width.", None),
        ("The lane width is 3.5 m and a cyclist rides along the kerb.", None),
        ("I pulled into a wide gap in the traffic.", None),
        ("The truck missed me by a bike's width.", "near_miss"),
    ],
    ids=["less-than", "barely", "lane-width-of-the-road", "gap-in-traffic", "bike-width"],
)
def test_a_width_cut_short_or_of_the_road_is_no_safe_margin(text, intent):
    assert _intent(text) == intent


# braking said with the brake as a verb's object ("hit the brakes", "applied the brake", "used his
# brakes") is the ego's brake; hard, an evasion; tapped or gentle, a give-way
@pytest.mark.parametrize(
    "text, intent",
    [
        ("The lorry swung out and I hit the brakes hard.", "near_miss"),
        ("I applied the brakes firmly when the jogger stepped out.", "near_miss"),
        ("I tapped the brakes to let the minibus in.", "safe"),
        ("I hit the brakes. Thankfully he was fine.", "near_miss"),
        ("I put the brakes on hard as the kid ran out.", "near_miss"),
        ("The van pushed the car with its brakes off.", None),
    ],
    ids=["hit-hard", "applied-firmly", "tapped", "hit-fine", "put-on-hard", "brakes-off"],
)
def test_braking_said_with_the_brake_as_object(text, intent):
    assert _intent(text) == intent


# the ego's brake beside a road user read cutting in or pulling out into its way was forced on it
@pytest.mark.parametrize(
    "text, intent",
    [
        ("A hatchback cut in right in front of me on the motorway and I hit the brakes.", "near_miss"),
        ("A delivery van pulled out of a side street into my path, so I braked.", "near_miss"),
        ("The SUV moved into my lane without looking. I applied the brake.", "near_miss"),
        ("A car merged into my lane and I braked gently to let it in.", "safe"),
        ("A car pulled out of the junction ahead and I stopped to let it go.", "safe"),
        ("A van cut in ahead of me and I braked, then he hit the cyclist.", "collision"),
        ("I braked for the red light.", "safe"),
    ],
    ids=[
        "cut-in-hit-brakes",
        "pulled-out-braked",
        "into-my-lane",
        "gently-let-in",
        "stopped-let-go",
        "contact",
        "red-light",
    ],  # fmt: skip
)
def test_a_brake_beside_a_road_user_cutting_in_is_forced(text, intent):
    assert read(text).intent == intent


# a contact noun whose verb of happening is denied after it: it did not happen (the ego's act decides
# how close it came); near-miss negatives: a denied verb that says what the contact did, and one that
# happened
NEVER_OCCURRED = [
    ("I had to brake hard. A collision did not take place, but my son was crying.", "near_miss"),
    ("The truck swerved into my lane, I braked, the crash didn't happen thankfully.", "near_miss"),
    ("Had to swerve; contact never occurred.", "near_miss"),
    ("I slammed on, and a collision has not occurred.", "near_miss"),
    ("The scooter ran the light and I stood on the brakes; the impact never came.", "near_miss"),
    ("The collision did not stop him, he rode on.", "collision"),
    ("The crash happened at the lights.", "collision"),
    ("A collision took place at the junction.", "collision"),
]


@pytest.mark.parametrize(("text", "intent"), NEVER_OCCURRED)
def test_a_contact_that_never_occurred(text: str, intent: str) -> None:
    assert _intent(text) == intent


# a passive of a denying verb said of trouble, or of a pronoun after the ego's escape: what was coming
# did not happen; near-miss negatives: a route avoided, and no escape said before the pronoun
AVERTED = [
    ("A moped came past the bus. I stepped on the brake and it was avoided.", "near_miss"),
    ("Lorry pulled out, I braked and thankfully it was avoided.", "near_miss"),
    ("The rider swerved in front; disaster was averted by my quick braking.", "near_miss"),
    ("A child ran out, I braked and tragedy was avoided.", "near_miss"),
    ("I slowed down and the danger was avoided.", "near_miss"),
    ("The motorway was closed so it was avoided.", None),
    ("A cyclist was ahead of me; it was avoided.", None),
]


@pytest.mark.parametrize(("text", "intent"), AVERTED)
def test_trouble_averted(text: str, intent: str | None) -> None:
    assert _intent(text) == intent


# a motion or a blow ending "against" a part of a road user, or a blow said where it landed ("hit on
# my door"), is a collision: a British text, a police report translated from Spanish, a Nigerian and
# an Australian voice note, a claim form; near-miss negatives: against a flow or a light, a part at
# rest ("leaned against"), and "onto the back of" (catching a slower vehicle up)
PART_MET = [
    ("The moped skidded and slid against my rear door.", "collision"),
    ("His handlebar scraped against the side of our car as he squeezed by.", "collision"),
    ("Vehicle B impacted with its front against the right rear of vehicle A.", "collision"),
    ("The okada just slammed against my bumper at the junction.", "collision"),
    ("We came up onto the back of a slow tractor.", None),
    ("A scooter came out of the side street and hit on my left front door.", "collision"),
    ("The bike's wheel banged against the tailgate of the ute.", "collision"),
    ("The cyclist rode against the traffic.", None),
    ("The rider went against the red light.", None),
    ("I pulled onto the back of the queue.", None),
    ("The kid hopped onto the back of his mate's bike.", None),
    ("The van pulled onto the side of the road.", None),
    ("A courier leaned against my door at the lights.", None),
    ("Rain beat against the windscreen all the way home.", None),
]


@pytest.mark.parametrize(("text", "intent"), PART_MET)
def test_a_part_met_against(text: str, intent: str | None) -> None:
    assert _intent(text) == intent


# a compound verb of a collision written as one word, as texts and voice-to-text write it, is a
# collision; near-miss negatives: the noun ("a tbone steak") and "the rear end" of a place
CLOSED_COMPOUND = [
    ("Mate got tboned by a ute at the lights, both ok.", "collision"),
    ("Some guy rearended me at the roundabout lol", "collision"),
    ("The cab was rearending the bus when the lights changed.", "collision"),
    ("A lorry rearends the stopped car in the test.", "collision"),
    ("A van came across the junction. Tboned. Nobody hurt thankfully.", "collision"),
    ("The tbone steak was great, then a cyclist passed us.", None),
    ("We parked at the rear end of the car park and a cyclist went by.", None),
]


@pytest.mark.parametrize(("text", "intent"), CLOSED_COMPOUND)
def test_a_compound_verb_of_collision_written_closed(text: str, intent: str | None) -> None:
    assert _intent(text) == intent


# a warning of what will happen to anyone, in the spoken forms of "going to", is no contact that
# happened; "speed bumps" and "road bumps" are the road's traffic calming, not a knock
FORETOLD = [
    ("A bus pulled out on me and I braked hard. Someone's gonna get hurt here.", "near_miss"),
    ("A cyclist swerved out and I swerved. Somebody gunna get hit at this junction.", "near_miss"),
    ("Bike came through the red, I stamped on the brake. Someone finna get killed here.", "near_miss"),
    ("A lorry cut me up and I had to slam on. Someone is bound to get hit here.", "near_miss"),
    ("A van nearly hit a boy on the crossing. The council should put in speed bumps.", "near_miss"),
    ("The lorry narrowly missed her; residents want road bumps on the hill.", "near_miss"),
    ("A scooter swerved out and I braked hard. The cyclist gonna sue him, he hit her.", "collision"),
    ("The car behind bumps us at the lights.", "collision"),
]


@pytest.mark.parametrize(("text", "intent"), FORETOLD)
def test_a_warning_or_traffic_calming_is_no_contact(text: str, intent: str | None) -> None:
    assert _intent(text) == intent
