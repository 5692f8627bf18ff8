"""A description that names a road user and says what it does is never refused: an unusual noun for
the road user, a verb the reader has no entry for, a passive, codes and IDs around it, or a text typed
in capitals, bullets or a table are read as well as they can be, and what was not used is listed.
Refusal stays where there is no road user at all, or nothing at all says what one does, and it names
what is missing."""

from __future__ import annotations

import pytest
from reading_of import kinds as _kinds

from vei_scenario.cli import main
from vei_scenario.language.reader import read
from vei_scenario.language.reading import NotUnderstood

RIDERS = ("bicycle", "e-scooter")


def _behaviours(text: str) -> list[list[str]]:
    return [[b[0] for b in a.behaviours] for a in read(text).actors]


# --- a road user named by a noun the lexicon lacks ----------------------------------------------------
@pytest.mark.parametrize(
    "text, kinds",
    [
        ("The rider shot off the kerb right in front of us.", [RIDERS]),
        ("Two riders rolled across the road ahead of the test vehicle.", [RIDERS, RIDERS]),
        ("A rider swung out of a side street on our left.", [RIDERS]),
        ("A figure in dark clothes walked out in front of the ego.", [("pedestrian",)]),
        ("Three escooters came along the kerb towards us at dusk.", [RIDERS, RIDERS, RIDERS]),
        ("Some lads on hire scooters zipped across the road ahead of us.", [RIDERS]),
    ],
    ids=["the-rider", "two-riders", "a-rider", "figure-in-clothes", "plural-lemminflect-lacks", "lads-on"],
)
def test_a_road_user_named_by_an_unusual_noun_is_read(text, kinds):
    read_kinds = _kinds(text)
    assert len(read_kinds) == len(kinds), read_kinds
    assert all(k in allowed for k, allowed in zip(read_kinds, kinds)), read_kinds
    assert all(_behaviours(text)), _behaviours(text)


@pytest.mark.parametrize(
    "text",
    [
        "A busker shuffled off the kerb in front of us.",
        "A picnicker hurried across in front of the ego.",
        "A punter stumbled off the kerb outside the pub.",
    ],
    ids=["busker", "picnicker", "punter"],
)
def test_someone_named_by_a_noun_of_who_does_a_verb_walks(text):
    assert _kinds(text) == ["pedestrian"]


def test_a_noun_of_who_does_a_verb_that_drives_is_a_vehicle():
    assert _kinds("A camper pulled out of a side road.")[0] in ("car", "van")


@pytest.mark.parametrize(
    "text",
    [
        "A Lime came hurtling down the pavement and out into the road.",
        "A Bird went straight over the crossing as I pulled up.",
        "Suddenly a Voi, ridden two-up, swerved off the cycle track in front of us.",
    ],
    ids=["a-lime", "a-bird", "a-voi"],
)
def test_a_shared_scooter_named_by_its_operator_is_an_e_scooter(text):
    assert _kinds(text) == ["e-scooter"]


@pytest.mark.parametrize(
    "text, kinds",
    [
        ("A cyclist turned into Lime Street in front of us.", ["bicycle"]),
        ("A bird flew across in front of the ego.", ["pedestrian"]),
        ("A lime green hatchback pulled out of a side road.", ["car"]),
    ],
    ids=["street-name", "lower-case-animal", "colour"],
)
def test_an_operator_word_that_is_no_scooter_stays_what_it_is(text, kinds):
    assert _kinds(text) == kinds


# --- a behaviour said by a verb the reader has no entry for --------------------------------------------
@pytest.mark.parametrize(
    "text, kind",
    [
        ("A lorry nicked our wing mirror on the ring road.", "truck"),
        ("A taxi T-boned us at the crossroads.", "car"),
        ("A delivery van rear-ended the ego at the lights.", "van"),
        ("A cyclist side-swiped the ego.", "bicycle"),
        ("A jogger grazed the ego's mirror.", "pedestrian"),
        ("An e-scooter tapped the test car's bumper.", "e-scooter"),
    ],
    ids=["nicked", "t-boned", "rear-ended", "side-swiped", "grazed", "tapped"],
)
def test_an_unknown_verb_of_contact_gives_a_default_behaviour_not_a_refusal(text, kind):
    reading = read(text)
    assert [a.kind for a in reading.actors] == [kind]
    assert reading.actors[0].behaviours


