/* vei_scenario.core._core: the compiled core as a Python extension (built with the package, see
 * setup.py). Each call is one step's question of one road (METH_FASTCALL: no argument tuples), so a
 * lane-keeping entity costs microseconds per step instead of tens. The numerics live in road.c; this
 * file only converts arguments and owns the memory. */
#define PY_SSIZE_T_CLEAN
#include <Python.h>
#include <math.h>
#include <string.h>

#include "road.h"
#include "vei_models.h"

typedef struct {
    PyObject_HEAD
    vr_road r;
    void *blocks[9];
} RoadObject;

static void Road_dealloc(RoadObject *self)
{
    vr_road_free(&self->r);
    for (int i = 0; i < 9; i++) PyMem_Free(self->blocks[i]);
    Py_TYPE(self)->tp_free((PyObject *)self);
}

/* a private copy of a bytes object's contents (its length in items of `size` bytes in *n) */
static void *copy_bytes(RoadObject *self, int slot, PyObject *b, size_t size, int *n)
{
    if (!PyBytes_Check(b)) {
        PyErr_SetString(PyExc_TypeError, "road arrays are passed as bytes");
        return NULL;
    }
    Py_ssize_t len = PyBytes_GET_SIZE(b);
    void *p = PyMem_Malloc(len > 0 ? (size_t)len : 1);
    if (!p) {
        PyErr_NoMemory();
        return NULL;
    }
    memcpy(p, PyBytes_AS_STRING(b), (size_t)len);
    self->blocks[slot] = p;
    if (n) *n = (int)((size_t)len / size);
    return p;
}

static int Road_init(RoadObject *self, PyObject *args, PyObject *kwds)
{
    PyObject *geom, *tab_s, *tab_q, *off, *sup, *sec_s, *sec_lane0, *lanes, *widths;
    double length;
    int varying;
    if (!PyArg_ParseTuple(args, "SSSSSSSSSdp", &geom, &tab_s, &tab_q, &off, &sup, &sec_s, &sec_lane0, &lanes,
                          &widths, &length, &varying))
        return -1;
    vr_road *r = &self->r;
    int n, dummy;
    if (!(r->geom = copy_bytes(self, 0, geom, sizeof(double) * VR_G_COLS, &r->n_geom))) return -1;
    if (!(r->tab_s = copy_bytes(self, 1, tab_s, sizeof(double), &dummy))) return -1;
    if (!(r->tab_q = copy_bytes(self, 2, tab_q, sizeof(double), &dummy))) return -1;
    if (!(r->off = copy_bytes(self, 3, off, sizeof(double) * 5, &r->n_off))) return -1;
    if (!(r->sup = copy_bytes(self, 4, sup, sizeof(double) * 5, &r->n_sup))) return -1;
    if (!(r->sec_s = copy_bytes(self, 5, sec_s, sizeof(double), &r->n_sec))) return -1;
    if (!(r->sec_lane0 = copy_bytes(self, 6, sec_lane0, sizeof(int), &n))) return -1;
    if (!(r->lanes = copy_bytes(self, 7, lanes, sizeof(double) * VR_L_COLS, &dummy))) return -1;
    if (!(r->widths = copy_bytes(self, 8, widths, sizeof(double) * 5, &dummy))) return -1;
    if (r->n_geom < 1 || r->n_sec < 1 || n != r->n_sec + 1) {
        PyErr_SetString(PyExc_ValueError, "a road needs a geometry and a lane section");
        return -1;
    }
    r->length = length;
    r->varying = varying;
    return 0;
}

static int args_ok(Py_ssize_t nargs, Py_ssize_t want, const char *name)
{
    if (nargs == want) return 1;
    PyErr_Format(PyExc_TypeError, "%s takes %zd arguments (%zd given)", name, want, nargs);
    return 0;
}

/* the n arguments of a call that takes n numbers, as doubles in out; 0 with the error set otherwise */
static int args_doubles(PyObject *const *args, Py_ssize_t nargs, Py_ssize_t n, const char *name, double *out)
{
    if (!args_ok(nargs, n, name)) return 0;
    for (Py_ssize_t i = 0; i < n; i++) {
        out[i] = PyFloat_AsDouble(args[i]);
        if (out[i] == -1.0 && PyErr_Occurred()) return 0;
    }
    return 1;
}

#define ARG_D(i, v)                                 \
    double v = PyFloat_AsDouble(args[i]);           \
    if (v == -1.0 && PyErr_Occurred()) return NULL;
#define ARG_I(i, v)                             \
    long v = PyLong_AsLong(args[i]);            \
    if (v == -1 && PyErr_Occurred()) return NULL;

static PyObject *pose_tuple(const double *p) { return Py_BuildValue("(ddd)", p[0], p[1], p[2]); }

static PyObject *no_lane(long lane)
{
    PyObject *key = PyLong_FromLong(lane);
    if (key) {
        PyErr_SetObject(PyExc_KeyError, key);
        Py_DECREF(key);
    }
    return NULL;
}

static PyObject *Road_ref_pose(RoadObject *self, PyObject *const *args, Py_ssize_t nargs)
{
    if (!args_ok(nargs, 1, "ref_pose")) return NULL;
    ARG_D(0, s);
    double p[3];
    vr_ref_pose(&self->r, s, p);
    return pose_tuple(p);
}

static PyObject *Road_geometry_pose(RoadObject *self, PyObject *const *args, Py_ssize_t nargs)
{
    if (!args_ok(nargs, 2, "geometry_pose")) return NULL;
    ARG_I(0, k);
    ARG_D(1, ds);
    if (k < 0 || k >= self->r.n_geom) return PyErr_Format(PyExc_IndexError, "no geometry %ld", k);
    double p[3];
    vr_geometry_pose(&self->r, (int)k, ds, p);
    return pose_tuple(p);
}

static PyObject *Road_world(RoadObject *self, PyObject *const *args, Py_ssize_t nargs)
{
    if (!args_ok(nargs, 2, "world")) return NULL;
    ARG_D(0, s);
    ARG_D(1, t);
    double p[3];
    vr_world(&self->r, s, t, p);
    return pose_tuple(p);
}

static PyObject *Road_lane_borders(RoadObject *self, PyObject *const *args, Py_ssize_t nargs)
{
    if (!args_ok(nargs, 2, "lane_borders")) return NULL;
    ARG_D(0, s);
    ARG_I(1, lane);
    double inner, outer;
    if (vr_lane_borders(&self->r, s, (int)lane, &inner, &outer) < 0) return no_lane(lane);
    return Py_BuildValue("(dd)", inner, outer);
}

static PyObject *Road_lane_center_t(RoadObject *self, PyObject *const *args, Py_ssize_t nargs)
{
    if (!args_ok(nargs, 2, "lane_center_t")) return NULL;
    ARG_D(0, s);
    ARG_I(1, lane);
    double t;
    if (vr_lane_center_t(&self->r, s, (int)lane, &t) < 0) return no_lane(lane);
    return PyFloat_FromDouble(t);
}

static PyObject *Road_section_index(RoadObject *self, PyObject *const *args, Py_ssize_t nargs)
{
    if (!args_ok(nargs, 1, "section_index")) return NULL;
    ARG_D(0, s);
    return PyLong_FromLong(vr_section_index(&self->r, s));
}

static PyObject *Road_lane_at(RoadObject *self, PyObject *const *args, Py_ssize_t nargs)
{
    if (!args_ok(nargs, 2, "lane_at")) return NULL;
    ARG_D(0, s);
    ARG_D(1, t);
    int lane;
    if (!vr_lane_at(&self->r, s, t, &lane)) Py_RETURN_NONE;
    return PyLong_FromLong(lane);
}

static PyObject *Road_lane_pose(RoadObject *self, PyObject *const *args, Py_ssize_t nargs)
{
    if (!args_ok(nargs, 3, "lane_pose")) return NULL;
    ARG_D(0, s);
    ARG_I(1, lane);
    ARG_D(2, offset);
    double out[4];
    if (vr_lane_pose(&self->r, s, (int)lane, offset, out) < 0) return no_lane(lane);
    return Py_BuildValue("(dddd)", out[0], out[1], out[2], out[3]);
}

static PyObject *Road_lane_stretch(RoadObject *self, PyObject *const *args, Py_ssize_t nargs)
{
    if (!args_ok(nargs, 3, "lane_stretch")) return NULL;
    ARG_D(0, s);
    ARG_I(1, lane);
    ARG_D(2, offset);
    double stretch;
    if (vr_lane_stretch(&self->r, s, (int)lane, offset, &stretch) < 0) return no_lane(lane);
    return PyFloat_FromDouble(stretch);
}

static PyObject *Road_lane_on(RoadObject *self, PyObject *const *args, Py_ssize_t nargs)
{
    if (!args_ok(nargs, 4, "lane_on")) return NULL;
    ARG_D(0, s0);
    ARG_D(1, s1);
    ARG_I(2, lane);
    int same = PyObject_IsTrue(args[3]);
    if (same < 0) return NULL;
    return PyLong_FromLong(vr_lane_on(&self->r, s0, s1, (int)lane, same));
}

/* A lane-keeping step that stays on the road, in one call: the stretch, the new s, the lane there and
 * its pose; None when the step leaves the road (the caller crosses to the next road itself). */
/* A lane-keeping step of `ds` metres along the lane that stays on the road: the new s and lane and
 * the pose there (vr_lane_pose's). 1: done; 0: it would leave the road; -1: no such lane (*lane1:
 * which). Road.lane_advance and the cruise both take their steps here. */
/* motion.lane_keep's move along the road: the s ds metres on along lane (at offset) and the lane there; 0
 * where it leaves the road, -1 without the lane */
static int lane_advance_s(const vr_road *r, double s, int lane, double offset, double ds, int forward, double *s1,
                          int *lane1)
{
    double stretch;
    *lane1 = lane;
    if (vr_lane_stretch(r, s, lane, offset, &stretch) < 0) return -1;
    *s1 = s + (forward ? ds : -ds) / stretch;
    if (*s1 > r->length || *s1 < 0.0) return 0;
    *lane1 = vr_lane_on(r, s, *s1, lane, 1);
    return 1;
}

static int lane_step(const vr_road *r, double s, int lane, double offset, double ds, int forward, double *s1,
                     int *lane1, double *out4)
{
    int done = lane_advance_s(r, s, lane, offset, ds, forward, s1, lane1);
    if (done != 1) return done;
    return vr_lane_pose(r, *s1, *lane1, offset, out4) < 0 ? -1 : 1;
}

static PyObject *Road_lane_advance(RoadObject *self, PyObject *const *args, Py_ssize_t nargs)
{
    if (!args_ok(nargs, 5, "lane_advance")) return NULL;
    ARG_D(0, s);
    ARG_I(1, lane);
    ARG_D(2, offset);
    ARG_D(3, ds);
    int forward = PyObject_IsTrue(args[4]);
    if (forward < 0) return NULL;
    double s1, out[4];
    int lane1, done = lane_step(&self->r, s, (int)lane, offset, ds, forward, &s1, &lane1, out);
    if (done < 0) return no_lane(lane1);
    if (done == 0) Py_RETURN_NONE;
    return Py_BuildValue("(diddd)", s1, lane1, out[0], out[1], out[2]);
}

static PyObject *Road_locate(RoadObject *self, PyObject *const *args, Py_ssize_t nargs)
{
    if (!args_ok(nargs, 2, "locate")) return NULL;
    ARG_D(0, x);
    ARG_D(1, y);
    double s, t, along, dist;
    int found, lane;
    if (vr_locate(&self->r, x, y, &s, &t, &along, &dist, &found, &lane) < 0) return PyErr_NoMemory();
    if (found) return Py_BuildValue("(ddddi)", s, t, along, dist, lane);
    return Py_BuildValue("(ddddO)", s, t, along, dist, Py_None);
}

#define M(name, doc) {#name, (PyCFunction)(void (*)(void))Road_##name, METH_FASTCALL, doc}
static PyMethodDef Road_methods[] = {
    M(ref_pose, "ref_pose(s) -> (x, y, heading) of the reference line"),
    M(geometry_pose, "geometry_pose(k, ds) -> pose ds metres into geometry k"),
    M(world, "world(s, t) -> (x, y, reference heading)"),
    M(lane_borders, "lane_borders(s, lane) -> (inner t, outer t); KeyError without the lane"),
    M(lane_center_t, "lane_center_t(s, lane) -> t of the lane's centre; KeyError without the lane"),
    M(section_index, "section_index(s) -> lane section at s"),
    M(lane_at, "lane_at(s, t) -> lane id, or None off the road"),
    M(lane_pose, "lane_pose(s, lane, offset) -> (x, y, lane heading, t) of a road user keeping the lane"),
    M(lane_stretch, "lane_stretch(s, lane, offset) -> reference-line metres per metre along the lane"),
    M(lane_on, "lane_on(s0, s1, lane, same_road) -> the lane id at s1 (links, lane ends, merges)"),
    M(lane_advance, "lane_advance(s, lane, offset, ds, forward) -> (s, lane, x, y, lane heading), None off the road"),
    M(locate, "locate(x, y) -> (s, t, along, distance, lane or None) of the nearest reference point"),
    {NULL, NULL, 0, NULL},
};

static PyTypeObject RoadType = {
    PyVarObject_HEAD_INIT(NULL, 0).tp_name = "vei_scenario.core._core.Road",
    .tp_basicsize = sizeof(RoadObject),
    .tp_dealloc = (destructor)Road_dealloc,
    .tp_flags = Py_TPFLAGS_DEFAULT,
    .tp_doc = "One OpenDRIVE road's geometry (see vei_scenario.roads.road_model.Road).",
    .tp_methods = Road_methods,
    .tp_init = (initproc)Road_init,
    .tp_new = PyType_GenericNew,
};

/* ---------------------------------------------------------------------------------------------- */
/* Polyline: a trajectory shape (vei_models.c), the one the interpreter, the kernel and the FMUs use */

typedef struct {
    PyObject_HEAD
    VeiPolyline p;
    double *mem; /* x, y, h, s and t in one block */
} PolylineObject;

static void Polyline_dealloc(PolylineObject *self)
{
    PyMem_Free(self->mem);
    Py_TYPE(self)->tp_free((PyObject *)self);
}

static int Polyline_init(PolylineObject *self, PyObject *args, PyObject *kwds)
{
    PyObject *xb, *yb, *hb, *tb;
    if (!PyArg_ParseTuple(args, "SSSS", &xb, &yb, &hb, &tb)) return -1;
    Py_ssize_t n = PyBytes_GET_SIZE(xb) / (Py_ssize_t)sizeof(double);
    int timed = PyBytes_GET_SIZE(tb) > 0;
    if (n < 1 || n > 100000000 || PyBytes_GET_SIZE(yb) != PyBytes_GET_SIZE(xb) ||
        PyBytes_GET_SIZE(hb) != PyBytes_GET_SIZE(xb) || (timed && PyBytes_GET_SIZE(tb) != PyBytes_GET_SIZE(xb))) {
        PyErr_SetString(PyExc_ValueError, "a polyline needs as many x, y, h (and t) as vertices, at least one");
        return -1;
    }
    if (self->mem) return 0; /* (initialised once) */
    double *mem = PyMem_Malloc(sizeof(double) * (size_t)n * 5);
    if (!mem) {
        PyErr_NoMemory();
        return -1;
    }
    size_t bytes = sizeof(double) * (size_t)n;
    memcpy(mem, PyBytes_AS_STRING(xb), bytes);
    memcpy(mem + n, PyBytes_AS_STRING(yb), bytes);
    memcpy(mem + 2 * n, PyBytes_AS_STRING(hb), bytes);
    if (timed) memcpy(mem + 4 * n, PyBytes_AS_STRING(tb), bytes);
    self->mem = mem;
    self->p.x = mem;
    self->p.y = mem + n;
    self->p.h = mem + 2 * n;
    self->p.s = mem + 3 * n;
    self->p.t = timed ? mem + 4 * n : NULL;
    self->p.n = (int)n;
    self->p.exit_speed = Py_NAN;
    vei_polyline_init(&self->p);
    return 0;
}

static PyObject *xyh(double x, double y, double h) { return Py_BuildValue("(ddd)", x, y, h); }

static PyObject *Polyline_at_s(PolylineObject *self, PyObject *const *args, Py_ssize_t nargs)
{
    if (!args_ok(nargs, 1, "at_s")) return NULL;
    ARG_D(0, s);
    double x, y, h;
    vei_polyline_at_s(&self->p, s, &x, &y, &h);
    return xyh(x, y, h);
}

static int timed_ok(PolylineObject *self)
{
    if (self->p.t != NULL) return 1;
    PyErr_SetString(PyExc_ValueError, "the polyline has no vertex times");
    return 0;
}

