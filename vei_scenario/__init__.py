"""vei-scenario: annotated vehicle–e-scooter clips → runnable ASAM OpenSCENARIO/OpenDRIVE scenarios.

The pipeline reads as the sub-packages do:

``clip`` (input contract) → ``geometry`` (projection, time sync, frames, splines, conflict analysis)
→ ``roads`` (OpenStreetMap → OpenDRIVE, or a road fitted to the ego track) → ``scenario`` (the
VEI-specific scenario model) → ``openscenario`` (writing and validating the standard files)
→ ``reports``.

The command line (:mod:`vei_scenario.cli`) is a thin layer over :func:`compile_clip` and
:func:`validate_files`.
"""

from vei_scenario.errors import VeiError, VeiInputError

__version__ = "0.1.0"

__all__ = ["VeiError", "VeiInputError", "__version__", "compile_clip", "validate_files"]


def __getattr__(name: str):
    # Lazy so that ``import vei_scenario`` stays cheap for the CLI's --help and error paths.
    if name == "compile_clip":
        from vei_scenario.compiler import compile_clip

        return compile_clip
    if name == "validate_files":
        from vei_scenario.openscenario.validation import validate_files

        return validate_files
    raise AttributeError(name)
