/* vei_fmu_ego.h: a native FMI 2.0 or 3.0 co-simulation FMU on the ego of the sweep kernel (vei_batch_run_driven):
 * its shared library opened once per process (dlopen, the fmi2 functions as pointers), an instance per
 * variant, stepped at the kernel's step as vei run's plugged controller steps it
 * (vei_scenario.sut.fmu.FmuController): inputs set, doStep(t, dt), a_cmd read and checked.
 *
 * A fault (a call returning more than fmi2Warning, a non-finite or absurd command) fails that variant
 * alone and is kept in `faults` for the caller to word. A crash or a hang inside the FMU cannot be caught
 * here: the caller runs this in a child process and reads `progress` (shared memory) to say where.
 */
#ifndef VEI_FMU_EGO_H
#define VEI_FMU_EGO_H

#include "vei_batch.h"

/* What is kept per variant in faults (VEI_FMU_FAULT_FIELDS doubles each): the kind, the step time
 * (NaN while instantiating), the call (VEI_FMU_CALLS' index) and the status or the command. */
enum { VEI_FMU_OK = 0, VEI_FMU_STATUS = 1, VEI_FMU_NULL = 2, VEI_FMU_NONFINITE = 3, VEI_FMU_ABSURD = 4 };
enum { VEI_FMU_FAULT_FIELDS = 4 };
/* progress (VEI_FMU_PROGRESS doubles, written before each call into the FMU): calls so far, the step
 * time, the call (vei_fmu_calls' index, -1 between calls), the variant */
enum { VEI_FMU_PROGRESS = 4 };
#define VEI_FMU_CALLS                                                                                     \
    "fmi2Instantiate,fmi2SetupExperiment,fmi2EnterInitializationMode,fmi2SetReal,fmi2SetInteger,"         \
    "fmi2SetBoolean,fmi2ExitInitializationMode,fmi2DoStep,fmi2GetReal,fmi2Terminate,fmi2FreeInstance"
#define VEI_FMU3_CALLS                                                                                    \
    "fmi3InstantiateCoSimulation,,fmi3EnterInitializationMode,fmi3SetFloat64,fmi3SetInt32,fmi3SetBoolean," \
    "fmi3ExitInitializationMode,fmi3DoStep,fmi3GetFloat64,fmi3Terminate,fmi3FreeInstance"

typedef struct {
    void *lib; /* vei_fmu_open's */
    const char *instance_name, *guid, *resource_uri; /* FMI 3.0: the token, the resource directory's path */
    int n_in;
    const int *in_vr, *in_which; /* value reference and VeiEgoDriver input index of each input it declares */
    int out_vr;                   /* a_cmd's */
    int n_par;
    const int *par_vr, *par_kind; /* kind 0 Real, 1 Integer, 2 Boolean */
    const double *par_values;     /* n_variants x n_par: each variant's values */
    double max_speed, max_command;
    double *faults;               /* n_variants x VEI_FMU_FAULT_FIELDS */
    volatile double *progress;    /* VEI_FMU_PROGRESS, or NULL */
} VeiFmuEgo;

/* The FMU's shared library opened and its fmi2 (fmi3: FMI 3.0) functions resolved; NULL with the
 * reason in err. */
void *vei_fmu_open(const char *library, int fmi3, char *err, int err_size);

/* The names of the calls of FMI 2.0 (fmi3: 3.0), separated by commas (the index kept in faults and
 * progress; FMI 3.0 has no fmi2SetupExperiment, its name empty). */
const char *vei_fmu_calls(int fmi3);

/* vei_batch_run with the FMU on the ego. Returns 0, or -1 when out of memory. */
int vei_batch_run_fmu(const VeiBatchScene *sc, const VeiBatchVariant *v, int n, double *out, double *traj,
                      VeiFmuEgo *fmu);

#endif
