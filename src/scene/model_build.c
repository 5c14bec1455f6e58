/* Building the dimensionless model (torsional, torsional-lr, bta) from a resolved case, with its
 * LTCA excitations: a herringbone pair as two helical halves, a spur or single-helical pair as one
 * mesh on the whole bodies (docs/model.md section 5.4). */
#include "geardyn/gd_scene.h"
#include "geardyn/gd_excitation.h"
#include "geardyn/gd_geometry.h"

#include <stdlib.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

static void add_nz(gd_nz *list, int *n, int i, int j, double v)
{
    if (v == 0.0)
        return;
    for (int q = 0; q < *n; q++)
        if (list[q].i == i && list[q].j == j) {
            list[q].v += v;
            return;
        }
    list[*n].i = i;
    list[*n].j = j;
    list[*n].v = v;
    (*n)++;
}

/* A linear spring (and damper) between DOF i and ground (j < 0) or DOF j. */
static void spring(gd_model *m, int i, int j, double k, double c)
{
    add_nz(m->K0, &m->nk, i, i, k);
    add_nz(m->C0, &m->nc, i, i, c);
    if (j >= 0) {
        add_nz(m->K0, &m->nk, j, j, k);
        add_nz(m->K0, &m->nk, i, j, -k);
        add_nz(m->K0, &m->nk, j, i, -k);
        add_nz(m->C0, &m->nc, j, j, c);
        add_nz(m->C0, &m->nc, i, j, -c);
        add_nz(m->C0, &m->nc, j, i, -c);
    }
}

/* Reorder the entries of a sparse list so that consecutive entries act on different rows (the
 * first entry of every row, then the second of every row, ...), keeping the order within each row.
 * The RHS subtracts the entries from the rows in list order: each row sees the same operations in
 * the same order (the same bits), and consecutive updates do not wait for each other. */
static void interleave_rows(gd_nz *list, int n)
{
    gd_nz out[GD_MAX_NNZ];
    int taken[GD_MAX_NNZ] = {0}, k = 0;
    for (int rank = 0; k < n; rank++) {
        int seen[GD_MAX_DOF] = {0};
        for (int q = 0; q < n; q++) {
            if (taken[q])
                continue;
            if (seen[list[q].i]++ == 0) { /* the first entry of its row not yet taken */
                out[k++] = list[q];
                taken[q] = 1;
            }
        }
    }
    memcpy(list, out, sizeof(gd_nz) * (size_t)n);
}

#define GD_GRAVITY_MPS2 9.80665 /* standard gravity (ISO 80000-3) */

static void name_dof(gd_model *m, int i, const char *name) { snprintf(m->dof_name[i], sizeof m->dof_name[i], "%s", name); }

/* A spur or single-helical pair: one mesh on the whole bodies, carrying the whole torque. */
static int single_pair(const gd_case *c) { return c->arrangement != GD_ARR_HERRINGBONE; }

/* The meshes that share the torque: the two halves of a herringbone, the one mesh of a single pair. */
static int torque_meshes(const gd_case *c) { return single_pair(c) ? 1 : 2; }

/* The scales and values of the case every model topology uses, dimensionless where stated. */
typedef struct build_scales {
    double cb, sb;           /* cos and (with axial coupling) sin of the base helix angle */
    double mn, km;           /* normal equivalent mass of one half (kg), mesh stiffness (N/m) */
    double fscale, cscale;   /* N -> dimensionless force, N s/m -> dimensionless damping */
    double bh, eh;           /* half backlash, half bearing clearance (dimensionless) */
} build_scales;

