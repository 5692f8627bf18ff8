"""Whose act a verb is, and whether it is an act at all.

A story told by the ego's driver leaves its subject out where it is the narrator ("Had to jump on the
brakes.", "Waited for a gap and passed them wide."): the reader would otherwise give the verb to the
last road user named, and the ego's reaction becomes the road user's extra behaviour (a spurious
hard stop, an overtake of the ego). The grammar says whose it is:

* a sentence whose subject is left out, told in the first person, is the narrator's when its first
  verb (or the modal before it: "had to", "needed to") is in the past tense or the plain form; the
  third person ("Brakes hard.") stays the road user's; a modal said after a clause's verb with
  nothing joining it ("pulled out right in front of me had to brake", "..., had to stamp on the
  brakes") opens such a sentence, as said aloud without a full stop;
* in such a sentence, a reaction (braking, stopping, slowing, swerving) is the narrator's, and so is
  a verb whose object is a road user said before as "him", "her", "them" or "it": whoever does it to
  that road user is not that road user ("passed them wide": the narrator passes, the riders go on).

"The rider" said alone names the road user named before that rides (a cyclist, an e-scooter rider):
read as no one, its verb would go to whoever was the subject last (often the ego, "the SV follows").

A behaviour said as a noun after "no" ("no braking", "no crossing intended", "no overtaking") or as
what an intent or a sign is denied of ("no intention of crossing", "without any sign of stopping")
does not happen: nothing is read of it. (A verb denied, "does not stop", is read by the reader as
what the road user does instead.)
"""

from __future__ import annotations

from collections.abc import Callable

from vei_scenario.language.lemmas import lemmas

#: What a narrator does to keep clear: braking, stopping, slowing, moving aside.
_REACTIONS = frozenset(("sudden_stop", "stop", "change_speed", "cut_in", "change_lane", "cut_out", "give_way"))
#: A road user said again as the object of a verb.
_OBJECT_PRONOUNS = frozenset(("him", "her", "them", "it"))
#: Words between a verb of passing and its object ("went round him", "got past her").
_ROUND = frozenset(("round", "around", "past", "by"))
#: Mentions that name someone: a subject, where one stands first.
_NAMING = frozenset(("actor", "pronoun", "member"))
#: Mentions that hold a sentence's first verb.
_VERB_SLOTS = frozenset(("modal", "unknown_verb", "behaviour", "stationary", "ego_verb", "to_stop"))
#: Nouns of a plan or of the sign of one: what "no" denies in "no intention of crossing".
_INTENT = frozenset(("intent", "intention", "intentions", "sign", "signs", "attempt", "indication", "plan", "wish"))
#: Words between "no" and such a noun ("no real intention", "without any sign").
_BEFORE_INTENT = frozenset(("any", "real", "apparent", "obvious", "clear", "visible"))


def _plain_or_past(word: str) -> bool:
    """Whether ``word`` is a verb in the past tense or the plain form ("had", "slowed", "brake"), not
    the third person ("brakes") nor a participle ("braking"): the forms of a verb whose subject,
    left out in a first-person story, is "I"."""
    verbs = lemmas(word).get("VERB", ())
    if not verbs:
        return False
    return not word.endswith("ing") and (word in verbs or not word.endswith("s"))


def narrators_acts(clauses: list, tokens: list[str], first_person: bool) -> dict[int, bool]:
    """The verbs the narrator does in sentences whose subject is left out, by their mention's start,
    each with whether the narrator passes the road user it names as its object (``tokens``: those
    the mentions index)."""
    out: dict[int, bool] = {}
    if not first_person:
        return out
    bare = False  # (in a sentence with no subject so far, whose first verb is the narrator's form)
    lead_seen = False
    for _, mentions in clauses:
        if not (mentions and mentions[0].slot == "link"):  # (a new sentence: no "then" or "while" before)
            bare, lead_seen = True, False
        acted = False  # (a verb said in this clause so far)
        for k, m in enumerate(mentions):
            if m.slot == "modal" and acted and _run_on(mentions, k):
                bare, lead_seen = True, False  # ("... right in front of me had to brake": a new one)
            if m.slot in _NAMING:
                bare = False
            acted = acted or m.slot in _VERB_SLOTS
            if not bare:
                continue
            if m.slot not in _VERB_SLOTS:
                continue
            if not lead_seen:
                lead_seen = True
                if not _plain_or_past(m.words.split()[0]):
                    bare = False
                    break
            if m.slot != "behaviour":
                continue
            after = tokens[m.end : m.end + 2]
            objected = bool(after) and (
                after[0] in _OBJECT_PRONOUNS
                or (after[0] in _ROUND and after[1:2] != [] and after[1] in _OBJECT_PRONOUNS)
            )
            to_the_ego = any(x.slot == "actor" and x.value == "ego" for x in mentions[k + 1 :])
            if objected or (m.value[0] in _REACTIONS and not to_the_ego):
                out[m.start] = objected and m.value[0] == "overtake"
    return out


def _run_on(mentions: list, k: int) -> bool:
    """Whether the modal at ``mentions[k]``, said after a verb in its clause, opens a clause of its own
    with its subject left out ("pulled out right in front of me had to brake", "..., had to stamp on
    the brakes"): nothing joins it to what came before ("and", "then") and no road user stands right
    before it as its subject ("the cyclist ahead of me had to brake" is the cyclist's)."""
    j = k - 1
    while j >= 0 and mentions[j].slot == "punct" and mentions[j].value == ",":
        j -= 1
    if j < 0:
        return False
    before = mentions[j]
    if before.slot in ("conj", "link", "relative"):
        return False
    return not (before.slot in _NAMING and before.value != "ego")


def not_meant(tokens: list[str], i: int) -> bool:
    """Whether the behaviour word at ``tokens[i]`` is said not to happen as a noun: right after "no"
    ("no braking", "no crossing intended") or as what an intent or its sign is denied of ("no
    intention of crossing", "without any sign of stopping")."""
    if i >= 1 and tokens[i - 1] == "no":
        return True
    j = i - 1
    if j >= 0 and tokens[j] in ("of", "to"):
        j -= 1
    if j < 0 or tokens[j] not in _INTENT:
        return False
    j -= 1
    while j >= 0 and tokens[j] in _BEFORE_INTENT:
        j -= 1
    return j >= 0 and tokens[j] in ("no", "without")


#: Road-user types that are ridden: "the rider" is one of them.
_RIDDEN = frozenset(("bicycle", "e-scooter"))
#: Words before "rider" that say it is one named before ("the rider", "this rider").
_BACK = frozenset(("the", "this", "that"))


def the_rider(tokens: list[str], kind_at: Callable[[list[str], int], tuple[str, int] | None]) -> list[str]:
    """``tokens`` with "the rider" (or "this rider") said as the word of
    the last ridden road user named before it ("a cyclist ... the rider": "the cyclist"), where
    ``kind_at`` (the reader's) reads no road user at that word and one was named. ``kind_at(tokens,
    i)`` gives the road-user type a phrase at ``i`` names and its length."""
    out = list(tokens)
    for i, tok in enumerate(out):
        if tok != "rider" or not i or out[i - 1] not in _BACK or kind_at(out, i) is not None:
            continue
        word, j = None, 0
        while j < i:
            found = kind_at(out, j)
            if found is not None and found[0] in _RIDDEN:
                word = out[j]
            j += found[1] if found is not None else 1
        if word is not None:
            out[i] = word
    return out
