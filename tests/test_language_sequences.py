"""What a road user does, said as a chain of verbs (:mod:`vei_scenario.language.motion`): two
behaviours in one clause chain stay two, in order; one behaviour said in two verbs stays one.
Wordings written for each construction, none taken from a corpus."""

from __future__ import annotations

import pytest

from vei_scenario.language.reader import read


def _behaviours(text: str) -> list[str]:
    (actor,) = read(text).actors
    return [b[0] for b in actor.behaviours]


@pytest.mark.parametrize(
    "text",
    [
        "Ego at 90 km/h, dual carriageway. The lorry ahead goes over to the next lane and then speeds up to 100 km/h.",
        "A van in front of us heads into the adjacent lane and accelerates hard.",
        "Ego 70 km/h, two lanes. The coach ahead of me moves to another lane, then it speeds up.",
    ],
)
def test_a_plain_move_into_another_lane_is_a_lane_change_then_what_follows(text):
    assert _behaviours(text) == ["change_lane", "change_speed"]


@pytest.mark.parametrize(
    "text",
    [
        "I was in lane 2 at 50 mph. A pickup moved from lane 3 into lane 2 just ahead of me and then braked hard.",
        "The ego is in lane 1 at 80 km/h; a taxi goes from lane 2 into lane 1 right in front of the ego and stops.",
        "Ego at 60 km/h. A hatchback came over into my lane in front of me and slammed on its brakes.",
    ],
)
def test_a_move_into_the_ego_lane_then_a_brake_is_a_cut_in_then_the_brake(text):
    names = _behaviours(text)
    assert names[0] == "cut_in" and names[-1] in ("sudden_stop", "stop") and len(names) == 2


@pytest.mark.parametrize(
    "text",
    [
        "Ego at 40 km/h behind a bin lorry; the lorry slows down and stops at the kerb.",
        "The taxi in front of me eases off and pulls up at the taxi rank. Ego 30 km/h.",
        "A delivery van ahead decelerates and comes to a halt outside the shop; ego 25 mph.",
    ],
)
def test_slowing_into_a_stop_is_the_stop(text):
    assert _behaviours(text) == ["stop"]


@pytest.mark.parametrize(
    "text",
    [
        "Was driving at 30 mph past the shops when a lad ran out from the kerb on the left. Braked and he "
        "made it over with room to spare.",
        "Came along the high street at 20 mph; a woman stepped out from the right. Slowed right down and she got "
        "to the other side fine.",
        "Was doing 40 km/h through the village when an old chap walked out from the left. Eased off and he got "
        "over safely.",
    ],
)
def test_a_diary_without_its_i_keeps_the_narrator_reaction_and_one_crossing(text):
    assert _behaviours(text) == ["cross_in_front"]


@pytest.mark.parametrize(
    "text",
    [
        "Ego turning right out of a side road at 10 mph. A van coming from the left slows, stops and flashes "
        "then waves me across.",
        "I wait to pull out of the junction; a lorry from the right eases to a halt and beckons me out.",
        "Ego at 20 km/h turns left at the crossroads; a cyclist on the right arm stops and allows the ego to "
        "finish its turn.",
        "Ego 30 km/h on the main road. From the side street on the left a moped pulls up short of the line, "
        "letting the ego go by.",
    ],
)
def test_a_road_user_letting_the_ego_go_gives_way(text):
    assert _behaviours(text) == ["give_way"]


@pytest.mark.parametrize(
    "text",
    [
        "Ego at 40 km/h. An e-scooter rider swerves out across the road ahead. Let the ego's braking decide.",
        "Test car does 30 mph; a kid on a scooter cuts across in front of it. We let the car's AEB handle it.",
        "I was doing 25 mph when a cyclist crossed in front of me. Let my brakes do the work, I thought.",
    ],
)
def test_letting_the_egos_own_system_act_is_no_giving_way(text):
    """ "Let the ego's braking decide" lets the ego's system act, not the ego go: the road user that
    crosses gives no way."""
    assert "give_way" not in _behaviours(text)


