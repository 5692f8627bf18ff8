"""A test's expected result that the ego's systems stay quiet: "Expected result: no FCW, no AEB",
"Then the AEB shall not activate", "no warning shall be issued", "no ACC braking expected", or that
they respond only as in everyday driving: "the ACC shall reduce speed without triggering a collision
warning", "Expected: smooth decel", "the system shall bring the ego to a controlled stop". Not where
an expected result also has the ego warn, brake in an emergency, swerve or hand over ("Expected: a
controlled stop after the FCW"). Keeping a time gap is no such result:
it is how a following test is set up, whatever happens next.

Why: a false-positive test states its outcome this way. The road user is there, does its thing and
is no threat; the case passes when nothing of the ego's reacts. Read as an outcome cue of its own
("unforced": no escape was needed, see :func:`outcome.decide`), it makes the case a safe pass only
where nothing else says the ego had to brake or swerve, nothing came close and nothing was hit: a
requirement that the ego brake ("the SuT shall brake") or a near miss said beside it still wins.

Only an expectation: the sentence, or the label just before it ("Expected result:"), says what is
expected or required. Only the ego's systems and responses: a road user "with no warning" or
"without warning" is a sudden act, and "no driver intervention" or "no driver braking" is how the
test is set up (the system must do the work), not its outcome. "Without warning" alone is a road
user's sudden act too; only "without" a warning of the ego's systems ("without a collision warning",
"without FCW", "without a takeover request") is its quiet."""

from __future__ import annotations

from vei_scenario.language.clauses import split

