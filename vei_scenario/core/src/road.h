/* One OpenDRIVE road's geometry, evaluated per step: reference line, lane borders, lane-keeping poses
 * and the projection of a world point. Loaded once from the arrays the Python reader builds
 * (vei_scenario/roads/road_model.py); no parsing and no allocation after vr_road_init. */
#ifndef VEI_ROAD_H
#define VEI_ROAD_H

enum { VR_LINE = 0, VR_ARC = 1, VR_SPIRAL = 2, VR_POLY3 = 3, VR_PARAMPOLY3 = 4 };

/* columns of a geometry row */
enum {
    VR_G_S, VR_G_X, VR_G_Y, VR_G_HDG, VR_G_LEN, VR_G_KIND,
    VR_G_P0, /* arc: curvature; spiral: curvStart, curvEnd; poly3: a b c d; paramPoly3: aU..dU aV..dV */
    VR_G_TAB = VR_G_P0 + 8, /* first row of its (arc length, parameter) table, -1 without */
    VR_G_NTAB,
    VR_G_COLS
};

/* columns of a lane row: section index, lane id, driving (1/0), first width record, count, successor
 * and predecessor lane ids (NAN: none) */
enum { VR_L_SEC, VR_L_ID, VR_L_DRIVING, VR_L_W0, VR_L_NW, VR_L_SUCC, VR_L_PRED, VR_L_COLS };

typedef struct {
    int n_geom;
    const double *geom;    /* n_geom x VR_G_COLS, sorted by s */
    const double *tab_s;   /* tables of poly3 / paramPoly3: arc length ... */
    const double *tab_q;   /* ... against the curve parameter */
    int n_off;
    const double *off;     /* lane offset records (s, a, b, c, d), sorted */
    int n_sup;
    const double *sup;     /* superelevation records */
    int n_sec;
    const double *sec_s;   /* start s of each lane section, sorted */
    const int *sec_lane0;  /* first lane row of each section, and n_sec + 1 entries */
    const double *lanes;   /* lane rows (VR_L_COLS), in the file's order within a section */
    const double *widths;  /* width records (sOffset, a, b, c, d) */
    double length;
    int varying;           /* a lane offset or width that is not constant */
    /* the projection's samples of the reference line (every 0.5 m, at most 4 000 001), made by
     * vr_road_init; NULL before */
    int n_samp;
    double *samp_s, *samp_x, *samp_y;
} vr_road;

/* cos and sin of `a`, the last few angles remembered (the same bits as cos(a) and sin(a)) */
void vr_cos_sin(double a, double *c, double *s);

/* Gauss-Legendre nodes and weights (24) for spirals: given once by the module */
void vr_set_quadrature(const double *x, const double *w);

int vr_road_init(vr_road *r); /* the projection's samples (once): 0, or -1 when out of memory */
void vr_road_free(vr_road *r);

void vr_geometry_pose(const vr_road *r, int k, double ds, double *out3);
void vr_ref_pose(const vr_road *r, double s, double *out3);
double vr_lane_offset(const vr_road *r, double s);
double vr_roll(const vr_road *r, double s);
int vr_section_index(const vr_road *r, double s);
int vr_lane_row(const vr_road *r, int sec, int lane_id);   /* -1 when the section has no such lane */
double vr_lane_width(const vr_road *r, int row, double ds);
int vr_lane_borders(const vr_road *r, double s, int lane_id, double *inner, double *outer); /* -1: no lane */
int vr_lane_center_t(const vr_road *r, double s, int lane_id, double *t);
double vr_curvature(const vr_road *r, double s);
double vr_lane_heading(const vr_road *r, double s, double t);
void vr_world(const vr_road *r, double s, double t, double *out3);
int vr_lane_at(const vr_road *r, double s, double t, int *lane_id); /* 1 found, 0 off the road */
int vr_lane_drift(const vr_road *r, double s, int lane_id, double *drift);
/* Where a road user keeping lane `lane_id` at `offset` from its centre is at s: x, y, the heading
 * of its lane there (turned where the lane centre runs sideways) and its t. -1: no such lane. */
int vr_lane_pose(const vr_road *r, double s, int lane_id, double offset, double *out4);
/* The factor from distance along a lane (at `offset` from its centre) to reference-line arc length. */
int vr_lane_stretch(const vr_road *r, double s, int lane_id, double offset, double *stretch);
/* The lane a road user in `lane_id` at s0 is in at s1 (same_road: s0 is on this road; else it has
 * just entered it at s1): through the lane links of the sections passed, to the nearest lane on its
 * side where its lane ends, and over to the nearest driving lane where its lane narrows to nothing. */
int vr_lane_on(const vr_road *r, double s0, double s1, int lane_id, int same_road);
/* nearest point of the reference line: s, t, along, distance to it; and the lane there */
int vr_locate(vr_road *r, double x, double y, double *s, double *t, double *along, double *dist,
              int *found, int *lane_id); /* -1 when out of memory */

#endif
