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
const char *fmi2GetTypesPlatform(void) { return fmi2TypesPlatform; }
const char *fmi2GetVersion(void) { return fmi2Version; }
#define OK(...) { return fmi2OK; }
fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean l, size_t n, const fmi2String cat[]) OK()
fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean tol, fmi2Real tv, fmi2Real t0, fmi2Boolean st,
                               fmi2Real t1) OK()
fmi2Status fmi2EnterInitializationMode(fmi2Component c) OK()
fmi2Status fmi2ExitInitializationMode(fmi2Component c) OK()
fmi2Status fmi2Terminate(fmi2Component c) OK()
fmi2Status fmi2Reset(fmi2Component c) OK()
fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2Integer v[]) OK()
fmi2Status fmi2GetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2Boolean v[]) OK()
fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2String v[]) OK()
fmi2Status fmi2SetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2Integer v[]) OK()
fmi2Status fmi2SetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2Boolean v[]) {
    for (size_t i = 0; i < n; i++) if (vr[i] == 2) ((Instance *)c)->enabled = v[i];
    return fmi2OK;
}
fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2String v[]) OK()
fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate *s) OK()
fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate s) OK()
fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate *s) OK()
fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate s, size_t *n) OK()
fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate s, fmi2Byte b[], size_t n) OK()
fmi2Status fmi2DeSerializeFMUstate(fmi2Component c, const fmi2Byte b[], size_t n, fmi2FMUstate *s) OK()
fmi2Status fmi2GetDirectionalDerivative(fmi2Component c, const fmi2ValueReference u[], size_t nu,
                                        const fmi2ValueReference z[], size_t nz, const fmi2Real du[],
                                        fmi2Real dz[]) OK()
fmi2Status fmi2SetRealInputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t n,
                                       const fmi2Integer o[], const fmi2Real v[]) OK()
fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t n,
                                        const fmi2Integer o[], fmi2Real v[]) OK()
fmi2Status fmi2CancelStep(fmi2Component c) OK()
fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind s, fmi2Status *v) OK()
fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind s, fmi2Real *v) OK()
fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind s, fmi2Integer *v) OK()
fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind s, fmi2Boolean *v) OK()
fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind s, fmi2String *v) OK()
