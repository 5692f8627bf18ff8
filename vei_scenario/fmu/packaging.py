"""Writing FMU (and SSP) archives: sorted entries, fixed timestamps, written through a temp file."""

from __future__ import annotations

import io
import zipfile
from pathlib import Path

from vei_scenario.atomic_io import write_bytes_atomic

_EPOCH = (1980, 1, 1, 0, 0, 0)


def xml_value(value) -> str:
    """A value as an XML attribute of FMI/SSP: booleans lower-case, floats round-tripping exactly."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        return repr(value)
    return str(value)


def zip_bytes(entries: dict[str, bytes]) -> bytes:
    """A zip archive of ``entries`` (path -> content), the same bytes for the same entries."""
    buf = io.BytesIO()
    with zipfile.ZipFile(buf, "w", zipfile.ZIP_DEFLATED) as zf:
        for name in sorted(entries):
            info = zipfile.ZipInfo(name, _EPOCH)
            info.compress_type = zipfile.ZIP_DEFLATED
            info.external_attr = 0o644 << 16
            zf.writestr(info, entries[name])
    return buf.getvalue()


def write_fmu(path: Path, entries: dict[str, bytes]) -> Path:
    write_bytes_atomic(path, zip_bytes(entries))
    return path
