"""The everyday constructions people state an outcome in (:mod:`vei_scenario.language.outcome`):
how close it came ("came within a foot of my door"), what it could have been ("could have been
nasty"), how close the ego was to a contact ("inches from hitting him"), the ego's forced escape said
as a noun ("had to take evasive action", "did an emergency stop"), an escape not needed ("didn't even
have to brake"), and contact said with a phrasal verb ("ran him over"). Each group is written in
several people's wording (none taken from a corpus), with near misses of the wording that must not
be read so."""

from __future__ import annotations

import pytest

from vei_scenario.language.outcome import stated_intent
from vei_scenario.language.reader import _tokens, read
from vei_scenario.language.reading import NotUnderstood


def _intent(text: str) -> str | None:
    return stated_intent(" ".join(_tokens(text)))


#: a margin said as how near one came to the other ("within a foot of my door"): a near miss
WITHIN = [
    "A van nosed out of a side road and came within a foot of my door.",
    "The cyclist swerved out and came within a whisker of my bonnet.",
    "That bus came within a metre of the kid on the bike.",
    "Car came within 50cm of rider, did not stop.",
    "The lorry's trailer came within inches of her handlebars.",
    "He got to within a couple of feet of us before he stopped.",
    "The moped passed within a hair's breadth of my mirror.",
]
#: a distance that is not a margin between the two: nothing about the outcome
WITHIN_NOT = [
    "The scooter stayed within 2 m of the kerb the whole way.",
    "Keep the ego within a metre of the lane centre while the van passes.",
    "The van was within 30 m of the junction when the lights changed.",
]


@pytest.mark.parametrize("text", WITHIN)
def test_came_within_a_margin_is_a_near_miss(text):
    assert _intent(text) == "near_miss"


@pytest.mark.parametrize("text", WITHIN_NOT)
def test_within_a_distance_of_a_place_is_no_outcome(text):
    assert _intent(text) is None


#: what it could have been, said of the event: a near miss
COULD_HAVE_BEEN = [
    "A van shot out of a side road, could have been nasty.",
    "A scooter darted across in front of me. Could have been a lot worse.",
    "A bus pulled out on me. That could have ended badly.",
    "A kid ran out between parked cars, it could've been really bad.",
    "A lorry drifted into my lane - would have been a disaster at that speed.",
    "The tipper cut across the cyclist; she could have been killed.",
    "The rider ran the red in front of us, someone might have been seriously hurt.",
    "Had the taxi been any quicker it would have been a different story.",
]
#: what should have been done, or a judgement that is no harm: nothing about the outcome
COULD_HAVE_BEEN_NOT = [
    "A van pulled out of the side road, it should have waited.",
    "The cyclist rode ahead of me; it would have been better to stay behind.",
    "The bus was late, it could have been the traffic.",
    "Before someone gets killed, the council must fix the junction where the vans pull out.",
]


@pytest.mark.parametrize("text", COULD_HAVE_BEEN)
def test_what_it_could_have_been_is_a_near_miss(text):
    assert _intent(text) == "near_miss"


@pytest.mark.parametrize("text", COULD_HAVE_BEEN_NOT)
def test_other_modal_perfects_say_no_outcome(text):
    assert _intent(text) is None


#: how near the ego came to a contact, said before it: the contact was not made
NEAR_TO_CONTACT = [
    "A kid on a bike darted out, I was millimetres from hitting him.",
    "A jogger stepped out, I was inches away from hitting her.",
    "I came so close to hitting the cyclist.",
    "We were seconds from a collision with the tram.",
    "The van was that close to taking the rider out.",
    "I was a split second from ploughing into the back of the scooter.",
    "Came this close to running him over.",
]


@pytest.mark.parametrize("text", NEAR_TO_CONTACT)
def test_how_near_to_a_contact_is_a_near_miss(text):
    assert _intent(text) == "near_miss"


