"""vei describe: language → layers → OpenSCENARIO, closed-loop evaluation and refinement."""

from __future__ import annotations

import http.server
import json
import threading
from pathlib import Path

import pytest

from vei_scenario.cli import main
from vei_scenario.errors import VeiInputError
from vei_scenario.language.behaviours import BEHAVIOURS
from vei_scenario.language.describe import describe_batch
from vei_scenario.language.layers import schema_problems
from vei_scenario.language.paper import DESCRIPTIONS
from vei_scenario.language.rules_backend import layers_from_text, read
from vei_scenario.language.scenario_writer import write_scenario
from vei_scenario.openscenario.validation import validate_files


def _batch(name: str, count: int, refine: bool = False, out: Path | None = None, seed: int = 0):
    text = DESCRIPTIONS[name]
    return describe_batch(lambda i: layers_from_text(text, seed * 1000 + i), count, out, text, "rules", seed, refine)


@pytest.mark.parametrize("name", list(DESCRIPTIONS))
def test_paper_descriptions_give_valid_scenarios(name, tmp_path, qc_venv):
    records, doc = _batch(name, 3, out=tmp_path)
    files = sorted(tmp_path.rglob("scenario.xo*"))
    assert len(files) == 6
    assert validate_files(files) == []  # ASAM XSDs (OpenSCENARIO 1.3, OpenDRIVE) and vei's rules
    assert all(r.outcome["duration_s"] >= 14.9 for r in records)  # vei run played them to the end


def test_cut_in_criticality_orders_act_comfort_and_crash_rate():
    s = {name: _batch(name, 32)[1]["summary"] for name in ("Dangerous", "Moderate", "Safe")}
    d, m, safe = s["Dangerous"], s["Moderate"], s["Safe"]
    assert d["mean_min_act_s"] < m["mean_min_act_s"] < safe["mean_min_act_s"]
    assert d["mean_comfort"] < m["mean_comfort"] < safe["mean_comfort"]
    assert d["crash_rate"] > 0 and m["crash_rate"] == 0 and safe["crash_rate"] == 0
    refined = _batch("Dangerous", 32, refine=True)[1]["summary"]
    assert refined["crash_rate"] < 0.10
    assert refined["mean_min_act_s"] < m["mean_min_act_s"]
    assert refined["episodes_run"] > 32  # some scenarios needed more than one episode


def test_refinement_records_each_episode():
    records, _ = _batch("Dangerous", 6, refine=True)
    multi = [r for r in records if len(r.episodes) > 1]
    assert multi
    for r in multi:
        assert [e["episode"] for e in r.episodes] == list(range(1, len(r.episodes) + 1))
        assert r.episodes[0]["ego_collided"] and r.episodes[0]["adjustment"] == "soften"
        gaps = [e["configuration"][0]["behaviour"]["config"]["gap_m"] for e in r.episodes]
        assert gaps[1] > gaps[0]  # softened after the crash: the cut-in gap grew
        assert r.episodes[-1]["intent_met"] or len(r.episodes) == 5


def test_a_value_that_started_in_the_target_profile_is_probed_on_both_sides():
    """A crossing timed in the middle of its dangerous profile has nowhere to go towards that middle:
    sharpening tries one profile width past it (earlier, the side the profiles order towards), then
    one on the other side, then two, within the parameter's range."""
    from vei_scenario.language.refinement import adjust

    layers = layers_from_text("A pedestrian steps out from the right kerb in front of the ego and is hit.", 0)
    cross = BEHAVIOURS["cross_in_front"]
    lo, hi = cross.PROFILES["dangerous"]["arrival_gap_s"]
    layers["adversaries"][0]["behaviour"]["config"]["arrival_gap_s"] = (lo + hi) / 2
    tried = [adjust(layers, "sharpen", k)["adversaries"][0]["behaviour"]["config"]["arrival_gap_s"] for k in range(4)]
    mid, w = (lo + hi) / 2, hi - lo
    assert tried == pytest.approx([mid - w, mid + w, mid - 2 * w, mid + 2 * w], abs=1e-3)
    # a value that started outside it still moves a growing share of the way to its middle
    layers["adversaries"][0]["behaviour"]["config"]["arrival_gap_s"] = 3.5
    moved = adjust(layers, "sharpen", 0)["adversaries"][0]["behaviour"]["config"]["arrival_gap_s"]
    assert moved == pytest.approx(3.5 + 0.3 * (mid - 3.5), abs=1e-3)


def test_a_collision_asked_for_is_reached_although_the_planner_brakes():
    """With the ego's planner braking, a crossing in the middle of the dangerous profile is avoided;
    refining probes past the profile until the pedestrian is hit (every scenario of the batch)."""
    text = "A pedestrian suddenly steps out from the right kerb right in front of the ego and is hit."
    records, doc = describe_batch(lambda i: layers_from_text(text, i), 3, None, text, "rules", 0, True)
    assert all(not r.episodes[0]["ego_collided"] for r in records)  # the planner avoids the first try
    assert all(r.episodes[-1]["intent_met"] and r.episodes[-1]["ego_collided"] for r in records)
    assert doc["summary"]["intent_met"] == 3


def test_same_seed_same_bytes_other_seed_other_scenarios(tmp_path):
    def files(out):
        return {p.relative_to(out): p.read_bytes() for p in sorted(out.rglob("*")) if p.is_file()}

    _batch("Running Red Light", 3, out=tmp_path / "a", seed=4)
    _batch("Running Red Light", 3, out=tmp_path / "b", seed=4)
    _batch("Running Red Light", 3, out=tmp_path / "c", seed=5)
    a, b, c = files(tmp_path / "a"), files(tmp_path / "b"), files(tmp_path / "c")
    assert a == b
    assert a.keys() == c.keys() and a != c


