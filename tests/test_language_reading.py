"""Reading descriptions as people type them: refused only when no road user or no behaviour can be
found; what was read printed and kept in batch.json; units and styles (mph, m/s, kph, numbers in
words, police and insurance narratives, Euro NCAP codes, lanes as people say them); the stated
outcome only where it is stated; and a batch of which nothing could be written fails."""

from __future__ import annotations

import json

import pytest

from vei_scenario.cli import main
from vei_scenario.language.reader import read
from vei_scenario.language.reading import NotUnderstood, reading_document, reading_lines
from vei_scenario.language.rules_backend import layers_from_text

MPH = 0.44704


# --- refusal -----------------------------------------------------------------------------------------
@pytest.mark.parametrize(
    "text, missing, named",
    [
        ("A zorblat frobnicates the quux.", "road user", ["zorblat", "frobnicates", "quux"]),
        ("A car.", "behaviour", []),
    ],
    ids=["no-road-user", "no-behaviour"],
)
def test_refused_only_when_no_road_user_or_no_behaviour_is_found(text, missing, named):
    with pytest.raises(NotUnderstood) as refused:
        read(text)
    assert refused.value.missing == missing and refused.value.words == named
    assert f"no {missing} found" in str(refused.value)


@pytest.mark.parametrize(
    "text, kind, behaviour, unused",
    [
        (
            "Please can you generate a test where a child runs across from the left?",
            "pedestrian",
            "cross_in_front",
            {"please", "generate", "test"},
        ),
        ("What happens if a lorry in the right lane swerves into our lane?", "truck", "cut_in", {"happens"}),
        ("Witness states a van overtook the ego and cut back in sharply.", "van", "overtake", {"witness", "states"}),
    ],
    ids=["request", "question", "statement"],
)
def test_a_stray_word_is_listed_not_refused(text, kind, behaviour, unused):
    r = read(text)
    assert [(a.kind, a.behaviours[0][0]) for a in r.actors] == [(kind, behaviour)]
    assert unused <= set(r.ignored)


# --- what was read -----------------------------------------------------------------------------------
TEXT = "Please create a test: at night a child runs across from the left at 8 km/h, 15 m ahead, and we drive at 30 mph."


def test_the_reading_is_printed_one_line_per_road_user_then_settings_then_words_not_used():
    lines = reading_lines(read(TEXT))
    assert lines == [
        "read: road user 1: pedestrian; starts roadside_left; cross_in_front; speed 8 km/h; gap 15 m",
        "read: settings: ego speed 48.3 km/h; time of day 23:00",
        "read: not used: 'please', 'create', 'test'",
    ]


def test_describe_prints_the_reading_and_batch_json_holds_it(tmp_path, capsys):
    assert main(["describe", TEXT, "-o", str(tmp_path / "out"), "--count", "2", "--jobs", "1"]) == 0
    out = capsys.readouterr().out
    assert out.startswith("read: road user 1: pedestrian; starts roadside_left; cross_in_front")
    assert "read: not used: 'please', 'create', 'test'" in out
    assert "intent met" not in out  # (no outcome stated: nothing to be met)
    doc = json.loads((tmp_path / "out" / "batch.json").read_text())
    assert doc["reading"] == reading_document(read(TEXT))
    assert doc["reading"]["actors"][0] == {
        "type": "pedestrian",
        "start": "roadside_left",
        "behaviours": [{"behaviour": "cross_in_front"}],
        "speed_mps": 2.222,
        "gap_m": 15.0,
    }
    assert doc["summary"]["intent_met"] is None and doc["summary"]["intent_stated"] == 0
    assert all(row["intent_met"] is None for row in doc["scenarios"])


def test_intent_met_is_counted_where_an_intent_is_stated(tmp_path, capsys):
    text = "A car in the left lane cuts in aggressively in front of the ego and almost hits it."
    assert main(["describe", text, "-o", str(tmp_path / "out"), "--count", "2", "--jobs", "1"]) == 0
    out = capsys.readouterr().out
    doc = json.loads((tmp_path / "out" / "batch.json").read_text())
    assert doc["summary"]["intent_stated"] == 2 and f"intent met {doc['summary']['intent_met']} of 2" in out