@pytest.mark.parametrize(
    "text, intent",
    [
        ("The van pulled in close to the kerb and hit the cyclist.", "collision"),
        ("A metre from the stop line, the bus hit the moped.", "collision"),
        ("I stopped close to the junction and a car hit me from behind.", "collision"),
        ("The clip of the cyclist ends at the moment of impact with the bus.", "collision"),
    ],
)
def test_closeness_to_a_place_leaves_a_contact(text, intent):
    assert _intent(text) == intent


#: the ego's escape said as a noun phrase: a near miss
ESCAPE_NOUNS = [
    "A taxi pulled out and I had to take evasive action.",
    "A cyclist swung out, so I had to take avoiding action.",
    "A van pulled out in front of me and I had to do an emergency stop.",
    "Scooter came off the pavement, had to emergency brake.",
    "A kid ran out and I locked up.",
    "A car shot out of a driveway and I locked the wheels.",
    "A car pulled out and I had to anchor up.",
    "A jogger stepped off the kerb and I had to jam the brakes on.",
    "A cyclist veered out and I had to brake like mad.",
    # a narrator's sentence that is the noun phrase alone: no verb, so no one else's act
    "I was doing 30 when a pedestrian stepped out from behind a parked van. Emergency stop.",
    "Came round the corner at 20 and a kid on a scooter was in the road. Emergency braking, nobody hurt.",
    "I was on 40 when the cyclist swung out round a pothole. Emergency stop, coffee everywhere.",
]


@pytest.mark.parametrize("text", ESCAPE_NOUNS)
def test_an_escape_said_as_a_noun_is_a_near_miss(text):
    assert _intent(text) == "near_miss"


#: an escape the ego did not need: nothing was forced, a safe pass
UNFORCED = [
    "The lorry overtook me, didn't even have to brake.",
    "The cyclist moved over and I didn't need to brake.",
    "The bus pulled out well ahead, I never had to slow down.",
    "The van came past with no need to brake or swerve.",
    "We got past the horse riders without having to brake.",
    "Nobody had to swerve or brake; the scooter just rode on.",
]
#: an escape denied outright, or a need that was there: not a safe pass
UNFORCED_NOT = [
    ("A kid ran out; I didn't brake, I swerved.", "near_miss"),
    ("A van pulled out and I had to brake hard.", "near_miss"),
    ("I did not need to brake hard but still clipped his mirror.", "collision"),
    ("A van drifted over, no signal nothing had to brake hard.", "near_miss"),
]


@pytest.mark.parametrize("text", UNFORCED)
def test_an_escape_not_needed_is_a_safe_pass(text):
    assert _intent(text) == "safe"


@pytest.mark.parametrize("text, intent", UNFORCED_NOT)
def test_a_denied_escape_is_not_unforced(text, intent):
    assert _intent(text) == intent


#: contact said by a phrasal verb with its object between, or an escape that failed: a collision
PHRASAL_CONTACT = [
    "A cyclist came up the inside and I ran him over.",
    "The dog ran out and the car ran it down.",
    "A car pulled out, I couldn't avoid him.",
    "The moped swerved and the van was unable to avoid her.",
    "A car whacked my rear bumper at the lights.",
    "The taxi nudged the back wheel of my bike.",
    "Some idiot dinged my door pulling out.",
    "A van totalled my bike on the roundabout.",
]
#: the same verbs with something else: not a contact
PHRASAL_NOT = [
    ("I ran the route over in my head before the van pulled out.", None),
    ("A kid ran down the hill towards the cyclist.", None),
    ("A van pulled out; I avoided him easily.", None),
    ("The bill for the van's repairs totalled 900 pounds.", None),
]


@pytest.mark.parametrize("text", PHRASAL_CONTACT)
def test_phrasal_and_failed_escapes_are_contact(text):
    assert _intent(text) == "collision"


@pytest.mark.parametrize("text, intent", PHRASAL_NOT)
def test_phrasal_verbs_without_a_road_user_are_no_contact(text, intent):
    assert _intent(text) != "collision"


