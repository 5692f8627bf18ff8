/* fmi3_wrapper.c: the FMI 3.0 co-simulation interface over a vei model (see fmu_instance.h).
 *
 * Value references are unique across types in FMI 3: Float64 first (the FMI 2 Real references), then
 * Int32, Boolean and String, each offset by the counts before it. Arrays stay runs of scalars. Errors
 * are logged with fmi3Error and never abort the host; functions of interfaces this FMU does not
 * declare (model exchange, scheduled execution, clocks, FMU state) return fmi3Error.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmi3Functions.h"
#include "fmu_instance.h"

typedef struct {
    fmi3InstanceEnvironment env;
    fmi3LogMessageCallback log;
    char name[128];
} Fmi3Data;

#define OFF_INTEGER (N_REAL)
#define OFF_BOOLEAN (N_REAL + N_INTEGER)
#define OFF_STRING (N_REAL + N_INTEGER + N_BOOLEAN)

static void log_error(Instance *m, const char *message) {
    Fmi3Data *w = (Fmi3Data *)m->wrapper;
    if (w->log) w->log(w->env, fmi3Error, "logStatusError", message);
}

static fmi3Status unsupported(fmi3Instance instance, const char *fn) {
    if (instance != NULL) {
        char msg[128];
        snprintf(msg, sizeof msg, "%s is not supported by this FMU", fn);
        log_error((Instance *)instance, msg);
    }
    return fmi3Error;
}

#define INST ((Instance *)instance)
#define CHECK_ALIVE(fn)                                                        \
    do {                                                                       \
        if (!vei_is_live(instance)) return fmi3Error; /* NULL, freed, not ours */ \
        if (INST->failed) {                                                    \
            log_error(INST, fn ": the instance is in error state (reset it)"); \
            return fmi3Error;                                                  \
        }                                                                      \
    } while (0)

const char *fmi3GetVersion(void) { return fmi3Version; }

fmi3Status fmi3SetDebugLogging(fmi3Instance instance, fmi3Boolean loggingOn, size_t n, const fmi3String c[]) {
    (void)loggingOn, (void)n, (void)c;
    return vei_is_live(instance) ? fmi3OK : fmi3Error;
}

fmi3Instance fmi3InstantiateCoSimulation(fmi3String instanceName, fmi3String instantiationToken,
                                         fmi3String resourcePath, fmi3Boolean visible, fmi3Boolean loggingOn,
                                         fmi3Boolean eventModeUsed, fmi3Boolean earlyReturnAllowed,
                                         const fmi3ValueReference requiredIntermediateVariables[],
                                         size_t nRequiredIntermediateVariables,
                                         fmi3InstanceEnvironment instanceEnvironment,
                                         fmi3LogMessageCallback logMessage,
                                         fmi3IntermediateUpdateCallback intermediateUpdate) {
    (void)resourcePath, (void)visible, (void)loggingOn, (void)earlyReturnAllowed;
    (void)requiredIntermediateVariables, (void)nRequiredIntermediateVariables, (void)intermediateUpdate;
    const char *name = instanceName ? instanceName : "";
    if (instantiationToken == NULL || strcmp(instantiationToken, MODEL_GUID) != 0 || eventModeUsed) {
        if (logMessage)
            logMessage(instanceEnvironment, fmi3Error, "logStatusError",
                       eventModeUsed ? "event mode is not supported"
                                     : "instantiation token does not match this binary (" MODEL_GUID ")");
        return NULL;
    }
    Instance *m = (Instance *)calloc(1, sizeof(Instance));
    Fmi3Data *w = (Fmi3Data *)calloc(1, sizeof(Fmi3Data));
    if (m == NULL || w == NULL) {
        free(m), free(w);
        return NULL;
    }
    w->env = instanceEnvironment;
    w->log = logMessage;
    snprintf(w->name, sizeof w->name, "%s", name);
    m->wrapper = w;
    m->log_error = log_error;
    vei_set_start_values(m);
    vei_register(m);
    return m;
}

void fmi3FreeInstance(fmi3Instance instance) {
    if (!vei_unregister((Instance *)instance)) return; /* NULL, or freed already: nothing to do */
    free(INST->wrapper);
    free(instance);
}

