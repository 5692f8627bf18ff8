/* osmp_wrapper.c: vei's e-scooter rider, or its planner driving the ego, as an ASAM OSI traffic
 * participant packaged as OSMP (FMI 2.0 co-simulation).
 *
 * Variables (Integer, value references as in the modelDescription vei_scenario.fmu.osmp_native writes):
 *   0..2  OSMPSensorViewIn.base.lo, .base.hi, .size      input   osi3::SensorView
 *   3..5  OSMPTrafficUpdateOut.base.lo, .base.hi, .size  output  osi3::TrafficUpdate
 *   6     ego_id (the rider) or threat_id (the planner)  parameter: the other object's id
 * and the model's parameters it declares (Real, Boolean and String, value references from 0 in each
 * type; osmp_config.h maps them to the model's), fixed: set before initialization ends.
 * A message's address is (base.hi << 32) | base.lo, each half a signed 32-bit integer.
 *
 * Each doStep(t, h) decodes the SensorView (protobuf-c, the C code generated from OSI's schema),
 * finds the host (host_vehicle_id) and the object the model watches (the moving object whose
 * source_reference names the scenario's entity OSMP_OTHER_ENTITY, else the one with the parameter's
 * id), steps the model as vei's FMU loop couples it, and encodes a TrafficUpdate: the host object as
 * the SensorView gave it, with the model's new position, yaw, velocity and acceleration. The
 * encoded update stays valid until the second doStep after the one that wrote it (OSMP's rule for
 * outputs; three buffers in turn). Nothing is kept of the SensorView after the step.
 */
#include <math.h>
#include <pthread.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmi2Functions.h"
#include "osi3/osi_trafficupdate.pb-c.h"
#include "vei_osmp_view.pb-c.h" /* the fields of a SensorView the participant reads */
#include "osmp_config.h" /* generated: identifier, GUID, OSI version, which models, value references */
#include "osmp_model.h"

enum { SV_LO, SV_HI, SV_SIZE, TU_LO, TU_HI, TU_SIZE, OTHER_ID, N_INT };
static const char *const INT_NAME[N_INT] = {
    "OSMPSensorViewIn.base.lo",     "OSMPSensorViewIn.base.hi", "OSMPSensorViewIn.size", "OSMPTrafficUpdateOut.base.lo",
    "OSMPTrafficUpdateOut.base.hi", "OSMPTrafficUpdateOut.size", OSMP_OTHER_PARAMETER};
#define KEPT 3 /* output buffers in turn: the one written, and the two before it */

enum { INSTANTIATED, INITIALIZATION, STEPPING, TERMINATED };

#if OSMP_PLANNER
OSMP_MODEL_API(cap)
OSMP_MODEL_API(ego)
#else
OSMP_MODEL_API(sfm)
#endif

/* The decoded SensorView lives in an arena: one block, reused every step (a SensorView is thousands
 * of small messages, each a malloc and a free otherwise); a step that needs more chains blocks, and
 * the next one starts with a single block of their total size. */
typedef struct Block {
    struct Block *next;
    size_t size, used;
    unsigned char data[];
} Block;

static void *arena_alloc(void *arena, size_t n) {
    Block **head = (Block **)arena;
    n = (n + 15) & ~(size_t)15;
    if (*head == NULL || (*head)->used + n > (*head)->size) {
        size_t size = n > 65536 ? n : 65536;
        Block *b = (Block *)malloc(sizeof(Block) + size);
        if (b == NULL) return NULL;
        b->next = *head, b->size = size, b->used = 0;
        *head = b;
    }
    void *p = (*head)->data + (*head)->used;
    (*head)->used += n;
    return p;
}

static void arena_free(void *arena, void *p) { (void)arena, (void)p; }

static void arena_reset(Block **head) {
    if (*head == NULL) return;
    if ((*head)->next == NULL) {
        (*head)->used = 0;
        return;
    }
    size_t total = 0;
    for (Block *b = *head, *next; b != NULL; b = next) {
        next = b->next, total += b->size;
        free(b);
    }
    *head = NULL;
    if (arena_alloc(head, total) != NULL) (*head)->used = 0;
}

