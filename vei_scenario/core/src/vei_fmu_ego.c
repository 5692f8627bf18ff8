/* vei_fmu_ego.c: see vei_fmu_ego.h. The FMI 2.0 and 3.0 types are declared here as the standards define
 * them (fmi2TypesPlatform.h, fmi2FunctionTypes.h, fmi3PlatformTypes.h, fmi3FunctionTypes.h), so the core
 * needs no FMI headers to build. */
#include "vei_fmu_ego.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifndef _WIN32
#include <dlfcn.h>
#endif

typedef void *fmi2Component;
typedef unsigned int fmi2ValueReference;
typedef int fmi2Boolean;
typedef int fmi2Status; /* fmi2OK 0, fmi2Warning 1, fmi2Discard 2, fmi2Error 3, fmi2Fatal 4, fmi2Pending 5 */
typedef struct {
    void (*logger)(void *, const char *, fmi2Status, const char *, const char *, ...);
    void *(*allocateMemory)(size_t, size_t);
    void (*freeMemory)(void *);
    void (*stepFinished)(void *, fmi2Status);
    void *componentEnvironment;
} fmi2CallbackFunctions;

/* FMI 3.0's (fmi3PlatformTypes.h, fmi3FunctionTypes.h): fmi3Boolean is C's bool */
typedef void *fmi3Instance;
typedef unsigned int fmi3ValueReference;
typedef int fmi3Status; /* fmi3OK 0, fmi3Warning 1, fmi3Discard 2, fmi3Error 3, fmi3Fatal 4 */
typedef _Bool fmi3Boolean;

typedef struct {
    fmi3Instance (*instantiate)(const char *, const char *, const char *, fmi3Boolean, fmi3Boolean, fmi3Boolean,
                                fmi3Boolean, const fmi3ValueReference *, size_t, void *,
                                void (*)(void *, fmi3Status, const char *, const char *), void *);
    fmi3Status (*enter_init)(fmi3Instance, fmi3Boolean, double, double, fmi3Boolean, double);
    fmi3Status (*exit_init)(fmi3Instance);
    fmi3Status (*set_float64)(fmi3Instance, const fmi3ValueReference *, size_t, const double *, size_t);
    fmi3Status (*set_int32)(fmi3Instance, const fmi3ValueReference *, size_t, const int *, size_t);
    fmi3Status (*set_boolean)(fmi3Instance, const fmi3ValueReference *, size_t, const fmi3Boolean *, size_t);
    fmi3Status (*get_float64)(fmi3Instance, const fmi3ValueReference *, size_t, double *, size_t);
    fmi3Status (*do_step)(fmi3Instance, double, double, fmi3Boolean, fmi3Boolean *, fmi3Boolean *, fmi3Boolean *,
                          double *);
    fmi3Status (*terminate)(fmi3Instance);
    void (*free_instance)(fmi3Instance);
} Fmi3;

typedef struct {
    fmi2Component (*instantiate)(const char *, int, const char *, const char *, const fmi2CallbackFunctions *,
                                 fmi2Boolean, fmi2Boolean);
    fmi2Status (*setup)(fmi2Component, fmi2Boolean, double, double, fmi2Boolean, double);
    fmi2Status (*enter_init)(fmi2Component);
    fmi2Status (*exit_init)(fmi2Component);
    fmi2Status (*set_real)(fmi2Component, const fmi2ValueReference *, size_t, const double *);
    fmi2Status (*set_integer)(fmi2Component, const fmi2ValueReference *, size_t, const int *);
    fmi2Status (*set_boolean)(fmi2Component, const fmi2ValueReference *, size_t, const fmi2Boolean *);
    fmi2Status (*get_real)(fmi2Component, const fmi2ValueReference *, size_t, double *);
    fmi2Status (*do_step)(fmi2Component, double, double, fmi2Boolean);
    fmi2Status (*terminate)(fmi2Component);
    void (*free_instance)(fmi2Component);
} Fmi2;

/* An opened FMU: its version and its functions. */
typedef struct {
    int fmi3;
    Fmi2 f2;
    Fmi3 f3;
} Fmi;

