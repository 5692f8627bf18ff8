"""One hardened XML parser for every file vei-scenario reads (OpenSCENARIO, OpenDRIVE, OSM).

No entity expansion (billion laughs), no DTD loading, no network access (XXE); huge trees stay
disabled. A syntax error becomes a :class:`~vei_scenario.errors.VeiInputError` naming the line.
"""

from __future__ import annotations

import functools
import hashlib
import math
import os
from pathlib import Path

from lxml import etree

from vei_scenario.errors import VeiInputError

#: Parser options that make XML inert: no entity expansion, no DTD, no network, no huge trees. Shared by
#: the tree parser below and the streaming ``etree.iterparse`` of large OSM files.
SAFE_OPTIONS = {"resolve_entities": False, "no_network": True, "load_dtd": False, "huge_tree": False}


def safe_parser(remove_comments: bool = False) -> etree.XMLParser:
    return etree.XMLParser(dtd_validation=False, remove_comments=remove_comments, **SAFE_OPTIONS)


def parse_xml(path: Path | str, remove_comments: bool = False) -> etree._ElementTree:
    """Parse ``path`` safely; refuse documents that declare entities."""
    path = Path(path)
    if not path.is_file():
        raise VeiInputError(path, "", "file not found")
    try:
        tree = etree.parse(str(path), safe_parser(remove_comments))
    except etree.XMLSyntaxError as exc:
        line = exc.lineno if exc.lineno else 0
        msg = exc.msg if hasattr(exc, "msg") else str(exc)
        raise VeiInputError(path, f"line {line}", f"malformed XML: {msg}{json_hint(path)}") from None
    except OSError as exc:
        raise VeiInputError(path, "", f"cannot read: {exc.strerror or exc}") from None
    docinfo = tree.docinfo
    if docinfo.internalDTD is not None and any(True for _ in docinfo.internalDTD.iterentities()):
        raise VeiInputError(path, "line 1", "XML entity declarations are not accepted (entity expansion is disabled)")
    return tree


def json_hint(path: Path) -> str:
    """A hint when the file is JSON (a clip given where a scenario is wanted): which command takes it."""
    try:
        with open(path, "rb") as fh:
            head = fh.read(512).lstrip(b"\xef\xbb\xbf \t\r\n")
    except OSError:
        return ""
    if not head.startswith((b"{", b"[")):
        return ""
    return f" (the file is JSON, not XML: if it is a clip, compile it first: vei compile {path} -o scenario.xosc)"


def content_key(path: Path | str) -> bytes:
    """What a file holds, as a short digest: the key of what is built from it once per process (a
    missing or unreadable file gets an empty key, and its error when it is parsed). The digest is
    read again whenever the file's size, inode, modification or change time differ from the last
    reading (a sweep asks for the same files for every variant; any write changes the change time)."""
    try:
        st = os.stat(path)
    except OSError:
        return b""
    return _digest(str(path), st.st_size, st.st_ino, st.st_mtime_ns, st.st_ctime_ns)


@functools.lru_cache(maxsize=256)
def _digest(path: str, size: int, inode: int, mtime_ns: int, ctime_ns: int) -> bytes:
    try:
        return hashlib.blake2b(Path(path).read_bytes(), digest_size=16).digest()
    except OSError:
        return b""


def float_attribute(path: Path | str | None, el, name: str) -> float:
    """A finite number from attribute ``name`` of ``el``; a VeiInputError naming the line otherwise."""
    try:
        v = float(el.get(name))
    except (TypeError, ValueError):
        raise VeiInputError(
            path, f"line {el.sourceline}", f"<{el.tag}> {name}={el.get(name)!r} is not a number"
        ) from None
    if not math.isfinite(v):
        raise VeiInputError(path, f"line {el.sourceline}", f"<{el.tag}> {name} is not finite")
    return v


def first_element(el):
    """The first child of ``el`` that is an element (comments and processing instructions skipped)."""
    return next((c for c in el if isinstance(c.tag, str)), None)
