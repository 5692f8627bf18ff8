/* c_host.c: a minimal OSMP host in C, for the tests: no Python in the process.
 *
 *   c_host FMU_BINARY GUID VIEWS OUT
 *
 * Loads the participant's shared object, instantiates it (FMI 2.0 co-simulation), and for each
 * SensorView in VIEWS (each a little-endian uint32 size and the bytes) sets OSMPSensorViewIn
 * (value references 0, 1, 2: base.lo, base.hi, size), calls fmi2DoStep(0.01 k, 0.01) and appends the
 * TrafficUpdate (value references 3, 4, 5) to OUT in the same framing. Exits 1 on any failure, with
 * the FMU's logged lines on stderr. */
#include <dlfcn.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmi2Functions.h"

static void logger(fmi2ComponentEnvironment env, fmi2String name, fmi2Status status, fmi2String category,
                   fmi2String message, ...) {
    (void)env, (void)status, (void)category;
    va_list ap;
    va_start(ap, message);
    fprintf(stderr, "%s: ", name);
    vfprintf(stderr, message, ap);
    fputc('\n', stderr);
    va_end(ap);
}

#define LOAD(T, name)                                                          \
    T name = (T)dlsym(lib, #name);                                            \
    if (name == NULL) {                                                       \
        fprintf(stderr, "no %s in the binary\n", #name);                       \
        return 1;                                                             \
    }

int main(int argc, char **argv) {
    if (argc != 5) return fprintf(stderr, "usage: c_host FMU_BINARY GUID VIEWS OUT\n"), 1;
    void *lib = dlopen(argv[1], RTLD_NOW | RTLD_LOCAL);
    if (lib == NULL) return fprintf(stderr, "%s\n", dlerror()), 1;
    LOAD(fmi2InstantiateTYPE *, fmi2Instantiate)
    LOAD(fmi2SetupExperimentTYPE *, fmi2SetupExperiment)
    LOAD(fmi2EnterInitializationModeTYPE *, fmi2EnterInitializationMode)
    LOAD(fmi2ExitInitializationModeTYPE *, fmi2ExitInitializationMode)
    LOAD(fmi2SetIntegerTYPE *, fmi2SetInteger)
    LOAD(fmi2GetIntegerTYPE *, fmi2GetInteger)
    LOAD(fmi2DoStepTYPE *, fmi2DoStep)
    LOAD(fmi2TerminateTYPE *, fmi2Terminate)
    LOAD(fmi2FreeInstanceTYPE *, fmi2FreeInstance)
    fmi2CallbackFunctions cb = {logger, calloc, free, NULL, NULL};
    fmi2Component c = fmi2Instantiate("c_host", fmi2CoSimulation, argv[2], "", &cb, fmi2False, fmi2False);
    if (c == NULL) return fprintf(stderr, "fmi2Instantiate failed\n"), 1;
    if (fmi2SetupExperiment(c, fmi2False, 0.0, 0.0, fmi2False, 0.0) != fmi2OK ||
        fmi2EnterInitializationMode(c) != fmi2OK || fmi2ExitInitializationMode(c) != fmi2OK)
        return fprintf(stderr, "initialization failed\n"), 1;
    FILE *in = fopen(argv[3], "rb"), *out = fopen(argv[4], "wb");
    if (in == NULL || out == NULL) return fprintf(stderr, "cannot open the files\n"), 1;
    const fmi2ValueReference sv[3] = {0, 1, 2}, tu[3] = {3, 4, 5};
    uint32_t size;
    for (int k = 0; fread(&size, 4, 1, in) == 1; k++) {
        unsigned char *view = malloc(size ? size : 1);
        if (view == NULL || fread(view, 1, size, in) != size) return fprintf(stderr, "short VIEWS file\n"), 1;
        uint64_t at = (uint64_t)(uintptr_t)view;
        fmi2Integer given[3] = {(fmi2Integer)(int32_t)(uint32_t)at, (fmi2Integer)(int32_t)(uint32_t)(at >> 32),
                                (fmi2Integer)size};
        if (fmi2SetInteger(c, sv, 3, given) != fmi2OK || fmi2DoStep(c, 0.01 * k, 0.01, fmi2True) != fmi2OK)
            return fprintf(stderr, "step %d failed\n", k), 1;
        memset(view, 0, size); /* (the input is the host's again once doStep returns) */
        free(view);
        fmi2Integer got[3];
        if (fmi2GetInteger(c, tu, 3, got) != fmi2OK) return fprintf(stderr, "step %d: no output\n", k), 1;
        uint64_t addr = ((uint64_t)(uint32_t)got[1] << 32) | (uint32_t)got[0];
        uint32_t n = (uint32_t)got[2];
        if (addr == 0 || got[2] <= 0) return fprintf(stderr, "step %d: no TrafficUpdate\n", k), 1;
        fwrite(&n, 4, 1, out);
        fwrite((const void *)(uintptr_t)addr, 1, n, out);
    }
    fclose(in), fclose(out);
    if (fmi2Terminate(c) != fmi2OK) return 1;
    fmi2FreeInstance(c);
    return 0;
}
