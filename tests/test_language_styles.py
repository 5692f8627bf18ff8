"""Reading descriptions in the styles people write them in: dashcam commentary, diary-style stories
told in the first person, terse notes, test-spec prose. Each case here is written for the rule it
pins down (who brakes when the narrator does not say "I", what an outcome said as a noun means, how
a clock or a spoken unit is read ...), not taken from a corpus."""

from __future__ import annotations

import pytest

from vei_scenario.language.corpus_check import layers_problems
from vei_scenario.language.reader import _tokens, read
from vei_scenario.language.stated import stated_clock, stated_outcome


def _actors(text: str) -> list[tuple]:
    return [(a.kind, a.relation, [b[0] for b in a.behaviours]) for a in read(text).actors]


# --- the outcome, said as commentary ------------------------------------------------------------------
@pytest.mark.parametrize(
    "text, intent",
    [
        ("Cyclist pulls out, I brake, brake... contact.", "collision"),
        ("A van swings into our lane. Close!", "near_miss"),
        ("The bus waits at the line for us. Clean.", "safe"),
        ("A moped cuts across and he misses us by a hair.", "near_miss"),
        ("I had to jink left to miss her.", "near_miss"),
        ("We stopped with half a metre to spare.", "near_miss"),
        ("The jogger kept to the verge and we gave her loads of room.", "safe"),
        ("The lorry braked and I went into the back of it.", "collision"),
        ("I tapped the scooter at walking pace.", "collision"),
        ("The taxi stopped dead but I didn't touch it.", "near_miss"),
        ("Two cars swerve and no one hits anyone.", "near_miss"),
        ("The pickup did not stop, hit the kerb and rolled.", "collision"),
        ("Honestly nothing happened, all fine.", "safe"),
    ],
)
def test_an_outcome_said_as_commentary_is_the_intent(text, intent):
    assert stated_outcome(" ".join(_tokens(text))) == intent


def test_a_description_with_no_other_road_user_is_safe():
    assert read("Just the ego on an empty country road at 80 km/h in the fog.").intent == "safe"


# --- clocks, spoken units, numbers in words -----------------------------------------------------------
@pytest.mark.parametrize(
    "said, clock",
    [("9 : 15 pm", "21:15"), ("7 am", "07:00"), ("12 : 30 am", "00:30"), ("14 : 05", "14:05"), ("11 pm", "23:00")],
)
def test_a_clock_with_am_or_pm(said, clock):
    assert stated_clock(f"it was {said} , a van stops") == clock


def test_a_clock_written_with_dots_does_not_end_the_sentence():
    assert read("At 7 a.m. on a wet Monday a van ahead of us stops.").time == "07:00"


@pytest.mark.parametrize(
    "text, kph",
    [
        ("Doing 70 k's on the ring road when a car ahead brakes hard.", 70.0),
        ("Ego at eighty k, a lorry pulls out from the left.", 80.0),
        ("I was doing like forty when a cyclist cut in.", 40.0),
        ("Ego at fifty-five, a car ahead stops.", 55.0),
    ],
)
def test_spoken_speeds(text, kph):
    assert read(text).ego_speed_mps * 3.6 == pytest.approx(kph)


@pytest.mark.parametrize(
    "text, attribute, value",
    [
        ("Rain pelting down, a cyclist crosses from the left.", "weather", "heavy_rain"),
        ("Light snowfall, a van ahead brakes.", "weather", "snow"),
        ("Pitch black, a deer runs across.", "time", "23:00"),
        ("It was getting dark when a child ran out.", "time", "19:30"),
        ("Low traffic volume; a car overtakes us.", "density", "light"),
    ],
)
def test_settings_said_as_people_say_them(text, attribute, value):
    assert getattr(read(text), attribute) == value


# --- who does what: the narrator's reactions ------------------------------------------------------------
@pytest.mark.parametrize(
    "text, expected",
    [
        # braking said after a comma with nobody named, once the road user is in the ego's path
        (
            "Taxi swings into our lane from the right, hard on the brakes, stopped a metre short.",
            [("car", "right", ["cut_in"])],
        ),
        (
            "A moped comes out of the side road on the left, braking, braking, phew.",
            [("car", "junction_left", ["turn_into"])],
        ),
        # a finite verb stays the road user's own
        ("A van cuts in ahead of us and then brakes hard.", [("van", None, ["cut_in", "sudden_stop"])]),
        # a first-person sentence with no subject
        (
            "A jogger was running along my lane towards me. Slowed right down and went round her.",
            [("pedestrian", "ahead", ["along_road"])],
        ),
    ],
)
def test_the_narrators_reactions_are_not_the_road_users(text, expected):
    assert _actors(text) == expected