/* the pose at trajectory time t (a single vertex: it stays there, whatever the time) */
static void at_time(const VeiPolyline *p, double t, double *x, double *y, double *h)
{
    if (p->n == 1)
        *x = p->x[0], *y = p->y[0], *h = p->h[0];
    else
        vei_polyline_at_time(p, t, x, y, h);
}

static PyObject *Polyline_at_time(PolylineObject *self, PyObject *const *args, Py_ssize_t nargs)
{
    if (!args_ok(nargs, 1, "at_time") || !timed_ok(self)) return NULL;
    ARG_D(0, t);
    double x, y, h;
    at_time(&self->p, t, &x, &y, &h);
    return xyh(x, y, h);
}

/* the arc length at trajectory time t (a single vertex: 0, wherever the time) */
static double s_at_time(const VeiPolyline *p, double t) { return p->n == 1 ? 0.0 : vei_polyline_s_at_time(p, t); }

/* A road user at arc length s moved ds metres along its path (against it when reversing: it then faces
 * against the path), never past its end: out x, y, yaw, s. motion.advance_along (Polyline.advance), the
 * timed follow step and the core's path step all take it here. */
static void path_advance(const VeiPolyline *p, double s, double ds, int reverse, double *out)
{
    double s1 = s + (reverse ? -ds : ds), length = p->s[p->n - 1], h;
    if (s1 > length) s1 = length;
    vei_polyline_at_s(p, s1, &out[0], &out[1], &h);
    out[2] = reverse ? atan2(-sin(h), -cos(h)) : h;
    out[3] = s1;
}

/* A road user at arc length s and speed v0 on a timed path after a step of dt that ends at trajectory
 * time tt (engine._motion's timed branch and the core's quiet steps both take it here): in position
 * mode where the trajectory puts it then, at the speed that covers the arc; in follow mode (esmini's)
 * tracking that point within its acceleration limits along the path, never past its end.
 * out: x, y, yaw, s, speed, acceleration. */
static void timed_step(const VeiPolyline *p, double tt, double s, double v0, int follow, double max_accel,
                       double max_decel, double dt, double *out)
{
    double target = s_at_time(p, tt);
    if (!follow) {
        double speed = (target - s) / dt;
        at_time(p, tt, &out[0], &out[1], &out[2]);
        out[3] = target, out[4] = speed, out[5] = (speed - v0) / dt;
        return;
    }
    double want = ((target - s) / dt - v0) / dt; /* (Python's max(-d, min(a, x))) */
    double a = want < max_accel ? want : max_accel;
    if (!(a > -max_decel)) a = -max_decel;
    double v = v0 + a * dt;
    if (!(v > 0.0)) v = 0.0;
    path_advance(p, s, 0.5 * (v0 + v) * dt, 0, out);
    out[4] = v, out[5] = a;
}

/* timed_step(tt, s, v0, follow, max_accel, max_decel, dt) -> (x, y, yaw, s, speed, accel): the
 * interpreter's step on a timed path */
static PyObject *Polyline_timed_step(PolylineObject *self, PyObject *const *args, Py_ssize_t nargs)
{
    if (!args_ok(nargs, 7, "timed_step") || !timed_ok(self)) return NULL;
    ARG_D(0, tt);
    ARG_D(1, s);
    ARG_D(2, v0);
    int follow = PyObject_IsTrue(args[3]);
    if (follow < 0) return NULL;
    ARG_D(4, max_accel);
    ARG_D(5, max_decel);
    ARG_D(6, dt);
    double out[6];
    timed_step(&self->p, tt, s, v0, follow, max_accel, max_decel, dt, out);
    return Py_BuildValue("(dddddd)", out[0], out[1], out[2], out[3], out[4], out[5]);
}

static PyObject *Polyline_s_at_time(PolylineObject *self, PyObject *const *args, Py_ssize_t nargs)
{
    if (!args_ok(nargs, 1, "s_at_time") || !timed_ok(self)) return NULL;
    ARG_D(0, t);
    return PyFloat_FromDouble(s_at_time(&self->p, t));
}

static PyObject *Polyline_project(PolylineObject *self, PyObject *const *args, Py_ssize_t nargs)
{
    if (!args_ok(nargs, 2, "project")) return NULL;
    ARG_D(0, x);
    ARG_D(1, y);
    return PyFloat_FromDouble(vei_polyline_project(&self->p, x, y));
}

/* drive(fs, a_cmd, max_accel, max_decel, jerk_max, dt, speed, accel) -> (fs, x, y, yaw, speed, accel):
 * vei_ego_drive along this path (the ego FMU's and the kernel's drive) */
static PyObject *Polyline_drive(PolylineObject *self, PyObject *const *args, Py_ssize_t nargs)
{
    if (!args_ok(nargs, 8, "drive")) return NULL;
    ARG_D(0, fs);
    ARG_D(1, a_cmd);
    ARG_D(2, max_accel);
    ARG_D(3, max_decel);
    ARG_D(4, jerk);
    ARG_D(5, dt);
    ARG_D(6, speed);
    ARG_D(7, accel);
    VeiVehicleLimits lim = {max_accel, max_decel, jerk};
    double x, y, yaw;
    vei_ego_drive(&self->p, NULL, &fs, a_cmd, &lim, dt, &x, &y, &yaw, &speed, &accel);
    return Py_BuildValue("(dddddd)", fs, x, y, yaw, speed, accel);
}

static PyObject *Polyline_end_speed(PolylineObject *self, PyObject *unused)
{
    if (!timed_ok(self)) return NULL;
    if (self->p.n < 2) /* a single vertex: it stays (unless an exit speed is given) */
        return PyFloat_FromDouble(isnan(self->p.exit_speed) ? 0.0 : self->p.exit_speed);
    return PyFloat_FromDouble(vei_polyline_end_speed(&self->p));
}

static PyObject *Polyline_set_exit_speed(PolylineObject *self, PyObject *const *args, Py_ssize_t nargs)
{
    if (!args_ok(nargs, 1, "set_exit_speed")) return NULL;
    ARG_D(0, v);
    self->p.exit_speed = v;
    Py_RETURN_NONE;
}

/* a Python list of n doubles (NULL with the exception set when one cannot be made) */
static PyObject *float_list(const double *v, long n)
{
    PyObject *out = PyList_New(n);
    for (long i = 0; out && i < n; i++) {
        PyObject *f = PyFloat_FromDouble(v[i]);
        if (!f) {
            Py_CLEAR(out);
            break;
        }
        PyList_SET_ITEM(out, i, f);
    }
    return out;
}

static PyObject *Polyline_arc_lengths(PolylineObject *self, PyObject *unused) { return float_list(self->p.s, self->p.n); }

/* advance(s, ds, reverse) -> (x, y, yaw, s): path_advance, for the interpreter's own steps */
static PyObject *Polyline_advance(PolylineObject *self, PyObject *const *args, Py_ssize_t nargs)
{
    if (!args_ok(nargs, 3, "advance")) return NULL;
    ARG_D(0, s);
    ARG_D(1, ds);
    int reverse = PyObject_IsTrue(args[2]);
    if (reverse < 0) return NULL;
    double out[4];
    path_advance(&self->p, s, ds, reverse, out);
    return Py_BuildValue("(dddd)", out[0], out[1], out[2], out[3]);
}

#define PM(name, doc) {#name, (PyCFunction)(void (*)(void))Polyline_##name, METH_FASTCALL, doc}
static PyMethodDef Polyline_methods[] = {
    PM(at_s, "at_s(s) -> (x, y, h) at arc length s (clamped to the path)"),
    PM(at_time, "at_time(t) -> (x, y, h) at trajectory time t; on along the last heading after the end"),
    PM(s_at_time, "s_at_time(t) -> arc length at trajectory time t (continued past the end)"),
    PM(advance, "advance(s, ds, reverse) -> (x, y, yaw, s) ds metres on along the path (against it reversing), never past its end"),
    PM(timed_step, "timed_step(tt, s, v0, follow, max_accel, max_decel, dt) -> (x, y, yaw, s, speed, accel) on a timed path"),
    PM(project, "project(x, y) -> arc length of the closest point (the first of equally close ones)"),
    PM(drive, "drive(fs, a_cmd, max_accel, max_decel, jerk_max, dt, speed, accel) -> (fs, x, y, yaw, speed, accel)"),
    PM(set_exit_speed, "set_exit_speed(v): the speed kept after the end (NaN: the last segment's)"),
    {"arc_lengths", (PyCFunction)Polyline_arc_lengths, METH_NOARGS, "arc_lengths() -> cumulative arc length"},
    {"end_speed", (PyCFunction)Polyline_end_speed, METH_NOARGS, "end_speed() -> the speed kept after the end"},
    {NULL, NULL, 0, NULL},
};

static PyTypeObject PolylineType = {
    PyVarObject_HEAD_INIT(NULL, 0).tp_name = "vei_scenario.core._core.Polyline",
    .tp_basicsize = sizeof(PolylineObject),
    .tp_dealloc = (destructor)Polyline_dealloc,
    .tp_flags = Py_TPFLAGS_DEFAULT,
    .tp_doc = "A trajectory shape: vertices with headings and optional times (vei_models.c).",
    .tp_methods = Polyline_methods,
    .tp_init = (initproc)Polyline_init,
    .tp_new = PyType_GenericNew,
};

static PyObject *set_quadrature(PyObject *mod, PyObject *args)
{
    PyObject *xb, *wb;
    if (!PyArg_ParseTuple(args, "SS", &xb, &wb)) return NULL;
    if (PyBytes_GET_SIZE(xb) != 24 * sizeof(double) || PyBytes_GET_SIZE(wb) != 24 * sizeof(double)) {
        PyErr_SetString(PyExc_ValueError, "24 Gauss-Legendre nodes and weights expected");
        return NULL;
    }
    vr_set_quadrature((const double *)PyBytes_AS_STRING(xb), (const double *)PyBytes_AS_STRING(wb));
    Py_RETURN_NONE;
}

/* ---------------------------------------------------------------------------------------------- */
/* The models of vei_models.c, one call per step (vei_scenario.models wraps them for the interpreter) */

/* n doubles from a bytes object into out; -1 with TypeError otherwise */
static int doubles_of(PyObject *b, double *out, Py_ssize_t n, const char *what)
{
    if (!PyBytes_Check(b) || PyBytes_GET_SIZE(b) != n * (Py_ssize_t)sizeof(double)) {
        PyErr_Format(PyExc_TypeError, "%s: %zd doubles as bytes expected", what, n);
        return -1;
    }
    memcpy(out, PyBytes_AS_STRING(b), (size_t)n * sizeof(double));
    return 0;
}

/* a box (x, y, yaw, length, width) from a tuple of 5 floats */
static int box_of(PyObject *t, VeiBox *b)
{
    if (!PyArg_ParseTuple(t, "ddddd", &b->x, &b->y, &b->yaw, &b->length, &b->width)) return -1;
    return 0;
}

/* sfm_step(x, y, vx, vy, waypoint, route_x, route_y, params, repulsive, ego_box or None, dt)
 *   -> (x, y, vx, vy, waypoint) */
static PyObject *sfm_step(PyObject *mod, PyObject *const *args, Py_ssize_t nargs)
{
    if (!args_ok(nargs, 11, "sfm_step")) return NULL;
    VeiSfmState st;
    ARG_D(0, x);
    ARG_D(1, y);
    ARG_D(2, vx);
    ARG_D(3, vy);
    ARG_I(4, wp);
    ARG_D(10, dt);
    st.x = x, st.y = y, st.vx = vx, st.vy = vy, st.waypoint = (int)wp;
    PyObject *rx = args[5], *ry = args[6];
    if (!PyBytes_Check(rx) || !PyBytes_Check(ry) || PyBytes_GET_SIZE(rx) != PyBytes_GET_SIZE(ry) ||
        PyBytes_GET_SIZE(rx) < (Py_ssize_t)sizeof(double)) {
        PyErr_SetString(PyExc_TypeError, "sfm_step: the route as two bytes of at least one double each");
        return NULL;
    }
    int n = (int)(PyBytes_GET_SIZE(rx) / (Py_ssize_t)sizeof(double));
    if (st.waypoint < 0 || st.waypoint >= n) return PyErr_Format(PyExc_IndexError, "no waypoint %d", st.waypoint);
    double pv[10];
    if (doubles_of(args[7], pv, 10, "sfm_step params") < 0) return NULL;
    VeiSfmParams p = {pv[0], pv[1], pv[2], pv[3], pv[4], pv[5], pv[6], pv[7], pv[8], pv[9]};
    int repulsive = PyObject_IsTrue(args[8]);
    if (repulsive < 0) return NULL;
    VeiBox ego, *egop = NULL;
    if (args[9] != Py_None) {
        if (box_of(args[9], &ego) < 0) return NULL;
        egop = &ego;
    }
    vei_sfm_step(&st, (const double *)PyBytes_AS_STRING(rx), (const double *)PyBytes_AS_STRING(ry), n, &p, repulsive,
                 egop, dt);
    return Py_BuildValue("(ddddi)", st.x, st.y, st.vx, st.vy, st.waypoint);
}

/* cap_step(brake, integral, prev_error or None, params, cruise, v, ttc, resume_ttc, dt)
 *   -> (brake, integral, prev_error or None, a_cmd, d_safe) */
static PyObject *cap_step(PyObject *mod, PyObject *const *args, Py_ssize_t nargs)
{
    if (!args_ok(nargs, 9, "cap_step")) return NULL;
    int brake = PyObject_IsTrue(args[0]);
    if (brake < 0) return NULL;
    ARG_D(1, integral);
    VeiCapState st = {brake, integral, 0.0, 0};
    if (args[2] != Py_None) {
        st.prev_error = PyFloat_AsDouble(args[2]);
        if (st.prev_error == -1.0 && PyErr_Occurred()) return NULL;
        st.has_prev = 1;
    }
    double pv[10];
    if (doubles_of(args[3], pv, 10, "cap_step params") < 0) return NULL;
    VeiCapParams p = {pv[0], pv[1], pv[2], pv[3], pv[4], pv[5], pv[6], pv[7], pv[8], pv[9]};
    ARG_D(4, cruise);
    ARG_D(5, v);
    ARG_D(6, ttc);
    ARG_D(7, resume);
    ARG_D(8, dt);
    double d_safe, a = vei_cap_step(&st, &p, cruise, v, ttc, resume, dt, &d_safe);
    if (st.has_prev)
        return Py_BuildValue("(Odddd)", st.brake ? Py_True : Py_False, st.integral, st.prev_error, a, d_safe);
    return Py_BuildValue("(OdOdd)", st.brake ? Py_True : Py_False, st.integral, Py_None, a, d_safe);
}

/* the adaptive cruise's parameters from AccParameters.packed (its field order is VeiAccParams') */
static int acc_params_of(PyObject *obj, VeiAccParams *p, const char *what)
{
    double pv[6];
    if (doubles_of(obj, pv, 6, what) < 0) return -1;
    *p = (VeiAccParams){pv[0], pv[1], pv[2], pv[3], pv[4], pv[5]};
    return 0;
}

/* acc_speed(params, v, set_speed, lead, gap, v_lead, max_accel, max_decel, dt) -> speed: the adaptive
 * cruise's step (vei_acc_speed); params: AccParameters.packed; lead false: nobody to follow */
static PyObject *acc_speed(PyObject *mod, PyObject *const *args, Py_ssize_t nargs)
{
    if (!args_ok(nargs, 9, "acc_speed")) return NULL;
    VeiAccParams p;
    if (acc_params_of(args[0], &p, "acc_speed params") < 0) return NULL;
    ARG_D(1, v);
    ARG_D(2, set_speed);
    int lead = PyObject_IsTrue(args[3]);
    if (lead < 0) return NULL;
    ARG_D(4, gap);
    ARG_D(5, v_lead);
    ARG_D(6, max_accel);
    ARG_D(7, max_decel);
    ARG_D(8, dt);
    return PyFloat_FromDouble(vei_acc_speed(&p, v, set_speed, lead, gap, v_lead, max_accel, max_decel, dt));
}

/* acc_lookahead(params, v, max_decel) -> metres ahead the adaptive cruise looks for a leader */
static PyObject *acc_lookahead(PyObject *mod, PyObject *const *args, Py_ssize_t nargs)
{
    if (!args_ok(nargs, 3, "acc_lookahead")) return NULL;
    VeiAccParams p;
    if (acc_params_of(args[0], &p, "acc_lookahead params") < 0) return NULL;
    ARG_D(1, v);
    ARG_D(2, max_decel);
    return PyFloat_FromDouble(vei_acc_lookahead(&p, v, max_decel));
}

