"""The partners' own tests run through tests/test_osmp.py (their host_alone.py), not collected here."""

collect_ignore = ["test_partners_alone.py"]
