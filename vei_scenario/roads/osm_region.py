"""Cut the map region of a scenario out of an OpenStreetMap XML file (the seed method's step 2).

Two streaming passes with a hardened parser, so city-sized extracts fit in memory: the first finds the
highway ways with at least one node inside the box and the nodes they need; the second copies those
nodes and ways. Ways are kept whole (netconvert needs their full geometry to build junctions), and
relations are dropped (turn restrictions do not matter for a scenario's road surface).
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from lxml import etree

from vei_scenario.errors import VeiInputError
from vei_scenario.safe_xml import SAFE_OPTIONS, float_attribute

#: Margin added around the scenario's bounding box before cropping (m).
DEFAULT_MARGIN_M = 60.0


@dataclass(frozen=True)
class OsmRegion:
    xml: bytes
    n_ways: int
    n_nodes: int
    n_missing_nodes: int  # node references the extract does not resolve (ways cut at its border)


#: The most lanes one OSM way may carry (the widest carriageways have about 16 per direction); more is a
#: typo netconvert would build for minutes.
MAX_OSM_LANES = 32
LANE_COUNT_KEYS = frozenset({"lanes", "lanes:forward", "lanes:backward", "lanes:both_ways"})


def _check_lane_count(path: Path, way, tag) -> None:
    """Refuse a lane count tag beyond MAX_OSM_LANES, naming the way and the line (a value that is no
    number is left to netconvert, which ignores it)."""
    if tag.get("k") not in LANE_COUNT_KEYS:
        return
    try:
        n = float(tag.get("v", ""))
    except ValueError:
        return
    if not n <= MAX_OSM_LANES:
        raise VeiInputError(
            path,
            f"line {tag.sourceline}",
            f"way {way.get('id')}: {tag.get('k')}={tag.get('v')!r}: more lanes than a road has "
            f"(at most {MAX_OSM_LANES})",
        )


def _iter(path: Path, tags: tuple[str, ...]):
    return etree.iterparse(str(path), events=("end",), tag=tags, remove_comments=True, **SAFE_OPTIONS)


def crop_osm(path: Path, bbox: tuple[float, float, float, float]) -> OsmRegion:
    """Highway ways touching ``bbox`` (south, west, north, east) and their nodes, as OSM XML bytes."""
    path = Path(path)
    if not path.is_file():
        raise VeiInputError(path, "", "map file not found")
    south, west, north, east = bbox
    inside: set[str] = set()
    keep_ways: set[str] = set()
    needed: set[str] = set()
    try:
        root_seen = False
        for _, el in etree.iterparse(str(path), events=("start",), **SAFE_OPTIONS):
            if el.tag != "osm":
                raise VeiInputError(
                    path, f"line {el.sourceline}", f"root element is <{el.tag}>, expected <osm> (OSM XML)"
                )
            root_seen = True
            break
        if not root_seen:
            raise VeiInputError(path, "", "empty OSM file")
        for _, el in _iter(path, ("node", "way")):
            if el.tag == "node":
                lat, lon = float_attribute(path, el, "lat"), float_attribute(path, el, "lon")
                if not (-90 <= lat <= 90 and -180 <= lon <= 180):
                    raise VeiInputError(path, f"line {el.sourceline}", f"<node> position ({lat}, {lon}) out of range")
                if south <= lat <= north and west <= lon <= east:
                    inside.add(el.get("id"))
            else:
                refs = [nd.get("ref") for nd in el.iterfind("nd")]
                is_highway = any(t.get("k") == "highway" for t in el.iterfind("tag"))
                if is_highway and len(refs) >= 2 and any(r in inside for r in refs):
                    keep_ways.add(el.get("id"))
                    needed.update(refs)
            el.clear()
        if not keep_ways:
            raise VeiInputError(
                path,
                "",
                f"no OSM highway within the scenario's region (lat {south:.5f}..{north:.5f}, "
                f"lon {west:.5f}..{east:.5f}); is this the map of the clip?",
            )
        out = etree.Element("osm", version="0.6", generator="vei-scenario")
        etree.SubElement(
            out, "bounds", minlat=f"{south:.7f}", minlon=f"{west:.7f}", maxlat=f"{north:.7f}", maxlon=f"{east:.7f}"
        )
        found: set[str] = set()
        ways = []
        for _, el in _iter(path, ("node", "way")):
            if el.tag == "node" and el.get("id") in needed:
                n = etree.SubElement(out, "node", id=el.get("id"), lat=el.get("lat"), lon=el.get("lon"))
                for t in el.iterfind("tag"):
                    etree.SubElement(n, "tag", k=t.get("k"), v=t.get("v"))
                found.add(el.get("id"))
            elif el.tag == "way" and el.get("id") in keep_ways:
                w = etree.Element("way", id=el.get("id"))
                for nd in el.iterfind("nd"):
                    etree.SubElement(w, "nd", ref=nd.get("ref"))
                for t in el.iterfind("tag"):
                    _check_lane_count(path, el, t)
                    etree.SubElement(w, "tag", k=t.get("k"), v=t.get("v"))
                ways.append(w)
            el.clear()
    except etree.XMLSyntaxError as exc:
        raise VeiInputError(path, f"line {exc.lineno}", f"malformed OSM XML: {exc.msg}") from None
    missing = needed - found
    n_ways = 0
    for w in ways:
        # Extracts cut ways at their border; keep the part the extract knows.
        for nd in [nd for nd in w.iterfind("nd") if nd.get("ref") in missing]:
            w.remove(nd)
        if len(w.findall("nd")) >= 2:
            out.append(w)
            n_ways += 1
    xml = etree.tostring(out, xml_declaration=True, encoding="UTF-8", pretty_print=True)
    return OsmRegion(xml, n_ways, len(found), len(missing))


def fetch_osm(bbox: tuple[float, float, float, float], dest: Path) -> Path:
    """Download the highways in ``bbox`` with osmnx (online only) into an OSM XML file at ``dest``.

    Offline runs never reach this: a clip's ``map.osm`` or ``--osm FILE`` is used instead.
    """
    try:
        import osmnx as ox
    except ImportError:
        raise VeiInputError(None, "--osm-fetch", "needs osmnx: pip install 'vei-scenario[osm-fetch]'") from None
    south, west, north, east = bbox
    try:
        ox.settings.all_oneway = True  # keeps OSM way direction, as save_graph_xml requires
        graph = ox.graph_from_bbox((west, south, east, north), network_type="drive", simplify=False)
        ox.io.save_graph_xml(graph, filepath=dest)
    except Exception as exc:  # network failures come in many types from requests/osmnx
        raise VeiInputError(None, "--osm-fetch", f"could not download OpenStreetMap data: {exc}") from None
    return dest
