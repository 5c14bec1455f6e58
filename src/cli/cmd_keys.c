/* geardyn keys: every key of the case schema with its unit, type, range, default and meaning. */
#include "cli.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static const char *type_name(gd_keytype t)
{
    switch (t) {
    case GD_KEY_DOUBLE: return "number";
    case GD_KEY_INT: return "integer";
    case GD_KEY_ENUM: return "choice";
    case GD_KEY_BOOL: return "on/off";
    case GD_KEY_STRING: return "text";
    case GD_KEY_DLIST: return "list of numbers";
    }
    return "?";
}

/* The valid values: [lo, hi] (a parenthesis for an excluded bound), or the choices. */
static void format_range(const gd_keyspec *k, char *buf, size_t len)
{
    switch (k->type) {
    case GD_KEY_DOUBLE:
    case GD_KEY_INT:
    case GD_KEY_DLIST:
        snprintf(buf, len, "%c%.6g, %.6g%c", k->min_open ? '(' : '[', k->min, k->max, k->max_open ? ')' : ']');
        return;
    case GD_KEY_ENUM:
    case GD_KEY_BOOL: {
        size_t o = 0;
        for (const char *p = k->choices; *p && o + 3 < len; p++)
            o += (size_t)snprintf(buf + o, len - o, "%s", *p == '|' ? ", " : (char[2]){*p, 0});
        buf[o < len ? o : len - 1] = 0;
        return;
    }
    case GD_KEY_STRING:
        snprintf(buf, len, "any text");
        return;
    }
}

/* The default as a case file would spell it; "derived" when computed from other keys. */
static void format_default(const gd_case *c, size_t i, const gd_keyspec *k, char *buf, size_t len)
{
    if ((k->type == GD_KEY_DOUBLE && isnan(k->def)) || gd_case_source(c, i, NULL) == GD_SRC_DERIVED) {
        snprintf(buf, len, "derived");
        return;
    }
    gd_case_format_value(c, i, buf, len);
    if (!buf[0])
        snprintf(buf, len, k->type == GD_KEY_DLIST ? "none" : "empty");
}

/* Markdown: a '|' inside a cell is escaped. */
static void md_cell(const char *s)
{
    for (; *s; s++) {
        if (*s == '|')
            fputc('\\', stdout);
        fputc(*s, stdout);
    }
}

static void print_key(const gd_case *c, size_t i, const gd_keyspec *k, int markdown)
{
    char range[512], def[1200];
    format_range(k, range, sizeof range);
    format_default(c, i, k, def, sizeof def);
    if (!markdown) {
        printf("%s.%s%s%s%s: %s; %s%s; default %s\n    %s\n", k->section, k->key, k->unit[0] ? " (" : "", k->unit,
               k->unit[0] ? ")" : "", type_name(k->type), k->type == GD_KEY_STRING ? "" : "valid ", range, def, k->help);
        return;
    }
    const char *cells[] = {k->key, k->unit[0] ? k->unit : "-", type_name(k->type), range, def, k->help};
    fputs("| ", stdout);
    for (size_t j = 0; j < sizeof cells / sizeof cells[0]; j++) {
        int code = j == 0;
        if (code)
            fputc('`', stdout);
        md_cell(cells[j]);
        fputs(code ? "` | " : j + 1 < sizeof cells / sizeof cells[0] ? " | " : " |\n", stdout);
    }
}

int cmd_keys(int argc, char **argv)
{
    int markdown = 0;
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--markdown") == 0) {
            markdown = 1;
        } else {
            fprintf(stderr, "geardyn: keys: unknown option '%s' (valid: --markdown)\n", argv[i]);
            return 2;
        }
    }
    gd_case c;
    gd_error err = {0};
    if (gd_case_init(&c, &err) != GD_OK)
        return cli_fail(&err);
    size_t n;
    const gd_keyspec *s = gd_case_schema(&n);
    if (markdown)
        printf("# Case-file keys\n\n"
               "Every key a case file may set, generated from the schema by `geardyn keys --markdown > "
               "docs/case-keys.md` (the test `case_keys` fails when this file differs from what the tool "
               "prints). Ranges are closed unless written with a parenthesis; `derived` defaults are "
               "computed from other keys (`geardyn check CASE` shows the value and its source).\n");
    const char *sec = "";
    for (size_t i = 0; i < n; i++) {
        if (strcmp(sec, s[i].section) != 0) {
            sec = s[i].section;
            if (markdown)
                printf("\n## [%s]\n\n| key | unit | type | valid | default | meaning |\n|---|---|---|---|---|---|\n", sec);
            else
                printf("%s[%s]\n", i ? "\n" : "", sec);
        }
        print_key(&c, i, &s[i], markdown);
    }
    gd_case_free(&c);
    return 0;
}