fmi3Status fmi3EnterInitializationMode(fmi3Instance instance, fmi3Boolean toleranceDefined, fmi3Float64 tolerance,
                                       fmi3Float64 startTime, fmi3Boolean stopTimeDefined, fmi3Float64 stopTime) {
    (void)toleranceDefined, (void)tolerance, (void)stopTimeDefined, (void)stopTime;
    CHECK_ALIVE("fmi3EnterInitializationMode");
    if (vei_require(INST, "fmi3EnterInitializationMode", VEI_IN(VEI_STATE_INSTANTIATED))) return fmi3Error;
    if (!isfinite(startTime)) {
        vei_fail(INST, "fmi3EnterInitializationMode: startTime %g is not finite", startTime);
        return fmi3Error;
    }
    INST->time = startTime;
    INST->state = VEI_STATE_INITIALIZATION;
    return fmi3OK;
}

fmi3Status fmi3ExitInitializationMode(fmi3Instance instance) {
    CHECK_ALIVE("fmi3ExitInitializationMode");
    if (vei_require(INST, "fmi3ExitInitializationMode", VEI_IN(VEI_STATE_INITIALIZATION))) return fmi3Error;
    if (model_initialize(INST) != 0) return fmi3Error;
    INST->initialized = 1;
    INST->state = VEI_STATE_STEPPING; /* (no event mode: straight to step mode) */
    return fmi3OK;
}

fmi3Status fmi3EnterStepMode(fmi3Instance instance) {
    CHECK_ALIVE("fmi3EnterStepMode");
    if (vei_require(INST, "fmi3EnterStepMode", VEI_IN(VEI_STATE_STEPPING))) return fmi3Error;
    return fmi3OK;
}

fmi3Status fmi3Terminate(fmi3Instance instance) {
    CHECK_ALIVE("fmi3Terminate");
    if (vei_require(INST, "fmi3Terminate", VEI_IN(VEI_STATE_STEPPING))) return fmi3Error;
    INST->state = VEI_STATE_TERMINATED;
    return fmi3OK;
}

fmi3Status fmi3Reset(fmi3Instance instance) {
    if (!vei_is_live(instance)) return fmi3Error;
    vei_set_start_values(INST); /* back to instantiated, error state cleared */
    return fmi3OK;
}

#define LOCAL(fn, vr, offset, count)                                                                       \
    unsigned local = (unsigned)(vr) - (offset);                                                          \
    if ((vr) < (offset) || local >= (count)) {                                                             \
        vei_fail(INST, fn ": value reference %u is not a variable of this type", (unsigned)(vr));         \
        return fmi3Error;                                                                                  \
    }

#define SETTABLE(fn, table, vr)                                                                            \
    if (!vei_settable(INST, table[local])) {                                                               \
        vei_fail(INST, fn ": value reference %u cannot be set now (%s)", (unsigned)(vr),                   \
                 table[local] == 'o' ? "an output" : "a fixed parameter after initialization");           \
        return fmi3Error;                                                                                  \
    }

fmi3Status fmi3GetFloat64(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, fmi3Float64 values[],
                          size_t nValues) {
    CHECK_ALIVE("fmi3GetFloat64");
    if (nValues < nvr) return unsupported(instance, "fmi3GetFloat64 with arrays");
    for (size_t k = 0; k < nvr; k++) {
        if (vr[k] == OFF_STRING + N_STRING) { /* the independent variable */
            values[k] = INST->time;
            continue;
        }
        LOCAL("fmi3GetFloat64", vr[k], 0, N_REAL);
        values[k] = INST->r[local];
    }
    return fmi3OK;
}

fmi3Status fmi3SetFloat64(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr,
                          const fmi3Float64 values[], size_t nValues) {
    CHECK_ALIVE("fmi3SetFloat64");
    if (vei_require(INST, "fmi3SetFloat64", VEI_ANY & ~VEI_IN(VEI_STATE_TERMINATED))) return fmi3Error;
    if (nValues < nvr) return unsupported(instance, "fmi3SetFloat64 with arrays");
    for (size_t k = 0; k < nvr; k++) {
        LOCAL("fmi3SetFloat64", vr[k], 0, N_REAL);
        SETTABLE("fmi3SetFloat64", REAL_CAUSALITY, vr[k]);
        if (!isfinite(values[k])) {
            vei_fail(INST, "fmi3SetFloat64: %s = %g is not a finite number", real_name(local), values[k]);
            return fmi3Error;
        }
        INST->r[local] = values[k];
    }
    return fmi3OK;
}