static void arena_drop(Block **head) {
    for (Block *b = *head, *next; b != NULL; b = next) {
        next = b->next;
        free(b);
    }
    *head = NULL;
}

typedef struct Participant Participant;
struct Participant {
    fmi2CallbackFunctions cb;
    char name[128];
    int ints[N_INT];
    int state;
    int failed;
    double time;
    void *model; /* the rider, or the vehicle the planner drives */
    void *cap;   /* the planner (OSMP_PLANNER) */
    Block *arena;
    uint8_t *out[KEPT];
    size_t out_capacity[KEPT];
    int next_out;
    Participant *next_live;
};

/* ---- live instances: a call on a freed (or foreign) pointer is refused without touching it ---- */
static pthread_mutex_t live_lock = PTHREAD_MUTEX_INITIALIZER;
static Participant *live_head = NULL;

static int is_live(const void *p) {
    int found = 0;
    if (p == NULL) return 0;
    pthread_mutex_lock(&live_lock);
    for (Participant *q = live_head; q != NULL; q = q->next_live)
        if ((const void *)q == p) found = 1;
    pthread_mutex_unlock(&live_lock);
    return found;
}

static int unregister(Participant *p) {
    int found = 0;
    pthread_mutex_lock(&live_lock);
    for (Participant **q = &live_head; *q != NULL; q = &(*q)->next_live)
        if (*q == p) {
            *q = p->next_live;
            found = 1;
            break;
        }
    pthread_mutex_unlock(&live_lock);
    return found;
}

