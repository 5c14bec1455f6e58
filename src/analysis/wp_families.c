/* The method families of a work-precision study (workprecision.families, each also without root
 * finding when root_finding_off) and the checks of the [workprecision] keys (docs/accuracy.md). */
#include "analysis_internal.h"

#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

static gd_status parse_token(const char *tok, gd_wp_family *f, gd_error *err)
{
    memset(f, 0, sizeof *f);
    f->root_finding = 1;
    if (strcmp(tok, "rk4") == 0) {
        f->method = GD_METHOD_RK4;
        f->order = 4;
        f->fixed = 1;
    } else if (strncmp(tok, "erk", 3) == 0 && isdigit((unsigned char)tok[3]) && tok[4] == '\0') {
        f->method = GD_METHOD_ERK;
        f->order = tok[3] - '0';
        if (f->order < 2 || f->order > 8)
            return gd_error_set(err, GD_ERR_INPUT, "workprecision.families: '%s' (valid orders of erk: 2 to 8)", tok);
    } else if (strncmp(tok, "dirk", 4) == 0 && isdigit((unsigned char)tok[4]) && tok[5] == '\0') {
        f->method = GD_METHOD_DIRK;
        f->order = tok[4] - '0';
        if (f->order < 2 || f->order > 5)
            return gd_error_set(err, GD_ERR_INPUT, "workprecision.families: '%s' (valid orders of dirk: 2 to 5)", tok);
    } else {
        return gd_error_set(err, GD_ERR_INPUT, "workprecision.families: unknown family '%s' (valid: rk4, erk2, erk3, "
                            "erk4, erk5, erk6, erk7, erk8, dirk2, dirk3, dirk4, dirk5)", tok);
    }
    snprintf(f->name, sizeof f->name, "%s", tok);
    return GD_OK;
}

gd_status gd_workprec_families(const gd_case *c, gd_wp_family *fam, int max, int *n, gd_error *err)
{
    *n = 0;
    char buf[sizeof c->wp_families];
    snprintf(buf, sizeof buf, "%s", c->wp_families);
    char *save = NULL;
    for (char *tok = strtok_r(buf, ", \t", &save); tok; tok = strtok_r(NULL, ", \t", &save)) {
        gd_wp_family f;
        gd_status st = parse_token(tok, &f, err);
        if (st != GD_OK)
            return st;
        for (int i = 0; i < *n; i++)
            if (strcmp(fam[i].name, f.name) == 0)
                return gd_error_set(err, GD_ERR_INPUT, "workprecision.families: '%s' given twice", tok);
        int copies = c->wp_root_finding_off ? 2 : 1;
        if (*n + copies > max)
            return gd_error_set(err, GD_ERR_INPUT, "workprecision.families: more than %d families (with root_finding_off "
                                "every family counts twice)", max);
        fam[(*n)++] = f;
        if (c->wp_root_finding_off) {
            f.root_finding = 0;
            snprintf(f.name, sizeof f.name, "%s-noroot", tok);
            fam[(*n)++] = f;
        }
    }
    if (*n == 0)
        return gd_error_set(err, GD_ERR_INPUT, "workprecision.families: empty (valid: a comma-separated list such as "
                            "rk4,erk5,erk8)");
    return GD_OK;
}

gd_status gd_workprec_check_case(const gd_case *c, gd_error *err)
{
    gd_wp_family fam[GD_WP_MAX_FAMILIES];
    int n;
    gd_status st = gd_workprec_families(c, fam, GD_WP_MAX_FAMILIES, &n, err);
    if (st != GD_OK)
        return st;
    if (c->wp_rk4_steps_min > c->wp_rk4_steps_max)
        return gd_error_set(err, GD_ERR_INPUT, "workprecision.rk4_steps_min: %d above rk4_steps_max %d",
                            c->wp_rk4_steps_min, c->wp_rk4_steps_max);
    if (c->wp_order_steps_min > c->wp_order_steps_max)
        return gd_error_set(err, GD_ERR_INPUT, "workprecision.order_steps_min: %d above order_steps_max %d",
                            c->wp_order_steps_min, c->wp_order_steps_max);
    if (c->wp_rtol_tightest > c->wp_rtol_loosest)
        return gd_error_set(err, GD_ERR_INPUT, "workprecision.rtol_tightest: %g above rtol_loosest %g",
                            c->wp_rtol_tightest, c->wp_rtol_loosest);
    if (c->wp_check_order == c->wp_reference_order)
        return gd_error_set(err, GD_ERR_INPUT, "workprecision.check_order: %d, the order of the reference (valid: "
                            "another order, so that the check is an independent method)", c->wp_check_order);
    if (c->wp_horizon_periods > c->record_periods)
        return gd_error_set(err, GD_ERR_INPUT, "workprecision.horizon_periods: %d longer than run.record_periods %d "
                            "(valid: at most the window)", c->wp_horizon_periods, c->record_periods);
    int levels = 0;
    for (long s = c->wp_rk4_steps_min; s <= c->wp_rk4_steps_max; s *= 2)
        levels++;
    int lo = 0;
    for (long s = c->wp_order_steps_min; s <= c->wp_order_steps_max; s *= 2)
        lo++;
    double decades = log10(c->wp_rtol_loosest / c->wp_rtol_tightest);
    int lr = (int)floor(decades * c->wp_rtols_per_decade + 1e-9) + 1;
    if (levels > GD_WP_MAX_LEVELS || lo > GD_WP_MAX_LEVELS || lr > GD_WP_MAX_LEVELS)
        return gd_error_set(err, GD_ERR_INPUT, "workprecision: more than %d settings in one family (fewer rtols per "
                            "decade or a narrower step range)", GD_WP_MAX_LEVELS);
    return GD_OK;
}
