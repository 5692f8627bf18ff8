"""Euro NCAP test codes in a test engineer's shorthand ("CCRb 50/50 km/h, 40 m gap, -6 m/s²",
"CPNA-25, VUT 40 km/h, EPTa 5 km/h"), said in words the reader knows.

A code is read by its grammar, as the AEB Car-to-Car, VRU and Motorcycle protocols (2023, and the
2026 Crash Avoidance ones) build it: "C" (the car under test) + the target's letter + the
configuration. Targets: C a car, P a pedestrian, B a bicyclist, M a motorcyclist; S an e-scooter
(no protocol names one, but writers extend the grammar to it: "CSFA (e-scooter crossing from the far
side)"). Configurations of a vehicle target: Rs/Rm/Rb rear (ahead standing, moving slower, braking),
Ftap front turn across path (the ego turns left across the oncoming target), Cscp crossing straight
crossing path (the target crosses the junction, from either side), Fhos/Fhol front head-on (the
target comes towards the ego in its lane). Configurations of a vulnerable target, whose last letter
says adult (A) or child (C): N nearside (crossing from the right, O: from behind an obstruction), F
far side (from the left), L longitudinal (along the road ahead), TA turning: the ego turns farside
(f, left) or nearside (n, right) into a road the target crosses, walking or riding the same way (s)
as the ego came or the opposite way (o); seen from the ego as it turns, the target then comes from
the left (fs, no) or the right (fo, ns). The reverse tests (CPRs, CPRm: the ego backing up) have no
behaviour here and stay unread. A suffix ("-25", "-50", "-style") is the impact point or a
variation, not a configuration.

The vehicle under test (VUT) is the ego; the targets (GVT, EPTa/EPTc, EBTa, EMT, "target") are the
code's road user, unless the text names another ("with an e-scooter target"). A speed right after
the code is the ego's (the protocols name a test by the VUT's speed); "50/50 km/h" is the ego's and
the target's.
"""

from __future__ import annotations

import re

#: Target letter → the target's noun (a pedestrian's by adult or child: its configuration's last letter).
_TARGET_NOUN = {"c": "car", "m": "motorcycle", "p": "pedestrian", "b": "cyclist", "s": "e-scooter"}
#: A vehicle target's configurations in words ("{who}": the target).
_VEHICLE_CONFIGURATION = {
    "rs": "a stationary {who} ahead",
    "rm": "a {who} ahead drives on",
    "rb": "a {who} ahead brakes hard",
    "ftap": "the ego turns left; an oncoming {who} goes straight on",
    "fta": "the ego turns left; an oncoming {who} goes straight on",
    "cscp": "at the junction a {who} crosses the ego's path",
    "fhos": "an oncoming {who} comes towards the ego in its lane",
    "fhol": "an oncoming {who} comes towards the ego in its lane",
}
#: The side a target crossing the road the ego turns into comes from, as the ego sees it turning.
_TURNING_FROM = {"fs": "left", "fo": "right", "ns": "right", "no": "left"}
_CODE = re.compile(
    r"\bc(?:([cm])(rs|rm|rb|ftap|fta|cscp|fhos|fhol)|([pbs])(?:([nfl])([ac])(o?)|ta([nf]?)([so]?)))"
    r"(?:-\d+)?(?:-style)?\b"
)


def configuration(m: re.Match) -> tuple[str, str]:
    """The target's noun and the configuration said in words ("{who}" the target) of code match ``m``."""
    if m.group(1):
        return _TARGET_NOUN[m.group(1)], _VEHICLE_CONFIGURATION[m.group(2)]
    letter, where, age = m.group(3), m.group(4), m.group(5)
    noun = "child" if letter == "p" and age == "c" else _TARGET_NOUN[letter]
    goes = "walks" if letter == "p" else "rides"
    if where == "n":
        return noun, "a {who} crosses from the nearside"
    if where == "f":
        return noun, "a {who} crosses from the far side"
    if where == "l":
        return noun, f"a {{who}} {goes} along the road ahead"
    turn, way = m.group(7), m.group(8) or "s"  # (turning: the target's way the same as the ego's, unless said)
    if not turn:
        return noun, "the ego turns at the junction; a {who} crosses the road it turns into"
    said = f"the ego turns {'left' if turn == 'f' else 'right'} at the junction; a {{who}} crosses the road it turns"
    return noun, said + f" into from the {_TURNING_FROM[turn + way]}"


#: The protocols' names of their targets.
_TARGETS = re.compile(
    r"\b(?:(?:the|a|an)\s+)?(?:(?:adult|child)\s+)?(?:gvt|evt|soft target|epta|eptc|ept|ebta|ebt|emt|pta|target)\b"
)


#: The words a test line uses for the target its code names.
_SAME_TARGET = {
    "pedestrian": "adult|pedestrian|walker",
    "child": "child|kid",
    "cyclist": "bicyclist|cyclist|bicycle|bike",
    "car": "car|vehicle(?! under)",
    "motorcycle": "motorcycle|motorbike|motorcyclist",
    "e-scooter": "e-scooter|escooter|scooter",
}