#: idioms of a close call: a near miss
CLOSE_IDIOMS = [
    "A van cut in front of me. Way too close for comfort.",
    "The motorbike undertook and cut in, touch and go for a second.",
    "The scooter came past me closer than I'd like.",
]


@pytest.mark.parametrize("text", CLOSE_IDIOMS)
def test_idioms_of_a_close_call(text):
    assert _intent(text) == "near_miss"


@pytest.mark.parametrize(
    "text",
    ["A van overtook me, all good, no near misses.", "Three passes by the bus, no near-misses at all."],
)
def test_near_misses_denied_are_a_safe_pass(text):
    assert _intent(text) == "safe"


@pytest.mark.parametrize(
    "text",
    [
        "The van waited behind the cyclist and passed when it was clear.",
        "I held back and went round the horse after the road was clear.",
    ],
)
def test_going_once_the_road_was_clear_is_a_safe_pass(text):
    assert _intent(text) == "safe"


#: a contact someone believed or expected would happen at the time: it did not, a near miss
BELIEVED = [
    "A kid ran out and I thought I was going to hit him.",
    "A van pulled out and I was sure I'd hit it.",
    "The cyclist swerved in front of me, I honestly thought I'd hit her.",
    "I fully expected to hit the scooter but he swerved.",
    "We braced for impact but the bus stopped.",
    "I was convinced the lorry would hit me.",
]
#: a spec's expected outcome, a belief of now about what happened, or a contact said after the belief
BELIEVED_NOT = [
    ("Expected outcome collision with the e-scooter.", "collision"),
    ("Expected: collision.", "collision"),
    ("I think I hit his mirror as I went past.", "collision"),
    ("I thought I'd missed him but then I hit his back wheel.", "collision"),
]


@pytest.mark.parametrize("text", BELIEVED)
def test_a_contact_believed_at_the_time_is_a_near_miss(text):
    assert _intent(text) == "near_miss"


@pytest.mark.parametrize("text, intent", BELIEVED_NOT)
def test_an_expected_outcome_or_a_later_contact_stays(text, intent):
    assert _intent(text) == intent


#: idioms of a fright the narrator was given: how close it came, a near miss
FRIGHT = [
    "A van pulled out, heart in my mouth.",
    "A bus pulled out on me, nearly had a heart attack.",
    "The lorry came over into my lane, scared the life out of me.",
    "A scooter shot out of the alley and frightened the hell out of us.",
    "A taxi pulled out on me, my life flashed before my eyes.",
    "Kid on a bike came out of nowhere, proper brown trouser moment.",
    "A motorbike flew past my mirror. I was terrified.",
]
#: a fright given to someone else, or said of how someone looked: nothing about the outcome
FRIGHT_NOT = [
    "The van's horn scared the cyclist ahead of me.",
    "The cyclist looked scared of the traffic on the bypass.",
]


@pytest.mark.parametrize("text", FRIGHT)
def test_a_fright_given_to_the_narrator_is_a_near_miss(text):
    assert _intent(text) == "near_miss"


@pytest.mark.parametrize("text", FRIGHT_NOT)
def test_a_fright_given_to_others_is_no_outcome(text):
    assert _intent(text) is None


@pytest.mark.parametrize(
    "text, intent",
    [
        ("I went round the cyclist, no bother.", "safe"),
        ("The overtake of the tractor was done without any fuss.", "safe"),
        ("Passed the horse riders, no hassle at all.", "safe"),
        ("The van didn't bother to indicate and pulled out.", None),
        ("The cyclist didn't bother looking before he crossed.", None),
    ],
)
def test_a_fuss_denied_is_a_safe_pass(text, intent):
    assert _intent(text) == intent


