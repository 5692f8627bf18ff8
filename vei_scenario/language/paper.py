"""The six descriptions of the LinguaSim evaluation, as this vocabulary writes them (the paper's
own wording is not reproduced; these carry the same scenes), and its reported figures."""

from __future__ import annotations

DESCRIPTIONS = {
    "Force Right Turn": "The ego vehicle goes straight at a crossroad. A car on the left lane turns right "
    "forcefully in front of the ego.",
    "Sudden Stop": "The ego vehicle drives on a straight road behind a car. The car ahead suddenly stops.",
    "Running Red Light": "The ego vehicle goes straight through a crossroad with traffic lights. A car from "
    "the left entrance runs the red light.",
    "Dangerous": "The ego vehicle drives on a straight road. A car in the left lane cuts in aggressively and "
    "very closely in front of the ego and almost hits it.",
    "Moderate": "The ego vehicle drives on a straight road. A car in the left lane cuts in front of the ego "
    "in a decent way.",
    "Safe": "The ego vehicle drives on a straight road. A car in the left lane cuts in remotely in front of the ego.",
}
#: LinguaSim's figures for the cut-in descriptions: mean minimum ACT (s), comfort, crash rate.
PAPER = {
    "Dangerous": (0.072, 0.654, 0.469),
    "Moderate": (0.938, 0.722, 0.0),
    "Safe": (3.532, 0.764, 0.0),
    "Dangerous, refined": (0.214, None, 0.063),
}