def test_unknown_words_are_named_not_refused(capsys, tmp_path):
    """A word with no meaning for the layers is read past and listed, a verb the reader has no word
    for among them (the road user goes on); only a description with no road user at all is refused,
    naming what is missing and the words not used, with nothing written."""
    r = read("A purple car zigzags wildly in front of the ego")
    assert r.ignored == ["purple", "zigzags", "wildly"] and [b[0] for b in r.actors[0].behaviours] == ["keep_going"]
    r = read("A purple car brakes wildly in front of the ego")
    assert r.ignored == ["purple", "wildly"] and [b[0] for b in r.actors[0].behaviours] == ["sudden_stop"]
    assert main(["describe", "A zorblat teleports", "-o", str(tmp_path / "x")]) == 2
    err = capsys.readouterr().err
    assert "no road user found" in err and "'zorblat', 'teleports'" in err and "Traceback" not in err
    assert not (tmp_path / "x").exists()


def test_reading_of_positions_sequences_and_words():
    r = read(
        "On a rainy evening the ego drives on a curved road. A truck behind follows the ego very closely, "
        "then it overtakes. A pedestrian from the kerb crosses the road."
    )
    assert (r.map_kind, r.weather, r.time) == ("curve", "rain", "20:00")
    truck, person = r.actors
    assert truck.kind == "truck" and truck.relation == "behind"
    assert [b[0] for b in truck.behaviours] == ["follow_vehicle", "overtake"]
    assert truck.behaviours[0][2] == "dangerous"
    assert person.kind == "pedestrian" and person.relation == "roadside_right"
    layers = layers_from_text("The ego drives at 36 km/h. A car ahead brakes hard while it changes lanes.", 1)
    assert layers["ego"]["speed_mps"] == pytest.approx(10.0)
    assert "parallel" in layers["adversaries"][0]["behaviour"]


@pytest.mark.parametrize(
    "text, kind, relation, behaviours",
    [
        # a road user said not to give way or stop at a junction goes through it, timed to meet the ego
        ("Ego turns left at a crossing; an oncoming motorcycle doesn't yield.", "car", "junction_opposite",
         ["run_red_light"]),
        ("A car approaching from the right does not stop at the junction.", "car", "junction_right", ["run_red_light"]),
        ("A car from the left won't give way at the crossroads.", "car", "junction_left", ["run_red_light"]),
        # one said not to brake or slow carries on; one said not to cross stands
        ("The lead car doesn't brake.", "car", "ahead", ["keep_going"]),
        ("The van in front didn't even bother to slow down.", "van", "ahead", ["keep_going"]),
        ("The truck ahead never slows down.", "truck", "ahead", ["keep_going"]),
        ("A pedestrian waits at the kerb and does not cross.", "pedestrian", "roadside_right", ["give_way"]),
        # "too fast to stop" does not stop; a stop sign is a junction; a rider not giving way rides through
        ("The ego waits at a stop sign, then pulls out; a car from the left is going too fast to stop.", "car",
         "junction_left", ["run_red_light"]),
        ("At a yield sign a cyclist from the right does not give way.", "bicycle", "junction_right",
         ["run_red_light"]),
        # a walker who does not give way or wait crosses (before: read as a car cutting in)
        ("A pedestrian does not give way to the ego.", "pedestrian", "roadside_right", ["cross_in_front"]),
        ("A child on the right does not wait for us and runs across.", "pedestrian", "roadside_right",
         ["cross_in_front"]),
        # the same verbs said plainly
        ("A car ahead brakes hard.", "car", "ahead", ["sudden_stop"]),
        ("The cyclist coming from the left yields to the AV at the crossroads.", "bicycle", "junction_left",
         ["give_way"]),
    ],
)  # fmt: skip
def test_a_denied_verb_is_not_read_as_said(text, kind, relation, behaviours):
    """ "does not yield", "doesn't brake", "never slows", "won't give way": before, the negation was
    dropped with the contraction and the verb read as said (the motorcycle gave way, the car braked)."""
    (actor,) = read(text).actors
    assert (actor.kind, actor.relation, [b[0] for b in actor.behaviours]) == (kind, relation, behaviours)


