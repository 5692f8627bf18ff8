/* One OpenDRIVE road's geometry in C: what every lane-keeping entity asks of its road at every step.
 * The formulas are the OpenDRIVE 1.8 ones (section 9: line, arc, Euler spiral by Gauss-Legendre
 * quadrature, poly3 and paramPoly3 through an arc-length table; section 11: lane offsets, lane widths
 * as cubic records; superelevation narrowing the road seen from above by cos(roll)). */
#include "road.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static double GL_X[24], GL_W[24];

void vr_set_quadrature(const double *x, const double *w)
{
    for (int i = 0; i < 24; i++) {
        GL_X[i] = x[i];
        GL_W[i] = w[i];
    }
}

/* index of the last key <= v (rows of `stride` doubles, key in column 0), -1 when v is before all */
static int last_at_or_before(const double *rows, int n, int stride, double v)
{
    int lo = 0, hi = n; /* bisect_right */
    while (lo < hi) {
        int mid = (lo + hi) / 2;
        if (v < rows[(long)mid * stride]) hi = mid;
        else lo = mid + 1;
    }
    return lo - 1;
}


/* p * u^3 as Python's p * u ** 3 gives it (pow), without pow where p is 0 (constant widths and
 * straight offsets: p * u has the same sign and value, for any u whose cube is finite) */
static double cubic_term(double p, double u)
{
    return (p == 0.0 && fabs(u) < 1e100) ? p * u : p * pow(u, 3.0);
}

/* a + b u + c u^2 + d u^3 of the coefficients c4 = (a, b, c, d), summed as the Python reader sums it */
static double cubic(const double *c4, double u) { return c4[0] + c4[1] * u + c4[2] * u * u + cubic_term(c4[3], u); }

/* cos and sin of an angle, the last few remembered: on a straight road every pose asks for its
 * geometry's heading, and every box of a road user driving straight for its yaw (the same libm calls
 * give the same bits; the core's per-step geometry runs under the GIL) */
static double memo_angle[4] = {NAN, NAN, NAN, NAN}, memo_cos[4], memo_sin[4];
static int memo_next;

void vr_cos_sin(double a, double *c, double *s)
{
    for (int i = 0; i < 4; i++)
        if (memcmp(&memo_angle[i], &a, sizeof a) == 0) {
            *c = memo_cos[i], *s = memo_sin[i];
            return;
        }
    *c = cos(a), *s = sin(a);
    memo_angle[memo_next] = a, memo_cos[memo_next] = *c, memo_sin[memo_next] = *s;
    memo_next = (memo_next + 1) & 3;
}

static double cubic_at(const double *polys, int n, double s)
{
    if (n == 0) return 0.0;
    int k = last_at_or_before(polys, n, 5, s);
    if (k < 0) return 0.0;
    const double *p = polys + 5 * k;
    return cubic(p + 1, s - p[0]);
}

/* numpy.interp on a sorted table: clamped at both ends */
static double interp(double x, const double *xp, const double *fp, int n)
{
    if (x <= xp[0]) return fp[0];
    if (x >= xp[n - 1]) return fp[n - 1];
    int lo = 0, hi = n;
    while (lo < hi) {
        int mid = (lo + hi) / 2;
        if (x < xp[mid]) hi = mid;
        else lo = mid + 1;
    }
    int j = lo - 1;
    double slope = (fp[j + 1] - fp[j]) / (xp[j + 1] - xp[j]);
    return slope * (x - xp[j]) + fp[j];
}

