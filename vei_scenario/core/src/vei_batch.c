/* vei_batch.c: see vei_batch.h. The simulation follows vei run's interpreter on the loop that
 * vei_scenario.loop.LoopScene reads (through the core's agents), the metrics
 * vei_scenario.metrics.definitions, operation for operation; tests/test_batch_native.py compares both
 * with vei run. */
#include "vei_batch.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

static double dmin(double a, double b) { return a < b ? a : b; }
static double dmax(double a, double b) { return a > b ? a : b; }

/* Contact values (metrics.definitions: EI_MIN_TTC_S, DRAC_CAP_MPS2): EI divides by the 2-D TTC but
 * not by less than 0.1 s, and DRAC is capped at 20 m/s^2 (about 2 g, beyond any tyre's grip: the
 * contact cannot be avoided by braking). Near contact both would otherwise grow without bound. */
#define VEI_EI_MIN_TTC_S 0.1
#define VEI_DRAC_CAP_MPS2 20.0
/* metrics/definitions.py: STANDING_MPS (the ego stands at or below it) and BRAKE_ONSET_MPS2 */
#define VEI_STANDING_MPS 0.1
#define VEI_BRAKE_ONSET_MPS2 1.0

/* The least distance from a's corners to box b, operation for operation as
 * vei_scenario.models.boxes.box_distance computes it (each corner in the world, then in b's frame, its
 * distance by hypot), so that a gap and what is derived from it (ACT, DRAC: quotients of small
 * differences) are the same bits in every engine. Only the corners whose squared distance lies within
 * 1e-12 of the least can hold the least hypot (hypot is within an ulp of the root), so only theirs
 * is taken. */
static double corners_to_box(const VeiTrigBox *a, const VeiTrigBox *b) {
    static const double along[4] = {1.0, -1.0, -1.0, 1.0}, across[4] = {1.0, 1.0, -1.0, -1.0};
    const double hl = 0.5 * a->length, hw = 0.5 * a->width, bl = 0.5 * b->length, bw = 0.5 * b->width;
    double ox[4], oy[4], d2[4], least = INFINITY;
    for (int k = 0; k < 4; k++) {
        double lx = along[k] * hl, ly = across[k] * hw; /* (an exact change of sign) */
        double cx = (a->x + a->c * lx) - a->s * ly, cy = (a->y + a->s * lx) + a->c * ly;
        double dx = cx - b->x, dy = cy - b->y;
        double px = b->c * dx + b->s * dy, py = (-b->s) * dx + b->c * dy;
        ox[k] = dmax(fabs(px) - bl, 0.0), oy[k] = dmax(fabs(py) - bw, 0.0);
        d2[k] = ox[k] * ox[k] + oy[k] * oy[k];
        least = dmin(least, d2[k]);
    }
    double out = INFINITY;
    for (int k = 0; k < 4; k++)
        if (d2[k] <= least * (1.0 + 1e-12)) out = dmin(out, hypot(ox[k], oy[k]));
    return out;
}

/* Distance between two disjoint boxes: they are closest at a corner of one of them, so it is the least
 * corner-to-box distance both ways. */
static double box_gap(const VeiTrigBox *a, const VeiTrigBox *b) {
    return dmin(corners_to_box(a, b), corners_to_box(b, a));
}

enum { EX, EY, EYAW, ESPEED, EACCEL, TX, TY, TYAW, TSPEED, TACCEL, NTRAJ };
/* the cosine and sine of each recorded heading: computed once per step by the simulation and shared
 * by the planner, the rider's repulsion from the ego and the metrics */
enum { EC, ES, TC, TS, NTRIG };
/* One entity's recorded rows in one table: x, y, yaw, speed, accel (of tr), cos, sin (of tg). */
enum { RX, RY, RYAW, RSPEED, RACCEL, RC, RS, NROWS };

/* The rows of entity e (0 ego, 1 threat) of tr/tg. */
static void entity_rows(double *tr[NTRAJ], double *tg[NTRIG], int e, double *rows[NROWS]) {
    for (int q = 0; q < 5; q++) rows[q] = tr[5 * e + q];
    rows[RC] = tg[2 * e], rows[RS] = tg[2 * e + 1];
}

/* tr/tg's rows of entity e pointed at rows. */
static void point_entity_rows(double *tr[NTRAJ], double *tg[NTRIG], int e, double *const rows[NROWS]) {
    for (int q = 0; q < 5; q++) tr[5 * e + q] = rows[q];
    tg[2 * e] = rows[RC], tg[2 * e + 1] = rows[RS];
}

static void copy_rows(double *const to[NROWS], double *const from[NROWS], int n) {
    for (int q = 0; q < NROWS; q++) memcpy(to[q], from[q], sizeof(double) * (size_t)n);
}

/* The key of motion shared between variants, compared bit for bit. */
static int same_key(const double a[3], const double b[3]) { return memcmp(a, b, 3 * sizeof(double)) == 0; }

/* vei_trig_time_to_conflict where it can matter. The planner treats every time to conflict beyond its
 * horizon as no conflict, and the boxes cannot touch before their circumscribed circles do: where the
 * circles stay apart for longer than the horizon (with a margin of 1e-6 for rounding), the box test
 * is skipped and INFINITY returned, which the planner treats exactly as it would the box test's value. */