def test_speeds_from_to_lane_counts_in_digits_and_kinds_of_road_user():
    """ "slows from 80 to 30 km/h" changes by 50 km/h (before: the first speed only, and the verb's
    default change); "3 lanes" and "a 2-lane road" are lane counts (before: numbers read past); a
    word naming a kind before a road user ("a police car", "a school bus") is not an unknown verb
    (before: the description was refused); "the bus stops" is a bus stopping, "at a bus stop" a place."""
    (truck,) = read("A truck slows from 80 to 30 km/h in front of the ego on a two-lane road.").actors
    assert truck.speed_mps == pytest.approx(80 / 3.6)
    assert truck.behaviours[0][:2] == ("change_speed", {"speed_delta_mps": pytest.approx(-50 / 3.6)})
    (car,) = read("The car ahead accelerates from 30 to 50 km/h.").actors
    assert car.behaviours[0][1]["speed_delta_mps"] == pytest.approx(20 / 3.6)
    assert read("Highway, 3 lanes. A car cuts in sharply in front of the ego.").lanes == 3
    r = read("On a 2-lane road a school bus stops ahead of the ego.")
    assert r.lanes == 1 and [  # (a two-lane road: one lane each way)
        (a.kind, a.relation, [b[0] for b in a.behaviours]) for a in r.actors
    ] == [("truck", "ahead", ["stop"])]
    (police,) = read("A police car drives the wrong way down the road towards the ego.").actors
    assert police.kind == "car" and police.behaviours[0][0] == "wrong_way"
    (bus, walker) = read("The bus stops at a bus stop and a pedestrian walks out in front of it.").actors
    assert (bus.kind, bus.behaviours[0][0], walker.kind) == ("truck", "stop", "pedestrian")
    (walker,) = read("The ego approaches a zebra crossing at 30 km/h; a woman with a pram steps onto it.").actors
    assert walker.kind == "pedestrian" and walker.behaviours[0][0] == "cross_in_front"
    # "ahead" before its road user is where it is, not a preposition taking it as an object (before:
    # the verb had no subject and the description was refused)
    (walker,) = read("Ego drives at 30 km/h; 20 m ahead a pedestrian suddenly steps off the kerb.").actors
    assert (walker.kind, walker.distance_m, walker.behaviours[0][0]) == ("pedestrian", 20.0, "cross_in_front")


@pytest.mark.parametrize(
    "text, ego_kph, kind, relation, behaviour",
    [
        ("Car-to-car rear stationary at 50 km/h.", 50, "car", "ahead", "stop"),  # (standing: stopped)
        ("Car-to-Car Rear braking, 12 m gap.", None, "car", "ahead", "sudden_stop"),
        ("Car-to-Pedestrian Nearside Child at 40 km/h.", 40, "pedestrian", "roadside_right", "cross_in_front"),
        ("Car-to-Bicyclist farside at 30 km/h.", 30, "bicycle", "roadside_left", "cross_in_front"),
        ("Car-to-Pedestrian Longitudinal Adult at 25 km/h", 25, "pedestrian", "ahead", "along_road"),
    ],
)
def test_euro_ncap_scenario_names_are_read(text, ego_kph, kind, relation, behaviour):
    """Euro NCAP's names of its tests, as a test engineer writes them: the target, where it is and
    what it does, and the speed after the name the ego's (before: "car-to-car" was read past and the
    description gave no road user at all; "rear" put the target behind)."""
    r = read(text)
    (actor,) = r.actors
    assert (actor.kind, actor.relation, actor.behaviours[0][0]) == (kind, relation, behaviour)
    assert (r.ego_speed_mps and round(r.ego_speed_mps * 3.6)) == ego_kph


def test_e_scooter_wording():
    """Plurals of hyphenated names ("e-scooters" was read past), "one of them" in the next sentence,
    riding side by side, entering the road from the sidewalk, a bike lane as the roadside (not a
    bicycle), "without stopping" as a denial."""
    first, second = read("Two e-scooters ride side by side ahead of the ego; one of them brakes suddenly.").actors
    assert (first.kind, second.kind, second.relation) == ("e-scooter", "e-scooter", "ahead")
    assert [b[0] for b in first.behaviours] == ["along_road"] and [b[0] for b in second.behaviours] == ["sudden_stop"]
    (rider,) = read("An e-scooter rider on the sidewalk suddenly enters the road 15 m in front of the ego.").actors
    assert (rider.kind, rider.relation, rider.distance_m, rider.behaviours[0][0]) == (
        "e-scooter",
        "roadside_right",
        15.0,
        "cross_in_front",
    )
    assert [a.kind for a in read("An e-scooter travels in the bike lane on the right.").actors] == ["e-scooter"]
    (scooter,) = read("An electric scooter crosses at the zebra crossing without stopping.").actors
    assert [b[0] for b in scooter.behaviours] == ["cross_in_front"]
    (scooter,) = read("A Lime scooter wobbles into the road from the right.").actors
    said = (scooter.kind, scooter.relation, scooter.behaviours[0][0])
    assert said == ("e-scooter", "roadside_right", "cross_in_front")


def test_notes_rates_pronouns_and_places():
    """A test engineer's notes (a label opening any sentence, the noun named again without an article
    is the same road user), decelerations in m/s² and "to a standstill", "daylight", an animal played
    as a walker, "it" after a clause about the ego meaning the road user when the verb is not the ego's,
    "the stop" as a place and pulling away from it as pulling out."""
    r = read(
        "Scenario: urban road, dry, daylight. Target: cyclist, same direction, 20 km/h, 30 m ahead. "
        "Cyclist turns left without signalling."
    )
    (cyclist,) = r.actors
    assert (r.time, cyclist.kind, cyclist.distance_m, cyclist.behaviours[0][0]) == (
        "13:00",
        "bicycle",
        30.0,
        "forced_turn",
    )
    (car,) = read("The leading vehicle decelerates at 3 m/s² to a standstill.").actors
    assert car.behaviours[0][:2] == ("stop", {"decel_mps2": 3.0})
    (car,) = read("The car ahead decelerates at 7 m/s² to a standstill.").actors
    assert car.behaviours[0][:2] == ("sudden_stop", {"decel_mps2": 7.0})  # (harder than a comfortable stop)
    (truck,) = read("A truck accelerates at 1.5 m/s² from 20 to 60 km/h.").actors
    assert truck.behaviours[0][1] == {"speed_delta_mps": pytest.approx(40 / 3.6), "rate_mps2": 1.5}
    (dog,) = read("Our AV drives at 45 km/h through a residential street and a dog runs out.").actors
    assert (dog.kind, dog.behaviours[0][0]) == ("pedestrian", "cross_in_front")
    (car,) = read("A car is parked on the right; as the ego approaches, it pulls out into traffic.").actors
    assert car.behaviours[0][0] == "cut_in"
    (van,) = read("The ego approaches a parked van; it brakes hard.").actors  # (the ego brakes: not the van)
    assert [b[0] for b in van.behaviours] != ["sudden_stop"]
    (bus,) = read("A bus pulls away from the stop into the ego's lane.").actors
    assert (bus.kind, [b[0] for b in bus.behaviours]) == ("truck", ["cut_in"])
    assert [a.relation for a in read("The ego is overtaking a truck when an oncoming car appears.").actors] == [
        None,
        "oncoming",
    ]


