/* A tiny native FMI 2.0 co-simulation FMU that reads every input vei provides (vr 0-14, in the order of
 * vei_scenario.sut.fmu.INPUTS: the ego's x, y, yaw, speed, accel, length, width, the threat's, time)
 * and commands a_cmd (vr 15) from all of them, so that a run shows whether each input arrives as the
 * interpreter gives it: a gentle pull towards 4 m/s, nudged by the others' accelerations, the box sizes
 * and the time. Every other FMI 2.0 function is a stub returning fmi2OK. */
#include <math.h>
#include <stdlib.h>
#include "fmi2Functions.h"

typedef struct { fmi2Real in[15], a_cmd; } Instance;

fmi2Component fmi2Instantiate(fmi2String n, fmi2Type t, fmi2String g, fmi2String r,
                              const fmi2CallbackFunctions *f, fmi2Boolean v, fmi2Boolean l) {
    (void)n; (void)t; (void)g; (void)r; (void)f; (void)v; (void)l;
    return calloc(1, sizeof(Instance));
}
void fmi2FreeInstance(fmi2Component c) { free(c); }
fmi2Status fmi2DoStep(fmi2Component c, fmi2Real t, fmi2Real h, fmi2Boolean nsp) {
    (void)t; (void)h; (void)nsp;
    const fmi2Real *u = ((Instance *)c)->in;
    double gap = hypot(u[7] - u[0], u[8] - u[1]);
    ((Instance *)c)->a_cmd = 0.5 * (4.0 - u[3]) + 0.1 * u[4] + 0.05 * u[11] + 0.01 * sin(u[2] - u[9]) +
                             0.01 * (u[5] + u[6] - u[12] - u[13]) + 0.001 * u[14] + 0.01 * u[10] -
                             (gap < 8.0 ? 3.0 : 0.0);
    return fmi2OK;
}
fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2Real v[]) {
    for (size_t i = 0; i < n; i++) if (vr[i] < 15) ((Instance *)c)->in[vr[i]] = v[i];
    return fmi2OK;
}
fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2Real v[]) {
    for (size_t i = 0; i < n; i++) v[i] = vr[i] == 15 ? ((Instance *)c)->a_cmd : ((Instance *)c)->in[vr[i] % 15];
    return fmi2OK;
}
#include "stubs.h"