static double conflict(const VeiBatchScene *sc, double reach, const VeiTrigBox *ego, double ego_speed,
                       const VeiTrigBox *threat, double tvx, double tvy) {
    return vei_trig_time_to_conflict_within(ego, ego_speed, sc->cap.corridor_margin_m, reach, threat, tvx, tvy,
                                            sc->cap.horizon_s);
}

/* The ego moved by a driver's command as vei run's plugged controller moves it (interpreter.plugged):
 * the vehicle model within the limits, the speed held at the Performance's maxSpeed, then along its path
 * (held at the path's end). */
static void driven(const VeiBatchScene *sc, VeiCursor *cur, double *fs, double a_cmd, double max_speed, double dt,
                   double *x, double *y, double *yaw, double *speed, double *accel) {
    VeiLongitudinal lon = {0.0, *speed, *accel};
    vei_longitudinal_step(&lon, a_cmd, &sc->limits, dt);
    double ds = lon.s, v = lon.v, a = lon.a;
    if (v > max_speed) { /* reached within the step, held there */
        v = max_speed;
        a = (v - *speed) / dt;
        ds = 0.5 * (*speed + v) * dt;
    }
    double along = *fs + ds, end = vei_polyline_length(&sc->ego_path);
    *fs = along < end ? along : end;
    *speed = v, *accel = a;
    vei_polyline_at_s_seg(&sc->ego_path, *fs, cur, x, y, yaw);
}

/* ---- simulation -------------------------------------------------------------------------------- */
/* With the planner on, the ego moves the same in every variant at one initial and cruise speed until
 * the planner first decides to brake: only that decision depends on the rider. The prefix of states
 * before it, recorded from earlier variants, is followed while a variant's own decision is not to
 * brake, and the variant works on from where it brakes or the prefix ends (~80 % of the planner's
 * steps in the case study need no ego motion of their own). */
typedef struct {
    double *row[NROWS];                   /* the ego's recorded state at each step */
    double *fs, *integral, *prev_error;   /* before each step's decision: arc length, planner state */
    int *has_prev, *seg;                  /* ... and the path cursor */
} EgoSteps;
typedef struct {
    int len;        /* states 0 .. len - 1 are known (0: none yet) */
    double key[3];  /* whose: initial speed, cruise speed */
    EgoSteps at;
} EgoPrefix;

/* One variant. With ego_given the ego's rows of tr and tg already hold its trajectory (a variant
 * without the planner at the same speed ran before: the ego's motion does not depend on the rider);
 * with threat_given the rider's rows do (a replayed or aggressive rider, who does not react to the
 * ego, at the same time shift and speed ran before); with pre, the planner's ego follows the prefix
 * while it can. Returns the step of the planner's first decision to brake (n_steps if it never
 * brakes); aux (planner variants) receives the state before each decision of the steps it works out
 * itself. */