#: Euro NCAP codes by their grammar: what each configuration is, whatever target it names.
_CODES = [
    ("CCRs", "car", "ahead", ["stop"], None),
    ("CCRm", "car", "ahead", ["keep_going"], None),
    ("CCRb", "car", "ahead", ["sudden_stop"], None),
    ("CMRs", "car", "ahead", ["stop"], None),
    ("CMRb", "car", "ahead", ["sudden_stop"], None),
    ("CCFtap", "car", "junction_opposite", ["keep_going"], "left"),
    ("CMFtap", "car", "junction_opposite", ["keep_going"], "left"),
    ("CCCscp", "car", None, ["run_red_light"], None),
    ("CMCscp", "car", None, ["run_red_light"], None),
    ("CCFhos", "car", "oncoming", ["wrong_way"], None),
    ("CCFhol", "car", "oncoming", ["wrong_way"], None),
    ("CPNA-25", "pedestrian", "roadside_right", ["cross_in_front"], None),
    ("CPNCO-50", "pedestrian", "roadside_right", ["cross_in_front"], None),
    ("CPFA-50", "pedestrian", "roadside_left", ["cross_in_front"], None),
    ("CPLA-25", "pedestrian", "ahead", ["along_road"], None),
    ("CBNAO", "bicycle", "roadside_right", ["cross_in_front"], None),
    ("CBFA-50", "bicycle", "roadside_left", ["cross_in_front"], None),
    ("CBLA-50", "bicycle", "ahead", ["along_road"], None),
    ("CSFA", "e-scooter", "roadside_left", ["cross_in_front"], None),
    ("CSNA", "e-scooter", "roadside_right", ["cross_in_front"], None),
    ("CSLA", "e-scooter", "ahead", ["along_road"], None),
    ("CPTAfs-50", "pedestrian", "roadside_left", ["cross_in_front"], "left"),
    ("CPTAfo", "pedestrian", "roadside_right", ["cross_in_front"], "left"),
    ("CPTAns-50", "pedestrian", "roadside_right", ["cross_in_front"], "right"),
    ("CPTAno", "pedestrian", "roadside_left", ["cross_in_front"], "right"),
    ("CBTAns", "bicycle", "roadside_right", ["cross_in_front"], "right"),
    ("CBTAfo", "bicycle", "roadside_right", ["cross_in_front"], "left"),
]


@pytest.mark.parametrize("form", ["{code} VUT 40 km/h, target 10 km/h", "{code}: VUT 40 km/h, target 10 km/h, dry"])
@pytest.mark.parametrize(("code", "kind", "relation", "names", "route"), _CODES)
def test_a_euro_ncap_code_reads_by_its_grammar(form, code, kind, relation, names, route):
    r = read(form.format(code=code))
    (actor,) = r.actors
    assert (actor.kind, [b[0] for b in actor.behaviours]) == (kind, names)
    assert relation is None or actor.relation == relation
    assert r.ego_route == route and round(r.ego_speed_mps * 3.6) == 40


@pytest.mark.parametrize(
    ("text", "kind", "relation"),
    [
        ("CPFA: VUT 30 km/h, pedestrian target 8 km/h", "pedestrian", "roadside_left"),
        ("CBNA (bike from the right): VUT 20 km/h, cyclist target 15 km/h, night", "bicycle", "roadside_right"),
        ("CPFA-75 (a child this time): VUT 25 km/h, EPTc 5 km/h", "pedestrian", "roadside_left"),
    ],
)
def test_a_code_labelling_a_list_of_speeds_still_says_its_configuration(text, kind, relation):
    (actor,) = read(text).actors
    assert (actor.kind, actor.relation, [b[0] for b in actor.behaviours]) == (kind, relation, ["cross_in_front"])


@pytest.mark.parametrize(
    "text",
    [
        "An oncoming van drifted across the centre line and hit us head-on. Heavy snow kept falling all evening.",
        "A car coming the other way crossed the center line and struck the ego head on. Rain had started falling.",
        "Ego on a bend at 50 km/h; an oncoming pickup drifted over the centre line and hit us head-on while hail "
        "was falling.",
    ],
)
def test_what_the_weather_does_is_no_behaviour_of_a_road_user(text):
    assert _behaviours(text) == ["wrong_way"]


