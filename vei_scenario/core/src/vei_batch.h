/* vei_batch.h: the sweep kernel: many variants of a vei-compiled two-entity scenario (ego with the
 * collision-avoidance planner, one scooter with the social force model), each simulated step by step
 * as vei run does and scored with vei run's metrics, in compiled loops (vei_scenario.batch.native).
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

enum {
    OUT_COLLISION, OUT_COLLISION_TIME, OUT_MIN_GAP, OUT_MIN_TTC, OUT_MIN_TTC_APPROX, OUT_ZONE_SAFE,
    OUT_ZONE_ATTENTION, OUT_ZONE_ALERT, OUT_ZONE_COLLISION, OUT_SAFETY_INDEX, OUT_ACT_MIN, OUT_EI_MAX,
    OUT_DRAC_MAX, OUT_PET, OUT_PEAK_DECEL, OUT_MAX_JERK, OUT_COMFORT, OUT_NEAR_MISS, OUT_IMPACT_SPEED, VEI_BATCH_OUTPUTS
};

/* Run variants [0, n); out: n * VEI_BATCH_OUTPUTS; traj (NULL or n * 10 * (n_steps + 1)): ego x, y, yaw,
 * speed, accel, then the threat's. Returns 0, or -1 when out of memory. */
int vei_batch_run(const VeiBatchScene *sc, const VeiBatchVariant *v, int n, double *out, double *traj);

#endif
