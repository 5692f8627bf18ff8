/* fmu_common.c: start values and error reporting shared by both FMI wrappers. */
#include <pthread.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "fmu_instance.h"

void vei_set_start_values(Instance *m) {
    memset(m->r, 0, sizeof m->r);
    memset(m->i, 0, sizeof m->i);
    memset(m->b, 0, sizeof m->b);
    memset(m->s, 0, sizeof m->s);
    SET_START_VALUES(m);
    m->time = 0.0;
    m->initialized = 0;
    m->failed = 0;
    m->state = VEI_STATE_INSTANTIATED;
}

static pthread_mutex_t live_lock = PTHREAD_MUTEX_INITIALIZER;
static Instance *live_head = NULL;

void vei_register(Instance *m) {
    pthread_mutex_lock(&live_lock);
    m->next_live = live_head;
    live_head = m;
    pthread_mutex_unlock(&live_lock);
}

int vei_unregister(Instance *m) {
    int found = 0;
    pthread_mutex_lock(&live_lock);
    for (Instance **p = &live_head; *p != NULL; p = &(*p)->next_live) {
        if (*p == m) {
            *p = m->next_live;
            found = 1;
            break;
        }
    }
    pthread_mutex_unlock(&live_lock);
    return found;
}

int vei_is_live(const void *ptr) {
    int found = 0;
    if (ptr == NULL) return 0;
    pthread_mutex_lock(&live_lock);
    for (Instance *p = live_head; p != NULL; p = p->next_live) {
        if ((const void *)p == ptr) {
            found = 1;
            break;
        }
    }
    pthread_mutex_unlock(&live_lock);
    return found;
}

static const char *state_name(int state) {
    switch (state) {
        case VEI_STATE_INSTANTIATED: return "instantiated";
        case VEI_STATE_INITIALIZATION: return "initialization mode";
        case VEI_STATE_STEPPING: return "step mode";
        case VEI_STATE_TERMINATED: return "terminated";
        default: return "unknown";
    }
}

int vei_require(Instance *m, const char *fn, unsigned allowed) {
    if (allowed & VEI_IN(m->state)) return 0;
    vei_fail(m, "%s: not allowed in state %s (the FMI state machine)", fn, state_name(m->state));
    return 1;
}

int vei_fail(Instance *m, const char *fmt, ...) {
    char msg[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    m->failed = 1;
    if (m->log_error) m->log_error(m, msg);
    return 1;
}

int vei_settable(const Instance *m, char causality) {
    if (causality == 'i') return 1;
    if (causality == 'p') return !m->initialized;
    return 0;
}