@pytest.mark.parametrize(
    "text",
    [
        "Ego at 40 km/h in the right lane; a cab in the lane to my left cuts across my lane to make a right.",
        "I'm going straight at 25 mph when the SUV beside me on the right swerves across in front of me to hang a "
        "left.",
        "A box truck in the left lane swung over across my lane to take a right at the lights. Ego 30 mph.",
    ],
)
def test_a_move_across_the_ego_lane_to_make_a_turn_is_the_turn(text):
    assert _behaviours(text) == ["forced_turn"]


@pytest.mark.parametrize(
    ("text", "route"),
    [
        ("I make a left at the lights at 20 km/h; a cyclist rides straight on beside me.", "left"),
        ("The ego takes a right at the crossroads at 15 mph while a pedestrian waits at the kerb.", "right"),
        ("Ego hangs a left at the junction at 20 km/h; an oncoming van goes straight.", "left"),
    ],
)
def test_making_a_left_or_a_right_is_turning_that_way(text, route):
    assert read(text).ego_route == route


@pytest.mark.parametrize(
    "text",
    [
        "I was following a bus along the high road at 30 mph. The bus pulled out to get round a lorry parked in "
        "the lane and I had to brake hard for the lorry.",
        "Ego follows a taxi at 40 km/h. The taxi swerves out to pass a van parked in our lane, revealing it late.",
        "Ego behind a pickup at 50 km/h; the pickup moves out to overtake a car parked in the road ahead.",
    ],
)
def test_the_vehicle_ahead_moving_out_round_one_standing_in_the_lane_is_a_cut_out(text):
    r = read(text)
    names = {a.kind: [b[0] for b in a.behaviours] for a in r.actors}
    movers = [a for a in r.actors if a.speed_mps != 0.0]
    (mover,) = movers
    assert [b[0] for b in mover.behaviours] == ["cut_out"] and mover.relation == "ahead", names
    (standing,) = [a for a in r.actors if a is not mover]
    assert standing.relation == "ahead"


@pytest.mark.parametrize(
    "text",
    [
        "car in front of me change suddenly to other lane because there is stopped truck on road, i crash in it. "
        "speed 60 kmh",
        "the van ahead of me go quickly to other lane because there was broken lorry in lane, i hit the lorry. "
        "me 50 km/h",
        "Ego 80 km/h. Car in front swerves to the next lane since there is a broken-down bus in the lane.",
    ],
)
def test_moving_out_because_something_stands_there_is_a_cut_out(text):
    r = read(text)
    kinds = [(a.kind, [b[0] for b in a.behaviours]) for a in r.actors]
    assert len(r.actors) == 2, kinds
    assert [b[0] for b in r.actors[0].behaviours] == ["cut_out"], kinds


@pytest.mark.parametrize(
    "text",
    [
        "I was in lane one at 50 mph. A van moved over into lane one, right ahead of me, leaving no room to stop.",
        "Ego in lane two at 70 km/h; a coupe came across into lane two just in front of the ego with too little "
        "space to brake.",
        "We were in lane one doing 40 mph when a lorry switched into lane one without signalling, directly ahead "
        "of us.",
    ],
)
def test_a_move_into_the_ego_lane_said_in_words_is_a_cut_in_and_room_to_stop_is_no_stop(text):
    assert _behaviours(text) == ["cut_in"]


@pytest.mark.parametrize(
    "text",
    [
        "The van ahead of me was dawdling, then suddenly accelerated hard. I kept to 40 mph.",
        "I was behind a tractor at 20 mph and it crept along, then abruptly sped up to 40 mph.",
        "the lorry in front of me was crawling along then suddenly sped up to about 70 mph. i stayed at 40 mph.",
    ],
)
def test_a_verb_after_then_in_a_first_person_story_keeps_its_subject(text):
    assert _behaviours(text) == ["change_speed"]


@pytest.mark.parametrize(
    "text",
    [
        "Ego turns left at 15 km/h; a walker at the corner waits on the kerb and lets the ego finish turning.",
        "At the T-junction ego goes right at 20 km/h; a cyclist on the side road holds back and lets us complete "
        "the manoeuvre.",
        "I turn right at 10 mph and a lady with a pram stops at the edge and lets me make the turn.",
    ],
)
def test_letting_the_ego_complete_what_it_does_is_a_safe_outcome(text):
    assert read(text).intent == "safe"
