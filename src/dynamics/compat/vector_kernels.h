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

#endif