/* The reference scales of the model, the mesh frequency and the static load. */
static void model_scales(const gd_case *c, const gd_geometry *g, gd_model *m, build_scales *b)
{
    double cb = cos(g->beta_b), sb = c->axial_coupling ? sin(g->beta_b) : 0.0;
    double me = c->equivalent_mass_kg;
    double mn = me / (cb * cb);          /* normal equivalent mass of the bodies of one mesh */
    double km = c->mesh_stiffness_n_per_m;
    m->kind = c->model;
    m->m_ref = mn;
    m->k_ref = km;
    m->omega_n = sqrt(km / mn);
    m->bc_m = c->characteristic_length_um * 1e-6;
    double omega_m = 2.0 * M_PI * c->teeth_pinion * c->speed_rpm / 60.0;
    m->mesh_freq_hz = omega_m / (2.0 * M_PI);
    m->Omega = omega_m / m->omega_n;
    m->period = 2.0 * M_PI / m->Omega;
    b->fscale = 1.0 / (km * m->bc_m);         /* N -> dimensionless force */
    b->cscale = 1.0 / (mn * m->omega_n);      /* N s/m -> dimensionless damping */
    double T = c->torque_nm;
    m->static_load_n = T / (torque_meshes(c) * g->rb[0] * cb);   /* normal force of one mesh */
    b->bh = 0.5 * c->backlash_um * 1e-6 / m->bc_m;
    b->eh = 0.5 * c->bearing_clearance_um * 1e-6 / m->bc_m;
    m->damp_contact_only = c->mesh_damping_mode == GD_DAMP_CONTACT;
    b->cb = cb;
    b->sb = sb;
    b->mn = mn;
    b->km = km;
}

/* The excitations of each mesh: stiffness variation and static transmission error. */
static void model_excitations(const gd_case *c, gd_model *m)
{
    const double deg = M_PI / 180.0;
    int nmesh = c->model == GD_MODEL_TORSIONAL || single_pair(c) ? 1 : 2;
    m->nmesh = nmesh;
    for (int s = 0; s < nmesh; s++) {
        gd_mesh_excitation *x = &m->mesh[s];
        x->kind = c->stiffness;
        x->nh = c->stiffness == GD_STIFF_HARMONIC ? c->n_stiffness_harmonics : 0;
        x->mean = 1.0;
        for (int j = 0; j < x->nh; j++) {
            x->a[j] = c->stiffness_harmonics[j];
            x->phi[j] = j < c->n_stiffness_phases ? c->stiffness_phases_deg[j] * deg : 0.0;
        }
        x->rect_frac = c->rectangular_high_fraction;
        x->rect_high = 1.0 + c->rectangular_variation;
        x->rect_low = 1.0 - c->rectangular_variation * x->rect_frac / (1.0 - x->rect_frac);
        x->phase = s == 1 ? c->half_phase_deg * deg : 0.0;
        x->cph = cos(x->phase);
        x->sph = sin(x->phase);
        double on = c->error_excitation ? 1.0 : 0.0;
        x->e_m = on * c->ste_mean_um * 1e-6 / m->bc_m;
        x->e_r = c->ste_source == GD_STE_LTCA ? 0.0 : on * c->ste_amplitude_um * 1e-6 / m->bc_m;
        x->e_phi = c->ste_phase_deg * deg;
        for (int j = 0; j < x->nh; j++) {
            x->cphi[j] = cos(x->phi[j]);
            x->sphi[j] = sin(x->phi[j]);
        }
        x->ce = cos(x->e_phi);
        x->se = sin(x->e_phi);
    }
}

/* torsional: one DOF q, one mesh carrying both halves of a herringbone (mass, stiffness, damping
 * and load twice those of one half) or the one mesh of a single pair. */
static void build_torsional(const gd_case *c, gd_model *m, const build_scales *b)
{
    double w = torque_meshes(c);
    m->ndof = 1;
    name_dof(m, 0, "q");
    m->mass[0] = w;
    m->F0[0] = w * m->static_load_n * b->fscale;
    gd_clearance *cl = &m->clear[0];
    cl->kind = GD_CLR_MESH;
    cl->mesh = 0;
    cl->nw = 1;
    cl->widx[0] = 0;
    cl->wval[0] = 1.0;
    cl->h = b->bh;
    cl->k = w;
    cl->c = w * 2.0 * c->mesh_damping_ratio;
    cl->damp_contact_only = m->damp_contact_only;
    snprintf(cl->name, sizeof cl->name, "mesh");
    m->nclear = 1;
    m->mesh_clear[0] = 0;
    m->q_dof[0] = 0;
}