/* ---- messages to the importer ---- */
static void say(Participant *p, fmi2Status status, const char *fmt, ...) {
    char msg[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    if (p->cb.logger)
        p->cb.logger(p->cb.componentEnvironment, p->name, status,
                     status == fmi2Warning ? "logStatusWarning" : "logStatusError", "%s", msg);
}

static fmi2Status fail(Participant *p, const char *fmt, ...) {
    char msg[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    p->failed = 1;
    say(p, fmi2Error, "%s", msg);
    return fmi2Error;
}

static void model_error(void *env, const char *message) {
    Participant *p = (Participant *)env;
    p->failed = 1;
    say(p, fmi2Error, "%s", message);
}

#define P ((Participant *)c)
#define CHECK_ALIVE(fn)                                                         \
    do {                                                                        \
        if (!is_live(c)) return fmi2Error;                                      \
        if (P->failed) return fail(P, "%s: the instance is in error state", fn); \
    } while (0)

static fmi2Status require(Participant *p, const char *fn, unsigned allowed) {
    static const char *const names[] = {"instantiated", "initialization mode", "step mode", "terminated"};
    if (allowed & (1u << p->state)) return fmi2OK;
    return fail(p, "%s: not allowed in state %s (the FMI state machine)", fn, names[p->state]);
}
#define IN(s) (1u << (s))

/* ---- the models ---- */
static void free_models(Participant *p) {
#if OSMP_PLANNER
    cap_osmp_model_free(p->cap);
    ego_osmp_model_free(p->model);
#else
    sfm_osmp_model_free(p->model);
#endif
    p->cap = p->model = NULL;
}

static int new_models(Participant *p) {
#if OSMP_PLANNER
    p->cap = cap_osmp_model_new(model_error, p);
    p->model = ego_osmp_model_new(model_error, p);
    return p->cap != NULL && p->model != NULL;
#else
    p->model = sfm_osmp_model_new(model_error, p);
    return p->model != NULL;
#endif
}

static int initialize_models(Participant *p) {
#if OSMP_PLANNER /* the planner starts from the vehicle's initial state, as the FMU loop connects them */
    if (ego_osmp_model_initialize(p->model) != 0) return 1;
    double *c = cap_osmp_model_reals(p->cap), *e = ego_osmp_model_reals(p->model);
    c[CAP_EGO_X] = e[EGO_X], c[CAP_EGO_Y] = e[EGO_Y], c[CAP_EGO_YAW] = e[EGO_YAW], c[CAP_EGO_SPEED] = e[EGO_SPEED];
    return cap_osmp_model_initialize(p->cap);
#else
    return sfm_osmp_model_initialize(p->model);
#endif
}

static double vx(const Osi3__Vector3d *v) { return v ? v->x : 0.0; }
static double vy(const Osi3__Vector3d *v) { return v ? v->y : 0.0; }

/* One step of the model from t to t + h, the other object as the SensorView shows it (NULL: not in
 * it, the model keeps its last view). out: x, y, yaw, speed, accel. */
static int advance(Participant *p, const Osi3__MovingObject *other, double t, double h, double out[5]) {
    const Osi3__BaseMoving *b = other ? other->base : NULL;
    double yaw = b && b->orientation ? b->orientation->yaw : 0.0;
#if OSMP_PLANNER
    double *c = cap_osmp_model_reals(p->cap), *e = ego_osmp_model_reals(p->model);
    c[CAP_EGO_X] = e[EGO_X], c[CAP_EGO_Y] = e[EGO_Y], c[CAP_EGO_YAW] = e[EGO_YAW], c[CAP_EGO_SPEED] = e[EGO_SPEED];
    if (other != NULL) {
        const Osi3__Vector3d *pos = b ? b->position : NULL, *vel = b ? b->velocity : NULL;
        c[CAP_THREAT_X] = vx(pos), c[CAP_THREAT_Y] = vy(pos), c[CAP_THREAT_YAW] = yaw;
        c[CAP_THREAT_SPEED] = vx(vel) * cos(yaw) + vy(vel) * sin(yaw);
    }
    if (cap_osmp_model_do_step(p->cap, t, h) != 0) return 1;
    e[EGO_A_CMD] = c[CAP_A_CMD];
    if (ego_osmp_model_do_step(p->model, t, h) != 0) return 1;
    out[0] = e[EGO_X], out[1] = e[EGO_Y], out[2] = e[EGO_YAW], out[3] = e[EGO_SPEED], out[4] = e[EGO_ACCEL];
#else
    double *r = sfm_osmp_model_reals(p->model);
    if (other != NULL) {
        const Osi3__Vector3d *pos = b ? b->position : NULL;
        r[SFM_EGO_X] = vx(pos), r[SFM_EGO_Y] = vy(pos), r[SFM_EGO_YAW] = yaw;
    }
    if (sfm_osmp_model_do_step(p->model, t, h) != 0) return 1;
    out[0] = r[SFM_X], out[1] = r[SFM_Y], out[2] = r[SFM_YAW], out[3] = r[SFM_SPEED], out[4] = r[SFM_ACCEL];
#endif
    return 0;
}

/* ---- FMI 2.0 ---- */
const char *fmi2GetTypesPlatform(void) { return fmi2TypesPlatform; }
const char *fmi2GetVersion(void) { return fmi2Version; }

fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean on, size_t n, const fmi2String categories[]) {
    (void)on, (void)n, (void)categories;
    return is_live(c) ? fmi2OK : fmi2Error;
}

fmi2Component fmi2Instantiate(fmi2String instanceName, fmi2Type fmuType, fmi2String fmuGUID,
                              fmi2String fmuResourceLocation, const fmi2CallbackFunctions *functions,
                              fmi2Boolean visible, fmi2Boolean loggingOn) {
    (void)fmuResourceLocation, (void)visible, (void)loggingOn;
    if (functions == NULL) return NULL;
    const char *name = instanceName ? instanceName : "";
    if (fmuType != fmi2CoSimulation || fmuGUID == NULL || strcmp(fmuGUID, OSMP_GUID) != 0) {
        if (functions->logger)
            functions->logger(functions->componentEnvironment, name, fmi2Error, "logStatusError",
                              fmuType != fmi2CoSimulation ? "only co-simulation is supported"
                                                          : "GUID does not match this binary (" OSMP_GUID ")");
        return NULL;
    }
    Participant *p = (Participant *)calloc(1, sizeof(Participant));
    if (p == NULL) return NULL;
    p->cb = *functions;
    snprintf(p->name, sizeof p->name, "%s", name);
    if (!new_models(p)) {
        free_models(p);
        free(p);
        return NULL;
    }
    p->state = INSTANTIATED;
    pthread_mutex_lock(&live_lock);
    p->next_live = live_head;
    live_head = p;
    pthread_mutex_unlock(&live_lock);
    return p;
}

void fmi2FreeInstance(fmi2Component c) {
    if (!unregister((Participant *)c)) return;
    free_models(P);
    for (int k = 0; k < KEPT; k++) free(P->out[k]);
    arena_drop(&P->arena);
    free(c);
}

fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean toleranceDefined, fmi2Real tolerance,
                               fmi2Real startTime, fmi2Boolean stopTimeDefined, fmi2Real stopTime) {
    (void)toleranceDefined, (void)tolerance, (void)stopTimeDefined, (void)stopTime;
    CHECK_ALIVE("fmi2SetupExperiment");
    if (require(P, "fmi2SetupExperiment", IN(INSTANTIATED))) return fmi2Error;
    P->time = startTime;
    return fmi2OK;
}