fmi3Status fmi3GetInt32(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, fmi3Int32 values[],
                        size_t nValues) {
    CHECK_ALIVE("fmi3GetInt32");
    if (nValues < nvr) return unsupported(instance, "fmi3GetInt32 with arrays");
    for (size_t k = 0; k < nvr; k++) {
        LOCAL("fmi3GetInt32", vr[k], OFF_INTEGER, N_INTEGER);
        values[k] = INST->i[local];
    }
    return fmi3OK;
}

fmi3Status fmi3SetInt32(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, const fmi3Int32 values[],
                        size_t nValues) {
    CHECK_ALIVE("fmi3SetInt32");
    if (vei_require(INST, "fmi3SetInt32", VEI_ANY & ~VEI_IN(VEI_STATE_TERMINATED))) return fmi3Error;
    if (nValues < nvr) return unsupported(instance, "fmi3SetInt32 with arrays");
    for (size_t k = 0; k < nvr; k++) {
        LOCAL("fmi3SetInt32", vr[k], OFF_INTEGER, N_INTEGER);
        SETTABLE("fmi3SetInt32", INTEGER_CAUSALITY, vr[k]);
        INST->i[local] = values[k];
    }
    return fmi3OK;
}

fmi3Status fmi3GetBoolean(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, fmi3Boolean values[],
                          size_t nValues) {
    CHECK_ALIVE("fmi3GetBoolean");
    if (nValues < nvr) return unsupported(instance, "fmi3GetBoolean with arrays");
    for (size_t k = 0; k < nvr; k++) {
        LOCAL("fmi3GetBoolean", vr[k], OFF_BOOLEAN, N_BOOLEAN);
        values[k] = INST->b[local] != 0;
    }
    return fmi3OK;
}

fmi3Status fmi3SetBoolean(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr,
                          const fmi3Boolean values[], size_t nValues) {
    CHECK_ALIVE("fmi3SetBoolean");
    if (vei_require(INST, "fmi3SetBoolean", VEI_ANY & ~VEI_IN(VEI_STATE_TERMINATED))) return fmi3Error;
    if (nValues < nvr) return unsupported(instance, "fmi3SetBoolean with arrays");
    for (size_t k = 0; k < nvr; k++) {
        LOCAL("fmi3SetBoolean", vr[k], OFF_BOOLEAN, N_BOOLEAN);
        SETTABLE("fmi3SetBoolean", BOOLEAN_CAUSALITY, vr[k]);
        INST->b[local] = values[k] ? 1 : 0;
    }
    return fmi3OK;
}

fmi3Status fmi3GetString(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, fmi3String values[],
                         size_t nValues) {
    CHECK_ALIVE("fmi3GetString");
    if (nValues < nvr) return unsupported(instance, "fmi3GetString with arrays");
    for (size_t k = 0; k < nvr; k++) {
        LOCAL("fmi3GetString", vr[k], OFF_STRING, N_STRING);
        values[k] = INST->s[local];
    }
    return fmi3OK;
}

fmi3Status fmi3SetString(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, const fmi3String values[],
                         size_t nValues) {
    CHECK_ALIVE("fmi3SetString");
    if (vei_require(INST, "fmi3SetString", VEI_ANY & ~VEI_IN(VEI_STATE_TERMINATED))) return fmi3Error;
    if (nValues < nvr) return unsupported(instance, "fmi3SetString with arrays");
    for (size_t k = 0; k < nvr; k++) {
        LOCAL("fmi3SetString", vr[k], OFF_STRING, N_STRING);
        SETTABLE("fmi3SetString", STRING_CAUSALITY, vr[k]);
        if (values[k] == NULL || strlen(values[k]) >= VEI_STRING_CAPACITY) {
            vei_fail(INST, "fmi3SetString: value reference %u: NULL or longer than %d characters", (unsigned)vr[k],
                     VEI_STRING_CAPACITY - 1);
            return fmi3Error;
        }
        strcpy(INST->s[local], values[k]);
    }
    return fmi3OK;
}