static int simulate(const VeiBatchScene *sc, const VeiBatchVariant *v, double *tr[NTRAJ], double *tg[NTRIG],
                    int ego_given, int threat_given, const EgoPrefix *pre, EgoSteps *aux, double reach,
                    const VeiEgoDriver *drv) {
    const double dt = sc->dt;
    double x[2] = {sc->ego_x0, sc->threat_x0}, y[2] = {sc->ego_y0, sc->threat_y0};
    double yaw[2] = {sc->ego_yaw0, sc->threat_yaw0}, speed[2] = {v->ego_speed0, v->threat_speed0};
    double c[2] = {cos(yaw[0]), cos(yaw[1])}, s[2] = {sin(yaw[0]), sin(yaw[1])};
    double accel[2] = {0.0, 0.0}, fs[1] = {0.0};
    VeiCapState cap = {0, 0.0, 0.0, 0};
    VeiRider rider = VEI_RIDER_START;
    int started = 0, first_brake = sc->n_steps;
    int following = pre != NULL && pre->len > 0;
    VeiCursor on_path = VEI_CURSOR_START;
    const double t_start = sc->track.t[0] * 1.0 + v->offset;
    const double length = vei_polyline_length(&sc->ego_path);
    double *ego_rows[NROWS], *threat_rows[NROWS];
    entity_rows(tr, tg, 0, ego_rows), entity_rows(tr, tg, 1, threat_rows);
/* entity e's state from / into step k of its rows */
#define LOAD(rows, k, e)                                                                            \
    (x[e] = (rows)[RX][k], y[e] = (rows)[RY][k], yaw[e] = (rows)[RYAW][k],                          \
     speed[e] = (rows)[RSPEED][k], accel[e] = (rows)[RACCEL][k], c[e] = (rows)[RC][k], s[e] = (rows)[RS][k])
#define STORE(rows, k, e)                                                                           \
    ((rows)[RX][k] = x[e], (rows)[RY][k] = y[e], (rows)[RYAW][k] = yaw[e],                          \
     (rows)[RSPEED][k] = speed[e], (rows)[RACCEL][k] = accel[e], (rows)[RC][k] = c[e], (rows)[RS][k] = s[e])
#define RECORD(k)                                                                                   \
    do {                                                                                            \
        if (!ego_given) STORE(ego_rows, k, 0);                                                      \
        if (!threat_given) STORE(threat_rows, k, 1);                                                \
    } while (0)
#define PLANNER_FROM_PREFIX(k)                                                                      \
    do {                                                                                            \
        fs[0] = pre->at.fs[k], on_path.seg = pre->at.seg[k];                                        \
        cap.brake = 0, cap.integral = pre->at.integral[k], cap.prev_error = pre->at.prev_error[k];  \
        cap.has_prev = pre->at.has_prev[k];                                                         \
    } while (0)
    RECORD(0);
    for (int k = 0; k < sc->n_steps; k++) {
        double t = sc->t[k], t_next = t + dt;
        if (!started && t > sc->behaviour_start) {
            started = 1;
            if (!ego_given && !following) fs[0] = vei_polyline_project(&sc->ego_path, x[0], y[0]);
        }
        if (following && k + 1 >= pre->len) { /* the prefix ends here: on from its last state */
            PLANNER_FROM_PREFIX(k);
            following = 0;
        }
        if (aux != NULL && !following) {
            aux->fs[k] = fs[0], aux->seg[k] = on_path.seg;
            aux->integral[k] = cap.integral, aux->prev_error[k] = cap.prev_error, aux->has_prev[k] = cap.has_prev;
        }
        if (!started) { /* vei_straight_ahead with the heading's cosine and sine kept */
            for (int e = 0; e < 2; e++) {
                double v0 = speed[e];
                accel[e] = (speed[e] - v0) / dt;
                double ds = 0.5 * (v0 + speed[e]) * dt;
                x[e] = x[e] + ds * c[e];
                y[e] = y[e] + ds * s[e];
            }
            if (ego_given) LOAD(ego_rows, k + 1, 0);
            if (following) LOAD(pre->at.row, k + 1, 0);
            if (threat_given) LOAD(threat_rows, k + 1, 1);
            RECORD(k + 1);
            continue;
        }
        /* the ego: the planner where it is on, else its path at constant speed */
        if (ego_given) {
            LOAD(ego_rows, k + 1, 0);
        } else {
            double v0 = speed[0], before = yaw[0];
            if (drv != NULL) { /* the driver's command (vei run's plugged controller): shown the step's start */
                const double in[VEI_EGO_INPUTS] = {x[0], y[0], yaw[0], speed[0], accel[0], sc->ego_length,
                                                   sc->ego_width, x[1], y[1], yaw[1], speed[1], accel[1],
                                                   sc->threat_length, sc->threat_width, t};
                double a_cmd;
                if (drv->step(drv->self, in, t, dt, &a_cmd)) return -1;
                driven(sc, &on_path, &fs[0], a_cmd, drv->max_speed, dt, &x[0], &y[0], &yaw[0], &speed[0], &accel[0]);
            } else if (v->cap_on) {
                VeiTrigBox ego = {x[0], y[0], yaw[0], sc->ego_length, sc->ego_width, c[0], s[0]};
                VeiTrigBox threat = {x[1], y[1], yaw[1], sc->threat_length, sc->threat_width, c[1], s[1]};
                double tvx = speed[1] * threat.c, tvy = speed[1] * threat.s;
                double ttc = conflict(sc, reach, &ego, v0, &threat, tvx, tvy);
                double resume = cap.brake ? conflict(sc, reach, &ego, v->cruise, &threat, tvx, tvy) : ttc;
                double d_safe;
                VeiCapState next = cap;
                double a_cmd = vei_cap_step(&next, &sc->cap, v->cruise, v0, ttc, resume, dt, &d_safe);
                if (next.brake && first_brake == sc->n_steps) first_brake = k;
                if (following && !next.brake) { /* as the prefix did: its next state */
                    cap = next;
                    LOAD(pre->at.row, k + 1, 0);
                    goto threat;
                }
                if (following) { /* brakes where the prefix did not: on from here */
                    PLANNER_FROM_PREFIX(k);
                    following = 0;
                }
                cap = next;
                vei_ego_drive(&sc->ego_path, &on_path, &fs[0], a_cmd, &sc->limits, dt, &x[0], &y[0], &yaw[0],
                              &speed[0], &accel[0]);
            } else {
                fs[0] = dmin(fs[0] + 0.5 * (v0 + v0) * dt, length);
                accel[0] = (v0 - v0) / dt;
                vei_polyline_at_s_seg(&sc->ego_path, fs[0], &on_path, &x[0], &y[0], &yaw[0]);
            }
            if (yaw[0] != before) c[0] = cos(yaw[0]), s[0] = sin(yaw[0]);
        }
    threat:
        if (threat_given) {
            LOAD(threat_rows, k + 1, 1);
            RECORD(k + 1); /* the ego's row */
            continue;
        }
        /* the threat: replay of its shifted track until the rider starts, then the social force model */
        VeiBox ego = {x[0], y[0], yaw[0], sc->ego_length, sc->ego_width};
        vei_rider_step(&rider, &sc->track, v->offset, t_start, sc->v_start, v->sfm_on, sc->route_x, sc->route_y,
                       sc->route_n, &sc->sfm, v->repulsive, &ego, c[0], s[0], t_next, dt, &x[1], &y[1], &yaw[1],
                       &speed[1], &accel[1], &c[1], &s[1]);
        RECORD(k + 1);
    }
#undef LOAD
#undef STORE
#undef RECORD
#undef PLANNER_FROM_PREFIX
    return first_brake;
}

/* ---- metrics ------------------------------------------------------------------------------------- */
static void gradient(const VeiBatchScene *sc, const double *f, int n, double *out) {
    if (n < 2) {
        if (n == 1) out[0] = 0.0;
        return;
    }
    if (sc->grad_uniform) {
        for (int i = 1; i < n - 1; i++) out[i] = (f[i + 1] - f[i - 1]) / (2. * sc->grad_h);
    } else {
        for (int i = 1; i < n - 1; i++)
            out[i] = sc->grad_a[i - 1] * f[i - 1] + sc->grad_b[i - 1] * f[i] + sc->grad_c[i - 1] * f[i + 1];
    }
    out[0] = (f[1] - f[0]) / sc->grad_dx0;
    out[n - 1] = (f[n - 1] - f[n - 2]) / sc->grad_dxn;
}

