/* The collision-avoidance planner FMU: state kept between steps. */
#include "vei_cap_variables.h"
#include "vei_models.h"

typedef struct {
    VeiCapState state;
} ModelState;