def test_an_outcome_said_as_a_noun_is_no_behaviour():
    """ "crash" is also a rider's fall (a sudden stop); standing alone after a modifier it names what
    happened, and a road-user noun that says what it does does it."""
    assert _actors("Red-light runner from the right, dusk, side-on crash.") == [
        ("car", "junction_right", ["run_red_light"])
    ]
    assert _actors("Ghost driver in our lane, head-on crash.")[0][2] == ["wrong_way"]


def test_a_behaviour_only_a_vehicle_does_said_with_no_road_user_is_a_cars():
    r = read("Cut-in on a busy motorway at 120 km/h.")
    assert [(a.kind, [b[0] for b in a.behaviours]) for a in r.actors] == [("car", ["cut_in"])]
    assert r.ego_speed_mps * 3.6 == pytest.approx(120.0)


# --- who does what: people, vehicles, groups --------------------------------------------------------------
@pytest.mark.parametrize(
    "text, kind",
    [
        ("Some bloke in front slammed on for no reason.", "car"),
        ("A guy coming the wrong way in our lane.", "car"),
        ("A guy walks across in front of us.", "pedestrian"),
        ("Some idiot in a pickup cuts in ahead of us.", "van"),
    ],
)
def test_a_person_word_is_a_driver_when_they_do_what_drivers_do(text, kind):
    assert [a.kind for a in read(text).actors] == [kind]


def test_the_first_and_the_second_of_a_group():
    r = read("Two vans ahead both brake: the second one stops hard, the first one stops normally.")
    assert [[b[0] for b in a.behaviours] for a in r.actors] == [["stop"], ["sudden_stop"]]


def test_an_apposition_after_a_word_for_any_vehicle_says_which():
    assert [a.kind for a in read("A lead vehicle, a white box van, brakes hard 20 m ahead.").actors] == ["van"]


def test_a_vehicle_someone_comes_out_from_behind_stands_and_the_distance_is_the_crossers():
    r = read("A boy dashes out from behind a parked-up camper on the left, 9 m ahead of us.")
    boy, camper = r.actors
    assert (boy.kind, boy.relation, boy.distance_m) == ("pedestrian", "roadside_left", 9.0)
    assert (camper.kind, camper.speed_mps, camper.distance_m) == ("van", 0.0, None)


def test_a_speed_after_what_the_ego_is_behind_is_the_egos():
    r = read("I was stuck behind a tractor at about 25 mph when a car overtook us both.")
    assert r.ego_speed_mps * 3.6 == pytest.approx(25 * 1.609344, abs=0.1)


@pytest.mark.parametrize(
    "text, expected",
    [
        # a phrase that denies giving way at a roundabout: straight into the ego's path from its arm
        (
            "Roundabout, a lorry coming in from the left does not give way.",
            [("truck", "junction_left", ["run_red_light"])],
        ),
        (
            "At the roundabout a van joins from the next entry on the right without yielding.",
            [("van", "junction_right", ["turn_into"])],
        ),
        # a possessive inside a phrase
        ("A cyclist sails through her red from the left.", [("bicycle", "junction_left", ["run_red_light"])]),
        # waiting for the ego to pass is giving way
        ("A car waits in the side road on the right for us to go.", [("car", "junction_right", ["give_way"])]),
        # pulling in at a stop is a stop, not a cut-in
        ("The bus ahead pulls in to the bus stop.", [("truck", "ahead", ["stop"])]),
        # a hard stop said by its wording
        ("The lorry ahead decelerates sharply to a standstill.", [("truck", "ahead", ["sudden_stop"])]),
        ("The car ahead brakes and stops gently.", [("car", "ahead", ["stop"])]),
        # the crossing said after the vehicle a rider comes out from is the rider's, with its side
        (
            "A cyclist shoots out from in front of the parked lorry crossing right to left.",
            [("bicycle", "roadside_right", ["cross_in_front"]), ("truck", "roadside_right", ["stop"])],
        ),
    ],
)
def test_behaviours_as_people_say_them(text, expected):
    assert _actors(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        # a rider cutting across at a junction crosses the ego's road
        ("A cyclist cuts across at the crossroads.", [("bicycle", "roadside_right", ["cross_in_front"])]),
        # a rider pulling out to overtake another does not cross
        (
            "Two cyclists ride along the kerb; the second one pulls out to overtake the first, right into our path.",
            # (it pulls out from the kerb, the near one of a writer who says "kerb": the left)
            [("bicycle", "ahead", ["along_road"]), ("bicycle", "roadside_left", ["cut_in", "overtake"])],
        ),
        # "two lanes over" is a lane to the side; "ahead" after a cut-in is where it cuts in
        ("A taxi two lanes over darts into our lane 8 m ahead.", [("car", None, ["cut_in"])]),
        # keeping a time headway is following
        ("A pickup keeps a 2 s time headway behind us.", [("van", "behind", ["follow_vehicle"])]),
    ],
)
def test_more_behaviours_as_people_say_them(text, expected):
    assert _actors(text) == expected


