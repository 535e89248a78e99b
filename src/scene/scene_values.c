/* SPDX-License-Identifier: MIT */
/* Value syntax of scene files (see scene_values.h). */
#include "scene_values.h"
#include "scene/ini_read.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Length of a strict decimal number at the start of s, 0 if there is none. */
static size_t decimal_len(const char *s)
{
    size_t i = 0, digits = 0;
    if (s[i] == '+' || s[i] == '-')
        i++;
    while (isdigit((unsigned char)s[i]))
        i++, digits++;
    if (s[i] == '.') {
        i++;
        while (isdigit((unsigned char)s[i]))
            i++, digits++;
    }
    if (!digits)
        return 0;
    if (s[i] == 'e' || s[i] == 'E') {
        size_t j = i + 1, ed = 0;
        if (s[j] == '+' || s[j] == '-')
            j++;
        while (isdigit((unsigned char)s[j]))
            j++, ed++;
        if (!ed)
            return 0; /* "1e" is not a number */
        i = j;
    }
    return i;
}

static int decimal(const char *s, size_t len, double *out)
{
    char buf[SCV_ITEM_MAX];
    if (len >= sizeof buf)
        return 0;
    memcpy(buf, s, len);
    buf[len] = 0;
    char *end;
    errno = 0;
    double v = strtod(buf, &end);
    if (end != buf + len || !isfinite(v))
        return 0;
    *out = v;
    return 1;
}

int isk__scv_number(const char *s, double *out)
{
    if (!s)
        return 0;
    size_t n = decimal_len(s);
    if (!n)
        return 0;
    double a;
    if (!decimal(s, n, &a))
        return 0;
    if (s[n] == 0) {
        *out = a;
        return 1;
    }
    /* a fraction "a/b", optional blanks around the slash */
    const char *p = s + n;
    while (*p == ' ' || *p == '\t')
        p++;
    if (*p != '/')
        return 0;
    p++;
    while (*p == ' ' || *p == '\t')
        p++;
    size_t m = decimal_len(p);
    double b;
    if (!m || p[m] != 0 || !decimal(p, m, &b) || b == 0.0)
        return 0;
    double q = a / b;
    if (!isfinite(q))
        return 0;
    *out = q;
    return 1;
}

int isk__scv_u64(const char *s, uint64_t *out)
{
    if (!s || !*s)
        return 0;
    uint64_t v = 0;
    for (const char *p = s; *p; p++) {
        if (!isdigit((unsigned char)*p))
            return 0;
        unsigned d = (unsigned)(*p - '0');
        if (v > (UINT64_MAX - d) / 10u)
            return 0;
        v = v * 10u + d;
    }
    *out = v;
    return 1;
}

/* Equal but for the case of ASCII letters. */
static int same_word(const char *a, const char *b)
{
    while (*a && *b && tolower((unsigned char)*a) == tolower((unsigned char)*b))
        a++, b++;
    return !*a && !*b;
}

int isk__scv_lookup(const char *s, const char *const *names, int n)
{
    for (int i = 0; i < n; i++)
        if (same_word(s, names[i]))
            return i;
    return -1;
}

int isk__scv_bool(const char *s, int *out)
{
    static const char *const names[] = {"false", "true", "no", "yes", "off", "on", "0", "1"};
    int i = isk__scv_lookup(s, names, 8);
    if (i < 0)
        return 0;
    *out = i & 1;
    return 1;
}

