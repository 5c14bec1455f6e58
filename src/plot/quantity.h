/* How a picture names a quantity: its name for a reader, its symbol and its unit, read off the
 * column tables' names (the unit is the column's suffix: lambda_L_um, rms_accel_mps2) and off the
 * schema (a key's unit and meaning). Every axis label and key entry of a picture comes from here. */
#ifndef GD_PLOT_QUANTITY_H
#define GD_PLOT_QUANTITY_H

#include <stddef.h>

typedef struct gd_qty {
    char name[120];   /* plain text: "mesh deflection" */
    char sym[48];     /* enhanced text (sub- and superscripts): "λ_L"; "" when none */
    char unit[32];    /* plain text: "µm", "m/s²"; "-" dimensionless; "" a count */
    double scale;     /* what is drawn: the column's value times scale (in unit) */
} gd_qty;

/* The quantity of a column of the tables ("lambda_L_um", "rms_accel_mps2", "t_s", "mle", "y1L_um",
 * "lambda_L_rate_mps" of variable.csv, "gte_left_arcsec", a bare variable "lambda_L" or "y1L" in
 * the tables' dimensionless units); halves: the meshes of the pair (1: a spur or single-helical
 * pair, whose one mesh has no side). Returns 0 for a column it does not know, whose name is then
 * the column's without its unit suffix, underscores as spaces. */
int gd_qty_column(const char *column, int halves, gd_qty *q);
/* The quantity of a key of the schema ("operating.speed_rpm"): its unit from the schema, its name
 * from a table of the keys one sweeps or continues, else the first words of the schema's
 * description. */
int gd_qty_key(const char *dotted, gd_qty *q);
/* Draw q in another unit of the same dimension (s as ms, N/m as N/µm); 0 when not known. */
int gd_qty_in(gd_qty *q, const char *unit);
/* The axis label "name symbol (unit)" as gnuplot enhanced text inside single quotes; a count
 * has no "(unit)". */
void gd_qty_label(const gd_qty *q, char *buf, size_t len);
/* The side of a herringbone's half (0 left, 1 right) as a subscript and as words; "" for a single
 * pair (halves 1). */
const char *gd_half_sub(int half, int halves);
const char *gd_half_words(int half, int halves);

/* An optimiser by the name its authors gave it ("CRS2-LM" for gn_crs2_lm). */
const char *gd_optimizer_words(int alg);

/* Plain text as gnuplot enhanced text inside single quotes: _ ^ { } @ & ~ literal, ' doubled. */
void gd_gp_text(const char *in, char *out, size_t len);
/* A case's title (scene.title, free text) as enhanced text inside single quotes: _ and ^ make
 * sub- and superscripts as in the docs' notation ("F_m", "kg m^2"), { } @ & ~ literal. */
void gd_gp_title(const char *in, char *out, size_t len);

#endif
