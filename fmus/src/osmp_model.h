/* osmp_model.h: one of vei's FMU models (sfm_model.c, cap_model.c, ego_model.c) inside an OSMP
 * participant's binary, behind a plain C interface.
 *
 * An OSMP participant may hold two models (the planner and the vehicle it drives), and each model's
 * Instance layout comes from its own generated variable table. So each model is compiled on its own
 * (its model.h on the include path) with every external name prefixed (vei_scenario.fmu.osmp_native
 * passes -Dosmp_model_new=cap_osmp_model_new and so on), and the participant (osmp_wrapper.c) reaches
 * it through these functions only: the model's variables by value reference (the reals the wrapper
 * exchanges, the parameters it declares), initialise, step.
 */
#ifndef OSMP_MODEL_H
#define OSMP_MODEL_H

typedef void (*OsmpLog)(void *env, const char *message);

#define OSMP_MODEL_API(P)                                                  \
    void *P##_osmp_model_new(OsmpLog log, void *env);                      \
    void P##_osmp_model_free(void *model);                                 \
    double *P##_osmp_model_reals(void *model);                             \
    int *P##_osmp_model_bools(void *model);                                \
    char *P##_osmp_model_string(void *model, int vr);                      \
    int P##_osmp_model_string_capacity(void);                              \
    int P##_osmp_model_initialize(void *model);                            \
    int P##_osmp_model_do_step(void *model, double t, double h);

#endif