/* bumper_gap(ds, own_length, own_center_x, other_length, other_center_x, same_way) -> m */
static PyObject *bumper_gap(PyObject *mod, PyObject *const *args, Py_ssize_t nargs)
{
    if (!args_ok(nargs, 6, "bumper_gap")) return NULL;
    ARG_D(0, ds);
    ARG_D(1, own_length);
    ARG_D(2, own_center_x);
    ARG_D(3, other_length);
    ARG_D(4, other_center_x);
    int same_way = PyObject_IsTrue(args[5]);
    if (same_way < 0) return NULL;
    return PyFloat_FromDouble(vei_bumper_gap(ds, own_length, own_center_x, other_length, other_center_x, same_way));
}

/* box_gaps(own_box, other_box) -> (along, across); close_ahead(x_gap, y_gap, other_length, closing) -> bool */
static PyObject *box_gaps(PyObject *mod, PyObject *const *args, Py_ssize_t nargs)
{
    if (!args_ok(nargs, 2, "box_gaps")) return NULL;
    VeiBox a, b;
    if (box_of(args[0], &a) < 0 || box_of(args[1], &b) < 0) return NULL;
    double along, across;
    vei_box_gaps(&a, &b, &along, &across);
    return Py_BuildValue("(dd)", along, across);
}

static PyObject *close_ahead(PyObject *mod, PyObject *const *args, Py_ssize_t nargs)
{
    if (!args_ok(nargs, 4, "close_ahead")) return NULL;
    ARG_D(0, x_gap);
    ARG_D(1, y_gap);
    ARG_D(2, other_length);
    ARG_D(3, closing);
    return PyBool_FromLong(vei_close_ahead(x_gap, y_gap, other_length, closing));
}

/* longitudinal_step(s, v, a, a_cmd, max_accel, max_decel, jerk_max, dt) -> (s, v, a) */
static PyObject *longitudinal_step(PyObject *mod, PyObject *const *args, Py_ssize_t nargs)
{
    if (!args_ok(nargs, 8, "longitudinal_step")) return NULL;
    ARG_D(0, s);
    ARG_D(1, v);
    ARG_D(2, a);
    ARG_D(3, cmd);
    ARG_D(4, max_accel);
    ARG_D(5, max_decel);
    ARG_D(6, jerk);
    ARG_D(7, dt);
    VeiLongitudinal st = {s, v, a};
    VeiVehicleLimits lim = {max_accel, max_decel, jerk};
    vei_longitudinal_step(&st, cmd, &lim, dt);
    return Py_BuildValue("(ddd)", st.s, st.v, st.a);
}

/* time_to_conflict(ego_box, ego_speed, margin, threat_box, threat_vx, threat_vy[, horizon]) -> s (inf:
 * never; with a horizon, inf also where the circles show it lies beyond the horizon, as the kernel) */
static PyObject *time_to_conflict(PyObject *mod, PyObject *const *args, Py_ssize_t nargs)
{
    if (nargs != 7 && !args_ok(nargs, 6, "time_to_conflict")) return NULL;
    VeiBox ego, threat;
    if (box_of(args[0], &ego) < 0 || box_of(args[3], &threat) < 0) return NULL;
    ARG_D(1, speed);
    ARG_D(2, margin);
    ARG_D(4, tvx);
    ARG_D(5, tvy);
    if (nargs == 6) return PyFloat_FromDouble(vei_threat_time_to_conflict(&ego, speed, margin, &threat, tvx, tvy));
    ARG_D(6, horizon);
    VeiTrigBox te = vei_trig_box(ego.x, ego.y, ego.yaw, ego.length, ego.width);
    VeiTrigBox tt = vei_trig_box(threat.x, threat.y, threat.yaw, threat.length, threat.width);
    double reach = vei_conflict_reach(ego.length, ego.width, margin, threat.length, threat.width);
    return PyFloat_FromDouble(vei_trig_time_to_conflict_within(&te, speed, margin, reach, &tt, tvx, tvy, horizon));
}

/* time_to_contact(box_a, vxa, vya, box_b, vxb, vyb) -> s (0: touching now, inf: never) */
static PyObject *time_to_contact(PyObject *mod, PyObject *const *args, Py_ssize_t nargs)
{
    if (!args_ok(nargs, 6, "time_to_contact")) return NULL;
    VeiBox a, b;
    if (box_of(args[0], &a) < 0 || box_of(args[3], &b) < 0) return NULL;
    ARG_D(1, vxa);
    ARG_D(2, vya);
    ARG_D(4, vxb);
    ARG_D(5, vyb);
    return PyFloat_FromDouble(vei_time_to_contact(&a, vxa, vya, &b, vxb, vyb));
}

/* ---------------------------------------------------------------------------------------------- */
/* Rider: the rider agent of vei_models.c (vei_rider_step) with its state, for Python's FMU model */

typedef struct {
    PyObject_HEAD
    VeiRider r;
    PyObject *track; /* the Polyline whose path it replays (kept alive) */
    double *route;   /* x then y */
    int route_n;
    VeiSfmParams p;
    double offset, t_start, v_start;
    int rides, repulsive;
} RiderObject;

static void Rider_dealloc(RiderObject *self)
{
    Py_XDECREF(self->track);
    PyMem_Free(self->route);
    Py_TYPE(self)->tp_free((PyObject *)self);
}

static int Rider_init(RiderObject *self, PyObject *args, PyObject *kwds)
{
    PyObject *track, *rx, *ry, *params;
    int rides, repulsive;
    if (!PyArg_ParseTuple(args, "O!SSSdddpp", &PolylineType, &track, &rx, &ry, &params, &self->offset, &self->t_start,
                          &self->v_start, &rides, &repulsive))
        return -1;
    if (((PolylineObject *)track)->p.t == NULL || ((PolylineObject *)track)->p.n < 2) {
        PyErr_SetString(PyExc_ValueError, "a rider replays a timed track of at least two vertices");
        return -1;
    }
    Py_ssize_t n = PyBytes_GET_SIZE(rx) / (Py_ssize_t)sizeof(double);
    if (n < 1 || PyBytes_GET_SIZE(ry) != PyBytes_GET_SIZE(rx)) {
        PyErr_SetString(PyExc_ValueError, "a rider needs a route of at least one waypoint (as many y as x)");
        return -1;
    }
    double pv[10];
    if (doubles_of(params, pv, 10, "Rider params") < 0) return -1;
    double *route = PyMem_Malloc(sizeof(double) * 2 * (size_t)n);
    if (!route) {
        PyErr_NoMemory();
        return -1;
    }
    memcpy(route, PyBytes_AS_STRING(rx), sizeof(double) * (size_t)n);
    memcpy(route + n, PyBytes_AS_STRING(ry), sizeof(double) * (size_t)n);
    PyMem_Free(self->route);
    Py_XDECREF(self->track);
    Py_INCREF(track);
    self->track = track, self->route = route, self->route_n = (int)n;
    self->p = (VeiSfmParams){pv[0], pv[1], pv[2], pv[3], pv[4], pv[5], pv[6], pv[7], pv[8], pv[9]};
    self->rides = rides, self->repulsive = repulsive;
    self->r = (VeiRider)VEI_RIDER_START;
    return 0;
}

/* step(t_next, dt, x, y, yaw, speed, accel, ego_box) -> (x, y, yaw, speed, accel, riding, waypoint, vx, vy) */
static PyObject *Rider_step(RiderObject *self, PyObject *const *args, Py_ssize_t nargs)
{
    if (!args_ok(nargs, 8, "step")) return NULL;
    if (!self->track) {
        PyErr_SetString(PyExc_ValueError, "the rider was not initialised");
        return NULL;
    }
    ARG_D(0, t_next);
    ARG_D(1, dt);
    ARG_D(2, x);
    ARG_D(3, y);
    ARG_D(4, yaw);
    ARG_D(5, speed);
    ARG_D(6, accel);
    VeiBox ego;
    if (box_of(args[7], &ego) < 0) return NULL;
    double c = cos(yaw), s = sin(yaw);
    vei_rider_step(&self->r, &((PolylineObject *)self->track)->p, self->offset, self->t_start, self->v_start,
                   self->rides, self->route, self->route + self->route_n, self->route_n, &self->p, self->repulsive, &ego,
                   cos(ego.yaw), sin(ego.yaw), t_next, dt, &x, &y, &yaw, &speed, &accel, &c, &s);
    double vx = self->r.riding ? self->r.st.vx : speed * cos(yaw), vy = self->r.riding ? self->r.st.vy : speed * sin(yaw);
    return Py_BuildValue("(dddddOidd)", x, y, yaw, speed, accel, self->r.riding ? Py_True : Py_False,
                         self->r.st.waypoint, vx, vy);
}

static PyMethodDef Rider_methods[] = {
    {"step", (PyCFunction)(void (*)(void))Rider_step, METH_FASTCALL,
     "step(t_next, dt, x, y, yaw, speed, accel, ego_box) -> (x, y, yaw, speed, accel, riding, waypoint, vx, vy)"},
    {NULL, NULL, 0, NULL},
};

static PyTypeObject RiderType = {
    PyVarObject_HEAD_INIT(NULL, 0).tp_name = "vei_scenario.core._core.Rider",
    .tp_basicsize = sizeof(RiderObject),
    .tp_dealloc = (destructor)Rider_dealloc,
    .tp_flags = Py_TPFLAGS_DEFAULT,
    .tp_doc = "Rider(track, route_x, route_y, params, offset, t_start, v_start, rides, repulsive): the rider agent.",
    .tp_methods = Rider_methods,
    .tp_init = (initproc)Rider_init,
    .tp_new = PyType_GenericNew,
};

/* whether two boxes overlap (circumscribed circles apart by more than a relative 1e-9 cannot: skipped) */
static int boxes_touch(const VeiBox *a, const VeiBox *b)
{
    double reach = 0.5 * hypot(a->length, a->width) * (1 + 1e-9) + 0.5 * hypot(b->length, b->width) * (1 + 1e-9);
    double dx = b->x - a->x, dy = b->y - a->y;
    return dx * dx + dy * dy <= reach * reach && vei_boxes_overlap(a, b);
}

/* overlapping(boxes) -> [(i, j), ...]: the pairs of (x, y, yaw, length, width) boxes that overlap, i < j */
static PyObject *overlapping(PyObject *mod, PyObject *arg)
{
    if (!PyBytes_Check(arg)) {
        PyErr_SetString(PyExc_TypeError, "overlapping takes the boxes as bytes of doubles");
        return NULL;
    }
    const VeiBox *b = (const VeiBox *)PyBytes_AS_STRING(arg);
    Py_ssize_t n = PyBytes_GET_SIZE(arg) / (Py_ssize_t)sizeof(VeiBox);
    PyObject *out = PyList_New(0);
    if (!out) return NULL;
    for (Py_ssize_t i = 0; i < n; i++) {
        for (Py_ssize_t j = i + 1; j < n; j++) {
            if (!boxes_touch(&b[i], &b[j])) continue;
            PyObject *pair = Py_BuildValue("(nn)", i, j);
            if (!pair || PyList_Append(out, pair) < 0) {
                Py_XDECREF(pair);
                Py_DECREF(out);
                return NULL;
            }
            Py_DECREF(pair);
        }
    }
    return out;
}

/* ---------------------------------------------------------------------------------------------- */
/* cruise: quiet steps of the interpreter (see vei_scenario/interpreter/cruise.py) in one call */

/* a road user's columns: mode (-1 deleted, 0 straight on, 1 its lane, 2 its path, 3 its timed path in
 * position mode, 4 its timed path in follow mode, 5 towed), where it is on its lane or path (s, lane,
 * offset, forward or, on a path, reversing, heading to the lane), pose, box, the bounds of a step,
 * odometer, speed (a step moves speed * dt, as the engine's), last step's metres, a running
 * SpeedAction's transition, a timed path's timing (PathFollower.trajectory_time: base, scale, offset;
 * the path's last time) and the road user's acceleration limits, the step's acceleration, and a towed
 * trailer's tow (its row), the tow's hitch, the trailer's coupler and its place in the chain (1: behind
 * a tow that is not towed itself); a running lane change or lane offset (actions.LaneChangeRuntime): its
 * shape (SHAPE_*), whether its progress is by time (else by distance), its length in that, start time and
 * odometer, the steps ahead its progress is taken at, whether only the along-road part of a step moves s,
 * the target lane, its offset, where it started from the target lane's centre, the target lane section's
 * span and index (the target's centre is taken within it; -1: on another road, taken where it is), its progress so far,
 * a lane change's progress along the road (over distance), whether it steps at the speed its step began with (a
 * SpeedAction after it in the storyboard sets the speed: esmini steps it later), and the position it headed from
 * (NaN: none yet) */
/* (each table's columns are listed once: their names reach Python as _core.CRUISE_LAYOUT, which
 * interpreter/cruise.py and synchronize.py build and read the columns by) */
#define ROAD_USER_COLUMNS(F)                                                                                    \
    F(MODE) F(S) F(LANE) F(OFFSET) F(FORWARD) F(HEADING) F(X) F(Y) F(YAW) F(CENTER_X) F(LENGTH) F(WIDTH)        \
    F(MAX_MOVE) F(MAX_DS) F(ODOMETER) F(SPEED) F(LAST_MOVED) F(PROFILE) F(PROFILE_V0) F(PROFILE_V1)            \
    F(PROFILE_T0) F(PROFILE_DURATION) F(TIME_BASE) F(TIME_SCALE) F(TIME_OFFSET) F(TIME_END) F(MAX_ACCEL)       \
    F(MAX_DECEL) F(ACCEL) F(TOW) F(HITCH) F(COUPLER) F(CHAIN) F(LATERAL) F(LAT_SHAPE) F(LAT_BY_TIME)           \
    F(LAT_VALUE) F(LAT_T0) F(LAT_ODO0) F(LAT_AHEAD) F(LAT_PROJECTS) F(LAT_TARGET_LANE) F(LAT_TARGET_OFFSET)    \
    F(LAT_START_REL) F(LAT_LO) F(LAT_HI) F(LAT_SECTION) F(LAT_FRACTION) F(LAT_PARAM) F(LAT_OLD_SPEED) F(PREV_X)  \
    F(PREV_Y) F(PAST_END)
#define CR_ENUM(name) CR_##name,
enum { ROAD_USER_COLUMNS(CR_ENUM) CR_COLS };
#define COLUMN_NAME(name) #name,
/* the modes */
#define MODES(F) F(STRAIGHT) F(LANE) F(PATH) F(TIMED) F(TIMED_FOLLOW) F(TOWED)
#define MODE_ENUM(name) MODE_##name,
enum { MODES(MODE_ENUM) };
/* a running SpeedAction's transition (entities.SpeedProfile): its shape (-1: none) */
#define SHAPES(F) F(LINEAR) F(CUBIC) F(SINUSOIDAL)
#define SHAPE_ENUM(name) SHAPE_##name,
enum { SHAPES(SHAPE_ENUM) };

/* transition_fraction: how far a transition of shape SHAPE_* has come at progress x */
static double shape_fraction(double shape, double x)
{
    if (shape == SHAPE_CUBIC) return x * x * (3 - 2 * x);
    if (shape == SHAPE_SINUSOIDAL) return 0.5 * (1 - cos(M_PI * x));
    return x;
}

/* the slope of shape_fraction at x (how fast a transition moves per unit of progress there) */
static double shape_slope(double shape, double x)
{
    if (shape == SHAPE_CUBIC) return 6 * x * (1 - x);
    if (shape == SHAPE_SINUSOIDAL) return 0.5 * M_PI * sin(M_PI * x);
    return 1.0;
}

/* A lane change's heading from its lane's direction (towards increasing t) in a step of ds metres, as
 * esmini 3.6 steps it (measured against its trajectories): from the lateral rate at progress x (where the
 * step starts) of a transition of `delta` metres sideways over `value` seconds (by_time) or metres, over
 * time asin(rate / speed), over distance atan(rate per metre along the road). LaneChangeRuntime.step_heading
 * (the interpreter's steps) and lateral_step (the core's) both take it here. */
static double lane_change_turn(double shape, int by_time, double delta, double value, double x, double dt, double ds)
{
    double rate = delta * shape_slope(shape, x) / value;
    if (!by_time) return atan(rate);
    double r = rate * dt / fabs(ds);
    return asin(r < -1.0 ? -1.0 : r > 1.0 ? 1.0 : r);
}

/* A SpeedAction's speed at time t of its transition from v0 at t0 to v1 over duration, of shape SHAPE_*
 * (none: v1 at once); 1 when the transition is over by t. SpeedProfile.speed (the interpreter's steps)
 * and profile_speed (the core's) both take it here. */
