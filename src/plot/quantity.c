/* How a picture names a quantity (quantity.h): the column tables' names and the schema read as a
 * reader's words, symbols and units. */
#include "quantity.h"

#include "geardyn/gd_case.h"
#include "geardyn/gd_optimize.h"

#include <ctype.h>
#include <stdio.h>
#include <string.h>

/* The unit suffixes of the tables' column names (docs: units in the names of keys and columns),
 * longest first where one ends another. */
static const struct {
    const char *suffix, *unit;
} suffixes[] = {
    {"_half_backlash_per_tau", "half backlashes per τ"}, {"_half_backlash", "half backlashes"}, {"_n_per_mm", "N/mm"}, {"_n_per_m", "N/m"}, {"_per_period", "per mesh period"}, {"_per_s", "1/s"},
    {"_mps2", "m/s²"}, {"_mps", "m/s"}, {"_um", "µm"}, {"_mm", "mm"}, {"_hz", "Hz"}, {"_rpm", "rpm"},
    {"_kw", "kW"}, {"_nm", "N m"}, {"_mpa", "MPa"}, {"_gpa", "GPa"}, {"_arcsec", "arcsec"}, {"_deg", "deg"},
    {"_periods", "mesh periods"}, {"_relative", "-"}, {"_kg", "kg"}, {"_s", "s"}, {"_n", "N"},
};

/* The stems of the columns: name for a reader, symbol (enhanced text), and the unit of a stem
 * whose column has no unit suffix ("" when it has one, "-" dimensionless). */
static const struct {
    const char *stem, *name, *sym, *unit;
} stems[] = {
    {"t", "time", "t", ""},
    {"lambda", "mesh deflection", "λ", "µm"},
    {"lambda_dot", "rate of mesh deflection", "dλ/dt", "-"},
    {"accel", "mesh acceleration", "", ""},
    {"rms_accel", "RMS mesh acceleration", "", ""},
    {"dte", "dynamic transmission error", "", "µm"},
    {"force", "mesh force", "F", ""},
    {"lambda_min", "smallest mesh deflection on the orbit", "λ_{min}", ""},
    {"lambda_max", "largest mesh deflection on the orbit", "λ_{max}", ""},
    {"gte", "geometric transmission error", "", ""},
    {"lte", "loaded transmission error", "", ""},
    {"te", "transmission error", "", ""},
    {"phi1", "pinion angle", "φ_1", ""},
    {"stiffness", "mesh stiffness", "k", ""},
    {"line_load", "line load", "", ""},
    {"pressure", "contact pressure", "", ""},
    {"max_pressure", "largest contact pressure", "", ""},
    {"separation", "separation of the flanks", "", ""},
    {"face", "face position", "z", ""},
    {"roll", "roll length", "", ""},
    {"load", "tooth load", "", ""},
    {"share", "load share", "", "-"},
    {"frequency", "frequency", "f", ""},
    {"order", "order of the mesh frequency", "", "-"},
    {"amplitude", "amplitude", "", ""},
    {"mle", "largest Lyapunov exponent", "", "per mesh period"},
    {"dynamic_load_factor", "dynamic load factor", "", "-"},
    {"cpu", "CPU time", "", ""},
    {"err_poincare", "error of the Poincaré points", "", "-"},
    {"err_short_horizon", "error of the trajectory", "", "-"},
    {"err_rms", "error of the RMS acceleration", "", ""},
    {"err_event_times", "error of the event times", "", ""},
    {"err_mle", "error of the largest Lyapunov exponent", "", ""},
    /* the degrees of freedom of the models (model.md section 2) */
    {"y1", "pinion's transverse displacement", "y_1", "µm"},
    {"z1", "pinion's axial displacement", "z_1", "µm"},
    {"y2", "gear's transverse displacement", "y_2", "µm"},
    {"z2", "gear's axial displacement", "z_2", "µm"},
    {"q", "torsional mesh coordinate", "q", "µm"},
};

