/* vei_batch.c: see vei_batch.h. The simulation follows vei_scenario.batch.engine.BatchScenario.run
 * (itself equal to vei run), the metrics vei_scenario.metrics.definitions, operation for operation;
 * tests/test_batch_native.py compares both with vei run. */
#include "vei_batch.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

static double dmin(double a, double b) { return a < b ? a : b; }
static double dmax(double a, double b) { return a > b ? a : b; }

/* Offsets (ox, oy) of a point outside a box along the box's axes; its distance is hypot(ox, oy). */
static void point_box_offsets(double px, double py, const VeiTrigBox *b, double *ox, double *oy) {
    double dx = px - b->x, dy = py - b->y;
    double lx = b->c * dx + b->s * dy, ly = -b->s * dx + b->c * dy;
    *ox = dmax(fabs(lx) - 0.5 * b->length, 0.0);
    *oy = dmax(fabs(ly) - 0.5 * b->width, 0.0);
}

/* The offsets of a's corners from b, and the least squared corner distance. */
static double corners_to_box(const VeiTrigBox *a, const VeiTrigBox *b, double ox[4], double oy[4]) {
    double c = a->c, s = a->s, hl = 0.5 * a->length, hw = 0.5 * a->width;
    const double lx[4] = {hl, -hl, -hl, hl}, ly[4] = {hw, hw, -hw, -hw};
    double least = INFINITY;
    for (int k = 0; k < 4; k++) {
        point_box_offsets(a->x + c * lx[k] - s * ly[k], a->y + s * lx[k] + c * ly[k], b, &ox[k], &oy[k]);
        double d2 = ox[k] * ox[k] + oy[k] * oy[k];
        if (d2 < least) least = d2;
    }
    return least;
}

/* The least corner-to-box distance min_k hypot(ox_k, oy_k) both ways, with hypot evaluated only for
 * corners whose squared distance is within 1e-9 (relative) of the least: hypot is monotonic, so the
 * corners left out cannot give the minimum, and the result equals the minimum over all eight. */
static double box_gap(const VeiTrigBox *a, const VeiTrigBox *b) {
    double oxa[4], oya[4], oxb[4], oyb[4];
    double la = corners_to_box(a, b, oxa, oya), lb = corners_to_box(b, a, oxb, oyb);
    double limit = dmin(la, lb) * (1.0 + 1e-9), best = INFINITY;
    for (int k = 0; k < 4; k++) {
        if (oxa[k] * oxa[k] + oya[k] * oya[k] <= limit) best = dmin(best, hypot(oxa[k], oya[k]));
        if (oxb[k] * oxb[k] + oyb[k] * oyb[k] <= limit) best = dmin(best, hypot(oxb[k], oyb[k]));
    }
    return best;
}

enum { EX, EY, EYAW, ESPEED, EACCEL, TX, TY, TYAW, TSPEED, TACCEL, NTRAJ };