fmi2Status fmi2EnterInitializationMode(fmi2Component c) {
    CHECK_ALIVE("fmi2EnterInitializationMode");
    if (require(P, "fmi2EnterInitializationMode", IN(INSTANTIATED))) return fmi2Error;
    P->state = INITIALIZATION;
    return fmi2OK;
}

fmi2Status fmi2ExitInitializationMode(fmi2Component c) {
    CHECK_ALIVE("fmi2ExitInitializationMode");
    if (require(P, "fmi2ExitInitializationMode", IN(INITIALIZATION))) return fmi2Error;
    if (initialize_models(P) != 0) return fmi2Error;
    P->state = STEPPING;
    return fmi2OK;
}

fmi2Status fmi2Terminate(fmi2Component c) {
    CHECK_ALIVE("fmi2Terminate");
    if (require(P, "fmi2Terminate", IN(STEPPING))) return fmi2Error;
    P->state = TERMINATED;
    return fmi2OK;
}

fmi2Status fmi2Reset(fmi2Component c) {
    if (!is_live(c)) return fmi2Error;
    free_models(P);
    if (!new_models(P)) return fail(P, "fmi2Reset: out of memory");
    memset(P->ints, 0, sizeof P->ints);
    P->state = INSTANTIATED, P->failed = 0, P->time = 0.0;
    return fmi2OK;
}

fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Integer value[]) {
    CHECK_ALIVE("fmi2GetInteger");
    if (nvr > 0 && (vr == NULL || value == NULL)) return fmi2Error;
    for (size_t k = 0; k < nvr; k++) {
        if (vr[k] >= N_INT) return fail(P, "fmi2GetInteger: value reference %u is no Integer variable", (unsigned)vr[k]);
        value[k] = P->ints[vr[k]];
    }
    return fmi2OK;
}

fmi2Status fmi2SetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2Integer value[]) {
    CHECK_ALIVE("fmi2SetInteger");
    if (require(P, "fmi2SetInteger", IN(INSTANTIATED) | IN(INITIALIZATION) | IN(STEPPING))) return fmi2Error;
    if (nvr > 0 && (vr == NULL || value == NULL)) return fmi2Error;
    for (size_t k = 0; k < nvr; k++) {
        if (vr[k] >= N_INT) return fail(P, "fmi2SetInteger: value reference %u is no Integer variable", (unsigned)vr[k]);
        if (vr[k] >= TU_LO && vr[k] <= TU_SIZE) return fail(P, "fmi2SetInteger: %s is an output", INT_NAME[vr[k]]);
        if (vr[k] == OTHER_ID && P->state == STEPPING)
            return fail(P, "fmi2SetInteger: %s is a fixed parameter, set before initialization ends", INT_NAME[vr[k]]);
        P->ints[vr[k]] = value[k];
    }
    return fmi2OK;
}

/* ---- the declared parameters: the model's own variables (value references in osmp_config.h), set
 * before initialization ends ---- */
