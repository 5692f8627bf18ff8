/* The collision-avoidance planner as an FMU: vei run's CollisionAvoidanceController without the
 * vehicle (the ego FMU moves the ego with this FMU's command).
 *
 * A doStep from t samples the inputs (ego and threat at t), advances the state machine and outputs the
 * command for the interval that follows, as the interpreter does within its step. Disabled, or before
 * behaviour_start_s, the command is 0: the ego holds its speed.
 */
#include <math.h>

#include "fmu_instance.h"

#define R(name) (m->r[VR_##name])

static VeiCapParams params(const Instance *m) {
    VeiCapParams p = {R(A_MAX_MPS2), R(T_H_S),     R(D0_M), R(KP), R(KI), R(KD), R(MAX_ACCEL_MPS2),
                      R(MAX_CRUISE_DECEL_MPS2), R(CORRIDOR_MARGIN_M), R(HORIZON_S)};
    return p;
}

int model_initialize(Instance *m) {
    if (!(R(A_MAX_MPS2) > 0)) return vei_fail(m, "a_max_mps2 must be positive (got %g)", R(A_MAX_MPS2));
    if (R(T_H_S) < 0 || R(D0_M) < 0 || R(CORRIDOR_MARGIN_M) < 0 || R(HORIZON_S) < 0 || R(MAX_ACCEL_MPS2) < 0 ||
        R(MAX_CRUISE_DECEL_MPS2) < 0)
        return vei_fail(m, "t_h_s, d0_m, corridor_margin_m, horizon_s and the comfort limits must not be negative");
    if (R(CRUISE_SPEED_MPS) < 0) return vei_fail(m, "cruise_speed_mps must not be negative (got %g)", R(CRUISE_SPEED_MPS));
    if (!(R(EGO_LENGTH_M) > 0 && R(EGO_WIDTH_M) > 0 && R(THREAT_LENGTH_M) > 0 && R(THREAT_WIDTH_M) > 0))
        return vei_fail(m, "box dimensions must be positive");
    m->ms.state.brake = 0;
    m->ms.state.integral = 0.0;
    m->ms.state.prev_error = 0.0;
    m->ms.state.has_prev = 0;
    R(A_CMD) = 0.0;
    VeiCapParams p = params(m);
    double v = R(EGO_SPEED);
    R(D_SAFE) = v * v / (2 * p.a_max_mps2) + v * p.t_h_s + p.d0_m;
    R(TIME_TO_CONFLICT) = 1e9;
    m->i[VR_MODE] = 0;
    return 0;
}

int model_do_step(Instance *m, double t, double h) {
    VeiCapParams p = params(m);
    double v = R(EGO_SPEED);
    if (!m->b[VR_ENABLED] || !(t > R(BEHAVIOUR_START_S))) {
        R(A_CMD) = 0.0;
        R(D_SAFE) = v * v / (2 * p.a_max_mps2) + v * p.t_h_s + p.d0_m;
        return 0;
    }
    VeiBox ego = {R(EGO_X), R(EGO_Y), R(EGO_YAW), R(EGO_LENGTH_M), R(EGO_WIDTH_M)};
    VeiBox threat = {R(THREAT_X), R(THREAT_Y), R(THREAT_YAW), R(THREAT_LENGTH_M), R(THREAT_WIDTH_M)};
    double tvx = R(THREAT_SPEED) * cos(threat.yaw), tvy = R(THREAT_SPEED) * sin(threat.yaw);
    double ttc = vei_threat_time_to_conflict(&ego, v, p.corridor_margin_m, &threat, tvx, tvy);
    double resume = m->ms.state.brake
                        ? vei_threat_time_to_conflict(&ego, R(CRUISE_SPEED_MPS), p.corridor_margin_m, &threat, tvx, tvy)
                        : ttc;
    double d_safe;
    R(A_CMD) = vei_cap_step(&m->ms.state, &p, R(CRUISE_SPEED_MPS), v, ttc, resume, h, &d_safe);
    R(D_SAFE) = d_safe;
    R(TIME_TO_CONFLICT) = isfinite(ttc) ? ttc : 1e9;
    m->i[VR_MODE] = m->ms.state.brake;
    return 0;
}
