/* vei_models.c: see vei_models.h. Every function follows its Python original line by line. */
#include "vei_models.h"

#include <math.h>
#include <stddef.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

double vei_hypot(double x, double y) { return hypot(x, y); }

double vei_wrap_angle(double a) {
    /* Python's (a + pi) % (2 pi) - pi: the remainder takes the divisor's sign. */
    const double two_pi = 2.0 * M_PI;
    double x = a + M_PI;
    if (x >= 0.0 && x < two_pi) return x - M_PI; /* fmod would return x itself: skip it */
    double r = fmod(x, two_pi);
    if (r != 0.0 && r < 0.0) r += two_pi;
    return r - M_PI;
}

void vei_rider_step(VeiRider *r, const VeiPolyline *track, double offset, double t_start, double v_start, int rides,
                    const double *route_x, const double *route_y, int route_n, const VeiSfmParams *p, int repulsive,
                    const VeiBox *ego, double ego_c, double ego_s, double t_next, double dt, double *x, double *y,
                    double *yaw, double *speed, double *accel, double *c, double *s) {
    if (rides && !r->riding && t_next >= t_start - 1e-9) {
        r->riding = 1;
        r->st.x = *x, r->st.y = *y;
        r->st.vx = v_start * *c, r->st.vy = v_start * *s;
        r->st.waypoint = 0;
        r->speed = hypot(r->st.vx, r->st.vy);
    }
    double before = *yaw;
    if (r->riding) {
        double sp = vei_sfm_step_trig(&r->st, r->speed, route_x, route_y, route_n, p, repulsive, ego, ego_c, ego_s, dt);
        r->speed = sp;
        *accel = (sp - *speed) / dt;
        *x = r->st.x, *y = r->st.y;
        if (sp > 0.05) *yaw = atan2(r->st.vy, r->st.vx);
        *speed = sp;
    } else { /* the replay of the recorded track, shifted in time */
        double tt = (t_next - offset) / 1.0;
        double target = vei_polyline_s_at_time_seg(track, tt, &r->on_track);
        double spd = (target - r->fs) / dt;
        *accel = (spd - *speed) / dt;
        *speed = spd;
        r->fs = target;
        vei_polyline_at_time_seg(track, tt, &r->on_track, x, y, yaw);
    }
    if (*yaw != before) *c = cos(*yaw), *s = sin(*yaw);
}

void vei_ego_drive(const VeiPolyline *path, VeiCursor *cur, double *fs, double a_cmd, const VeiVehicleLimits *lim,
                   double dt, double *x, double *y, double *yaw, double *speed, double *accel) {
    VeiLongitudinal lon = {0.0, *speed, *accel};
    vei_longitudinal_step(&lon, a_cmd, lim, dt);
    double along = *fs + lon.s, end = vei_polyline_length(path);
    if (along < end) {
        *fs = along, *speed = lon.v, *accel = lon.a;
    } else { /* at the path's end it stands (vei_models.h) */
        *fs = end, *speed = 0.0, *accel = 0.0;
    }
    vei_polyline_at_s_seg(path, *fs, cur, x, y, yaw);
}

double vei_straight_ahead(double *x, double *y, double yaw, double speed, double *accel, double dt) {
    double v0 = speed;
    *accel = (speed - v0) / dt;
    double ds = 0.5 * (v0 + speed) * dt;
    *x = *x + ds * cos(yaw);
    *y = *y + ds * sin(yaw);
    return ds;
}

static double dmin(double a, double b) { return a < b ? a : b; }
static double dmax(double a, double b) { return a > b ? a : b; }

VeiTrigBox vei_trig_box(double x, double y, double yaw, double length, double width) {
    VeiTrigBox b = {x, y, yaw, length, width, cos(yaw), sin(yaw)};
    return b;
}

