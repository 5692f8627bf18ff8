"""The wheel a user installs: a manylinux platform wheel with the compiled core (sweep kernel included) and the
example clips inside, and `vei examples` copying those clips out so that they compile."""

from __future__ import annotations

import os
import subprocess
import sys
import zipfile
from pathlib import Path

import pytest

from conftest import ROOT
from vei_scenario.cli import main


@pytest.fixture(scope="module")
def wheel(tmp_path_factory) -> Path:
    pytest.importorskip("auditwheel")
    out = tmp_path_factory.mktemp("wheel")
    env = dict(os.environ, PATH=f"{Path(sys.executable).parent}{os.pathsep}{os.environ.get('PATH', '')}")
    subprocess.run(
        [sys.executable, "-m", "pip", "wheel", "-q", "--no-deps", str(ROOT), "-w", str(out / "dist")],
        check=True, capture_output=True, env=env,
    )  # fmt: skip
    (built,) = (out / "dist").glob("*.whl")
    subprocess.run(
        [sys.executable, "-m", "auditwheel", "repair", str(built), "-w", str(out / "wheelhouse")],
        check=True, capture_output=True, env=env,
    )  # fmt: skip
    (repaired,) = (out / "wheelhouse").glob("*.whl")
    return repaired


def test_wheel_is_a_manylinux_platform_wheel_with_the_core(wheel):
    assert "manylinux" in wheel.name
    names = zipfile.ZipFile(wheel).namelist()
    assert any(n.startswith("vei_scenario/core/_core") and n.endswith(".so") for n in names)
    assert not any("_kernel" in n for n in names)  # the sweep kernel is part of the core
    tags = zipfile.ZipFile(wheel).read(next(n for n in names if n.endswith(".dist-info/WHEEL"))).decode()
    assert "Root-Is-Purelib: false" in tags and "manylinux" in tags


def test_wheel_carries_the_examples_and_schemas(wheel):
    names = set(zipfile.ZipFile(wheel).namelist())
    for rel in (
        "case_study/clip.json",
        "maps/helsinki_center.osm",
        "ci/suite.toml",
        "controllers/aeb.py",
        "osmp/StraightLine.fmu",
        "osmp/src/TrajectoryFollower.py",
        "generate_dataset.py",
        "generate_examples.py",
    ):
        assert f"vei_scenario/data/examples/{rel}" in names
    assert "vei_scenario/data/clip.schema.json" in names


def test_vei_examples_copies_clips_that_compile(tmp_path, capsys):
    assert main(["examples", str(tmp_path / "ex")]) == 0
    # the guides' example controller and dataset generator come out too
    assert (tmp_path / "ex" / "controllers" / "aeb.py").is_file()
    assert (tmp_path / "ex" / "generate_dataset.py").is_file()
    assert (tmp_path / "ex" / "maps" / "helsinki_center.osm").is_file()
    # the OSMP guide's participants, with their sources, byte for byte
    ours = Path(__file__).parents[1] / "examples" / "osmp"
    for rel in ("SimpleAebOsmp.fmu", "StraightLine.fmu", "TrajectoryFollower.fmu", "src/osmp_common.py"):
        assert (tmp_path / "ex" / "osmp" / rel).read_bytes() == (ours / rel).read_bytes()
    assert (
        main(["compile", str(tmp_path / "ex" / "case_study" / "clip.json"), "-o", str(tmp_path / "o" / "s.xosc")]) == 0
    )
    capsys.readouterr()
    assert main(["examples", str(tmp_path / "ex")]) == 2  # nothing overwritten without --force
    assert "already exists" in capsys.readouterr().err


def test_validate_works_in_process_without_the_checker_environment(compiled):
    """After the README's install (the XSDs installed beside vei), no second environment is needed."""
    files = [str(p) for p in compiled["case_study"].written]
    env = {k: v for k, v in os.environ.items() if k not in ("VEI_QC_VENV", "VEI_ASAM_SCHEMAS")}
    proc = subprocess.run(
        [sys.executable, "-m", "vei_scenario", "validate", *files], capture_output=True, text=True, env=env
    )
    assert proc.returncode == 0, proc.stdout + proc.stderr
    assert proc.stdout.strip().endswith("valid")