def test_the_narrator_drives_where_a_first_person_story_opens_without_its_i():
    r = read("Just cruising behind my neighbour's van at about 30 mph, nothing to report.")
    assert r.ego_speed_mps * 3.6 == pytest.approx(30 * 1.609344, abs=0.1)
    assert [(a.kind, a.relation) for a in r.actors] == [("van", "ahead")]


def test_it_in_a_story_told_as_we_is_the_road_user():
    r = read("We were behind a tram at 25 km/h when it drew to a stop.")
    assert [(a.kind, [b[0] for b in a.behaviours]) for a in r.actors] == [("truck", ["stop"])]


def test_a_bare_speed_among_the_settings_of_a_terse_line_is_the_egos():
    r = read("Lead van brakes hard, 70 km/h, fog.")
    assert r.ego_speed_mps * 3.6 == pytest.approx(70.0) and r.actors[0].speed_mps is None


def test_a_distance_after_then_is_the_subjects():
    (car,) = read("A car in the right lane then moves into our lane 12 m ahead of us.").actors
    assert car.distance_m == 12.0


def test_a_junction_named_by_its_line_or_sign_is_no_behaviour():
    r = read("A van waits at the stop sign on the right, then pulls out in front of us.")
    assert r.map_kind == "crossroad"
    assert [(a.kind, a.relation, [b[0] for b in a.behaviours]) for a in r.actors] == [
        ("van", "junction_right", ["turn_into"])
    ]


def test_a_bare_number_after_a_verb_of_going_is_a_speed():
    assert read("Ego drives 45, a jogger crosses from the left.").ego_speed_mps * 3.6 == pytest.approx(45.0)
    assert read("Ego drives 45, a jogger crosses from the left.").actors[0].speed_mps is None


def test_an_animal_or_child_moving_into_the_road_crosses_it():
    assert _actors("A fox shot into the road from the hedge.") == [("pedestrian", "roadside_right", ["cross_in_front"])]


def test_the_lights_on_red_are_no_red_light_run_and_another_driver_behind_is_another_car():
    r = read("Approaching the lights on red, the van in front stops, the van behind us does not stop and hits us.")
    assert [(a.kind, a.relation) for a in r.actors] == [("van", "ahead"), ("van", "behind")]
    assert all("run_red_light" not in [b[0] for b in a.behaviours] for a in r.actors)


def test_a_zebra_crossing_is_no_junction():
    r = read("At the zebra crossing a man starts to cross from the right.")
    assert r.map_kind != "crossroad" and _actors("At the zebra crossing a man crosses from the right.")[0][2] == [
        "cross_in_front"
    ]


def test_where_the_ego_is_struck_from_is_where_the_doer_comes_from():
    (truck,) = read("Our vehicle was waiting at the lights when it was struck from behind by a lorry.").actors
    assert (truck.kind, truck.relation) == ("truck", "behind")


def test_an_animal_jumping_from_the_side_onto_the_road_crosses():
    assert _actors("A deer is jumping from the trees on the left, 30 m ahead.")[0][1:] == (
        "roadside_left",
        ["cross_in_front"],
    )