enum { C_INSTANTIATE, C_SETUP, C_ENTER, C_SET_REAL, C_SET_INTEGER, C_SET_BOOLEAN, C_EXIT, C_DO_STEP, C_GET_REAL,
       C_TERMINATE, C_FREE };

const char *vei_fmu_calls(int fmi3) { return fmi3 ? VEI_FMU3_CALLS : VEI_FMU_CALLS; }

void *vei_fmu_open(const char *library, int fmi3, char *err, int err_size) {
#ifdef _WIN32
    (void)library, (void)fmi3;
    snprintf(err, (size_t)err_size, "native FMUs are stepped in the interpreter on this platform");
    return NULL;
#else
    void *h = dlopen(library, RTLD_NOW | RTLD_LOCAL);
    if (h == NULL) {
        snprintf(err, (size_t)err_size, "%s", dlerror());
        return NULL;
    }
    Fmi *fmi = (Fmi *)calloc(1, sizeof(Fmi));
    if (fmi == NULL) {
        snprintf(err, (size_t)err_size, "out of memory");
        dlclose(h);
        return NULL;
    }
    fmi->fmi3 = fmi3;
    Fmi2 *f = &fmi->f2;
    Fmi3 *g = &fmi->f3;
    static const char *names2[] = {"fmi2Instantiate", "fmi2SetupExperiment", "fmi2EnterInitializationMode",
                                   "fmi2ExitInitializationMode", "fmi2SetReal", "fmi2SetInteger", "fmi2SetBoolean",
                                   "fmi2GetReal", "fmi2DoStep", "fmi2Terminate", "fmi2FreeInstance"};
    static const char *names3[] = {"fmi3InstantiateCoSimulation", "fmi3EnterInitializationMode",
                                   "fmi3ExitInitializationMode", "fmi3SetFloat64", "fmi3SetInt32", "fmi3SetBoolean",
                                   "fmi3GetFloat64", "fmi3DoStep", "fmi3Terminate", "fmi3FreeInstance", NULL};
    void **slots2[] = {(void **)&f->instantiate, (void **)&f->setup,       (void **)&f->enter_init,
                       (void **)&f->exit_init,   (void **)&f->set_real,    (void **)&f->set_integer,
                       (void **)&f->set_boolean, (void **)&f->get_real,    (void **)&f->do_step,
                       (void **)&f->terminate,   (void **)&f->free_instance};
    void **slots3[] = {(void **)&g->instantiate, (void **)&g->enter_init,  (void **)&g->exit_init,
                       (void **)&g->set_float64, (void **)&g->set_int32,   (void **)&g->set_boolean,
                       (void **)&g->get_float64, (void **)&g->do_step,     (void **)&g->terminate,
                       (void **)&g->free_instance, NULL};
    const char **names = fmi3 ? names3 : names2;
    void ***slots = fmi3 ? slots3 : slots2;
    size_t count = fmi3 ? 10 : 11;
    for (size_t k = 0; k < count; k++) {
        *slots[k] = dlsym(h, names[k]);
        if (*slots[k] == NULL) {
            snprintf(err, (size_t)err_size, "its library has no function %s", names[k]);
            free(fmi);
            dlclose(h);
            return NULL;
        }
    }
    return fmi; /* (the library stays open for the process's life, as fmpy leaves it) */
#endif
}

static void quiet(void *env, const char *name, fmi2Status status, const char *category, const char *message, ...) {
    (void)env, (void)name, (void)status, (void)category, (void)message;
}
static const fmi2CallbackFunctions CALLBACKS = {quiet, calloc, free, NULL, NULL};
static void quiet3(void *env, fmi3Status status, const char *category, const char *message) {
    (void)env, (void)status, (void)category, (void)message;
}

/* One run's instance and the variant it drives. */
typedef struct {
    VeiFmuEgo *cfg;
    const Fmi *fmi;
    const Fmi2 *f;
    const Fmi3 *g;
    fmi2Component c;
    int variant;
    double *fault;
    double t; /* the last step's time */
    fmi2ValueReference in_vr[VEI_EGO_INPUTS];
    double calls;
} Host;

