/* fmi2_wrapper.c: the FMI 2.0 co-simulation interface over a vei model (see fmu_instance.h).
 *
 * Errors never abort the host: a refused call logs one message through the importer's logger with
 * status fmi2Error and returns fmi2Error; the instance then refuses further calls until reset.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmi2Functions.h"
#include "fmu_instance.h"

typedef struct {
    fmi2CallbackFunctions cb;
    char name[128];
    int logging_on;
} Fmi2Data;

static void log_error(Instance *m, const char *message) {
    Fmi2Data *w = (Fmi2Data *)m->wrapper;
    if (w->cb.logger) w->cb.logger(w->cb.componentEnvironment, w->name, fmi2Error, "logStatusError", "%s", message);
}

#define INST ((Instance *)c)
#define CHECK_ALIVE(fn)                                                        \
    do {                                                                       \
        if (!vei_is_live(c)) return fmi2Error; /* NULL, freed or not ours */   \
        if (INST->failed) {                                                    \
            log_error(INST, fn ": the instance is in error state (reset it)"); \
            return fmi2Error;                                                  \
        }                                                                      \
    } while (0)

const char *fmi2GetTypesPlatform(void) { return fmi2TypesPlatform; }
const char *fmi2GetVersion(void) { return fmi2Version; }

fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean loggingOn, size_t n, const fmi2String categories[]) {
    (void)n, (void)categories;
    if (!vei_is_live(c)) return fmi2Error;
    ((Fmi2Data *)INST->wrapper)->logging_on = loggingOn;
    return fmi2OK;
}

fmi2Component fmi2Instantiate(fmi2String instanceName, fmi2Type fmuType, fmi2String fmuGUID,
                              fmi2String fmuResourceLocation, const fmi2CallbackFunctions *functions,
                              fmi2Boolean visible, fmi2Boolean loggingOn) {
    (void)fmuResourceLocation, (void)visible;
    if (functions == NULL) return NULL;
    const char *name = instanceName ? instanceName : "";
    if (fmuType != fmi2CoSimulation || fmuGUID == NULL || strcmp(fmuGUID, MODEL_GUID) != 0) {
        if (functions->logger)
            functions->logger(functions->componentEnvironment, name, fmi2Error, "logStatusError",
                              fmuType != fmi2CoSimulation ? "only co-simulation is supported"
                                                          : "GUID does not match this binary (" MODEL_GUID ")");
        return NULL;
    }
    Instance *m = (Instance *)calloc(1, sizeof(Instance));
    Fmi2Data *w = (Fmi2Data *)calloc(1, sizeof(Fmi2Data));
    if (m == NULL || w == NULL) {
        free(m), free(w);
        return NULL;
    }
    w->cb = *functions;
    snprintf(w->name, sizeof w->name, "%s", name);
    w->logging_on = loggingOn;
    m->wrapper = w;
    m->log_error = log_error;
    vei_set_start_values(m);
    vei_register(m);
    return m;
}

void fmi2FreeInstance(fmi2Component c) {
    if (!vei_unregister((Instance *)c)) return; /* NULL, or freed already: nothing to do */
    free(INST->wrapper);
    free(c);
}

fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean toleranceDefined, fmi2Real tolerance,
                               fmi2Real startTime, fmi2Boolean stopTimeDefined, fmi2Real stopTime) {
    (void)toleranceDefined, (void)tolerance, (void)stopTimeDefined, (void)stopTime;
    CHECK_ALIVE("fmi2SetupExperiment");
    if (vei_require(INST, "fmi2SetupExperiment", VEI_IN(VEI_STATE_INSTANTIATED))) return fmi2Error;
    if (!isfinite(startTime)) {
        vei_fail(INST, "fmi2SetupExperiment: startTime %g is not finite", startTime);
        return fmi2Error;
    }
    INST->time = startTime;
    return fmi2OK;
}

fmi2Status fmi2EnterInitializationMode(fmi2Component c) {
    CHECK_ALIVE("fmi2EnterInitializationMode");
    if (vei_require(INST, "fmi2EnterInitializationMode", VEI_IN(VEI_STATE_INSTANTIATED))) return fmi2Error;
    INST->state = VEI_STATE_INITIALIZATION;
    return fmi2OK;
}

