"""The closed classes of English the reader's modules share: articles and other determiners, the
subject pronouns, the forms of "be", and the prepositions and conjunctions that end a phrase or a clause.

They sit in a module of their own, below every reading rule, so that any rule can name them without
importing a reader that may in turn import it: a rule of the outcome reader needs a subject pronoun as
much as the discourse reader does, and the outcome reader is imported by modules the discourse reader
imports.
"""

from __future__ import annotations

#: The articles, one another's forms in a phrase.
ARTICLES = frozenset({"a", "an", "the"})
INDEFINITE = frozenset({"a", "an", "some", "another", "one", "this"})  # ("this guy on a bike": new)
DEFINITE = frozenset({"the", "that", "these", "those"})
POSSESSIVE = frozenset({"my", "our", "his", "her", "their", "its", "your"})
DETERMINERS = INDEFINITE | DEFINITE | POSSESSIVE
FIRST_PERSON = frozenset({"i", "we", "me", "us", "my", "our"})
#: Pronouns that are a clause's subject ("he", not "him").
SUBJECT_PRONOUNS = frozenset({"i", "we", "he", "she", "they", "you"})
#: Words that end a noun phrase after its head: prepositions, conjunctions and relative words ("the
#: pallets lying in the lane": "the pallets").
PHRASE_ENDS = frozenset(("of", "at", "on", "in", "from", "behind", "and", "with", "to", "without", "lying", "which",
                         "that", "who", "before", "after", "as", "while", "by", "for", "ahead"))  # fmt: skip
#: Prepositions that say where someone is ("a man on the pavement", "a girl at the kerb").
WHERE_PREPOSITIONS = frozenset(("on", "at", "by", "in", "near", "beside"))
#: Conjunctions that end a clause, and with it the scope of a negation or a hedge.
CLAUSE_BREAKS = frozenset(
    ("but", "and", "then", "so", "because", "when", "while", "whilst", "until", "till", "although", "though")
)
BE = frozenset({"am", "is", "are", "was", "were", "be", "been", "being", "sat", "sitting"})
#: Words that name a time, not a person: "today's", "Friday's", "this morning's" own nothing on the road.
WORDS_OF_TIME = frozenset(
    ("today", "yesterday", "tomorrow", "tonight", "morning", "afternoon", "evening", "night", "day", "week",
     "weekend", "month", "year", "season", "monday", "tuesday", "wednesday", "thursday", "friday", "saturday",
     "sunday", "spring", "summer", "autumn", "winter", "last", "next")
)  # fmt: skip
#: Words that stand where a noun phrase does but name no one ("there's", "it's", "what's", "here's").
NO_ONE = frozenset(
    ("there", "here", "it", "that", "this", "what", "who", "where", "everyone", "everybody", "someone", "somebody",
     "nobody", "he", "she", "they", "one", "let", "how", "why", "when")
)  # fmt: skip
#: How the ego's lane is said after "out of", "into" and the like: its owner's words before "lane"
#: ("my lane", "the ego's lane", "the ego lane").
EGO_LANE_OWNERS = (("my",), ("our",), ("the", "ego", "'s"), ("ego", "'s"), ("the", "ego"))
#: Verbs of saying that report what follows ("Mem said a lorry braked", "driver states rider was
#: coming"); several are nouns as well ("states", "reports", "says"), so a tagger may miss them as verbs.
SAYING = frozenset(
    {"said", "says", "say", "states", "stated", "reckons", "reckoned", "told", "tells", "reports", "reported",
     "claims", "claimed"}
)  # fmt: skip
#: The words that say a number is only roughly so ("about 40", "roughly 20 m"): every hedge of a
#: number has them (normalise writes "approx.", "circa", "ca.", "est." and "~" before a digit as "about").
ABOUT = frozenset({"about", "around", "roughly", "approximately"})