double vei_trig_time_to_contact(const VeiTrigBox *a, double vxa, double vya, const VeiTrigBox *b, double vxb,
                                double vyb) {
    double dx = b->x - a->x, dy = b->y - a->y, wx = vxb - vxa, wy = vyb - vya;
    double ca = a->c, sa = a->s, cb = b->c, sb = b->s;
    double axes[4][2] = {{ca, sa}, {-sa, ca}, {cb, sb}, {-sb, cb}};
    double enter = -INFINITY, leave = INFINITY;
    for (int k = 0; k < 4; k++) {
        double ux = axes[k][0], uy = axes[k][1];
        double r = 0.5 * a->length * fabs(ux * ca + uy * sa) + 0.5 * a->width * fabs(-ux * sa + uy * ca);
        /* (r + b's half-extents one after the other: the sums of models.boxes.time_to_contact) */
        r = r + 0.5 * b->length * fabs(ux * cb + uy * sb) + 0.5 * b->width * fabs(-ux * sb + uy * cb);
        double p = dx * ux + dy * uy, q = wx * ux + wy * uy;
        if (fabs(q) <= 1e-12) {
            if (fabs(p) > r) return INFINITY;
            continue;
        }
        double t1 = (-r - p) / q, t2 = (r - p) / q;
        enter = dmax(enter, dmin(t1, t2));
        leave = dmin(leave, dmax(t1, t2));
    }
    return (enter <= leave && leave >= 0) ? dmax(enter, 0.0) : INFINITY;
}

int vei_trig_boxes_overlap(const VeiTrigBox *a, const VeiTrigBox *b) {
    double dx = b->x - a->x, dy = b->y - a->y;
    double ca = a->c, sa = a->s, cb = b->c, sb = b->s;
    double axes[4][2] = {{ca, sa}, {-sa, ca}, {cb, sb}, {-sb, cb}};
    for (int k = 0; k < 4; k++) {
        double ux = axes[k][0], uy = axes[k][1];
        double ra = 0.5 * a->length * fabs(ux * ca + uy * sa) + 0.5 * a->width * fabs(-ux * sa + uy * ca);
        double rb = 0.5 * b->length * fabs(ux * cb + uy * sb) + 0.5 * b->width * fabs(-ux * sb + uy * cb);
        if (fabs(dx * ux + dy * uy) > ra + rb) return 0;
    }
    return 1;
}

double vei_time_to_contact(const VeiBox *a, double vxa, double vya, const VeiBox *b, double vxb, double vyb) {
    VeiTrigBox ta = vei_trig_box(a->x, a->y, a->yaw, a->length, a->width);
    VeiTrigBox tb = vei_trig_box(b->x, b->y, b->yaw, b->length, b->width);
    return vei_trig_time_to_contact(&ta, vxa, vya, &tb, vxb, vyb);
}

int vei_boxes_overlap(const VeiBox *a, const VeiBox *b) {
    VeiTrigBox ta = vei_trig_box(a->x, a->y, a->yaw, a->length, a->width);
    VeiTrigBox tb = vei_trig_box(b->x, b->y, b->yaw, b->length, b->width);
    return vei_trig_boxes_overlap(&ta, &tb);
}

static void closest_point_on_box(double px, double py, const VeiBox *b, double c, double s, double *qx, double *qy) {
    double dx = px - b->x, dy = py - b->y;
    double lx = dmax(-0.5 * b->length, dmin(0.5 * b->length, c * dx + s * dy));
    double ly = dmax(-0.5 * b->width, dmin(0.5 * b->width, -s * dx + c * dy));
    *qx = b->x + c * lx - s * ly;
    *qy = b->y + s * lx + c * ly;
}

/* vei_sfm_acceleration with the cosine and sine of the ego's heading given (c, s) */
static void sfm_acceleration(const VeiSfmState *st, double dest_x, double dest_y, const VeiSfmParams *p, int repulsive,
                             const VeiBox *ego, double c, double s, double *ax, double *ay) {
    double ex = dest_x - st->x, ey = dest_y - st->y;
    double scale = p->v0_mps / sqrt(ex * ex + ey * ey + p->sigma_m * p->sigma_m);
    double k = p->mass_kg / p->tau_s;
    double fx = k * (ex * scale - st->vx);
    double fy = k * (ey * scale - st->vy);
    if (repulsive && ego != NULL) {
        double qx, qy;
        closest_point_on_box(st->x, st->y, ego, c, s, &qx, &qy);
        double nx = st->x - qx, ny = st->y - qy;
        double d = hypot(nx, ny);
        if (d > 1e-9) {
            double mag = p->repulsion_n * exp(-d / p->repulsion_range_m);
            fx += mag * nx / d;
            fy += mag * ny / d;
        } else { /* inside the ego box: push away from its centre */
            nx = st->x - ego->x;
            ny = st->y - ego->y;
            double n = hypot(nx, ny);
            if (n == 0.0) n = 1.0;
            fx += p->repulsion_n * nx / n;
            fy += p->repulsion_n * ny / n;
        }
    }
    *ax = fx / p->mass_kg;
    *ay = fy / p->mass_kg;
}