@pytest.mark.parametrize(
    "text, intent",
    [
        ("Nearly ran over a lad on a bike!! Still shaking", "near_miss"),
        ("The lorry ran over a fox on the bypass.", "collision"),
        ("A kid ran down the slope towards the cyclist.", None),
        ("The scooter ran over the kerb and onto the road.", None),
    ],
)
def test_running_over_someone_not_somewhere(text, intent):
    assert _intent(text) == intent


#: contact said in other Englishes and trades: a collision
WORLD_CONTACT = [
    "An auto dashed my car from behind at the signal.",
    "An okada jammed my car at the junction.",
    "The danfo jammed the okada man at the bus stop.",
    "A bus banged my car at the junction.",
    "It was only a fender bender with the taxi.",
    "We had a minor shunt with the van at the lights.",
    "The taxi and I had a coming-together at the roundabout.",
    "It was only a light bump on the cyclist's back wheel.",
]
#: the same verbs with a place, a pedal or a horn: no contact
WORLD_CONTACT_NOT = [
    ("A kid dashed across the road in front of me.", None),
    ("I jammed the brakes on as a van pulled out.", "near_miss"),
    ("A bus banged its horn at the cyclist.", None),
    ("The boy dashed out between the parked cars.", None),
]


@pytest.mark.parametrize("text", WORLD_CONTACT)
def test_contact_in_other_englishes(text):
    assert _intent(text) == "collision"


@pytest.mark.parametrize("text, intent", WORLD_CONTACT_NOT)
def test_those_verbs_without_a_road_user_are_no_contact(text, intent):
    assert _intent(text) == intent


@pytest.mark.parametrize(
    "text, intent",
    [
        ("A jogger steps out from the right, the ego cannot stop in time.", "collision"),
        ("A child runs out; the ego cannot avoid her.", "collision"),
        ("A jogger steps out; the ego should brake and stop with at least 2 m margin.", "safe"),
    ],
)
def test_cannot_denies_and_a_margin_at_least_said(text, intent):
    assert _intent(text) == intent


@pytest.mark.parametrize(
    "text, intent",
    [
        ("A cyclist was coming up my inside. Didn't see him at all until my instructor shouted.", "near_miss"),
        ("I never noticed the scooter till it was right beside my door.", "near_miss"),
        ("We did not spot the jogger until the last moment and stopped.", "near_miss"),
        ("I didn't see any cyclists on the way home.", None),
        ("A van pulled out; I waited until it had gone.", "safe"),
    ],
)
def test_seen_too_late(text, intent):
    assert _intent(text) == intent


def test_seen_late_then_passed_wide_is_a_safe_pass():
    text = "I didn't see the cyclist until he was 10 m ahead, then gave him a wide berth, no problem."
    assert _intent(text) == "safe"


@pytest.mark.parametrize(
    "text, intent",
    [
        ("A lorry swung across both lanes, it was nearly a disaster.", "near_miss"),
        ("The bus jumped the red: almost a tragedy at the crossing.", "near_miss"),
        ("The council calls the junction a disaster waiting to happen.", None),
    ],
)
def test_a_disaster_nearly_had(text, intent):
    assert _intent(text) == intent


#: a person who springs clear on foot, out of the way or back when forced to: a near miss
ESCAPED_ON_FOOT = [
    "I went through the crossing on amber and a man stepping off the kerb had to step back.",
    "The bus pulled out of the stop and an old woman had to jump back onto the pavement.",
    "A taxi turned into the side road and the jogger crossing it jumped out of the way.",
    "The van reversed out of the drive; the postman had to leap clear.",
    "Our car rolled forward at the zebra and the lady with the pram had to get out of its way.",
    "Car turned left across the crossing, ped dived out of the way.",
]
#: a step by choice, an escape denied or under a condition, or a contact after it: not read so
ESCAPED_ON_FOOT_NOT = [
    ("The pedestrian stepped back to let me through.", "safe"),
    ("A man stepped out. He didn't have to jump out of the way, I had stopped well back.", "safe"),
    ("A boy ran out and I hit him. He had tried to jump out of the way.", "collision"),
    ("If the van had kept going she would have had to jump out of the way.", None),
    ("A cyclist stopped at the lights and stepped back onto the pavement.", None),
]


