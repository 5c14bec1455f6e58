/* Internal: the serial vector operations ARKODE calls at every step, compiled with geardyn
 * (bit-for-bit the results of SUNDIALS' own serial kernels; see vector_kernels.c). */
#ifndef GD_VECTOR_KERNELS_H
#define GD_VECTOR_KERNELS_H

#include <nvector/nvector_serial.h>

/* Put geardyn's kernels into the operations table of the serial vector v (its clones inherit
 * them). Returns 0, or -1 if v is not a serial vector. */
int gd_vector_use_compiled_ops(N_Vector v);

/* The linear combination four lanes wide (AVX, where the processor has it: the default) or two
 * (SSE2): the bits are the same. Returns 1 if AVX is in use. Process-wide and not thread-safe:
 * for the tests, which check both. */
int gd_vector_kernels_wide(int on);

/* The error weights w_i = 1 / (rtol |y_i| + atol) of serial vectors y, w in one pass, two lanes at
 * a time: the operations of ARKODE's scalar-tolerance weights (arkEwtSetSS: N_VAbs, N_VScale,
 * N_VAddConst, N_VInv) in their order, so the same bits. Returns -1, as ARKODE does, when atol is
 * 0 and a weight's inverse is not positive, else 0. */
int gd_vector_error_weights(N_Vector y, N_Vector w, double rtol, double atol);

#endif
