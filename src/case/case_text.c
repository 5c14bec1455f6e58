/* Reading a case file's text and checking it line by line before inih parses it.
 *
 * Why the text is pre-processed rather than handed to inih as it is: Debian's libinih is built
 * with fixed compile-time options (INI_MAX_LINE 200, INI_ALLOW_MULTILINE 1, no line numbers in
 * the handler) and reads whatever the stream gives it. Left alone it reads an indented line as a
 * continuation of the previous key, drops text after a section header's ']', splits a long line
 * in two (its error then names no line or the wrong one), and reads a FIFO or a device for ever.
 * Here, and only here, the file is checked as a file and as text; what inih then reads has one
 * line per line of the file, so every message of the loader names the real line. */
#include "case_text.h"

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* The whole file into *buf (NUL-terminated), refusing anything but a regular file of sane size.
 * O_NONBLOCK: opening a FIFO with no writer must not wait; it is refused by fstat right after. */
static gd_status read_regular(const char *path, char **buf, size_t *len, gd_error *err)
{
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    if (fd < 0)
        return gd_error_set(err, GD_ERR_INPUT, "%s: cannot open case file: %s", path, strerror(errno));
    struct stat st;
    if (fstat(fd, &st) != 0) {
        int e = errno;
        close(fd);
        return gd_error_set(err, GD_ERR_INPUT, "%s: cannot open case file: %s", path, strerror(e));
    }
    if (!S_ISREG(st.st_mode)) {
        close(fd);
        return gd_error_set(err, GD_ERR_INPUT, "%s: is %s, not a case file (valid: a regular file of key = value "
                            "lines)", path, S_ISDIR(st.st_mode) ? "a directory" : S_ISFIFO(st.st_mode) ? "a FIFO"
                            : S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode) ? "a device" : "not a regular file");
    }
    if (st.st_size > GD_CASE_MAX_BYTES) {
        close(fd);
        return gd_error_set(err, GD_ERR_INPUT, "%s: %lld bytes, too large for a case file (valid: at most %d bytes)",
                            path, (long long)st.st_size, GD_CASE_MAX_BYTES);
    }
    size_t cap = (size_t)st.st_size + 2;  /* one byte more than its size: a file that grows is seen */
    char *b = malloc(cap);
    if (!b) {
        close(fd);
        return gd_error_set(err, GD_ERR_NOMEM, "%s: out of memory reading the case file", path);
    }
    size_t n = 0;
    for (;;) {
        if (n + 1 == cap) {
            char *nb = cap > GD_CASE_MAX_BYTES ? NULL : realloc(b, 2 * cap);
            if (!nb) {
                n = GD_CASE_MAX_BYTES + 1;
                break;
            }
            b = nb;
            cap *= 2;
        }
        ssize_t r = read(fd, b + n, cap - 1 - n);
        if (r < 0 && errno == EINTR)
            continue;
        if (r < 0) {
            int e = errno;
            free(b);
            close(fd);
            return gd_error_set(err, GD_ERR_INPUT, "%s: cannot read case file: %s", path, strerror(e));
        }
        if (r == 0 || (n += (size_t)r) > GD_CASE_MAX_BYTES)
            break;
    }
    close(fd);
    if (n > GD_CASE_MAX_BYTES) {
        free(b);
        return gd_error_set(err, GD_ERR_INPUT, "%s: grew beyond %d bytes while read (valid: a case file of at most "
                            "that size)", path, GD_CASE_MAX_BYTES);
    }
    b[n] = '\0';
    *buf = b;
    *len = n;
    return GD_OK;
}

/* The line (1-based) of byte offset off; CRLF, CR and LF each end one line. */
static int line_of(const char *b, size_t off)
{
    int line = 1;
    for (size_t i = 0; i < off; i++)
        if (b[i] == '\n' || (b[i] == '\r' && b[i + 1] != '\n'))
            line++;
    return line;
}

/* UTF-16 (with or without its byte-order mark) and NUL bytes: a case file is UTF-8 text. */
static gd_status check_nul(const char *path, const char *b, size_t len, gd_error *err)
{
    const unsigned char *u = (const unsigned char *)b;
    if (len >= 2 && ((u[0] == 0xFF && u[1] == 0xFE) || (u[0] == 0xFE && u[1] == 0xFF)))
        return gd_error_set(err, GD_ERR_INPUT, "%s:1: UTF-16 text (byte-order mark %02X %02X) (valid: UTF-8 text; "
                            "save the case file as UTF-8)", path, u[0], u[1]);
    const char *nul = memchr(b, '\0', len);
    if (!nul)
        return GD_OK;
    size_t zeros = 0, probe = len < 64 ? len : 64;
    for (size_t i = 0; i < probe; i++)
        zeros += u[i] == 0;
    if (probe >= 4 && zeros * 3 >= probe)
        return gd_error_set(err, GD_ERR_INPUT, "%s:1: UTF-16 text (NUL bytes between the characters) (valid: UTF-8 "
                            "text; save the case file as UTF-8)", path);
    return gd_error_set(err, GD_ERR_INPUT, "%s:%d: NUL byte (valid: UTF-8 text; this is not a text file)", path,
                        line_of(b, (size_t)(nul - b)));
}