/* The mean direction of the flagged samples (every step-th record), from their headings' cosines and
 * sines as the simulation computed them */
static double circular_mean_angle(const double *c, const double *s, int step, const int *in, int n) {
    double sum_c = 0.0, sum_s = 0.0;
    int m = 0;
    for (int i = 0; i < n; i++)
        if (in[i]) sum_c += c[i * step], sum_s += s[i * step], m++;
    return atan2(sum_s / m, sum_c / m);
}

static double pet(const VeiBatchScene *sc, double *tr[NTRAJ], double *tg[NTRIG], int n, int *in_e, int *in_o, int *ie,
                  int *io) {
    int step = sc->pet_step, m = 0;
    double reach = sc->radius_sum;
    double exmin = INFINITY, exmax = -INFINITY, eymin = INFINITY, eymax = -INFINITY;
    double oxmin = INFINITY, oxmax = -INFINITY, oymin = INFINITY, oymax = -INFINITY;
    for (int k = 0; k < n; k += step, m++) {
        exmin = dmin(exmin, tr[EX][k]), exmax = dmax(exmax, tr[EX][k]);
        eymin = dmin(eymin, tr[EY][k]), eymax = dmax(eymax, tr[EY][k]);
        oxmin = dmin(oxmin, tr[TX][k]), oxmax = dmax(oxmax, tr[TX][k]);
        oymin = dmin(oymin, tr[TY][k]), oymax = dmax(oymax, tr[TY][k]);
        in_e[m] = in_o[m] = 0;
    }
    int ne = 0, no = 0;
    for (int i = 0; i < m; i++) {
        double ex = tr[EX][i * step], ey = tr[EY][i * step], ox = tr[TX][i * step], oy = tr[TY][i * step];
        if (ex >= oxmin - reach && ex <= oxmax + reach && ey >= oymin - reach && ey <= oymax + reach) ie[ne++] = i;
        if (ox >= exmin - reach && ox <= exmax + reach && oy >= eymin - reach && oy <= eymax + reach) io[no++] = i;
    }
    /* pairs whose circumscribed circles meet: both sides' samples in blocks of 16 (consecutive in
     * time, so close together), a pair of blocks skipped when their bounding boxes are out of reach */
    enum { BLOCK = 16 };
    const double tl = sc->threat_length, tw = sc->threat_width;
    const double other_r2 = 0.25 * (tl * tl + tw * tw) * (1.0 + 1e-9); /* the other's circumradius squared */
    int n_eb = (ne + BLOCK - 1) / BLOCK;
    double ebox[n_eb > 0 ? n_eb : 1][4];
    for (int q = 0; q < n_eb; q++) {
        double *bb = ebox[q];
        bb[0] = INFINITY, bb[1] = -INFINITY, bb[2] = INFINITY, bb[3] = -INFINITY;
        for (int a = q * BLOCK; a < ne && a < (q + 1) * BLOCK; a++) {
            int i = ie[a] * step;
            bb[0] = dmin(bb[0], tr[EX][i]), bb[1] = dmax(bb[1], tr[EX][i]);
            bb[2] = dmin(bb[2], tr[EY][i]), bb[3] = dmax(bb[3], tr[EY][i]);
        }
    }
    int any = 0;
    for (int b0 = 0; b0 < no; b0 += BLOCK) {
        int b1 = b0 + BLOCK < no ? b0 + BLOCK : no;
        double bx0 = INFINITY, bx1 = -INFINITY, by0 = INFINITY, by1 = -INFINITY;
        for (int b = b0; b < b1; b++) {
            int j = io[b] * step;
            bx0 = dmin(bx0, tr[TX][j]), bx1 = dmax(bx1, tr[TX][j]);
            by0 = dmin(by0, tr[TY][j]), by1 = dmax(by1, tr[TY][j]);
        }
        for (int q = 0; q < n_eb; q++) {
            const double *bb = ebox[q];
            if (bb[1] < bx0 - reach || bb[0] > bx1 + reach || bb[3] < by0 - reach || bb[2] > by1 + reach) continue;
            for (int a = q * BLOCK; a < ne && a < (q + 1) * BLOCK; a++) {
                int i = ie[a] * step;
                double ex = tr[EX][i], ey = tr[EY][i];
                if (ex < bx0 - reach || ex > bx1 + reach || ey < by0 - reach || ey > by1 + reach) continue;
                VeiTrigBox eb = {ex, ey, tr[EYAW][i], sc->ego_length, sc->ego_width, tg[EC][i], tg[ES][i]};
                for (int b = b0; b < b1; b++) {
                    if (in_e[ie[a]] && in_o[io[b]]) continue; /* both already in the conflict area */
                    int j = io[b] * step;
                    double dx = ex - tr[TX][j], dy = ey - tr[TY][j];
                    if (dx * dx + dy * dy > reach * reach) continue;
                    /* the other's centre farther from the ego's box than the other's circumradius: apart */
                    double lx = fabs(eb.c * dx + eb.s * dy) - 0.5 * sc->ego_length;
                    double ly = fabs(-eb.s * dx + eb.c * dy) - 0.5 * sc->ego_width;
                    lx = dmax(lx, 0.0), ly = dmax(ly, 0.0);
                    if (lx * lx + ly * ly > other_r2) continue;
                    VeiTrigBox ob = {tr[TX][j], tr[TY][j], tr[TYAW][j], sc->threat_length, sc->threat_width,
                                     tg[TC][j], tg[TS][j]};
                    if (vei_trig_boxes_overlap(&eb, &ob)) in_e[ie[a]] = in_o[io[b]] = any = 1;
                }
            }
        }
    }
    if (!any) return NAN;
    double he = circular_mean_angle(tg[EC], tg[ES], step, in_e, m);
    double ho = circular_mean_angle(tg[TC], tg[TS], step, in_o, m);
    double d = he - ho;
    double crossing = fabs(atan2(sin(d), cos(d)) * (180.0 / M_PI));
    if (dmin(crossing, 180.0 - crossing) < 20.0) return NAN;
    int fe = -1, le = -1, fo = -1, lo = -1;
    for (int i = 0; i < m; i++) {
        if (in_e[i]) le = i, fe = fe < 0 ? i : fe;
        if (in_o[i]) lo = i, fo = fo < 0 ? i : fo;
    }
    const double *t = sc->t;
    double first_exit, second_entry;
    if (t[fe * step] <= t[fo * step])
        first_exit = t[le * step], second_entry = t[fo * step];
    else
        first_exit = t[lo * step], second_entry = t[fe * step];
    return dmax(0.0, second_entry - first_exit);
}