void vei_sfm_acceleration(const VeiSfmState *st, double dest_x, double dest_y, const VeiSfmParams *p,
                          int repulsive, const VeiBox *ego, double *ax, double *ay) {
    double c = ego != NULL ? cos(ego->yaw) : 1.0, s = ego != NULL ? sin(ego->yaw) : 0.0;
    sfm_acceleration(st, dest_x, dest_y, p, repulsive, ego, c, s, ax, ay);
}

/* hypot(dx, dy) <= r, with hypot evaluated only where the squared distance cannot decide it (hypot is
 * within an ulp of sqrt(dx^2 + dy^2), so the margins of 1e-9 leave the answer exact) */
static int within(double dx, double dy, double r) {
    double d2 = dx * dx + dy * dy, r2 = r * r;
    if (d2 > r2 * (1.0 + 1e-9)) return 0;
    if (d2 < r2 * (1.0 - 1e-9)) return 1;
    return hypot(dx, dy) <= r;
}

double vei_sfm_step_trig(VeiSfmState *st, double speed, const double *route_x, const double *route_y, int n,
                         const VeiSfmParams *p, int repulsive, const VeiBox *ego, double c, double s, double dt) {
    int wp = st->waypoint;
    while (wp < n - 1) {
        double wx = route_x[wp], wy = route_y[wp], nx_ = route_x[wp + 1], ny_ = route_y[wp + 1];
        int near = within(wx - st->x, wy - st->y, p->waypoint_radius_m);
        int passed = (st->x - wx) * (nx_ - wx) + (st->y - wy) * (ny_ - wy) > 0;
        if (near || passed)
            wp += 1;
        else
            break;
    }
    double ax, ay;
    sfm_acceleration(st, route_x[wp], route_y[wp], p, repulsive, ego, c, s, &ax, &ay);
    if (speed > 1e-9) {
        double ux = st->vx / speed, uy = st->vy / speed;
        double a_long = ax * ux + ay * uy;
        double a_lat_x = ax - a_long * ux, a_lat_y = ay - a_long * uy;
        a_long = dmax(-p->max_decel_mps2, dmin(p->max_accel_mps2, a_long));
        ax = a_long * ux + a_lat_x;
        ay = a_long * uy + a_lat_y;
    }
    if (!within(ax, ay, p->max_decel_mps2)) {
        double a = hypot(ax, ay);
        ax = ax * p->max_decel_mps2 / a;
        ay = ay * p->max_decel_mps2 / a;
    }
    double vx = st->vx + ax * dt, vy = st->vy + ay * dt;
    double v = hypot(vx, vy);
    if (v > p->max_speed_mps) {
        vx = vx * p->max_speed_mps / v;
        vy = vy * p->max_speed_mps / v;
        v = hypot(vx, vy);
    }
    st->x = st->x + 0.5 * (st->vx + vx) * dt;
    st->y = st->y + 0.5 * (st->vy + vy) * dt;
    st->vx = vx;
    st->vy = vy;
    st->waypoint = wp;
    return v;
}

void vei_sfm_step(VeiSfmState *st, const double *route_x, const double *route_y, int n, const VeiSfmParams *p,
                  int repulsive, const VeiBox *ego, double dt) {
    double c = ego != NULL ? cos(ego->yaw) : 1.0, s = ego != NULL ? sin(ego->yaw) : 0.0;
    vei_sfm_step_trig(st, hypot(st->vx, st->vy), route_x, route_y, n, p, repulsive, ego, c, s, dt);
}