def test_a_batch_of_which_no_scenario_can_be_written_exits_1_with_the_first_reason(tmp_path, capsys):
    layers = layers_from_text("A car in the left lane cuts in.", 0)
    layers["adversaries"][0]["spawn"] = {"relation": "junction_left"}  # (a straight road has no junction)
    path = tmp_path / "layers.json"
    path.write_text(json.dumps(layers))
    assert main(["describe", "--layers", str(path), "-o", str(tmp_path / "out")]) == 1
    captured = capsys.readouterr()
    assert "no scenario could be written (1 of 1 failed); scenario_000:" in captured.err
    assert "needs a junction" in captured.err and "scenario(s): crash rate" not in captured.out
    assert not (tmp_path / "out").exists()  # (a failed batch leaves no output behind)


# --- the stated outcome ------------------------------------------------------------------------------
@pytest.mark.parametrize(
    "text, intent",
    [
        ("A cyclist crosses from the right and the ego hits him.", "collision"),
        ("A cyclist crosses from the right; we want an impact.", "collision"),
        ("A cyclist crosses from the right. I braked hard but didn't hit him.", "near_miss"),
        ("A cyclist crosses from the right and the ego stops 1 m short of him.", "near_miss"),
        ("A cyclist crosses from the right; no contact was made.", "near_miss"),
        ("A cyclist crosses from the right and the ego passes without problem.", "safe"),
        ("A cyclist crosses from the right.", None),
        ("A cyclist crosses from the right; the ego hits the brakes.", None),
    ],
)
def test_the_outcome_is_read_only_where_it_is_stated(text, intent):
    assert read(text).intent == intent


# --- units and styles --------------------------------------------------------------------------------
@pytest.mark.parametrize(
    "said, mps",
    [
        ("at 30 mph", 30 * MPH),
        ("at forty miles an hour", 40 * MPH),
        ("at 10 meter per second", 10.0),
        ("at 50 kph", 50 / 3.6),
        ("at about 36 km/h", 10.0),
        ("at a hundred kilometres per hour", 100 / 3.6),
        ("at forty-five km/h", 45 / 3.6),
        ("at 20m/s", 20.0),
    ],
)
def test_the_ego_speed_in_the_units_people_use(said, mps):
    r = read(f"The ego drives {said} when a car in the left lane cuts in.")
    assert r.ego_speed_mps == pytest.approx(mps, abs=1e-6)


@pytest.mark.parametrize(
    "text, lanes",
    [
        ("On a two-lane road a van ahead stops.", 1),
        ("On a two-lane motorway a van ahead stops.", 2),
        ("On a road with three lanes each way a van ahead stops.", 3),
        ("We are in the middle lane of three when a van ahead stops.", 3),
    ],
)
def test_lanes_as_people_say_them(text, lanes):
    assert read(text).lanes == lanes


def test_a_police_narrative_names_the_ego_and_the_other_party():
    r = read(
        "Vehicle 1 was travelling at approx. 30 mph when V2, a Ford Transit, pulled out of a side road on "
        "the left into the path of V1. V2 struck V1."
    )
    assert r.ego_speed_mps == pytest.approx(30 * MPH) and r.intent == "collision"
    assert [(a.kind, a.relation, a.behaviours[0][0]) for a in r.actors] == [("van", "junction_left", "turn_into")]