def test_a_road_user_entering_a_roundabout_without_yielding_plays_a_run_into_the_egos_path(tmp_path):
    """The roundabout's arms link one lane each way into the ring: with one lane each way (unless the
    text asks for more) the ego and the road user entering from the next arm both reach the ring, and
    the entry meets the ego's path (before, both stopped at the end of their arms, 60 m apart)."""
    from vei_scenario.language.corpus_check import play_case
    from vei_scenario.language.rules_backend import layers_from_text

    text = "On the roundabout a moped comes in from the right without giving way."
    # (going onto the ring with no light said: a turn into the ego's way round, see ring_entry)
    assert _actors(text) == [("car", "junction_right", ["turn_into"])]
    for seed in (0, 1):
        assert play_case({"text": text}, layers_from_text, tmp_path, seed) == [], seed


def test_a_vehicle_coming_up_behind_on_a_side_to_cut_in_starts_in_that_lane_faster_than_the_ego(tmp_path):
    from vei_scenario.language.corpus_check import play_case
    from vei_scenario.language.rules_backend import layers_from_text

    text = "At 60 mph a van comes up behind on the left and swerves into our lane."
    (van,) = read(text).actors
    assert (van.relation, [b[0] for b in van.behaviours]) == ("left", ["cut_in"]) and van.speed_mps < 0  # (faster)
    assert play_case({"text": text}, layers_from_text, tmp_path) == []


def test_braking_to_a_speed_is_a_slowing_by_the_difference():
    (truck,) = read("A truck at 80 km/h ahead of us brakes to 50 km/h.").actors
    assert [b[0] for b in truck.behaviours] == ["change_speed"]
    assert truck.behaviours[0][1]["speed_delta_mps"] * 3.6 == pytest.approx(-30.0)


@pytest.mark.parametrize(
    "text, intent",
    [("A van drove into its rear.", "collision"), ("The bus missed us by centimetres.", "near_miss")],
)
def test_more_outcomes(text, intent):
    assert stated_outcome(" ".join(_tokens(text))) == intent


# --- the scorer, aligned with the format ---------------------------------------------------------------
def _layers(adversaries):
    env = {"map": {"kind": "straight"}, "weather": {"condition": "clear"}, "time_of_day": "12:00"}
    return {"environment": env | {"traffic_density": "none"}, "ego": {"speed_mps": 10.0}, "adversaries": adversaries}


def test_a_vehicle_standing_in_the_lane_doing_nothing_is_scenery_not_a_listed_road_user():
    """The format lists road users "not parked scenery unless it acts": a broken-down lorry a cut-out
    reveals does not act, wherever it stands."""
    cut_out = {"type": "car", "spawn": {"relation": "ahead"}, "speed_mps": 20.0, "behaviour": {"behaviour": "cut_out"}}
    lorry = {"type": "truck", "spawn": {"relation": "ahead"}, "speed_mps": 0.0, "behaviour": {"behaviour": "stop"}}
    case = {"actors": [{"type": "car", "behaviours": ["cut_out"]}]}
    assert layers_problems(_layers([cut_out, lorry]), case) == []
    moving = dict(lorry, speed_mps=5.0)  # (one that moves acts, and is counted)
    assert layers_problems(_layers([cut_out, moving]), case) != []


def test_a_rider_along_the_road_at_the_edge_of_the_lane_starts_on_that_kerb_side():
    rider = {
        "type": "bicycle",
        "spawn": {"relation": "ahead", "lateral_m": 1.2},
        "speed_mps": 5.0,
        "behaviour": {"behaviour": "along_road"},
    }
    want = {"type": "bicycle", "behaviours": ["along_road"], "relation": ["roadside_left"]}
    assert layers_problems(_layers([rider]), {"actors": [want]}) == []
    assert layers_problems(_layers([rider]), {"actors": [dict(want, relation=["roadside_right"])]}) != []