#: Words that frame a sentence as what is expected of the ego ("Expected result", "Pass criteria",
#: "Then ... shall").
_EXPECTING = frozenset(
    ("expected", "expect", "expects", "expectation", "criteria", "criterion", "shall", "acceptance", "requirement",
     "required", "postcondition", "postconditions")
)  # fmt: skip
#: "Pass" frames an expectation only as a label or a condition ("Pass: ...", "pass if ...", "pass
#: criteria"), not as a verb of passing.
_PASS_FRAMES = frozenset((":", "if", "when", "criteria", "criterion"))
#: Responses of the ego's systems whose absence is the expected result ("braking" only as a system's,
#: with a word of one before it: "no emergency braking", "no AEB braking"; "no braking" alone may be
#: anyone's).
_RESPONSES = frozenset(
    ("fcw", "aeb", "aebs", "warning", "warnings", "intervention", "interventions", "activation", "activations",
     "braking", "takeover", "tor", "alert", "alerts")
)  # fmt: skip
#: Words before "braking" that make it a system's.
_SYSTEM_BRAKING = frozenset(("emergency", "aeb", "automatic", "autonomous", "system", "harsh", "hard", "strong"))
#: Words before "no" that make the response someone else's ("giving no warning", "gave no signal").
_GIVING = frozenset(("giving", "gave", "give", "gives", "with", "without"))
#: What may stand between "no" and the response ("no false activation", "no emergency braking").
_QUALIFIERS = frozenset(
    ("false", "unnecessary", "emergency", "brake", "braking", "system", "aeb", "acc", "fcw", "visual", "acoustic",
     "haptic", "or", "harsh", "hard", "strong", "automatic", "autonomous", "steering")
)  # fmt: skip
#: Verbs of a system's response, denied after "shall not" / "should not" / "must not".
_RESPONDING = frozenset(("activate", "trigger", "intervene", "warn", "brake", "react", "fire", "issue", "alert"))
#: The ego's systems, as the subject of a denied response.
_SYSTEMS = frozenset(
    ("aeb", "aebs", "fcw", "acc", "system", "function", "feature", "ads", "adas", "alks", "planner", "controller",
     "assistant")
)  # fmt: skip
#: Warnings of the ego's systems, after "without" ("without triggering a collision warning", "without
#: FCW", "without a takeover request"); "without warning" alone is anyone's.
_OWN_WARNINGS = frozenset(("collision", "fcw", "aeb", "aebs", "takeover", "take-over", "tor"))
#: Words between "without" and the warning ("without triggering a ...", "without issuing any ...").
_WITHOUT_FILLERS = frozenset(("triggering", "issuing", "raising", "a", "an", "any"))
#: Words that say a response of everyday driving ("smooth decel", "comfortable braking", "a controlled
#: stop", "adapt speed smoothly").
_COMFORTABLE = frozenset(("smooth", "smoothly", "comfortable", "comfortably", "gentle", "gently", "moderate"))
#: Words that say the ego's response was hard after all, in the same sentence.
_HARD = frozenset(("hard", "harsh", "emergency", "full", "abrupt", "abruptly", "sharp", "sharply", "critical"))
#: Words of a response beyond everyday driving (a warning, the emergency brake, an evasive move, a
#: takeover), which, said and not denied beside a smooth one, leave the outcome to the rest of the text.
_BEYOND_EVERYDAY = frozenset(
    ("aeb", "aebs", "fcw", "warning", "warnings", "intervention", "interventions", "activates", "evasive", "swerve",
     "swerves", "swerving", "steer", "steers", "steering", "takeover", "take-over", "tor", "avoid", "avoids",
     "avoiding", "avoidance")
)  # fmt: skip
#: Words that deny the response after them ("no FCW", "without a warning", "not ... takeover").
_DENIALS = frozenset(("no", "without", "not", "never"))
#: Words after a denied response that make it a bound, not its absence ("shall not brake later than 1 s",
#: "shall not brake unless the TTC ...").
_BOUNDS = frozenset(
    ("later", "earlier", "harder", "stronger", "more", "less", "unless", "until", "before", "than", "above", "beyond")
)  # fmt: skip
#: What "nominal" frames as expected ("Nominal outcome", "nominal behaviour").
_OUTCOMES = frozenset(("outcome", "result", "results", "behaviour", "behavior", "response", "reaction"))
#: Words of the ego's response that a word of everyday driving says the manner of ("smooth decel",
#: "a gentle stop", "decelerates smoothly", "adapt speed smoothly"), not of the road or the weather.
_RESPONSE = frozenset(
    ("decel", "deceleration", "decelerate", "decelerates", "decelerating", "braking", "brake", "brakes", "stop",
     "stops", "slow", "slows", "slowing", "slowdown", "reaction", "response", "reduction", "adapt", "adapts",
     "adapting", "reduce", "reduces", "reducing", "speed")
)  # fmt: skip
#: Who may say "expected" of a story ("I expected the car to stop"): then it frames no requirement.
_EXPECTERS = frozenset(("i", "we", "he", "she", "they", "you"))
#: Where a sentence ends (an expectation goes on after a ";": "Expected: a smooth stop; if not, AEB").
_SENTENCE_ENDS = frozenset((".", "!", "?"))


def _beyond_everyday(words: list[str]) -> bool:
    """Whether ``words`` say the ego's response was hard or more than everyday driving (a warning, the
    emergency brake, an evasive move, a takeover), not denied ("no FCW", "without any warning")."""
    if set(words) & _HARD:
        return True
    return any(w in _BEYOND_EVERYDAY and not set(words[max(0, k - 4) : k]) & _DENIALS for k, w in enumerate(words))


def _quiet_said(words: list[str]) -> list[str] | None:
    """The words that say a response of the ego's stays away ("no fcw", "aeb shall not activate"),
    or None."""
    for k, w in enumerate(words):
        if w == "no" and (k == 0 or words[k - 1] not in _GIVING):
            j = k + 1
            while j < len(words) and j <= k + 3 and words[j] in _QUALIFIERS and words[j] not in _RESPONSES:
                j += 1
            if j >= len(words) or words[j] not in _RESPONSES or words[j - 1] == "driver":
                continue
            if words[j] == "braking" and words[j - 1] not in _SYSTEM_BRAKING:
                continue  # ("the lead car continues, no braking": anyone's)
            if words[j + 1 : j + 2] in (["from"], ["by"], ["came"], ["was"]):
                continue  # ("no warning from the car", "no warning came": a road user's, or a story's)
            return words[k : j + 1]
        if w == "without" and not _beyond_everyday(words):  # (not "an emergency stop without a collision warning")
            j = k + 1
            while j < len(words) and j <= k + 3 and words[j] in _WITHOUT_FILLERS:
                j += 1
            if j < len(words) and words[j] in _OWN_WARNINGS:
                return words[k : j + 1]
        if w in ("shall", "should", "must") and words[k + 1 : k + 2] == ["not"]:
            subject = words[max(0, k - 2) : k]
            verb = words[k + 2 : k + 3]
            if set(subject) & _SYSTEMS and verb and verb[0] in _RESPONDING and not set(words[k + 3 : k + 5]) & _BOUNDS:
                return words[max(0, k - 2) : k + 3]
    return None