/* Length of the well-formed UTF-8 sequence at s (at most n bytes), 0 if malformed. */
static size_t utf8_seq(const unsigned char *s, size_t n)
{
    size_t len;
    unsigned lo = 0x80, hi = 0xBF;
    if (s[0] < 0x80)
        return 1;
    if (s[0] >= 0xC2 && s[0] <= 0xDF)
        len = 2;
    else if (s[0] >= 0xE0 && s[0] <= 0xEF) {
        len = 3;
        if (s[0] == 0xE0) lo = 0xA0;
        if (s[0] == 0xED) hi = 0x9F;  /* no surrogates */
    } else if (s[0] >= 0xF0 && s[0] <= 0xF4) {
        len = 4;
        if (s[0] == 0xF0) lo = 0x90;
        if (s[0] == 0xF4) hi = 0x8F;
    } else
        return 0;
    if (n < len || s[1] < lo || s[1] > hi)
        return 0;
    for (size_t i = 2; i < len; i++)
        if (s[i] < 0x80 || s[i] > 0xBF)
            return 0;
    return len;
}

static int blank(char ch) { return ch == ' ' || ch == '\t'; }

/* One line of the file (s, n bytes, no line ending) checked and appended to out, ending in '\n'. */
static gd_status normalise_line(const char *path, int line, const char *s, size_t n, char *out, size_t *used,
                                gd_error *err)
{
    for (size_t i = 0; i < n;) {
        unsigned char ch = (unsigned char)s[i];
        if ((ch < 0x20 && ch != '\t') || ch == 0x7F)
            return gd_error_set(err, GD_ERR_INPUT, "%s:%d: control character 0x%02X at column %zu (valid: UTF-8 "
                                "text, tabs allowed)", path, line, ch, i + 1);
        size_t k = utf8_seq((const unsigned char *)s + i, n - i);
        if (!k)
            return gd_error_set(err, GD_ERR_INPUT, "%s:%d: not UTF-8: byte 0x%02X at column %zu (valid: UTF-8 text; "
                                "save the case file as UTF-8)", path, line, ch, i + 1);
        i += k;
    }
    while (n > 0 && blank(*s)) { s++; n--; }
    while (n > 0 && blank(s[n - 1])) n--;
    if (n == 0 || *s == ';' || *s == '#')
        n = 0;
    else if (*s == '[') {
        const char *close = memchr(s, ']', n);
        if (!close)
            return gd_error_set(err, GD_ERR_INPUT, "%s:%d: '%.*s': section header without its closing ']' (valid: "
                                "[section])", path, line, (int)(n < 80 ? n : 80), s);
        const char *rest = close + 1, *end = s + n;
        while (rest < end && blank(*rest)) rest++;
        if (rest < end && *rest != ';' && *rest != '#')
            return gd_error_set(err, GD_ERR_INPUT, "%s:%d: text after the section header %.*s: '%.*s' (valid: the "
                                "header alone on its line, each key = value on a line of its own)", path, line,
                                (int)(close + 1 - s), s, (int)((end - rest) < 80 ? end - rest : 80), rest);
        n = (size_t)(close + 1 - s);
    } else {
        for (size_t i = 1; i < n; i++)  /* inih's inline comment: ';' after a blank */
            if (s[i] == ';' && blank(s[i - 1])) {
                n = i;
                break;
            }
        while (n > 0 && blank(s[n - 1])) n--;
        if (!memchr(s, '=', n) && !memchr(s, ':', n))  /* inih's separators */
            return gd_error_set(err, GD_ERR_INPUT, "%s:%d: syntax error: '%.*s' (valid: a [section] header or a "
                                "key = value line)", path, line, (int)(n < 80 ? n : 80), s);
    }
    if (n > GD_CASE_MAX_LINE)
        return gd_error_set(err, GD_ERR_INPUT, "%s:%d: a line of %zu characters (valid: at most %d characters, "
                            "comments excepted)", path, line, n, GD_CASE_MAX_LINE);
    memcpy(out + *used, s, n);
    *used += n;
    out[(*used)++] = '\n';
    return GD_OK;
}

gd_status gd_case_text_normalise(const char *path, const char *b, size_t len, char **text, gd_error *err)
{
    *text = NULL;
    if (len > GD_CASE_MAX_BYTES)
        return gd_error_set(err, GD_ERR_INPUT, "%s: %zu bytes, too large for a case file (valid: at most %d bytes)",
                            path, len, GD_CASE_MAX_BYTES);
    gd_status st = check_nul(path, b, len, err);
    char *out = st == GD_OK ? malloc(2 * len + 2) : NULL;
    if (st == GD_OK && !out)
        st = gd_error_set(err, GD_ERR_NOMEM, "%s: out of memory reading the case file", path);
    size_t pos = (len >= 3 && memcmp(b, "\xEF\xBB\xBF", 3) == 0) ? 3 : 0, used = 0;
    for (int line = 1; st == GD_OK && pos < len; line++) {
        size_t e = pos;
        while (e < len && b[e] != '\n' && b[e] != '\r')
            e++;
        st = normalise_line(path, line, b + pos, e - pos, out, &used, err);
        pos = e + (e < len && b[e] == '\r' && e + 1 < len && b[e + 1] == '\n' ? 2 : 1);
    }
    if (st != GD_OK) {
        free(out);
        return st;
    }
    out[used] = '\0';
    *text = out;
    return GD_OK;
}

gd_status gd_case_text_read(const char *path, char **text, gd_error *err)
{
    char *b = NULL;
    size_t len = 0;
    *text = NULL;
    gd_status st = read_regular(path, &b, &len, err);
    if (st != GD_OK)
        return st;
    st = gd_case_text_normalise(path, b, len, text, err);
    free(b);
    return st;
}
