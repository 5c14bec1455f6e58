/* The command line's lines of what an optimisation over load and speed reports after it
 * (gd_optpost.h, docs/optimisation.md section 12): the three flanks on bta beside the loop's model,
 * whether they rank the same, and the least LTE amplitude of each flank on the Harris map. */
#include "cli.h"

#include "geardyn/gd_optpost.h"

#include <stdio.h>

static const char *const flank_words[GD_OPTPOST_NFLANKS] = {"unmodified", "the case's", "optimum"};

static void ranking(const int *rank, char *buf, size_t n)
{
    size_t at = 0;
    buf[0] = '\0';
    for (int r = 0; r < GD_OPTPOST_NFLANKS; r++)
        for (int j = 0; j < GD_OPTPOST_NFLANKS; j++)
            if (rank[j] == r && at < n)
                at += (size_t)snprintf(buf + at, n - at, "%s%s", r ? " < " : "", flank_words[j]);
}

void cli_optpost_report(const gd_case *c, const gd_optimize_outcome *o)
{
    const gd_optpost *p = o->post;
    if (!p)
        return;
    if (p->dynamic) {
        const char *unit = c->opt_dynamic_response == GD_DYN_DTE_PP ? "um" : "m/s^2";
        char rl[128], rb[128];
        ranking(p->rank_loop, rl, sizeof rl);
        ranking(p->rank_bta, rb, sizeof rb);
        printf("  on bta (%s): unmodified %.6g, the case's modification %.6g, optimum %.6g (%+.1f %% against the "
               "unmodified pair; %.1f s of CPU for the three flanks)\n", unit, p->on_bta[0].value, p->on_bta[1].value,
               p->on_bta[2].value, 100 * (p->on_bta[2].value - p->on_bta[0].value) / p->on_bta[0].value,
               p->bta_cpu_s);
        for (int k = 0; k < p->on_bta[0].ntorques; k++)
            printf("    at %g N m: unmodified %.6g, the case's %.6g, optimum %.6g (its largest at %.0f rpm)\n",
                   p->on_bta[0].curve[k].torque_nm, p->on_bta[0].curve[k].peak, p->on_bta[1].curve[k].peak,
                   p->on_bta[2].curve[k].peak, p->on_bta[2].curve[k].peak_speed_rpm);
        printf("    ranking %s: %s on bta, %s in the loop\n", p->same_ranking ? "the same" : "NOT the same", rb, rl);
    }
    printf("  LTE over torque (%d torques, %g to %g N m), least: ", p->nharris, p->harris_torque_nm[0],
           p->harris_torque_nm[p->nharris - 1]);
    for (int j = 0; j < GD_OPTPOST_NFLANKS; j++) {
        int least = 0;
        for (int i = 1; i < p->nharris; i++)
            if (p->harris_lte_pp_arcsec[j][i] < p->harris_lte_pp_arcsec[j][least])
                least = i;
        printf("%s%s %.4g arcsec at %.4g N m", j ? ", " : "", flank_words[j], p->harris_lte_pp_arcsec[j][least],
               p->harris_torque_nm[least]);
    }
    printf("\n");
}