static int transition_speed(double v0, double v1, double t0, double duration, double shape, double t, double *v)
{
    if (duration <= 0) {
        *v = v1;
        return 1;
    }
    double x = (t - t0) / duration;
    if (0.0 > x) x = 0.0; /* (Python's min(max(x, 0.0), 1.0): NaN stays NaN) */
    if (x > 1.0) x = 1.0;
    *v = v0 + (v1 - v0) * shape_fraction(shape, x);
    return x >= 1.0;
}

/* the speed at the end of a step from t to t_next (the engine's t + dt) in *v; 0 when the transition
 * ends in the step or its action would end after it (SpeedAction.update: the interpreter's steps) */
static int profile_speed(const double *e, double t, double t_next, double *v)
{
    double t0 = e[CR_PROFILE_T0], duration = e[CR_PROFILE_DURATION];
    if (!(duration > 0) || t >= t0 + duration - 1e-9) return 0;
    return !transition_speed(e[CR_PROFILE_V0], e[CR_PROFILE_V1], t0, duration, e[CR_PROFILE], t_next, v);
}

/* a running SynchronizeAction (interpreter/synchronize.py), whose distances are along the path or
 * road each party stays on (|goal s - s|) or, with a program (its offset, else -1), over the chains of
 * roads from the party's road to the goal's */
#define SYNC_COLUMNS(F)                                                                                         \
    F(ENTITY) F(MASTER) F(GOAL) F(MASTER_GOAL) F(TOL) F(TOL_MASTER) F(FINAL) F(STEADY) F(MODE) F(SUBMODE)     \
    F(LAST) F(LAST_MASTER) F(PROGRAM) F(MASTER_PROGRAM)
#define SY_ENUM(name) SY_##name,
enum { SYNC_COLUMNS(SY_ENUM) SY_COLS };
/* the profile's modes (Synchronize.mode: the names Python reads them by) and the side it bends to */
#define SYNC_MODES(F) F(NONE) F(WAITING) F(STEADY) F(STOP_NOW) F(STOPPED) F(LINEAR) F(NON_LINEAR)
#define SM_ENUM(name) SM_##name,
enum { SYNC_MODES(SM_ENUM) };
enum { SS_NONE, SS_CONVEX, SS_CONCAVE };

/* a distance, time or speed taken as none, and a time taken as no limit (a master standing) */
#define SYNC_SMALL 1e-10
#define SYNC_LARGE 1e10
/* the braking when a stop must start at once (esmini's MAX_DECELERATION), m/s^2 */
#define SYNC_STOP_DECELERATION 8.0
/* how close (m/s) the speed must be to the straight speed line to switch to it */
#define SYNC_ON_LINE 0.1

/* (acceleration of the first piece, speed at its end) of a profile of two constant-acceleration pieces
 * from v0 to a speed vx and on to v1 covering s in t with the same magnitude of acceleration. From
 * s = (v0 + vx) x / 2 + (vx + v1)(t - x) / 2 and (vx - v0) / x = (vx - v1) / (t - x): a quadratic in vx,
 * whose root with 0 < x < t is taken (symmetric: the turn half way) */
static void sync_two_piece(double v0, double v1, double s, double t, double *acc, double *vx)
{
    if (fabs(v1 - v0) < SYNC_SMALL) {
        *vx = (s - (t / 2.0) * v0) / (t / 2.0);
        *acc = (*vx - v0) / (t / 2.0);
        return;
    }
    double q = 2.0 * s * s - 2.0 * (v1 + v0) * t * s + (v1 * v1 + v0 * v0) * t * t;
    double root = sqrt(2.0) * sqrt(q > 0.0 ? q : 0.0); /* (Python's max(0.0, q)) */
    for (int k = 0; k < 2; k++) {
        double sign = k == 0 ? 1.0 : -1.0;
        double x = -(sign * root + 2.0 * s - 2.0 * v1 * t) / (2.0 * (v1 - v0));
        double v = (2.0 * s - sign * root) / (2.0 * t);
        if (0.0 < x && x < t) {
            *acc = (v - v0) / x, *vx = v;
            return;
        }
    }
    *acc = 0.0, *vx = 0.0;
}

/* the speed for the coming step of esmini's profile that covers s in t ending at v1 (the module docstring
 * of interpreter/synchronize.py tells its pieces), on the columns' mode and submode; master_moved: whether
 * the master moved in the last step */
static double sync_profile(double *sy, double v0, double s, double t, double v1, double dt, int master_moved)
{
    int mode = (int)sy[SY_MODE], sub = (int)sy[SY_SUBMODE];
    double v;
    if (!isnan(sy[SY_STEADY]) && mode != SM_STEADY) {
        double steady = sy[SY_STEADY], time_to_steady = v1 > SYNC_SMALL ? steady / v1 : SYNC_LARGE;
        if (s - steady < SYNC_SMALL || t - time_to_steady < SYNC_SMALL) mode = SM_STEADY, sub = SS_NONE;
        else s -= steady, t -= time_to_steady; /* (plan to reach the final speed where the steady stretch begins) */
    }
    if (mode == SM_STEADY) {
        v = v1;
        goto out;
    }
    if (mode == SM_WAITING) { /* stopped for a master that does not move */
        if (t >= SYNC_LARGE) {
            v = v0;
            goto out;
        }
        mode = SM_NONE;
    }
    if (mode == SM_STOP_NOW) {
        v = v0 - SYNC_STOP_DECELERATION * dt;
        if (v < 0.0) mode = SM_WAITING, v = 0.0;
        goto out;
    }
    if (mode == SM_STOPPED) {
        if (v1 > SYNC_SMALL && t < 2.0 * s / v1) mode = SM_LINEAR; /* time to start again: on the line */
        else {
            v = 0.0;
            goto out;
        }
    }
    if (mode == SM_LINEAR) {
        if (t > SYNC_LARGE - 1.0) v = 0.0;
        else {
            double vf = v1 > 0.0 ? v1 : 0.0, line = (t < 0.001 || s < 0.001) ? 0.0 : 2.0 * s / t - vf;
            v = line > 0.0 ? line : 0.0;
        }
        goto out;
    }
    if (mode == SM_NON_LINEAR && t < SYNC_LARGE && fabs(v0 - (2.0 * s / t - v1)) < SYNC_ON_LINE) { /* on the line */
        mode = SM_LINEAR, v = v0;
        goto out;
    }
    if (mode == SM_NONE) {
        /* which side of the mean speed the profile bends to is judged from the master's measured motion:
         * before it has moved (a synchronisation started at t = 0) esmini 3.6 sees no time limit and picks
         * the lingering side, then takes the straight line at once if the first piece must accelerate
         * after all (its log: "Reached apex" in the first step) */
        mode = SM_NON_LINEAR;
        double t_seen = master_moved ? t : SYNC_LARGE;
        sub = (v1 + v0) / 2.0 < s / t_seen ? SS_CONVEX : SS_CONCAVE;
    }
    double acc, vx;
    sync_two_piece(v0, v1, s, t, &acc, &vx);
    /* the apex is passed: keep the speed for this step, then the line */
    if ((sub == SS_CONCAVE && acc > 0) || (sub == SS_CONVEX && acc < 0)) mode = SM_LINEAR, acc = 0.0;
    if (mode == SM_NON_LINEAR && vx < 0.0) { /* the trough is below 0: brake to a stop, wait */
        double t1 = 2.0 * v0 * s / (v0 * v0 + v1 * v1);
        acc = fabs(t1) > SYNC_SMALL ? -v0 / t1 : 0.0;
        if (t1 * v0 / 2.0 > s / 2.0) acc = -SYNC_STOP_DECELERATION, mode = SM_STOP_NOW; /* (more than half the way) */
        if (v0 + acc * dt < 0.0) {
            mode = SM_STOPPED, v = 0.0;
            goto out;
        }
    }
    v = v0 + acc * dt;
out:
    sy[SY_MODE] = mode, sy[SY_SUBMODE] = sub;
    return v;
}

/* routes.road_distance from s on a road to a goal on another: the least over the chains of roads
 * between them, summed in its order. program: road length, goal road length, goal s, number of chains,
 * then per chain: leaving forward, arriving forward, number of roads driven whole, their lengths.
 * -1 where s is off its road (the interpreter searches afresh there). */
static double road_program(const double *prog, double sa)
{
    double la = prog[0], lb = prog[1], sb = prog[2], best = -1.0;
    if (!(0.0 <= sa && sa <= la)) return -1.0;
    const double *c = prog + 4;
    for (long k = 0, chains = (long)prog[3]; k < chains; k++) {
        long middle = (long)c[2];
        double total = c[0] != 0.0 ? la - sa : sa;
        for (long j = 0; j < middle; j++) total += c[3 + j];
        total += c[1] != 0.0 ? sb : lb - sb;
        if (best < 0.0 || total < best) best = total;
        c += 3 + middle;
    }
    return best;
}

/* whether the program at offset o (-1: none) lies within the n numbers given */
static int program_fits(const double *programs, Py_ssize_t n, double o)
{
    if (o < 0) return 1;
    if (o + 4 > n) return 0;
    Py_ssize_t at = (Py_ssize_t)o + 4;
    for (long k = 0, chains = (long)programs[(Py_ssize_t)o + 3]; k < chains; k++) {
        if (at + 3 > n || !(programs[at + 2] >= 0)) return 0;
        at += 3 + (Py_ssize_t)programs[at + 2];
        if (at > n) return 0;
    }
    return 1;
}

/* how far a party at s still has to go to its goal (-1: not known in the core) */
static double sync_distance(const double *programs, double program, double goal, double s)
{
    return program < 0 ? fabs(goal - s) : road_program(programs + (Py_ssize_t)program, s);
}

/* Synchronize.step once the two distances to go are known (before the tolerances), on the columns of the
 * synchronisation (its tolerances, last distances, final speed, steady stretch, mode and submode, which
 * it updates): the entity's speed for the coming step from its speed v and the master's, in *v_out; 0
 * when the action ends in this step (the interpreter then sets the final speed). The core's quiet
 * steps and the interpreter's own steps (the module's sync_speed) both take it. */
static int sync_speed(double *sy, double dist, double master_dist, double v, double master_speed, int master_moved,
                      double dt, double *v_out)
{
    if (dist < sy[SY_TOL] + SYNC_SMALL || master_dist < sy[SY_TOL_MASTER] + SYNC_SMALL || dist > sy[SY_LAST] ||
        master_dist > sy[SY_LAST_MASTER])
        return 0;
    sy[SY_LAST] = dist, sy[SY_LAST_MASTER] = master_dist;
    dist -= sy[SY_TOL], master_dist -= sy[SY_TOL_MASTER];
    if (SYNC_SMALL > dist) dist = SYNC_SMALL;
    if (SYNC_SMALL > master_dist) master_dist = SYNC_SMALL;
    double master_time = SYNC_LARGE;
    master_speed = fabs(master_speed); /* (a master reversing along its path comes closer too) */
    if (master_speed > SYNC_SMALL) {
        master_time = master_dist / master_speed;
        if (master_time < dt) return 0;
    }
    if (isnan(sy[SY_FINAL])) { /* reach the target at whatever speed a constant acceleration gives */
        double v_end = 2.0 * dist / master_time - v;
        v += (v_end - v) / master_time * dt;
    } else
        v = sync_profile(sy, v, dist, master_time, sy[SY_FINAL], dt, master_moved);
    *v_out = v;
    return 1;
}

/* Synchronize.step on the columns before the move, its distances along paths or over road programs: the
 * entity's new speed in its column, or 0 when the action ends in this step (the interpreter takes that
 * step) */
static int sync_step(double *sy, const double *programs, const double *cur, double *next, double dt)
{
    const double *e = cur + (Py_ssize_t)sy[SY_ENTITY] * CR_COLS, *m = cur + (Py_ssize_t)sy[SY_MASTER] * CR_COLS;
    double master_dist = sync_distance(programs, sy[SY_MASTER_PROGRAM], sy[SY_MASTER_GOAL], m[CR_S]);
    double dist = sync_distance(programs, sy[SY_PROGRAM], sy[SY_GOAL], e[CR_S]);
    if (master_dist < 0 || dist < 0) return 0;
    return sync_speed(sy, dist, master_dist, e[CR_SPEED], m[CR_SPEED], m[CR_LAST_MOVED] > 0.0, dt,
                      &next[(Py_ssize_t)sy[SY_ENTITY] * CR_COLS + CR_SPEED]);
}

/* the bounding box of a road user at (x, y, yaw) whose box centre is center_x ahead of it (Entity.box) */
static VeiBox entity_box(double x, double y, double yaw, double center_x, double length, double width)
{
    double c, s;
    vr_cos_sin(yaw, &c, &s);
    return (VeiBox){x + c * center_x, y + s * center_x, yaw, length, width};
}

/* the bounding box of the road user whose core columns are e */
static VeiBox row_box(const double *e)
{
    return entity_box(e[CR_X], e[CR_Y], e[CR_YAW], e[CR_CENTER_X], e[CR_LENGTH], e[CR_WIDTH]);
}

/* the pairs (i * n + j) of road users whose boxes overlap; count in *k */
static void cruise_pairs(const double *st, Py_ssize_t n, VeiBox *box, int *pairs, Py_ssize_t *k)
{
    for (Py_ssize_t i = 0; i < n; i++) {
        const double *e = st + i * CR_COLS;
        box[i] = row_box(e);
    }
    *k = 0;
    for (Py_ssize_t i = 0; i < n; i++) {
        if (st[i * CR_COLS + CR_MODE] < 0) continue;
        for (Py_ssize_t j = i + 1; j < n; j++)
            if (st[j * CR_COLS + CR_MODE] >= 0 && boxes_touch(&box[i], &box[j])) pairs[(*k)++] = (int)(i * n + j);
    }
}

/* PathFollower.finished: whether a timed path's action is done after the step that starts at t (never
 * when its last time is NaN: the action is over and the road user plays on past the path's end) */
static int timed_done(const double *e, double t, double dt)
{
    double left = e[CR_TIME_END] - ((t - e[CR_TIME_BASE]) * e[CR_TIME_SCALE] + e[CR_TIME_OFFSET]);
    return left <= dt * e[CR_TIME_SCALE] + 1e-9;
}

/* one road user on its timed path in the step from t (timed_step); 0 when the path's action ends in the
 * evaluation at t (which the core replaces: the interpreter steps on from there). */
static int timed_move(const VeiPolyline *p, const double *e, double t, double dt, double *next)
{
    if (timed_done(e, t, dt)) return 0;
    double tt = (t + dt - e[CR_TIME_BASE]) * e[CR_TIME_SCALE] + e[CR_TIME_OFFSET], out[6];
    timed_step(p, tt, e[CR_S], e[CR_SPEED], e[CR_MODE] != MODE_TIMED, e[CR_MAX_ACCEL], e[CR_MAX_DECEL], dt, out);
    next[CR_X] = out[0], next[CR_Y] = out[1], next[CR_YAW] = out[2];
    next[CR_S] = out[3], next[CR_SPEED] = out[4], next[CR_ACCEL] = out[5];
    return 1;
}

/* whether a road user's step from e to next stays within its bounds: moved no further than its
 * largest move, turned no more than max_turn */
static int within_bounds(const double *e, const double *next, double max_turn)
{
    double turn = fabs(remainder(next[CR_YAW] - e[CR_YAW], 2 * M_PI));
    return hypot(next[CR_X] - e[CR_X], next[CR_Y] - e[CR_Y]) <= e[CR_MAX_MOVE] && turn <= max_turn;
}

/* Where a trailer at (x, y, yaw) is after its tow has moved to (tx, ty, tyaw) (trailers.pull and the
 * core's quiet steps both take it here): its coupler, coupler metres ahead of its axle, rides on the
 * tow's hitch, hitch metres ahead of the tow's reference point; the axle is drawn towards the hitch
 * along the rod, the trailer turned to face it (a coupler behind the axle: the rod points the other
 * way). out: x, y, yaw. */
static void towed_pose(double tx, double ty, double tyaw, double hitch, double coupler, double x, double y,
                       double yaw, double *out)
{
    double hx = tx + hitch * cos(tyaw), hy = ty + hitch * sin(tyaw);
    double dx = hx - x, dy = hy - y;
    if (hypot(dx, dy) > 1e-12) yaw = coupler < 0 ? atan2(-dy, -dx) : atan2(dy, dx);
    out[0] = hx - coupler * cos(yaw), out[1] = hy - coupler * sin(yaw), out[2] = yaw;
}

/* a towed trailer (e, next) after its tow has moved (tow: the tow's next columns); 0 when it moves or
 * turns more than the bounds */