@pytest.mark.parametrize(
    "text",
    [
        "Our AV drives at 45 km/h through a residential street and a unicorn runs out.",
        "The ego drives on; then a hovercraft cuts in.",
    ],
)
def test_someone_the_reader_has_no_word_for_is_a_road_user_of_its_own_not_the_ego(text):
    """Before, the verb of an unknown road user went to whoever was named last (the ego); it is a road
    user of its own, of the kind its behaviour needs (running out: a walker; cutting in: a car)."""
    (who,) = read(text).actors
    assert (who.kind, who.behaviours[0][0]) in (("pedestrian", "cross_in_front"), ("car", "cut_in"))


def test_crossings_centre_lines_trams_and_jaywalkers():
    """ "at the crossing" and "at the pedestrian crossing" are places ("a pedestrian crossing from the
    right" is a walker crossing); an oncoming truck crossing the centre line comes into the ego's lane;
    a tram is a long vehicle; a jaywalker walks."""
    assert read("A tram approaches from the left at the crossing.").map_kind == "crossroad"
    (tram,) = read("A tram approaches from the left at the crossing.").actors
    assert (tram.kind, tram.relation) == ("truck", "junction_left")
    (child,) = read("The ego stops at the pedestrian crossing and a child crosses.").actors
    assert (child.kind, child.behaviours[0][0]) == ("pedestrian", "cross_in_front")
    (walker,) = read("A pedestrian crossing from the right stops in the middle of the lane.").actors
    assert [b[0] for b in walker.behaviours] == ["cross_in_front", "stop"]
    (truck,) = read("An oncoming truck crosses the centre line on a bend.").actors
    assert (truck.relation, truck.behaviours[0][0]) == ("oncoming", "wrong_way")
    (walker,) = read("A jaywalker crosses mid-block, ego doing 35 mph.").actors
    assert (walker.kind, walker.behaviours[0][0]) == ("pedestrian", "cross_in_front")


def test_both_cars_before_anyone_are_the_ego_and_one_more():
    """Euro NCAP shorthand: "both cars at 50 km/h" before anyone is named means the ego and its target
    (before: two adversaries, and the ego's speed sampled). Two cyclists named first stay two."""
    r = read("CCRb: both cars at 50 km/h with a 40 m gap; the car in front brakes at 6 m/s² down to standstill.")
    (car,) = r.actors
    assert r.ego_speed_mps == car.speed_mps == pytest.approx(50 / 3.6) and car.distance_m == 40.0
    assert car.behaviours[0][:2] == ("sudden_stop", {"decel_mps2": 6.0})
    assert len(read("Two cyclists ride ahead; both brake.").actors) == 2


@pytest.mark.parametrize(
    "text, ego_kph, kind, relation, speed, behaviours",
    [
        # a speed standing next to the ego after a vehicle's place is said of both, unless the ego's is said
        ("The lead vehicle, 12 m ahead of the ego at 50 km/h, brakes hard to a stop.", 50, "car", "ahead", 50,
         ["sudden_stop"]),
        ("A truck 30 m in front of us at 60 km/h stops.", 60, "truck", "ahead", 60, ["stop"]),
        ("The ego drives at 80 km/h; a car ahead of the ego at 30 km/h brakes.", 80, "car", "ahead", 30,
         ["sudden_stop"]),
        ("A cyclist ahead of the ego at 20 km/h falls.", None, "bicycle", "ahead", 20, ["sudden_stop"]),
        # "slow" before a road user is how fast it goes (before: a slowing), not the ego's speed
        ("A slow truck ahead.", None, "truck", "ahead", -0.7, ["keep_going"]),  # (said where, not what: it goes on)
        ("A slow truck ahead of us at 30 km/h brakes.", None, "truck", "ahead", 30, ["sudden_stop"]),
        ("A slow-moving tractor in front brakes.", None, "truck", "ahead", -0.6, ["sudden_stop"]),
        ("The truck in front is very slow and then stops.", None, "truck", "ahead", -0.7, ["stop"]),
        # the ego said to be behind someone: that one is ahead (before: no place), and the other way round
        ("Ego cruising at 100 km/h behind a slower van; the van brakes suddenly.", 100, "van", "ahead", -0.7,
         ["sudden_stop"]),
        ("We drive behind a truck that brakes.", None, "truck", "ahead", None, ["sudden_stop"]),
        ("The AV is following a bus.", None, "truck", "ahead", None, ["keep_going"]),
        ("We are ahead of a motorcycle that overtakes us.", None, "car", "behind", None, ["overtake"]),
        ("A car is behind the ego.", None, "car", "behind", None, ["keep_going"]),
        # the ego's own participle after a relation to it: its speed, not the road user's (before: the
        # dog ran at 40 km/h and the ego's speed was sampled)
        ("A dog runs onto the road 15 m ahead of the ego travelling at 40 km/h.", 40, "pedestrian",
         "roadside_right", None, ["cross_in_front"]),
        ("A child steps out 20 m in front of the ego doing 50 km/h.", 50, "pedestrian", "roadside_right", None,
         ["cross_in_front"]),
        # a clause that goes on with its subject: the speed is that subject's (before: the ego's)
        ("An e-scooter follows the ego closely and then overtakes it on the right at 25 km/h.", None, "e-scooter",
         "behind", 25, ["follow_vehicle", "overtake"]),
        # the ego follows someone, or someone leads: that one is ahead (before: no place)
        ("The subject vehicle follows a lead car at a 2 s gap; the lead car brakes hard.", None, "car", "ahead",
         None, ["sudden_stop"]),
        ("A preceding truck brakes suddenly.", None, "truck", "ahead", None, ["sudden_stop"]),
    ],
)  # fmt: skip
def test_speeds_and_places_said_beside_the_ego(text, ego_kph, kind, relation, speed, behaviours):
    """Where a speed or a place is said next to the ego, whose it is: "12 m ahead of the ego at 50
    km/h" (before: the lead's only, the ego's sampled), "a slow truck" (before: a truck slowing
    down), "we drive behind a truck" (before: the truck had no place). A negative speed is a factor
    of the default speed (a speed word)."""
    r = read(text)
    (a,) = r.actors
    assert (None if r.ego_speed_mps is None else round(r.ego_speed_mps * 3.6, 6)) == ego_kph
    got = None if a.speed_mps is None else round(a.speed_mps * (3.6 if a.speed_mps > 0 else 1), 6)
    assert (a.kind, a.relation, got, [b[0] for b in a.behaviours]) == (kind, relation, speed, behaviours)


