"""Shared fixtures: the bundled examples compiled once, noise-free clips, the ASAM QC checker."""

from __future__ import annotations

import glob
import importlib.util
import os
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ROOT / "examples"
#: Test partners kept as received under data/ bring their own tests (run through tests/test_osmp.py).
collect_ignore_glob = ["data/*/test_*.py"]

EXAMPLE_NAMES = ("case_study", "multi_scooter", "no_map", "stop_and_go")
#: The reference material beside the checkout (esmini/ with its examples and roads, osc-ncap/: the Euro NCAP
#: pack), or a folder named by ``$VEI_SHARED``; tests that need it skip where it is absent.
SHARED = Path(os.environ.get("VEI_SHARED") or ROOT.parent / "shared")
#: The one-line reason such a test gives where it is absent.
NO_SHARED = "set VEI_SHARED to a folder holding esmini/ and osc-ncap/, or place it at ../shared"


def _qc_venv() -> Path | None:
    for cand in (os.environ.get("VEI_QC_VENV"), ROOT / ".venv-qc"):
        if cand and (Path(cand) / "bin" / "qc_openscenario").exists():
            return Path(cand).resolve()
    return None


if _qc_venv() is not None:  # lets vei's XSD locator find the schemas in the checker's venv
    os.environ.setdefault("VEI_QC_VENV", str(_qc_venv()))


@pytest.fixture(scope="session")
def qc_venv() -> Path:
    """The ASAM Quality Checker's own venv; required in CI, skipped elsewhere when absent."""
    venv = _qc_venv()
    if venv is None:
        if os.environ.get("CI"):
            pytest.fail("CI needs the ASAM Quality Checker venv (.venv-qc or VEI_QC_VENV); see README")
        pytest.skip("ASAM Quality Checker venv not installed (.venv-qc)")
    return venv


@pytest.fixture(scope="session")
def compiled(tmp_path_factory) -> dict:
    """Each example compiled once: {name: CompileResult}, case study with resolved variants."""
    from vei_scenario.compiler import CompileOptions, compile_clip

    out = tmp_path_factory.mktemp("compiled")
    results = {}
    for name in EXAMPLE_NAMES:
        variants = out / name / "variants" if name == "case_study" else None
        results[name] = compile_clip(
            EXAMPLES / name / "clip.json", out / name / "scenario.xosc", CompileOptions(variants_dir=variants)
        )
    return results


@pytest.fixture(scope="session")
def noise_free_dir(tmp_path_factory) -> Path:
    """The example clips regenerated without GPS noise (with their ground truth)."""
    out = tmp_path_factory.mktemp("noise_free")
    subprocess.run(
        [sys.executable, str(EXAMPLES / "generate_examples.py"), "--noise-free", str(out)],
        check=True,
        capture_output=True,
    )
    return out


def native_test_fmus():
    """The builder of the tiny native C test FMUs (data/sut/native_src/build.py: faults, all inputs),
    loaded as a module; skips the test where there is no C compiler to build them."""
    import shutil

    from vei_scenario.core.sources import compiler

    if shutil.which(compiler()) is None:
        pytest.skip(f"no C compiler ({compiler()}) to build the native test FMUs")
    path = Path(__file__).parent / "data" / "sut" / "native_src" / "build.py"
    spec = importlib.util.spec_from_file_location("native_test_fmus", path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


@pytest.fixture(scope="session")
def case_study(compiled) -> Path:
    """The compiled case study's scenario.xosc."""
    return next(p for p in compiled["case_study"].written if p.name == "scenario.xosc")


@pytest.fixture(scope="session")
def multi(compiled) -> Path:
    """The compiled multi_scooter example's scenario.xosc."""
    return next(p for p in compiled["multi_scooter"].written if p.name == "scenario.xosc")


def load_generator():
    spec = importlib.util.spec_from_file_location("generate_examples", EXAMPLES / "generate_examples.py")
    mod = importlib.util.module_from_spec(spec)
    sys.modules["generate_examples"] = mod
    spec.loader.exec_module(mod)
    return mod


def site_packages(venv: Path) -> Path:
    return Path(sorted(glob.glob(str(venv / "lib" / "python*" / "site-packages")))[0])


@pytest.fixture
def esmini_if_here():
    """esmini when it is here (``$VEI_ESMINI`` or beside the checkout), else None: for tests whose own
    assertions stand without it and that compare with it when they can."""
    from vei_scenario.conformance.esmini import find_esmini

    return find_esmini(SHARED / "esmini" / "bin" / "esmini")


@pytest.fixture(scope="session")
def esmini():
    """esmini, the reference player: ``$VEI_ESMINI`` or ``../shared/esmini/bin/esmini`` beside the
    checkout. Skipped where it is absent (a user's machine); CI has it and so runs the cross-checks."""
    from vei_scenario.conformance.esmini import find_esmini

    found = find_esmini(SHARED / "esmini" / "bin" / "esmini")
    if found is None:
        pytest.skip("esmini not found (set VEI_ESMINI to its binary, or VEI_SHARED to a folder holding esmini/)")
    return found