/* ---------------------------------------------------------------------------------------------- */
double vei_cap_step(VeiCapState *st, const VeiCapParams *p, double cruise, double v, double ttc, double resume_ttc,
                    double dt, double *d_safe) {
    double ds = v * v / (2 * p->a_max_mps2) + v * p->t_h_s + p->d0_m;
    *d_safe = ds;
    int in_path = ttc <= p->horizon_s;
    double gap = in_path ? v * ttc : INFINITY;
    int brake = st->brake;
    if (!brake && in_path && gap < ds)
        brake = 1;
    else if (brake && !(resume_ttc <= p->horizon_s))
        brake = 0;
    if (brake) {
        double room = dmax(gap - p->d0_m, 0.05);
        double need = isfinite(gap) ? v * v / (2 * room) : 0.0;
        double a_cmd = v > 0 ? -dmin(p->a_max_mps2, dmax(need, p->max_cruise_decel_mps2)) : 0.0;
        st->brake = 1;
        st->has_prev = 0;
        return a_cmd;
    }
    double error = cruise - v;
    double deriv = st->has_prev ? (error - st->prev_error) / dt : 0.0;
    double integral = st->integral + error * dt;
    double a_raw = p->kp * error + p->ki * integral + p->kd * deriv;
    double a_cmd = dmax(-p->max_cruise_decel_mps2, dmin(p->max_accel_mps2, a_raw));
    if (a_cmd != a_raw) integral = st->integral; /* saturated: anti-windup */
    st->brake = 0;
    st->integral = integral;
    st->prev_error = error;
    st->has_prev = 1;
    return a_cmd;
}

double vei_trig_time_to_conflict(const VeiTrigBox *ego, double ego_speed, double margin, const VeiTrigBox *threat,
                                 double threat_vx, double threat_vy) {
    double c = ego->c, s = ego->s;
    VeiTrigBox corridor = {ego->x + 0.5 * margin * c, ego->y + 0.5 * margin * s, ego->yaw, ego->length + margin,
                           ego->width + 2 * margin, c, s};
    return vei_trig_time_to_contact(&corridor, ego_speed * c, ego_speed * s, threat, threat_vx, threat_vy);
}

double vei_conflict_reach(double ego_length, double ego_width, double margin, double threat_length,
                          double threat_width) {
    return (0.5 * hypot(ego_length + margin, ego_width + 2 * margin) + 0.5 * hypot(threat_length, threat_width)) *
               (1.0 + 1e-6) +
           1e-9;
}

double vei_trig_time_to_conflict_within(const VeiTrigBox *ego, double ego_speed, double m, double reach,
                                        const VeiTrigBox *threat, double tvx, double tvy, double horizon) {
    double cx = ego->x + 0.5 * m * ego->c, cy = ego->y + 0.5 * m * ego->s;
    double rx = threat->x - cx, ry = threat->y - cy;
    double wx = tvx - ego_speed * ego->c, wy = tvy - ego_speed * ego->s;
    double r2 = rx * rx + ry * ry, gap2 = r2 - reach * reach;
    if (gap2 > 0.0) {
        double b = rx * wx + ry * wy, a = wx * wx + wy * wy;
        if (b >= 0.0) return INFINITY; /* not closing: the circles never meet */
        double disc = b * b - a * gap2;
        if (disc < 0.0) return INFINITY; /* they pass each other */
        double t_meet = gap2 / (-b + sqrt(disc));
        if (t_meet > horizon * (1.0 + 1e-6) + 1e-9) return INFINITY;
    }
    return vei_trig_time_to_conflict(ego, ego_speed, m, threat, tvx, tvy);
}

double vei_threat_time_to_conflict(const VeiBox *ego, double ego_speed, double margin, const VeiBox *threat,
                                   double threat_vx, double threat_vy) {
    VeiTrigBox te = vei_trig_box(ego->x, ego->y, ego->yaw, ego->length, ego->width);
    VeiTrigBox tt = vei_trig_box(threat->x, threat->y, threat->yaw, threat->length, threat->width);
    return vei_trig_time_to_conflict(&te, ego_speed, margin, &tt, threat_vx, threat_vy);
}

/* ---------------------------------------------------------------------------------------------- */
/* Python's min(a, b) and max(a, b) of two floats (the first unless the second is smaller, larger): the
 * adaptive cruise is played by the interpreter through these functions, so the clamps keep its order */
