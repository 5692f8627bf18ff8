/* vei_models.h: the numerical models of vei-scenario in C: the compiled core (vei_scenario.core), the
 * sweep kernel and the FMUs.
 *
 * Each function mirrors a Python function of vei_scenario.models (or vei_scenario.interpreter) operation
 * for operation, so that the FMUs reproduce `vei run`; tests/test_fmus.py compares them on
 * 10 000 random states. Pure functions: no allocation, no I/O, no global state.
 */
#ifndef VEI_MODELS_H
#define VEI_MODELS_H

typedef struct { double x, y, yaw, length, width; } VeiBox;

/* vei_scenario.models.boxes.time_to_contact_scalar: time until two boxes moving at constant velocity
 * first touch; 0 when they overlap now, INFINITY when they never will. */
double vei_time_to_contact(const VeiBox *a, double vxa, double vya, const VeiBox *b, double vxb, double vyb);

/* vei_scenario.models.boxes.boxes_overlap_scalar */
int vei_boxes_overlap(const VeiBox *a, const VeiBox *b);

/* A box with the cosine and sine of its heading, for code that tests one box many times (the sweep
 * kernel); the functions below are the two above with the trigonometry done once. */
typedef struct { double x, y, yaw, length, width, c, s; } VeiTrigBox;
VeiTrigBox vei_trig_box(double x, double y, double yaw, double length, double width);
double vei_trig_time_to_contact(const VeiTrigBox *a, double vxa, double vya, const VeiTrigBox *b, double vxb,
                                double vyb);
int vei_trig_boxes_overlap(const VeiTrigBox *a, const VeiTrigBox *b);
double vei_trig_time_to_conflict(const VeiTrigBox *ego, double ego_speed, double margin, const VeiTrigBox *threat,
                                 double threat_vx, double threat_vy);

/* --- social force model (vei_scenario.models.sfm) --- */
typedef struct {
    double v0_mps, mass_kg, tau_s, sigma_m, repulsion_n, repulsion_range_m, waypoint_radius_m;
    double max_speed_mps, max_accel_mps2, max_decel_mps2;
} VeiSfmParams;

typedef struct { double x, y, vx, vy; int waypoint; } VeiSfmState;

void vei_sfm_acceleration(const VeiSfmState *st, double dest_x, double dest_y, const VeiSfmParams *p,
                          int repulsive, const VeiBox *ego, double *ax, double *ay);
/* One explicit step (sfm_step); route of n >= 1 waypoints; ego may be NULL. */
void vei_sfm_step(VeiSfmState *st, const double *route_x, const double *route_y, int n, const VeiSfmParams *p,
                  int repulsive, const VeiBox *ego, double dt);
/* The same step for a caller that knows the rider's speed hypot(vx, vy) and the cosine and sine of the
 * ego's heading (the sweep kernel: no trigonometry twice); returns the new speed hypot(vx, vy). */
double vei_sfm_step_trig(VeiSfmState *st, double speed, const double *route_x, const double *route_y, int n,
                         const VeiSfmParams *p, int repulsive, const VeiBox *ego, double c, double s, double dt);

/* --- collision-avoidance planner (vei_scenario.models.cap) --- */
typedef struct {
    double a_max_mps2, t_h_s, d0_m, kp, ki, kd, max_accel_mps2, max_cruise_decel_mps2, corridor_margin_m,
        horizon_s;
} VeiCapParams;

typedef struct { int brake; double integral; double prev_error; int has_prev; } VeiCapState;

/* One planner step (cap_step): returns the acceleration command; *d_safe receives d_safe.
 * ttc / resume_ttc: time to conflict (INFINITY: no conflict); resume_ttc is used only in BRAKE. */
double vei_cap_step(VeiCapState *st, const VeiCapParams *p, double cruise, double v, double ttc, double resume_ttc,
                    double dt, double *d_safe);

/* The reach of the planner's prefilter: the corridor's and the threat's circumscribed radii, with a
 * margin over rounding (1e-6 relative, 1e-9 absolute). */