def test_a_miss_lists_all_it_gets_wrong_past_a_wrong_count_or_type():
    """A wrong count or type is one miss among several: the actors still paired are checked too."""
    car = {"type": "car", "spawn": {"relation": "ahead"}, "speed_mps": 8.0, "behaviour": {"behaviour": "cut_in"}}
    extra = {"type": "van", "spawn": {"relation": "ahead"}, "speed_mps": 9.0, "behaviour": {"behaviour": "keep_lane"}}
    want = {"type": "car", "behaviours": ["cut_out"], "relation": ["ahead"]}
    problems = layers_problems(_layers([extra, car]), {"actors": [want]})  # (the car pairs best: one miss)
    assert problems == [
        "2 adversaries ['van', 'car'] (expected 1: ['car'])",
        "behaviours ['cut_in'] (expected among ['cut_out'])",
    ]
    alone = layers_problems(_layers([car]), {"actors": [dict(want, type="bicycle", relation=["left"])]})
    assert [p.split(" ")[0] for p in alone] == ["type", "behaviours", "relation"]
    assert layers_problems(_layers([]), {"actors": [want]}) == ["0 adversaries [] (expected 1: ['car'])"]


# --- text by writers who never saw the reader: slips, shorthand, narratives, lists --------------------
def _reading(text: str):
    return read(text)


@pytest.mark.parametrize(
    "typed, read_as",
    [("stright", "straight"), ("trafic", "traffic"), ("overtaeks", "overtakes"), ("roundabuot", "roundabout"),
     ("aftrenoon", "afternoon"), ("teh", "the")],
)  # fmt: skip
def test_a_word_one_slip_from_a_reader_word_is_read_as_it(typed, read_as):
    assert _tokens(f"a van on the {typed} bit")[4] == read_as


def test_a_word_a_dictionary_knows_is_never_respelt():
    assert "strait" in _tokens("a ferry in the strait stops")


def test_slips_keep_the_scene_and_are_reported():
    r = _reading("a lorry enterring the roundabuot from the left dosnt give way, hevy trafic, foggy aftrenoon")
    assert (r.map_kind, r.density, r.weather) == ("roundabout", "heavy", "fog")
    assert r.time == "15:30" and [(a.kind, a.relation) for a in r.actors] == [("truck", "junction_left")]
    assert ("roundabuot", "roundabout") in r.read_as


@pytest.mark.parametrize(
    "text, kind, relation",
    [
        ("Ego on the ring road roundabout at 20 km/h. M/bike entering from L arm fails to give way.", "car",
         "junction_left"),
        ("Ego veh NB, 50 kph. Hatchback from the lane to the R cuts in sharp.", "car", "right"),
    ],
)  # fmt: skip
def test_shorthand_of_radio_reports_is_read(text, kind, relation):
    assert [(a.kind, a.relation) for a in _reading(text).actors] == [(kind, relation)]


def test_lt_traffic_and_nite_are_light_traffic_at_night():
    r = _reading("Ego 40 kph, a van ahead stops. Lt traffic, nite.")
    assert (r.density, r.time) == ("light", "23:00")


@pytest.mark.parametrize("said, metres", [("40 feet", 12.2), ("20 yards", 18.3), ("30 ft", 9.1)])
def test_a_distance_in_feet_or_yards_is_metres(said, metres):
    (actor,) = _reading(f"A jogger steps off the kerb on the left {said} ahead of the ego.").actors
    assert actor.distance_m == pytest.approx(metres, abs=0.05)


@pytest.mark.parametrize(
    "text, clock",
    [
        ("I was doing about 40 mph around 5pm when a van ahead braked hard.", "17:00"),
        ("At approx. 06:50 hrs the ego at 40 mph met a van braking hard ahead.", "06:50"),
        ("At 1945 hrs the ego at 40 mph met a van braking hard ahead.", "19:45"),
        ("It was about 4 in the afternoon, I was at 40 mph and a van ahead braked hard.", "16:00"),
        ("It was about 10 at night, I was at 40 mph and a van ahead braked hard.", "22:00"),
    ],
)
def test_a_clock_hour_is_the_time_and_never_the_speed(text, clock):
    r = _reading(text)
    assert r.time == clock
    assert r.ego_speed_mps == pytest.approx(40 * 0.44704)