static double first_min(double a, double b) { return b < a ? b : a; }
static double first_max(double a, double b) { return b > a ? b : a; }

double vei_acc_speed(const VeiAccParams *p, double v, double set_speed, int lead, double gap, double v_lead,
                     double max_accel, double max_decel, double dt) {
    if (!lead) { /* towards the set speed, not past it */
        double a = (set_speed - v) * p->approach_gain * max_accel;
        a = first_min(first_max(a, -max_decel), p->approach_gain * max_accel);
        double v1 = v + a * dt;
        return fabs(v1 - set_speed) > fabs(v - set_speed) ? set_speed : v1;
    }
    if (gap < p->stop_gap_m) return 0.0; /* (esmini's last resort) */
    double follow = p->min_gap_m + p->time_gap_s * fabs(first_max(v, v_lead));
    double f = first_min(1.0, (gap - follow) / follow);
    double dv_set = v - set_speed, dv_min = v - first_min(set_speed, v_lead);
    double a = p->distance_gain_mps2 * f - f * dv_set - (1.0 - f) * dv_min;
    a = first_min(first_max(a, -max_decel), max_accel);
    return first_min(first_max(0.0, v + a * dt), set_speed);
}

double vei_acc_lookahead(const VeiAccParams *p, double v, double max_decel) {
    return first_max(50.0, 2 * p->min_gap_m + v * v / first_max(max_decel, 1e-9));
}

double vei_bumper_gap(double ds, double own_length, double own_center_x, double other_length, double other_center_x,
                      int same_way) {
    double own_front = 0.5 * own_length + own_center_x;
    double other_near = same_way ? 0.5 * other_length - other_center_x : 0.5 * other_length + other_center_x;
    return ds - own_front - other_near;
}

/* the signed gap between [-half, half] and [centre - extent, centre + extent], 0 where they overlap */
static double interval_gap(double centre, double extent, double half) {
    if (centre - extent > half) return centre - extent - half;
    if (centre + extent < -half) return centre + extent + half;
    return 0.0;
}

void vei_box_gaps(const VeiBox *own, const VeiBox *other, double *along, double *across) {
    double c = cos(own->yaw), s = sin(own->yaw);
    double dx = other->x - own->x, dy = other->y - own->y;
    double a = c * dx + s * dy, b = -s * dx + c * dy;
    double cd = fabs(cos(other->yaw - own->yaw)), sd = fabs(sin(other->yaw - own->yaw));
    *along = interval_gap(a, 0.5 * (other->length * cd + other->width * sd), 0.5 * own->length);
    *across = interval_gap(b, 0.5 * (other->length * sd + other->width * cd), 0.5 * own->width);
}

int vei_close_ahead(double x_gap, double y_gap, double other_length, double closing) {
    return 0.0 < x_gap && x_gap < 1.0 + other_length + 0.5 * first_max(0.0, closing) && -0.5 < y_gap && y_gap < 0.2;
}

/* ---------------------------------------------------------------------------------------------- */
void vei_longitudinal_step(VeiLongitudinal *st, double a_cmd, const VeiVehicleLimits *lim, double dt) {
    double target = dmax(-lim->max_decel_mps2, dmin(lim->max_accel_mps2, a_cmd));
    /* the stop ramp (vehicle.py stop_ramp): ease off the braking at the jerk limit before standstill */
    double da = lim->jerk_max_mps3 * dt;
    if (target < 0.0 && st->v > 0.0) /* the stop ramp of vehicle.py: ease off to zero by standstill */
        target = dmax(target, -0.5 * (sqrt(da * da + 8.0 * lim->jerk_max_mps3 * st->v) - da));
    double a = dmax(st->a - da, dmin(st->a + da, target));
    double v0 = st->v;
    if (v0 <= 0.0 && a <= 0.0) {
        st->v = 0.0;
        st->a = 0.0;
        return;
    }
    double v1 = v0 + a * dt;
    if (v1 < 0.0) { /* comes to rest inside the step */
        double t_stop = v0 / -a;
        st->s = st->s + v0 * t_stop + 0.5 * a * t_stop * t_stop;
        st->v = 0.0;
        st->a = a;
        return;
    }
    st->s = st->s + v0 * dt + 0.5 * a * dt * dt;
    st->v = v1;
    st->a = a;
}

