/* Where a key's value came from, for the checks that name it: shared by every layer that checks
 * keys of a case (the cross-key checks, the scene, the sweep and optimiser sections); and the names
 * of enum values, for the writers. Internal. */
#ifndef GD_CASE_KEYS_H
#define GD_CASE_KEYS_H

#include "geardyn/gd_case.h"

/* Index of [section] key in the schema (the key must exist). */
size_t gd_case_key_index(const char *section, const char *key);
/* 1 when the key was given in the file or by --set. */
int gd_case_key_given(const gd_case *c, const char *section, const char *key);
/* "file:line", "--set #N" or the case path when the key was not given. */
void gd_case_key_where(const gd_case *c, const char *section, const char *key, char *buf, size_t len);
/* Set a field to a derived value unless the key was given; marks it derived. */
void gd_case_key_derive(gd_case *c, const char *section, const char *key, double *field, double value);
/* 1 when v is finite and within the key's range (open or closed at either end). */
int gd_case_key_in_range(const gd_keyspec *k, double v);
/* The name of value among the choices of an enum key (the schema's '|'-separated names, the one
 * list of them: "torsional" for scene.model 0), "?" when out of range; written to buf, returned. */
const char *gd_case_key_choice(const char *section, const char *key, int value, char *buf, size_t len);
/* The schema entry of a "section.key" name, NULL when there is none. */
const gd_keyspec *gd_case_key_dotted(const char *name);
/* The valid range of a numeric key as messages write it ("a number in [0, 1e+06] rpm"). */
void gd_case_key_range_text(const gd_keyspec *k, char *buf, size_t len);

#endif
