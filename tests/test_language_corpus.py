"""The description corpus (tests/data/language_corpus.json, 126 descriptions in several writers' words,
written before the reader was rebuilt): at least 90 % are read and turned into layers that carry what
the text says (checked on three seeds each); every refusal names what is missing."""

from __future__ import annotations

import pytest

from conftest import ROOT
from vei_scenario.language.corpus_check import check_corpus, load_corpus
from vei_scenario.language.rules_backend import layers_from_text

CORPUS = ROOT / "tests" / "data" / "language_corpus.json"
#: 28 more, written after the reader was rebuilt and measured before anything was changed for them
#: (first measurement: 20 faithful, 71 %; see the README).
HELD_OUT = ROOT / "tests" / "data" / "language_heldout.json"
#: 40 more in new wording, many asking for behaviours the library did not have yet (left turn across
#: the path, pulling out of a side road, giving way, walking or riding along the road, wrong-way
#: driving, cut-out, parked occluders); first measured before those were built: 8 faithful (20 %).
HELD_OUT_2 = ROOT / "tests" / "data" / "language_heldout2.json"
#: 20 more, written once those behaviours existed and measured before anything was changed for them:
#: 18 understood, 15 faithful (75 %).
HELD_OUT_3 = ROOT / "tests" / "data" / "language_heldout3.json"
CORPORA = [CORPUS, HELD_OUT, HELD_OUT_2, HELD_OUT_3]


@pytest.mark.parametrize("corpus", CORPORA, ids=["corpus", "held-out", "held-out-2", "held-out-3"])
def test_at_least_nine_in_ten_descriptions_are_understood_and_faithful(corpus):
    results = check_corpus(load_corpus(corpus), layers_from_text)
    assert len(results) >= {CORPUS: 120, HELD_OUT: 25, HELD_OUT_2: 40, HELD_OUT_3: 20}[corpus]
    faithful = [r for r in results if r.faithful]
    failing = "\n".join(f"{r.text}: {r.problems}" for r in results if not r.faithful)
    assert len(faithful) >= 0.9 * len(results), failing
    for r in results:
        if not r.understood:  # (refused only for a missing road user or behaviour, said as such)
            assert r.problems[0].startswith(("no road user found", "no behaviour found"))


