/* Internals of the contact solvers shared by src/contact/contact_solve.c and ltca_qp.c (not
 * installed). */
#ifndef GD_CONTACT_INTERNAL_H
#define GD_CONTACT_INTERNAL_H

#include "geardyn/gd_contact.h"

/* The cold start of both active-set solvers: clears in_free (n entries) and marks the least-gap
 * points whose rows of G are independent (Gram-Schmidt), one per freedom while there is one.
 * Returns how many were marked (pb->m when a full set was found). */
int contact_cold_start(const gd_contact_problem *pb, unsigned char *in_free);

#endif