/* torsional-lr: one DOF and one mesh per half (qL, qR). */
static void build_torsional_lr(const gd_case *c, gd_model *m, const build_scales *b)
{
    m->ndof = 2;
    name_dof(m, 0, "qL");
    name_dof(m, 1, "qR");
    for (int s = 0; s < 2; s++) {
        m->mass[s] = 1.0;
        m->F0[s] = m->static_load_n * b->fscale;
        gd_clearance *cl = &m->clear[s];
        cl->kind = GD_CLR_MESH;
        cl->mesh = s;
        cl->nw = 1;
        cl->widx[0] = s;
        cl->wval[0] = 1.0;
        cl->h = b->bh;
        cl->k = 1.0;
        cl->c = 2.0 * c->mesh_damping_ratio;
        cl->damp_contact_only = m->damp_contact_only;
        snprintf(cl->name, sizeof cl->name, "mesh-%c", s ? 'R' : 'L');
        m->mesh_clear[s] = s;
        m->q_dof[s] = s;
    }
    m->nclear = 2;
}

/* The suffix of the names of half s: "L", "R", or none for the one mesh of a single pair. */
static const char *half_suffix(const gd_model *m, int s) { return m->nmesh == 1 ? "" : s ? "R" : "L"; }

/* bta: the mesh of half s (DOFs from b0), clearance number *nclr. */
static void bta_mesh(const gd_case *c, gd_model *m, const build_scales *b, int s, int b0, int *nclr)
{
    double cb = b->cb, sb = b->sb;
    double sig = s == 0 ? 1.0 : -1.0;
    gd_clearance *cl = &m->clear[*nclr];
    cl->kind = GD_CLR_MESH;
    cl->mesh = s;
    int nw = 0;
    cl->widx[nw] = b0 + 0; cl->wval[nw++] = cb;
    cl->widx[nw] = b0 + 2; cl->wval[nw++] = -cb;
    cl->widx[nw] = b0 + 4; cl->wval[nw++] = 1.0;
    if (sb != 0.0) {
        cl->widx[nw] = b0 + 1; cl->wval[nw++] = sig * sb;
        cl->widx[nw] = b0 + 3; cl->wval[nw++] = -sig * sb;
    }
    cl->nw = nw;
    cl->h = b->bh;
    cl->k = 1.0;
    cl->c = 2.0 * c->mesh_damping_ratio;
    cl->damp_contact_only = m->damp_contact_only;
    snprintf(cl->name, sizeof cl->name, "mesh%s%s", m->nmesh == 1 ? "" : "-", half_suffix(m, s));
    m->mesh_clear[s] = (*nclr)++;
    m->q_dof[s] = b0 + 4;
}

/* bta: the radial supports of both bodies of half s (dead zone or linear), then the axial ones. */
static void bta_supports(const gd_case *c, gd_model *m, const build_scales *b, int s, int b0, int *nclr)
{
    double m1 = c->pinion_mass_kg, m2 = c->gear_mass_kg;
    double k1y = c->radial_stiffness_pinion_n_per_m, k2y = c->radial_stiffness_gear_n_per_m;
    double k1z = c->axial_stiffness_pinion_n_per_m, k2z = c->axial_stiffness_gear_n_per_m;
    double zs = c->support_damping_ratio, km = b->km, cscale = b->cscale;
    for (int body = 0; body < 2; body++) {
        int i = b0 + 2 * body;
        double k = body ? k2y : k1y, mass = body ? m2 : m1;
        double cy = 2.0 * zs * sqrt(k * mass);
        if (c->bearing_clearance) {
            gd_clearance *bl = &m->clear[(*nclr)++];
            bl->kind = GD_CLR_BEARING;
            bl->mesh = -1;
            bl->nw = 1;
            bl->widx[0] = i;
            bl->wval[0] = 1.0;
            bl->h = b->eh;
            bl->k = k / km;
            snprintf(bl->name, sizeof bl->name, "bearing-%d%s", body + 1, half_suffix(m, s));
            if (c->bearing_damping_mode == GD_DAMP_CONTACT) { /* only while the journal touches */
                bl->c = cy * cscale;
                bl->damp_contact_only = 1;
            } else { /* on the journal's velocity always, inside the clearance too */
                bl->c = 0.0;
                add_nz(m->C0, &m->nc, i, i, cy * cscale);
            }
        } else {
            spring(m, i, -1, k / km, cy * cscale);
        }
    }
    spring(m, b0 + 1, -1, k1z / km, 2.0 * zs * sqrt(k1z * m1) * cscale);
    spring(m, b0 + 3, -1, k2z / km, 2.0 * zs * sqrt(k2z * m2) * cscale);
}

