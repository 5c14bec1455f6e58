/* The text of a case file, read and checked before inih sees it (src/case/case_text.c). */
#ifndef GD_CASE_TEXT_H
#define GD_CASE_TEXT_H

#include "geardyn/gd_error.h"

#include <stddef.h>

/* The largest case file read, in bytes: a case is a few hundred lines; anything larger is the
 * wrong file (a result table, a device). */
#define GD_CASE_MAX_BYTES (1024 * 1024)
/* The longest line inih reads whole (its INI_MAX_LINE of 200 holds the line, its newline and
 * the terminating NUL); a longer key = value line is refused with its number. */
#define GD_CASE_MAX_LINE 198

/* Read the case file at path: a regular file of at most GD_CASE_MAX_BYTES, UTF-8 (a byte-order
 * mark allowed; NUL bytes, UTF-16 and malformed sequences refused), with LF, CRLF or CR line
 * endings. On success *text (malloc'd, free it) holds one line per line of the file, ended by
 * '\n', so that line numbers are kept: leading and trailing blanks removed (an indented line is a
 * line of its own, never inih's continuation of the previous key), comment lines and trailing
 * ' ;' comments blanked, section headers reduced to "[name]" (text after one is refused, as is a
 * header without its ']'), and no line longer than GD_CASE_MAX_LINE. Messages start with
 * "path:line:" and say what is wrong. */
gd_status gd_case_text_read(const char *path, char **text, gd_error *err);
/* The same checks and normalisation of a case file's len bytes b (not NUL-terminated) that name
 * calls the file in messages (gd_case_load_text). */
gd_status gd_case_text_normalise(const char *name, const char *b, size_t len, char **text, gd_error *err);

#endif
