"""Run SUMO's netconvert to turn OSM XML into OpenDRIVE in the scenario's own projection.

netconvert comes with the ``eclipse-sumo`` wheel. It is given the scenario's PROJ string and told not
to shift the origin, so its OpenDRIVE coordinates are the scenario's metres and its ``geoReference``
names the same projection.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import tempfile
from pathlib import Path

from vei_scenario.errors import VeiInputError

#: netconvert options, each with the reason it is here.
NETCONVERT_OPTIONS = [
    "--offset.disable-normalization",
    "true",  # keep the scenario's origin
    "--keep-edges.by-vclass",
    "passenger,bicycle",  # roads cars or scooters use; no footpaths
    "--geometry.remove",
    "true",  # merge straight runs of nodes into one geometry
    "--junctions.join",
    "true",  # one junction per real intersection
    "--roundabouts.guess",
    "true",
    "--tls.discard-simple",
    "true",
    "--output.street-names",
    "true",
    "--osm.elevation",
    "false",
    "--no-warnings",
    "true",
]


def find_netconvert() -> str:
    """The netconvert executable: ``$VEI_NETCONVERT``, the eclipse-sumo wheel, ``$SUMO_HOME`` or PATH."""
    env = os.environ.get("VEI_NETCONVERT")
    if env:
        if not (Path(env).is_file() and os.access(env, os.X_OK)):
            raise VeiInputError(None, "VEI_NETCONVERT", f"{env} is not an executable file")
        return env
    candidates = []
    try:
        import sumo  # the eclipse-sumo wheel

        candidates.append(Path(sumo.SUMO_HOME) / "bin" / "netconvert")
    except ImportError:
        pass
    if os.environ.get("SUMO_HOME"):
        candidates.append(Path(os.environ["SUMO_HOME"]) / "bin" / "netconvert")
    for c in candidates:
        if c.is_file() and os.access(c, os.X_OK):
            return str(c)
    found = shutil.which("netconvert")
    if found:
        return found
    raise VeiInputError(None, "netconvert", "SUMO netconvert not found; install it with: pip install eclipse-sumo")


class NetconvertJob:
    """netconvert running in the background, so it overlaps with the reconstruction (two cores)."""

    def __init__(self, osm_xml: bytes, proj_string: str, osm_source: Path, timeout_s: float = 120.0) -> None:
        self.osm_source = osm_source
        self.timeout_s = timeout_s
        exe = find_netconvert()
        self._tmp = tempfile.TemporaryDirectory(prefix="vei-netconvert-")
        src, self._dst = Path(self._tmp.name) / "region.osm", Path(self._tmp.name) / "region.xodr"
        src.write_bytes(osm_xml)
        cmd = [exe, "--osm-files", str(src), "--opendrive-output", str(self._dst), "--proj", proj_string]
        try:
            self._proc = subprocess.Popen(
                [*cmd, *NETCONVERT_OPTIONS], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True
            )
        except OSError as exc:
            self._tmp.cleanup()
            raise VeiInputError(osm_source, "netconvert", f"could not start {exe}: {exc.strerror or exc}") from None

    def result(self) -> bytes:
        """Wait for netconvert; the OpenDRIVE bytes, or a VeiInputError naming the map file."""
        try:
            try:
                out, err = self._proc.communicate(timeout=self.timeout_s)
            except subprocess.TimeoutExpired:
                self._proc.kill()
                self._proc.communicate()
                raise VeiInputError(self.osm_source, "netconvert", f"timed out after {self.timeout_s:.0f} s") from None
            if self._proc.returncode != 0 or not self._dst.is_file():
                lines = [ln.strip() for ln in (err + out).splitlines() if ln.strip()]
                errors = [ln for ln in lines if ln.lower().startswith(("error", "fatal"))] or lines[-1:]
                detail = errors[0] if errors else f"exit code {self._proc.returncode}"
                raise VeiInputError(self.osm_source, "netconvert", f"failed: {detail}")
            return self._dst.read_bytes()
        finally:
            self._tmp.cleanup()

    def cancel(self) -> None:
        if self._proc.poll() is None:
            self._proc.kill()
            self._proc.communicate()
        self._tmp.cleanup()