fmi3Status fmi3DoStep(fmi3Instance instance, fmi3Float64 currentCommunicationPoint,
                      fmi3Float64 communicationStepSize, fmi3Boolean noSetFMUStatePriorToCurrentPoint,
                      fmi3Boolean *eventHandlingNeeded, fmi3Boolean *terminateSimulation, fmi3Boolean *earlyReturn,
                      fmi3Float64 *lastSuccessfulTime) {
    (void)noSetFMUStatePriorToCurrentPoint;
    CHECK_ALIVE("fmi3DoStep");
    if (vei_require(INST, "fmi3DoStep", VEI_IN(VEI_STATE_STEPPING))) return fmi3Error;
    if (eventHandlingNeeded) *eventHandlingNeeded = fmi3False;
    if (terminateSimulation) *terminateSimulation = fmi3False;
    if (earlyReturn) *earlyReturn = fmi3False;
    if (!INST->initialized) {
        vei_fail(INST, "fmi3DoStep: called before fmi3ExitInitializationMode");
        return fmi3Error;
    }
    if (!(communicationStepSize > 0) || !isfinite(currentCommunicationPoint)) {
        vei_fail(INST, "fmi3DoStep: the step size must be positive (got %g)", communicationStepSize);
        return fmi3Error;
    }
    if (model_do_step(INST, currentCommunicationPoint, communicationStepSize) != 0) return fmi3Error;
    INST->time = currentCommunicationPoint + communicationStepSize;
    if (lastSuccessfulTime) *lastSuccessfulTime = INST->time;
    return fmi3OK;
}

/* ---- interfaces and capabilities this FMU does not declare ------------------------------------ */
fmi3Instance fmi3InstantiateModelExchange(fmi3String instanceName, fmi3String instantiationToken, fmi3String resourcePath, fmi3Boolean visible, fmi3Boolean loggingOn, fmi3InstanceEnvironment instanceEnvironment, fmi3LogMessageCallback logMessage) {
    return NULL;
}

fmi3Instance fmi3InstantiateScheduledExecution(fmi3String instanceName, fmi3String instantiationToken, fmi3String resourcePath, fmi3Boolean visible, fmi3Boolean loggingOn, fmi3InstanceEnvironment instanceEnvironment, fmi3LogMessageCallback logMessage, fmi3ClockUpdateCallback clockUpdate, fmi3LockPreemptionCallback lockPreemption, fmi3UnlockPreemptionCallback unlockPreemption) {
    return NULL;
}

fmi3Status fmi3EnterEventMode(fmi3Instance instance) {
    return unsupported(instance, "fmi3EnterEventMode");
}

fmi3Status fmi3GetFloat32(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences, fmi3Float32 values[], size_t nValues) {
    return unsupported(instance, "fmi3GetFloat32");
}

fmi3Status fmi3GetInt8(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences, fmi3Int8 values[], size_t nValues) {
    return unsupported(instance, "fmi3GetInt8");
}

fmi3Status fmi3GetUInt8(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences, fmi3UInt8 values[], size_t nValues) {
    return unsupported(instance, "fmi3GetUInt8");
}

fmi3Status fmi3GetInt16(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences, fmi3Int16 values[], size_t nValues) {
    return unsupported(instance, "fmi3GetInt16");
}

fmi3Status fmi3GetUInt16(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences, fmi3UInt16 values[], size_t nValues) {
    return unsupported(instance, "fmi3GetUInt16");
}

fmi3Status fmi3GetUInt32(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences, fmi3UInt32 values[], size_t nValues) {
    return unsupported(instance, "fmi3GetUInt32");
}

fmi3Status fmi3GetInt64(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences, fmi3Int64 values[], size_t nValues) {
    return unsupported(instance, "fmi3GetInt64");
}

fmi3Status fmi3GetUInt64(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences, fmi3UInt64 values[], size_t nValues) {
    return unsupported(instance, "fmi3GetUInt64");
}

fmi3Status fmi3GetBinary(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences, size_t valueSizes[], fmi3Binary values[], size_t nValues) {
    return unsupported(instance, "fmi3GetBinary");
}

fmi3Status fmi3GetClock(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences, fmi3Clock values[]) {
    return unsupported(instance, "fmi3GetClock");
}

fmi3Status fmi3SetFloat32(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences, const fmi3Float32 values[], size_t nValues) {
    return unsupported(instance, "fmi3SetFloat32");
}

fmi3Status fmi3SetInt8(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences, const fmi3Int8 values[], size_t nValues) {
    return unsupported(instance, "fmi3SetInt8");
}

fmi3Status fmi3SetUInt8(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences, const fmi3UInt8 values[], size_t nValues) {
    return unsupported(instance, "fmi3SetUInt8");
}

fmi3Status fmi3SetInt16(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences, const fmi3Int16 values[], size_t nValues) {
    return unsupported(instance, "fmi3SetInt16");
}