void vr_geometry_pose(const vr_road *r, int k, double ds, double *out)
{
    const double *g = r->geom + (long)k * VR_G_COLS;
    const double *p = g + VR_G_P0;
    double x0 = g[VR_G_X], y0 = g[VR_G_Y], hdg = g[VR_G_HDG];
    double c, s_;
    vr_cos_sin(hdg, &c, &s_);
    int kind = (int)g[VR_G_KIND];
    if (kind == VR_LINE || (kind == VR_ARC && fabs(p[0]) < 1e-12)) {
        out[0] = x0 + ds * c;
        out[1] = y0 + ds * s_;
        out[2] = hdg;
        return;
    }
    if (kind == VR_ARC) {
        double kk = p[0], h = hdg + kk * ds;
        out[0] = x0 + (sin(h) - s_) / kk;
        out[1] = y0 - (cos(h) - c) / kk;
        out[2] = h;
        return;
    }
    if (kind == VR_SPIRAL) {
        double k0 = p[0], k1 = p[1], len = g[VR_G_LEN];
        double rate = len > 0 ? (k1 - k0) / len : 0.0;
        double sx = 0.0, sy = 0.0;
        for (int i = 0; i < 24; i++) {
            double u = 0.5 * ds * (GL_X[i] + 1.0);
            double h = hdg + k0 * u + 0.5 * rate * u * u;
            double w = 0.5 * ds * GL_W[i];
            sx += w * cos(h);
            sy += w * sin(h);
        }
        out[0] = x0 + sx;
        out[1] = y0 + sy;
        out[2] = hdg + k0 * ds + 0.5 * rate * ds * ds;
        return;
    }
    int t0 = (int)g[VR_G_TAB], nt = (int)g[VR_G_NTAB];
    double q = interp(ds, r->tab_s + t0, r->tab_q + t0, nt);
    double u, v, du, dv;
    if (kind == VR_POLY3) {
        u = q;
        v = cubic(p, q);
        du = 1.0;
        dv = p[1] + 2 * p[2] * q + 3 * p[3] * q * q;
    } else {
        u = cubic(p, q);
        v = cubic(p + 4, q);
        du = p[1] + 2 * p[2] * q + 3 * p[3] * q * q;
        dv = p[5] + 2 * p[6] * q + 3 * p[7] * q * q;
    }
    out[0] = x0 + u * c - v * s_;
    out[1] = y0 + u * s_ + v * c;
    out[2] = hdg + atan2(dv, du);
}

void vr_ref_pose(const vr_road *r, double s, double *out)
{
    s = fmin(fmax(s, 0.0), r->length);
    int k = last_at_or_before(r->geom, r->n_geom, VR_G_COLS, s);
    if (k < 0) k = 0;
    const double *g = r->geom + (long)k * VR_G_COLS;
    vr_geometry_pose(r, k, fmin(s - g[VR_G_S], g[VR_G_LEN]), out);
}

double vr_lane_offset(const vr_road *r, double s) { return cubic_at(r->off, r->n_off, s); }

double vr_roll(const vr_road *r, double s) { return cubic_at(r->sup, r->n_sup, s); }

int vr_section_index(const vr_road *r, double s)
{
    int k = last_at_or_before(r->sec_s, r->n_sec, 1, s + 1e-9);
    return k < 0 ? 0 : k;
}

int vr_lane_row(const vr_road *r, int sec, int lane_id)
{
    for (int i = r->sec_lane0[sec]; i < r->sec_lane0[sec + 1]; i++)
        if ((int)r->lanes[(long)i * VR_L_COLS + VR_L_ID] == lane_id) return i;
    return -1;
}

double vr_lane_width(const vr_road *r, int row, double ds)
{
    const double *lane = r->lanes + (long)row * VR_L_COLS;
    int n = (int)lane[VR_L_NW];
    if (n == 0) return 0.0;
    const double *w = r->widths + 5 * (long)lane[VR_L_W0];
    int k = last_at_or_before(w, n, 5, ds);
    if (k < 0) k = 0;
    w += 5 * k;
    return cubic(w + 1, ds - w[0]);
}

int vr_lane_borders(const vr_road *r, double s, int lane_id, double *inner, double *outer)
{
    int sec = vr_section_index(r, s);
    int row = vr_lane_row(r, sec, lane_id);
    if (row < 0) return -1;
    double ds = s - r->sec_s[sec];
    int sign = lane_id > 0 ? 1 : -1, n = abs(lane_id);
    double t = vr_lane_offset(r, s);
    /* the widths of the lanes between the centre and this one, nearest the centre first (ids that
     * are missing add nothing; found by the lanes there are, however large the ids) */
    for (int last = 0;;) {
        int next_row = -1, next_abs = n;
        for (int i = r->sec_lane0[sec]; i < r->sec_lane0[sec + 1]; i++) {
            int id = (int)r->lanes[(long)i * VR_L_COLS + VR_L_ID], a = abs(id);
            if ((id > 0) == (lane_id > 0) && a > last && a < next_abs) next_abs = a, next_row = i;
        }
        if (next_row < 0) break;
        t += sign * vr_lane_width(r, next_row, ds);
        last = next_abs;
    }
    *inner = t;
    *outer = t + sign * vr_lane_width(r, row, ds);
    return 0;
}

int vr_lane_center_t(const vr_road *r, double s, int lane_id, double *t)
{
    double inner, outer;
    if (vr_lane_borders(r, s, lane_id, &inner, &outer) < 0) return -1;
    *t = 0.5 * (inner + outer);
    return 0;
}

double vr_curvature(const vr_road *r, double s)
{
    const double eps = 0.05;
    double a = fmax(s - eps, 0.0), b = fmin(s + eps, r->length);
    if (b <= a) return 0.0;
    double pa[3], pb[3];
    vr_ref_pose(r, b, pb);
    vr_ref_pose(r, a, pa);
    double dh = pb[2] - pa[2];
    return atan2(sin(dh), cos(dh)) / (b - a);
}

