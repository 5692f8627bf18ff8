/* A tiny native FMI 2.0 co-simulation FMU that drives the ego at 0 m/s^2 and then fails inside its own
 * binary, as a real controller's native code can, at t >= 1 s: compiled with -DFAULT_CRASH it
 * dereferences NULL (SIGSEGV), with -DFAULT_HANG it never returns from fmi2DoStep, with -DFAULT_ERROR
 * fmi2DoStep returns fmi2Error, with -DFAULT_NAN its a_cmd is NaN. It fails only while its Boolean
 * parameter enabled (vr 2, true unless set; the planner's property of that name in vei's scenarios) is
 * true: a modelDescription that declares it gates the fault by the scenario's CapEnabled.
 * Ports: input ego_speed (vr 0), output a_cmd (vr 1). Every other FMI 2.0 function is a stub returning
 * fmi2OK. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "fmi2Functions.h"

typedef struct { fmi2Real speed, a_cmd; fmi2Boolean enabled; } Instance;

fmi2Component fmi2Instantiate(fmi2String n, fmi2Type t, fmi2String g, fmi2String r,
                              const fmi2CallbackFunctions *f, fmi2Boolean v, fmi2Boolean l) {
    (void)n; (void)t; (void)g; (void)r; (void)f; (void)v; (void)l;
    Instance *i = calloc(1, sizeof(Instance));
    if (i != NULL) i->enabled = fmi2True;
    return i;
}
void fmi2FreeInstance(fmi2Component c) { free(c); }
fmi2Status fmi2DoStep(fmi2Component c, fmi2Real t, fmi2Real h, fmi2Boolean nsp) {
    (void)h; (void)nsp;
    ((Instance *)c)->a_cmd = 0.0;
    if (t >= 1.0 && ((Instance *)c)->enabled) {
#ifdef FAULT_CRASH
        *(volatile int *)0 = 1;
#endif
#ifdef FAULT_HANG
        for (;;) pause();
#endif
#ifdef FAULT_ERROR
        return fmi2Error;
#endif
#ifdef FAULT_NAN
        ((Instance *)c)->a_cmd = NAN;
#endif
    }
    return fmi2OK;
}
fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2Real v[]) {
    for (size_t i = 0; i < n; i++) if (vr[i] == 0) ((Instance *)c)->speed = v[i];
    return fmi2OK;
}
fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2Real v[]) {
    for (size_t i = 0; i < n; i++) v[i] = vr[i] == 1 ? ((Instance *)c)->a_cmd : ((Instance *)c)->speed;
    return fmi2OK;
}
fmi2Status fmi2SetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2Boolean v[]) {
    for (size_t i = 0; i < n; i++) if (vr[i] == 2) ((Instance *)c)->enabled = v[i];
    return fmi2OK;
}
#define HAS_SET_BOOLEAN
#include "stubs.h"