fmi3Status fmi3SetUInt16(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences, const fmi3UInt16 values[], size_t nValues) {
    return unsupported(instance, "fmi3SetUInt16");
}

fmi3Status fmi3SetUInt32(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences, const fmi3UInt32 values[], size_t nValues) {
    return unsupported(instance, "fmi3SetUInt32");
}

fmi3Status fmi3SetInt64(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences, const fmi3Int64 values[], size_t nValues) {
    return unsupported(instance, "fmi3SetInt64");
}

fmi3Status fmi3SetUInt64(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences, const fmi3UInt64 values[], size_t nValues) {
    return unsupported(instance, "fmi3SetUInt64");
}

fmi3Status fmi3SetBinary(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences, const size_t valueSizes[], const fmi3Binary values[], size_t nValues) {
    return unsupported(instance, "fmi3SetBinary");
}

fmi3Status fmi3SetClock(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences, const fmi3Clock values[]) {
    return unsupported(instance, "fmi3SetClock");
}

fmi3Status fmi3GetNumberOfVariableDependencies(fmi3Instance instance, fmi3ValueReference valueReference, size_t* nDependencies) {
    return unsupported(instance, "fmi3GetNumberOfVariableDependencies");
}

fmi3Status fmi3GetVariableDependencies(fmi3Instance instance, fmi3ValueReference dependent, size_t elementIndicesOfDependent[], fmi3ValueReference independents[], size_t elementIndicesOfIndependents[], fmi3DependencyKind dependencyKinds[], size_t nDependencies) {
    return unsupported(instance, "fmi3GetVariableDependencies");
}

fmi3Status fmi3GetFMUState(fmi3Instance instance, fmi3FMUState* FMUState) {
    return unsupported(instance, "fmi3GetFMUState");
}

fmi3Status fmi3SetFMUState(fmi3Instance instance, fmi3FMUState FMUState) {
    return unsupported(instance, "fmi3SetFMUState");
}

fmi3Status fmi3FreeFMUState(fmi3Instance instance, fmi3FMUState* FMUState) {
    return unsupported(instance, "fmi3FreeFMUState");
}

fmi3Status fmi3SerializedFMUStateSize(fmi3Instance instance, fmi3FMUState FMUState, size_t* size) {
    return unsupported(instance, "fmi3SerializedFMUStateSize");
}

fmi3Status fmi3SerializeFMUState(fmi3Instance instance, fmi3FMUState FMUState, fmi3Byte serializedState[], size_t size) {
    return unsupported(instance, "fmi3SerializeFMUState");
}

fmi3Status fmi3DeserializeFMUState(fmi3Instance instance, const fmi3Byte serializedState[], size_t size, fmi3FMUState* FMUState) {
    return unsupported(instance, "fmi3DeserializeFMUState");
}

fmi3Status fmi3GetDirectionalDerivative(fmi3Instance instance, const fmi3ValueReference unknowns[], size_t nUnknowns, const fmi3ValueReference knowns[], size_t nKnowns, const fmi3Float64 seed[], size_t nSeed, fmi3Float64 sensitivity[], size_t nSensitivity) {
    return unsupported(instance, "fmi3GetDirectionalDerivative");
}

fmi3Status fmi3GetAdjointDerivative(fmi3Instance instance, const fmi3ValueReference unknowns[], size_t nUnknowns, const fmi3ValueReference knowns[], size_t nKnowns, const fmi3Float64 seed[], size_t nSeed, fmi3Float64 sensitivity[], size_t nSensitivity) {
    return unsupported(instance, "fmi3GetAdjointDerivative");
}

fmi3Status fmi3EnterConfigurationMode(fmi3Instance instance) {
    return unsupported(instance, "fmi3EnterConfigurationMode");
}

fmi3Status fmi3ExitConfigurationMode(fmi3Instance instance) {
    return unsupported(instance, "fmi3ExitConfigurationMode");
}

fmi3Status fmi3GetIntervalDecimal(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences, fmi3Float64 intervals[], fmi3IntervalQualifier qualifiers[]) {
    return unsupported(instance, "fmi3GetIntervalDecimal");
}

fmi3Status fmi3GetIntervalFraction(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences, fmi3UInt64 counters[], fmi3UInt64 resolutions[], fmi3IntervalQualifier qualifiers[]) {
    return unsupported(instance, "fmi3GetIntervalFraction");
}