/* The keys one sweeps or continues: a reader's name and symbol (the unit is the schema's). */
static const struct {
    const char *key, *name, *sym;
} keys[] = {
    {"operating.speed_rpm", "input speed", "n"},
    {"operating.power_kw", "input power", "P"},
    {"operating.torque_nm", "input torque", "T"},
    {"clearance.backlash_um", "backlash", "2b"},
    {"clearance.bearing_clearance_um", "bearing clearance", "2ε"},
    {"damping.mesh_damping_ratio", "mesh damping ratio", "ζ"},
    {"damping.support_damping_ratio", "support damping ratio", "ζ_s"},
    {"damping.shaft_damping_ratio", "shaft damping ratio", ""},
    {"excitation.ste_amplitude_um", "amplitude of the static transmission error", "e_r"},
    {"excitation.ste_mean_um", "mean static transmission error", "e_m"},
    {"excitation.ste_phase_deg", "phase of the static transmission error", "φ"},
    {"excitation.mesh_stiffness_n_per_m", "mean mesh stiffness", "k_m"},
    {"excitation.rectangular_variation", "variation of the mesh stiffness", ""},
    {"excitation.half_phase_deg", "mesh phase of the right half", ""},
    {"gear.helix_angle_deg", "helix angle", "β"},
    {"gear.normal_module_mm", "normal module", "m_n"},
    {"support.radial_stiffness_pinion_n_per_m", "radial bearing stiffness of the pinion", ""},
    {"support.radial_stiffness_gear_n_per_m", "radial bearing stiffness of the gear", ""},
    {"support.axial_stiffness_pinion_n_per_m", "axial support stiffness of the pinion", ""},
    {"support.axial_stiffness_gear_n_per_m", "axial support stiffness of the gear", ""},
};

/* Units of one dimension and their factors to the first. */
static const struct {
    const char *from, *to;
    double factor;
} conversions[] = {
    {"s", "ms", 1e3}, {"s", "µs", 1e6}, {"N/m", "N/µm", 1e-6}, {"N/m", "MN/m", 1e-6}, {"µm", "mm", 1e-3},
    {"mm", "µm", 1e3}, {"N", "kN", 1e-3}, {"m/s", "mm/s", 1e3}, {"kW", "MW", 1e-3},
};

static void copy(char *dst, size_t len, const char *src)
{
    snprintf(dst, len, "%s", src);
}

static int ends_with(const char *s, size_t n, const char *suf)
{
    size_t k = strlen(suf);
    return n >= k && strncmp(s + n - k, suf, k) == 0;
}

/* The schema's unit as a picture writes it. */
static const char *schema_unit(const char *u)
{
    if (!u || !u[0])
        return "-";
    if (strcmp(u, "um") == 0)
        return "µm";
    if (strcmp(u, "kg m^2") == 0)
        return "kg m²";
    if (strcmp(u, "kg/m^3") == 0)
        return "kg/m³";
    return u;
}

const char *gd_half_sub(int half, int halves)
{
    return halves > 1 ? (half ? "R" : "L") : "";
}

const char *gd_half_words(int half, int halves)
{
    return halves > 1 ? (half ? "right half" : "left half") : "";
}

/* sym with the side's subscript: "λ" + L -> "λ_L"; "y_1" + L -> "y_{1L}" */
static void side_symbol(char *out, size_t len, const char *sym, const char *side)
{
    if (!side[0] || !sym[0]) {
        copy(out, len, sym);
        return;
    }
    const char *us = strrchr(sym, '_');
    if (us && us[1] && us[1] != '{' && !strchr(us + 1, '/'))
        snprintf(out, len, "%.*s_{%s%s}", (int)(us - sym), sym, us + 1, side);
    else if (us && us[1] == '{')
        snprintf(out, len, "%.*s_{%.*s,%s}", (int)(us - sym), sym, (int)(strlen(us + 2) - 1), us + 2, side);
    else if (strchr(sym, '/')) /* dλ/dt: the subscript on λ */
        snprintf(out, len, "%.*s_%s%s", (int)(strchr(sym, '/') - sym), sym, side, strchr(sym, '/'));
    else
        snprintf(out, len, "%s_%s", sym, side);
}