#: Written independently by writers who never saw the reader (requests, chat, test-spec lines, police,
#: insurance and radio narratives, long stories, lists, learners' English, typos). The figures first
#: measured on each, before the reader was changed for it, are in benchmarks/language_corpus.py (FIRST;
#: ``--all`` prints them beside today's); G, J, K, N, O, P, Q, T, U, V, W, X, Y and Z3
#: to Z26 were kept sealed until the reader's last change and measured after it. The floors are the figures
#: measured last:
#: (understood, faithful).
INDEPENDENT = {
    ROOT / "tests" / "data" / "language_independent_a.json": (59, 59),
    ROOT / "tests" / "data" / "language_independent_b.json": (63, 62),
    ROOT / "tests" / "data" / "language_independent_c.json": (65, 61),
    ROOT / "tests" / "data" / "language_independent_d.json": (56, 55),
    ROOT / "tests" / "data" / "language_independent_e.json": (70, 68),
    ROOT / "tests" / "data" / "language_independent_f.json": (60, 57),
    ROOT / "tests" / "data" / "language_independent_g.json": (60, 56),
    ROOT / "tests" / "data" / "language_independent_h.json": (50, 48),
    ROOT / "tests" / "data" / "language_independent_i.json": (50, 46),
    ROOT / "tests" / "data" / "language_independent_j.json": (45, 44),
    ROOT / "tests" / "data" / "language_independent_k.json": (45, 41),
    ROOT / "tests" / "data" / "language_independent_l.json": (50, 47),
    ROOT / "tests" / "data" / "language_independent_m.json": (50, 44),
    ROOT / "tests" / "data" / "language_independent_n.json": (45, 35),
    ROOT / "tests" / "data" / "language_independent_o.json": (45, 30),
    ROOT / "tests" / "data" / "language_independent_p.json": (45, 36),
    ROOT / "tests" / "data" / "language_independent_q.json": (45, 39),
    ROOT / "tests" / "data" / "language_independent_r.json": (50, 44),
    ROOT / "tests" / "data" / "language_independent_s.json": (50, 44),
    ROOT / "tests" / "data" / "language_independent_t.json": (45, 37),
    ROOT / "tests" / "data" / "language_independent_u.json": (45, 39),
    ROOT / "tests" / "data" / "language_independent_v.json": (50, 38),
    ROOT / "tests" / "data" / "language_independent_w.json": (50, 39),
    ROOT / "tests" / "data" / "language_independent_x.json": (50, 40),
    ROOT / "tests" / "data" / "language_independent_y.json": (50, 36),
    ROOT / "tests" / "data" / "language_independent_z3.json": (50, 24),
    ROOT / "tests" / "data" / "language_independent_z4.json": (50, 16),
    ROOT / "tests" / "data" / "language_independent_z5.json": (50, 27),
    ROOT / "tests" / "data" / "language_independent_z6.json": (50, 28),
    ROOT / "tests" / "data" / "language_independent_z7.json": (50, 19),
    ROOT / "tests" / "data" / "language_independent_z8.json": (50, 20),
    ROOT / "tests" / "data" / "language_independent_z9.json": (50, 34),
    ROOT / "tests" / "data" / "language_independent_z10.json": (50, 24),
    ROOT / "tests" / "data" / "language_independent_z11.json": (50, 24),
    ROOT / "tests" / "data" / "language_independent_z12.json": (50, 19),
    ROOT / "tests" / "data" / "language_independent_z13.json": (50, 10),
    ROOT / "tests" / "data" / "language_independent_z14.json": (50, 39),
    ROOT / "tests" / "data" / "language_independent_z15.json": (50, 23),
    ROOT / "tests" / "data" / "language_independent_z16.json": (50, 22),
    ROOT / "tests" / "data" / "language_independent_z17.json": (50, 14),
    ROOT / "tests" / "data" / "language_independent_z18.json": (50, 19),
    ROOT / "tests" / "data" / "language_independent_z19.json": (50, 5),
    ROOT / "tests" / "data" / "language_independent_z20.json": (50, 32),
    ROOT / "tests" / "data" / "language_independent_z21.json": (50, 15),
    ROOT / "tests" / "data" / "language_independent_z22.json": (50, 19),
    ROOT / "tests" / "data" / "language_independent_z23.json": (50, 13),
    ROOT / "tests" / "data" / "language_independent_z24.json": (50, 12),
    ROOT / "tests" / "data" / "language_independent_z25.json": (50, 20),
    ROOT / "tests" / "data" / "language_independent_z26.json": (50, 18),
    ROOT / "tests" / "data" / "language_independent_z27.json": (50, 12),
    ROOT / "tests" / "data" / "language_independent_z28.json": (50, 13),
    ROOT / "tests" / "data" / "language_independent_z29.json": (50, 8),
    ROOT / "tests" / "data" / "language_independent_z30.json": (49, 5),
    ROOT / "tests" / "data" / "language_independent_z31.json": (50, 11),
    ROOT / "tests" / "data" / "language_independent_z32.json": (50, 7),
    ROOT / "tests" / "data" / "language_independent_z33.json": (50, 17),
    ROOT / "tests" / "data" / "language_independent_z34.json": (50, 6),
    ROOT / "tests" / "data" / "language_independent_z35.json": (49, 15),
    ROOT / "tests" / "data" / "language_independent_z36.json": (50, 19),
    ROOT / "tests" / "data" / "language_independent_z37.json": (49, 11),
    ROOT / "tests" / "data" / "language_independent_z38.json": (50, 3),
    ROOT / "tests" / "data" / "language_independent_z39.json": (50, 12),
    ROOT / "tests" / "data" / "language_independent_z40.json": (50, 4),
    ROOT / "tests" / "data" / "language_independent_z41.json": (50, 7),
    ROOT / "tests" / "data" / "language_independent_z42.json": (50, 19),
    ROOT / "tests" / "data" / "language_independent_z43.json": (50, 8),
    ROOT / "tests" / "data" / "language_independent_z44.json": (50, 15),
    ROOT / "tests" / "data" / "language_independent_z45.json": (50, 11),
    ROOT / "tests" / "data" / "language_independent_z46.json": (50, 20),
    ROOT / "tests" / "data" / "language_independent_z47.json": (50, 7),
    ROOT / "tests" / "data" / "language_independent_z48.json": (50, 17),
    ROOT / "tests" / "data" / "language_independent_z49.json": (50, 14),
    ROOT / "tests" / "data" / "language_independent_z50.json": (50, 8),
    ROOT / "tests" / "data" / "language_independent_z51.json": (50, 18),
    ROOT / "tests" / "data" / "language_independent_z52.json": (50, 13),
    ROOT / "tests" / "data" / "language_independent_z53.json": (50, 15),
    ROOT / "tests" / "data" / "language_independent_z54.json": (50, 8),
    ROOT / "tests" / "data" / "language_independent_z55.json": (50, 16),
    ROOT / "tests" / "data" / "language_independent_z56.json": (50, 14),
    ROOT / "tests" / "data" / "language_independent_z57.json": (50, 16),
    ROOT / "tests" / "data" / "language_independent_z58.json": (50, 18),
    ROOT / "tests" / "data" / "language_independent_z59.json": (50, 13),
    ROOT / "tests" / "data" / "language_independent_z60.json": (50, 13),
    ROOT / "tests" / "data" / "language_independent_z61.json": (50, 1),
    ROOT / "tests" / "data" / "language_independent_z62.json": (50, 11),
    ROOT / "tests" / "data" / "language_independent_z63.json": (50, 1),
    ROOT / "tests" / "data" / "language_independent_z64.json": (50, 6),
    ROOT / "tests" / "data" / "language_independent_z65.json": (48, 11),
    ROOT / "tests" / "data" / "language_independent_z66.json": (48, 4),
    ROOT / "tests" / "data" / "language_independent_z67.json": (48, 21),
    ROOT / "tests" / "data" / "language_independent_z68.json": (48, 6),
    ROOT / "tests" / "data" / "language_independent_z69.json": (48, 12),
    ROOT / "tests" / "data" / "language_independent_z70.json": (48, 2),
}


