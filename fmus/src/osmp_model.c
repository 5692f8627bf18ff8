/* osmp_model.c: a vei FMU model (its Instance with the scenario's start values) behind osmp_model.h's
 * interface. Compiled once per model in an OSMP participant, its names prefixed (see osmp_model.h). */
#include <stdlib.h>

#include "fmu_instance.h"
#include "osmp_model.h"

typedef struct {
    OsmpLog log;
    void *env;
} Logger;

static void forward(Instance *m, const char *message) {
    Logger *l = (Logger *)m->wrapper;
    if (l->log) l->log(l->env, message);
}

void *osmp_model_new(OsmpLog log, void *env) {
    Instance *m = (Instance *)calloc(1, sizeof(Instance));
    Logger *l = (Logger *)calloc(1, sizeof(Logger));
    if (m == NULL || l == NULL) {
        free(m), free(l);
        return NULL;
    }
    l->log = log, l->env = env;
    m->wrapper = l;
    m->log_error = forward;
    vei_set_start_values(m);
    return m;
}

void osmp_model_free(void *model) {
    if (model == NULL) return;
    free(((Instance *)model)->wrapper);
    free(model);
}

double *osmp_model_reals(void *model) { return ((Instance *)model)->r; }

int *osmp_model_bools(void *model) { return ((Instance *)model)->b; }

char *osmp_model_string(void *model, int vr) { return ((Instance *)model)->s[vr]; }

int osmp_model_string_capacity(void) { return VEI_STRING_CAPACITY; }

int osmp_model_initialize(void *model) {
    Instance *m = (Instance *)model;
    if (model_initialize(m) != 0) return 1;
    m->initialized = 1;
    m->state = VEI_STATE_STEPPING;
    return 0;
}

int osmp_model_do_step(void *model, double t, double h) { return model_do_step((Instance *)model, t, h); }