fmi2Status fmi2ExitInitializationMode(fmi2Component c) {
    CHECK_ALIVE("fmi2ExitInitializationMode");
    if (vei_require(INST, "fmi2ExitInitializationMode", VEI_IN(VEI_STATE_INITIALIZATION))) return fmi2Error;
    if (model_initialize(INST) != 0) return fmi2Error;
    INST->initialized = 1;
    INST->state = VEI_STATE_STEPPING;
    return fmi2OK;
}

fmi2Status fmi2Terminate(fmi2Component c) {
    CHECK_ALIVE("fmi2Terminate");
    if (vei_require(INST, "fmi2Terminate", VEI_IN(VEI_STATE_STEPPING))) return fmi2Error;
    INST->state = VEI_STATE_TERMINATED;
    return fmi2OK;
}

fmi2Status fmi2Reset(fmi2Component c) {
    if (!vei_is_live(c)) return fmi2Error;
    vei_set_start_values(INST); /* back to instantiated, error state cleared */
    return fmi2OK;
}

/* ---- getters and setters ------------------------------------------------------------------- */
#define RANGE_CHECK(fn, vr, count)                                                         \
    if ((vr) >= (count)) {                                                                 \
        vei_fail(INST, fn ": value reference %u is not a variable of this type", (unsigned)(vr)); \
        return fmi2Error;                                                                  \
    }

fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Real value[]) {
    CHECK_ALIVE("fmi2GetReal");
    if (nvr > 0 && (vr == NULL || value == NULL)) return fmi2Error;
    for (size_t k = 0; k < nvr; k++) {
        RANGE_CHECK("fmi2GetReal", vr[k], N_REAL);
        value[k] = INST->r[vr[k]];
    }
    return fmi2OK;
}

fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Integer value[]) {
    CHECK_ALIVE("fmi2GetInteger");
    if (nvr > 0 && (vr == NULL || value == NULL)) return fmi2Error;
    for (size_t k = 0; k < nvr; k++) {
        RANGE_CHECK("fmi2GetInteger", vr[k], N_INTEGER);
        value[k] = INST->i[vr[k]];
    }
    return fmi2OK;
}

fmi2Status fmi2GetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Boolean value[]) {
    CHECK_ALIVE("fmi2GetBoolean");
    if (nvr > 0 && (vr == NULL || value == NULL)) return fmi2Error;
    for (size_t k = 0; k < nvr; k++) {
        RANGE_CHECK("fmi2GetBoolean", vr[k], N_BOOLEAN);
        value[k] = INST->b[vr[k]] ? fmi2True : fmi2False;
    }
    return fmi2OK;
}

fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2String value[]) {
    CHECK_ALIVE("fmi2GetString");
    if (nvr > 0 && (vr == NULL || value == NULL)) return fmi2Error;
    for (size_t k = 0; k < nvr; k++) {
        RANGE_CHECK("fmi2GetString", vr[k], N_STRING);
        value[k] = INST->s[vr[k]];
    }
    return fmi2OK;
}

#define SETTABLE_CHECK(fn, causality_table, vr)                                                      \
    if (!vei_settable(INST, causality_table[vr])) {                                                  \
        vei_fail(INST, fn ": value reference %u cannot be set now (%s)", (unsigned)(vr),             \
                 causality_table[vr] == 'o' ? "an output" : "a fixed parameter after initialization"); \
        return fmi2Error;                                                                            \
    }

fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2Real value[]) {
    CHECK_ALIVE("fmi2SetReal");
    if (vei_require(INST, "fmi2SetReal", VEI_ANY & ~VEI_IN(VEI_STATE_TERMINATED))) return fmi2Error;
    if (nvr > 0 && (vr == NULL || value == NULL)) return fmi2Error;
    for (size_t k = 0; k < nvr; k++) {
        RANGE_CHECK("fmi2SetReal", vr[k], N_REAL);
        SETTABLE_CHECK("fmi2SetReal", REAL_CAUSALITY, vr[k]);
        if (!isfinite(value[k])) {
            vei_fail(INST, "fmi2SetReal: %s = %g is not a finite number", real_name(vr[k]), value[k]);
            return fmi2Error;
        }
        INST->r[vr[k]] = value[k];
    }
    return fmi2OK;
}