/* ---- simulation -------------------------------------------------------------------------------- */
static void simulate(const VeiBatchScene *sc, const VeiBatchVariant *v, double *tr[NTRAJ]) {
    const double dt = sc->dt;
    double x[2] = {sc->ego_x0, sc->threat_x0}, y[2] = {sc->ego_y0, sc->threat_y0};
    double yaw[2] = {sc->ego_yaw0, sc->threat_yaw0}, speed[2] = {v->ego_speed0, v->threat_speed0};
    double accel[2] = {0.0, 0.0}, fs[2] = {0.0, 0.0};
    VeiCapState cap = {0, 0.0, 0.0, 0};
    VeiSfmState st = {0, 0, 0, 0, 0};
    int riding = 0, started = 0;
    const double t_start = sc->track.t[0] * 1.0 + v->offset;
    const double length = vei_polyline_length(&sc->ego_path);
#define RECORD(k)                                                                                   \
    do {                                                                                            \
        tr[EX][k] = x[0], tr[EY][k] = y[0], tr[EYAW][k] = yaw[0], tr[ESPEED][k] = speed[0];         \
        tr[EACCEL][k] = accel[0], tr[TX][k] = x[1], tr[TY][k] = y[1], tr[TYAW][k] = yaw[1];         \
        tr[TSPEED][k] = speed[1], tr[TACCEL][k] = accel[1];                                         \
    } while (0)
    RECORD(0);
    for (int k = 0; k < sc->n_steps; k++) {
        double t = sc->t[k], t_next = t + dt;
        if (!started && t > sc->behaviour_start) {
            started = 1;
            fs[0] = vei_polyline_project(&sc->ego_path, x[0], y[0]);
        }
        if (!started) {
            for (int e = 0; e < 2; e++) vei_straight_ahead(&x[e], &y[e], yaw[e], speed[e], &accel[e], dt);
            RECORD(k + 1);
            continue;
        }
        /* the ego: the planner where it is on, else its path at constant speed */
        double v0 = speed[0];
        if (v->cap_on) {
            VeiTrigBox ego = vei_trig_box(x[0], y[0], yaw[0], sc->ego_length, sc->ego_width);
            VeiTrigBox threat = vei_trig_box(x[1], y[1], yaw[1], sc->threat_length, sc->threat_width);
            double tvx = speed[1] * threat.c, tvy = speed[1] * threat.s;
            double m = sc->cap.corridor_margin_m;
            double ttc = vei_trig_time_to_conflict(&ego, v0, m, &threat, tvx, tvy);
            double resume = cap.brake ? vei_trig_time_to_conflict(&ego, v->cruise, m, &threat, tvx, tvy) : ttc;
            double d_safe;
            double a_cmd = vei_cap_step(&cap, &sc->cap, v->cruise, v0, ttc, resume, dt, &d_safe);
            VeiLongitudinal lon = {0.0, v0, accel[0]};
            vei_longitudinal_step(&lon, a_cmd, &sc->limits, dt);
            fs[0] = dmin(fs[0] + lon.s, length);
            speed[0] = lon.v;
            accel[0] = lon.a;
        } else {
            fs[0] = dmin(fs[0] + 0.5 * (v0 + v0) * dt, length);
            accel[0] = (v0 - v0) / dt;
        }
        vei_polyline_at_s(&sc->ego_path, fs[0], &x[0], &y[0], &yaw[0]);
        /* the threat: replay of its shifted track until the rider starts, then the social force model */
        if (v->sfm_on && !riding && t_next >= t_start - 1e-9) {
            riding = 1;
            st.x = x[1], st.y = y[1];
            st.vx = sc->v_start * cos(yaw[1]), st.vy = sc->v_start * sin(yaw[1]);
            st.waypoint = 0;
        }
        if (riding) {
            VeiBox ego = {x[0], y[0], yaw[0], sc->ego_length, sc->ego_width};
            vei_sfm_step(&st, sc->route_x, sc->route_y, sc->route_n, &sc->sfm, v->repulsive, &ego, dt);
            double sp = hypot(st.vx, st.vy);
            accel[1] = (sp - speed[1]) / dt;
            x[1] = st.x, y[1] = st.y;
            if (sp > 0.05) yaw[1] = atan2(st.vy, st.vx);
            speed[1] = sp;
        } else {
            double tt = (t_next - v->offset) / 1.0;
            double target = vei_polyline_s_at_time(&sc->track, tt);
            double spd = (target - fs[1]) / dt;
            accel[1] = (spd - speed[1]) / dt;
            speed[1] = spd;
            fs[1] = target;
            vei_polyline_at_time(&sc->track, tt, &x[1], &y[1], &yaw[1]);
        }
        RECORD(k + 1);
    }
#undef RECORD
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

static double circular_mean_angle(const double *yaw, const int *in, int n) {
    double sc = 0.0, ss = 0.0;
    int m = 0;
    for (int i = 0; i < n; i++)
        if (in[i]) sc += cos(yaw[i]), ss += sin(yaw[i]), m++;
    return atan2(ss / m, sc / m);
}

static double pet(const VeiBatchScene *sc, double *tr[NTRAJ], int n, int *in_e, int *in_o, int *ie, int *io) {
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
    /* pairs whose circumscribed circles meet: the other's samples in blocks of 16 (consecutive in
     * time, so close together), a block skipped when its bounding box is out of reach */
    enum { BLOCK = 16 };
    int any = 0;
    for (int b0 = 0; b0 < no; b0 += BLOCK) {
        int b1 = b0 + BLOCK < no ? b0 + BLOCK : no;
        double bx0 = INFINITY, bx1 = -INFINITY, by0 = INFINITY, by1 = -INFINITY;
        for (int b = b0; b < b1; b++) {
            int j = io[b] * step;
            bx0 = dmin(bx0, tr[TX][j]), bx1 = dmax(bx1, tr[TX][j]);
            by0 = dmin(by0, tr[TY][j]), by1 = dmax(by1, tr[TY][j]);
        }
        for (int a = 0; a < ne; a++) {
            int i = ie[a] * step;
            double ex = tr[EX][i], ey = tr[EY][i];
            if (ex < bx0 - reach || ex > bx1 + reach || ey < by0 - reach || ey > by1 + reach) continue;
            VeiTrigBox eb = vei_trig_box(ex, ey, tr[EYAW][i], sc->ego_length, sc->ego_width);
            for (int b = b0; b < b1; b++) {
                int j = io[b] * step;
                double dx = ex - tr[TX][j], dy = ey - tr[TY][j];
                if (dx * dx + dy * dy > reach * reach) continue;
                VeiTrigBox ob = vei_trig_box(tr[TX][j], tr[TY][j], tr[TYAW][j], sc->threat_length, sc->threat_width);
                if (vei_trig_boxes_overlap(&eb, &ob)) in_e[ie[a]] = in_o[io[b]] = any = 1;
            }
        }
    }
    if (!any) return NAN;
    double eyaw[m], oyaw[m]; /* sampled headings */
    for (int i = 0; i < m; i++) eyaw[i] = tr[EYAW][i * step], oyaw[i] = tr[TYAW][i * step];
    double he = circular_mean_angle(eyaw, in_e, m), ho = circular_mean_angle(oyaw, in_o, m);
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

static void score(const VeiBatchScene *sc, double *tr[NTRAJ], Scratch *w, double *out) {
    const int n = sc->n_steps + 1;
    const double *t = sc->t;
    int any_contact = 0, first_contact = -1;
    double min_gap = INFINITY, min_ttc = INFINITY, min_ttc_approx = INFINITY, ei_max = -INFINITY, impact = NAN;
    long zone[4] = {0, 0, 0, 0};
    for (int k = 0; k < n; k++) {
        double ex = tr[EX][k], ey = tr[EY][k], eyaw = tr[EYAW][k], ev = tr[ESPEED][k];
        double ox = tr[TX][k], oy = tr[TY][k], oyaw = tr[TYAW][k], ov = tr[TSPEED][k];
        VeiTrigBox eb = vei_trig_box(ex, ey, eyaw, sc->ego_length, sc->ego_width);
        VeiTrigBox ob = vei_trig_box(ox, oy, oyaw, sc->threat_length, sc->threat_width);
        double evx = ev * eb.c, evy = ev * eb.s, ovx = ov * ob.c, ovy = ov * ob.s;
        double rx = ox - ex, ry = oy - ey, vx = ovx - evx, vy = ovy - evy;
        double v2 = vx * vx + vy * vy, d2 = rx * rx + ry * ry;
        int closing = (rx * vx + ry * vy) < 0;
        double mfd = v2 > 1e-12 ? fabs(rx * vy - ry * vx) / sqrt(v2) : hypot(rx, ry);
        /* Each box lies within its circumscribed circle. Where the circles are apart now (no contact)
         * or stay apart at constant velocity (no time to contact), the box tests are left out: they
         * would give the same answer, so every output stays bit-identical (~99 % of steps). */
        double reach = sc->radius_sum * (1.0 + 1e-9);
        int apart_now = d2 > reach * reach;
        int apart_ahead = apart_now && (!closing || mfd > reach);
        int contact = apart_now ? 0 : vei_trig_boxes_overlap(&eb, &ob);
        w->contact[k] = contact;
        if (contact && !any_contact) any_contact = 1, first_contact = k, impact = hypot(vx, vy);
        double gap = contact ? 0.0 : box_gap(&eb, &ob);
        w->gap[k] = gap;
        min_gap = dmin(min_gap, gap);
        double ttc2d = apart_ahead ? INFINITY : vei_trig_time_to_contact(&eb, evx, evy, &ob, ovx, ovy);
        min_ttc = dmin(min_ttc, ttc2d);
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
        double ttc_ei = dmax(ttc2d, sc->metric_dt);
        double ei = (in_depth > 0 && isfinite(ttc2d)) ? in_depth / ttc_ei : 0.0;
        ei_max = dmax(ei_max, ei);
    }
    gradient(sc, w->gap, n, w->rate);
    gradient(sc, tr[EACCEL], n, w->jerk);
    double act_min = INFINITY, drac_max = -INFINITY, peak = INFINITY, jerk_max = 0.0;
    long comfortable = 0;
    for (int k = 0; k < n; k++) {
        double rate = -w->rate[k], gap = w->gap[k];
        double act = rate > 1e-6 ? gap / rate : INFINITY;
        if (w->contact[k]) act = 0.0;
        act_min = dmin(act_min, act);
        double drac = (rate > 0 && gap > 1e-3) ? rate * rate / (2 * gap) : 0.0;
        drac_max = dmax(drac_max, drac);
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
    out[OUT_DRAC_MAX] = drac_max;
    out[OUT_PET] = pet(sc, tr, n, w->in_e, w->in_o, w->ie, w->io);
    out[OUT_PEAK_DECEL] = dmax(0.0, -peak) + 0.0; /* + 0.0: never -0.0, as in the Python metric */
    out[OUT_MAX_JERK] = jerk_max;
    out[OUT_COMFORT] = (double)comfortable / n;
    out[OUT_NEAR_MISS] = !any_contact && sc->near_lo <= min_ttc && min_ttc <= sc->near_hi;
    out[OUT_IMPACT_SPEED] = impact;
}

int vei_batch_run(const VeiBatchScene *sc, const VeiBatchVariant *v, int n_variants, double *out, double *traj) {
    const int n = sc->n_steps + 1;
    double *buf = (double *)malloc(sizeof(double) * (size_t)n * (NTRAJ + 3));
    int *ibuf = (int *)malloc(sizeof(int) * (size_t)n * 5);
    if (buf == NULL || ibuf == NULL) {
        free(buf), free(ibuf);
        return -1;
    }
    Scratch w = {buf + NTRAJ * n, buf + (NTRAJ + 1) * n, buf + (NTRAJ + 2) * n,
                 ibuf, ibuf + n, ibuf + 2 * n, ibuf + 3 * n, ibuf + 4 * n};
    for (int i = 0; i < n_variants; i++) {
        double *tr[NTRAJ];
        for (int q = 0; q < NTRAJ; q++) tr[q] = traj ? traj + ((size_t)i * NTRAJ + q) * n : buf + (size_t)q * n;
        simulate(sc, &v[i], tr);
        score(sc, tr, &w, out + (size_t)i * VEI_BATCH_OUTPUTS);
    }
    free(buf);
    free(ibuf);
    return 0;
}