typedef struct {
    double *gap, *rate, *jerk;
    int *contact, *in_e, *in_o, *ie, *io;
} Scratch;

static void score(const VeiBatchScene *sc, double *tr[NTRAJ], double *tg[NTRIG], Scratch *w, double *out) {
    const int n = sc->n_steps + 1;
    const double *t = sc->t;
    int any_contact = 0, first_contact = -1, onset = -1, stand_start = -1, stood_from = -1;
    double min_gap = INFINITY, min_ttc = INFINITY, min_ttc_approx = INFINITY, ei_max = -INFINITY, impact = NAN;
    double ttc_at_onset = NAN;
    long zone[4] = {0, 0, 0, 0};
    for (int k = 0; k < n; k++) {
        double ex = tr[EX][k], ey = tr[EY][k], eyaw = tr[EYAW][k], ev = tr[ESPEED][k];
        double ox = tr[TX][k], oy = tr[TY][k], oyaw = tr[TYAW][k], ov = tr[TSPEED][k];
        VeiTrigBox eb = {ex, ey, eyaw, sc->ego_length, sc->ego_width, tg[EC][k], tg[ES][k]};
        VeiTrigBox ob = {ox, oy, oyaw, sc->threat_length, sc->threat_width, tg[TC][k], tg[TS][k]};
        double evx = ev * eb.c, evy = ev * eb.s, ovx = ov * ob.c, ovy = ov * ob.s;
        double rx = ox - ex, ry = oy - ey, vx = ovx - evx, vy = ovy - evy;
        double v2 = vx * vx + vy * vy, d2 = rx * rx + ry * ry;
        int closing = (rx * vx + ry * vy) < 0;
        /* Each box lies within its circumscribed circle. Where the circles are apart now (no contact)
         * or stay apart at constant velocity (no time to contact), the box tests are left out: they
         * would give the same answer, so every output stays bit-identical (~99 % of steps). */
        double reach = sc->radius_sum * (1.0 + 1e-9);
        int apart_now = d2 > reach * reach, apart_ahead = apart_now;
        /* the miss distance while closing; where its square shows it beyond reach (margin 1e-9 over
         * rounding) the time to contact is infinite and the Emergency Index 0, so it is not needed */
        double mfd = 0.0;
        if (closing) {
            double cross = rx * vy - ry * vx;
            if (apart_now && v2 > 1e-12 && cross * cross > reach * reach * v2 * (1.0 + 1e-9)) {
                mfd = INFINITY;
            } else {
                mfd = v2 > 1e-12 ? fabs(cross) / sqrt(v2) : hypot(rx, ry);
                apart_ahead = apart_now && mfd > reach;
            }
        }
        int contact = apart_now ? 0 : vei_trig_boxes_overlap(&eb, &ob);
        w->contact[k] = contact;
        if (ev <= VEI_STANDING_MPS) {
            if (stand_start < 0) stand_start = k;
        } else {
            stand_start = -1;
        }
        if (contact && !any_contact) any_contact = 1, first_contact = k, impact = hypot(vx, vy), stood_from = stand_start;
        double gap = contact ? 0.0 : box_gap(&eb, &ob);
        w->gap[k] = gap;
        min_gap = dmin(min_gap, gap);
        double ttc2d = apart_ahead ? INFINITY : vei_trig_time_to_contact(&eb, evx, evy, &ob, ovx, ovy);
        min_ttc = dmin(min_ttc, ttc2d);
        /* brake onset: the first step (up to the first contact) the ego decelerates at BRAKE_ONSET or more */
        if (onset < 0 && (!any_contact || k == first_contact) && tr[EACCEL][k] <= -VEI_BRAKE_ONSET_MPS2)
            onset = k, ttc_at_onset = ttc2d;
        /* the seed's approximation: gap to the other ahead in the ego's lane band / v_ego; the band is
         * at most half the ego's width plus half the other's diagonal wide, so beyond that the other's
         * relative heading is not needed */
        double c = eb.c, s = eb.s, dx = rx, dy = ry;
        double lateral = fabs(-s * dx + c * dy);
        double path_gap = INFINITY;
        if (lateral <= sc->band_reach) {
            double rel = oyaw - eyaw, cr = fabs(cos(rel)), sr = fabs(sin(rel));
            double ahead =
                c * dx + s * dy - 0.5 * sc->ego_length - 0.5 * (sc->threat_length * cr + sc->threat_width * sr);
            double half_band = 0.5 * sc->ego_width + 0.5 * (sc->threat_length * sr + sc->threat_width * cr);
            if (lateral <= half_band && ahead >= 0) path_gap = ahead;
        }
        double ttc_approx = (ev > 1e-3 && isfinite(path_gap)) ? path_gap / ev : INFINITY;
        if (contact) ttc_approx = 0.0;
        min_ttc_approx = dmin(min_ttc_approx, ttc_approx);
        double zt = sc->zone_ttc_2d ? ttc2d : ttc_approx;
        int z = contact ? 3 : (zt >= sc->safe_ttc ? 0 : (zt >= sc->alert_ttc ? 1 : 2));
        zone[z]++;
        /* Emergency Index */
        double in_depth = closing ? sc->radius_sum - mfd : 0.0;
        double ttc_ei = dmax(ttc2d, VEI_EI_MIN_TTC_S);
        double ei = (in_depth > 0 && isfinite(ttc2d)) ? in_depth / ttc_ei : 0.0;
        ei_max = dmax(ei_max, ei);
    }
    gradient(sc, w->gap, n, w->rate);
    gradient(sc, tr[EACCEL], n, w->jerk);
    double act_min = INFINITY, drac_max = -INFINITY, peak = INFINITY, jerk_max = 0.0;
    long comfortable = 0;
    for (int k = 0; k < n; k++) {
        double rate = -w->rate[k], gap = w->gap[k];
        /* a division only where its quotient can move the minimum or maximum (margins 1e-12 over the
         * rounding of the products, so the results are the same) */
        if (w->contact[k])
            act_min = dmin(act_min, 0.0);
        else if (rate > 1e-6 && !(gap > act_min * rate * (1.0 + 1e-12)))
            act_min = dmin(act_min, gap / rate);
        if (rate > 0 && gap > 1e-3) {
            if (!(rate * rate < drac_max * (2 * gap) * (1.0 - 1e-12)))
                drac_max = dmax(drac_max, rate * rate / (2 * gap));
        } else {
            drac_max = dmax(drac_max, 0.0);
        }
        double a = tr[EACCEL][k];
        peak = dmin(peak, a);
        jerk_max = dmax(jerk_max, fabs(w->jerk[k]));
        if (fabs(a) <= sc->comfort_accel + 1e-9 && fabs(w->jerk[k]) <= sc->comfort_jerk + 1e-9) comfortable++;
    }
    double times[4], total;
    for (int z = 0; z < 4; z++) times[z] = (double)zone[z] * sc->metric_dt;
    total = ((times[0] + times[1]) + times[2]) + times[3];
    double safety = total > 0 ? (times[0] + times[1]) / total : 1.0;
    out[OUT_COLLISION] = any_contact;
    out[OUT_COLLISION_TIME] = any_contact ? t[first_contact] : NAN;
    out[OUT_MIN_GAP] = min_gap;
    out[OUT_MIN_TTC] = min_ttc;
    out[OUT_MIN_TTC_APPROX] = min_ttc_approx;
    for (int z = 0; z < 4; z++) out[OUT_ZONE_SAFE + z] = times[z];
    out[OUT_SAFETY_INDEX] = any_contact ? 0.0 : safety;
    out[OUT_ACT_MIN] = act_min;
    out[OUT_EI_MAX] = ei_max;
    out[OUT_DRAC_MAX] = dmin(drac_max, VEI_DRAC_CAP_MPS2);
    out[OUT_PET] = pet(sc, tr, tg, n, w->in_e, w->in_o, w->ie, w->io);
    out[OUT_PEAK_DECEL] = dmax(0.0, -peak) + 0.0; /* + 0.0: never -0.0, as in the Python metric */
    out[OUT_MAX_JERK] = jerk_max;
    out[OUT_COMFORT] = (double)comfortable / n;
    out[OUT_NEAR_MISS] = !any_contact && sc->near_lo <= min_ttc && min_ttc <= sc->near_hi;
    out[OUT_IMPACT_SPEED] = impact;
    double ev_contact = any_contact ? tr[ESPEED][first_contact] : NAN;
    out[OUT_EGO_CONTACT_SPEED] = ev_contact;
    out[OUT_EGO_MOVING] = any_contact && ev_contact > VEI_STANDING_MPS;
    out[OUT_STOOD_BEFORE] = !any_contact ? NAN : (stood_from >= 0 ? t[first_contact] - t[stood_from] : 0.0);
    out[OUT_BRAKE_ONSET] = onset >= 0 ? t[onset] : NAN;
    out[OUT_TTC_AT_BRAKE] = onset >= 0 ? ttc_at_onset : NAN;
    out[OUT_SPEED_REDUCTION] = !any_contact ? NAN : (onset >= 0 ? tr[ESPEED][onset] - ev_contact : 0.0);
}

