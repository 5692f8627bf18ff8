"""The English a text is written in, where it tells the unit of a bare speed ("doing about 30").

Why: a writer who gives a speed with no unit gives it in the unit of their road signs, and says far
more often which English they speak than which unit they mean. Some words of the road and of daily
life are used only where miles per hour are signed: "quid" is British money, a "bridleway" is a
British right of way, and pelican, puffin and toucan crossings are British signals. A text that uses
one is set where miles per hour are signed. Commoner British words ("pavement", "lorry") are not
used: British test engineers write them and give their speeds in km/h. Ireland says British words
too and signs km/h; its police, the Gardaí, say so first.

Only the unit of a bare speed is read from here, and only where the text states no unit of its own
(:func:`vei_scenario.language.quantities.carried_unit` asks that first).
"""

from __future__ import annotations

#: Words only British or American English use of the road and its traffic (see the module's docstring).
MILES_ENGLISH_WORDS = frozenset({"quid", "bridleway", "bridleways"})
#: Crossings by the names only Britain gives its signal crossings ("the pelican crossing").
_CROSSING_NAMES = frozenset({"pelican", "puffin", "toucan"})
_CROSSINGS = frozenset({"crossing", "crossings"})
#: The Irish police by their own name: a text that names them is set in Ireland, which signs km/h.
_IRISH_POLICE = frozenset({"garda", "gardai", "gardaí"})


def said_in_miles_english(tokens: list[str]) -> bool:
    """Whether the words ``tokens`` (lowercased) are British or American English by a word of the road
    only that English uses ("fifty quid", "along the bridleway", "the pelican crossing"), and
    not set in Ireland ("the gardai"). A pelican that is a bird is none: only a crossing's name counts."""
    if any(t in _IRISH_POLICE for t in tokens):
        return False
    if any(t in MILES_ENGLISH_WORDS for t in tokens):
        return True
    return any(t in _CROSSING_NAMES and nxt in _CROSSINGS for t, nxt in zip(tokens, tokens[1:]))