@pytest.mark.parametrize(
    "text",
    [
        "The subject vehicle (V1, the test car) was at 30 mph when a cyclist (V2) crossed from the left kerb.",
        "My client, the driver of the insured car, was at 30 mph when a cyclist crossed from the left kerb.",
        "The insured vehicle (ego) was at 30 mph when a cyclist crossed from the left kerb.",
    ],
)
def test_the_ego_named_again_in_apposition_is_one_ego(text):
    r = _reading(text)
    assert [(a.kind, a.relation) for a in r.actors] == [("bicycle", "roadside_left")]
    assert r.ego_speed_mps == pytest.approx(30 * 0.44704)


@pytest.mark.parametrize(
    "text, kind",
    [
        ("The SV drives at 50 km/h. POV1 (van) in the left lane cuts in 10 m ahead of the SV.", "van"),
        ("The SV drives at 50 km/h. The POV, a 10 m rigid bus, cuts in from the left lane.", "truck"),
        ("I was at 50 km/h. The third party vehicle, a blue van, cut in from the left lane.", "van"),
    ],
)
def test_a_code_of_the_other_party_is_the_road_user_it_names(text, kind):
    assert [(a.kind, a.behaviours[0][0]) for a in _reading(text).actors] == [(kind, "cut_in")]


@pytest.mark.parametrize("bullet", ["- ", "* ", "\u2022 ", "1. ", "2) "])
def test_each_item_of_a_list_is_read_on_its_own(bullet):
    items = ["motorway, sunny", "ego at 90 km/h", "motorbike comes up from behind at 120 km/h, overtakes"]
    text = "\n".join(bullet + item for item in items)
    r = _reading(text)
    assert (r.weather, r.ego_speed_mps) == ("clear", pytest.approx(25.0))
    assert [(a.kind, a.speed_mps) for a in r.actors] == [("car", pytest.approx(120 / 3.6))]


@pytest.mark.parametrize(
    "text, time",
    [
        ("Ego 40 kph, van ahead brakes hard. Dry, PM.", "15:30"),
        ("Ego 40 kph, van ahead brakes hard. Snowing, AM.", "08:30"),
        ("The sun was setting as a van ahead braked hard in front of me.", "19:30"),
    ],
)
def test_the_half_of_the_day_or_the_setting_sun_is_the_time(text, time):
    assert _reading(text).time == time


@pytest.mark.parametrize(
    "said, density",
    [
        ("traffic: none", "none"),
        ("density: high", "heavy"),
        ("background traffic density: low", "light"),
        ("no other traffic", "none"),
        ("moderately busy", "moderate"),
        ("bumper to bumper", "heavy"),
    ],
)
def test_traffic_said_as_a_field_or_in_other_words(said, density):
    assert _reading(f"A van ahead brakes hard, {said}.").density == density


def test_a_grey_car_is_a_colour_not_the_weather():
    assert _reading("The car in front, a grey Volvo, braked hard for no reason.").weather is None
    assert _reading("A grey morning; the car in front braked hard.").weather == "cloudy"


def test_a_manner_said_in_a_clause_of_its_own_is_the_one_road_users():
    r = _reading("A cyclist rides along the left kerb ahead. I pass it with plenty of room.")
    assert [(b[0], b[2]) for b in r.actors[0].behaviours] == [("along_road", "safe")]
    from vei_scenario.language.rules_backend import layers_from_text

    (adv,) = layers_from_text("A cyclist rides along the left kerb ahead. I pass it with plenty of room.", 0)[
        "adversaries"
    ]
    assert adv["behaviour"]["config"]["criticality"] == "safe"


@pytest.mark.parametrize(
    "text", ["A lorry overtakes the ego and is cutting in too early.", "A van cuts in, in last moment."]
)
def test_too_early_and_in_last_moment_are_dangerous(text):
    assert _reading(text).actors[0].behaviours[0][2] == "dangerous"


@pytest.mark.parametrize(
    "text",
    [
        "You're doing 25 mph and the van in front of you brakes hard.",
        "Ego: 25 mph. Van ahead brakes hard.",
        "Van ahead brakes hard. Speed of ego is 25 mph.",
        "Can you do a van ahead that brakes hard, like 25 mph for me?",
    ],
)
def test_the_egos_speed_said_as_you_a_field_or_for_me(text):
    assert _reading(text).ego_speed_mps == pytest.approx(25 * 0.44704)


@pytest.mark.parametrize(
    "text",
    ["The ego was following a van at 30 mph. The van braked hard.", "Ego following van, 30 mph. Van brakes hard."],
)
def test_what_the_ego_follows_is_ahead(text):
    assert [(a.kind, a.relation) for a in _reading(text).actors] == [("van", "ahead")]


