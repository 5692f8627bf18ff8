"""Euro NCAP test codes in a test engineer's shorthand ("CCRb 50/50 km/h, 40 m gap, -6 m/s²",
"CPNA-25, VUT 40 km/h, EPTa 5 km/h"), said in words the reader knows.

A code names the target and its configuration (the AEB Car-to-Car, VRU and Motorcycle protocols):
CCRs/CCRm/CCRb a car ahead standing, moving slower, braking; CCFtap the ego turning left across an
oncoming car; CCCscp a car crossing the junction; CCFhol/CCFhos a car head-on in the ego's lane;
CPNA/CPNC(O) an adult/child crossing from the nearside (the right), CPFA from the far side (the
left), CPLA walking along the ego's lane; CBNA(O)/CBFA/CBLA the same for a cyclist; CMRs/CMRb a
motorcycle ahead standing or braking, CMFtap an oncoming motorcycle. The vehicle under test
(VUT) is the ego; the targets (GVT, EPTa/EPTc, EBTa, EMT, "target") are the code's road user,
unless the text names another ("with an e-scooter target"). A speed right after the code is the
ego's (the protocols name a test by the VUT's speed); "50/50 km/h" is the ego's and the target's.
"""

from __future__ import annotations

import re

#: code (lowercase, longest first) → (the target's noun, the configuration in words, "{who}" the target).
CODES: dict[str, tuple[str, str]] = {
    "ccrs": ("car", "a stationary {who} ahead"),
    "ccrm": ("car", "a {who} ahead drives on"),
    "ccrb": ("car", "a {who} ahead brakes hard"),
    "ccftap": ("car", "the ego turns left; an oncoming {who} goes straight on"),
    "cccscp": ("car", "at the junction a {who} comes"),
    "ccfhol": ("car", "an oncoming {who} comes towards the ego in its lane"),
    "ccfhos": ("car", "an oncoming {who} comes towards the ego in its lane"),
    "cpnco": ("child", "a {who} crosses from the nearside"),
    "cpnc": ("child", "a {who} crosses from the nearside"),
    "cpna": ("pedestrian", "a {who} crosses from the nearside"),
    "cpfa": ("pedestrian", "a {who} crosses from the far side"),
    "cpla": ("pedestrian", "a {who} walks along the road ahead"),
    "cplc": ("child", "a {who} walks along the road ahead"),
    "cbnao": ("cyclist", "a {who} crosses from the nearside"),
    "cbna": ("cyclist", "a {who} crosses from the nearside"),
    "cbfa": ("cyclist", "a {who} crosses from the far side"),
    "cbla": ("cyclist", "a {who} rides along the road ahead"),
    "cmrs": ("motorcycle", "a stationary {who} ahead"),
    "cmrb": ("motorcycle", "a {who} ahead brakes hard"),
    "cmftap": ("motorcycle", "the ego turns left; an oncoming {who} goes straight on"),
    "cmfta": ("motorcycle", "the ego turns left; an oncoming {who} goes straight on"),
}
_CODE = re.compile(r"\b(" + "|".join(sorted(CODES, key=len, reverse=True)) + r")(?:-\d+)?(?:-style)?\b")
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
}


def rewrite(text: str, actor_noun) -> str:
    """``text`` (lowercased, units normalised) with its first Euro NCAP code said in words.
    ``actor_noun(word)`` says whether a word names a road user (for "an e-scooter target")."""
    m = _CODE.search(text)
    if m is None:
        return text
    noun, configuration = CODES[m.group(1)]
    named = re.search(r"\b(?:(?:an?|the)\s+)?([a-z][a-z-]*)\s+target\b", text)
    if named and actor_noun(named.group(1)):
        noun = named.group(1)  # ("with an e-scooter target", "adult target walking ...": that one)
        text = text[: named.start()] + f"the {noun}" + text[named.end() :]
    said = configuration.format(who=noun)
    rest = text[m.end() :]
    label = re.match(r"\s*:", rest) is not None
    if label and any(actor_noun(w) for w in re.findall(r"[a-z][a-z-]*", _TARGETS.sub(" ", rest))):
        # "CCRs: the ego approaches a stationary car ...": a label; the text after it says the rest
        rest = re.sub(r"\bthe vehicle\b", "the ego", _TARGETS.sub(f"the {noun}", rest))
        return text[: m.end()] + re.sub(
            rf"\b(vut|ego|{re.escape(noun)})\s+(?=\d+(?:\.\d+)?\s*(?:km/h|mph|m/s))", r"\1 at ", rest
        )
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


def _speed_after(noun: str, text: str) -> str:
    """ "VUT 40 km/h", "the pedestrian 5 km/h": a road user and its speed, said with "at"; a road user
    named right after another's speed starts a new item of the list ("VUT 45 km/h EBTa 15 km/h")."""
    text = re.sub(rf"\b(vut|ego|{re.escape(noun)})\s+(?=\d+(?:\.\d+)?\s*(?:km/h|mph|m/s))", r"\1 at ", text)
    return re.sub(rf"(km/h|mph|m/s)\s+(?=(?:the\s+)?(?:vut|ego|{re.escape(noun)})\b)", r"\1, ", text)