@pytest.mark.parametrize(
    "corpus",
    sorted(INDEPENDENT),
    ids=[f"independent-{c.stem.rsplit('_', 1)[1]}" for c in sorted(INDEPENDENT)],
)
def test_independent_corpora_stay_at_their_measured_figures(corpus):
    results = check_corpus(load_corpus(corpus), layers_from_text)
    understood, faithful = INDEPENDENT[corpus]
    assert sum(r.understood for r in results) >= understood
    assert sum(r.faithful for r in results) >= faithful


def test_a_case_that_is_not_met_is_reported_with_its_reasons():
    """The checker itself: a wrong expectation is caught and explained."""
    case = {
        "text": "A car in the left lane cuts in aggressively.",
        "actors": [{"type": "truck", "behaviours": ["overtake"]}],
        "ego_speed_kph": 200,
    }
    [r] = check_corpus([case], layers_from_text, seeds=(0,))
    assert r.understood and not r.faithful
    assert any("ego speed" in p for p in r.problems) and any("type car (expected truck)" in p for p in r.problems)


def test_an_actor_whose_behaviour_the_text_does_not_settle_is_checked_on_the_rest():
    """An expectation may leave out what the road user does (a target standing in the lane): its type
    and start are still checked, and any behaviour is accepted."""
    text = "A cyclist rides along the kerb ahead of the ego."
    [fits] = check_corpus([{"text": text, "actors": [{"type": "bicycle"}]}], layers_from_text, seeds=(0,))
    assert fits.faithful, fits.problems
    [wrong] = check_corpus(
        [{"text": text, "actors": [{"type": "bicycle", "relation": ["oncoming"]}]}], layers_from_text, seeds=(0,)
    )
    assert not wrong.faithful and any("relation" in p for p in wrong.problems)


def test_every_description_gives_a_scenario_that_can_be_written():
    """Whatever the reading, the layers place every actor on the map: no description of the corpus
    ends in a placement error (seed 0 of each; the files are not kept)."""
    from vei_scenario.language.scenario_writer import write_scenario

    failures = []
    for corpus in CORPORA:
        for case in load_corpus(corpus):
            try:
                write_scenario(layers_from_text(case["text"], 0), "scenario")
            except ValueError as exc:
                failures.append(f"{case['text']}: {exc}")
    assert not failures, "\n".join(failures)


def test_the_played_scenarios_do_what_their_layers_say(tmp_path):
    """Every fourth description of the corpus, written and played by vei run (seed 0): at least nine
    in ten adversaries do what their layers say, judged from the trajectories."""
    from vei_scenario.language.corpus_check import play_case

    cases = load_corpus(CORPUS)[::4] + load_corpus(HELD_OUT_2)[::2] + load_corpus(HELD_OUT_3)[::2]
    failing = {c["text"]: p for c in cases if (p := play_case(c, layers_from_text, tmp_path))}
    assert len(failing) <= 0.1 * len(cases), failing


