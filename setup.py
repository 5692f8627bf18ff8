"""Build step beyond pyproject.toml: the compiled core as an extension module (required: every scenario,
every sweep and the FMUs' reference run through it)."""

import sys

from setuptools import Extension, setup

setup(
    ext_modules=[
        # road geometry and lane keeping, the models and agents, the sweep kernel: one shared object.
        # No fused multiply-add, so that the FMUs (compiled with the same flags) reproduce it bit for bit.
        Extension(
            "vei_scenario.core._core",
            sources=[
                "vei_scenario/core/src/core_module.c",
                "vei_scenario/core/src/road.c",
                "vei_scenario/core/src/vei_models.c",
                "vei_scenario/core/src/vei_batch.c",
                "vei_scenario/core/src/vei_fmu_ego.c",
            ],
            include_dirs=["vei_scenario/core/src"],
            extra_compile_args=[] if sys.platform == "win32" else ["-O3", "-std=c99", "-ffp-contract=off"],
            # (dl: the native FMU on the ego of the sweep kernel, opened with dlopen; in libc since glibc 2.34)
            libraries=[] if sys.platform == "win32" else ["m"] + (["dl"] if sys.platform.startswith("linux") else []),
        ),
    ]
)