@pytest.mark.parametrize(
    "text, kind, relation, behaviour, ego_kph, speed_kph",
    [
        ("CCRm VUT 60 km/h GVT 20 km/h", "car", "ahead", "keep_going", 60, 20),
        ("CPFA-75, VUT 30 km/h, EPTa 6 km/h", "pedestrian", "roadside_left", "cross_in_front", 30, 6),
        ("CBNA-50 at 25 km/h, EBTa 15 km/h", "bicycle", "roadside_right", "cross_in_front", 25, 15),
        ("CBLA-25 VUT 25 km/h EBTa 15 km/h", "bicycle", "ahead", "along_road", 25, 15),
        ("CMRb 60 km/h, EMT 60 km/h, 20 m headway", "car", "ahead", "sudden_stop", 60, 60),
        ("CPLA-50 with e-scooter target, VUT 35 km/h", "e-scooter", "ahead", "along_road", 35, None),
    ],
)
def test_euro_ncap_codes_mean_their_target_and_configuration(text, kind, relation, behaviour, ego_kph, speed_kph):
    r = read(text)
    (a,) = r.actors
    assert (a.kind, a.relation, a.behaviours[0][0]) == (kind, relation, behaviour)
    assert r.ego_speed_mps * 3.6 == pytest.approx(ego_kph)
    if speed_kph is not None:
        assert a.speed_mps * 3.6 == pytest.approx(speed_kph)


# --- the red-light runner from the left -------------------------------------------------------------
RED_LIGHT = "A bicycle coming from the left runs the red and crosses in front of the ego."


def test_the_red_light_runner_from_the_left_generates_every_scenario_and_plays_a_run_of_the_red(tmp_path):
    """Before, it was read as a kerb crossing from a junction arm, and all 32 scenarios failed to be
    written ("cross_in_front needs a roadside spawn")."""
    from vei_scenario.language.corpus_check import play_case
    from vei_scenario.language.scenario_writer import write_scenario

    (a,) = read(RED_LIGHT).actors
    assert (a.kind, a.relation, [b[0] for b in a.behaviours]) == ("bicycle", "junction_left", ["run_red_light"])
    for seed in range(32):
        write_scenario(layers_from_text(RED_LIGHT, seed), "scenario")
    for seed in (0, 1, 2):
        assert play_case({"text": RED_LIGHT}, layers_from_text, tmp_path, seed) == [], seed


# --- who does what, in narratives and lists ----------------------------------------------------------
@pytest.mark.parametrize(
    "text, expected",
    [
        # the ego's heading first; an opposite one is oncoming: a left turn across its path
        (
            "Unit 1 was southbound at 40 mph. Unit 2, a Honda Civic travelling northbound, turned left across "
            "the path of Unit 1.",
            [("car", "junction_opposite", "turn_across")],
        ),
        # "she" names the narrator all through ("She braked" is not the pickup's)
        (
            "My daughter said she was doing 30 mph when an oncoming pickup turned left across our lane. "
            "She braked hard.",
            [("van", "junction_opposite", "turn_across")],
        ),
        # done to a road user by the ego: the ego's
        ("A cyclist overtaken by the ego at 50 km/h.", [("bicycle", "ahead", "along_road")]),
        # an apposition after a definite road user, and a list sharing its verb
        ("The car ahead, a taxi, stops suddenly.", [("car", "ahead", "sudden_stop")]),
        (
            "A van, a car and a truck overtake us.",
            [("van", None, "overtake"), ("car", None, "overtake"), ("truck", None, "overtake")],
        ),
        # passengers and asides are no road users; the narrator's noun is the ego
        (
            "I was the designated driver and my kids were asleep in the back when a deer ran out from the left.",
            [("pedestrian", "roadside_left", "cross_in_front")],
        ),
    ],
    ids=["headings", "she", "passive-by-ego", "apposition", "list", "asides"],
)
def test_who_does_what_in_narratives_and_lists(text, expected):
    assert [(a.kind, a.relation, a.behaviours[0][0]) for a in read(text).actors] == expected


@pytest.mark.parametrize(
    "text, attribute, value",
    [
        ("It was grey and drizzly when a cyclist crossed from the right.", "weather", "rain"),
        ("It is raining strong and a cyclist crosses from the right.", "weather", "heavy_rain"),
        ("At 22:40 hrs a cyclist crossed from the right.", "time", "22:40"),
        ("At dusk a jogger in dark clothing crosses from the left.", "time", "19:30"),
        ("The motorway was heavy when a lorry cut in.", "density", "heavy"),
    ],
)
def test_settings_said_in_other_words(text, attribute, value):
    assert getattr(read(text), attribute) == value


