"""Normalise OpenDRIVE documents before writing them: same input, same bytes.

netconvert and scenariogeneration both stamp the wall-clock time into the header (and netconvert its
whole configuration, with temporary paths, into a comment). Here comments go, the header date becomes
the clip's recording time (or is left out), the ``geoReference`` carries the scenario projection, and
paramPoly3 lengths are repaired (:mod:`vei_scenario.roads.opendrive_repair`).
"""

from __future__ import annotations

from lxml import etree

from vei_scenario.roads.opendrive_repair import repair_parampoly3_lengths
from vei_scenario.safe_xml import safe_parser


def finalize_opendrive(
    xodr: bytes | etree._Element,
    name: str,
    proj_string: str | None,
    date: str | None,
    bounds: tuple[float, float, float, float] | None = None,
) -> bytes:
    """Normalised OpenDRIVE bytes. ``bounds`` (west, south, east, north in metres) replaces a header
    extent that is missing or all zero, as scenariogeneration leaves it."""
    root = etree.fromstring(xodr, safe_parser(remove_comments=True)) if isinstance(xodr, bytes) else xodr
    repair_parampoly3_lengths(root)
    for c in root.xpath("//comment()"):
        c.getparent().remove(c)
    for empty in root.xpath("//road/elevationProfile[not(*)] | //road/lateralProfile[not(*)]"):
        empty.getparent().remove(empty)  # (scenariogeneration writes them; the XSD wants content)
    header = root.find("header")
    if header is None:
        raise ValueError("OpenDRIVE document without <header>")
    header.set("name", name)
    if date:
        header.set("date", date)
    elif "date" in header.attrib:
        del header.attrib["date"]
    extent = [header.get(k) for k in ("west", "south", "east", "north")]
    if bounds is not None and all(v in (None, "0", "0.0") for v in extent):
        for k, v in zip(("west", "south", "east", "north"), bounds):
            header.set(k, f"{v:.2f}")
    if proj_string is not None:  # (a generated map has no place on earth: no geoReference)
        geo = header.find("geoReference")
        if geo is None:
            geo = etree.Element("geoReference")
            header.insert(0, geo)
        geo.text = etree.CDATA(proj_string)
    etree.indent(root, space="    ")
    return etree.tostring(root, xml_declaration=True, encoding="UTF-8", pretty_print=True)
