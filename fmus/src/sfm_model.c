/* The e-scooter social force model as an FMU: the rider of vei run's SocialForceController.
 *
 * Until behaviour_start_s the scooter keeps its initial speed and heading (the scenario's Init); then
 * it replays its recorded track shifted by time_shift_s until the rider starts (the track's first
 * time + the shift), then rides the social force model towards the route's waypoints, repelled by the
 * ego's box (normal rider) or not (aggressive). rider_type replay never rides.
 */
#include <math.h>
#include <string.h>

#include "fmu_instance.h"

#define R(name) (m->r[VR_##name])

int model_initialize(Instance *m) {
    ModelState *ms = &m->ms;
    const char *rider = m->s[VR_RIDER_TYPE];
    if (strcmp(rider, "replay") == 0)
        ms->rider = 0;
    else if (strcmp(rider, "normal") == 0)
        ms->rider = 1;
    else if (strcmp(rider, "aggressive") == 0)
        ms->rider = 2;
    else
        return vei_fail(m, "rider_type '%s' is not one of replay, normal, aggressive", rider);
    if (!(R(MASS_KG) > 0)) return vei_fail(m, "mass_kg must be positive (got %g)", R(MASS_KG));
    if (!(R(TAU_S) > 0)) return vei_fail(m, "tau_s must be positive (got %g)", R(TAU_S));
    if (R(SIGMA_M) < 0 || R(REPULSION_RANGE_M) <= 0 || R(MAX_SPEED_MPS) < 0 || R(MAX_DECEL_MPS2) < 0 ||
        R(MAX_ACCEL_MPS2) < 0 || R(WAYPOINT_RADIUS_M) < 0)
        return vei_fail(m, "sigma_m, max_speed_mps, max_accel_mps2, max_decel_mps2, waypoint_radius_m must not be "
                           "negative and repulsion_range_m must be positive");
    int n = m->i[VR_TRACK_N], nr = m->i[VR_ROUTE_N];
    if (n < 2 || n > VEI_MAX_PATH) return vei_fail(m, "track_n must be 2..%d (got %d)", VEI_MAX_PATH, n);
    if (nr < 1 || nr > VEI_MAX_ROUTE) return vei_fail(m, "route_n must be 1..%d (got %d)", VEI_MAX_ROUTE, nr);
    for (int k = 1; k < n; k++)
        if (!(m->r[VR_TRACK_T + k] > m->r[VR_TRACK_T + k - 1]))
            return vei_fail(m, "track_t must increase (track_t[%d] = %g after %g)", k + 1, m->r[VR_TRACK_T + k],
                            m->r[VR_TRACK_T + k - 1]);
    ms->track.x = &m->r[VR_TRACK_X];
    ms->track.y = &m->r[VR_TRACK_Y];
    ms->track.h = &m->r[VR_TRACK_H];
    ms->track.t = &m->r[VR_TRACK_T];
    ms->track.s = ms->track_s;
    ms->track.n = n;
    ms->track.exit_speed = NAN;
    vei_polyline_init(&ms->track);
    ms->agent = (VeiRider)VEI_RIDER_START;
    ms->t_start = ms->track.t[0] * 1.0 + R(TIME_SHIFT_S);
    ms->v_start = (ms->track_s[1] - ms->track_s[0]) / (ms->track.t[1] - ms->track.t[0]);
    R(X) = R(X0), R(Y) = R(Y0), R(YAW) = R(YAW0), R(SPEED) = R(SPEED0), R(ACCEL) = 0.0;
    R(VX) = R(SPEED) * cos(R(YAW)), R(VY) = R(SPEED) * sin(R(YAW));
    m->b[VR_RIDING] = 0;
    m->i[VR_WAYPOINT] = 0;
    return 0;
}

int model_do_step(Instance *m, double t, double h) {
    ModelState *ms = &m->ms;
    double t_next = t + h;
    if (!(t > R(BEHAVIOUR_START_S))) { /* not started: straight ahead at the current speed */
        vei_straight_ahead(&R(X), &R(Y), R(YAW), R(SPEED), &R(ACCEL), h);
    } else {
        VeiBox ego = {R(EGO_X), R(EGO_Y), R(EGO_YAW), R(EGO_LENGTH_M), R(EGO_WIDTH_M)};
        VeiSfmParams p = {R(V0_MPS),        R(MASS_KG),          R(TAU_S),             R(SIGMA_M),
                          R(REPULSION_N),   R(REPULSION_RANGE_M), R(WAYPOINT_RADIUS_M), R(MAX_SPEED_MPS),
                          R(MAX_ACCEL_MPS2), R(MAX_DECEL_MPS2)};
        double c = cos(R(YAW)), s = sin(R(YAW));
        int rides_now = ms->agent.riding || (ms->rider != 0 && t_next >= ms->t_start - 1e-9);
        if (rides_now && (!isfinite(ego.x) || !isfinite(ego.y) || !isfinite(ego.yaw)))
            return vei_fail(m, "the ego inputs are not finite"); /* (only a riding rider reads them) */
        vei_rider_step(&ms->agent, &ms->track, R(TIME_SHIFT_S), ms->t_start, ms->v_start, ms->rider != 0,
                       &m->r[VR_ROUTE_X], &m->r[VR_ROUTE_Y], m->i[VR_ROUTE_N], &p, ms->rider == 1, &ego,
                       cos(ego.yaw), sin(ego.yaw), t_next, h, &R(X), &R(Y), &R(YAW), &R(SPEED), &R(ACCEL), &c, &s);
        if (ms->agent.riding) m->i[VR_WAYPOINT] = ms->agent.st.waypoint;
    }
    m->b[VR_RIDING] = ms->agent.riding;
    if (ms->agent.riding) {
        R(VX) = ms->agent.st.vx, R(VY) = ms->agent.st.vy;
    } else {
        R(VX) = R(SPEED) * cos(R(YAW)), R(VY) = R(SPEED) * sin(R(YAW));
    }
    if (!isfinite(R(X)) || !isfinite(R(Y))) return vei_fail(m, "the scooter state became non-finite at t = %g", t);
    return 0;
}
