/* SPDX-License-Identifier: MIT */
/* The widgets' names, as scripts use them (press:NAME): every name of the
 * window now (the last frame's, then the inspector's keys scrolled out of
 * view), for --list-widgets, and the likely ones for a name no widget
 * has: names that hold it or that it holds ("explosions" ->
 * "explosion-count"), then the nearest by edit distance. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "play.h"

/* The names seen, so each is given once. */
typedef struct seen {
    char (*names)[ISK_UI_ID_MAX];
    int n, cap;
    void (*name)(void *user, const char *name);
    void *user;
} seen;

static void once(void *user, const char *name)
{
    seen *s = user;
    for (int i = 0; i < s->n; i++)
        if (!strcmp(s->names[i], name))
            return;
    if (s->n == s->cap) {
        int cap = s->cap ? 2 * s->cap : 256;
        void *grown = realloc(s->names, sizeof *s->names * (size_t)cap);
        if (!grown)
            return; /* out of memory: the name is given, perhaps twice */
        s->names = grown;
        s->cap = cap;
    }
    snprintf(s->names[s->n++], ISK_UI_ID_MAX, "%s", name);
    s->name(s->user, name);
}

void play_widget_names(const player *p, void (*name)(void *user, const char *name), void *user)
{
    seen s = {NULL, 0, 0, name, user};
    for (int i = 0; i < p->ui.nitems; i++)
        once(&s, p->ui.items[i].id);
    if (p->panel && p->panel_kind == PLAY_PANEL_INSPECTOR)
        play_inspector_names(p, once, &s);
    free(s.names);
}

/* ---- suggestions --------------------------------------------------------------------------- */

/* Edit distance (insert, delete, replace), 99 for long words. */
static int distance(const char *a, const char *b)
{
    const size_t la = strlen(a), lb = strlen(b);
    if (la >= 64 || lb >= 64)
        return 99;
    int d[64][64];
    for (size_t i = 0; i <= la; i++)
        d[i][0] = (int)i;
    for (size_t j = 0; j <= lb; j++)
        d[0][j] = (int)j;
    for (size_t i = 1; i <= la; i++)
        for (size_t j = 1; j <= lb; j++) {
            int best = d[i - 1][j - 1] + (a[i - 1] != b[j - 1]);
            if (d[i - 1][j] + 1 < best)
                best = d[i - 1][j] + 1;
            if (d[i][j - 1] + 1 < best)
                best = d[i][j - 1] + 1;
            d[i][j] = best;
        }
    return d[la][lb];
}

typedef struct ranked {
    const char *wrong;
    char best[3][ISK_UI_ID_MAX];
    int score[3], n;
} ranked;

/* The last path part of a name ("emitter-flame/rate" -> "rate"). */
static const char *last_part(const char *name)
{
    const char *s = strrchr(name, '/');
    return s ? s + 1 : name;
}

static size_t common_prefix(const char *a, const char *b)
{
    size_t n = 0;
    while (a[n] && a[n] == b[n])
        n++;
    return n;
}

/* A name's score (lower is likelier; 0 not at all), in three kinds: 1-3
 * a name holding the wrong one or held by it; 4-6 one sharing most of its
 * start ("explosions", "explosion-count"); from 10 a close spelling of it
 * or of the name's last part.  Nearer in length first within a kind. */
static int score_of(const char *wrong, const char *name)
{
    const size_t lw = strlen(wrong), ln = strlen(name), diff = ln > lw ? ln - lw : lw - ln;
    const size_t prefix = common_prefix(wrong, name), prefix_last = common_prefix(wrong, last_part(name));
    const size_t shared = prefix > prefix_last ? prefix : prefix_last;
    const int nearer = (int)(diff < 16 ? diff : 16) / 8; /* 0..2 */
    if (strstr(name, wrong) || strstr(wrong, name))
        return 1 + nearer;
    if (shared >= 4 && 5 * shared >= 3 * lw)
        return 4 + nearer;
    int d = distance(wrong, name), e = distance(wrong, last_part(name));
    d = e < d ? e : d;
    const int allowed = (int)lw / 3 + 1;
    return d <= allowed ? 10 + d : 0;
}

static void consider(void *user, const char *name)
{
    ranked *r = user;
    const int sc = score_of(r->wrong, name);
    if (!sc)
        return;
    /* kept in order of score, at most three */
    int at = r->n;
    while (at > 0 && r->score[at - 1] > sc)
        at--;
    if (at >= 3)
        return;
    for (int i = (r->n < 3 ? r->n : 2); i > at; i--) {
        r->score[i] = r->score[i - 1];
        memcpy(r->best[i], r->best[i - 1], sizeof r->best[i]);
    }
    r->score[at] = sc;
    snprintf(r->best[at], sizeof r->best[at], "%s", name);
    if (r->n < 3)
        r->n++;
}

static int kind_of(int score) { return score < 4 ? 0 : score < 10 ? 1 : 2; }

void play_suggest_widget(const player *p, const char *wrong, char *out, size_t n)
{
    ranked r;
    memset(&r, 0, sizeof r);
    r.wrong = wrong;
    play_widget_names(p, consider, &r);
    out[0] = 0;
    if (!r.n)
        return;
    /* only the likeliest kind: a near spelling is not offered beside a name that holds it */
    while (r.n > 1 && kind_of(r.score[r.n - 1]) != kind_of(r.score[0]))
        r.n--;
    size_t used = (size_t)snprintf(out, n, "; did you mean ");
    for (int i = 0; i < r.n && used < n; i++)
        used += (size_t)snprintf(out + used, n - used, "%s'%s'", i == 0 ? "" : i + 1 == r.n ? " or " : ", ", r.best[i]);
    if (used < n)
        snprintf(out + used, n - used, "?");
}