def test_a_stated_distance_times_a_crossing_and_is_kept():
    layers = layers_from_text("The ego drives at 30 km/h; a pedestrian steps out from the right 20 m ahead.", 0)
    config = layers["adversaries"][0]["behaviour"]["config"]
    assert config["distance_m"] == 20.0 and -0.2 <= config["arrival_gap_s"] <= 6.0


@pytest.mark.parametrize(
    "text, side",
    [
        ("At the crossroads a jogger comes from the left.", "left"),
        ("At the intersection a woman with a pram comes from the right while the ego turns left.", "right"),
        ("Near the junction an old man on foot appears from the left, ego at 30 km/h.", "left"),
    ],
)
def test_a_walker_coming_from_a_side_of_a_junction_crosses_from_that_kerb(text, side):
    """A road user on a junction arm who just comes on drives across the ego's path; on foot it crosses
    from the kerb of that side (a walker does not drive down an arm), and its scenario can be written."""
    from vei_scenario.language.rules_backend import layers_from_text
    from vei_scenario.language.scenario_writer import write_scenario

    [walker] = read(text).actors
    assert (walker.kind, walker.relation) == ("pedestrian", f"roadside_{side}")
    assert [b[0] for b in walker.behaviours] == ["cross_in_front"]
    write_scenario(layers_from_text(text, 0), "scenario")


@pytest.mark.parametrize(
    "text, word",
    [
        ("A van came out of the side road on the right and V1 clipped it.", "clipped"),
        ("The ego is doing 40 km/h; a jogger steps out from the left and gets bumped.", "bumped"),
        ("A cyclist swerves in front of us and we tag him.", "tag"),
    ],
)
def test_words_the_outcome_was_read_from_are_not_listed_as_unused(text, word):
    """A verb of contact read as the outcome (collision) was used: "not used" does not list it."""
    r = read(text)
    assert r.intent == "collision" and word not in r.ignored


@pytest.mark.parametrize(
    "text",
    [
        "09:10 lorry ahead at 40 m slows to 30 km/h\n09:11 lorry brakes gently to a halt in lane to unload",
        "At the junction we yield; the bus on the main road goes on and a cyclist crosses behind it.",
        "A van pulled out of a side road and it had to stop sharply.",
    ],
)
def test_the_layers_carry_none_of_the_readers_own_marks(text):
    """The reader marks behaviours for its own passes (words, a right of way); the layers a scenario
    is written from hold only the parameters the behaviours take."""
    for seed in (0, 1):
        written = json.dumps(layers_from_text(text, seed=seed)["adversaries"])
        assert '"_' not in written


def test_a_scenario_the_player_refuses_fails_alone_with_its_files_kept(tmp_path, capsys, monkeypatch):
    """A generated scenario that is written but cannot be played fails by itself, as one that cannot be
    written does: the batch goes on, and its folder keeps the files to look at and the reason names the
    scenario's own file, not the batch's temporary copy of it."""
    from vei_scenario.errors import VeiInputError
    from vei_scenario.language import describe

    real, calls = describe.evaluate, []

    def refuse_first(xosc, rate_hz):
        calls.append(xosc)
        if len(calls) == 1:
            raise VeiInputError(xosc, "line 240", "no chain of roads joins the route's waypoints")
        return real(xosc, rate_hz)

    monkeypatch.setattr(describe, "evaluate", refuse_first)
    text = "A cyclist pulls out of a side road on the left in front of the ego."
    assert main(["describe", text, "-o", str(tmp_path / "out"), "--count", "2", "--jobs", "1"]) == 0
    doc = json.loads((tmp_path / "out" / "batch.json").read_text())
    first, second = doc["scenarios"]
    reason = "could not be played: scenario.xosc: line 240: no chain of roads joins the route's waypoints"
    assert first["error"] == reason
    assert second["error"] is None
    assert {p.name for p in (tmp_path / "out" / "scenario_000").iterdir()} >= {"scenario.xosc", "layers.json"}
    assert "vei-describe-" not in capsys.readouterr().err