/* CSS colour names (a useful subset; the values are CSS's). */
static const struct {
    const char *name;
    uint8_t r, g, b, a;
} colors[] = {
    {"black", 0, 0, 0, 255},         {"white", 255, 255, 255, 255},  {"red", 255, 0, 0, 255},
    {"green", 0, 128, 0, 255},       {"lime", 0, 255, 0, 255},       {"blue", 0, 0, 255, 255},
    {"yellow", 255, 255, 0, 255},    {"orange", 255, 165, 0, 255},   {"cyan", 0, 255, 255, 255},
    {"aqua", 0, 255, 255, 255},      {"magenta", 255, 0, 255, 255},  {"fuchsia", 255, 0, 255, 255},
    {"gray", 128, 128, 128, 255},    {"grey", 128, 128, 128, 255},   {"silver", 192, 192, 192, 255},
    {"maroon", 128, 0, 0, 255},      {"navy", 0, 0, 128, 255},       {"olive", 128, 128, 0, 255},
    {"purple", 128, 0, 128, 255},    {"teal", 0, 128, 128, 255},     {"brown", 165, 42, 42, 255},
    {"pink", 255, 192, 203, 255},    {"gold", 255, 215, 0, 255},     {"orangered", 255, 69, 0, 255},
    {"darkred", 139, 0, 0, 255},     {"skyblue", 135, 206, 235, 255}, {"darkgray", 169, 169, 169, 255},
    {"lightgray", 211, 211, 211, 255}, {"transparent", 0, 0, 0, 0},
};
#define NCOLORS ((int)(sizeof colors / sizeof colors[0]))

const int isk__scv_color_count = NCOLORS;

const char *isk__scv_color_name_at(int i)
{
    return i >= 0 && i < NCOLORS ? colors[i].name : NULL;
}

static int hexval(char c)
{
    if (c >= '0' && c <= '9')
        return c - '0';
    c = (char)tolower((unsigned char)c);
    if (c >= 'a' && c <= 'f')
        return c - 'a' + 10;
    return -1;
}

int isk__scv_color(const char *s, isk_color *out)
{
    if (!s)
        return 0;
    if (s[0] == '#') {
        size_t n = strlen(s + 1);
        if (n != 6 && n != 8)
            return 0;
        uint8_t ch[4] = {0, 0, 0, 255};
        for (size_t i = 0; i < n; i += 2) {
            int hi = hexval(s[1 + i]), lo = hexval(s[2 + i]);
            if (hi < 0 || lo < 0)
                return 0;
            ch[i / 2] = (uint8_t)(hi * 16 + lo);
        }
        *out = isk_rgba(ch[0], ch[1], ch[2], ch[3]);
        return 1;
    }
    for (int i = 0; i < NCOLORS; i++)
        if (same_word(s, colors[i].name)) {
            *out = isk_rgba(colors[i].r, colors[i].g, colors[i].b, colors[i].a);
            return 1;
        }
    return 0;
}

char *isk__scv_trim(char *s)
{
    while (*s == ' ' || *s == '\t')
        s++;
    size_t n = strlen(s);
    while (n && (s[n - 1] == ' ' || s[n - 1] == '\t' || s[n - 1] == '\r'))
        s[--n] = 0;
    return s;
}

int isk__scv_split(const char *s, char *buf, size_t bufsize, char sep, char **items, int max, int *n)
{
    *n = 0;
    size_t len = strlen(s);
    if (len + 1 > bufsize)
        return 0;
    memcpy(buf, s, len + 1);
    if (!*isk__scv_trim(buf))
        return 1;
    char *p = buf;
    for (;;) {
        char *c = strchr(p, sep);
        if (c)
            *c = 0;
        char *item = isk__scv_trim(p);
        if (!*item || *n >= max)
            return 0;
        items[(*n)++] = item;
        if (!c)
            return 1;
        p = c + 1;
    }
}

const char *isk__scv_suggest(const char *word, const char *const *names, int count)
{
    const char *s = isk__ini_suggest(word, names, (size_t)count);
    if (s)
        return s;
    size_t n = strlen(word);
    for (int i = 0; i < count; i++) {
        if (strlen(names[i]) != n)
            continue;
        size_t a = 0;
        while (a < n && word[a] == names[i][a])
            a++;
        if (a + 1 < n && word[a] == names[i][a + 1] && word[a + 1] == names[i][a] &&
            !strcmp(word + a + 2, names[i] + a + 2))
            return names[i];
    }
    return NULL;
}

const char *isk__scv_color_name(isk_color c)
{
    for (int i = 0; i < NCOLORS; i++)
        if (colors[i].r == c.r && colors[i].g == c.g && colors[i].b == c.b && colors[i].a == c.a)
            return colors[i].name;
    return NULL;
}