#: Words of a conflict the ego got out of ("collision avoided", "no contact", "without impact"): said
#: beside a controlled stop, the stop was an escape, a near miss (not a "collision warning").
_CONFLICT = frozenset(("collision", "collisions", "contact", "impact", "crash", "avoided"))


def _conflict_said(words: list[str]) -> bool:
    """Whether ``words`` speak of a conflict, denied or not ("controlled stop, no collision"), other
    than a system named after one ("collision warning", "crash alert", "collision mitigation braking")
    or a time to one ("time to collision stays above 3 s")."""
    return any(
        w in _CONFLICT and not set(words[k + 1 : k + 2]) & _NAMED_AFTER_A_CONFLICT and words[k - 1 : k] != ["to"]
        for k, w in enumerate(words)
    )


#: Words after a conflict's name that make it a system's or a measure's ("collision warning").
_NAMED_AFTER_A_CONFLICT = frozenset(("warning", "warnings", "alert", "alerts", "mitigation", "avoidance", "imminent"))


def _comfort_said(words: list[str]) -> list[str] | None:
    """The words that say the ego responds as in everyday driving ("smooth decel", "a controlled stop",
    "adapt speed smoothly"): a word of everyday manner said of a response, not of the road or the
    weather ("smooth dry asphalt", "moderate rain"), where nothing in the sentence says the ego did more
    (:func:`_beyond_everyday`) or that a conflict was got out of (:func:`_conflict_said`); or None."""
    if _beyond_everyday(words) or _conflict_said(words):
        return None
    for k, w in enumerate(words):
        manner = w in _COMFORTABLE or w == "controlled"
        of_response = words[k + 1 : k + 2] and words[k + 1] in _RESPONSE and words[k + 1] != "speed"
        after_response = w != "controlled" and set(words[max(0, k - 2) : k]) & _RESPONSE
        if manner and (of_response or after_response):
            return words[max(0, k - 2) : k + 2]
    return None


def _framed(words: list[str]) -> bool:
    """Whether ``words`` say what is expected or required of the ego ("Expected result", "Pass criteria",
    "Pass: ...", "the AEB shall not ...")."""
    if any(w in _EXPECTING and not (k and words[k - 1] in _EXPECTERS) for k, w in enumerate(words)):
        return True  # (not a story's "I expected the car to stop")
    if any(w == "nominal" and words[k + 1 : k + 2] and words[k + 1] in _OUTCOMES for k, w in enumerate(words)):
        return True  # ("Nominal outcome: ...", not "nominal 50 km/h" or "Nominal scenario")
    return any(w == "pass" and words[k + 1 : k + 2] and words[k + 1] in _PASS_FRAMES for k, w in enumerate(words))


def no_response_expected(tokens: list[str]) -> str | None:
    """The words of an expected result that the ego's systems stay quiet, or None (see the module).
    ``tokens``: the reader's lowercased tokens, punctuation apart."""
    previous: list[str] = []
    comfort: list[str] | None = None
    more = False  # (whether an expected result says the ego does more than everyday driving)
    for words, _ in split(tokens, _SENTENCE_ENDS):
        framed = _framed(words) or (previous and previous[-1] == ":" and _framed(previous))
        if framed:
            quiet = _quiet_said(words)
            if quiet:
                return " ".join(quiet)
            comfort = comfort or _comfort_said(words)
            more = more or _beyond_everyday(words)
        previous = words
    # (an everyday response in one expected result, and a warning or the AEB in another, is no quiet pass:
    # "Expected: gentle decel behind the van. Pass: FCW and AEB if the van brakes harder")
    return " ".join(comfort) if comfort and not more else None