/* bta: per half the pinion and gear (y, z) and the mesh deflection q, ten DOFs; the groove
 * shafts couple the axial motion of the two halves of each body. A single pair has one such
 * half, five DOFs, whose axial supports take the axial mesh force (none for a spur pair). */
static void build_bta(const gd_case *c, gd_model *m, const build_scales *b)
{
    int halves = m->nmesh;
    m->ndof = 5 * halves;
    double m1 = c->pinion_mass_kg, m2 = c->gear_mass_kg, mn = b->mn, km = b->km, cscale = b->cscale;
    double k1s = c->shaft_stiffness_pinion_n_per_m, k2s = c->shaft_stiffness_gear_n_per_m;
    double zsh = c->shaft_damping_ratio;
    static const char *names[5] = {"y1", "z1", "y2", "z2", "q"};
    int nclr = 0;
    for (int s = 0; s < halves; s++) {
        int b0 = 5 * s;
        for (int j = 0; j < 5; j++) {
            char nm[8];
            snprintf(nm, sizeof nm, "%s%s", names[j], half_suffix(m, s));
            name_dof(m, b0 + j, nm);
        }
        m->mass[b0 + 0] = m1 / mn;
        m->mass[b0 + 1] = m1 / mn;
        m->mass[b0 + 2] = m2 / mn;
        m->mass[b0 + 3] = m2 / mn;
        m->mass[b0 + 4] = 1.0;
        m->F0[b0 + 4] = m->static_load_n * b->fscale;
        if (c->gravity) { /* the weights along y: their component along the line of action */
            double gy = GD_GRAVITY_MPS2 * cos(c->gravity_angle_deg * M_PI / 180.0);
            m->F0[b0 + 0] = m1 * gy * b->fscale;
            m->F0[b0 + 2] = m2 * gy * b->fscale;
        }
        bta_mesh(c, m, b, s, b0, &nclr);
        bta_supports(c, m, b, s, b0, &nclr);
    }
    m->nclear = nclr;
    if (halves == 1)
        return;
    /* groove shafts couple the axial motion of the two halves of each body */
    spring(m, 1, 6, k1s / km, 2.0 * zsh * sqrt(k1s * m1 / 2.0) * cscale);
    spring(m, 3, 8, k2s / km, 2.0 * zsh * sqrt(k2s * m2 / 2.0) * cscale);
}

GD_API gd_status gd_model_build(const gd_case *c, gd_model *m, gd_error *err)
{
    memset(m, 0, sizeof *m);
    gd_geometry g;
    const gd_pair pair = gd_pair_from_case(c);
    gd_status st = gd_geometry_compute(&pair, &g, err);
    if (st != GD_OK)
        return st;
    if (c->model == GD_MODEL_TORSIONAL && c->half_phase_deg != 0.0)
        return gd_error_set(err, GD_ERR_INPUT, "%s: excitation.half_phase_deg: %g with model torsional (valid: 0, "
                            "the torsional model has one mesh; use torsional-lr)", c->path, c->half_phase_deg);
    if (single_pair(c) && c->model == GD_MODEL_TORSIONAL_LR) /* gd_scene_resolve names the lines */
        return gd_error_set(err, GD_ERR_INPUT, "%s: scene.model: torsional-lr with gear.arrangement = %s (valid: "
                            "torsional, bta; torsional-lr is the two halves of a herringbone)", c->path,
                            c->arrangement == GD_ARR_SPUR ? "spur" : "helical");
    build_scales b;
    model_scales(c, &g, m, &b);
    model_excitations(c, m);
    if (c->model == GD_MODEL_TORSIONAL)
        build_torsional(c, m, &b);
    else if (c->model == GD_MODEL_TORSIONAL_LR)
        build_torsional_lr(c, m, &b);
    else
        build_bta(c, m, &b);
    m->n = 2 * m->ndof;
    interleave_rows(m->K0, m->nk);
    interleave_rows(m->C0, m->nc);
    for (int i = 0; i < m->ndof; i++)
        m->inv_mass[i] = 1.0 / m->mass[i];
    m->dte_scale = b.cb;
    m->force_share = c->model == GD_MODEL_TORSIONAL && !single_pair(c) ? 0.5 : 1.0;
    return gd_model_apply_ltca(c, m, err);
}