@pytest.mark.parametrize(
    "text, relation, behaviour",
    [
        # a side said right after a sideways verb is where the road user moves to: a cut-in comes from the
        # other side, a lane change or a swerve out goes that way (before: "swerves left into our lane"
        # was refused, "merges right" came from the right)
        ("A cyclist swerves left into our lane.", "right", ("cut_in", {})),
        ("The van merges right from the middle lane just in front of us.", "left", ("cut_in", {})),
        ("The car ahead changes lanes left.", "ahead", ("change_lane", {"direction": 1.0})),
        ("The truck ahead swerves right to avoid a stopped car.", "ahead", ("cut_out", {"direction": -1.0})),
        ("A child runs left across the road.", "roadside_right", ("cross_in_front", {})),
        # "right" before a place is "just", not a side
        ("A car cuts in right in front of us.", None, ("cut_in", {})),
        ("The van cuts in right ahead of the ego.", None, ("cut_in", {})),
        ("A cyclist on the right swerves.", "right", ("cut_in", {})),
        ("A car cuts in from the right.", "right", ("cut_in", {})),
        # articles stand for one another in phrases; animals leap onto the road
        ("A bus pulls away from a bus stop on the right into the ego's lane.", "right", ("cut_in", {})),
        ("At dusk a deer jumps onto the road 40 m ahead.", "roadside_right", ("cross_in_front", {})),
        # "<verb> to/into the left lane": a lane change that way (before: "changes to" refused, "moves to
        # the left lane" kept going there, "changes into the left lane" cut in)
        ("The vehicle in front changes to the left lane, revealing a stopped car.", "ahead",
         ("cut_out", {"direction": 1.0})),
        ("The lead car moves to the right lane.", "ahead", ("change_lane", {"direction": -1.0})),
        ("The car ahead changes into the left lane.", "ahead", ("change_lane", {"direction": 1.0})),
        ("A truck in the right lane moves over into the left lane.", "right", ("change_lane", {"direction": 1.0})),
        # a walker who emerges from between parked cars crosses (before: a car turning out of a side road)
        ("A child emerges from between parked cars.", "roadside_right", ("cross_in_front", {})),
        ("An e-scooter rider suddenly enters the roadway from between two parked vans.", "roadside_right",
         ("cross_in_front", {})),
    ],
)  # fmt: skip
def test_where_a_road_user_moves_to(text, relation, behaviour):
    a = read(text).actors[0]
    assert (a.relation, a.behaviours[0][:2]) == (relation, behaviour)


def test_test_specification_wording():
    """How test specifications say it: "target pedestrian (adult)" is one walker (before: a car and two
    walkers), "50% of the vehicle width" is no speed and no road user (before: a car at 50 km/h), a
    walker "from the far side" crosses from there (before: walked along the road), a POV that "fails to
    give way" at a junction goes through it (before: did nothing), "performs an evasive lane change"
    is a lane change (before: refused)."""
    r = read(
        "Test case: target pedestrian (adult) walks from the far side at 5 km/h, impact at 50% of the vehicle width."
    )
    (walker,) = r.actors
    assert (walker.kind, walker.relation, walker.behaviours[0][0]) == ("pedestrian", "roadside_left", "cross_in_front")
    assert walker.speed_mps == pytest.approx(5 / 3.6) and r.ego_speed_mps is None
    (pov,) = read("SV travelling at 50 km/h approaches a junction; POV from the right fails to give way.").actors
    assert (pov.kind, pov.relation, pov.behaviours[0][0]) == ("car", "junction_right", "run_red_light")
    lead, truck = read(
        "The vehicle in front performs an evasive lane change to the left, revealing a stationary truck."
    ).actors
    assert lead.behaviours[0][:2] == ("cut_out", {"direction": 1.0}) and (truck.kind, truck.speed_mps) == ("truck", 0.0)
    courier, van = read("A courier walks out from behind a parked van.").actors
    assert (courier.kind, courier.behaviours[0][0], van.kind, van.speed_mps) == (
        "pedestrian",
        "cross_in_front",
        "van",
        0,
    )
    opened = read("A cyclist rides ahead; someone opens the car door.")  # (no behaviour opens a door: said)
    assert [a.kind for a in opened.actors] == ["bicycle"] and "opens" in opened.ignored
    (cyclist,) = read("A cyclist comes from the right.").actors
    assert (cyclist.relation, cyclist.behaviours[0][0]) == ("roadside_right", "cross_in_front")
    (walker,) = read("A child walks along the kerb on the right.").actors
    assert walker.behaviours[0][0] == "along_road"


