/* The ego vehicle FMU: state kept between steps. */
#include "vei_ego_variables.h"
#include "vei_models.h"

typedef struct {
    double path_s[VEI_MAX_PATH];
    VeiPolyline path;
    int on_path; /* projected onto its path (the first step after behaviour_start_s) */
    double s;
} ModelState;