/* Keep the states of a planner variant that the prefix does not know yet: 0 .. first_brake are states
 * before its first decision to brake. */
static void extend_prefix(EgoPrefix *pre, const EgoSteps *aux, double *tr[NTRAJ], double *tg[NTRIG], int first_brake) {
    double *rows[NROWS];
    entity_rows(tr, tg, 0, rows);
    for (int k = pre->len; k <= first_brake; k++) {
        for (int q = 0; q < NROWS; q++) pre->at.row[q][k] = rows[q][k];
        pre->at.fs[k] = aux->fs[k], pre->at.integral[k] = aux->integral[k];
        pre->at.prev_error[k] = aux->prev_error[k], pre->at.has_prev[k] = aux->has_prev[k];
        pre->at.seg[k] = aux->seg[k];
    }
    if (first_brake + 1 > pre->len) pre->len = first_brake + 1;
}

static EgoSteps ego_steps(double *d, int *i, int n) {
    EgoSteps e;
    for (int q = 0; q < NROWS; q++) e.row[q] = d + (size_t)q * n;
    e.fs = d + (size_t)NROWS * n, e.integral = d + (size_t)(NROWS + 1) * n;
    e.prev_error = d + (size_t)(NROWS + 2) * n;
    e.has_prev = i, e.seg = i + n;
    return e;
}

