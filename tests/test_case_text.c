/* The case reader is blind to how a valid file is laid out (src/case/case_text.c): every shipped
 * case, rewritten with CRLF or CR line endings, a UTF-8 byte-order mark, every line indented by a
 * blank and a tab, trailing blanks, or a 300-character comment line on top, loads to the same value
 * of every key, each from the same line (one line later under the added comment). A reader that
 * glued indented lines to the previous key, lost CR-separated lines or miscounted a long line
 * fails here. */
#include "tap.h"

#include "geardyn/geardyn.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static const char *const shipped[] = {
    "cases/quickstart.ini", "cases/validation/kahraman-singh.ini", "cases/paper/sweep-speed.ini",
    "cases/paper/local-speed-1500rpm.ini", "cases/paper/optimize-alo.ini", "cases/accuracy/rattle-4000rpm.ini",
    "cases/paper/tca-modified.ini", "cases/optimize/compare-test-functions.ini",
};

enum { V_CRLF, V_CR, V_BOM, V_INDENT, V_TRAILING, V_COMMENT, NVARIANTS };
static const char *const vname[] = {"CRLF", "CR", "byte-order mark", "indented", "trailing blanks",
                                    "long comment on top"};

static char *slurp(const char *path, size_t *len)
{
    FILE *fp = fopen(path, "rb");
    if (!fp)
        return NULL;
    char *b = malloc(1 << 20);
    *len = b ? fread(b, 1, (1 << 20) - 1, fp) : 0;
    fclose(fp);
    return b;
}

/* The file rewritten as variant v. */
static void write_variant(const char *text, size_t len, int v, const char *out)
{
    FILE *fp = fopen(out, "wb");
    if (v == V_BOM)
        fputs("\xEF\xBB\xBF", fp);
    if (v == V_COMMENT) {
        fputc(';', fp);
        for (int i = 0; i < 299; i++)
            fputc('x', fp);
        fputc('\n', fp);
    }
    int bol = 1;
    for (size_t i = 0; i < len; i++) {
        char ch = text[i];
        if (bol && v == V_INDENT)
            fputs(" \t", fp);
        bol = ch == '\n';
        if (ch == '\n') {
            if (v == V_TRAILING) fputs("  \t", fp);
            fputs(v == V_CRLF ? "\r\n" : v == V_CR ? "\r" : "\n", fp);
        } else
            fputc(ch, fp);
    }
    fclose(fp);
}

static int load(const char *path, gd_case *c, char *msg, size_t len)
{
    gd_error err = {0};
    if (gd_case_init(c, &err) != GD_OK || gd_case_load(c, path, &err) != GD_OK) {
        snprintf(msg, len, "%s", err.msg);
        return 0;
    }
    return 1;
}

/* Every key of b equals a's, from the line a's came from plus shift; the first difference in why. */
static int same_case(const gd_case *a, const gd_case *b, int shift, char *why, size_t len)
{
    size_t n;
    const gd_keyspec *s = gd_case_schema(&n);
    for (size_t i = 0; i < n; i++) {
        char va[1200], vb[1200];
        int la = 0, lb = 0;
        gd_case_format_value(a, i, va, sizeof va);
        gd_case_format_value(b, i, vb, sizeof vb);
        gd_source sa = gd_case_source(a, i, &la), sb = gd_case_source(b, i, &lb);
        if (strcmp(va, vb) != 0 || sa != sb || (sa == GD_SRC_FILE && lb != la + shift)) {
            snprintf(why, len, "%s.%s: '%s' line %d against '%s' line %d", s[i].section, s[i].key, vb, lb, va, la);
            return 0;
        }
    }
    return 1;
}

int main(void)
{
    const char *root = getenv("GEARDYN_SOURCE");
    char tmp[] = "/tmp/gd-case-text-XXXXXX";
    int fd = mkstemp(tmp);
    if (!root || fd < 0) {
        tap_ok(0, "GEARDYN_SOURCE set and a temporary file");
        return tap_done();
    }
    close(fd);
    for (size_t f = 0; f < sizeof shipped / sizeof shipped[0]; f++) {
        char path[1024], msg[1024] = "";
        snprintf(path, sizeof path, "%s/%s", root, shipped[f]);
        size_t len;
        char *text = slurp(path, &len);
        gd_case ref;
        int ok = text && load(path, &ref, msg, sizeof msg);
        tap_ok(ok, "%s loads as shipped %s", shipped[f], msg);
        for (int v = 0; ok && v < NVARIANTS; v++) {
            gd_case c;
            char why[1400] = "";
            write_variant(text, len, v, tmp);
            int same = load(tmp, &c, why, sizeof why) && same_case(&ref, &c, v == V_COMMENT, why, sizeof why);
            tap_ok(same, "%s, %s: every key the same, from the same line %s", shipped[f], vname[v], why);
            gd_case_free(&c);
        }
        if (ok)
            gd_case_free(&ref);
        free(text);
    }
    unlink(tmp);
    return tap_done();
}