#if OSMP_PLANNER
#define PARAMS(p) ((p)->cap)
#define param_reals cap_osmp_model_reals
#define param_bools cap_osmp_model_bools
#define param_string cap_osmp_model_string
#define param_string_capacity cap_osmp_model_string_capacity
#else
#define PARAMS(p) ((p)->model)
#define param_reals sfm_osmp_model_reals
#define param_bools sfm_osmp_model_bools
#define param_string sfm_osmp_model_string
#define param_string_capacity sfm_osmp_model_string_capacity
#endif
static const int REAL_PARAM[] = OSMP_REAL_PARAMS, BOOLEAN_PARAM[] = OSMP_BOOLEAN_PARAMS, STRING_PARAM[] = OSMP_STRING_PARAMS;
static const char *const REAL_NAME[] = OSMP_REAL_NAMES, *const BOOLEAN_NAME[] = OSMP_BOOLEAN_NAMES,
                         *const STRING_NAME[] = OSMP_STRING_NAMES;

/* 0 when value reference vr is one of the n parameters of the type and may be set now; else says why */
static int settable(Participant *p, const char *fn, const char *type, fmi2ValueReference vr, int n,
                    const char *const names[]) {
    if ((int)vr >= n) return fail(p, "%s: value reference %u is no %s variable", fn, (unsigned)vr, type), 1;
    if (p->state != INSTANTIATED && p->state != INITIALIZATION)
        return fail(p, "%s: %s is a fixed parameter, set before initialization ends", fn, names[vr]), 1;
    return 0;
}

fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Real value[]) {
    CHECK_ALIVE("fmi2GetReal");
    if (nvr > 0 && (vr == NULL || value == NULL)) return fmi2Error;
    for (size_t k = 0; k < nvr; k++) {
        if ((int)vr[k] >= OSMP_N_REAL_PARAMS)
            return fail(P, "fmi2GetReal: value reference %u is no Real variable", (unsigned)vr[k]);
        value[k] = param_reals(PARAMS(P))[REAL_PARAM[vr[k]]];
    }
    return fmi2OK;
}

fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2Real value[]) {
    CHECK_ALIVE("fmi2SetReal");
    if (nvr > 0 && (vr == NULL || value == NULL)) return fmi2Error;
    for (size_t k = 0; k < nvr; k++) {
        if (settable(P, "fmi2SetReal", "Real", vr[k], OSMP_N_REAL_PARAMS, REAL_NAME)) return fmi2Error;
        if (!isfinite(value[k])) return fail(P, "fmi2SetReal: %s = %g is not finite", REAL_NAME[vr[k]], value[k]);
        param_reals(PARAMS(P))[REAL_PARAM[vr[k]]] = value[k];
    }
    return fmi2OK;
}

fmi2Status fmi2GetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Boolean value[]) {
    CHECK_ALIVE("fmi2GetBoolean");
    if (nvr > 0 && (vr == NULL || value == NULL)) return fmi2Error;
    for (size_t k = 0; k < nvr; k++) {
        if ((int)vr[k] >= OSMP_N_BOOLEAN_PARAMS)
            return fail(P, "fmi2GetBoolean: value reference %u is no Boolean variable", (unsigned)vr[k]);
        value[k] = param_bools(PARAMS(P))[BOOLEAN_PARAM[vr[k]]] ? fmi2True : fmi2False;
    }
    return fmi2OK;
}

fmi2Status fmi2SetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2Boolean value[]) {
    CHECK_ALIVE("fmi2SetBoolean");
    if (nvr > 0 && (vr == NULL || value == NULL)) return fmi2Error;
    for (size_t k = 0; k < nvr; k++) {
        if (settable(P, "fmi2SetBoolean", "Boolean", vr[k], OSMP_N_BOOLEAN_PARAMS, BOOLEAN_NAME)) return fmi2Error;
        param_bools(PARAMS(P))[BOOLEAN_PARAM[vr[k]]] = value[k] ? 1 : 0;
    }
    return fmi2OK;
}

fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2String value[]) {
    CHECK_ALIVE("fmi2GetString");
    if (nvr > 0 && (vr == NULL || value == NULL)) return fmi2Error;
    for (size_t k = 0; k < nvr; k++) {
        if ((int)vr[k] >= OSMP_N_STRING_PARAMS)
            return fail(P, "fmi2GetString: value reference %u is no String variable", (unsigned)vr[k]);
        value[k] = param_string(PARAMS(P), STRING_PARAM[vr[k]]);
    }
    return fmi2OK;
}

fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2String value[]) {
    CHECK_ALIVE("fmi2SetString");
    if (nvr > 0 && (vr == NULL || value == NULL)) return fmi2Error;
    for (size_t k = 0; k < nvr; k++) {
        if (settable(P, "fmi2SetString", "String", vr[k], OSMP_N_STRING_PARAMS, STRING_NAME)) return fmi2Error;
        if (value[k] == NULL) return fail(P, "fmi2SetString: %s = NULL", STRING_NAME[vr[k]]);
        if ((int)strlen(value[k]) >= param_string_capacity())
            return fail(P, "fmi2SetString: %s: longer than %d characters", STRING_NAME[vr[k]], param_string_capacity() - 1);
        strcpy(param_string(PARAMS(P), STRING_PARAM[vr[k]]), value[k]);
    }
    return fmi2OK;
}

static uint64_t address(int lo, int hi) { return ((uint64_t)(uint32_t)hi << 32) | (uint64_t)(uint32_t)lo; }

static const Osi3__MovingObject *find_by_id(const VeiOsmp__GroundTruth *gt, uint64_t id) {
    for (size_t k = 0; gt && k < gt->n_moving_object; k++) {
        const Osi3__MovingObject *m = gt->moving_object[k];
        if (m->id && m->id->value == id) return m;
    }
    return NULL;
}

static const Osi3__MovingObject *find_by_name(const VeiOsmp__GroundTruth *gt, const char *entity) {
    for (size_t k = 0; gt && k < gt->n_moving_object; k++) {
        const Osi3__MovingObject *m = gt->moving_object[k];
        for (size_t r = 0; r < m->n_source_reference; r++)
            for (size_t i = 0; i < m->source_reference[r]->n_identifier; i++)
                if (strcmp(m->source_reference[r]->identifier[i], entity) == 0) return m;
    }
    return NULL;
}

/* The host's sub-message of type T at *slot, made (in the step's arena) where the SensorView left
 * it out. */
#define ENSURE(slot, T, init)                               \
    do {                                                    \
        if ((slot) == NULL) {                               \
            (slot) = (T *)arena_alloc(&P->arena, sizeof(T)); \
            if ((slot) == NULL) goto out_of_memory;         \
            init((slot));                                   \
        }                                                   \
    } while (0)

