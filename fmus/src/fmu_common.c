/* fmu_common.c: start values and error reporting shared by both FMI wrappers. */
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
