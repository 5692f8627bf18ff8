#!/usr/bin/env python
"""Build the OSMP test-partner FMUs deterministically.

1. pythonfmu builds <src>/<Name>.py (+ the shared osmp_common.py) into a temp dir. The partners that
   behave (StraightLine, SimpleAebOsmp, TrajectoryFollower) are vei's examples: their sources and the
   shared base are in examples/osmp/src/ and they are built into examples/osmp/; the bad ones are
   built here from src/.
2. modelDescription.xml is post-processed:
   - guid := uuid5 over the FMU's name and all its other files; generationDateAndTime removed
   - <VendorAnnotations><Tool name="net.pmsf.osmp" ...><osmp:osmp version="1.5.0" osi-version="3.7.0"/></Tool></VendorAnnotations>
     inserted after DefaultExperiment (FMI 2.0 element order)
   - each OSMP Integer gets <Annotations><Tool name="net.pmsf.osmp" ...><osmp:osmp-binary-variable .../></Tool></Annotations>
   - the XML is pretty-printed
3. The zip is rewritten with sorted entries and a fixed timestamp.
Usage: build.py [Name ...]   (default: all partners)
"""
import hashlib
import io
import re
import sys
import tempfile
import uuid
import zipfile
from pathlib import Path
from xml.dom import minidom
import xml.etree.ElementTree as ET

from pythonfmu.builder import FmuBuilder

HERE = Path(__file__).resolve().parent
EXAMPLES = HERE.parents[2] / "examples" / "osmp"  # (the good partners: the guide's examples)
SRC = HERE / "src"
COMMON = EXAMPLES / "src" / "osmp_common.py"
OSMP_VERSION = "1.5.0"
OSI_VERSION = "3.7.0"
NS = "http://xsd.pmsf.net/OSISensorModelPackaging"
MIME = "application/x-open-simulation-interface; type={type}; version=" + OSI_VERSION
TYPES = {"OSMPSensorViewIn": "SensorView", "OSMPTrafficCommandIn": "TrafficCommand",
         "OSMPTrafficUpdateOut": "TrafficUpdate"}
PARTNERS = {
    "StraightLine": {},
    "SimpleAebOsmp": {},
    "TrajectoryFollower": {},
    "WrongMime": {"OSMPSensorViewIn": "SensorData"},   # the deliberate defect
    "ZeroSize": {},
    "WrongId": {},
    "NeverWrites": {},
}
FIXED_DATE = (1980, 1, 1, 0, 0, 0)
GOOD = ("StraightLine", "SimpleAebOsmp", "TrajectoryFollower")


def home(name):
    """Where a partner's source is and its FMU goes."""
    return (EXAMPLES / "src", EXAMPLES) if name in GOOD else (SRC, HERE)


def top_annotation():
    return (f'<Tool name="net.pmsf.osmp" xmlns:osmp="{NS}">'
            f'<osmp:osmp version="{OSMP_VERSION}" osi-version="{OSI_VERSION}"/></Tool>')


def var_annotation(prefix, role, typ):
    return (f'<Tool name="net.pmsf.osmp" xmlns:osmp="{NS}">'
            f'<osmp:osmp-binary-variable name="{prefix}" role="{role}" '
            f'mime-type="{MIME.format(type=typ)}"/></Tool>')


def patch_model_description(xml_bytes, name, overrides, guid):
    root = ET.fromstring(xml_bytes)
    for el in root.iter():  # drop pythonfmu's whitespace so the re-indent is clean
        if el.text is not None and not el.text.strip():
            el.text = None
        if el.tail is not None and not el.tail.strip():
            el.tail = None
    root.attrib.pop("generationDateAndTime", None)
    root.set("guid", "{%s}" % guid)
    raw = {}
    # VendorAnnotations: after DefaultExperiment / LogCategories, before ModelVariables
    children = list(root)
    idx = [c.tag for c in children].index("ModelVariables")
    va = ET.Element("VendorAnnotations")
    ET.SubElement(va, "OSMP_PLACEHOLDER_0")
    raw["OSMP_PLACEHOLDER_0"] = top_annotation()
    root.insert(idx, va)
    n = 1
    for sv in root.find("ModelVariables"):
        m = re.fullmatch(r"(OSMP\w+)\.(base\.lo|base\.hi|size)", sv.get("name"))
        if not m or m.group(1) not in TYPES:
            continue
        prefix, role = m.groups()
        typ = overrides.get(prefix, TYPES[prefix])
        ann = ET.SubElement(sv, "Annotations")
        key = f"OSMP_PLACEHOLDER_{n}"
        n += 1
        ET.SubElement(ann, key)
        raw[key] = var_annotation(prefix, role, typ)
    text = minidom.parseString(ET.tostring(root, encoding="unicode")).toprettyxml(indent="  ")
    text = text.replace('<?xml version="1.0" ?>', '<?xml version="1.0" encoding="UTF-8"?>')
    for key, value in raw.items():
        text = text.replace(f"<{key}/>", value)
    assert "OSMP_PLACEHOLDER" not in text
    return text.encode("utf-8")


def build(name):
    overrides = PARTNERS[name]
    src, dest = home(name)
    with tempfile.TemporaryDirectory() as td:
        fmu = FmuBuilder.build_FMU(src / f"{name}.py", dest=Path(td) / f"{name}.fmu",
                                   project_files=[COMMON])
        with zipfile.ZipFile(fmu) as z:
            files = {i.filename: z.read(i.filename) for i in z.infolist() if not i.is_dir()}
    h = hashlib.sha256(name.encode())
    for fn in sorted(files):
        if fn != "modelDescription.xml" and "__pycache__" not in fn:
            h.update(fn.encode())
            h.update(files[fn])
    h.update(repr(sorted(overrides.items())).encode())
    guid = uuid.uuid5(uuid.NAMESPACE_URL, "osmp-partner:" + h.hexdigest())
    files["modelDescription.xml"] = patch_model_description(
        files["modelDescription.xml"], name, overrides, guid)
    out = dest / f"{name}.fmu"
    buf = io.BytesIO()
    with zipfile.ZipFile(buf, "w", zipfile.ZIP_DEFLATED) as z:
        for fn in sorted(files):
            if "__pycache__" in fn:
                continue
            info = zipfile.ZipInfo(fn, date_time=FIXED_DATE)
            info.compress_type = zipfile.ZIP_DEFLATED
            info.external_attr = 0o644 << 16
            z.writestr(info, files[fn])
    out.write_bytes(buf.getvalue())
    print(f"built {out.name}  guid {guid}")
    return out


if __name__ == "__main__":
    for n in (sys.argv[1:] or list(PARTNERS)):
        build(n)