def test_where_the_ego_is_struck_is_not_the_side_it_came_from():
    text = "At the crossroads a hatchback from the ego's left ran the red light and struck the ego on its nearside."
    assert [a.relation for a in _reading(text).actors] == ["junction_left"]


def test_a_distance_on_its_own_line_is_the_moving_road_users_not_the_parked_cars():
    text = "- ego at 30 mph\n- a boy runs out from between parked cars on the left\n- 9 metres ahead of ego"
    moving = [a for a in _reading(text).actors if a.kind == "pedestrian"]
    assert moving[0].distance_m == 9.0


def test_fields_between_bars_are_read_one_at_a_time():
    r = _reading(
        "time: 21:30 | ego: 40 km/h | actor1: e-scooter, crosses from right kerb, 18 km/h | outcome: near miss"
    )
    assert r.ego_speed_mps == pytest.approx(40 / 3.6)


@pytest.mark.parametrize(
    "text, behaviour",
    [
        ("A van waiting in the side road on the right let me go by.", "give_way"),
        ("One van in right line is change to my line close before me.", "cut_in"),
        ("A lorry in the left lane drifts over into my lane.", "cut_in"),
    ],
)
def test_learners_and_other_words_for_behaviours(text, behaviour):
    assert _reading(text).actors[0].behaviours[0][0] == behaviour


@pytest.mark.parametrize(
    "text, intent",
    [
        ("A van pulled out and I stopped 3 metres short of it.", "near_miss"),
        ("An e-scooter cut in front, no harm done but close.", "near_miss"),
        ("A jogger ahead on the verge, I pass her fine.", "safe"),
        ("A bus stops ahead and I stop behind. Nothing happen.", "safe"),
    ],
)
def test_outcomes_in_other_words(text, intent):
    assert _reading(text).intent == intent


@pytest.mark.parametrize("thing", ["debris lying", "a fallen mattress lying", "a pile of pallets lying", "cones"])
def test_a_vehicle_swerving_round_something_lying_in_the_lane_is_a_cut_out(thing):
    r = _reading(f"The van ahead swerves into the right lane to avoid {thing} in our lane.")
    assert r.actors[0].behaviours[0][0] == "cut_out" and r.actors[0].obstacle == 1


def test_one_act_said_twice_is_read_once():
    walker = _reading("A woman steps off the left kerb and crosses into my path.").actors[0]
    assert [b[0] for b in walker.behaviours] == ["cross_in_front"]
    car = _reading("The car in front slammed its brakes on and came to a complete stop.").actors[0]
    assert [b[0] for b in car.behaviours] == ["sudden_stop"]
    rider = _reading("A cyclist at the kerb on the right waits for me to go past, then crosses behind me.").actors[0]
    assert [b[0] for b in rider.behaviours] == ["give_way"]


def test_a_map_word_before_the_egos_own_name_is_the_map():
    assert _reading("In the roundabout my car drive 20 km/h, a van enters from the left.").map_kind == "roundabout"


@pytest.mark.parametrize(
    "text, lanes",
    [
        ("A 4-lane divided highway at 60 mph, a van ahead brakes hard.", 2),
        ("Highway, 3 each direction, 60 mph, a van ahead brakes hard.", 3),
        ("A single-carriageway road at 40 mph, a van ahead brakes hard.", 1),
    ],
)
def test_lanes_said_as_a_total_of_a_divided_road_or_a_carriageway(text, lanes):
    assert _reading(text).lanes == lanes


def test_a_pickup_truck_is_a_van_and_a_curvy_road_a_curve():
    r = _reading("On a curvy road a pickup truck ahead brakes hard.")
    assert (r.map_kind, [a.kind for a in r.actors]) == ("curve", ["van"])


def test_both_vehicles_after_the_event_are_no_new_road_users():
    r = _reading("A cyclist crosses from the left kerb, near miss, both vehicles continued.")
    assert [a.kind for a in r.actors] == ["bicycle"]


@pytest.mark.parametrize("said, density", [("a quiet road", "light"), ("a dead quiet road", "none")])
def test_a_quiet_road_has_a_little_traffic_a_dead_quiet_one_none(said, density):
    assert _reading(f"On {said} a van ahead brakes hard.").density == density


