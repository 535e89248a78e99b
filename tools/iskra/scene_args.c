/* SPDX-License-Identifier: MIT */
/* Shared scene options for the iskra commands (see scene_args.h). */
#include "scene_args.h"
#include "scene/scene_values.h"

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/scene.h"
#include "iskra/tasks.h"

int arg_value(const char *cmd, int argc, char **argv, int *i, const char *name, const char **value)
{
    const char *a = argv[*i];
    size_t n = strlen(name);
    if (strncmp(a, name, n) != 0)
        return 0;
    if (a[n] == '=') {
        *value = a + n + 1;
        return 1;
    }
    if (a[n] != 0)
        return 0;
    if (*i + 1 >= argc) {
        fprintf(stderr, "iskra %s: %s needs a value\n", cmd, name);
        return -1;
    }
    *value = argv[++*i];
    return 1;
}

int arg_long(const char *cmd, const char *opt, const char *s, long lo, long hi, long *out)
{
    char *end;
    errno = 0;
    long v = strtol(s, &end, 10);
    if (*s && *end && !errno && !strpbrk(s, "xX")) {
        /* "1e7" or "2.5e1", as scene files write whole numbers: the value, if whole */
        double d = strtod(s, &end);
        int whole = !*end && isfinite(d) && d == floor(d) && d >= (double)lo && d <= (double)hi;
        v = whole ? (long)d : lo - 1 + (lo == LONG_MIN); /* out of range: refused below */
        if (!whole)
            end = (char *)"x";
    }
    if (!*s || *end || errno || v < lo || v > hi || s[0] == '+' || s[0] == ' ') {
        fprintf(stderr, "iskra %s: %s: expected a whole number between %ld and %ld, got \"%s\"\n", cmd, opt, lo,
                hi, s);
        return 0;
    }
    *out = v;
    return 1;
}

int arg_double_pos(const char *cmd, const char *opt, const char *s, double *out)
{
    char *end;
    errno = 0;
    double v = strtod(s, &end);
    if (!*s || *end || !isfinite(v) || !(v > 0) || v > 1000) {
        fprintf(stderr, "iskra %s: %s: expected a number > 0 and <= 1000, got \"%s\"\n", cmd, opt, s);
        return 0;
    }
    *out = v;
    return 1;
}