/* ---------------------------------------------------------------------------------------------- */
void vei_polyline_init(VeiPolyline *p) {
    p->s[0] = 0.0;
    for (int i = 1; i < p->n; i++) p->s[i] = p->s[i - 1] + hypot(p->x[i] - p->x[i - 1], p->y[i] - p->y[i - 1]);
}

double vei_polyline_length(const VeiPolyline *p) { return p->s[p->n - 1]; }

static int bisect_right(const double *a, int n, double v) {
    int lo = 0, hi = n;
    while (lo < hi) {
        int mid = (lo + hi) / 2;
        if (v < a[mid])
            hi = mid;
        else
            lo = mid + 1;
    }
    return lo;
}

static void lerp(const VeiPolyline *p, int i, double f, double *x, double *y, double *h) {
    int j = i + 1 < p->n - 1 ? i + 1 : p->n - 1;
    double h0 = p->h[i], h1 = p->h[j];
    *x = p->x[i] + f * (p->x[j] - p->x[i]);
    *y = p->y[i] + f * (p->y[j] - p->y[i]);
    *h = vei_wrap_angle(h0 + f * vei_wrap_angle(h1 - h0));
}

/* bisect_right(a, n, v) - 1 for a[0] <= v < a[n - 1], starting from the cursor's segment when that is at or before
 * the answer (a caller moving forward along a path finds its segment in a step or two) */
static int seek(const double *a, int n, double v, VeiCursor *cur) {
    int i = cur != NULL ? cur->seg : -1;
    if (i < 0 || i >= n || a[i] > v)
        i = bisect_right(a, n, v) - 1;
    else
        while (i + 1 < n && a[i + 1] <= v) i++;
    if (cur != NULL) cur->seg = i;
    return i;
}

void vei_polyline_at_s_seg(const VeiPolyline *p, double s, VeiCursor *cur, double *x, double *y, double *h) {
    if (s <= 0) {
        *x = p->x[0], *y = p->y[0], *h = p->h[0];
        return;
    }
    if (s >= p->s[p->n - 1]) {
        *x = p->x[p->n - 1], *y = p->y[p->n - 1], *h = p->h[p->n - 1];
        return;
    }
    int i = seek(p->s, p->n, s, cur);
    double ds = p->s[i + 1] - p->s[i];
    lerp(p, i, ds <= 0 ? 0.0 : (s - p->s[i]) / ds, x, y, h);
}

void vei_polyline_at_s(const VeiPolyline *p, double s, double *x, double *y, double *h) {
    vei_polyline_at_s_seg(p, s, NULL, x, y, h);
}

double vei_polyline_end_speed(const VeiPolyline *p) {
    if (!isnan(p->exit_speed)) return p->exit_speed;
    /* the last segment that takes time: vertices that repeat the last time are a jump at the end (esmini plays
     * them so), with no speed of their own */
    for (int e = p->n - 1; e > 0; e--) {
        double dt = p->t[e] - p->t[e - 1];
        if (dt > 0) return (p->s[e] - p->s[e - 1]) / dt;
    }
    return 0.0;
}

void vei_polyline_at_time_seg(const VeiPolyline *p, double t, VeiCursor *cur, double *x, double *y, double *h) {
    const double *ts = p->t;
    if (t <= ts[0]) {
        *x = p->x[0], *y = p->y[0], *h = p->h[0];
        return;
    }
    if (t >= ts[p->n - 1]) { /* after the recording: on along the last heading at the last speed */
        const int e = p->n - 1;
        double d = (t - ts[e]) * vei_polyline_end_speed(p), c, s;
        if (cur != NULL && cur->has_end) {
            c = cur->end_c, s = cur->end_s;
        } else {
            c = cos(p->h[e]), s = sin(p->h[e]);
            if (cur != NULL) cur->end_c = c, cur->end_s = s, cur->has_end = 1;
        }
        *x = p->x[e] + d * c, *y = p->y[e] + d * s, *h = p->h[e];
        return;
    }
    int i = seek(ts, p->n, t, cur);
    lerp(p, i, (t - ts[i]) / (ts[i + 1] - ts[i]), x, y, h);
}