# A verb the reader has no behaviour for, taking the road user as its object: something was done to it,
# so it was there, in the ego's way.
@pytest.mark.parametrize(
    "text, kind",
    [
        ("Nearly flattened a jogger on the school run.", "pedestrian"),
        ("I nudged a cyclist at the lights this morning.", "bicycle"),
        ("We almost mowed down a scooter rider outside the station.", "e-scooter"),
        ("Ego very nearly skittled a delivery van on the bend.", "van"),
    ],
    ids=["flattened", "nudged", "mowed-down", "skittled"],
)
def test_a_road_user_an_unknown_verb_is_done_to_gets_a_default_behaviour(text, kind):
    reading = read(text)
    assert [a.kind for a in reading.actors] == [kind]
    assert reading.actors[0].behaviours


@pytest.mark.parametrize(
    "text",
    ["A child hotfooted it across the road.", "A pensioner legged it over the zebra.", "A kid legged it."],
    ids=["hotfooted", "legged-it-over", "legged-it"],
)
def test_a_word_in_ed_right_after_its_subject_is_its_deed(text):
    assert _kinds(text) == ["pedestrian"] and _behaviours(text)[0]


@pytest.mark.parametrize(
    "text, kind",
    [
        ("The cyclist got hit by the ego vehicle.", "bicycle"),
        ("A pedestrian was clipped by the test car.", "pedestrian"),
        ("A kid was struck by the ego.", "pedestrian"),
    ],
    ids=["got-hit-by", "was-clipped-by", "was-struck-by"],
)
def test_the_subject_of_a_passive_is_a_road_user_with_a_behaviour(text, kind):
    reading = read(text)
    assert [a.kind for a in reading.actors] == [kind]
    assert reading.actors[0].behaviours


@pytest.mark.parametrize(
    "text, kind",
    [
        ("Sheep on the road, ego at 50 km/h.", "pedestrian"),
        ("Case 7. A child in the road. The ego drives at 30 km/h.", "pedestrian"),
        ("Stray horse on the motorway. Ego at 100 km/h.", "pedestrian"),
    ],
    ids=["sheep-on-the-road", "child-in-the-road", "horse-on-the-motorway"],
)
def test_a_road_user_said_to_be_on_the_road_with_no_verb_stands_there(text, kind):
    reading = read(text)
    assert [a.kind for a in reading.actors] == [kind]
    assert reading.actors[0].behaviours


# --- codes, capitals, bullets and tables round one road user ------------------------------------------
@pytest.mark.parametrize(
    "text, kind",
    [
        ("Ticket 8812-B / ref 31/220 / VIN ZZ9PLURALZA: scooter struck by ego.", "e-scooter"),
        ("LORRY PULLS OUT OF SIDE ROAD EGO BRAKES HARD", "truck"),
        ("* ego 40 km/h\n* cyclist crosses from the left", "bicycle"),
        ("| who | does |\n|---|---|\n| pedestrian | crosses from the right |", "pedestrian"),
    ],
    ids=["codes", "capitals", "bullets", "table"],
)
def test_formatting_and_codes_round_a_road_user_are_read_past(text, kind):
    assert _kinds(text) == [kind]


# --- what must stay refused, or read as no road user --------------------------------------------------
@pytest.mark.parametrize(
    "text, missing",
    [
        ("It was raining on Tuesday.", "road user"),
        ("A bike rack stood next to the bus lane.", "road user"),
        ("A zorblat frobnicates the quux.", "road user"),
        ("There was a cyclist.", "behaviour"),
        ("A tired cyclist.", "behaviour"),
        ("A battered van.", "behaviour"),
        ("A van on a wet Tuesday.", "behaviour"),
        ("A flattened cyclist.", "behaviour"),
        ("Photographed: a van.", "behaviour"),
    ],
    ids=[
        "weather-only",
        "bike-rack",
        "nonsense",
        "only-there",
        "participle-before",
        "participle-of-a-van",
        "no-verb",
        "participle-after-the-article",
        "no-article-after-the-verb",
    ],
)
def test_refused_where_no_road_user_or_no_behaviour_is_found(text, missing):
    with pytest.raises(NotUnderstood) as refused:
        read(text)
    assert refused.value.missing == missing


@pytest.mark.parametrize(
    "text",
    [
        "The ego drives past the scooter bay at 30 km/h.",
        "The ego drives along the bus lane at 40 km/h.",
        "The rider manual lay on the ego's back seat while the ego drove at 50 km/h.",
    ],
    ids=["scooter-bay", "bus-lane", "rider-manual"],
)
def test_a_vehicle_word_naming_a_place_or_thing_is_no_road_user(text):
    assert read(text).actors == []


def test_the_command_line_names_what_is_missing_in_one_line(tmp_path, capsys):
    code = main(["describe", "It was raining on Tuesday.", "-o", str(tmp_path / "out")])
    err = capsys.readouterr().err.strip()
    assert code != 0 and len(err.splitlines()) == 1 and "no road user found" in err
    assert not (tmp_path / "out").exists()