fmi2Status fmi2DoStep(fmi2Component c, fmi2Real t, fmi2Real h, fmi2Boolean noSetFMUStatePriorToCurrentPoint) {
    (void)noSetFMUStatePriorToCurrentPoint;
    CHECK_ALIVE("fmi2DoStep");
    if (require(P, "fmi2DoStep", IN(STEPPING))) return fmi2Error;
    if (!(h > 0) || !isfinite(t)) return fail(P, "fmi2DoStep: the step size must be positive (got %g)", h);
    uint64_t at = address(P->ints[SV_LO], P->ints[SV_HI]);
    int size = P->ints[SV_SIZE];
    P->time = t + h;
    if (at == 0 || size <= 0) { /* no SensorView given: nothing to advance from, no new update */
        say(P, fmi2Warning, "doStep at t = %g s: no SensorView (OSMPSensorViewIn unset): the model waits", t);
        return fmi2OK;
    }
    arena_reset(&P->arena);
    ProtobufCAllocator allocator = {arena_alloc, arena_free, &P->arena};
    VeiOsmp__SensorView *view = vei_osmp__sensor_view__unpack(&allocator, (size_t)size, (const uint8_t *)(uintptr_t)at);
    if (view == NULL)
        return fail(P, "doStep at t = %g s: OSMPSensorViewIn: %d bytes that are no osi3.SensorView", t, size);
    VeiOsmp__GroundTruth *gt = view->global_ground_truth;
    uint64_t host_id = view->host_vehicle_id ? view->host_vehicle_id->value
                       : gt && gt->host_vehicle_id ? gt->host_vehicle_id->value
                                                   : 0;
    Osi3__MovingObject *host = (Osi3__MovingObject *)find_by_id(gt, host_id);
    if (host == NULL) { /* not in the scene: no update */
        say(P, fmi2Warning, "doStep at t = %g s: the host vehicle is no moving object of the SensorView", t);
        return fmi2OK;
    }
    const Osi3__MovingObject *other = find_by_name(gt, OSMP_OTHER_ENTITY);
    if (other == NULL) other = find_by_id(gt, (uint64_t)(int64_t)P->ints[OTHER_ID]);
    double s[5];
    if (advance(P, other, t, h, s) != 0) return fmi2Error;
    /* the update: the host as shown, at its new pose, velocity and acceleration along its heading */
    ENSURE(host->base, Osi3__BaseMoving, osi3__base_moving__init);
    Osi3__BaseMoving *b = host->base;
    ENSURE(b->position, Osi3__Vector3d, osi3__vector3d__init);
    ENSURE(b->orientation, Osi3__Orientation3d, osi3__orientation3d__init);
    ENSURE(b->velocity, Osi3__Vector3d, osi3__vector3d__init);
    ENSURE(b->acceleration, Osi3__Vector3d, osi3__vector3d__init);
    double cy = cos(s[2]), sy = sin(s[2]);
    b->position->has_x = b->position->has_y = 1;
    b->position->x = s[0], b->position->y = s[1];
    b->orientation->has_yaw = 1, b->orientation->yaw = s[2];
    b->velocity->has_x = b->velocity->has_y = 1;
    b->velocity->x = s[3] * cy, b->velocity->y = s[3] * sy;
    b->acceleration->has_x = b->acceleration->has_y = 1;
    b->acceleration->x = s[4] * cy, b->acceleration->y = s[4] * sy;

    Osi3__InterfaceVersion version = OSI3__INTERFACE_VERSION__INIT;
    version.has_version_major = version.has_version_minor = version.has_version_patch = 1;
    version.version_major = OSMP_OSI_MAJOR, version.version_minor = OSMP_OSI_MINOR;
    version.version_patch = OSMP_OSI_PATCH;
    Osi3__Timestamp stamp = OSI3__TIMESTAMP__INIT;
    long long ns = (long long)nearbyint((t + h) * 1e9); /* (round half to even, as Python's round) */
    stamp.has_seconds = stamp.has_nanos = 1;
    stamp.seconds = ns / 1000000000LL, stamp.nanos = (uint32_t)(ns % 1000000000LL);
    Osi3__TrafficUpdate update = OSI3__TRAFFIC_UPDATE__INIT;
    Osi3__MovingObject *moved[1] = {host};
    update.version = &version, update.timestamp = &stamp;
    update.n_update = 1, update.update = moved;
    size_t n = osi3__traffic_update__get_packed_size(&update);
    int k = P->next_out;
    if (n > P->out_capacity[k] || P->out[k] == NULL) {
        uint8_t *grown = (uint8_t *)realloc(P->out[k], n > 0 ? n : 1);
        if (grown == NULL) goto out_of_memory;
        P->out[k] = grown, P->out_capacity[k] = n > 0 ? n : 1;
    }
    osi3__traffic_update__pack(&update, P->out[k]);
        uintptr_t out_at = (uintptr_t)P->out[k];
    P->ints[TU_LO] = (int)(int32_t)(uint32_t)((uint64_t)out_at & 0xFFFFFFFFu);
    P->ints[TU_HI] = (int)(int32_t)(uint32_t)((uint64_t)out_at >> 32);
    P->ints[TU_SIZE] = (int)n;
    P->next_out = (k + 1) % KEPT;
    return fmi2OK;
out_of_memory:
    return fail(P, "fmi2DoStep: out of memory");
}

fmi2Status fmi2CancelStep(fmi2Component c) {
    (void)c;
    return fmi2Error;
}
fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind s, fmi2Real *value) {
    if (!is_live(c) || s != fmi2LastSuccessfulTime || value == NULL) return fmi2Discard;
    *value = P->time;
    return fmi2OK;
}

/* ---- capabilities this FMU does not declare ---- */
static fmi2Status unsupported(fmi2Component c, const char *fn) {
    if (is_live(c)) say(P, fmi2Error, "%s is not supported by this FMU", fn);
    return fmi2Error;
}
#include "fmi2_unsupported.h"
