"""OpenSCENARIO/OpenDRIVE files: writing the compiled scenario and validating any such file."""

#: OpenSCENARIO 1.x minor versions vei can write.
SUPPORTED_MINOR_VERSIONS = (0, 1, 2, 3)

#: ``storyboardElementType`` values → the element tags they name.
STORYBOARD_ELEMENT_TYPES = {
    "story": "Story",
    "act": "Act",
    "maneuverGroup": "ManeuverGroup",
    "maneuver": "Maneuver",
    "event": "Event",
    "action": "Action",
}