#: no one who had to spring clear ("Nobody had to ...", "No-one had to ..."), or a vehicle making way:
#: no near miss, read as the whole text is read
NO_ONE_ESCAPED = [
    "I drove through the crossing at 20 km/h. Nobody had to jump out of the way, it was a quiet street.",
    "No-one had to step back when the van reversed out of the drive.",
    "The lorry had to get out of the way of the ambulance and pulled onto the hard shoulder.",
    "Cars had to get out of the way of the fire engine at the junction.",
]


@pytest.mark.parametrize("text", NO_ONE_ESCAPED)
def test_no_one_springing_clear_is_no_near_miss(text):
    assert read(text).intent != "near_miss"


@pytest.mark.parametrize("text", ESCAPED_ON_FOOT)
def test_a_person_springing_clear_is_a_near_miss(text):
    assert _intent(text) == "near_miss"


@pytest.mark.parametrize("text, intent", ESCAPED_ON_FOOT_NOT)
def test_a_step_by_choice_or_denied_is_no_escape(text, intent):
    assert _intent(text) == intent


#: a learner at the ego's wheel ("the candidate", "Applicant") who brakes hard or swerves after someone
#: came into the way: the ego's escape, a near miss
LEARNER_ESCAPES = [
    "A rider rode across from the left against the red. The candidate braked hard.",
    "E-scooter came off the kerb on the right. Applicant detected late, braked firmly and stopped.",
    "Cyclist pulled out of the side road; pupil swerved and stopped.",
]
#: a learner brought in as someone new is no one at the ego's wheel
LEARNER_ESCAPES_NOT = [
    "A pupil ran out from the school gate and stopped at the kerb.",
]


@pytest.mark.parametrize("text", LEARNER_ESCAPES)
def test_a_learner_drivers_escape_is_a_near_miss(text):
    assert read(text).intent == "near_miss"


@pytest.mark.parametrize("text", LEARNER_ESCAPES_NOT)
def test_a_learner_brought_in_as_new_is_no_ego(text):
    assert read(text).intent is None


#: a brake or stop the ego had to make for someone who came into its way: its escape, a near miss
FORCED_FOR_ONE_IN_THE_WAY = [
    "Turning right, a pedestrian was crossing the side road and I had to brake.",
    "Two kids stepped out between parked cars ahead of us and we had to stop.",
    "A lad on a scooter came down our side the wrong way and Dad had to brake.",
]
#: one it had to make in a queue, to let someone go, or with no one coming into its way: as before
FORCED_NOT_FOR_ONE_IN_THE_WAY = [
    ("A cyclist pulled out and I had to stop to let him go.", "safe"),
    ("The car ahead braked and I had to brake too.", None),
]


@pytest.mark.parametrize("text", FORCED_FOR_ONE_IN_THE_WAY)
def test_a_forced_brake_for_one_in_the_way_is_a_near_miss(text):
    assert read(text).intent == "near_miss"


@pytest.mark.parametrize("text, intent", FORCED_NOT_FOR_ONE_IN_THE_WAY)
def test_a_forced_brake_for_no_one_in_the_way_is_as_before(text, intent):
    assert read(text).intent == intent


#: a text whose only "someone" is nobody ("Nobody ...", "At no point did anyone ...") names no road user
#: at all, and is refused as such, not read with someone on foot who sprang clear
NO_ROAD_USER_AT_ALL = [
    "Nobody had to step back, the crossing was clear.",
    "At no point did anyone have to jump out of the way, the street was empty.",
]


@pytest.mark.parametrize("text", NO_ROAD_USER_AT_ALL)
def test_nobody_is_no_road_user(text):
    with pytest.raises(NotUnderstood, match="no road user"):
        read(text)
