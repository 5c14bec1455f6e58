/* Memory the library allocates and hands to its caller (a journal record, an event log's selected
 * rows, geardyn check's JSON): freed here, so that a caller with no C runtime of its own (a
 * foreign-function interface) frees it with the allocator that made it. */
#include "geardyn/gd_error.h"

#include <stdlib.h>

GD_API void gd_free(void *p) { free(p); }