int scene_args_take(scene_args *a, int argc, char **argv, int *i)
{
    const char *v;
    int r;
    long n;
    if ((r = arg_value(a->cmd, argc, argv, i, "--seed", &v)) != 0) {
        if (r < 0)
            return -1;
        if (!isk__scv_u64(v, &a->seed)) {
            fprintf(stderr, "iskra %s: --seed: expected a whole number between 0 and 18446744073709551615, got \"%s\"\n",
                    a->cmd, v);
            return -1;
        }
        a->have_seed = 1;
        return 1;
    }
    if ((r = arg_value(a->cmd, argc, argv, i, "--size", &v)) != 0) {
        if (r < 0)
            return -1;
        char *end;
        errno = 0;
        long w = strtol(v, &end, 10), h = 0;
        int ok = end != v && (*end == 'x' || *end == 'X') && !errno && v[0] != '+' && v[0] != '-';
        if (ok) {
            const char *hs = end + 1;
            h = strtol(hs, &end, 10);
            ok = end != hs && !*end && !errno && hs[0] != '+' && hs[0] != '-';
        }
        if (!ok || w < 1 || h < 1 || w > ISK_CANVAS_MAX_DIM || h > ISK_CANVAS_MAX_DIM) {
            fprintf(stderr, "iskra %s: --size: expected WIDTHxHEIGHT, each 1..%d (e.g. 800x600), got \"%s\"\n",
                    a->cmd, ISK_CANVAS_MAX_DIM, v);
            return -1;
        }
        a->width = (int)w;
        a->height = (int)h;
        return 1;
    }
    if ((r = arg_value(a->cmd, argc, argv, i, "--dt", &v)) != 0) {
        if (r < 0 || !arg_double_pos(a->cmd, "--dt", v, &a->dt))
            return -1;
        return 1;
    }
    if ((r = arg_value(a->cmd, argc, argv, i, "--substeps", &v)) != 0) {
        if (r < 0 || !arg_long(a->cmd, "--substeps", v, 1, 1000, &n))
            return -1;
        a->substeps = (int)n;
        return 1;
    }
    if ((r = arg_value(a->cmd, argc, argv, i, "--threads", &v)) != 0) {
        if (r < 0 || !arg_long(a->cmd, "--threads", v, 1, 256, &n))
            return -1;
        a->threads = (int)n;
        return 1;
    }
    if ((r = arg_value(a->cmd, argc, argv, i, "--max-memory", &v)) != 0) {
        /* whole bytes, or with a binary suffix: 512M, 8G */
        char *end;
        errno = 0;
        unsigned long long b = strtoull(v, &end, 10);
        int shift = *end == 'K' || *end == 'k' ? 10 : *end == 'M' || *end == 'm' ? 20 : *end == 'G' || *end == 'g' ? 30 : 0;
        if (shift)
            end++;
        if (r < 0 || end == v || *end || errno || v[0] == '-' || v[0] == '+' || b == 0) {
            if (r > 0)
                fprintf(stderr, "iskra %s: --max-memory: expected a size in bytes such as 512M or 8G, got \"%s\"\n",
                        a->cmd, v);
            return -1;
        }
        if (b > (unsigned long long)(SIZE_MAX >> shift)) { /* 4G and more on a 32-bit system */
            fprintf(stderr, "iskra %s: --max-memory: %s is more than this program can address (at most %zu bytes)\n",
                    a->cmd, v, (size_t)SIZE_MAX);
            return -1;
        }
        a->max_memory = (size_t)b << shift;
        return 1;
    }
    if ((r = arg_value(a->cmd, argc, argv, i, "--max-work", &v)) != 0) {
        /* units of work a frame (or the prewarm) may ask for: 5e9, 2000000000 */
        char *end;
        errno = 0;
        double w = r > 0 ? strtod(v, &end) : 0;
        if (r < 0 || end == v || *end || errno || !isfinite(w) || !(w >= 1) || v[0] == '+' || v[0] == ' ') {
            if (r > 0)
                fprintf(stderr, "iskra %s: --max-work: expected a number of units >= 1 such as 5e9, got \"%s\"\n",
                        a->cmd, v);
            return -1;
        }
        a->max_work = w;
        return 1;
    }
    const char *s = argv[*i];
    if (s[0] == '-' && s[1]) {
        fprintf(stderr, "iskra %s: unknown option '%s' (iskra %s --help)\n", a->cmd, s, a->cmd);
        return -1;
    }
    if (a->scene) {
        fprintf(stderr, "iskra %s: one scene only (got '%s' and '%s')\n", a->cmd, a->scene, s);
        return -1;
    }
    a->scene = s;
    return 1;
}

void scene_args_help(FILE *f)
{
    fprintf(f, "  SCENE            a scene file (.ini) or a built-in scene name (iskra list)\n"
               "  --seed N         random seed, 0..2^64-1 (default: the scene's)\n"
               "  --size WxH       canvas size in pixels, e.g. 800x600 (default: the scene's)\n"
               "  --dt SECONDS     time step per frame, > 0 (default: the scene's)\n"
               "  --substeps N     substeps per frame, 1..1000 (default: the scene's)\n"
               "  --threads N      threads to step on, 1..256 (default: ISKRA_THREADS, else every core;\n"
               "                   the result is the same for every number)\n"
               "  --max-memory B   the most memory the scene may take with every pool full, with what\n"
               "                   the command holds to write it (a GIF's tables, a strip), in bytes\n"
               "                   or with K, M, G (default: the smaller of %juG and half the address\n"
               "                   space); a scene that could need more is refused\n"
               "  --max-work N     the most work a frame or the prewarm may ask for, in particle-steps and\n"
               "                   pixels drawn, counted at their worst (default %.0e); more is refused\n",
            ISK_EFFECT_MAX_MEMORY_CEILING >> 30, ISK_EFFECT_DEFAULT_MAX_WORK);
}