/* Rows kept from one variant for the next one that moves the same (the ego without the planner, or a
 * rider who does not react to the ego), and whose motion they are. */
typedef struct {
    int valid;
    double key[3];
    double *row[NROWS];
} Kept;

/* Point entity e's rows at the kept ones (no trajectory recorded: the simulation writes into them), or
 * copy them in when they are given (recording). */
static void use_kept(const Kept *k, int given, double *tr[NTRAJ], double *tg[NTRIG], int e, double *traj, int n) {
    if (traj == NULL) {
        point_entity_rows(tr, tg, e, k->row);
    } else if (given) {
        double *rows[NROWS];
        entity_rows(tr, tg, e, rows);
        copy_rows(rows, k->row, n);
    }
}

static void keep(Kept *k, const double key[3], double *tr[NTRAJ], double *tg[NTRIG], int e, double *traj, int n) {
    if (traj != NULL) { /* recorded into the trajectory: copy out */
        double *rows[NROWS];
        entity_rows(tr, tg, e, rows);
        copy_rows(k->row, rows, n);
    }
    k->valid = 1;
    memcpy(k->key, key, sizeof k->key);
}

int vei_batch_run(const VeiBatchScene *sc, const VeiBatchVariant *v, int n_variants, double *out, double *traj) {
    const int n = sc->n_steps + 1;
    /* per variant: the trajectory, its headings' cosines and sines, gap, rate, jerk; then the kept ego
     * and rider rows; then the planner's prefix and one variant's own planner states (EgoSteps:
     * NROWS + 3 doubles, 2 ints) */
    enum { PER = NTRAJ + NTRIG + 3, KEPT = NROWS, STEPS = NROWS + 3 };
    double *buf = (double *)malloc(sizeof(double) * (size_t)n * (PER + 2 * KEPT + 2 * STEPS));
    int *ibuf = (int *)malloc(sizeof(int) * (size_t)n * (5 + 2 * 2));
    if (buf == NULL || ibuf == NULL) {
        free(buf), free(ibuf);
        return -1;
    }
    double *rows = buf + (size_t)(NTRAJ + NTRIG) * n;
    Scratch w = {rows, rows + n, rows + 2 * n, ibuf, ibuf + n, ibuf + 2 * n, ibuf + 3 * n, ibuf + 4 * n};
    Kept ego = {0, {0}, {0}}, rider = {0, {0}, {0}};
    for (int q = 0; q < KEPT; q++) {
        ego.row[q] = buf + (size_t)(PER + q) * n;
        rider.row[q] = buf + (size_t)(PER + KEPT + q) * n;
    }
    EgoPrefix prefix = {0, {0.0, 0.0, 0.0}, ego_steps(buf + (size_t)(PER + 2 * KEPT) * n, ibuf + 5 * n, n)};
    EgoSteps own = ego_steps(buf + (size_t)(PER + 2 * KEPT + STEPS) * n, ibuf + 7 * n, n);
    const double m = sc->cap.corridor_margin_m;
    const double reach = vei_conflict_reach(sc->ego_length, sc->ego_width, m, sc->threat_length, sc->threat_width);
    for (int i = 0; i < n_variants; i++) {
        const VeiBatchVariant *vi = &v[i];
        double *tr[NTRAJ], *tg[NTRIG];
        for (int q = 0; q < NTRAJ; q++) tr[q] = traj ? traj + ((size_t)i * NTRAJ + q) * n : buf + (size_t)q * n;
        for (int q = 0; q < NTRIG; q++) tg[q] = buf + (size_t)(NTRAJ + q) * n;
        /* the ego without the planner moves the same at one initial speed */
        const double ego_key[3] = {vi->ego_speed0, 0.0, 0.0};
        int ego_given = !vi->cap_on && ego.valid && same_key(ego.key, ego_key);
        if (!vi->cap_on) use_kept(&ego, ego_given, tr, tg, 0, traj, n);
        /* a rider who does not react to the ego (replayed, or the social force model without the ego's
         * repulsion) moves the same at one time shift and initial speed */
        const int rider_kept = !vi->sfm_on || !vi->repulsive;
        const double rider_key[3] = {vi->offset, (double)vi->sfm_on, vi->threat_speed0};
        int threat_given = rider_kept && rider.valid && same_key(rider.key, rider_key);
        if (rider_kept) use_kept(&rider, threat_given, tr, tg, 1, traj, n);
        /* the planner's ego before it brakes moves the same at one initial and cruise speed */
        const double prefix_key[3] = {vi->ego_speed0, vi->cruise, 0.0};
        if (vi->cap_on && !same_key(prefix.key, prefix_key)) /* another ego: start a new prefix */
            prefix.len = 0, memcpy(prefix.key, prefix_key, sizeof prefix.key);
        int first_brake = simulate(sc, vi, tr, tg, ego_given, threat_given, vi->cap_on ? &prefix : NULL,
                                   vi->cap_on ? &own : NULL, reach, NULL);
        if (vi->cap_on) extend_prefix(&prefix, &own, tr, tg, first_brake);
        if (!vi->cap_on && !ego_given) keep(&ego, ego_key, tr, tg, 0, traj, n);
        if (rider_kept && !threat_given) keep(&rider, rider_key, tr, tg, 1, traj, n);
        score(sc, tr, tg, &w, out + (size_t)i * VEI_BATCH_OUTPUTS);
    }
    free(buf);
    free(ibuf);
    return 0;
}

