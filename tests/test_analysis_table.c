/* The table of analyses (gd_analysis.h) agrees with the case schema: every value scene.analysis
 * accepts has exactly one row, under the same name, in the order of the gd_analysis values; and a
 * case is resolved through its row (an analysis's own checks run only for that analysis). */
#include "geardyn/gd_analysis.h"
#include "tap.h"

#include <string.h>

int main(void)
{
    size_t n = 0;
    const gd_analysis_type *rows = gd_analysis_types(&n);
    const gd_keyspec *k = gd_case_find_key("scene", "analysis");
    tap_ok(k && k->type == GD_KEY_ENUM, "scene.analysis is an enum key");
    /* the schema's names, '|'-separated, index = gd_analysis value */
    char names[512];
    snprintf(names, sizeof names, "%s", k ? k->choices : "");
    size_t nschema = 0;
    for (char *save = NULL, *tok = strtok_r(names, "|", &save); tok; tok = strtok_r(NULL, "|", &save), nschema++) {
        const gd_analysis_type *a = gd_analysis_find((int)nschema);
        tap_ok(a && strcmp(a->name, tok) == 0, "schema value %zu '%s' has the row '%s'", nschema, tok,
               a ? a->name : "(none)");
        tap_ok(nschema < n && rows[nschema].id == (int)nschema, "row %zu is gd_analysis %zu", nschema, nschema);
    }
    tap_ok(nschema == n, "%zu schema values, %zu rows", nschema, n);
    tap_ok(gd_analysis_find(-1) == NULL && gd_analysis_find((int)n) == NULL, "no row outside the table");

    /* a zero torque is refused by the ltca row only: response resolves, ltca does not */
    gd_case c;
    gd_error err = { 0 };
    gd_status st = gd_case_init(&c, &err);
    if (st == GD_OK)
        st = gd_case_set(&c, "operating.torque_nm=0", 0, &err);
    c.speed_rpm = 4000; /* the paper's speed: a case must give one */
    tap_ok(st == GD_OK, "case with torque_nm = 0: %s", err.msg);
    gd_case r = c;
    st = gd_case_copy(&r, &c, &err);
    tap_ok(st == GD_OK && gd_case_resolve(&r, &err) == GD_OK, "response resolves at zero torque: %s", err.msg);
    gd_case_free(&r);
    gd_error_clear(&err);
    st = gd_case_set(&c, "scene.analysis=ltca", 1, &err);
    gd_status sr = st == GD_OK ? gd_case_resolve(&c, &err) : st;
    tap_ok(sr == GD_ERR_INPUT && strstr(err.msg, "--set #1: operating.torque_nm") && strstr(err.msg, "for LTCA"),
           "ltca's row refuses it, naming the key: %s", err.msg);
    gd_case_free(&c);
    return tap_done();
}
