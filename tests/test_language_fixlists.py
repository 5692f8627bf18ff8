"""Review findings 8-10 of round 29 (code notes):

* the pass speed of a cut-in from behind the ego is decided by one predicate
  (:func:`cut_in.comes_past_first`), which the writer's top speed and the cut-in's compile both ask, on
  where the actor is placed, not on its spawn relation alone;
* word lists that meant the same lived in several modules: the ego's lane's owners, the verbs of
  saying and the hedges of a number are now one list each (:mod:`function_words`), and reading them
  does what it did;
* the docstring of :func:`met_coming.waits_facing` says where a giver of way coming the other way
  waits as the reader has it: a vehicle giving way makes the map a crossroad, so it waits on the
  opposite arm; only with no junction (a rider, a bend) does it stop in its lane, oncoming."""

from __future__ import annotations

import pytest

from vei_scenario.language import function_words, met_coming, motion, out_of_the_lane, owned_by_name, whose_act
from vei_scenario.language.behaviours import cut_in
from vei_scenario.language.behaviours.base import ActorContext
from vei_scenario.language.rules_backend import layers_from_text
from vei_scenario.language.scenario_writer import TYPES, top_speed

CFG = {"gap_m": 6.0, "lane_change_s": 1.5, "lead_s": 2.5}


def _ctx(actor_lane: int = -2, actor_s: float = 80.0, speed: float = 12.0, kind: str = "car") -> ActorContext:
    return ActorContext(
        actor="Adversary1",
        actor_type=kind,
        ego="Ego",
        ego_speed_mps=14.0,
        actor_speed_mps=speed,
        ego_lane_id=-2,
        actor_lane_id=actor_lane,
        actor_road="1",
        actor_s_m=actor_s,
        lanes=2,
        friction=1.0,
        map_kind="straight",
        ego_s_m=100.0,
    )


def _adv(relation: str, kind: str = "car", speed: float = 12.0) -> dict:
    return {
        "name": "Adversary1",
        "type": kind,
        "spawn": {"relation": relation, "longitudinal_m": -20.0},
        "speed_mps": speed,
        "behaviour": {"behaviour": "cut_in", "config": CFG},
    }


# --- 8: one predicate for the cut-in from behind ---------------------------------------------------


def test_one_behind_in_the_ego_s_lane_and_moving_comes_past_first():
    assert cut_in.comes_past_first(_ctx())
    assert not cut_in.comes_past_first(_ctx(actor_lane=-1))  # (in the next lane: a lane change)
    assert not cut_in.comes_past_first(_ctx(actor_s=120.0))  # (ahead of the ego)
    assert not cut_in.comes_past_first(_ctx(speed=0.0))  # (standing: it pulls out as the ego comes)
    across = _ctx()
    across.pulls_out_across = True
    assert not cut_in.comes_past_first(across)


def test_the_top_speed_is_raised_for_the_pass_only_where_the_cut_in_comes_past():
    # a "behind" spawn placed in another lane changes lane as any cut-in does: its kind's usual top
    assert top_speed(_adv("behind"), 14.0, _ctx(actor_lane=-1)) == TYPES["car"][3]
    # one in the ego's lane behind it, whatever its relation was called, gets the pass it compiles
    ctx = _ctx()
    assert top_speed(_adv("left"), 14.0, ctx) >= cut_in.pass_speed_of(ctx, CFG) - 1e-6
    assert top_speed(_adv("behind", "bicycle", 8.0), 14.0, _ctx(speed=8.0, kind="bicycle")) > 14.0


def test_the_pass_compiled_is_the_one_the_top_speed_allows():
    ctx = _ctx(speed=8.0, kind="bicycle")
    ctx.actor_max_speed_mps = top_speed(_adv("behind", "bicycle", 8.0), 14.0, ctx)
    steps = cut_in.compile(ctx, CFG)
    assert steps[0].name == "pull_out"
    wanted = cut_in.pass_speed_of(ctx, CFG)
    assert ctx.reachable(wanted, cut_in.PASS_ACCEL_MPS2)[0] == pytest.approx(wanted)
    # not coming past: no pull-out, and no raised top
    other = _ctx(actor_lane=-1)
    assert cut_in.compile(other, CFG)[0].name == "cut_in"


def test_a_cut_in_from_behind_read_from_text_still_comes_past():
    layers = layers_from_text("A car behind me pulled out and cut in ahead of me. I was doing 40 mph.", 1)
    (adv,) = layers["adversaries"]
    assert adv["spawn"]["relation"] == "behind"


# --- 9: one list each --------------------------------------------------------------------------------


def test_the_ego_s_lane_owners_are_one_list():
    assert out_of_the_lane._EGO_OWNERS is function_words.EGO_LANE_OWNERS
    assert motion._EGO_OWNERS is function_words.EGO_LANE_OWNERS


def test_the_verbs_of_saying_are_one_list():
    assert owned_by_name.REPORTING is function_words.SAYING
    assert whose_act._SAYS is function_words.SAYING


def test_the_hedges_of_a_number_share_their_words():
    from vei_scenario.language import ego_speed, quantities

    for hedges in (quantities._HEDGES, ego_speed._HEDGES, ego_speed._AT_HEDGES, ego_speed._NOTE_HEDGES):
        assert function_words.ABOUT <= hedges


def _first(text: str) -> tuple:
    a = layers_from_text(text, 1)["adversaries"][0]
    node = a["behaviour"]
    names = [n["behaviour"] for n in node.get("sequence", [node])]
    return a["type"], a["spawn"]["relation"], names, a.get("speed_mps")


@pytest.mark.parametrize(
    ("text", "behaviour"),
    [
        ("The van in front of me drifted out of my lane.", "change_lane"),
        ("The bus ahead pulled out of my lane into the right lane.", "change_lane"),
    ],
)
def test_out_of_the_ego_s_lane_still_reads_as_before(text, behaviour):
    assert _first(text)[2][0] == behaviour


@pytest.mark.parametrize(
    ("text", "kmh"),
    [
        ("A cyclist approx. 18 km/h came past me.", 18.0),
        ("Truck ca. 80 km/h overtakes ego at 70 km/h.", 80.0),
        ("Truck ca 80 km/h overtakes ego at 70 km/h.", 80.0),
        ("Truck circa ~80 km/h overtakes ego at 70 km/h.", 80.0),
    ],
)
def test_a_hedged_speed_after_its_noun_still_reads_as_before(text, kmh):
    assert _first(text)[3] == pytest.approx(kmh / 3.6, abs=0.05)


# --- 10: where a giver of way coming the other way waits -----------------------------------------------


@pytest.mark.parametrize(
    ("text", "kind", "map_kind", "relation"),
    [
        ("The oncoming bus waited and waved me on.", "truck", "crossroad", "junction_opposite"),
        ("An oncoming cyclist waited and waved me on.", "bicycle", "straight", "oncoming"),
        ("On the bend the oncoming bus waited and waved me on.", "truck", "curve", "oncoming"),
    ],
)
def test_a_giver_of_way_coming_the_other_way_waits_where_the_docstring_says(text, kind, map_kind, relation):
    layers = layers_from_text(text, 1)
    (a,) = layers["adversaries"]
    assert (a["type"], layers["environment"]["map"]["kind"], a["spawn"]["relation"]) == (kind, map_kind, relation)
    assert a["behaviour"]["behaviour"] == "give_way"


def test_the_waits_facing_docstring_says_a_vehicle_giving_way_makes_a_crossroad():
    doc = " ".join((met_coming.waits_facing.__doc__ or "").split())
    assert "crossroad" in doc and "no junction" in doc