/* The pulse of one half's mesh-in impact im at the pinion speed omega1 (docs/model.md section 8.4): its
 * force F (N) and duration (s). The peak F_s is the energy balance with the contact law F = c delta^n
 * and the normal equivalent mass of a half. impact_form = contact: the rectangle of that peak and of
 * the impulse m_n v_s that stops the approach (the compression phase's), m_n v_s / F_s long, at most a
 * mesh period (beyond it F_s acts throughout: a contact of that peak cannot stop the approach within a
 * cycle). paper: F_s for the rise time of the linearised contact, at most a quarter of the mesh period
 * (the paper gives no duration). */
static void impact_pulse(const gd_case *c, const gd_model *m, const gd_ltca_impact *im, double omega1, double *F,
                         double *dur)
{
    double vs = fabs(im->vs_per_omega * omega1), rise, Tm = 1.0 / m->mesh_freq_hz;
    gd_impact_force(vs, m->m_ref, im->ks, im->delta_m, c->impact_exponent, F, &rise);
    if (!(*F > 0))
        *dur = 0.0; /* no approach: no pulse */
    else if (c->impact_form == GD_IMPACT_PAPER)
        *dur = fmin(rise, 0.25 * Tm);
    else
        *dur = fmin(m->m_ref * vs / *F, Tm);
}

/* excitation.ste = ltca: LTCA's transmission error as the error excitation of mesh j (docs/ltca.md
 * section 8). Under the static load F of the mesh the model's mesh coordinate sits at q = e(t) +
 * F/k(t) (+ the half backlash); LTCA's loaded approach of the half is q_LTCA = -LTE r_b2 cos(beta_b)
 * along the normal (the gear lags). So e = q_LTCA - F/k(t), its mean removed: the quasi-static
 * model reproduces LTCA's loaded transmission error whatever part of it the stiffness carries. The
 * torsional model of a herringbone has one mesh for both halves: their mean. */
static gd_status apply_ltca_error(const gd_case *c, gd_model *m, const gd_ltca_excitation *x, double rb2, double cbb,
                                  gd_error *err)
{
    const double arcsec = M_PI / (180.0 * 3600.0);
    int two = x->halves > 1 && x->lte_half_arcsec[1] != NULL;
    double *buf = malloc(sizeof(double) * (size_t)x->npos);
    if (!buf)
        return gd_error_set(err, GD_ERR_NOMEM, "LTCA error excitation: out of memory");
    gd_status st = GD_OK;
    for (int j = 0; j < m->nmesh && st == GD_OK; j++) {
        int h = j < 1 || !two ? 0 : 1;
        double mean = 0;
        for (int i = 0; i < x->npos; i++) {
            double lte = m->kind == GD_MODEL_TORSIONAL && two ?
                0.5 * (x->lte_half_arcsec[0][i] + x->lte_half_arcsec[1][i]) : x->lte_half_arcsec[h][i];
            double k = c->stiffness == GD_STIFF_LTCA ?
                (m->kind == GD_MODEL_TORSIONAL && two ? 0.5 * (x->k[0][i] + x->k[1][i]) : x->k[h][i]) : m->k_ref;
            buf[i] = -lte * arcsec * rb2 * cbb - m->static_load_n / k;
            mean += buf[i];
        }
        mean /= x->npos;
        for (int i = 0; i < x->npos; i++)
            buf[i] -= mean;
        st = gd_model_set_error_table(m, j, buf, x->npos, err);
    }
    free(buf);
    return st == GD_OK ? GD_OK : gd_error_prefix(err, "LTCA error excitation");
}

