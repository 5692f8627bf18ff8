"""The outcome told indirectly or set aside (:mod:`vei_scenario.language.outcome`): an impact told by
its sound alone, a vehicle driven onto the back of another, damage to a vehicle, a collision
threatened as the consequence of an alternative ("brake or they will collide"), named as a risk or
said not to be coming, touching all but done ("only almost hit"), a hedge said alone ("Barely."), the
wheel wrenched away, and a road user said to stay in its place. Wordings written for these tests,
none taken from a corpus; the guards are near wordings that must not take the new readings (a plain
wheel turn, "bang on 30", "onto the shoulder", the ego's hard brake beside a road user kept in lane,
a rider hurt in a fall of their own)."""

from __future__ import annotations

import pytest

from tests.test_language_outcome import _case, _intent
from vei_scenario.language.rules_backend import layers_from_text

# an impact said by its sound as a sentence of its own; a car driven onto the back of another; damage
# to a vehicle or a part of one: a collision
TOLD_INDIRECTLY = {
    "collision": [
        "The lorry ahead braked for nothing at all. I braked too. Thud. I sat there swearing.",
        "A taxi stopped dead in front of my van. BANG! My dashcam caught it all.",
        "The estate car in front stopped sharply and I slid up onto the back of it on the ice.",
        "Car 2 halted at the lights and car 1 ran up onto the rear of car 2 at about 20 km/h.",
        "A cyclist swung out round a pothole at the lights. Slight damage to my nearside wing, cyclist fine.",
        "The van reversed out of a driveway and left a dent in my passenger door.",
        "A girl on a scooter misjudged the gap and went into the front passenger door.",
    ],
}
# a collision threatened as the consequence of an alternative, or named as a risk of the place: no
# collision happened; a test that rates its scenario critical stays critical
THREATENED = {
    "critical": [
        "Critical scenario: a cyclist crosses 2 s ahead of the ego; the ego must brake or they will collide.",
    ],
    "near_miss": [
        "A van pulled out of the side road and I had to brake hard or we would collide.",
    ],
}
NAMED_AS_A_RISK = [
    "Summary: there is a risk of head-on collisions on this stretch. A van pulled out ahead of me.",
    "The danger of a crash here is high, says the council. A bus pulls in ahead of the ego.",
]
# touching all but done, a hedge alone after the event, the wheel wrenched away: a near miss
ALL_BUT = {
    "near_miss": [
        "A bus came the other way on the narrow bridge, our mirrors almost touching.",
        "The bike squeezed through the gap, handlebars nearly brushing my door.",
        "A scooter shot across the lights in front of me. He got away with it. Barely.",
        "A van came at me on my side of the road and I wrenched the wheel to the left.",
        "The kid ran out after his ball and I yanked the steering wheel over.",
        "A moped shot the red right in front of me, I braked, almost hit.",
        "A courier came out of the car park and I had to brake to avoid a collision. Cause: failure to give way.",
    ],
}
# a road user said to stay in its place, and a collision said not to be coming: a safe pass
STAYED_OUT = {
    "safe": [
        "The emergency braking fired for a cyclist on the hard shoulder. The cyclist never left the shoulder.",
        "A jogger runs along the footway beside the test car and does not enter the road.",
        "The assistant braked although a crash was not going to happen; there was no danger at all.",
    ],
}
# guards: a plain wheel turn, a hedge that is a speed, a sound that is a word of a sentence, a word
# of damage that is hypothetical or denied, an ordinary "onto" of a place, and the outcomes the
# reader already read
GUARDS = {
    None: [
        "I turned the wheel and went left into the side road while a cyclist waited.",
    ],
    "near_miss": [
        "A cyclist swerved out and I nearly hit him.",
        "A lad ran across; I did not hit him but I braked really hard.",
        "A scooter pulled out and I hit the brakes hard.",
        "A bus pulled out and it could have caused real damage to my car.",
        "A van pulled out, I braked hard, the van never left its lane.",
        "A scooter came off the kerb and I stopped a foot from him. He fell off, he's fine, just scraped up.",
    ],
    "collision": [
        "Bang on 30 mph a cyclist pulled out and I hit him.",
        "The car in front stopped and I went into the back of it.",
    ],
    "safe": [
        "A van pulled onto the shoulder of the road and waited while I passed, no damage to anything.",
    ],
}


@pytest.mark.parametrize("text,intent", _case(TOLD_INDIRECTLY))
def test_contact_told_indirectly(text: str, intent: str) -> None:
    assert _intent(text) == intent


@pytest.mark.parametrize("text,intent", _case(THREATENED))
def test_threatened_collision_is_no_contact(text: str, intent: str) -> None:
    assert layers_from_text(text, 0)["intent"] == intent


@pytest.mark.parametrize("text", NAMED_AS_A_RISK)
def test_collision_named_as_a_risk_is_no_contact(text: str) -> None:
    assert _intent(text) != "collision"


@pytest.mark.parametrize("text,intent", _case(ALL_BUT))
def test_all_but_a_contact(text: str, intent: str) -> None:
    assert _intent(text) == intent


@pytest.mark.parametrize("text,intent", _case(STAYED_OUT))
def test_road_user_that_stayed_out_of_the_way(text: str, intent: str) -> None:
    assert _intent(text) == intent


@pytest.mark.parametrize("text,intent", _case(GUARDS))
def test_guards_keep_their_reading(text: str, intent: str | None) -> None:
    assert _intent(text) == intent