static int towed_move(const double *e, const double *tow, double dt, double max_turn, double *next)
{
    double out[3];
    towed_pose(tow[CR_X], tow[CR_Y], tow[CR_YAW], e[CR_HITCH], e[CR_COUPLER], e[CR_X], e[CR_Y], e[CR_YAW], out);
    next[CR_X] = out[0], next[CR_Y] = out[1], next[CR_YAW] = out[2];
    next[CR_ACCEL] = (tow[CR_SPEED] - e[CR_SPEED]) / dt;
    next[CR_SPEED] = tow[CR_SPEED];
    return within_bounds(e, next, max_turn);
}

/* one road user's next pose keeping its lane, driving straight on or along its path, timed or not (the
 * interpreter's default motion: motion.lane_keep's one-call path, motion.advance_along, the timed
 * branch); 0 when the step is not a quiet one (off its road or lane, to its path's end or its timed
 * path's action's, further or more turned than the bounds, starting or ending a standstill). next holds
 * the step's speed already (a timed path sets its own). */
/* whether hypot's h may lie on the other side of threshold than Python's math.hypot puts it (the two
 * may differ in the last bit): the interpreter then takes the step */
static int near_threshold(double h, double threshold) { return fabs(h - threshold) <= threshold * 1e-12; }

/* motion._lane_yaw: the yaw of a road user turned heading from its lane's direction base, in (-pi, pi] */
static double lane_yaw(double base, double heading)
{
    double c, s;
    vr_cos_sin(base + heading, &c, &s);
    return atan2(s, c);
}

/* LaneChangeRuntime.offset at s for a transition come to fraction f: from the target lane's centre (held
 * within its section), going from where it started to the target offset, less the centre of the lane it
 * keeps; 0 where the core leaves that to the interpreter (the target's section maps its lane) */
static int lateral_offset(const vr_road *r, const double *e, double s, double f, double *offset)
{
    double c_target, c_here, s_in = fmin(fmax(s, e[CR_LAT_LO]), e[CR_LAT_HI]);
    /* (held where the target's section maps its lane to another one's: Road.lane_center_t_in's, the interpreter's) */
    if (e[CR_LAT_SECTION] >= 0 && vr_section_index(r, s_in) != (int)e[CR_LAT_SECTION]) return 0;
    if (vr_lane_center_t(r, s_in, (int)e[CR_LAT_TARGET_LANE], &c_target) < 0 ||
        vr_lane_center_t(r, s, (int)e[CR_LANE], &c_here) < 0)
        return 0;
    *offset = c_target + (1 - f) * e[CR_LAT_START_REL] + f * e[CR_LAT_TARGET_OFFSET] - c_here;
    return 1;
}

/* motion.lane_keep with a running lane change or lane offset (LaneChangeRuntime), on one road in one lane: a
 * lane change moves s by the along-road part of its step at the heading its lateral rate gives
 * (lane_change_turn; over distance its progress advances by that part), taken at the offset the step brings
 * it to, and heads so; a lane offset heads where it moves. 0 (not quiet) where the step leaves the road or
 * lane, or where the transition completes */
static int lateral_step(const vr_road *r, const double *e, double t, double ds, double dt, double *next)
{
    int lane = (int)e[CR_LANE], lane1, forward = e[CR_FORWARD] != 0.0;
    int projects = e[CR_LAT_PROJECTS] != 0.0, by_time = e[CR_LAT_BY_TIME] != 0.0;
    double s1, out[4], turn = 0.0, param = e[CR_LAT_PARAM], along_offset = e[CR_OFFSET], value = e[CR_LAT_VALUE];
    if (projects) { /* (LaneChangeRuntime.step_heading) */
        double x0 = (by_time ? t + (e[CR_LAT_AHEAD] - 1) * dt - e[CR_LAT_T0] : param) / value;
        x0 = fmin(fmax(x0, 0.0), 1.0);
        turn = lane_change_turn(e[CR_LAT_SHAPE], by_time, e[CR_LAT_TARGET_OFFSET] - e[CR_LAT_START_REL], value, x0, dt, ds);
        if (!by_time) param += fabs(ds) * cos(turn);
        ds *= cos(turn);
    }
    double done = by_time ? t + e[CR_LAT_AHEAD] * dt - e[CR_LAT_T0] : projects ? param : e[CR_ODOMETER] - e[CR_LAT_ODO0];
    double x = done / value, offset;
    x = x > 0.0 ? x : 0.0;
    if (x >= 1.0) return 0; /* (it completes: the interpreter's step, and its action's end) */
    double f = shape_fraction(e[CR_LAT_SHAPE], x);
    if (projects && !lateral_offset(r, e, e[CR_S], f, &along_offset)) return 0;
    if (lane_advance_s(r, e[CR_S], lane, along_offset, ds, forward, &s1, &lane1) != 1 || lane1 != lane) return 0;
    if (!lateral_offset(r, e, s1, f, &offset) || vr_lane_pose(r, s1, lane, offset, out) < 0) return 0;
    double base = forward ? out[2] : out[2] + M_PI, moved = hypot(out[0] - e[CR_X], out[1] - e[CR_Y]);
    if (near_threshold(moved, 1e-9)) return 0;
    next[CR_S] = s1, next[CR_OFFSET] = offset, next[CR_LAT_FRACTION] = x, next[CR_LAT_PARAM] = param;
    next[CR_X] = out[0], next[CR_Y] = out[1];
    next[CR_YAW] = lane_yaw(base, e[CR_HEADING]);
    if (moved > 1e-9 && projects) {
        next[CR_YAW] = lane_yaw(base, forward ? turn : -turn);
    } else if (moved > 1e-9) { /* it heads where it moves (from where it last headed from) */
        double px = e[CR_PREV_X], py = e[CR_PREV_Y];
        next[CR_PREV_X] = out[0], next[CR_PREV_Y] = out[1];
        if (isnan(px)) {
            next[CR_YAW] = base;
        } else {
            double dx = out[0] - px, dy = out[1] - py, h = hypot(dx, dy);
            if (near_threshold(h, 1e-6)) return 0;
            next[CR_YAW] = h > 1e-6 ? atan2(dy, dx) : base;
        }
    }
    return 1;
}

/* cruise_move's refusal of a road user starting or stopping: the interpreter's step (it marks when a
 * standstill began), a one-step event after which the steps are quiet again as a rule */
#define STANDSTILL_EDGE -1

static int cruise_move(PyObject *way, const double *e, double t, double max_turn, double dt, double *next)
{
    double mode = e[CR_MODE];
    if (mode < 0 || mode == MODE_TOWED) return 1; /* (a trailer is pulled after everyone has moved) */
    if (mode >= MODE_TIMED) {
        if (!timed_move(&((PolylineObject *)way)->p, e, t, dt, next)) return 0;
    } else {
        next[CR_ACCEL] = (next[CR_SPEED] - e[CR_SPEED]) / dt;
    }
    double speed = next[CR_SPEED], ds = speed * dt;
    if ((fabs(speed) < 1e-9) != (fabs(e[CR_SPEED]) < 1e-9)) return STANDSTILL_EDGE;
    if (mode == MODE_LANE && e[CR_LATERAL] != 0.0 && e[CR_LAT_OLD_SPEED] != 0.0 && e[CR_PROFILE] >= 0) ds = e[CR_SPEED] * dt;
    if (mode == MODE_STRAIGHT) {
        double c, s;
        vr_cos_sin(e[CR_YAW], &c, &s);
        next[CR_X] = e[CR_X] + ds * c;
        next[CR_Y] = e[CR_Y] + ds * s;
    } else if (mode == MODE_LANE && e[CR_LATERAL] != 0.0) {
        /* a lane change paused by a standstill (motion.lane_keep: it waits, its clock shifted) is the interpreter's */
        if (fabs(speed) < 1e-9 && e[CR_LAT_PROJECTS] != 0.0) return 0;
        if (!lateral_step(&((RoadObject *)way)->r, e, t, ds, dt, next) || fabs(next[CR_S] - e[CR_S]) > e[CR_MAX_DS]) return 0;
    } else if (mode == MODE_LANE) {
        int lane = (int)e[CR_LANE], lane1, forward = e[CR_FORWARD] != 0.0;
        double s1, out[4];
        if (lane_step(&((RoadObject *)way)->r, e[CR_S], lane, e[CR_OFFSET], ds, forward, &s1, &lane1, out) != 1 ||
            lane1 != lane || fabs(s1 - e[CR_S]) > e[CR_MAX_DS])
            return 0;
        next[CR_S] = s1;
        next[CR_X] = out[0];
        next[CR_Y] = out[1];
        next[CR_YAW] = lane_yaw(forward ? out[2] : out[2] + M_PI, e[CR_HEADING]);
    } else if (mode == MODE_PATH) {
        const VeiPolyline *p = &((PolylineObject *)way)->p;
        double length = p->s[p->n - 1], out[4];
        int reverse = e[CR_FORWARD] != 0.0;
        if (e[CR_S] + fabs(ds) > length) {
            /* on past its end (engine._motion, as esmini): to the end, the rest straight on at the end's
             * heading; once it is there (the action that reached it over: reaching it is the interpreter's) */
            if (e[CR_PAST_END] == 0.0 || (ds < 0) != reverse || e[CR_S] < length - 1e-9) return 0;
            double over = copysign(e[CR_S] + fabs(ds) - length, ds), c, s;
            path_advance(p, e[CR_S], ds - over, reverse, out);
            vr_cos_sin(out[2], &c, &s);
            next[CR_X] = out[0] + over * c, next[CR_Y] = out[1] + over * s;
        } else {
            path_advance(p, e[CR_S], ds, reverse, out);
            if (out[3] >= length - 1e-9 || fabs(out[3] - e[CR_S]) > e[CR_MAX_DS]) return 0;
            next[CR_X] = out[0], next[CR_Y] = out[1];
        }
        next[CR_YAW] = out[2], next[CR_S] = out[3];
    } else if (fabs(next[CR_S] - e[CR_S]) > e[CR_MAX_DS]) {
        return 0;
    }
    return within_bounds(e, next, max_turn);
}

/* a continuous LongitudinalDistanceAction (longitudinal.LongitudinalDistance): its road user and the one it
 * keeps the gap to, the distance or time gap, whether it is a time gap, the side (+1: behind the reference),
 * whether the gap is between the boxes, and whether it is a difference of s (both on one road, measured along
 * it); without dynamic constraints (SPRING 0) the road user is placed at the gap along its lane before everyone
 * moves and goes on at its reference's speed; with them (SPRING 1) a damped spring on the gap sets its speed
 * within the limits, ACCEL the acceleration it gave last. FOLLOW 1: a SpeedAction's continuous RelativeTargetSpeed
 * (actions.Speed) instead, the road user towards its reference's speed plus VALUE (times VALUE: BY_FACTOR), held
 * within MAX_SPEED, at no more than MAX_ACCEL/MAX_DECEL */
#define KEEP_COLUMNS(F)                                                                                          \
    F(ENTITY) F(REF) F(VALUE) F(BY_TIME) F(SIDE) F(FREESPACE) F(ALONG_ROAD) F(SPRING) F(MAX_ACCEL) F(MAX_DECEL)  \
    F(MAX_SPEED) F(ACCEL_RATE) F(DECEL_RATE) F(ACCEL) F(FOLLOW) F(BY_FACTOR)
#define KP_ENUM(name) KP_##name,
/* the spring's stiffness per m/s^2 of permitted acceleration (1/s^2): the gap closes in a few seconds */
#define SPRING_PER_ACCEL 0.4
enum { KEEP_COLUMNS(KP_ENUM) KP_COLS };

/* The signed distance from a road user at (ax, ay, ayaw) to one at (bx, by) along the first's heading:
 * between their reference points, or with freespace between their boxes ba and bb (0 while their
 * projections on that axis overlap: side by side). longitudinal.longitudinal_gap (the interpreter's steps)
 * and keep_gap (the core's) both take it here. */
static double heading_gap(double ax, double ay, double ayaw, const VeiBox *ba, double bx, double by, const VeiBox *bb,
                          int freespace)
{
    double c, s;
    vr_cos_sin(ayaw, &c, &s);
    if (!freespace) return c * (bx - ax) + s * (by - ay);
    double dc, ds;
    vr_cos_sin(bb->yaw - ayaw, &dc, &ds);
    double own = c * ba->x + s * ba->y, other = c * bb->x + s * bb->y;
    double half_b = 0.5 * (bb->length * fabs(dc) + bb->width * fabs(ds));
    double lo_a = own - 0.5 * ba->length, hi_a = own + 0.5 * ba->length, lo_b = other - half_b, hi_b = other + half_b;
    return hi_a < lo_b ? lo_b - hi_a : hi_b < lo_a ? hi_b - lo_a : 0.0;
}

/* the gap keep kp measures from road user a to b: along their road (a difference of s) or heading_gap */
static double keep_gap(const double *kp, const double *a, const double *b)
{
    int freespace = kp[KP_FREESPACE] != 0.0;
    if (!freespace && kp[KP_ALONG_ROAD] != 0.0) return a[CR_FORWARD] != 0.0 ? b[CR_S] - a[CR_S] : a[CR_S] - b[CR_S];
    VeiBox ba = row_box(a), bb = row_box(b);
    return heading_gap(a[CR_X], a[CR_Y], a[CR_YAW], &ba, b[CR_X], b[CR_Y], &bb, freespace);
}

/* Python's min(a, b) and max(a, b) of two floats: the first unless the second is smaller (larger), so zeros
 * keep their sign and a NaN goes where Python's would */
static double py_min(double a, double b) { return b < a ? b : a; }
static double py_max(double a, double b) { return b > a ? b : a; }

/* the gap of keep kp now less the gap it keeps */
static double keep_error(const double *kp, const double *e, const double *ref, double ref_speed)
{
    double wanted = kp[KP_SIDE] * (kp[KP_BY_TIME] != 0.0 ? fabs(ref_speed) * kp[KP_VALUE] : kp[KP_VALUE]);
    return keep_gap(kp, e, ref) - wanted;
}

/* LongitudinalDistance's damped spring (esmini's): the acceleration for the coming step from the gap's error
 * (the gap less the one kept) and the speeds, its stiffness that of the acceleration (too far) or deceleration
 * (too close) permitted, clipped to those and grown in size from last no faster than the rate of its sign (dt
 * 0: not at all); *v: the speed it gives, within max_speed. LongitudinalDistance.step (the interpreter's
 * steps) and keep_spring (the core's) both take it here. */
static double spring_step(double error, double speed, double ref_speed, double max_accel, double max_decel,
                          double accel_rate, double decel_rate, double last, double max_speed, double dt, double *v)
{
    double k = (error < 0.0 ? max_accel : max_decel) * SPRING_PER_ACCEL;
    double acc = error * k - (speed - ref_speed) * 2.0 * sqrt(k);
    acc = py_max(-max_decel, py_min(max_accel, acc));
    if (acc < 0.0 && acc < last)
        acc = py_max(last - (dt > 0.0 ? decel_rate * dt : 0.0), acc);
    else if (acc >= 0.0 && acc > last)
        acc = py_min(last + (dt > 0.0 ? accel_rate * dt : 0.0), acc);
    *v = py_max(-max_speed, py_min(max_speed, speed + acc * dt));
    return acc;
}

/* the spring's speed for keep kp's road user for the coming step (st: where everyone is; ref_speed: its
 * reference's speed as the keeps stepped before this one left it), its acceleration kept in kp */
static double keep_spring(double *kp, const double *st, double ref_speed, double dt)
{
    const double *e = st + (Py_ssize_t)kp[KP_ENTITY] * CR_COLS, *ref = st + (Py_ssize_t)kp[KP_REF] * CR_COLS;
    double v;
    kp[KP_ACCEL] = spring_step(keep_error(kp, e, ref, ref_speed), e[CR_SPEED], ref_speed, kp[KP_MAX_ACCEL],
                               kp[KP_MAX_DECEL], kp[KP_ACCEL_RATE], kp[KP_DECEL_RATE], kp[KP_ACCEL], kp[KP_MAX_SPEED], dt, &v);
    return v;
}

/* LongitudinalDistance.step without dynamic constraints: the road user of keep kp put at its gap along its lane
 * (motion.lane_keep) in st (the caller gives it its reference's speed); 0 when that leaves its road or lane
 * (the interpreter takes the step) */
static int keep_place(const double *kp, PyObject *ways, double *st, double ref_speed)
{
    Py_ssize_t i = (Py_ssize_t)kp[KP_ENTITY];
    double *e = st + i * CR_COLS, *ref = st + (Py_ssize_t)kp[KP_REF] * CR_COLS;
    double error = keep_error(kp, e, ref, ref_speed), s1, out[4];
    int lane = (int)e[CR_LANE], lane1, forward = e[CR_FORWARD] != 0.0;
    if (lane_step(&((RoadObject *)PyTuple_GET_ITEM(ways, i))->r, e[CR_S], lane, e[CR_OFFSET], error, forward, &s1, &lane1, out) != 1 ||
        lane1 != lane)
        return 0;
    e[CR_S] = s1, e[CR_X] = out[0], e[CR_Y] = out[1];
    e[CR_YAW] = lane_yaw(forward ? out[2] : out[2] + M_PI, e[CR_HEADING]);
    return 1;
}