void vei_polyline_at_time(const VeiPolyline *p, double t, double *x, double *y, double *h) {
    vei_polyline_at_time_seg(p, t, NULL, x, y, h);
}

double vei_polyline_s_at_time_seg(const VeiPolyline *p, double t, VeiCursor *cur) {
    const double *ts = p->t;
    if (t <= ts[0]) return 0.0;
    if (t >= ts[p->n - 1]) return p->s[p->n - 1] + (t - ts[p->n - 1]) * vei_polyline_end_speed(p);
    int i = seek(ts, p->n, t, cur);
    return p->s[i] + (t - ts[i]) / (ts[i + 1] - ts[i]) * (p->s[i + 1] - p->s[i]);
}

double vei_polyline_s_at_time(const VeiPolyline *p, double t) { return vei_polyline_s_at_time_seg(p, t, NULL); }

double vei_polyline_project(const VeiPolyline *p, double px, double py) {
    double best = 0.0, best_d = INFINITY;
    for (int i = 0; i < p->n - 1; i++) {
        double ax = p->x[i], ay = p->y[i], bx = p->x[i + 1], by = p->y[i + 1];
        double L2 = (bx - ax) * (bx - ax) + (by - ay) * (by - ay);
        double f = L2 == 0 ? 0.0 : dmax(0.0, dmin(1.0, ((px - ax) * (bx - ax) + (py - ay) * (by - ay)) / L2));
        double d = hypot(ax + f * (bx - ax) - px, ay + f * (by - ay) - py);
        if (d < best_d - 1e-12) {
            best = p->s[i] + f * (p->s[i + 1] - p->s[i]);
            best_d = d;
        }
    }
    return best;
}

/* --- a clothoid sampled into a polyline --- */

long vei_clothoid_samples(double length, double fine, long keep, long *n_fine) {
    double steps = ceil(length / fine);
    long n = steps + 1.0 > 2.0 ? (long)steps + 1 : 2;
    *n_fine = n;
    return (n - 1) / keep + 1 + ((n - 1) % keep != 0);
}

void vei_clothoid_sample(double x0, double y0, double h0, double curvature, double rate, double length, long n,
                         long keep, double *x, double *y, double *h) {
    /* the samples' arc lengths as an even grid from 0 to length, its last one the length itself; a
     * step too small to be told from 0 is spread as a fraction of the length instead */
    double step = length / (double)(n - 1), half_rate = 0.5 * rate;
    long k = 0;
#define ARC(i) ((i) == n - 1 ? length : step == 0.0 ? (double)(i) / (double)(n - 1) * length : (double)(i) * step)
    if (curvature == 0.0 && rate == 0.0) { /* a straight line: its points in closed form */
        double c = cos(h0), s = sin(h0);
        for (long i = 0; i < n; i += keep) x[k] = x0 + c * ARC(i), y[k] = y0 + s * ARC(i), h[k++] = h0 + 0.0;
        if ((n - 1) % keep) x[k] = x0 + c * length, y[k] = y0 + s * length, h[k] = h0 + 0.0;
        return;
    }
    /* the trapezoid rule, one sample at a time: each fine step adds the mean of its ends' cosines
     * (sines) times its length */
    double s_prev = 0.0, h_first = (h0 + curvature * 0.0) + half_rate * 0.0 * 0.0, vx = 0.0, vy = 0.0;
    double c_prev = cos(h_first), sn_prev = sin(h_first);
    x[k] = x0 + vx, y[k] = y0 + vy, h[k++] = h_first;
    for (long i = 1; i < n; i++) {
        double s = ARC(i), hi = (h0 + curvature * s) + half_rate * s * s, c = cos(hi), sn = sin(hi), ds = s - s_prev;
        vx += 0.5 * (c + c_prev) * ds;
        vy += 0.5 * (sn + sn_prev) * ds;
        if (i % keep == 0 || i == n - 1) x[k] = x0 + vx, y[k] = y0 + vy, h[k++] = hi;
        s_prev = s, c_prev = c, sn_prev = sn;
    }
#undef ARC
}
