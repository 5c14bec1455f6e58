/* The defaults of gd_solver_opts (gd_sim.h): the [solver] keys' defaults read from the schema and
 * mapped as gd_solver_opts_from_case maps a case's (src/scene/solver_options.c), the rest as that
 * function leaves them. */
#include "geardyn/gd_sim.h"
#include "geardyn/gd_case.h"

#include <string.h>

static double def(const char *key) { return gd_case_find_key("solver", key)->def; }

GD_API gd_solver_opts gd_solver_opts_defaults(void)
{
    gd_solver_opts o;
    memset(&o, 0, sizeof o);
    o.method = (int)def("method");
    o.order = (int)def("order");
    o.rtol = def("rtol");
    o.atol = def("atol");
    o.steps_per_period = (int)def("steps_per_period");
    o.fixed_step = (int)def("fixed_step");
    o.refine_events = 1;
    o.root_finding = (int)def("root_finding");
    o.grazing_watch = (int)def("grazing_watch");
    o.library_vector_ops = (int)def("vector_kernels") == GD_VECTOR_KERNELS_SUNDIALS;
    o.generic_rhs = !(int)def("compiled_rhs");
    o.ungated_roots = !(int)def("gated_roots");
    o.max_step_fraction = def("max_step_fraction");
    o.max_events_per_period = (int)def("max_events_per_period");
    o.max_separated_periods = 1000;
    return o;
}