def rewrite(text: str, actor_noun) -> str:
    """``text`` (lowercased, units normalised) with its first Euro NCAP code said in words.
    ``actor_noun(word)`` says whether a word names a road user (for "an e-scooter target")."""
    m = _CODE.search(text)
    if m is None:
        return text
    noun, said_as = configuration(m)
    named = re.search(r"\b(?:(?:an?|the)\s+)?([a-z][a-z-]*)\s+target\b", text)
    if named and actor_noun(named.group(1)):
        noun = named.group(1)  # ("with an e-scooter target", "adult target walking ...": that one)
        text = text[: named.start()] + f"the {noun}" + text[named.end() :]
    rest = text[m.end() :]
    gloss = re.match(r"([^:.;\d]*[a-z][^:.;\d]*):", rest)  # (words only: "at VUT 30 km/h:" is no gloss)
    if gloss:  # ("CSFA (e-scooter crossing from the far side): ...", "CBNA style but with an e-scooter: ..."): a
        # gloss of the code, the label of what follows; the road user it names is the target
        noun = next((w for w in re.findall(r"[a-z][a-z-]*", gloss.group(1)) if actor_noun(w)), noun)
        rest = rest[gloss.end() :]
    said = said_as.format(who=noun)
    label = re.match(r"\s*:", rest) is not None
    if label and any(actor_noun(w) for w in re.findall(r"[a-z][a-z-]*", _TARGETS.sub(" ", rest))):
        # "CCRs: the ego approaches a stationary car ...": a label; the text after it says the rest, unless
        # it only lists who goes how fast ("CPFA: VUT 40 km/h, pedestrian target 8 km/h"): then the code
        # says the configuration, said before the list
        rest = re.sub(r"\bthe vehicle\b", "the ego", _TARGETS.sub(f"the {noun}", rest))
        rest = re.sub(rf"\b(vut|ego|{re.escape(noun)})\s+(?=\d+(?:\.\d+)?\s*(?:km/h|mph|m/s))", r"\1 at ", rest)
        if not _only_speeds(rest):
            return text[: m.end()] + rest
        return text[: m.start()] + said + ". " + text[m.start() : m.end()] + rest
    ego = re.match(r"\s*[,:]?\s*(?:at\s+)?(\d+(?:\.\d+)?)(?:\s*/\s*(\d+(?:\.\d+)?))?\s*(km/h|mph|m/s)", rest)
    # ("CCRb 50/50, ...": the pair without its unit, in the protocols' km/h)
    ego = ego or re.match(r"\s*[,:]?\s*(\d+(?:\.\d+)?)\s*/\s*(\d+(?:\.\d+)?)()(?=\s*(?:[,;.]|$))", rest)
    if ego is not None:  # "CCRb 50/50 km/h": the ego's speed, then the target's
        unit = ego.group(3) or "km/h"
        said += f"; the ego drives at {ego.group(1)} {unit}"
        if ego.group(2):
            said += f", the {noun} at {ego.group(2)} {unit}"
        rest = rest[ego.end() :]
    if noun in _SAME_TARGET:  # ("CPFA-50, farside adult running at 8 km/h": the code's target, said again)
        again = r"\b(?:(?:a|an|the)\s+)?(?:target\s+)?(?:(?:farside|nearside|far-side|near-side|longitudinal)\s+)?"
        rest = re.sub(again + rf"(?:{_SAME_TARGET[noun]})(?:\s+target)?\b", f"the {noun}", rest, count=1)
    rest = _TARGETS.sub(f"the {noun}", rest)
    rest = re.sub(r"\bthe vehicle\b", "the ego", rest)  # (the vehicle under test)
    text = text[: m.start()] + said + ", " + rest.lstrip(" ,:;")
    return _speed_after(noun, text)


_SPEED_ITEM = re.compile(r"^(?:[a-z-]+\s+){1,3}(?:at\s+)?\d+(?:\.\d+)?\s*(?:km/h|mph|m/s)$")


def _only_speeds(rest: str) -> bool:
    """Whether the first sentence of ``rest`` (after a code and its colon) only lists road users and
    their speeds, and settings of a word or two ("vut at 40 km/h, the pedestrian 8 km/h, wet"): it
    says nothing of what the target does."""
    sentence = re.split(r"[.;]", rest.lstrip(" :"), maxsplit=1)[0]
    items = [x.strip() for x in sentence.split(",") if x.strip()]
    return any(_SPEED_ITEM.match(x) for x in items) and all(_SPEED_ITEM.match(x) or len(x.split()) <= 2 for x in items)


def _speed_after(noun: str, text: str) -> str:
    """ "VUT 40 km/h", "the pedestrian 5 km/h": a road user and its speed, said with "at"; a road user
    named right after another's speed starts a new item of the list ("VUT 45 km/h EBTa 15 km/h")."""
    text = re.sub(rf"\b(vut|ego|{re.escape(noun)})\s+(?=\d+(?:\.\d+)?\s*(?:km/h|mph|m/s))", r"\1 at ", text)
    return re.sub(rf"(km/h|mph|m/s)\s+(?=(?:the\s+)?(?:vut|ego|{re.escape(noun)})\b)", r"\1, ", text)
