"""OpenSCENARIO/OpenDRIVE files: writing the compiled scenario and validating any such file."""

#: OpenSCENARIO 1.x minor versions vei can write.
SUPPORTED_MINOR_VERSIONS = (0, 1, 2, 3)