/* The LTCA excitation x applied to m; x is only read here (gd_model_set_stiffness_table keeps the
 * Fourier coefficients of the samples, gd_model_set_impact scalars). */
static gd_status apply_excitation(const gd_case *c, gd_model *m, const gd_ltca_excitation *x, gd_error *err)
{
    gd_status st = GD_OK;
    int two = x->halves > 1 && x->k[1] != NULL;
    if (c->stiffness == GD_STIFF_LTCA) {
        double *buf = malloc(sizeof(double) * (size_t)x->npos);
        if (!buf)
            return gd_error_set(err, GD_ERR_NOMEM, "LTCA stiffness: out of memory");
        for (int j = 0; j < m->nmesh && st == GD_OK; j++) {
            for (int i = 0; i < x->npos; i++) {
                if (m->kind == GD_MODEL_TORSIONAL) /* one mesh for both halves: their mean per half */
                    buf[i] = two ? 0.5 * (x->k[0][i] + x->k[1][i]) : x->k[0][i];
                else
                    buf[i] = x->k[j < 1 || !two ? 0 : 1][i];
            }
            st = gd_model_set_stiffness_table(m, j, buf, x->npos, err);
        }
        free(buf);
        if (st != GD_OK)
            return gd_error_prefix(err, "LTCA stiffness");
    }
    if (c->impact) {
        double omega1 = 2.0 * M_PI * c->speed_rpm / 60.0;
        int halves = x->halves > 1 ? 2 : 1;
        for (int j = 0; j < m->nmesh; j++) {
            gd_mesh_excitation *mx = &m->mesh[j];
            mx->nimp = 0;
            mx->imp_contact_only = c->impact_form == GD_IMPACT_CONTACT;
            /* the halves whose impacts the mesh receives: its own; both on the one mesh of a
             * herringbone's torsional model, each at its own phase with its own force */
            int h0 = m->kind == GD_MODEL_TORSIONAL ? 0 : j, h1 = m->kind == GD_MODEL_TORSIONAL ? halves - 1 : j;
            for (int h = h0; h <= h1 && st == GD_OK; h++) {
                const gd_ltca_impact *im = &x->impact[h];
                if (!im->found)
                    continue;
                double F, dur;
                impact_pulse(c, m, im, omega1, &F, &dur);
                st = gd_model_add_impact(m, j, F, 2.0 * M_PI * im->phase, dur, err);
                if (st == GD_OK && dur > 0)
                    mx->imp_half[mx->nimp - 1] = h;
            }
            if (st != GD_OK)
                return gd_error_prefix(err, "mesh-in impact of mesh %d", j);
        }
    }
    return GD_OK;
}

GD_API gd_status gd_model_apply_ltca(const gd_case *c, gd_model *m, gd_error *err)
{
    int ste = c->ste_source == GD_STE_LTCA && c->error_excitation;
    if ((c->stiffness != GD_STIFF_LTCA && !c->impact && !ste) || c->ltca_deferred)
        return GD_OK;
    const gd_ltca_excitation *x;
    const gd_pair pair = gd_pair_from_case(c);
    const gd_ltca_settings set = gd_ltca_settings_from_case(c);
    gd_status st = gd_ltca_excitation_cached(&pair, &set, &x, err);
    if (st != GD_OK)
        return st;
    st = apply_excitation(c, m, x, err);
    if (st == GD_OK && ste) {
        gd_geometry g;
        st = gd_geometry_compute(&pair, &g, err);
        if (st == GD_OK)
            st = apply_ltca_error(c, m, x, g.rb[1], cos(g.beta_b), err);
    }
    gd_ltca_excitation_release(x); /* the model keeps no pointer into x */
    return st;
}
