"""Build step beyond pyproject.toml: the compiled core (required) and the sweep kernel (optional: without
a C compiler the kernel is compiled on first use, or sweeps use numpy) as extension modules."""

import hashlib
import sys
from pathlib import Path

from setuptools import Extension, setup

C = Path("vei_scenario/core/src")
# what the kernel is built from; vei_scenario.batch.native compares it with the sources it ships, so a
# checkout whose C files changed since the last build compiles the new ones instead of using this
DIGEST = hashlib.sha256(
    b"".join((C / n).read_bytes() for n in ("vei_models.c", "vei_batch.c", "vei_models.h", "vei_batch.h"))
).hexdigest()[:16]

KERNEL_SOURCES = [
    "vei_scenario/batch/_kernel_module.c",
    "vei_scenario/core/src/vei_models.c",
    "vei_scenario/core/src/vei_batch.c",
]

setup(
    ext_modules=[
        # the compiled core (road geometry, lane keeping, the models): required, every scenario runs through it
        Extension(
            "vei_scenario.core._core",
            sources=[
                "vei_scenario/core/src/core_module.c",
                "vei_scenario/core/src/road.c",
                "vei_scenario/core/src/vei_models.c",
            ],
            include_dirs=["vei_scenario/core/src"],
            extra_compile_args=[] if sys.platform == "win32" else ["-O3", "-std=c99", "-ffp-contract=off"],
            libraries=[] if sys.platform == "win32" else ["m"],
        ),
        Extension(
            "vei_scenario.batch._kernel",
            sources=KERNEL_SOURCES,
            include_dirs=["vei_scenario/core/src"],
            define_macros=[("VEI_KERNEL_DIGEST", f'"{DIGEST}"')],
            # the flags of the on-demand build: no fused multiply-add, so rows equal vei run's bit for bit
            extra_compile_args=[] if sys.platform == "win32" else ["-O3", "-std=c99", "-ffp-contract=off"],
            libraries=[] if sys.platform == "win32" else ["m"],
            optional=True,
        )
    ]
)