/* an adaptive cruise in charge of a road user on its lane (controllers.AdaptiveCruiseController): its road
 * user, the speed it commands and its set speed, the road user's acceleration limits, whether an action's new
 * speed becomes the set speed (additive), whether it sees the road users that moved before it after their moves
 * (sequential coupling), whether its road user moves after every other (override mode: esmini moves it in the
 * controller's own step), whether its road leads on ahead (a road or junction linked there), and its
 * parameters (VeiAccParams, in order from TIME_GAP) */
#define ACC_COLUMNS(F)                                                                                          \
    F(ENTITY) F(CURRENT) F(SET_SPEED) F(MAX_ACCEL) F(MAX_DECEL) F(ADDITIVE) F(SEQUENTIAL) F(LAST) F(LINKED)    \
    F(TIME_GAP) F(LATERAL_DIST) F(MIN_GAP) F(APPROACH_GAIN) F(DISTANCE_GAIN) F(STOP_GAP)
#define AC_ENUM(name) AC_##name,
enum { ACC_COLUMNS(AC_ENUM) AC_COLS };

/* AdaptiveCruiseController._leader in the core, for road user i on its lane with every other road user on
 * theirs, not changing lanes (their road points are their lane states): -1 where the core cannot tell (the
 * search along the lane would go on past its road onto the next, or a road user is elsewhere), else whether
 * it follows one, at bumper-to-bumper *gap driving at *v_lead. It sees the road users as the interpreter's
 * order leaves them: under sequential coupling those that moved already (moved[j]) after their moves, `next`;
 * else all at the step's start, `pre`. */
static int acc_leader(const double *ac, PyObject *ways, const double *pre, const double *next, const char *moved,
                      Py_ssize_t n, Py_ssize_t i, double *gap, double *v_lead)
{
    const double *e = pre + i * CR_COLS;
    PyObject *way = PyTuple_GET_ITEM(ways, i);
    const vr_road *r = &((RoadObject *)way)->r;
    const VeiAccParams *p = (const VeiAccParams *)(ac + AC_TIME_GAP);
    int lane = (int)e[CR_LANE], forward = e[CR_FORWARD] != 0.0, found = 0;
    double s = e[CR_S], current = ac[AC_CURRENT], my_t;
    if (vr_lane_center_t(r, s, lane, &my_t) < 0) return -1;
    my_t += e[CR_OFFSET];
    double limit = vei_acc_lookahead(p, current, ac[AC_MAX_DECEL]);
    if (ac[AC_LINKED] != 0.0 && !((forward ? r->length - s : s) > limit)) return -1;
    VeiBox own = row_box(e);
    for (Py_ssize_t j = 0; j < n; j++) {
        const double *o = (ac[AC_SEQUENTIAL] != 0.0 && moved[j] ? next : pre) + j * CR_COLS;
        if (j == i || o[CR_MODE] < 0) continue;
        if (o[CR_MODE] != MODE_LANE || o[CR_LATERAL] != 0.0) return -1;
        if (PyTuple_GET_ITEM(ways, j) == way) { /* on its road: how far ahead along its lane */
            int o_lane = (int)o[CR_LANE];
            double t;
            if (vr_lane_center_t(r, o[CR_S], o_lane, &t) < 0) return -1;
            if (fabs(t + o[CR_OFFSET] - my_t) < p->lateral_dist_m) {
                int there = (o[CR_S] >= s) == forward ? vr_lane_on(r, s, o[CR_S], lane, 1) : lane;
                double ds = forward ? o[CR_S] - s : s - o[CR_S];
                if (there == o_lane && ds <= limit) {
                    int same_way = fabs(remainder(o[CR_YAW] - e[CR_YAW], 2 * M_PI)) < 0.5 * M_PI;
                    double g = vei_bumper_gap(ds, e[CR_LENGTH], e[CR_CENTER_X], o[CR_LENGTH], o[CR_CENTER_X], same_way);
                    if (0.0 < g && (!found || g < *gap)) {
                        *gap = g, *v_lead = o[CR_SPEED], found = 1;
                        continue;
                    }
                }
            }
        }
        VeiBox other = row_box(o);
        double x_gap, y_gap;
        vei_box_gaps(&own, &other, &x_gap, &y_gap);
        if (vei_close_ahead(x_gap, y_gap, o[CR_LENGTH], current - o[CR_SPEED])) *gap = x_gap, *v_lead = o[CR_SPEED], found = 1;
    }
    return found;
}

/* AdaptiveCruiseController.move's speed for the coming step of acc ac's road user i into next (and as the
 * speed it commands); 0 where the core cannot tell who it follows */
static int acc_step(double *ac, PyObject *ways, const double *pre, double *next, const char *moved, Py_ssize_t n,
                    double dt)
{
    Py_ssize_t i = (Py_ssize_t)ac[AC_ENTITY];
    double speed = pre[i * CR_COLS + CR_SPEED], gap = 0.0, v_lead = 0.0;
    if (ac[AC_ADDITIVE] != 0.0 && fabs(speed - ac[AC_CURRENT]) > 1e-3) ac[AC_SET_SPEED] = speed;
    int lead = acc_leader(ac, ways, pre, next, moved, n, i, &gap, &v_lead);
    if (lead < 0) return 0;
    double v = vei_acc_speed((const VeiAccParams *)(ac + AC_TIME_GAP), ac[AC_CURRENT], ac[AC_SET_SPEED], lead, gap,
                             v_lead, ac[AC_MAX_ACCEL], ac[AC_MAX_DECEL], dt);
    ac[AC_CURRENT] = v;
    next[i * CR_COLS + CR_SPEED] = v;
    return 1;
}

/* a guard of a quiet stretch (cruise.QuietBounds.guard, .guard_distance): road user, the other road user (-1:
 * none; for a distance, the point POINT_X/Y/YAW instead), what is compared, the comparison (conditions.RULE_CODES)
 * and its value; a distance's freespace flag (between boxes, not reference points) */
#define GUARD_COLUMNS(F) F(ENTITY) F(OTHER) F(QUANTITY) F(RULE) F(VALUE) F(FREESPACE) F(POINT_X) F(POINT_Y) F(POINT_YAW)
#define GD_ENUM(name) GD_##name,
enum { GUARD_COLUMNS(GD_ENUM) GD_COLS };
/* speed and acceleration (less the other's) and the odometer are the interpreter's own columns, compared
 * exactly (the odometer as the step's rows sum it, before the guards are checked); distances
 * (conditions._relative) are recomputed here, so they are compared with a margin (GUARD_MARGIN_M), as is
 * AHEAD: how far the other's reference point is ahead of the road user's along its heading, signed
 * (conditions.TimeHeadway: a target behind has no headway) */
#define GUARD_QUANTITIES(F) F(SPEED) F(ACCEL) F(ODOMETER) F(CARTESIAN) F(LONGITUDINAL) F(LATERAL) F(AHEAD)
#define GQ_ENUM(name) GQ_##name,
enum { GUARD_QUANTITIES(GQ_ENUM) GQ_COUNT };
/* conditions.RULE_CODES: greaterThan, lessThan, greaterOrEqual, lessOrEqual, equalTo, notEqualTo */
#define RULES(F) F(GT) F(LT) F(GE) F(LE) F(EQ) F(NE)
#define RULE_ENUM(name) RULE_##name,
enum { RULES(RULE_ENUM) };
/* How near its threshold (m) a distance the core works out is taken as undecided: the interpreter's own
 * (conditions._relative) takes the box distance and hypot from here but projects on a road user's frame in
 * Python, which a compiler that fuses multiply-adds may round differently in the last bits, so the core stops
 * before a step that leaves a distance within this of its threshold and the interpreter decides the step. */
#define GUARD_MARGIN_M 1e-6

/* conditions.RULES: a comparison of a with b (equality within 1e-9, relative) */
static int rule_holds(int rule, double a, double b)
{
    double tolerance = 1e-9 * (fabs(b) > 1.0 ? fabs(b) : 1.0);
    switch (rule) {
    case RULE_GT: return a > b;
    case RULE_LT: return a < b;
    case RULE_GE: return a >= b;
    case RULE_LE: return a <= b;
    case RULE_EQ: return fabs(a - b) <= tolerance;
    default: return fabs(a - b) > tolerance;
    }
}

/* the distance from point (px, py) to box b (0 inside) */
static double point_box_distance(double px, double py, const VeiBox *b)
{
    double c, s, dx = px - b->x, dy = py - b->y;
    vr_cos_sin(b->yaw, &c, &s);
    double ox = fabs(c * dx + s * dy) - 0.5 * b->length, oy = fabs(-s * dx + c * dy) - 0.5 * b->width;
    return hypot(ox > 0 ? ox : 0.0, oy > 0 ? oy : 0.0);
}

/* the shortest distance between two boxes (0 where they touch; models.boxes.box_distance is its vectorised
 * form, for whole runs): two disjoint convex polygons are closest at a corner of one of them */
static double box_gap(const VeiBox *a, const VeiBox *b)
{
    if (vei_boxes_overlap(a, b)) return 0.0;
    double best = INFINITY;
    for (int k = 0; k < 2; k++) {
        const VeiBox *p = k ? b : a, *q = k ? a : b;
        double c, s, hl = 0.5 * p->length, hw = 0.5 * p->width;
        vr_cos_sin(p->yaw, &c, &s);
        for (int corner = 0; corner < 4; corner++) {
            double lx = corner == 0 || corner == 3 ? hl : -hl, ly = corner < 2 ? hw : -hw;
            double d = point_box_distance(p->x + c * lx - s * ly, p->y + s * lx + c * ly, q);
            if (d < best) best = d;
        }
    }
    return best;
}

/* conditions._relative's distance between road user g[ENTITY] and g[OTHER] (or the guard's point) */
static double guard_distance(const double *g, const double *st)
{
    const double *a = st + (Py_ssize_t)g[GD_ENTITY] * CR_COLS;
    int freespace = g[GD_FREESPACE] != 0, kind = (int)g[GD_QUANTITY];
    VeiBox ba = row_box(a), bb;
    double bx, by;
    if (g[GD_OTHER] >= 0) {
        const double *b = st + (Py_ssize_t)g[GD_OTHER] * CR_COLS;
        bb = row_box(b);
        bx = b[CR_X], by = b[CR_Y];
    } else {
        bb = (VeiBox){g[GD_POINT_X], g[GD_POINT_Y], g[GD_POINT_YAW], 0.0, 0.0};
        bx = bb.x, by = bb.y;
    }
    double rx = freespace ? bb.x - ba.x : bx - a[CR_X], ry = freespace ? bb.y - ba.y : by - a[CR_Y];
    if (kind == GQ_CARTESIAN) return freespace ? box_gap(&ba, &bb) : hypot(rx, ry);
    double c, s, dc, ds, d, half;
    vr_cos_sin(ba.yaw, &c, &s);
    if (kind == GQ_AHEAD) return c * (bx - a[CR_X]) + s * (by - a[CR_Y]);
    vr_cos_sin(bb.yaw - ba.yaw, &dc, &ds);
    dc = fabs(dc), ds = fabs(ds);
    if (kind == GQ_LONGITUDINAL)
        d = c * rx + s * ry, half = 0.5 * (ba.length + bb.length * dc + bb.width * ds);
    else
        d = -s * rx + c * ry, half = 0.5 * (ba.width + bb.width * dc + bb.length * ds);
    d = fabs(d) - (freespace ? half : 0.0);
    return d > 0 ? d : 0.0;
}

/* what a guard says of state st: 1 or 2 (a speed's comparison false or true), or for a distance 1 below its
 * threshold, 3 above it, 0 within the margin (undecided) */
static int guard_state(const double *g, const double *st)
{
    int quantity = (int)g[GD_QUANTITY];
    if (quantity >= GQ_CARTESIAN) {
        double d = guard_distance(g, st), value = g[GD_VALUE];
        double margin = GUARD_MARGIN_M + 1e-9 * fabs(value);
        return d > value + margin ? 3 : d < value - margin ? 1 : 0;
    }
    int col = quantity == GQ_ACCEL ? CR_ACCEL : quantity == GQ_ODOMETER ? CR_ODOMETER : CR_SPEED;
    double q = st[(Py_ssize_t)g[GD_ENTITY] * CR_COLS + col];
    if (g[GD_OTHER] >= 0) q -= st[(Py_ssize_t)g[GD_OTHER] * CR_COLS + col];
    return 1 + rule_holds((int)g[GD_RULE], q, g[GD_VALUE]);
}

/* the rows of one of cruise's tables (bytes of cols doubles each): their count in *rows; NULL with a ValueError
 * naming the table when its size is not whole rows */
static const double *table_rows(PyObject *bytes, Py_ssize_t cols, const char *name, Py_ssize_t *rows)
{
    Py_ssize_t size = PyBytes_GET_SIZE(bytes), row = (Py_ssize_t)sizeof(double) * cols;
    *rows = size / row;
    if (size != *rows * row) {
        PyErr_Format(PyExc_ValueError, "cruise: the %s need their columns each", name);
        return NULL;
    }
    return (const double *)PyBytes_AS_STRING(bytes);
}

/* cruise(ways, state, syncs, keeps, accs, programs, guards, times, max_turn, dt) -> (n, poses, state, syncs, keeps,
 * accs, edge): up to n_max steps (times: the simulation time at the start of each) of every road user (ways: per road
 * user its Road (mode 1), its Polyline (mode 2) or None), the kept distances (KP_COLS each) placing their road
 * users first, then the synchronisations (SY_COLS each) and the running transitions of SpeedActions setting
 * their entities' speeds before each move, and the adaptive cruises (AC_COLS each) setting theirs as their road
 * users' turns to move come; stops before a step
 * that is not quiet, ends a synchronisation, changes what a guard compares or which pairs overlap. poses: n x users x (x, y,
 * yaw, metres moved, speed, acceleration); state, syncs: the columns after the n steps. The metres moved
 * and the odometer are vei_hypot's, as the interpreter's own steps measure them (the module's hypot); edge: 1
 * when the step it stopped before starts or ends a road user's standstill (STANDSTILL_EDGE). */
