"""Where a road user starts when the text says it only later: one that goes into the rear of the ego
started behind it, even after it was said to travel the same way."""

import pytest

from vei_scenario.language.reader import read


def _relations(text: str) -> list:
    return [a.relation for a in read(text).actors]


@pytest.mark.parametrize(
    "text",
    [
        "A cyclist riding in the same direction went into the rear of my car.",
        "A moped travelling in our direction rode into the rear of our car at 20 mph.",
        "A van heading in the same direction crashed into the rear of our vehicle.",
        "Doing 30 mph, a lorry heading in the same direction ploughed into the rear of my van.",
    ],
)
def test_into_the_rear_of_the_ego_starts_behind(text: str) -> None:
    assert _relations(text) == ["behind"]


@pytest.mark.parametrize(
    "text",
    [
        "A car ahead of us braked and we went into the back of it.",
        "A van in front of me stopped suddenly and I went into the rear of the van.",
        "A cyclist riding in the same direction ahead of me wobbled.",
    ],
)
def test_into_the_rear_of_another_is_not_behind(text: str) -> None:
    assert "behind" not in _relations(text)