def test_pulling_away_and_cutting_the_corner():
    """ "pulls away" alone speeds up (before: refused); from a bus stop it pulls out; an oncoming truck
    that "cuts the corner into the ego's lane" comes into it (the corpus's wording)."""
    assert read("The bus ahead pulls away.").actors[0].behaviours[0][0] == "change_speed"
    assert read("A bus pulls away from a bus stop on the right.").actors[0].behaviours[0][0] == "cut_in"
    (truck,) = read(
        "The ego takes a left-hand bend at 60 km/h; an oncoming truck cuts the corner into the ego's lane."
    ).actors
    assert truck.behaviours[0][0] in ("cut_in", "wrong_way")


def test_riders_against_the_traffic_come_towards_the_ego():
    (cyclist,) = read("A cyclist rides against the traffic in the ego's lane.").actors  # (head-on: the wrong way)
    assert (cyclist.relation, cyclist.facing, cyclist.behaviours[0][0]) == ("ahead", "against", "wrong_way")
    (rider,) = read("An e-scooter rides ahead of the ego.").actors
    assert rider.facing is None


def test_lights_on_a_car_are_not_a_junction():
    assert read("At night a cyclist without lights rides in our lane 40 m ahead.").map_kind is None
    r = read("Heavy fog. A broken-down car stands in our lane 80 m ahead with hazard lights on.")
    assert (r.map_kind, r.actors[0].speed_mps, r.actors[0].distance_m) == (None, 0.0, 80.0)
    assert read("A car stops at the traffic lights.").map_kind == "crossroad"


def test_behaviour_library_is_complete_and_listed(capsys):
    wanted = {
        "keep_lane",
        "change_speed",
        "follow_vehicle",
        "overtake",
        "cut_in",
        "sudden_stop",
        "forced_turn",
        "run_red_light",
        "cross_in_front",
        "stop",
        "keep_going",
    }
    assert wanted <= set(BEHAVIOURS)
    assert main(["behaviours", "-v"]) == 0
    out = capsys.readouterr().out
    assert all(name in out for name in wanted) and "ACC follower" in out and "gap_m" in out


def test_layers_json_is_validated_and_runs(tmp_path, capsys):
    layers = layers_from_text(DESCRIPTIONS["Sudden Stop"], 7)
    good = tmp_path / "layers.json"
    good.write_text(json.dumps(layers))
    assert main(["describe", "--layers", str(good), "-o", str(tmp_path / "out")]) == 0
    assert (tmp_path / "out" / "scenario_000" / "scenario.xosc").is_file()
    layers["adversaries"][0]["behaviour"]["behaviour"] = "moonwalk"
    layers["ego"]["lane"] = 9
    bad = tmp_path / "bad.json"
    bad.write_text(json.dumps(layers))
    assert main(["describe", "--layers", str(bad), "-o", str(tmp_path / "out2")]) == 2
    err = capsys.readouterr().err
    assert "bad.json: ego/lane: 9 is greater than the maximum of 4" in err and "Traceback" not in err
    layers["ego"]["lane"] = 1
    assert any("unknown behaviour 'moonwalk'" in p for p in schema_problems(layers))


def test_spawn_that_the_map_cannot_hold_is_refused():
    layers = layers_from_text(DESCRIPTIONS["Moderate"], 1)
    layers["ego"]["lane"] = 2  # the lane next to the centre line: nothing to its left in its direction
    with pytest.raises(ValueError, match="no lane left of the ego"):
        write_scenario(layers, "scenario")


class _Replay(http.server.BaseHTTPRequestHandler):
    answers: list[str] = []
    requests: list[dict] = []

    def do_POST(self):  # noqa: N802 (http.server's name)
        body = json.loads(self.rfile.read(int(self.headers["Content-Length"])))
        type(self).requests.append(body)
        content = type(self).answers[min(len(type(self).requests) - 1, len(type(self).answers) - 1)]
        data = json.dumps({"choices": [{"message": {"role": "assistant", "content": content}}]}).encode()
        self.send_response(200)
        self.send_header("Content-Type", "application/json")
        self.send_header("Content-Length", str(len(data)))
        self.end_headers()
        self.wfile.write(data)

    def log_message(self, *args):
        pass


@pytest.fixture()
def replay_server():
    server = http.server.HTTPServer(("127.0.0.1", 0), _Replay)
    thread = threading.Thread(target=server.serve_forever, daemon=True)
    thread.start()
    _Replay.requests = []
    yield f"http://127.0.0.1:{server.server_address[1]}/v1"
    server.shutdown()