/* What the scene shows besides its background: a drawing, a deflector
 * shown, an emitter that draws its particles, a potential drawn as a disc.
 * NULL when nothing is drawn, else the first such thing. */
static const char *first_drawn(const isk_effect_def *d)
{
    if (d->ndrawings > 0)
        return "drawing";
    for (int i = 0; i < d->ndeflectors; i++)
        if (d->deflectors[i].show)
            return "deflector";
    for (int i = 0; i < d->nemitters; i++)
        if (d->emitters[i].look.draw != ISK_DRAW_NONE)
            return "emitter";
    for (int i = 0; i < d->nforces; i++)
        if (d->forces[i].kind == ISK_FORCE_POTENTIAL && d->forces[i].draw && d->forces[i].pot.enabled)
            return "potential";
    return NULL;
}

/* A scene that draws nothing renders its background alone, which looks
 * like a broken renderer: say so (a warning; the scene is valid). */
static void warn_if_nothing_drawn(const scene_args *a, const isk_effect_def *d)
{
    if (first_drawn(d))
        return;
    if (d->nemitters > 0)
        fprintf(stderr, "iskra %s: warning: %s: nothing is drawn: every emitter has draw = none and there is no "
                        "[drawing NAME] section (the picture is the background alone)\n",
                a->cmd, a->scene);
    else
        fprintf(stderr, "iskra %s: warning: %s: nothing is drawn: the scene has no [emitter NAME] or "
                        "[drawing NAME] section (the picture is the background alone)\n",
                a->cmd, a->scene);
}

int scene_args_load(const scene_args *a, isk_effect_def *def, isk_effect **fx, char *why, size_t n)
{
    isk_error err;
    if (!a->scene) {
        snprintf(why, n, "iskra %s: which scene? (iskra %s --help)", a->cmd, a->cmd);
        isk_effect_def_init(def);
        return 2;
    }
    isk_status s = a->text ? isk_scene_load_string(def, a->text, a->scene, &err) : isk_scene_load(def, a->scene, &err);
    if (s != ISK_OK) {
        snprintf(why, n, "%s", err.message);
        return s == ISK_ERR_NOMEM ? 1 : 2;
    }
    if (a->have_seed)
        def->seed = a->seed;
    if (a->width) {
        def->width = a->width;
        def->height = a->height;
    }
    if (a->dt > 0)
        def->dt = a->dt;
    if (a->substeps)
        def->substeps = a->substeps;
    def->max_memory = a->max_memory;
    def->max_work = a->max_work;
    if (a->host_needs)
        a->host_needs(def, a->host_ctx);
    def->threads = a->threads;
    s = isk_effect_create(fx, def, &err);
    if (s != ISK_OK) {
        /* "emitter 'x' (line 12): why" -> "FILE:12: emitter 'x': why", like the parser's */
        const char *lp = strstr(err.message, " (line ");
        int line = 0, used = 0;
        if (lp && sscanf(lp, " (line %d)%n", &line, &used) == 1 && used > 0 && line > 0)
            snprintf(why, n, "%s:%d: %.*s%s", a->scene, line, (int)(lp - err.message), err.message, lp + used);
        else
            snprintf(why, n, "%s: %s", a->scene, err.message);
        isk_effect_def_free(def);
        isk_effect_def_init(def);
        return s == ISK_ERR_NOMEM ? 1 : 2;
    }
    warn_if_nothing_drawn(a, def);
    return 0;
}

int scene_args_open(const scene_args *a, isk_effect_def *def, isk_effect **fx)
{
    /* The library ignores a bad ISKRA_THREADS (it has no one to tell):
     * say so, unless --threads makes it moot. */
    const char *env = getenv("ISKRA_THREADS");
    if (!a->threads && env && *env && !isk_threads_from_text(env))
        fprintf(stderr, "iskra %s: ISKRA_THREADS=\"%s\" is not a number of threads 1..%d: ignored, every core is "
                        "used\n", a->cmd, env, ISK_TASKS_MAX_WORKERS);
    char why[1024];
    int rc = scene_args_load(a, def, fx, why, sizeof why);
    if (rc)
        fprintf(stderr, "%s\n", why);
    return rc;
}