int gd_qty_column(const char *column, int halves, gd_qty *q)
{
    memset(q, 0, sizeof *q);
    q->scale = 1;
    char col[96];
    copy(col, sizeof col, column);
    size_t n = strlen(col);
    const char *unit = NULL;
    for (size_t i = 0; i < sizeof suffixes / sizeof suffixes[0] && !unit; i++)
        if (ends_with(col, n, suffixes[i].suffix) && n > strlen(suffixes[i].suffix)) {
            unit = suffixes[i].unit;
            n -= strlen(suffixes[i].suffix);
            col[n] = '\0';
        }
    /* a rate of variable.csv: "NAME_rate" */
    int rate = 0;
    if (ends_with(col, n, "_rate")) {
        rate = 1;
        n -= 5;
        col[n] = '\0';
    }
    /* the side: _L/_R, _left/_right, or a DOF's trailing L/R */
    const char *side = "";
    int half = -1;
    if (ends_with(col, n, "_left") || ends_with(col, n, "_right")) {
        half = ends_with(col, n, "_right");
        n -= half ? 6 : 5;
    } else if (n > 2 && col[n - 2] == '_' && (col[n - 1] == 'L' || col[n - 1] == 'R')) {
        half = col[n - 1] == 'R';
        n -= 2;
    } else if (n >= 2 && (col[n - 1] == 'L' || col[n - 1] == 'R') && islower((unsigned char)col[0]) &&
               (isdigit((unsigned char)col[n - 2]) || (n == 2 && col[0] == 'q'))) {
        half = col[n - 1] == 'R';
        n -= 1;
    }
    col[n] = '\0';
    /* "lambda_dot_L" -> "lambda_dot" + L: the side sits before _dot in the tables' names too */
    if (half >= 0)
        side = gd_half_sub(half, halves);
    for (size_t i = 0; i < sizeof stems / sizeof stems[0]; i++) {
        if (strcmp(col, stems[i].stem) != 0)
            continue;
        char sym[48];
        side_symbol(sym, sizeof sym, stems[i].sym, side);
        if (rate) {
            snprintf(q->name, sizeof q->name, "rate of the %s", stems[i].name);
            if (sym[0])
                snprintf(q->sym, sizeof q->sym, "d%s/dt", sym);
        } else {
            copy(q->name, sizeof q->name, stems[i].name);
            copy(q->sym, sizeof q->sym, sym);
        }
        if (!q->sym[0] && half >= 0 && halves > 1) {
            size_t l = strlen(q->name);
            snprintf(q->name + l, sizeof q->name - l, " of the %s", gd_half_words(half, halves));
        }
        copy(q->unit, sizeof q->unit, unit ? unit : stems[i].unit);
        /* a rate in dimensionless time (the basins' sections): d/dτ, τ = ω_n t */
        char *dt = strstr(q->sym, "/dt");
        if (dt && strstr(q->unit, "per τ"))
            snprintf(dt, sizeof q->sym - (size_t)(dt - q->sym), "/dτ");
        return 1;
    }
    /* not known: the column's words */
    size_t k = 0;
    for (const char *s = col; *s && k + 1 < sizeof q->name; s++)
        q->name[k++] = *s == '_' ? ' ' : *s;
    q->name[k] = '\0';
    copy(q->unit, sizeof q->unit, unit ? unit : "-");
    return 0;
}