def test_a_term_with_its_abbreviation_in_brackets_is_one_road_user():
    r = _reading("A principal other vehicle (POV), a van, travels in the left lane and cuts in 8 m ahead.")
    assert [(a.kind, a.behaviours[0][0]) for a in r.actors] == [("van", "cut_in")]


def test_a_cut_across_the_egos_lane_to_turn_is_one_forced_turn():
    r = _reading("At the crossroads the car in the lane to my right cuts across in front of me to turn left.")
    assert [b[0] for b in r.actors[0].behaviours] == ["forced_turn"]


def test_the_car_is_the_ego_when_the_ego_is_the_only_car_named():
    r = _reading("Ego car drives at 30 km/h, a cyclist comes out from the right, the car must brake hard.")
    assert [a.kind for a in r.actors] == ["bicycle"]
    two = _reading("My car at 30 km/h, a car pulls out from the left, the car stops.")  # (another car: that one)
    assert [a.kind for a in two.actors] == ["car"]


def test_an_oncoming_car_keeping_to_its_lane_is_no_wrong_way_driver():
    (car,) = _reading("A car coming the other way keeps to its lane.").actors
    assert (car.relation, car.behaviours[0][0]) == ("oncoming", "keep_lane")


def test_riders_of_a_group_all_ride_what_they_are_on():
    r = _reading("Two kids on bicycles rode off the pavement on the right in front of me.")
    assert [a.kind for a in r.actors] == ["bicycle", "bicycle"]


def test_a_noun_without_its_article_after_because_is_the_one_named_before():
    r = _reading("Bus is pulling out from the stop in front of ego, no accident because bus go slow.")
    assert [a.kind for a in r.actors] == ["truck"]


@pytest.mark.parametrize(
    "text, behaviour",
    [
        ("A walker on the right footway initiates a crossing manoeuvre across the ego's path.", "cross_in_front"),
    ],
)
def test_a_behaviour_said_as_a_noun_performed_is_that_behaviour(text, behaviour):
    assert _reading(text).actors[0].behaviours[0][0] == behaviour


@pytest.mark.parametrize(
    "said", ["when the time-to-collision reaches 1.5 s", "a near-collision without contact, TTC below 1 s"]
)
def test_time_to_collision_and_a_near_collision_are_no_collision(said):
    assert stated_outcome(" ".join(_tokens(f"A van cuts in, {said}."))) != "collision"


@pytest.mark.parametrize(
    "text, kind",
    [("CPNA-25, nearside adult walking at 5 km/h, VUT 40 km/h.", "pedestrian"),
     ("CBFA-50, farside bicyclist 15 km/h crossing, VUT 30 km/h.", "bicycle")],
)  # fmt: skip
def test_the_target_of_a_test_code_said_again_is_that_target(text, kind):
    (target,) = _reading(text).actors
    assert target.kind == kind and target.speed_mps is not None


def test_an_acceleration_with_a_caret_is_no_speed():
    (car,) = _reading("CCRb, VUT 50 km/h, GVT 50 km/h, headway 20 m, GVT decel 4 m/s^2 to standstill.").actors
    assert car.speed_mps == pytest.approx(50 / 3.6)


# "heads up" as a notice opening a message ("Heads up:", "heads up for tomorrow's run") is no verb of the
# road user named after it; "heads up the hill" still is one
@pytest.mark.parametrize(
    "text",
    [
        "heads up for tomorrow's track run: oncoming Transit turns right across us at the junction, we're at 50kph.",
        "Heads up: oncoming van turns right across us at the junction, we're at 50kph.",
        "Heads-up - at the junction an oncoming car turns right across our path, ego 50 km/h.",
        "quick heads up on Thursday's test: oncoming car turns right across us at the junction, we're doing 50.",
    ],
)
def test_a_heads_up_is_a_notice_not_a_move(text):
    (car,) = read(text).actors
    assert [b[0] for b in car.behaviours] == ["turn_across"]


def test_heading_up_the_road_is_still_a_move():
    (rider,) = read("A cyclist heads up the hill towards us; we're at 30 km/h.").actors
    assert [b[0] for b in rider.behaviours] != []
