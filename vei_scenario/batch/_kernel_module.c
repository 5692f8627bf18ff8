/* The sweep kernel as a Python extension module: vei_batch.c and vei_models.c (the FMUs' sources)
 * compiled when vei-scenario is built, so a wheel carries the kernel and no compiler is needed where
 * it is installed. Python never calls into the module; vei_scenario.batch.native loads the same
 * shared object with ctypes. This file only makes it an importable extension on every platform. */
#define PY_SSIZE_T_CLEAN
#include <Python.h>

#ifndef VEI_KERNEL_DIGEST
#define VEI_KERNEL_DIGEST ""
#endif

/* The digest of the C sources this was built from (see setup.py). */
const char *vei_kernel_digest(void) { return VEI_KERNEL_DIGEST; }

static struct PyModuleDef kernel_module = {PyModuleDef_HEAD_INIT, "_kernel",
                                           "vei-scenario's compiled sweep kernel (loaded with ctypes).", -1, NULL};

PyMODINIT_FUNC PyInit__kernel(void) { return PyModule_Create(&kernel_module); }
