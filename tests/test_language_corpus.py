"""The description corpus (tests/data/language_corpus.json, 126 descriptions in several writers' words,
written before the reader was rebuilt): at least 90 % are read and turned into layers that carry what
the text says (checked on three seeds each); every refusal names the words it could not place."""

from __future__ import annotations

from conftest import ROOT
from vei_scenario.language.corpus_check import check_corpus, load_corpus
from vei_scenario.language.rules_backend import layers_from_text

CORPUS = ROOT / "tests" / "data" / "language_corpus.json"


def test_at_least_nine_in_ten_descriptions_are_understood_and_faithful():
    results = check_corpus(load_corpus(CORPUS), layers_from_text)
    assert len(results) >= 120
    faithful = [r for r in results if r.faithful]
    failing = "\n".join(f"{r.text}: {r.problems}" for r in results if not r.faithful)
    assert len(faithful) >= 0.9 * len(results), failing
    for r in results:
        if not r.understood:
            assert "could not place '" in r.problems[0]


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