double vr_lane_heading(const vr_road *r, double s, double t)
{
    const double eps = 0.05;
    double pose[3];
    vr_ref_pose(r, s, pose);
    double h = pose[2];
    if (r->n_sup == 0) return h;
    double a = fmax(s - eps, 0.0), b = fmin(s + eps, r->length);
    if (b <= a) return h;
    double dt_ds = t * (cos(vr_roll(r, b)) - cos(vr_roll(r, a))) / (b - a);
    double along = 1.0 - t * cos(vr_roll(r, s)) * vr_curvature(r, s);
    return h + atan2(dt_ds, along);
}

void vr_world(const vr_road *r, double s, double t, double *out)
{
    double pose[3];
    vr_ref_pose(r, s, pose);
    if (r->n_sup) t *= cos(vr_roll(r, s));
    double c, s_;
    vr_cos_sin(pose[2], &c, &s_);
    out[0] = pose[0] - t * s_;
    out[1] = pose[1] + t * c;
    out[2] = pose[2];
}

int vr_lane_at(const vr_road *r, double s, double t, int *lane_id)
{
    int sec = vr_section_index(r, s);
    for (int i = r->sec_lane0[sec]; i < r->sec_lane0[sec + 1]; i++) {
        int id = (int)r->lanes[(long)i * VR_L_COLS + VR_L_ID];
        double inner, outer;
        vr_lane_borders(r, s, id, &inner, &outer);
        if (fmin(inner, outer) - 1e-9 <= t && t <= fmax(inner, outer) + 1e-9 && inner != outer) {
            *lane_id = id;
            return 1;
        }
    }
    return 0;
}

int vr_lane_drift(const vr_road *r, double s, int lane_id, double *drift)
{
    const double eps = 0.05;
    *drift = 0.0;
    if (!r->varying) return 0;
    int k = vr_section_index(r, s);
    /* (within the section: a micrometre short of the next one, which vr_section_index rounds 1e-9 into, and
     * where the lane may have another id or none) */
    double lo = r->sec_s[k], hi = k + 1 < r->n_sec ? r->sec_s[k + 1] - 1e-6 : r->length;
    double a = fmax(s - eps, lo), b = fmin(s + eps, hi);
    if (b <= a || vr_lane_row(r, k, lane_id) < 0) return 0;
    double tb, ta;
    if (vr_lane_center_t(r, b, lane_id, &tb) < 0 || vr_lane_center_t(r, a, lane_id, &ta) < 0) return -1;
    *drift = (tb - ta) / (b - a);
    return 0;
}

int vr_lane_pose(const vr_road *r, double s, int lane_id, double offset, double *out)
{
    double centre, drift, w[3];
    if (vr_lane_center_t(r, s, lane_id, &centre) < 0) return -1;
    double t = centre + offset;
    vr_world(r, s, t, w);
    double base = vr_lane_heading(r, s, t);
    if (vr_lane_drift(r, s, lane_id, &drift) < 0) return -1;
    if (drift != 0.0) base += atan2(drift, fmax(1.0 - t * vr_curvature(r, s), 0.05));
    out[0] = w[0];
    out[1] = w[1];
    out[2] = base;
    out[3] = t;
    return 0;
}

int vr_lane_stretch(const vr_road *r, double s, int lane_id, double offset, double *stretch)
{
    double centre;
    if (vr_lane_center_t(r, s, lane_id, &centre) < 0) return -1;
    *stretch = fmax(1.0 - (centre + offset) * vr_curvature(r, s), 0.05);
    return 0;
}

static int lane_id_of(const vr_road *r, int row) { return (int)r->lanes[(long)row * VR_L_COLS + VR_L_ID]; }