static void progress(Host *h, int call, double t) {
    volatile double *p = h->cfg->progress;
    if (p != NULL) p[1] = t, p[2] = call, p[3] = h->variant, p[0] = ++h->calls;
}

/* A fault kept for the caller; the instance ended as FMI 2.0 allows after it (nothing after fmi2Fatal,
 * only fmi2FreeInstance after fmi2Error, else fmi2Terminate first: vei_scenario.sut.fmu.end_instance). */
static int fail(Host *h, int kind, double t, int call, double value) {
    h->fault[0] = kind, h->fault[1] = t, h->fault[2] = call, h->fault[3] = value;
    if (h->c != NULL) {
        int status = kind == VEI_FMU_STATUS ? (int)value : 0;
        if (status != 4) {
            if (status != 3) progress(h, C_TERMINATE, t), h->fmi->fmi3 ? h->g->terminate(h->c) : h->f->terminate(h->c);
            progress(h, C_FREE, t);
            if (h->fmi->fmi3)
                h->g->free_instance(h->c);
            else
                h->f->free_instance(h->c);
        }
        h->c = NULL;
    }
    progress(h, -1, t);
    return 1;
}

#define CALL(h, call, t, expr)                                                                             \
    do {                                                                                                   \
        progress(h, call, t);                                                                              \
        fmi2Status status_ = (expr);                                                                       \
        if (status_ > 1) return fail(h, VEI_FMU_STATUS, t, call, status_);                               \
    } while (0)

/* FMI 3.0: fmi3InstantiateCoSimulation, fmi3EnterInitializationMode(start 0), the parameters, exit
 * (fmpy's FMU3Slave as vei_scenario.sut.fmu.FmuController drives it). */
static int begin3(Host *h) {
    const VeiFmuEgo *g = h->cfg;
    const Fmi3 *f = h->g;
    progress(h, C_INSTANTIATE, NAN);
    h->c = f->instantiate(g->instance_name, g->guid, g->resource_uri, 0, 0, 0, 0, NULL, 0, NULL, quiet3, NULL);
    if (h->c == NULL) return fail(h, VEI_FMU_NULL, NAN, C_INSTANTIATE, 0.0);
    CALL(h, C_ENTER, NAN, f->enter_init(h->c, 0, 0.0, 0.0, 0, 0.0));
    const double *values = g->par_values + (size_t)h->variant * g->n_par;
    for (int k = 0; k < g->n_par; k++) {
        fmi3ValueReference vr = (fmi3ValueReference)g->par_vr[k];
        if (g->par_kind[k] == 0) {
            CALL(h, C_SET_REAL, NAN, f->set_float64(h->c, &vr, 1, &values[k], 1));
        } else if (g->par_kind[k] == 1) {
            int i = (int)values[k];
            CALL(h, C_SET_INTEGER, NAN, f->set_int32(h->c, &vr, 1, &i, 1));
        } else {
            fmi3Boolean b = values[k] != 0.0;
            CALL(h, C_SET_BOOLEAN, NAN, f->set_boolean(h->c, &vr, 1, &b, 1));
        }
    }
    CALL(h, C_EXIT, NAN, f->exit_init(h->c));
    progress(h, -1, 0.0);
    return 0;
}

