/* The ego vehicle as an FMU: moves along its path with vei run's jerk-limited longitudinal model.
 *
 * Until behaviour_start_s it keeps its initial speed and heading (the scenario's Init); at the first
 * step after it, it continues from its projection onto the path, as a FollowTrajectoryAction without
 * timing does in vei run.
 */
#include <math.h>

#include "fmu_instance.h"

#define R(name) (m->r[VR_##name])

int model_initialize(Instance *m) {
    ModelState *ms = &m->ms;
    int n = m->i[VR_PATH_N];
    if (n < 2 || n > VEI_MAX_PATH) return vei_fail(m, "path_n must be 2..%d (got %d)", VEI_MAX_PATH, n);
    if (!(R(MAX_ACCEL_MPS2) >= 0 && R(MAX_DECEL_MPS2) >= 0 && R(JERK_MAX_MPS3) > 0))
        return vei_fail(m, "max_accel_mps2 and max_decel_mps2 must not be negative, jerk_max_mps3 must be positive");
    if (R(SPEED0) < 0) return vei_fail(m, "speed0 must not be negative (got %g)", R(SPEED0));
    ms->path.x = &m->r[VR_PATH_X];
    ms->path.y = &m->r[VR_PATH_Y];
    ms->path.h = &m->r[VR_PATH_H];
    ms->path.t = NULL;
    ms->path.s = ms->path_s;
    ms->path.n = n;
    ms->path.exit_speed = NAN;
    vei_polyline_init(&ms->path);
    ms->on_path = 0;
    ms->s = 0.0;
    R(X) = R(X0), R(Y) = R(Y0), R(YAW) = R(YAW0), R(SPEED) = R(SPEED0), R(ACCEL) = 0.0, R(S) = 0.0;
    return 0;
}

int model_do_step(Instance *m, double t, double h) {
    ModelState *ms = &m->ms;
    if (!(t > R(BEHAVIOUR_START_S))) { /* not started: straight ahead at the current speed */
        R(S) = R(S) + vei_straight_ahead(&R(X), &R(Y), R(YAW), R(SPEED), &R(ACCEL), h);
        return 0;
    }
    if (!isfinite(R(A_CMD))) return vei_fail(m, "a_cmd is not finite");
    if (!ms->on_path) {
        ms->s = vei_polyline_project(&ms->path, R(X), R(Y));
        ms->on_path = 1;
    }
    VeiVehicleLimits lim = {R(MAX_ACCEL_MPS2), R(MAX_DECEL_MPS2), R(JERK_MAX_MPS3)};
    vei_ego_drive(&ms->path, NULL, &ms->s, R(A_CMD), &lim, h, &R(X), &R(Y), &R(YAW), &R(SPEED), &R(ACCEL));
    R(S) = ms->s;
    return 0;
}