static PyObject *cruise(PyObject *mod, PyObject *const *args, Py_ssize_t nargs)
{
    if (!args_ok(nargs, 10, "cruise")) return NULL;
    PyObject *ways = args[0], *state = args[1], *syncs = args[2], *keep_cols = args[3], *acc_cols = args[4];
    PyObject *progs = args[5], *guard_cols = args[6], *clock = args[7];
    double max_turn = PyFloat_AsDouble(args[8]), dt = PyFloat_AsDouble(args[9]);
    if (PyErr_Occurred()) return NULL;
    if (!PyTuple_Check(ways) || !PyBytes_Check(state) || !PyBytes_Check(syncs) || !PyBytes_Check(keep_cols) ||
        !PyBytes_Check(acc_cols) || !PyBytes_Check(progs) || !PyBytes_Check(guard_cols) || !PyBytes_Check(clock) ||
        !(dt > 0)) {
        PyErr_SetString(PyExc_TypeError, "cruise(ways tuple, state bytes, syncs bytes, keeps bytes, accs bytes, "
                                         "programs bytes, guards bytes, times bytes, max_turn, dt > 0)");
        return NULL;
    }
    Py_ssize_t n_keeps, n_guards, n_sync, n_accs;
    const double *keeps0 = table_rows(keep_cols, KP_COLS, "keeps", &n_keeps);
    const double *accs0 = table_rows(acc_cols, AC_COLS, "accs", &n_accs);
    const double *guards = table_rows(guard_cols, GD_COLS, "guards", &n_guards);
    const double *sy0 = table_rows(syncs, SY_COLS, "syncs", &n_sync);
    if (!keeps0 || !accs0 || !guards || !sy0) return NULL;
    /* times: the simulation time at the start of each step it may take */
    const double *times = (const double *)PyBytes_AS_STRING(clock);
    long n_max = (long)(PyBytes_GET_SIZE(clock) / (Py_ssize_t)sizeof(double));
    const double *programs = (const double *)PyBytes_AS_STRING(progs);
    Py_ssize_t n_programs = PyBytes_GET_SIZE(progs) / (Py_ssize_t)sizeof(double);
    Py_ssize_t n = PyTuple_GET_SIZE(ways);
    if (PyBytes_GET_SIZE(state) != n * (Py_ssize_t)sizeof(double) * CR_COLS) {
        PyErr_SetString(PyExc_ValueError, "cruise: the state needs its columns for every road user");
        return NULL;
    }
    const double *st0 = (const double *)PyBytes_AS_STRING(state);
    double max_chain = 0;
    for (Py_ssize_t i = 0; i < n; i++) {
        PyObject *w = PyTuple_GET_ITEM(ways, i);
        double mode = st0[i * CR_COLS + CR_MODE];
        int on_path = mode == MODE_PATH || mode == MODE_TIMED || mode == MODE_TIMED_FOLLOW;
        double tow = st0[i * CR_COLS + CR_TOW];
        if (mode == MODE_TOWED && !(tow >= 0 && tow < n && tow != i && st0[i * CR_COLS + CR_CHAIN] >= 1)) {
            PyErr_SetString(PyExc_ValueError, "cruise: a towed trailer names its tow and its place in the chain");
            return NULL;
        }
        if (mode == MODE_TOWED && st0[i * CR_COLS + CR_CHAIN] > max_chain) max_chain = st0[i * CR_COLS + CR_CHAIN];
        if ((mode == MODE_LANE && !PyObject_TypeCheck(w, &RoadType)) ||
            (on_path && !(PyObject_TypeCheck(w, &PolylineType) && ((PolylineObject *)w)->p.n >= 1)) ||
            (on_path && mode >= MODE_TIMED && ((PolylineObject *)w)->p.t == NULL) || mode > MODE_TOWED) {
            PyErr_SetString(PyExc_TypeError,
                            "cruise: a road user on its lane has its Road, on its path its Polyline (timed: with times)");
            return NULL;
        }
    }
    for (Py_ssize_t k = 0; k < n_guards; k++) {
        const double *g = guards + k * GD_COLS;
        if (!(g[GD_ENTITY] >= 0 && g[GD_ENTITY] < n && g[GD_OTHER] >= -1 && g[GD_OTHER] < n)) {
            PyErr_SetString(PyExc_ValueError, "cruise: a guard names road users that are not there");
            return NULL;
        }
        if (!(g[GD_QUANTITY] >= 0 && g[GD_QUANTITY] < GQ_COUNT && g[GD_RULE] >= RULE_GT && g[GD_RULE] <= RULE_NE)) {
            PyErr_SetString(PyExc_ValueError, "cruise: a guard compares a quantity or by a rule the core does not know");
            return NULL;
        }
    }
    for (Py_ssize_t k = 0; k < n_keeps; k++) {
        const double *kp = keeps0 + k * KP_COLS;
        double a = kp[KP_ENTITY], b = kp[KP_REF];
        if (!(a >= 0 && a < n && b >= 0 && b < n && a != b)) {
            PyErr_SetString(PyExc_ValueError, "cruise: a keep names road users that are not there");
            return NULL;
        }
        const double *e = st0 + (Py_ssize_t)a * CR_COLS, *r = st0 + (Py_ssize_t)b * CR_COLS;
        int spring = kp[KP_SPRING] != 0.0 || kp[KP_FOLLOW] != 0.0;
        if ((spring ? !(e[CR_MODE] >= MODE_STRAIGHT && e[CR_MODE] <= MODE_PATH)
                    : (e[CR_MODE] != MODE_LANE || e[CR_LATERAL] != 0.0)) ||
            e[CR_PROFILE] >= 0 || r[CR_MODE] < 0 ||
            (kp[KP_ALONG_ROAD] != 0.0 && (r[CR_MODE] != MODE_LANE || e[CR_MODE] != MODE_LANE))) {
            PyErr_SetString(PyExc_ValueError, "cruise: a keep's road user keeps its lane (placed) or moves at its "
                                              "speed (a spring), at no speed of its own, and its reference is there "
                                              "(on its lane, for a gap along the road)");
            return NULL;
        }
    }
    for (Py_ssize_t k = 0; k < n_sync; k++) {
        double a = sy0[k * SY_COLS + SY_ENTITY], b = sy0[k * SY_COLS + SY_MASTER];
        if (!(a >= 0 && a < n && b >= 0 && b < n && a != b)) {
            PyErr_SetString(PyExc_ValueError, "cruise: a sync names road users that are not there");
            return NULL;
        }
        if (!program_fits(programs, n_programs, sy0[k * SY_COLS + SY_PROGRAM]) ||
            !program_fits(programs, n_programs, sy0[k * SY_COLS + SY_MASTER_PROGRAM])) {
            PyErr_SetString(PyExc_ValueError, "cruise: a sync's road program runs past the programs given");
            return NULL;
        }
    }
    size_t m = (size_t)(n > 0 ? n : 1);
    for (Py_ssize_t k = 0; k < n_accs; k++) {
        double a = accs0[k * AC_COLS + AC_ENTITY];
        const double *e = st0 + (Py_ssize_t)(a >= 0 && a < n ? a : 0) * CR_COLS;
        int taken = 0;
        for (Py_ssize_t q = 0; q < n_keeps; q++) taken |= keeps0[q * KP_COLS + KP_ENTITY] == a;
        for (Py_ssize_t q = 0; q < n_sync; q++) taken |= sy0[q * SY_COLS + SY_ENTITY] == a;
        for (Py_ssize_t q = 0; q < k; q++) taken |= accs0[q * AC_COLS + AC_ENTITY] == a;
        if (!(a >= 0 && a < n && a == floor(a)) || e[CR_MODE] != MODE_LANE || e[CR_PROFILE] >= 0 || taken) {
            PyErr_SetString(PyExc_ValueError, "cruise: an adaptive cruise's road user is there, keeps its lane, and no "
                                              "transition, keep, synchronisation or other cruise sets its speed");
            return NULL;
        }
    }
    size_t keep_bytes = sizeof(double) * KP_COLS * (size_t)n_keeps, acc_bytes = sizeof(double) * AC_COLS * (size_t)n_accs;
    double *cur = PyMem_Malloc(sizeof(double) * (CR_COLS * m * 3 + SY_COLS * (size_t)(n_sync + 1) * 2 +
                                                 KP_COLS * (size_t)(n_keeps + 1) * 2 + m + AC_COLS * (size_t)(n_accs + 1) * 2));
    Py_ssize_t *acc_of = PyMem_Malloc(sizeof(Py_ssize_t) * m); /* each road user's cruise (-1: none) */
    char *moved = PyMem_Malloc(m); /* which road users have moved in the step under way */
    VeiBox *box = PyMem_Malloc(sizeof(VeiBox) * m);
    int *pairs = PyMem_Malloc(sizeof(int) * m * m * 2);
    int *first = PyMem_Malloc(sizeof(int) * (size_t)(n_guards + 1)); /* what each guard says at the start */
    PyObject *poses = PyBytes_FromStringAndSize(NULL, (Py_ssize_t)(sizeof(double) * 6 * m * (size_t)n_max));
    if (!cur || !acc_of || !moved || !box || !pairs || !first || !poses) {
        PyMem_Free(cur), PyMem_Free(acc_of), PyMem_Free(moved), PyMem_Free(box), PyMem_Free(pairs), PyMem_Free(first);
        Py_XDECREF(poses);
        return PyErr_NoMemory();
    }
    double *next = cur + CR_COLS * m, *out = (double *)PyBytes_AS_STRING(poses);
    double *placed = next + CR_COLS * m, *sync = placed + CR_COLS * m, *sync_next = sync + SY_COLS * (size_t)(n_sync + 1);
    double *keeps = sync_next + SY_COLS * (size_t)(n_sync + 1), *keeps_next = keeps + KP_COLS * (size_t)(n_keeps + 1);
    double *speed_now = keeps_next + KP_COLS * (size_t)(n_keeps + 1); /* (the speeds as the keeps set them) */
    double *accs = speed_now + m, *accs_next = accs + AC_COLS * (size_t)(n_accs + 1);
    memcpy(keeps, keeps0, keep_bytes);
    memcpy(accs, accs0, acc_bytes);
    for (Py_ssize_t i = 0; i < n; i++) acc_of[i] = -1;
    for (Py_ssize_t k = 0; k < n_accs; k++) acc_of[(Py_ssize_t)accs0[k * AC_COLS + AC_ENTITY]] = k;
    size_t sync_bytes = sizeof(double) * SY_COLS * (size_t)n_sync;
    int *pairs0 = pairs, *pairs1 = pairs + m * m;
    memcpy(cur, st0, sizeof(double) * CR_COLS * (size_t)n);
    memcpy(sync, sy0, sync_bytes);
    Py_ssize_t k0, k1;
    cruise_pairs(cur, n, box, pairs0, &k0);
    for (Py_ssize_t k = 0; k < n_guards; k++) first[k] = guard_state(guards + k * GD_COLS, cur);
    long done = 0;
    int edge = 0; /* (whether the step it stops before is refused for a standstill's edge) */
    for (; done < n_max; done++) {
        int quiet = 1;
        edge = 0;
        /* pre: where the road users start their moves, the keeps' road users placed at their gaps first */
        double *pre = cur;
        if (n_keeps) {
            memcpy(placed, cur, sizeof(double) * CR_COLS * (size_t)n);
            memcpy(keeps_next, keeps, keep_bytes);
            pre = placed;
            for (Py_ssize_t i = 0; i < n; i++) speed_now[i] = cur[i * CR_COLS + CR_SPEED];
            /* in the interpreter's order: each one sees the speeds the ones before it set (a continuous relative
             * speed takes its reference's at the step's start, and its own only when everyone moves) */
            for (Py_ssize_t k = 0; k < n_keeps && quiet; k++) {
                double *kp = keeps_next + k * KP_COLS, ref_speed = speed_now[(Py_ssize_t)kp[KP_REF]];
                if (kp[KP_FOLLOW] != 0.0) continue;
                if (kp[KP_SPRING] != 0.0)
                    speed_now[(Py_ssize_t)kp[KP_ENTITY]] = keep_spring(kp, pre, ref_speed, dt);
                else {
                    quiet = keep_place(kp, ways, pre, ref_speed);
                    speed_now[(Py_ssize_t)kp[KP_ENTITY]] = ref_speed;
                }
            }
        }
        memcpy(next, pre, sizeof(double) * CR_COLS * (size_t)n);
        memcpy(sync_next, sync, sync_bytes);
        memcpy(accs_next, accs, acc_bytes);
        for (Py_ssize_t k = 0; k < n_keeps; k++) {
            const double *kp = keeps_next + k * KP_COLS;
            double v = speed_now[(Py_ssize_t)kp[KP_ENTITY]];
            if (kp[KP_FOLLOW] != 0.0) {
                double v0 = pre[(Py_ssize_t)kp[KP_ENTITY] * CR_COLS + CR_SPEED], acc;
                v = pre[(Py_ssize_t)kp[KP_REF] * CR_COLS + CR_SPEED];
                v = kp[KP_BY_FACTOR] != 0.0 ? v * kp[KP_VALUE] : v + kp[KP_VALUE];
                if (fabs(v) > kp[KP_MAX_SPEED]) v = copysign(kp[KP_MAX_SPEED], v);
                /* towards it within the Performance's limits (Entity.tracked_speed) */
                acc = (v - v0) / dt;
                if (acc > kp[KP_MAX_ACCEL])
                    v = v0 + kp[KP_MAX_ACCEL] * dt;
                else if (acc < -kp[KP_MAX_DECEL])
                    v = v0 - kp[KP_MAX_DECEL] * dt;
            }
            next[(Py_ssize_t)kp[KP_ENTITY] * CR_COLS + CR_SPEED] = v;
        }
        for (Py_ssize_t k = 0; k < n_sync && quiet; k++) quiet = sync_step(sync_next + k * SY_COLS, programs, pre, next, dt);
        for (Py_ssize_t i = 0; i < n && quiet; i++)
            if (pre[i * CR_COLS + CR_PROFILE] >= 0)
                quiet = profile_speed(pre + i * CR_COLS, times[done], times[done] + dt, &next[i * CR_COLS + CR_SPEED]);
        /* (in the interpreter's order, a cruise in override mode after everyone else: a cruise sees those that
         * moved before it after their moves) */
        memset(moved, 0, (size_t)n);
        for (int pass = 0; pass < 2 && quiet; pass++)
            for (Py_ssize_t i = 0; i < n && quiet; i++) {
                double *ac = acc_of[i] >= 0 ? accs_next + acc_of[i] * AC_COLS : NULL;
                if ((ac != NULL && ac[AC_LAST] != 0.0) != (pass == 1)) continue;
                if (ac != NULL) quiet = acc_step(ac, ways, pre, next, moved, n, dt);
                if (quiet) {
                    quiet = cruise_move(PyTuple_GET_ITEM(ways, i), pre + i * CR_COLS, times[done], max_turn, dt, next + i * CR_COLS);
                    if (quiet == STANDSTILL_EDGE) quiet = 0, edge = 1;
                }
                moved[i] = 1;
            }
        for (double chain = 1; chain <= max_chain && quiet; chain++) /* (trailers front to back) */
            for (Py_ssize_t i = 0; i < n && quiet; i++) {
                double *e = pre + i * CR_COLS;
                if (e[CR_MODE] == MODE_TOWED && e[CR_CHAIN] == chain)
                    quiet = towed_move(e, next + (Py_ssize_t)e[CR_TOW] * CR_COLS, dt, max_turn, next + i * CR_COLS);
            }
        for (Py_ssize_t k = 0; k < n_keeps && quiet; k++) { /* (placed and moved: within the step's bounds) */
            if (keeps[k * KP_COLS + KP_SPRING] != 0.0 || keeps[k * KP_COLS + KP_FOLLOW] != 0.0) continue;
            Py_ssize_t i = (Py_ssize_t)keeps[k * KP_COLS + KP_ENTITY] * CR_COLS;
            quiet = within_bounds(cur + i, next + i, max_turn) && fabs(next[i + CR_S] - cur[i + CR_S]) <= cur[i + CR_MAX_DS];
        }
        if (!quiet) break;
        /* (the odometers first: a guard may compare one) */
        double *row = out + (size_t)done * 6 * (size_t)n;
        for (Py_ssize_t i = 0; i < n; i++) {
            double *e = pre + i * CR_COLS, *f = next + i * CR_COLS, moved = 0.0;
            if (e[CR_MODE] >= 0) {
                moved = vei_hypot(f[CR_X] - e[CR_X], f[CR_Y] - e[CR_Y]);
                f[CR_ODOMETER] = e[CR_ODOMETER] + moved;
                f[CR_LAST_MOVED] = moved;
            }
            row[6 * i] = f[CR_X], row[6 * i + 1] = f[CR_Y], row[6 * i + 2] = f[CR_YAW], row[6 * i + 3] = moved;
            row[6 * i + 4] = f[CR_SPEED], row[6 * i + 5] = f[CR_ACCEL];
        }
        for (Py_ssize_t k = 0; k < n_guards && quiet; k++)
            quiet = first[k] != 0 && guard_state(guards + k * GD_COLS, next) == first[k];
        if (!quiet) break;
        cruise_pairs(next, n, box, pairs1, &k1);
        if (k1 != k0 || memcmp(pairs0, pairs1, sizeof(int) * (size_t)k0) != 0) break;
        memcpy(cur, next, sizeof(double) * CR_COLS * (size_t)n);
        memcpy(sync, sync_next, sync_bytes);
        memcpy(keeps, keeps_next, keep_bytes);
        memcpy(accs, accs_next, acc_bytes);
    }
    PyObject *result = NULL;
    if (_PyBytes_Resize(&poses, (Py_ssize_t)(sizeof(double) * 6 * (size_t)n * (size_t)done)) == 0)
        result = Py_BuildValue("(lNy#y#y#y#i)", done, poses, (const char *)cur, (Py_ssize_t)(sizeof(double) * CR_COLS * n),
                               (const char *)sync, (Py_ssize_t)sync_bytes, (const char *)keeps, (Py_ssize_t)keep_bytes,
                               (const char *)accs, (Py_ssize_t)acc_bytes, edge);
    PyMem_Free(cur), PyMem_Free(acc_of), PyMem_Free(moved), PyMem_Free(box), PyMem_Free(pairs), PyMem_Free(first);
    return result;
}

/* sync_speed(columns, dist, master_dist, v, master_speed, master_moved, dt) -> speed or None: sync_speed
 * for the interpreter's own steps; columns: a writable buffer of the synchronisation's SY_COLS doubles
 * (array('d')), updated in place; None when the action ends in this step */
