/* fmu_loader.c: a host without Python for the native FMI 2.0 FMUs (tests/test_fmus.py).
 *
 * usage: fmu_loader BINARY.so GUID < commands
 * commands, one per line:  real VR VALUE | int VR VALUE | bool VR 0|1 | string VR VALUE | init |
 *                          step T H | get VR | free
 * Each command prints "<command> <status>" (status: 0 OK ... 3 error) and `get` prints the value.
 * The logger prints "log <status> <category> <message>". The loader exits 0 unless it cannot run.
 */
#include <dlfcn.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmi2Functions.h"

static void logger(fmi2ComponentEnvironment env, fmi2String name, fmi2Status status, fmi2String category,
                   fmi2String message, ...) {
    (void)env, (void)name;
    char buf[1024];
    va_list ap;
    va_start(ap, message);
    vsnprintf(buf, sizeof buf, message, ap);
    va_end(ap);
    printf("log %d %s %s\n", (int)status, category, buf);
}

#define LOAD(name) name##TYPE *name = (name##TYPE *)dlsym(lib, #name)

int main(int argc, char **argv) {
    if (argc != 3) return 64;
    void *lib = dlopen(argv[1], RTLD_NOW | RTLD_LOCAL);
    if (!lib) {
        fprintf(stderr, "%s\n", dlerror());
        return 65;
    }
    LOAD(fmi2Instantiate);
    LOAD(fmi2SetupExperiment);
    LOAD(fmi2EnterInitializationMode);
    LOAD(fmi2ExitInitializationMode);
    LOAD(fmi2SetReal);
    LOAD(fmi2SetInteger);
    LOAD(fmi2SetBoolean);
    LOAD(fmi2SetString);
    LOAD(fmi2GetReal);
    LOAD(fmi2DoStep);
    LOAD(fmi2FreeInstance);
    if (!fmi2Instantiate || !fmi2DoStep || !fmi2FreeInstance) return 66;
    fmi2CallbackFunctions cb = {logger, calloc, free, NULL, NULL};
    fmi2Component c = fmi2Instantiate("loader", fmi2CoSimulation, argv[2], "", &cb, fmi2False, fmi2False);
    printf("instantiate %d\n", c != NULL ? 0 : 3);
    if (c == NULL) return 0;
    fmi2SetupExperiment(c, fmi2False, 0.0, 0.0, fmi2False, 0.0);
    fmi2EnterInitializationMode(c);
    char cmd[32], text[256];
    unsigned vr;
    double value, t, h;
    while (scanf("%31s", cmd) == 1) {
        fmi2Status s = fmi2OK;
        if (strcmp(cmd, "real") == 0 && scanf("%u %lf", &vr, &value) == 2) {
            s = fmi2SetReal(c, &vr, 1, &value);
        } else if (strcmp(cmd, "int") == 0 && scanf("%u %lf", &vr, &value) == 2) {
            fmi2Integer i = (fmi2Integer)value;
            s = fmi2SetInteger(c, &vr, 1, &i);
        } else if (strcmp(cmd, "bool") == 0 && scanf("%u %lf", &vr, &value) == 2) {
            fmi2Boolean b = value != 0;
            s = fmi2SetBoolean(c, &vr, 1, &b);
        } else if (strcmp(cmd, "string") == 0 && scanf("%u %255s", &vr, text) == 2) {
            fmi2String str = text;
            s = fmi2SetString(c, &vr, 1, &str);
        } else if (strcmp(cmd, "init") == 0) {
            s = fmi2ExitInitializationMode(c);
        } else if (strcmp(cmd, "step") == 0 && scanf("%lf %lf", &t, &h) == 2) {
            s = fmi2DoStep(c, t, h, fmi2True);
        } else if (strcmp(cmd, "get") == 0 && scanf("%u", &vr) == 1) {
            s = fmi2GetReal(c, &vr, 1, &value);
            printf("value %.17g\n", value);
        } else if (strcmp(cmd, "free") == 0) {
            fmi2FreeInstance(c);
            c = NULL;
            printf("free 0\n");
            break;
        } else {
            printf("bad command %s\n", cmd);
            continue;
        }
        printf("%s %d\n", cmd, (int)s);
    }
    if (c) fmi2FreeInstance(c);
    dlclose(lib);
    return 0;
}