#: One description per behaviour that the library gained with held-out-2, in words of their own.
NEW_BEHAVIOURS = {
    "turn_across": "At the crossroads an oncoming car turns left across our path.",
    "turn_into": "A van waiting in the side road on the left pulls out into our road ahead of us.",
    "give_way": "A lorry approaching from the side road on the right gives way to the ego.",
    "give_way_kerb": "A woman at the kerb on the right waits for us to pass and then crosses behind us.",
    "along_road": "A cyclist rides towards the ego along the edge of its lane.",
    "wrong_way": "A ghost driver comes towards us in our lane and swerves back to its own side.",
    "wrong_way_drift": "An oncoming truck drifts into our lane and then returns to its lane.",
    "cut_out": "The car in front swerves into the left lane to avoid a stopped van in our lane.",
    "parked": "A child steps out from behind a parked van on the nearside.",
}


@pytest.mark.parametrize("name", sorted(NEW_BEHAVIOURS))
def test_each_behaviour_happens_when_played(name, tmp_path):
    """Written, played by vei run and judged from the trajectories on three seeds: each does what it
    says (turns within 3 m of the ego's path, stands and is not hit while giving way, keeps to the
    ego's lane head-on, leaves the lane ...), and no background vehicle collides."""
    from vei_scenario.language.corpus_check import play_case
    from vei_scenario.language.layers import behaviour_nodes

    layers = layers_from_text(NEW_BEHAVIOURS[name], 0)
    said = {n["behaviour"] for a in layers["adversaries"] for _, n in behaviour_nodes(a["behaviour"])}
    wanted = {"parked": "cross_in_front", "give_way_kerb": "give_way"}.get(name, name.split("_drift")[0])
    assert wanted in said, said
    for seed in (0, 1, 2):
        assert play_case({"text": NEW_BEHAVIOURS[name]}, layers_from_text, tmp_path, seed) == [], seed


@pytest.mark.parametrize(
    "text",
    [
        "A parked car on the right pulls out into the ego's lane.",
        "A car from the left at 130 km/h cuts in front of us.",
    ],
    ids=["standing", "faster"],
)
def test_a_cut_in_by_a_standing_or_a_faster_car_happens(text, tmp_path):
    """A parked car pulls out (speeding up as it changes lane, timed from the ego's approach); a car
    faster than the ego draws ahead first and cuts in once it is gap_m ahead: either ends ahead of
    the ego in its lane."""
    from vei_scenario.language.corpus_check import play_case

    assert play_case({"text": text}, layers_from_text, tmp_path) == []


@pytest.mark.parametrize(
    "text, expected",
    [
        # what is said of the ego as an object ("towards us") stays with the actor it was said of
        (
            "A ghost driver comes towards us in our lane while a cyclist rides along the kerb ahead.",
            [("car", "wrong_way", "oncoming", None), ("bicycle", "along_road", "ahead", None)],
        ),
        # the passive: the doer follows "by"
        ("The AV gets cut off by a van from the right lane.", [("van", "cut_in", "right", None)]),
        # two subjects joined by "and" share the verb
        (
            "A boy and a girl run across from the far side.",
            [("pedestrian", "cross_in_front", "roadside_left", None)] * 2,
        ),
        # the ego's own view: what it follows is ahead of it
        (
            "Following a lorry, it swerves out to the left, revealing a stalled car.",
            [("truck", "cut_out", "ahead", None), ("car", "stop", "ahead", None)],
        ),
    ],
    ids=["towards-us", "passive", "joined", "following"],
)
def test_constructions_are_read_for_who_does_what(text, expected):
    from vei_scenario.language.reader import read

    got = [(a.kind, a.behaviours[0][0] if a.behaviours else None, a.relation, a.facing) for a in read(text).actors]
    assert got == expected