static int begin(void *self, int variant) {
    Host *h = (Host *)self;
    const VeiFmuEgo *g = h->cfg;
    h->variant = variant;
    h->fault = g->faults + (size_t)variant * VEI_FMU_FAULT_FIELDS;
    h->fault[0] = VEI_FMU_OK;
    h->t = NAN;
    if (h->fmi->fmi3) return begin3(h);
    progress(h, C_INSTANTIATE, NAN);
    h->c = h->f->instantiate(g->instance_name, 1 /* fmi2CoSimulation */, g->guid, g->resource_uri, &CALLBACKS, 0, 0);
    if (h->c == NULL) return fail(h, VEI_FMU_NULL, NAN, C_INSTANTIATE, 0.0);
    CALL(h, C_SETUP, NAN, h->f->setup(h->c, 0, 0.0, 0.0, 0, 0.0));
    CALL(h, C_ENTER, NAN, h->f->enter_init(h->c));
    const double *values = g->par_values + (size_t)variant * g->n_par;
    for (int k = 0; k < g->n_par; k++) {
        fmi2ValueReference vr = (fmi2ValueReference)g->par_vr[k];
        if (g->par_kind[k] == 0) {
            CALL(h, C_SET_REAL, NAN, h->f->set_real(h->c, &vr, 1, &values[k]));
        } else if (g->par_kind[k] == 1) {
            int i = (int)values[k];
            CALL(h, C_SET_INTEGER, NAN, h->f->set_integer(h->c, &vr, 1, &i));
        } else {
            fmi2Boolean b = values[k] != 0.0;
            CALL(h, C_SET_BOOLEAN, NAN, h->f->set_boolean(h->c, &vr, 1, &b));
        }
    }
    CALL(h, C_EXIT, NAN, h->f->exit_init(h->c));
    progress(h, -1, 0.0);
    return 0;
}

static int step(void *self, const double *in, double t, double dt, double *a_cmd) {
    Host *h = (Host *)self;
    const VeiFmuEgo *g = h->cfg;
    h->t = t;
    double values[VEI_EGO_INPUTS];
    for (int k = 0; k < g->n_in; k++) values[k] = in[g->in_which[k]];
    fmi2ValueReference out = (fmi2ValueReference)g->out_vr;
    double a = NAN;
    if (h->fmi->fmi3) {
        const Fmi3 *f = h->g;
        fmi3Boolean event = 0, stop = 0, early = 0;
        double last = t;
        size_t n = (size_t)g->n_in;
        if (n > 0) CALL(h, C_SET_REAL, t, f->set_float64(h->c, h->in_vr, n, values, n));
        CALL(h, C_DO_STEP, t, f->do_step(h->c, t, dt, 1, &event, &stop, &early, &last));
        CALL(h, C_GET_REAL, t, f->get_float64(h->c, &out, 1, &a, 1));
    } else {
        if (g->n_in > 0) CALL(h, C_SET_REAL, t, h->f->set_real(h->c, h->in_vr, (size_t)g->n_in, values));
        CALL(h, C_DO_STEP, t, h->f->do_step(h->c, t, dt, 1));
        CALL(h, C_GET_REAL, t, h->f->get_real(h->c, &out, 1, &a));
    }
    progress(h, -1, t);
    /* the contract's check of a command (sut.contract.command_from) */
    if (!isfinite(a)) return fail(h, VEI_FMU_NONFINITE, t, C_GET_REAL, a);
    if (fabs(a) > g->max_command) return fail(h, VEI_FMU_ABSURD, t, C_GET_REAL, a);
    *a_cmd = a;
    return 0;
}

static void end(void *self, int failed) {
    Host *h = (Host *)self;
    if (failed || h->c == NULL) return; /* (ended where it failed) */
    if (h->fmi->fmi3) {
        progress(h, C_TERMINATE, h->t), h->g->terminate(h->c);
        progress(h, C_FREE, h->t), h->g->free_instance(h->c);
    } else {
        progress(h, C_TERMINATE, h->t), h->f->terminate(h->c);
        progress(h, C_FREE, h->t), h->f->free_instance(h->c);
    }
    h->c = NULL;
    progress(h, -1, h->t);
}

int vei_batch_run_fmu(const VeiBatchScene *sc, const VeiBatchVariant *v, int n, double *out, double *traj,
                      VeiFmuEgo *fmu) {
    Host h;
    memset(&h, 0, sizeof h);
    h.cfg = fmu, h.fmi = (const Fmi *)fmu->lib;
    h.f = &h.fmi->f2, h.g = &h.fmi->f3;
    if (fmu->n_in > VEI_EGO_INPUTS) return -1;
    for (int k = 0; k < fmu->n_in; k++) h.in_vr[k] = (fmi2ValueReference)fmu->in_vr[k];
    h.calls = fmu->progress != NULL ? fmu->progress[0] : 0.0;
    VeiEgoDriver drv = {&h, begin, step, end, fmu->max_speed};
    return vei_batch_run_driven(sc, v, n, out, traj, &drv);
}
