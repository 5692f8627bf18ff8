"""The ego of a third-person text (a news item, a court report, an incident log): the vehicle the
text follows is the ego, never also listed as another road user, and its speed is the ego's."""

from __future__ import annotations

import pytest

from vei_scenario.language.reader import read


def _kinds(text: str) -> list[str]:
    return [a.kind for a in read(text).actors]


def _ego_kph(text: str) -> float | None:
    mps = read(text).ego_speed_mps
    return None if mps is None else round(mps * 3.6, 1)


# A news report that opens on a driver and goes on with "his"/"her" vehicle and "he"/"she": that
# driver's vehicle is the ego, and a speed said of the driver's pronoun is the ego's.
@pytest.mark.parametrize(
    "text, kinds, kph",
    [
        ("A bus driver has been praised after a girl on a bike rode out of a side road into the path of "
         "his bus. He was going at 15 mph and stopped in time.", ["bicycle"], 24.1),
        ("A lorry driver has been banned after a cyclist was hit by his lorry at a junction. The court "
         "heard he was travelling at 30 mph.", ["bicycle"], 48.3),
        ("A delivery driver escaped injury when a pedestrian walked out in front of her van. She was "
         "doing about 25 mph and braked hard.", ["pedestrian"], 40.2),
        ("A minicab driver was cleared after a girl on an e-scooter swerved across the front of his "
         "taxi. He had been driving at 20 mph.", ["e-scooter"], 32.2),
    ],
)  # fmt: skip
def test_a_driver_a_news_report_follows_through_his_or_her_vehicle_is_the_ego(text, kinds, kph):
    assert _kinds(text) == kinds
    assert _ego_kph(text) == kph


# "him"/"her" placed by another road user is the driver the report opens on: the taxi, not the van.
def test_a_driver_another_road_user_is_placed_by_is_the_ego():
    assert _kinds("A taxi driver was hurt when a van pulled out in front of him on the ring road.") == ["van"]
    assert _kinds("A coach driver was shaken after a lorry came across into her lane near Leeds.") == ["truck"]


# Near misses: a watcher who is no party; a speed said of someone of the other gender; a driver the
# report does not open on.
@pytest.mark.parametrize(
    "text, kinds, kph",
    [
        ("A taxi driver watched as a van doing 40 mph hit a cyclist who came out from the left.",
         ["bicycle"], 64.4),
        ("A bus driver stopped in time when a woman stepped out in front of his bus. She was running at "
         "9 km/h.", ["pedestrian"], None),
        ("A cyclist was hurt when a van driver opened his door into her path. She was riding at 12 mph.",
         ["van"], None),
    ],
)  # fmt: skip
def test_a_driver_the_report_does_not_follow_is_not_the_ego(text, kinds, kph):
    assert _kinds(text) == kinds
    assert _ego_kph(text) == kph
