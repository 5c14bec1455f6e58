/* The solver options of a case's [solver] section. */
#include "geardyn/gd_scene.h"

#include <stdio.h>
#include <string.h>

GD_API void gd_solver_opts_from_case(const gd_case *c, gd_solver_opts *o)
{
    *o = gd_solver_opts_defaults(); /* what no key sets: refine_events, max_separated_periods */
    o->method = c->method;
    o->order = c->order;
    snprintf(o->table, sizeof o->table, "%s", c->table);
    o->rtol = c->rtol;
    o->atol = c->atol;
    o->steps_per_period = c->steps_per_period;
    o->fixed_step = c->fixed_step;
    o->root_finding = c->root_finding;
    o->grazing_watch = c->grazing_watch;
    o->library_vector_ops = c->vector_kernels == GD_VECTOR_KERNELS_SUNDIALS;
    o->generic_rhs = !c->compiled_rhs;
    o->ungated_roots = !c->gated_roots;
    o->max_step_fraction = c->max_step_fraction;
    o->max_events_per_period = c->max_events_per_period;
}
