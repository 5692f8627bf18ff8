/* The e-scooter social force model FMU: state kept between steps. */
#include "vei_sfm_variables.h"
#include "vei_models.h"

typedef struct {
    double track_s[VEI_MAX_PATH];
    VeiPolyline track;
    VeiRider agent;  /* the rider agent's state (vei_models.h: the sweep kernel steps the same one) */
    int rider;       /* 0 replay, 1 normal, 2 aggressive */
    double t_start;  /* when the rider starts: the track's first time + time shift */
    double v_start;  /* speed of the track's first segment */
} ModelState;