int gd_qty_key(const char *dotted, gd_qty *q)
{
    memset(q, 0, sizeof *q);
    q->scale = 1;
    char sec[64];
    const char *dot = strchr(dotted, '.');
    if (!dot || (size_t)(dot - dotted) >= sizeof sec) {
        copy(q->name, sizeof q->name, dotted);
        copy(q->unit, sizeof q->unit, "-");
        return 0;
    }
    snprintf(sec, sizeof sec, "%.*s", (int)(dot - dotted), dotted);
    const gd_keyspec *k = gd_case_find_key(sec, dot + 1);
    copy(q->unit, sizeof q->unit, schema_unit(k ? k->unit : ""));
    for (size_t i = 0; i < sizeof keys / sizeof keys[0]; i++)
        if (strcmp(keys[i].key, dotted) == 0) {
            copy(q->name, sizeof q->name, keys[i].name);
            copy(q->sym, sizeof q->sym, keys[i].sym);
            return 1;
        }
    /* the schema's description up to its first clause, without parentheses and a leading "y1: " */
    const char *h = k && k->help ? k->help : dot + 1;
    const char *colon = strchr(h, ':');
    if (colon && colon - h < 6)
        h = colon + 2;
    size_t m = 0;
    int paren = 0;
    for (const char *s = h; *s && m + 1 < 60; s++) {
        if (*s == '(') {
            paren++;
            continue;
        }
        if (*s == ')') {
            paren -= paren > 0;
            continue;
        }
        if (paren)
            continue;
        if (*s == ',' || *s == ';' || *s == ':')
            break;
        if (*s == ' ' && m > 0 && q->name[m - 1] == ' ')
            continue;
        q->name[m++] = *s == '_' ? ' ' : *s;
    }
    while (m > 0 && q->name[m - 1] == ' ')
        m--;
    q->name[m] = '\0';
    return 0;
}

int gd_qty_in(gd_qty *q, const char *unit)
{
    if (strcmp(q->unit, unit) == 0)
        return 1;
    for (size_t i = 0; i < sizeof conversions / sizeof conversions[0]; i++)
        if (strcmp(conversions[i].from, q->unit) == 0 && strcmp(conversions[i].to, unit) == 0) {
            q->scale *= conversions[i].factor;
            copy(q->unit, sizeof q->unit, unit);
            return 1;
        }
    return 0;
}

void gd_gp_text(const char *in, char *out, size_t len)
{
    size_t k = 0;
    for (const char *s = in; *s && k + 3 < len; s++) {
        if (*s == '_' || *s == '^' || *s == '{' || *s == '}' || *s == '@' || *s == '&' || *s == '~')
            out[k++] = '\\';
        else if (*s == '\'')
            out[k++] = '\'';
        out[k++] = *s;
    }
    out[k] = '\0';
}

void gd_gp_title(const char *in, char *out, size_t len)
{
    size_t k = 0;
    for (const char *s = in; *s && k + 3 < len; s++) {
        if (*s == '{' || *s == '}' || *s == '@' || *s == '&' || *s == '~')
            out[k++] = '\\';
        else if (*s == '\'')
            out[k++] = '\'';
        out[k++] = *s;
    }
    out[k] = '\0';
}

void gd_qty_label(const gd_qty *q, char *buf, size_t len)
{
    char name[256];
    gd_gp_text(q->name, name, sizeof name);
    /* the symbol is enhanced text already: only its quotes */
    char sym[96];
    size_t k = 0;
    for (const char *s = q->sym; *s && k + 2 < sizeof sym; s++) {
        if (*s == '\'')
            sym[k++] = '\'';
        sym[k++] = *s;
    }
    sym[k] = '\0';
    if (q->unit[0])
        snprintf(buf, len, "%s%s%s (%s)", name, sym[0] ? " " : "", sym, q->unit);
    else
        snprintf(buf, len, "%s%s%s", name, sym[0] ? " " : "", sym);
}

const char *gd_optimizer_words(int alg)
{
    const char *n = gd_opt_algorithm_name(alg);
    static const struct {
        const char *code, *words;
    } w[] = {{"alo", "ALO"}, {"gn_direct_l", "DIRECT-L"}, {"gn_crs2_lm", "CRS2-LM"}, {"gn_isres", "ISRES"},
             {"gn_esch", "ESCH"}, {"ln_bobyqa", "BOBYQA"}, {"ln_cobyla", "COBYLA"}, {"ln_sbplx", "Sbplx"},
             {"random", "random search"}, {"moalo", "MOALO"}, {"weighted-sum", "weighted sums"},
             {"eps-constraint", "ε-constraints"}};
    for (size_t i = 0; n && i < sizeof w / sizeof w[0]; i++)
        if (strcmp(w[i].code, n) == 0)
            return w[i].words;
    return n ? n : "?";
}