int vr_lane_on(const vr_road *r, double s0, double s1, int lane, int same_road)
{
    if (same_road) {
        int k0 = vr_section_index(r, s0), k1 = vr_section_index(r, s1), step = k1 > k0 ? 1 : -1;
        for (int k = k0; k != k1; k += step) {
            int row = vr_lane_row(r, k, lane);
            if (row < 0) continue;
            double link = r->lanes[(long)row * VR_L_COLS + (step > 0 ? VR_L_SUCC : VR_L_PRED)];
            if (!isnan(link) && vr_lane_row(r, k + step, (int)link) >= 0) lane = (int)link;
        }
    }
    int sec = vr_section_index(r, s1), first = r->sec_lane0[sec], end = r->sec_lane0[sec + 1];
    double ds = s1 - r->sec_s[sec];
    if (vr_lane_row(r, sec, lane) < 0) { /* its lane ends: the nearest on the same side, else any */
        int best = lane, found = 0, best_d = 0;
        for (int pass = 0; pass < 2 && !found; pass++)
            for (int i = first; i < end; i++) {
                int id = lane_id_of(r, i), d = abs(id - lane);
                if (pass == 0 && (id > 0) != (lane > 0)) continue;
                if (!found || d < best_d) best = id, best_d = d, found = 1;
            }
        lane = best;
    }
    int row = vr_lane_row(r, sec, lane);
    if (row >= 0 && r->lanes[(long)row * VR_L_COLS + VR_L_DRIVING] != 0 && vr_lane_width(r, row, ds) < 1e-6) {
        double here, t;
        vr_lane_center_t(r, s1, lane, &here);
        int best = lane, found = 0;
        double best_d = 0.0;
        for (int i = first; i < end; i++) {
            int id = lane_id_of(r, i);
            if ((id > 0) != (lane > 0) || r->lanes[(long)i * VR_L_COLS + VR_L_DRIVING] == 0 ||
                vr_lane_width(r, i, ds) < 1e-6)
                continue;
            vr_lane_center_t(r, s1, id, &t);
            if (!found || fabs(t - here) < best_d) best = id, best_d = fabs(t - here), found = 1;
        }
        lane = best;
    }
    return lane;
}

int vr_road_init(vr_road *r)
{
    if (r->samp_s) return 0;
    /* every 0.5 m; beyond 2 000 km of road (no real one) at most 4 000 001 samples, further apart */
    double count = ceil(r->length / 0.5) + 1;
    int n = count > 4000001.0 ? 4000001 : (int)count;
    if (n < 2) n = 2;
    r->n_samp = n;
    r->samp_s = malloc(sizeof(double) * 3 * (size_t)n);
    if (!r->samp_s) return -1;
    r->samp_x = r->samp_s + n;
    r->samp_y = r->samp_s + 2 * n;
    double step = r->length / (n - 1);
    for (int i = 0; i < n; i++) {
        double s = i < n - 1 ? i * step : r->length; /* numpy.linspace */
        double pose[3];
        vr_ref_pose(r, s, pose);
        r->samp_s[i] = s;
        r->samp_x[i] = pose[0];
        r->samp_y[i] = pose[1];
    }
    return 0;
}

void vr_road_free(vr_road *r)
{
    free(r->samp_s);
    r->samp_s = r->samp_x = r->samp_y = NULL;
}

/* arc length of the point of the reference line nearest (x, y) near s0 (ternary search) */
static double refine(const vr_road *r, double x, double y, double s0, double step)
{
    double lo = fmax(0.0, s0 - step), hi = fmin(r->length, s0 + step);
    for (int i = 0; i < 40; i++) {
        double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3, p1[3], p2[3];
        vr_ref_pose(r, m1, p1);
        vr_ref_pose(r, m2, p2);
        double d1 = (p1[0] - x) * (p1[0] - x) + (p1[1] - y) * (p1[1] - y);
        double d2 = (p2[0] - x) * (p2[0] - x) + (p2[1] - y) * (p2[1] - y);
        if (d1 <= d2) hi = m2;
        else lo = m1;
    }
    return 0.5 * (lo + hi);
}

int vr_locate(vr_road *r, double x, double y, double *s_out, double *t_out, double *along_out,
              double *dist_out, int *found, int *lane_id)
{
    if (vr_road_init(r) < 0) return -1; /* the samples, made on the first projection onto this road */
    int best = 0;
    double best_d2 = INFINITY;
    for (int i = 0; i < r->n_samp; i++) {
        double dx = r->samp_x[i] - x, dy = r->samp_y[i] - y, d2 = dx * dx + dy * dy;
        if (d2 < best_d2) {
            best_d2 = d2;
            best = i;
        }
    }
    double s = refine(r, x, y, r->samp_s[best], r->samp_s[1] - r->samp_s[0]);
    double p[3];
    vr_ref_pose(r, s, p);
    double t = -(x - p[0]) * sin(p[2]) + (y - p[1]) * cos(p[2]);
    if (r->n_sup) t /= cos(vr_roll(r, s));
    double along = (x - p[0]) * cos(p[2]) + (y - p[1]) * sin(p[2]);
    *s_out = s;
    *t_out = t;
    *along_out = along;
    *dist_out = hypot(x - p[0], y - p[1]);
    *found = fabs(along) < 0.5 ? vr_lane_at(r, s, t, lane_id) : 0;
    return 0;
}