int vei_batch_run_driven(const VeiBatchScene *sc, const VeiBatchVariant *v, int n_variants, double *out,
                         double *traj, const VeiEgoDriver *drv) {
    const int n = sc->n_steps + 1;
    enum { PER = NTRAJ + NTRIG + 3, KEPT = NROWS };
    double *buf = (double *)malloc(sizeof(double) * (size_t)n * (PER + KEPT));
    int *ibuf = (int *)malloc(sizeof(int) * (size_t)n * 5);
    if (buf == NULL || ibuf == NULL) {
        free(buf), free(ibuf);
        return -1;
    }
    double *rows = buf + (size_t)(NTRAJ + NTRIG) * n;
    Scratch w = {rows, rows + n, rows + 2 * n, ibuf, ibuf + n, ibuf + 2 * n, ibuf + 3 * n, ibuf + 4 * n};
    Kept rider = {0, {0}, {0}};
    for (int q = 0; q < KEPT; q++) rider.row[q] = buf + (size_t)(PER + q) * n;
    const double m = sc->cap.corridor_margin_m;
    const double reach = vei_conflict_reach(sc->ego_length, sc->ego_width, m, sc->threat_length, sc->threat_width);
    for (int i = 0; i < n_variants; i++) {
        const VeiBatchVariant *vi = &v[i];
        double *o = out + (size_t)i * VEI_BATCH_OUTPUTS;
        double *tr[NTRAJ], *tg[NTRIG];
        for (int q = 0; q < NTRAJ; q++) tr[q] = traj ? traj + ((size_t)i * NTRAJ + q) * n : buf + (size_t)q * n;
        for (int q = 0; q < NTRIG; q++) tg[q] = buf + (size_t)(NTRAJ + q) * n;
        /* a rider who does not react to the ego moves the same at one time shift and initial speed */
        const int rider_kept = !vi->sfm_on || !vi->repulsive;
        const double rider_key[3] = {vi->offset, (double)vi->sfm_on, vi->threat_speed0};
        int threat_given = rider_kept && rider.valid && same_key(rider.key, rider_key);
        if (rider_kept) use_kept(&rider, threat_given, tr, tg, 1, traj, n);
        int failed = drv->begin(drv->self, i) != 0;
        if (!failed) {
            failed = simulate(sc, vi, tr, tg, 0, threat_given, NULL, NULL, reach, drv) < 0;
            drv->end(drv->self, failed);
        }
        if (failed) { /* the driver says why; the rows it left half written are no one's */
            for (int q = 0; q < VEI_BATCH_OUTPUTS; q++) o[q] = NAN;
            if (rider_kept && !threat_given) rider.valid = 0;
            continue;
        }
        if (rider_kept && !threat_given) keep(&rider, rider_key, tr, tg, 1, traj, n);
        score(sc, tr, tg, &w, o);
    }
    free(buf);
    free(ibuf);
    return 0;
}

int vei_batch_score(const VeiBatchScene *sc, const double *traj, double *out) {
    const int n = sc->n_steps + 1;
    double *buf = (double *)malloc(sizeof(double) * (size_t)n * (NTRIG + 3));
    int *ibuf = (int *)malloc(sizeof(int) * (size_t)n * 5);
    if (buf == NULL || ibuf == NULL) {
        free(buf), free(ibuf);
        return -1;
    }
    double *tr[NTRAJ], *tg[NTRIG];
    for (int q = 0; q < NTRAJ; q++) tr[q] = (double *)traj + (size_t)q * n;
    for (int q = 0; q < NTRIG; q++) tg[q] = buf + (size_t)q * n;
    for (int k = 0; k < n; k++) {
        tg[EC][k] = cos(tr[EYAW][k]), tg[ES][k] = sin(tr[EYAW][k]);
        tg[TC][k] = cos(tr[TYAW][k]), tg[TS][k] = sin(tr[TYAW][k]);
    }
    double *rows = buf + (size_t)NTRIG * n;
    Scratch w = {rows, rows + n, rows + 2 * n, ibuf, ibuf + n, ibuf + 2 * n, ibuf + 3 * n, ibuf + 4 * n};
    score(sc, tr, tg, &w, out);
    free(buf);
    free(ibuf);
    return 0;
}

#define VEI_OUTPUT_NAME(id, name) name ","
const char *vei_batch_outputs(void) { return VEI_BATCH_OUTPUT_LIST(VEI_OUTPUT_NAME); }
#undef VEI_OUTPUT_NAME