double vei_conflict_reach(double ego_length, double ego_width, double margin, double threat_length,
                          double threat_width);
/* The planner's time to conflict within `horizon` (INFINITY beyond it): the box test below, left out
 * where the corridor's and the threat's circumscribed circles (`reach`), at constant velocity, meet no
 * sooner than the horizon. The interpreter and the sweep kernel both decide with it. */
double vei_trig_time_to_conflict_within(const VeiTrigBox *ego, double ego_speed, double margin, double reach,
                                        const VeiTrigBox *threat, double threat_vx, double threat_vy,
                                        double horizon);

/* The planner's view of the threat (interpreter.controllers.threat_view): the threat's box against
 * the ego's path corridor, the ego moving at `ego_speed` along its heading. */
double vei_threat_time_to_conflict(const VeiBox *ego, double ego_speed, double margin, const VeiBox *threat,
                                   double threat_vx, double threat_vy);

/* --- adaptive cruise (vei_scenario.models.acc: esmini's ACCController and ALKSController) --- */
typedef struct {
    double time_gap_s, lateral_dist_m, min_gap_m, approach_gain, distance_gain_mps2, stop_gap_m;
} VeiAccParams;

/* The speed after one step of dt from v (acc_speed): towards set_speed with nobody to follow (lead 0),
 * else behind a leader at bumper-to-bumper `gap` driving at v_lead. */
double vei_acc_speed(const VeiAccParams *p, double v, double set_speed, int lead, double gap, double v_lead,
                     double max_accel, double max_decel, double dt);
/* How far ahead along the lane a leader is looked for (AccParameters.lookahead_m). */
double vei_acc_lookahead(const VeiAccParams *p, double v, double max_decel);
/* The gap between the ego's front and the other's near end from the distance ds between their
 * reference points along the lane (bumper_gap). */
double vei_bumper_gap(double ds, double own_length, double own_center_x, double other_length, double other_center_x,
                      int same_way);
/* The gaps between two boxes along and across the first one's heading (box_gaps). */
void vei_box_gaps(const VeiBox *own, const VeiBox *other, double *along, double *across);
/* An entity just ahead of the ego's box that the lane test may miss (close_ahead). */
int vei_close_ahead(double x_gap, double y_gap, double other_length, double closing);

/* --- longitudinal vehicle (vei_scenario.models.vehicle) --- */
typedef struct { double s, v, a; } VeiLongitudinal;
typedef struct { double max_accel_mps2, max_decel_mps2, jerk_max_mps3; } VeiVehicleLimits;
void vei_longitudinal_step(VeiLongitudinal *st, double a_cmd, const VeiVehicleLimits *lim, double dt);

/* --- polylines (vei_scenario.interpreter.entities.Polyline) --- */
typedef struct {
    const double *x, *y, *h, *t; /* t may be NULL (untimed) */
    double *s;                   /* cumulative arc length, filled by vei_polyline_init */
    int n;
    double exit_speed;           /* speed kept after a timed end (a NURBS's); NAN: its last segment's */
} VeiPolyline;

void vei_polyline_init(VeiPolyline *p);
double vei_polyline_length(const VeiPolyline *p);
void vei_polyline_at_s(const VeiPolyline *p, double s, double *x, double *y, double *h);
void vei_polyline_at_time(const VeiPolyline *p, double t, double *x, double *y, double *h);
double vei_polyline_s_at_time(const VeiPolyline *p, double t);
/* The speed kept after a timed polyline's end: its exit_speed where given, else its last segment's
 * (a timed polyline of at least two vertices). */
double vei_polyline_end_speed(const VeiPolyline *p);
/* The three above for a caller moving forward along the path: a cursor (start it as VEI_CURSOR_START)
 * carries the segment from one call to the next instead of a bisection each time, and the last
 * heading's cosine and sine once computed; results are the same. */