def test_word_salad_of_the_lexicon_is_read_or_refused_never_broken():
    """600 random strings of the lexicon's own phrases, numbers and units (seeded): each is refused
    with a ValueError, or read into layers that pass the schema and can be written."""
    import random

    from vei_scenario.language import lexicon as lex
    from vei_scenario.language.layers import schema_problems
    from vei_scenario.language.scenario_writer import write_scenario

    phrases = [
        w for group in (lex.BEHAVIOUR_VERBS, lex.RELATIONS, lex.SIDES, lex.TURNS) for ws in group.values() for w in ws
    ]
    phrases += [w for ws in lex.ACTOR_NOUNS.values() for w in ws] + list(lex.CAR_NOUNS) + list(lex.EGO_NOUNS)
    phrases += list(lex.STATIONARY) + list(lex.WRONG_WAY) + list(lex.RETURNS) + list(lex.SIDE_ROAD_EXITS)
    phrases += ["a", "the", "and", "then", "while", "until", "by", "is", "it", "two", "one", "the other", ",", "."]
    phrases += ["at 50 km/h", "30 m", "0 km/h", "500 km/h", "1e9 m", "following", "junction", "roundabout"]
    rng = random.Random(7)
    for i in range(600):
        text = " ".join(rng.choice(phrases) for _ in range(rng.randint(1, 25)))
        try:
            layers = layers_from_text(text, i)
        except ValueError:
            continue
        assert schema_problems(layers) == [], text
        try:
            write_scenario(layers, "scenario")
        except ValueError as exc:  # a placement the map cannot hold: refused with its reason
            assert str(exc), text


@pytest.mark.parametrize(
    "text, named",
    [
        ("A zorblat frobnicates the quux.", "no road user found (name one: the ego, a pedestrian"),
        ("The zorblat frobnicates the quux.", "words not used: 'zorblat', 'frobnicates', 'quux'"),
    ],
    ids=["nothing-readable", "words-named"],
)
def test_a_description_with_nothing_to_hold_is_refused_by_name(text, named):
    from vei_scenario.language.reading import NotUnderstood

    with pytest.raises(NotUnderstood) as err:
        layers_from_text(text, 0)
    assert named in str(err.value)


def test_more_road_users_than_a_scenario_holds_keeps_those_that_act_and_names_the_rest():
    """A text naming more road users than a scenario holds is read, not refused: the ones that do
    something are kept first, in the order named, and the rest are said to be not used."""
    from vei_scenario.language.layers import schema_problems
    from vei_scenario.language.reader import MAX_ACTORS, read

    r = read("a car cuts in " * 50)
    assert len(r.actors) == MAX_ACTORS
    assert any("50 road users, a scenario holds 8: car (42)" in w for w in r.ignored)
    text = (
        "I was doing 25 mph past a parked van, a parked lorry, a parked bus, a parked taxi, a parked car, "
        "a parked pickup, a parked minibus and a parked camper when a cyclist pulled out in front of me "
        "and an e-scooter rider crossed from the right."
    )
    r = read(text)
    kinds = [a.kind for a in r.actors]
    assert len(kinds) <= MAX_ACTORS and "bicycle" in kinds and "e-scooter" in kinds, kinds
    assert any(w.startswith("10 road users, a scenario holds 8: ") for w in r.ignored), r.ignored
    assert schema_problems(layers_from_text(text, 0)) == []


@pytest.mark.parametrize(
    "spec",
    [
        {"kind": "straight", "lanes_per_direction": 3},
        {"kind": "curve", "lanes_per_direction": 1, "curve_radius_m": 90.0},
        {"kind": "crossroad", "lanes_per_direction": 2, "traffic_signals": False},
        {"kind": "roundabout", "lanes_per_direction": 2},
    ],
    ids=["straight", "curve", "crossroad", "roundabout"],
)
def test_the_map_layout_known_before_writing_is_the_written_maps(spec):
    """Background traffic and junction timing are placed from maps.layout before any road is built:
    it must describe the map build_map then writes (road lengths, the feature's s, the arms)."""
    from vei_scenario.language import maps

    assert maps.layout(spec) == maps.build_map(spec)[1]


def test_a_road_user_ahead_facing_the_ego_counts_as_oncoming():
    """The layers place a wrong-way rider ahead in the ego's lane facing it; the format calls that start
    oncoming. One ahead going the ego's way is not."""
    towards = "An e-scooter rides the wrong way in the ego's lane towards the ego."
    layers = layers_from_text(towards, 0)
    assert layers["adversaries"][0]["spawn"] == {
        **layers["adversaries"][0]["spawn"],
        "relation": "ahead",
        "facing": "against",
    }
    want = {"type": "e-scooter", "relation": ["oncoming"]}
    [r] = check_corpus([{"text": towards, "actors": [want]}], layers_from_text, seeds=(0,))
    assert r.faithful, r.problems
    [r] = check_corpus(
        [{"text": "A cyclist rides ahead of the ego.", "actors": [{**want, "type": "bicycle"}]}],
        layers_from_text,
        seeds=(0,),
    )
    assert not r.faithful and any("relation ahead" in p for p in r.problems)
