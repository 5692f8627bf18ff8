"""OpenSCENARIO/OpenDRIVE files: writing the compiled scenario and validating any such file."""