typedef struct { int seg, has_end; double end_c, end_s; } VeiCursor;
#define VEI_CURSOR_START {-1, 0, 0.0, 0.0}
void vei_polyline_at_s_seg(const VeiPolyline *p, double s, VeiCursor *cur, double *x, double *y, double *h);
void vei_polyline_at_time_seg(const VeiPolyline *p, double t, VeiCursor *cur, double *x, double *y, double *h);
double vei_polyline_s_at_time_seg(const VeiPolyline *p, double t, VeiCursor *cur);
/* Arc length of the closest point of the path (FollowTrajectory without timing starts there). */
double vei_polyline_project(const VeiPolyline *p, double px, double py);

/* --- a clothoid sampled into a polyline (interpreter.shapes: a Clothoid or ClothoidSpline trajectory) ---
 * A clothoid's heading is quadratic in arc length, so its points have no closed form (Fresnel
 * integrals): they are integrated by the trapezoid rule on n_fine samples about `fine` apart, one
 * sample after the other (the cost of a trajectory is one cosine and one sine per sample), and kept
 * every `keep` samples and at the end. vei_clothoid_samples gives n_fine (at least 2) and the number
 * of kept points; vei_clothoid_sample fills x, y, h with them. */
long vei_clothoid_samples(double length, double fine, long keep, long *n_fine);
void vei_clothoid_sample(double x0, double y0, double h0, double curvature, double rate, double length, long n_fine,
                         long keep, double *x, double *y, double *h);

/* --- the rider agent (vei run's SocialForceController over its replayed track) --- */
typedef struct {
    VeiSfmState st;     /* the rider once it rides */
    double speed;       /* hypot(st.vx, st.vy) */
    double fs;          /* arc length of the replay along the track */
    int riding;         /* the social force model moves it */
    VeiCursor on_track; /* the replay's place on the track */
} VeiRider;
#define VEI_RIDER_START {{0, 0, 0, 0, 0}, 0.0, 0.0, 0, VEI_CURSOR_START}

/* One step of the rider once its behaviour has started: it replays its track shifted by `offset`
 * until `t_next` reaches `t_start` (when `rides`: a normal or aggressive rider), then starts at
 * `v_start` along its heading and rides the social force model towards the route's waypoints,
 * repelled by the ego's box (`repulsive`; `ego_c`, `ego_s`: cosine and sine of the ego's heading).
 * Pose, speed, acceleration and the heading's cosine and sine (`c`, `s`) are updated in place. The
 * sweep kernel and the e-scooter FMU both step the rider with it. */
void vei_rider_step(VeiRider *r, const VeiPolyline *track, double offset, double t_start, double v_start, int rides,
                    const double *route_x, const double *route_y, int route_n, const VeiSfmParams *p, int repulsive,
                    const VeiBox *ego, double ego_c, double ego_s, double t_next, double dt, double *x, double *y,
                    double *yaw, double *speed, double *accel, double *c, double *s);

/* The ego along its path (vei run's ego with the planner): the vehicle follows `a_cmd` within its limits
 * and moves along the path by the distance it covers, held at the path's end; pose, speed and
 * acceleration updated in place, `fs` the arc length along the path. The sweep kernel and the ego FMU
 * both drive the ego with it. */
/* The ego moved by a longitudinal command along its path; where the step reaches the path's end it
 * stands there, speed and acceleration 0 (a recorded path ends where the recording did: a faster
 * system runs out of it, and a held position at a kept speed would count as moving). */
void vei_ego_drive(const VeiPolyline *path, VeiCursor *cur, double *fs, double a_cmd, const VeiVehicleLimits *lim,
                   double dt, double *x, double *y, double *yaw, double *speed, double *accel);

/* Before its behaviour starts an entity keeps its Init speed and heading (the interpreter's motion of
 * an entity without a trajectory or speed action). Returns the distance moved. */
double vei_straight_ahead(double *x, double *y, double yaw, double speed, double *accel, double dt);

double vei_wrap_angle(double a);
double vei_hypot(double x, double y);

#endif
