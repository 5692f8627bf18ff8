"""A narrator's bare speed stays km/h where the words or the place say km/h is signed.

A first-person story told in words only British roads use ("off the pavement", "my nearside") reads its
bare speeds in mph; words every English of km/h says too ("car park", "pushbike"), a limit that is no
British one or a km/h town's too ("a 50 limit"), a speed no driver means in mph ("doing 100", "at 90") and a
place that signs km/h ("in Nairobi", "in Sydney") keep km/h. Every wording here is written for these
tests (none is from a corpus)."""

from __future__ import annotations

import pytest

from vei_scenario.language.miles_english import told_in_miles_english
from vei_scenario.language.reader import read

MPH = 0.44704
KPH = 1 / 3.6


def _ego(text: str) -> float | None:
    return read(text).ego_speed_mps


@pytest.mark.parametrize(
    "text, kph",
    [
        # finding 1: words said where km/h is signed, and places that sign it
        ("I was doing 80 on Mombasa Road in Nairobi when a lorry swerved into my lane.", 80),
        ("I was doing 100 on the highway in India when a lorry pulled out.", 100),
        ("I was doing 60 in Sydney when a car reversed out of the car park in front of me.", 60),
        ("I was doing 50 in Toronto when a pickup clipped my fender.", 50),
        ("I was doing 100 when a lorry pulled out in front of me.", 100),
        ("I was driving at 90 on the motorway and a lorry moved into my lane.", 90),
        ("We were doing 70 near Kuala Lumpur when a van nudged into us from the nearside.", 70),
        ("I was doing 120 when a van came off the pavement slip lane into my path.", 120),
        # finding 2: a limit no British town is signed with, and a rider's pushbike
        ("In my village there is a 50 limit and I was driving 50 when a tractor pulled out.", 50),
        ("I was riding at 25 on my pushbike when a car pulled out.", 25),
        ("There's an 80 limit on that stretch and I was doing 80 when a deer ran out.", 80),
    ],
    ids=[
        "nairobi-lorry", "india-lorry", "sydney-car-park", "toronto-fender", "doing-100-lorry", "90-lorry",
        "kuala-lumpur-nearside", "doing-120-pavement", "50-limit", "pushbike", "80-limit",
    ],
)  # fmt: skip
def test_km_h_kept(text, kph):
    assert _ego(text) == pytest.approx(kph * KPH, abs=0.05)


@pytest.mark.parametrize(
    "text, mph",
    [
        ("I was doing about 20 when a kid stepped off the pavement right in front of me.", 20),
        ("I was doing about 40 when a van coming the other way clipped my wing mirror.", 40),
        ("It's a 20 limit on our street and I was doing 20 when a cyclist pulled out from the left.", 20),
        ("I was doing 30 in Leeds when a van pulled out on my nearside.", 30),
        ("I was doing about 50 when an artic drifted across into my lane.", 50),
        ("Thirty limit, and I was doing 30 when a boy ran off the pavement.", 30),
        ("I was doing 30 when a lorry pulled out of a side road on my left.", 30),
        ("I was doing 60 in a 40 limit when a car pulled out.", 60),
        ("I was doing 80 on the motorway when a lorry moved into my lane.", 80),
        ("We were doing 25 when a pickup backed into our fender.", 25),
    ],
    ids=[
        "pavement",
        "wing-mirror",
        "20-limit",
        "nearside-leeds",
        "artic",
        "thirty-limit",
        "lorry",
        "40-limit",
        "80-lorry",
        "fender",
    ],  # fmt: skip
)
def test_british_narrators_keep_mph(text, mph):
    assert _ego(text) == pytest.approx(mph * MPH, abs=0.05)


@pytest.mark.parametrize(
    "words, said",
    [
        ("a 20 limit here".split(), True),
        ("the thirty limit".split(), True),
        ("the national speed limit".split(), True),
        ("a 50 limit".split(), False),
        ("a 40 limit".split(), True),
        ("an 80 limit".split(), False),
        ("the lorry pulled out".split(), True),
        ("the car park".split(), False),
        ("my fender".split(), True),
        ("doing 90 and the lorry".split(), False),
        ("on my pushbike".split(), False),
        ("off the pavement".split(), True),
        ("doing 100 off the pavement".split(), False),
        ("doing about 110 on my nearside".split(), False),
        ("ref 2231 off the pavement".split(), True),
    ],
)
def test_told_in_miles_english(words, said):
    assert told_in_miles_english(words) is said


def test_a_km_h_place_keeps_km_h():
    words = "i was doing 30 in nairobi when a kid came off the pavement".split()
    assert not told_in_miles_english(words, "I was doing 30 in Nairobi when a kid came off the pavement.")
    assert told_in_miles_english(words[:5] + words[7:], "I was doing 30 when a kid came off the pavement.")