def test_llm_backend_repairs_validates_and_retries(replay_server, tmp_path):
    from vei_scenario.language.llm_backend import layers_from_llm

    good = layers_from_text(DESCRIPTIONS["Safe"], 2)
    for key in ("format", "background", "description", "seed"):
        good.pop(key)  # repairable omissions
    wrong = dict(good, ego=dict(good["ego"], placement="on_the_moon"))
    _Replay.answers = [json.dumps(wrong), json.dumps(good)]
    doc = layers_from_llm("a safe cut-in", 5, replay_server, "recorded")
    assert doc["format"] == "vei-layers/1" and doc["background"] == {"vehicles": []} and doc["seed"] == 5
    first, second = _Replay.requests
    assert first["response_format"]["json_schema"]["schema"]["title"].startswith("vei-layers/1")
    assert "ego/placement" in second["messages"][-1]["content"]  # the validator's finding went back
    _Replay.answers = ["not json at all"]
    _Replay.requests = []
    with pytest.raises(VeiInputError, match="refused after 2 attempts"):
        layers_from_llm("x", 1, replay_server, "recorded")
    _Replay.answers = [json.dumps(good)]
    code = main(
        [
            "describe",
            "a safe cut-in",
            "-o",
            str(tmp_path / "llm"),
            "--count",
            "2",
            "--backend",
            "llm",
            "--llm-url",
            replay_server,
            "--llm-model",
            "recorded",
            "--jobs",
            "1",
        ]
    )
    assert code == 0 and len(list((tmp_path / "llm").glob("scenario_*/scenario.xosc"))) == 2


ESMINI_CASES = ["Dangerous", "Sudden Stop", "Running Red Light", "Force Right Turn"]


@pytest.mark.parametrize("name", ESMINI_CASES)
def test_esmini_plays_what_has_no_custom_controller(name, tmp_path, esmini):
    from vei_scenario.conformance.esmini import cross_check

    layers = layers_from_text(DESCRIPTIONS[name], 5)
    layers["ego"]["agent"] = "lane_keep"  # no planner: every entity is esmini's default driver
    layers["background"]["vehicles"] = []
    w = write_scenario(layers, "scenario")
    (tmp_path / "scenario.xodr").write_bytes(w.xodr)
    (tmp_path / "scenario.xosc").write_bytes(w.xosc)
    c = cross_check(esmini, tmp_path / "scenario.xosc", dt=0.05)
    assert {e.entity for e in c.entities} == {"Ego", "Adversary1"}
    assert max(e.max_deviation_m for e in c.entities) < 0.25, c.entities
    assert [x[1:] for x in c.vei_collisions] == [x[1:] for x in c.esmini_collisions]


@pytest.mark.parametrize(
    "text",
    [
        "An oncoming car turns left across the ego's path at the crossroads.",
        "A car waiting in the side road on the right turns right into the ego's lane.",
        "A lorry approaching from the side road on the right gives way to the ego.",
        "A cyclist rides towards the ego along the edge of its lane.",
        "A ghost driver comes towards us in our lane and swerves back to its own side.",
        "An oncoming truck drifts into our lane and then returns to its lane.",
        "The car in front swerves into the left lane to avoid a stopped van in our lane.",
        "The ego drives on a two-lane road in heavy traffic.",
        # round a one-way ring: before, vei planned routes against the ring's lanes and turned the ego
        # from an unlinked approach lane into the exit lane (esmini: 100-160 m apart)
        "At a roundabout a car from the right does not give way.",
        "The ego enters a roundabout; a van coming from the left fails to stop.",
    ],
    ids=["turn_across", "turn_into", "give_way", "along_road", "wrong_way", "drift", "cut_out", "traffic",
         "roundabout_right", "roundabout_left"],
)  # fmt: skip
def test_esmini_plays_the_newer_behaviours_and_the_traffic_alike(text, tmp_path, esmini):
    """The behaviours added later, and background traffic in both directions, play the same in
    esmini: every entity within 0.25 m, the same collisions (the ego without its planner)."""
    from vei_scenario.conformance.esmini import cross_check

    layers = layers_from_text(text, 3)
    layers["ego"]["agent"] = "lane_keep"
    w = write_scenario(layers, "scenario")
    (tmp_path / "scenario.xodr").write_bytes(w.xodr)
    (tmp_path / "scenario.xosc").write_bytes(w.xosc)
    c = cross_check(esmini, tmp_path / "scenario.xosc", dt=0.05)
    assert len(c.entities) == 1 + len(layers["adversaries"]) + len(layers["background"]["vehicles"])
    assert max(e.max_deviation_m for e in c.entities) < 0.25, c.entities
    assert [x[1:] for x in c.vei_collisions] == [x[1:] for x in c.esmini_collisions]


def test_a_scenario_that_cannot_be_placed_is_a_row_with_its_reason(tmp_path):
    """One scenario of a batch asks for a lane the road lacks: it becomes a row with the reason, the
    others are written and scored, the batch goes on."""
    good = layers_from_text(DESCRIPTIONS["Moderate"], 1)
    bad = json.loads(json.dumps(good))
    bad["ego"]["lane"] = 2  # the lane next to the centre line: no lane left of the ego for the cut-in
    records, doc = describe_batch(lambda i: [good, bad][i], 2, tmp_path / "b", "mixed", "layers", 0, jobs=1)
    assert [r.ok for r in records] == [True, False]
    assert "no lane left of the ego" in records[1].error
    assert doc["summary"]["failed"] == 1 and doc["summary"]["scenarios"] == 1
    rows = (tmp_path / "b" / "batch.csv").read_text().splitlines()
    assert rows[0].endswith(",error") and "no lane left of the ego" in rows[2]
    assert (tmp_path / "b" / "scenario_000" / "scenario.xosc").is_file()
    assert (tmp_path / "b" / "scenario_001" / "layers.json").is_file()
    assert not (tmp_path / "b" / "scenario_001" / "scenario.xosc").exists()