static PyObject *sync_speed_(PyObject *mod, PyObject *const *args, Py_ssize_t nargs)
{
    if (!args_ok(nargs, 7, "sync_speed")) return NULL;
    ARG_D(1, dist);
    ARG_D(2, master_dist);
    ARG_D(3, v);
    ARG_D(4, master_speed);
    int master_moved = PyObject_IsTrue(args[5]);
    if (master_moved < 0) return NULL;
    ARG_D(6, dt);
    Py_buffer buf;
    if (PyObject_GetBuffer(args[0], &buf, PyBUF_WRITABLE | PyBUF_FORMAT) < 0) return NULL;
    PyObject *result = NULL;
    if (buf.len != (Py_ssize_t)sizeof(double) * SY_COLS || !buf.format || strcmp(buf.format, "d") != 0)
        PyErr_SetString(PyExc_TypeError, "sync_speed: the synchronisation's columns as array('d') of its row");
    else {
        double out;
        result = sync_speed((double *)buf.buf, dist, master_dist, v, master_speed, master_moved, dt, &out)
                     ? PyFloat_FromDouble(out)
                     : Py_NewRef(Py_None);
    }
    PyBuffer_Release(&buf);
    return result;
}

/* transition_fraction(shape, x): shape_fraction for the interpreter's own steps (a SpeedAction's
 * transition, a lane change's or lane offset's); shape: a SHAPE_* code, any other linear */
static PyObject *transition_fraction(PyObject *mod, PyObject *const *args, Py_ssize_t nargs)
{
    if (!args_ok(nargs, 2, "transition_fraction")) return NULL;
    ARG_D(0, shape);
    ARG_D(1, x);
    return PyFloat_FromDouble(shape_fraction(shape, x));
}

/* lane_change_turn(shape, by_time, delta, value, x, dt, ds) -> a lane change's heading in a step (lane_change_turn) */
static PyObject *lane_change_turn_(PyObject *mod, PyObject *const *args, Py_ssize_t nargs)
{
    if (!args_ok(nargs, 7, "lane_change_turn")) return NULL;
    ARG_D(0, shape);
    int by_time = PyObject_IsTrue(args[1]);
    if (by_time < 0) return NULL;
    ARG_D(2, delta);
    ARG_D(3, value);
    ARG_D(4, x);
    ARG_D(5, dt);
    ARG_D(6, ds);
    return PyFloat_FromDouble(lane_change_turn(shape, by_time, delta, value, x, dt, ds));
}

/* box_distance(box_a, box_b) -> the shortest distance between two boxes (0 where they touch): box_gap, for
 * the interpreter's conditions (the one the core's guards measure) */
static PyObject *box_distance_(PyObject *mod, PyObject *const *args, Py_ssize_t nargs)
{
    VeiBox a, b;
    if (!args_ok(nargs, 2, "box_distance") || box_of(args[0], &a) < 0 || box_of(args[1], &b) < 0) return NULL;
    return PyFloat_FromDouble(box_gap(&a, &b));
}

/* transition_speed(v0, v1, t0, duration, shape, t) -> (speed, over): a SpeedAction's transition at t
 * for the interpreter's own steps; shape: a SHAPE_* code, any other linear */
static PyObject *transition_speed_(PyObject *mod, PyObject *const *args, Py_ssize_t nargs)
{
    double a[6], v;
    if (!args_doubles(args, nargs, 6, "transition_speed", a)) return NULL;
    int over = transition_speed(a[0], a[1], a[2], a[3], a[4], a[5], &v);
    return Py_BuildValue("(dO)", v, over ? Py_True : Py_False);
}

/* towed_pose(tow_x, tow_y, tow_yaw, hitch, coupler, x, y, yaw) -> (x, y, yaw): a trailer pulled by the
 * interpreter's own steps */
static PyObject *towed_pose_(PyObject *mod, PyObject *const *args, Py_ssize_t nargs)
{
    double a[8], out[3];
    if (!args_doubles(args, nargs, 8, "towed_pose", a)) return NULL;
    towed_pose(a[0], a[1], a[2], a[3], a[4], a[5], a[6], a[7], out);
    return xyh(out[0], out[1], out[2]);
}

/* spring_step(error, speed, ref_speed, max_accel, max_decel, accel_rate, decel_rate, last, max_speed, dt) ->
 * (acceleration, speed): LongitudinalDistance's spring for the interpreter's own steps */
static PyObject *spring_step_(PyObject *mod, PyObject *const *args, Py_ssize_t nargs)
{
    double a[10], v;
    if (!args_doubles(args, nargs, 10, "spring_step", a)) return NULL;
    double acc = spring_step(a[0], a[1], a[2], a[3], a[4], a[5], a[6], a[7], a[8], a[9], &v);
    return Py_BuildValue("(dd)", acc, v);
}

/* hypot(x, y): vei_hypot, for the interpreter's own steps: a step's metres are the same function of its
 * move whether the core or the interpreter takes the step */
static PyObject *hypot_(PyObject *mod, PyObject *const *args, Py_ssize_t nargs)
{
    if (!args_ok(nargs, 2, "hypot")) return NULL;
    ARG_D(0, x);
    ARG_D(1, y);
    return PyFloat_FromDouble(vei_hypot(x, y));
}

/* the most fine samples a clothoid takes (the caller refuses longer ones with a message of its own) */
#define CLOTHOID_MAX_SAMPLES 40000000L

/* clothoid(x0, y0, h0, curvature, rate, length, fine, keep) -> (xs, ys, hs): vei_clothoid_sample's
 * kept points as three bytes objects of doubles (the interpreter's polyline vertices, read as arrays:
 * a trajectory of thousands of points is never a list of Python floats) */
static PyObject *clothoid(PyObject *mod, PyObject *const *args, Py_ssize_t nargs)
{
    if (!args_ok(nargs, 8, "clothoid")) return NULL;
    ARG_D(0, x0);
    ARG_D(1, y0);
    ARG_D(2, h0);
    ARG_D(3, curvature);
    ARG_D(4, rate);
    ARG_D(5, length);
    ARG_D(6, fine);
    ARG_I(7, keep);
    if (!(isfinite(x0) && isfinite(y0) && isfinite(h0) && isfinite(curvature) && isfinite(rate)) ||
        !(length > 0.0 && fine > 0.0 && length / fine <= (double)CLOTHOID_MAX_SAMPLES) || keep < 1) {
        PyErr_SetString(PyExc_ValueError, "clothoid: finite start and curvatures, 0 < length <= fine * 4e7, keep >= 1");
        return NULL;
    }
    long n_fine, n = vei_clothoid_samples(length, fine, keep, &n_fine);
    Py_ssize_t bytes = (Py_ssize_t)n * (Py_ssize_t)sizeof(double);
    PyObject *xs = PyBytes_FromStringAndSize(NULL, bytes), *ys = PyBytes_FromStringAndSize(NULL, bytes),
             *hs = PyBytes_FromStringAndSize(NULL, bytes);
    if (!xs || !ys || !hs) {
        Py_XDECREF(xs), Py_XDECREF(ys), Py_XDECREF(hs);
        return NULL;
    }
    vei_clothoid_sample(x0, y0, h0, curvature, rate, length, n_fine, keep, (double *)PyBytes_AS_STRING(xs),
                        (double *)PyBytes_AS_STRING(ys), (double *)PyBytes_AS_STRING(hs));
    return Py_BuildValue("(NNN)", xs, ys, hs);
}

#define F(name, doc) {#name, (PyCFunction)(void (*)(void))name, METH_FASTCALL, doc}

/* an entity's x, y, yaw, center_x, length and width (interpreter.entities.Entity) into v; 0 with the error set */
static int entity_values(PyObject *entity, double *v)
{
    static const char *names[] = {"x", "y", "yaw", "center_x", "length", "width"};
    for (int k = 0; k < 6; k++) {
        PyObject *a = PyObject_GetAttrString(entity, names[k]);
        v[k] = a ? PyFloat_AsDouble(a) : -1.0;
        Py_XDECREF(a);
        if (v[k] == -1.0 && PyErr_Occurred()) return 0;
    }
    return 1;
}

/* entity_boxes(entities) -> bytes: the bounding box (centre x, centre y, yaw, length, width) of each
 * object with x, y, yaw, center_x (reference point to box centre, along the heading), length, width:
 * Entity.box() of the interpreter for a whole list in one call (the collision check's) */
static PyObject *entity_boxes(PyObject *mod, PyObject *seq)
{
    PyObject *fast = PySequence_Fast(seq, "entity_boxes takes a sequence of entities");
    if (!fast) return NULL;
    Py_ssize_t n = PySequence_Fast_GET_SIZE(fast);
    PyObject *out = PyBytes_FromStringAndSize(NULL, n * (Py_ssize_t)sizeof(VeiBox));
    if (!out) {
        Py_DECREF(fast);
        return NULL;
    }
    VeiBox *b = (VeiBox *)PyBytes_AS_STRING(out);
    for (Py_ssize_t i = 0; i < n; i++) {
        double v[6];
        if (!entity_values(PySequence_Fast_GET_ITEM(fast, i), v)) {
            Py_DECREF(out);
            Py_DECREF(fast);
            return NULL;
        }
        b[i] = entity_box(v[0], v[1], v[2], v[3], v[4], v[5]);
    }
    Py_DECREF(fast);
    return out;
}

/* heading_gap(a, b, freespace) -> the signed distance from entity a to entity b along a's heading
 * (between their boxes with freespace), for the interpreter's own steps */
static PyObject *heading_gap_(PyObject *mod, PyObject *const *args, Py_ssize_t nargs)
{
    double a[6], b[6];
    if (!args_ok(nargs, 3, "heading_gap") || !entity_values(args[0], a) || !entity_values(args[1], b)) return NULL;
    int freespace = PyObject_IsTrue(args[2]);
    if (freespace < 0) return NULL;
    VeiBox ba = entity_box(a[0], a[1], a[2], a[3], a[4], a[5]), bb = entity_box(b[0], b[1], b[2], b[3], b[4], b[5]);
    return PyFloat_FromDouble(heading_gap(a[0], a[1], a[2], &ba, b[0], b[1], &bb, freespace));
}

static PyMethodDef module_methods[] = {
    {"entity_boxes", entity_boxes, METH_O, "entity_boxes(entities) -> the boxes as bytes for overlapping()"},
    F(sfm_step, "sfm_step(x, y, vx, vy, waypoint, route_x, route_y, params, repulsive, ego_box, dt) -> state"),
    F(cap_step, "cap_step(brake, integral, prev_error, params, cruise, v, ttc, resume_ttc, dt) -> (state, a, d_safe)"),
    F(longitudinal_step, "longitudinal_step(s, v, a, a_cmd, max_accel, max_decel, jerk_max, dt) -> (s, v, a)"),
    F(acc_speed, "acc_speed(params, v, set_speed, lead, gap, v_lead, max_accel, max_decel, dt) -> the adaptive cruise's speed"),
    F(acc_lookahead, "acc_lookahead(params, v, max_decel) -> how far ahead the adaptive cruise looks for a leader"),
    F(bumper_gap, "bumper_gap(ds, own_length, own_center_x, other_length, other_center_x, same_way) -> m"),
    F(box_gaps, "box_gaps(own_box, other_box) -> (along, across) gaps between two boxes in the first's frame"),
    F(close_ahead, "close_ahead(x_gap, y_gap, other_length, closing) -> whether a box just ahead is followed"),
    F(time_to_conflict, "time_to_conflict(ego_box, ego_speed, margin, threat_box, vx, vy[, horizon]) -> s"),
    F(time_to_contact, "time_to_contact(box_a, vxa, vya, box_b, vxb, vyb) -> s"),
    {"overlapping", overlapping, METH_O, "overlapping(boxes) -> pairs (i, j) of overlapping boxes"},
    F(cruise, "cruise(ways, state, syncs, keeps, accs, programs, guards, times, max_turn, dt) -> (n, poses, state, syncs, keeps, accs, edge): quiet steps in one call"),
    F(transition_fraction, "transition_fraction(shape, x) -> how far a transition of SHAPES code shape has come at x"),
    {"lane_change_turn", (PyCFunction)(void (*)(void))lane_change_turn_, METH_FASTCALL,
     "lane_change_turn(shape, by_time, delta, value, x, dt, ds) -> a lane change's heading from its lane in a step"},
    {"transition_speed", (PyCFunction)(void (*)(void))transition_speed_, METH_FASTCALL,
     "transition_speed(v0, v1, t0, duration, shape, t) -> (speed, over): a SpeedAction's transition at t"},
    {"towed_pose", (PyCFunction)(void (*)(void))towed_pose_, METH_FASTCALL,
     "towed_pose(tow_x, tow_y, tow_yaw, hitch, coupler, x, y, yaw) -> (x, y, yaw) of a trailer pulled along"},
    {"box_distance", (PyCFunction)(void (*)(void))box_distance_, METH_FASTCALL,
     "box_distance(box_a, box_b) -> the shortest distance between two boxes (x, y, yaw, length, width), 0 where they touch"},
    {"heading_gap", (PyCFunction)(void (*)(void))heading_gap_, METH_FASTCALL,
     "heading_gap(a, b, freespace) -> the signed distance from entity a to b along a's heading"},
    {"spring_step", (PyCFunction)(void (*)(void))spring_step_, METH_FASTCALL,
     "spring_step(error, speed, ref_speed, max_accel, max_decel, accel_rate, decel_rate, last, max_speed, dt) -> (accel, speed)"},
    {"sync_speed", (PyCFunction)(void (*)(void))sync_speed_, METH_FASTCALL,
     "sync_speed(columns, dist, master_dist, v, master_speed, master_moved, dt) -> the synchronised speed or None"},
    {"hypot", (PyCFunction)(void (*)(void))hypot_, METH_FASTCALL, "hypot(x, y) -> the length of (x, y) as the core measures a step (the odometer's metres in every engine)"},
    F(clothoid, "clothoid(x0, y0, h0, curvature, rate, length, fine, keep) -> (xs, ys, hs): a clothoid's points (bytes of doubles)"),
    {"set_quadrature", set_quadrature, METH_VARARGS, "set_quadrature(nodes, weights): 24 doubles each"},
    {NULL, NULL, 0, NULL},
};

static struct PyModuleDef core_module = {PyModuleDef_HEAD_INIT, "_core", "vei-scenario's compiled core.", -1,
                                         module_methods};

/* the names of a table's columns, in order (NULL-terminated), as a tuple of str */
static PyObject *names_tuple(const char *const *names)
{
    Py_ssize_t n = 0;
    while (names[n]) n++;
    PyObject *t = PyTuple_New(n);
    for (Py_ssize_t i = 0; t && i < n; i++) {
        PyObject *name = PyUnicode_FromString(names[i]);
        if (!name) {
            Py_CLEAR(t);
            break;
        }
        PyTuple_SET_ITEM(t, i, name);
    }
    return t;
}

PyMODINIT_FUNC PyInit__core(void)
{
    if (PyType_Ready(&RoadType) < 0 || PyType_Ready(&PolylineType) < 0 || PyType_Ready(&RiderType) < 0) return NULL;
    PyObject *m = PyModule_Create(&core_module);
    if (!m) return NULL;
    Py_INCREF(&RoadType);
    Py_INCREF(&PolylineType);
    Py_INCREF(&RiderType);
    static const char *const road_user[] = {ROAD_USER_COLUMNS(COLUMN_NAME) NULL};
    static const char *const sync[] = {SYNC_COLUMNS(COLUMN_NAME) NULL};
    static const char *const guard[] = {GUARD_COLUMNS(COLUMN_NAME) NULL}, *const keep[] = {KEEP_COLUMNS(COLUMN_NAME) NULL};
    static const char *const acc[] = {ACC_COLUMNS(COLUMN_NAME) NULL};
    static const char *const quantity[] = {GUARD_QUANTITIES(COLUMN_NAME) NULL};
    static const char *const mode[] = {MODES(COLUMN_NAME) NULL}, *const shape[] = {SHAPES(COLUMN_NAME) NULL};
    static const char *const rule[] = {RULES(COLUMN_NAME) NULL};
    static const char *const sync_mode[] = {SYNC_MODES(COLUMN_NAME) NULL};
    PyObject *layout = Py_BuildValue("{s:N,s:N,s:N,s:N,s:N,s:N,s:N,s:N,s:N,s:N}", "road_user", names_tuple(road_user),
                                     "sync", names_tuple(sync), "keep", names_tuple(keep), "acc", names_tuple(acc),
                                     "guard", names_tuple(guard),
                                     "guard_quantity", names_tuple(quantity), "mode", names_tuple(mode), "shape",
                                     names_tuple(shape), "rule", names_tuple(rule), "sync_mode", names_tuple(sync_mode));
    if (!layout || PyModule_AddObject(m, "CRUISE_LAYOUT", layout) < 0 ||
        PyModule_AddObject(m, "Road", (PyObject *)&RoadType) < 0 ||
        PyModule_AddObject(m, "Polyline", (PyObject *)&PolylineType) < 0 ||
        PyModule_AddObject(m, "Rider", (PyObject *)&RiderType) < 0) {
        Py_XDECREF(layout);
        Py_DECREF(m);
        return NULL;
    }
    return m;
}