fmi3Status fmi3GetShiftDecimal(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences, fmi3Float64 shifts[]) {
    return unsupported(instance, "fmi3GetShiftDecimal");
}

fmi3Status fmi3GetShiftFraction(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences, fmi3UInt64 counters[], fmi3UInt64 resolutions[]) {
    return unsupported(instance, "fmi3GetShiftFraction");
}

fmi3Status fmi3SetIntervalDecimal(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences, const fmi3Float64 intervals[]) {
    return unsupported(instance, "fmi3SetIntervalDecimal");
}

fmi3Status fmi3SetIntervalFraction(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences, const fmi3UInt64 counters[], const fmi3UInt64 resolutions[]) {
    return unsupported(instance, "fmi3SetIntervalFraction");
}

fmi3Status fmi3SetShiftDecimal(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences, const fmi3Float64 shifts[]) {
    return unsupported(instance, "fmi3SetShiftDecimal");
}

fmi3Status fmi3SetShiftFraction(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences, const fmi3UInt64 counters[], const fmi3UInt64 resolutions[]) {
    return unsupported(instance, "fmi3SetShiftFraction");
}

fmi3Status fmi3EvaluateDiscreteStates(fmi3Instance instance) {
    return unsupported(instance, "fmi3EvaluateDiscreteStates");
}

fmi3Status fmi3UpdateDiscreteStates(fmi3Instance instance, fmi3Boolean* discreteStatesNeedUpdate, fmi3Boolean* terminateSimulation, fmi3Boolean* nominalsOfContinuousStatesChanged, fmi3Boolean* valuesOfContinuousStatesChanged, fmi3Boolean* nextEventTimeDefined, fmi3Float64* nextEventTime) {
    return unsupported(instance, "fmi3UpdateDiscreteStates");
}

fmi3Status fmi3EnterContinuousTimeMode(fmi3Instance instance) {
    return unsupported(instance, "fmi3EnterContinuousTimeMode");
}

fmi3Status fmi3CompletedIntegratorStep(fmi3Instance instance, fmi3Boolean noSetFMUStatePriorToCurrentPoint, fmi3Boolean* enterEventMode, fmi3Boolean* terminateSimulation) {
    return unsupported(instance, "fmi3CompletedIntegratorStep");
}

fmi3Status fmi3SetTime(fmi3Instance instance, fmi3Float64 time) {
    return unsupported(instance, "fmi3SetTime");
}

fmi3Status fmi3SetContinuousStates(fmi3Instance instance, const fmi3Float64 continuousStates[], size_t nContinuousStates) {
    return unsupported(instance, "fmi3SetContinuousStates");
}

fmi3Status fmi3GetContinuousStateDerivatives(fmi3Instance instance, fmi3Float64 derivatives[], size_t nContinuousStates) {
    return unsupported(instance, "fmi3GetContinuousStateDerivatives");
}

fmi3Status fmi3GetEventIndicators(fmi3Instance instance, fmi3Float64 eventIndicators[], size_t nEventIndicators) {
    return unsupported(instance, "fmi3GetEventIndicators");
}

fmi3Status fmi3GetContinuousStates(fmi3Instance instance, fmi3Float64 continuousStates[], size_t nContinuousStates) {
    return unsupported(instance, "fmi3GetContinuousStates");
}

fmi3Status fmi3GetNominalsOfContinuousStates(fmi3Instance instance, fmi3Float64 nominals[], size_t nContinuousStates) {
    return unsupported(instance, "fmi3GetNominalsOfContinuousStates");
}

fmi3Status fmi3GetNumberOfEventIndicators(fmi3Instance instance, size_t* nEventIndicators) {
    return unsupported(instance, "fmi3GetNumberOfEventIndicators");
}

fmi3Status fmi3GetNumberOfContinuousStates(fmi3Instance instance, size_t* nContinuousStates) {
    return unsupported(instance, "fmi3GetNumberOfContinuousStates");
}

fmi3Status fmi3GetOutputDerivatives(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences, const fmi3Int32 orders[], fmi3Float64 values[], size_t nValues) {
    return unsupported(instance, "fmi3GetOutputDerivatives");
}

fmi3Status fmi3ActivateModelPartition(fmi3Instance instance, fmi3ValueReference clockReference, fmi3Float64 activationTime) {
    return unsupported(instance, "fmi3ActivateModelPartition");
}