def test_vei_run_of_a_generated_scenario_gives_the_batchs_run(tmp_path):
    """The batch runs and scores at vei run's own step (written in batch.json as rate_hz), so playing a
    generated scenario with vei run's defaults gives the batch's collisions and duration."""
    from vei_scenario.interpreter import run_scenario

    records, doc = _batch("Dangerous", 4, out=tmp_path)
    assert doc["rate_hz"] == [100.0]
    for r in records:
        result = run_scenario(tmp_path / f"scenario_{r.index:03d}" / "scenario.xosc")
        collisions = [{"time_s": round(t, 3), "entities": [a, b]} for t, a, b in result.collisions]
        assert collisions == r.outcome["collisions"]
        assert round(float(result.t[-1]), 3) == r.outcome["duration_s"]
    assert any(r.outcome["collisions"] for r in records)  # (a batch where something does collide)


@pytest.mark.parametrize(
    "text",
    [
        # a walker crossing four lanes on the way to a junction: the ego starts far enough back for the
        # crossing to reach its path (before: the child set off at once and crossed behind the ego)
        "Ego vehicle approaches a zebra crossing at 40 kph; a child runs across from the left.",
        # an oncoming rider swerving into the ego's lane rides head-on in it, as a wrong-way driver does
        # (before: a lane change into the traffic behind the ego, which ran into it)
        "An e-scooter coming from the opposite direction swerves into the ego's lane.",
    ],
)
def test_what_the_layers_say_is_what_plays(text, tmp_path):
    from vei_scenario.language.corpus_check import play_case
    from vei_scenario.language.rules_backend import layers_from_text

    for seed in (0, 1):
        assert play_case({"text": text}, layers_from_text, tmp_path, seed) == [], seed


@pytest.mark.parametrize("kind", ["e-scooter", "bicycle"])
def test_a_junction_road_user_without_a_stated_speed_keeps_within_its_top_speed(kind):
    """Its timing is worked out from the speed the layers give it: a speed its vehicle cannot reach
    would bring it to the ego's path seconds late."""
    from vei_scenario.language.scenario_writer import TYPES

    text = f"The ego goes straight at a crossroad with lights. A {kind.replace('-', ' ')} from the right runs the red."
    for seed in range(5):
        [adv] = layers_from_text(text, seed)["adversaries"]
        assert adv["type"] == kind and adv["behaviour"]["behaviour"] == "run_red_light"
        assert 0 < adv["speed_mps"] <= TYPES[kind][3]


def _crossing_at(gap: float) -> dict:
    from vei_scenario.language.rules_backend import place_adversary

    layers = layers_from_text("A pedestrian crosses from the right kerb in front of the ego.", 0)
    adv = layers["adversaries"][0]
    adv["behaviour"]["config"]["arrival_gap_s"] = gap
    adv["spawn"], adv["speed_mps"] = place_adversary(
        adv["type"], adv["spawn"]["relation"], "cross_in_front", adv["behaviour"]["config"], layers["ego"], 1
    )
    return layers


@pytest.mark.parametrize("gap, first", [(4.0, "adversary"), (-3.0, "ego")])
def test_each_episode_says_who_passed_first(gap, first):
    """A pedestrian timed to be across seconds before the ego arrives went first; one timed to reach
    the lane seconds after the ego passed did not."""
    from vei_scenario.language.describe import run_one

    record = run_one(_crossing_at(gap), 0, refine=False)
    assert record.episodes[0]["passed_first"] == {"Adversary1": first}
    assert not record.episodes[0]["ego_collided"]


def test_sharpening_a_timing_halves_the_closest_bracket():
    """Once one timing let the road user go first and another let the ego, the next try is the middle
    of the closest such pair; a pair narrower than the limit is not halved again."""
    from vei_scenario.language.refinement import NARROWEST_BRACKET_S, adjust

    def episode(gap: float, first: str) -> dict:
        layers = _crossing_at(gap)
        conf = [{"adversary": a["name"], "behaviour": a["behaviour"]} for a in layers["adversaries"]]
        return {"configuration": conf, "passed_first": {"Adversary1": first}}

    history = [episode(2.0, "adversary"), episode(-1.0, "ego"), episode(0.5, "adversary")]
    layers = _crossing_at(0.5)
    nxt = adjust(layers, "sharpen", 3, history=history)["adversaries"][0]["behaviour"]["config"]["arrival_gap_s"]
    assert nxt == pytest.approx(-0.25)
    narrow = [episode(0.0, "adversary"), episode(NARROWEST_BRACKET_S / 2, "ego")]
    kept = adjust(layers, "sharpen", 2, history=narrow)["adversaries"][0]["behaviour"]["config"]["arrival_gap_s"]
    assert kept != pytest.approx(NARROWEST_BRACKET_S / 4)
    # (the first try, 0 s, lay in the dangerous profile: probed two widths past it instead)
    lo, hi = BEHAVIOURS["cross_in_front"].PROFILES["dangerous"]["arrival_gap_s"]
    assert kept == pytest.approx((lo + hi) / 2 - 2 * (hi - lo))
