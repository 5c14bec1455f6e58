/* Statistics of a run: ARKODE's step counts and geardyn's own counters (RHS, root and
 * Jacobian evaluations, resets, grazing rewinds, events by kind and by clearance). */
#include "sim_internal.h"

#include <string.h>

GD_API void gd_sim_get_stats(const gd_sim *s, gd_sim_stats *st)
{
    memset(st, 0, sizeof *st);
    s->ops->get_num_steps(s->mem, &st->steps);
    s->ops->get_num_step_attempts(s->mem, &st->step_attempts);
    st->root_evals = s->nroot_evals;
    st->rhs_evals = s->nrhs;
    st->extra_rhs_evals = s->extra_rhs;
    st->jac_evals = s->jac_calls;
    if (s->implicit)
        s->ops->get_num_lin_iters(s->mem, &st->lin_iters);
    st->resets = s->resets;
    st->grazing_suspects = s->grazing_suspects;
    st->grazing_rewinds = s->grazing_rewinds;
    st->events = s->events;
    memcpy(st->events_by_kind, s->by_kind, sizeof s->by_kind);
    memcpy(st->events_by_clearance, s->by_clear, sizeof s->by_clear);
}