fmi2Status fmi2SetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2Integer value[]) {
    CHECK_ALIVE("fmi2SetInteger");
    if (vei_require(INST, "fmi2SetInteger", VEI_ANY & ~VEI_IN(VEI_STATE_TERMINATED))) return fmi2Error;
    if (nvr > 0 && (vr == NULL || value == NULL)) return fmi2Error;
    for (size_t k = 0; k < nvr; k++) {
        RANGE_CHECK("fmi2SetInteger", vr[k], N_INTEGER);
        SETTABLE_CHECK("fmi2SetInteger", INTEGER_CAUSALITY, vr[k]);
        INST->i[vr[k]] = value[k];
    }
    return fmi2OK;
}

fmi2Status fmi2SetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2Boolean value[]) {
    CHECK_ALIVE("fmi2SetBoolean");
    if (vei_require(INST, "fmi2SetBoolean", VEI_ANY & ~VEI_IN(VEI_STATE_TERMINATED))) return fmi2Error;
    if (nvr > 0 && (vr == NULL || value == NULL)) return fmi2Error;
    for (size_t k = 0; k < nvr; k++) {
        RANGE_CHECK("fmi2SetBoolean", vr[k], N_BOOLEAN);
        SETTABLE_CHECK("fmi2SetBoolean", BOOLEAN_CAUSALITY, vr[k]);
        INST->b[vr[k]] = value[k] != fmi2False;
    }
    return fmi2OK;
}

fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2String value[]) {
    CHECK_ALIVE("fmi2SetString");
    if (vei_require(INST, "fmi2SetString", VEI_ANY & ~VEI_IN(VEI_STATE_TERMINATED))) return fmi2Error;
    if (nvr > 0 && (vr == NULL || value == NULL)) return fmi2Error;
    for (size_t k = 0; k < nvr; k++) {
        RANGE_CHECK("fmi2SetString", vr[k], N_STRING);
        SETTABLE_CHECK("fmi2SetString", STRING_CAUSALITY, vr[k]);
        if (value[k] == NULL || strlen(value[k]) >= VEI_STRING_CAPACITY) {
            vei_fail(INST, "fmi2SetString: value reference %u: NULL or longer than %d characters", (unsigned)vr[k],
                     VEI_STRING_CAPACITY - 1);
            return fmi2Error;
        }
        strcpy(INST->s[vr[k]], value[k]);
    }
    return fmi2OK;
}

/* ---- co-simulation ------------------------------------------------------------------------- */
fmi2Status fmi2DoStep(fmi2Component c, fmi2Real currentCommunicationPoint, fmi2Real communicationStepSize,
                      fmi2Boolean noSetFMUStatePriorToCurrentPoint) {
    (void)noSetFMUStatePriorToCurrentPoint;
    CHECK_ALIVE("fmi2DoStep");
    if (vei_require(INST, "fmi2DoStep", VEI_IN(VEI_STATE_STEPPING))) return fmi2Error;
    if (!(communicationStepSize > 0) || !isfinite(currentCommunicationPoint)) {
        vei_fail(INST, "fmi2DoStep: the step size must be positive (got %g)", communicationStepSize);
        return fmi2Error;
    }
    if (model_do_step(INST, currentCommunicationPoint, communicationStepSize) != 0) return fmi2Error;
    INST->time = currentCommunicationPoint + communicationStepSize;
    return fmi2OK;
}

fmi2Status fmi2CancelStep(fmi2Component c) { return c ? fmi2Error : fmi2Error; }

fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind s, fmi2Real *value) {
    if (!vei_is_live(c) || s != fmi2LastSuccessfulTime || value == NULL) return fmi2Discard;
    *value = INST->time;
    return fmi2OK;
}

/* ---- optional capabilities this FMU does not declare (canGetAndSetFMUstate etc. are false) ---- */
static fmi2Status unsupported(fmi2Component c, const char *fn) {
    if (c != NULL) {
        char msg[128];
        snprintf(msg, sizeof msg, "%s is not supported by this FMU", fn);
        log_error(INST, msg);
    }
    return fmi2Error;
}
#include "fmi2_unsupported.h"
