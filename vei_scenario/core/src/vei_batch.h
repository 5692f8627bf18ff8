/* vei_batch.h: the sweep kernel: many variants of a vei-compiled closed loop (ego with the
 * collision-avoidance planner, the threat scooter with the social force model; other road users only
 * replay and do not enter a row), each simulated step by step as vei run does and scored with vei run's
 * metrics, in compiled loops (vei_scenario.batch.native).
 */
#ifndef VEI_BATCH_H
#define VEI_BATCH_H

#include "vei_models.h"

typedef struct {
    /* time: t[k] = round(k dt, 9) for k = 0..n_steps; the run records n_steps + 1 samples */
    const double *t;
    int n_steps;
    double dt, behaviour_start;
    /* np.gradient(f, t) coefficients: interior a, b, c (n_steps - 1 each); edges 1 / dt0, 1 / dtn */
    const double *grad_a, *grad_b, *grad_c;
    double grad_dx0, grad_dxn;
    int grad_uniform;
    double grad_h; /* uniform spacing */
    /* paths */
    VeiPolyline ego_path, track; /* s given, track timed */
    const double *route_x, *route_y;
    int route_n;
    double v_start;
    double ego_x0, ego_y0, ego_yaw0, threat_x0, threat_y0, threat_yaw0;
    double ego_length, ego_width, threat_length, threat_width;
    VeiCapParams cap;
    VeiSfmParams sfm;
    VeiVehicleLimits limits;
    /* metrics */
    double metric_dt; /* median step */
    double safe_ttc, alert_ttc, comfort_accel, comfort_jerk, near_lo, near_hi;
    int zone_ttc_2d;
    int pet_step;
    double radius_sum; /* sum of the circumscribed radii: PET's reach and EI's safety distance */
    double band_reach; /* widest the approximate TTC's lane band can be (half ego width + half other diagonal) */
} VeiBatchScene;

typedef struct {
    int cap_on, sfm_on, repulsive;
    double cruise, offset, ego_speed0, threat_speed0;
} VeiBatchVariant;

/* The outputs of a variant, each with the name of vei run's metric it holds (zones: ttc_zones_s.<zone>):
 * one list, from which the column indices and the names the Python side reads (vei_batch_outputs) come. */
#define VEI_BATCH_OUTPUT_LIST(X)                                                                           \
    X(OUT_COLLISION, "collision") X(OUT_COLLISION_TIME, "collision_time_s") X(OUT_MIN_GAP, "min_gap_m")    \
    X(OUT_MIN_TTC, "min_ttc_s") X(OUT_MIN_TTC_APPROX, "min_ttc_approx_s")                                \
    X(OUT_ZONE_SAFE, "ttc_zones_s.safe") X(OUT_ZONE_ATTENTION, "ttc_zones_s.attention")                  \
    X(OUT_ZONE_ALERT, "ttc_zones_s.alert") X(OUT_ZONE_COLLISION, "ttc_zones_s.collision")                \
    X(OUT_SAFETY_INDEX, "safety_index") X(OUT_ACT_MIN, "act_min_s") X(OUT_EI_MAX, "ei_max_mps")           \
    X(OUT_DRAC_MAX, "drac_max_mps2") X(OUT_PET, "pet_s") X(OUT_PEAK_DECEL, "peak_decel_mps2")            \
    X(OUT_MAX_JERK, "max_jerk_mps3") X(OUT_COMFORT, "comfort_score") X(OUT_NEAR_MISS, "near_miss")       \
    X(OUT_IMPACT_SPEED, "impact_speed_mps") X(OUT_EGO_CONTACT_SPEED, "ego_speed_at_contact_mps")                 \
    X(OUT_EGO_MOVING, "collision_ego_moving") X(OUT_STOOD_BEFORE, "ego_standing_before_contact_s")           \
    X(OUT_BRAKE_ONSET, "brake_onset_s") X(OUT_TTC_AT_BRAKE, "ttc_at_brake_onset_s")                         \
    X(OUT_SPEED_REDUCTION, "speed_reduction_mps")

#define VEI_OUTPUT_ENUM(id, name) id,
enum { VEI_BATCH_OUTPUT_LIST(VEI_OUTPUT_ENUM) VEI_BATCH_OUTPUTS };
#undef VEI_OUTPUT_ENUM

/* The output names in column order, separated by commas. */
const char *vei_batch_outputs(void);

/* Run variants [0, n); out: n * VEI_BATCH_OUTPUTS; traj (NULL or n * 10 * (n_steps + 1)): ego x, y, yaw,
 * speed, accel, then the threat's. Returns 0, or -1 when out of memory. */
int vei_batch_run(const VeiBatchScene *sc, const VeiBatchVariant *v, int n, double *out, double *traj);

/* An external controller driving the ego in place of the planner (vei run's plugged controller): each
 * step it is shown the states at the step's start, VEI_EGO_INPUTS doubles in the order of
 * vei_scenario.sut.fmu.INPUTS (the ego's x, y, yaw, speed, accel, length, width, the threat's, then the
 * time), and returns the acceleration command; the ego follows it through the vehicle model, held at
 * max_speed, along its path. begin(variant) before a variant's first step and end(failed) after its
 * last; begin or step return non-zero for a fault (the driver keeps why), which fails that variant alone. */
enum { VEI_EGO_INPUTS = 15 };
typedef struct {
    void *self;
    int (*begin)(void *self, int variant);
    int (*step)(void *self, const double *in, double t, double dt, double *a_cmd);
    void (*end)(void *self, int failed);
    double max_speed;
} VeiEgoDriver;

/* vei_batch_run with the driver on the ego (the planner's switch is not read: the driver is in charge
 * from the first step); a variant the driver fails has NaN outputs. The scene's behaviour must start at
 * the first step. Returns 0, or -1 when out of memory. */
int vei_batch_run_driven(const VeiBatchScene *sc, const VeiBatchVariant *v, int n, double *out, double *traj,
                         const VeiEgoDriver *drv);

/* The metrics of one recorded run (traj: 10 * (n_steps + 1), laid out as vei_batch_run's) into out
 * (VEI_BATCH_OUTPUTS): how vei run scores any scenario's ego and threat. Only the scene's time, gradient
 * and metric fields and the two boxes' sizes are read. Returns 0, or -1 when out of memory. */
int vei_batch_score(const VeiBatchScene *sc, const double *traj, double *out);

#endif
