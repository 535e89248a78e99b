/* SPDX-License-Identifier: MIT */
/* The library's layers, read from its sources and its object files.
 *
 * Data flows one way (docs/architecture.md, "Modules"): core <- raster <-
 * view <- sim <- scene; io, ui and chart depend on raster only; the
 * teaching API (teach) sits above sim and view.  Checked here:
 *   - every #include "..." of src/ and include/iskra/ names a header of a
 *     module its file may use (the table below, written once);
 *   - every call between the library's objects (nm: a name one object
 *     needs and another defines) goes the same way;
 *   - no two files of a module call each other, directly or round a
 *     longer circle;
 *   - the library touches no file at run time: only src/io and the scene
 *     module's file readers and writers call the C library's file-system
 *     functions (that it reads no clock is test_hygiene's check).
 * The known exceptions are listed with why; each must still be found, so
 * one that is fixed is deleted from the list too. */
#include <criterion/criterion.h>
#include <criterion/logging.h>
#include <glob.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "refimg.h"

/* ---- the rule, once --------------------------------------------------------------- */

/* Each module of src/ (and the header-only bridge ui_sdl), and the
 * modules its files may include and call besides itself. */
static const struct {
    const char *module, *may_use;
} layers[] = {
    {"core", ""},
    {"raster", "core"},
    {"view", "raster core"},
    {"sim", "core"},
    {"teach", "sim view raster core"},
    {"scene", "sim view raster core io"}, /* io: only the files in scene_files[] */
    {"io", "raster core"},
    {"ui", "raster core"},
    {"chart", "raster core"},
    {"ui_sdl", "ui io raster core"}, /* iskra/ui_sdl.h: the window's events for the widgets */
};

/* The module each public header belongs to. */
static const struct {
    const char *header, *module;
} headers[] = {
    {"version.h", "core"},     {"color.h", "core"},        {"status.h", "core"},     {"rng.h", "core"},
    {"sinlut.h", "core"},      {"gradient.h", "core"},     {"timestep.h", "core"},   {"vec2.h", "core"},
    {"canvas.h", "raster"},    {"blend.h", "raster"},      {"blend_inline.h", "raster"},
    {"blend_inline_sse2.h", "raster"},
    {"draw.h", "raster"},      {"text.h", "raster"},       {"sprite.h", "raster"},   {"texture.h", "raster"},
    {"view.h", "view"},
    {"particles.h", "sim"},    {"forces.h", "sim"},        {"integrate.h", "sim"},   {"impact.h", "sim"},
    {"bounds.h", "sim"},       {"explode.h", "sim"},       {"system.h", "sim"},      {"deflector.h", "sim"},
    {"contacts.h", "sim"},
    {"shape.h", "sim"},        {"problems.h", "sim"},      {"limits.h", "sim"},      {"tasks.h", "sim"},
    {"teach.h", "teach"},
    {"keys.h", "scene"},       {"effect.h", "scene"},      {"scene.h", "scene"},     {"presets.h", "scene"},
    {"snapshot.h", "scene"},   {"timeline.h", "scene"},    {"probes.h", "scene"},    {"stability.h", "scene"},
    {"png.h", "io"},           {"texture_png.h", "io"},    {"anim.h", "io"},         {"outfile.h", "io"},
    {"refimg.h", "io"},        {"sdl.h", "io"},
    {"ui.h", "ui"},            {"ui_sdl.h", "ui_sdl"},
    {"chart.h", "chart"},
};

/* The scene module's files that read and write files: the loader (scene
 * text, the PNGs its emitters name, the files built in with the built-in
 * scenes) and isk_scene_save.  They resolve every path while loading, so
 * the rest of the scene module (the effect's runtime) opens none. */
static const char *const scene_files[] = {
    "src/scene/ini_read.c",      "src/scene/ini_read.h",      "src/scene/scene_parse.c", "src/scene/scene_load.c",
    "src/scene/scene_load.h",    "src/scene/scene_textures.c", "src/scene/scene_builtin.c",
    "src/scene/scene_write.c",   "src/scene/snapshot_file.c",
};

/* Names of the C library that open, find or change files. */
static const char *const file_functions[] = {
    "fopen", "fopen64", "freopen", "fdopen", "open", "open64", "openat", "creat", "access", "faccessat",
    "euidaccess", "stat", "stat64", "lstat", "lstat64", "fstatat", "__xstat", "__xstat64", "__lxstat",
    "__fxstatat", "opendir", "fdopendir", "scandir", "unlink", "unlinkat", "remove", "rename", "renameat",
    "mkdir", "mkdirat", "rmdir", "tmpfile", "mkstemp", "mkstemps", "mkdtemp", "realpath", "chdir", "getcwd",
    "truncate", "dlopen", "popen", "system",
};

/* Known exceptions, each with why.  Includes: a file (or every file under
 * a folder, ending in '/') and the header it includes. */
static const struct {
    const char *from, *header, *why;
} known_includes[] = {
    {NULL, NULL, NULL}, /* none: a row names a file (or folder/), a header and why */
};
/* Circles between two files (a calls or names b's, b a's). */
static const struct {
    const char *a, *b, *why;
} known_circles[] = {
    {"src/ui/ui.c", "src/ui/ui_choice.c", "the popups call the widget state's functions and it draws them"},
};

/* ---- small helpers ---------------------------------------------------------------- */

static int in_words(const char *word, const char *words)
{
    size_t n = strlen(word);
    for (const char *p = words; (p = strstr(p, word)) != NULL; p += n)
        if ((p == words || p[-1] == ' ') && (p[n] == 0 || p[n] == ' '))
            return 1;
    return 0;
}

static int layer_of(const char *module)
{
    for (size_t i = 0; i < sizeof layers / sizeof layers[0]; i++)
        if (!strcmp(layers[i].module, module))
            return (int)i;
    return -1;
}

static int may_use(const char *from, const char *to)
{
    int k = layer_of(from);
    return !strcmp(from, to) || (k >= 0 && in_words(to, layers[k].may_use));
}

static int is_scene_file(const char *path)
{
    for (size_t i = 0; i < sizeof scene_files / sizeof scene_files[0]; i++)
        if (!strcmp(scene_files[i], path))
            return 1;
    return 0;
}

/* "src/sim/x.c" -> "sim" (in buf). */
static const char *module_of_path(const char *path, char *buf, size_t n)
{
    const char *a = path + 4, *b = strchr(a, '/');
    size_t len = b ? (size_t)(b - a) : 0;
    len = len < n ? len : n - 1;
    memcpy(buf, a, len);
    buf[len] = 0;
    return buf;
}

static const char *module_of_header(const char *name)
{
    for (size_t i = 0; i < sizeof headers / sizeof headers[0]; i++)
        if (!strcmp(headers[i].header, name))
            return headers[i].module;
    return NULL;
}

typedef struct paths {
    glob_t g;
} paths;

static size_t find(paths *p, const char *pattern)
{
    memset(p, 0, sizeof *p);
    int r = glob(pattern, 0, NULL, &p->g);
    cr_assert(r == 0 || r == GLOB_NOMATCH, "glob %s", pattern);
    return p->g.gl_pathc;
}

/* ---- includes ----------------------------------------------------------------------- */

typedef struct tally {
    int violations;
    int used[sizeof known_includes / sizeof known_includes[0]];
} tally;

/* The module an #include "name" of a file of module `from` reaches;
 * NULL when it is not the library's (asserted against below). */
static const char *target_module(const char *from, const char *name, char *buf, size_t n)
{
    if (!strncmp(name, "iskra/", 6))
        return module_of_header(name + 6);
    const char *slash = strchr(name, '/');
    if (!slash)
        return from; /* a header beside the file (or scenes_gen.h, generated for scene_builtin.c) */
    snprintf(buf, n, "%.*s", (int)(slash - name), name);
    return layer_of(buf) >= 0 ? buf : NULL;
}

static void check_includes_of(const char *path, const char *module, tally *t)
{
    FILE *f = fopen(path, "r");
    cr_assert_not_null(f, "%s", path);
    char line[512];
    for (int no = 1; fgets(line, sizeof line, f); no++) {
        char name[256], buf[64];
        if (sscanf(line, " # include \"%255[^\"]\"", name) != 1)
            continue;
        const char *to = target_module(module, name, buf, sizeof buf);
        cr_assert_not_null(to, "%s:%d: #include \"%s\": no module of the table in tests/test_layers.c has it", path,
                           no, name);
        int ok = may_use(module, to) && (strcmp(to, "io") || strcmp(module, "scene") || is_scene_file(path));
        for (size_t k = 0; !ok && k < sizeof known_includes / sizeof known_includes[0] && known_includes[k].from; k++) {
            size_t n = strlen(known_includes[k].from);
            int file_match = known_includes[k].from[n - 1] == '/' ? !strncmp(path, known_includes[k].from, n)
                                                                  : !strcmp(path, known_includes[k].from);
            if (file_match && !strcmp(name, known_includes[k].header)) {
                ok = 1;
                t->used[k] = 1;
            }
        }
        if (!ok) {
            cr_log_error("%s:%d: #include \"%s\": %s may use %s%s", path, no, name, module,
                         *layers[layer_of(module)].may_use ? layers[layer_of(module)].may_use : "no other module",
                         !strcmp(to, "io") ? " (io: only the scene module's file readers)" : "");
            t->violations++;
        }
    }
    fclose(f);
}

Test(layers, every_include_follows_the_layers)
{
    tally t = {0};
    paths p;
    size_t n = find(&p, "src/*/*.[ch]");
    cr_assert_gt(n, 100);
    for (size_t i = 0; i < n; i++) {
        char mod[64];
        const char *path = p.g.gl_pathv[i];
        module_of_path(path, mod, sizeof mod);
        cr_assert_geq(layer_of(mod), 0, "%s: the module %s has no row in tests/test_layers.c (layers[])", path, mod);
        check_includes_of(path, mod, &t);
    }
    globfree(&p.g);
    n = find(&p, "include/iskra/*.h");
    cr_assert_gt(n, 30);
    for (size_t i = 0; i < n; i++) {
        const char *path = p.g.gl_pathv[i];
        const char *mod = module_of_header(strrchr(path, '/') + 1);
        cr_assert_not_null(mod, "%s: no module in tests/test_layers.c (headers[]): say where it belongs", path);
        check_includes_of(path, mod, &t);
    }
    globfree(&p.g);
    cr_assert_eq(t.violations, 0, "%d includes against the layers (above)", t.violations);
    for (size_t k = 0; k < sizeof known_includes / sizeof known_includes[0] && known_includes[k].from; k++)
        cr_assert(t.used[k], "no file of %s includes %s any more: delete its exception in tests/test_layers.c",
                  known_includes[k].from, known_includes[k].header);
}

/* Every row of the tables names something that exists. */
Test(layers, the_tables_name_what_exists)
{
    for (size_t i = 0; i < sizeof headers / sizeof headers[0]; i++) {
        char path[128];
        snprintf(path, sizeof path, "include/iskra/%s", headers[i].header);
        FILE *f = fopen(path, "r");
        cr_assert_not_null(f, "tests/test_layers.c names %s", path);
        fclose(f);
        cr_assert_geq(layer_of(headers[i].module), 0, "%s: module %s", path, headers[i].module);
    }
    for (size_t i = 0; i < sizeof scene_files / sizeof scene_files[0]; i++) {
        FILE *f = fopen(scene_files[i], "r");
        cr_assert_not_null(f, "tests/test_layers.c names %s", scene_files[i]);
        fclose(f);
    }
    for (size_t i = 0; i < sizeof layers / sizeof layers[0]; i++)
        for (size_t j = 0; j < sizeof layers / sizeof layers[0]; j++)
            cr_assert(!(i != j && may_use(layers[i].module, layers[j].module) &&
                        may_use(layers[j].module, layers[i].module)),
                      "%s and %s may use each other", layers[i].module, layers[j].module);
}

/* ---- the objects -------------------------------------------------------------------- */

enum { MAX_OBJECTS = 512, MAX_NAMES = 12000 };

typedef struct object {
    char src[128], module[32];
} object;

typedef struct symbol {
    char name[96];
    int object;
    int defined;
} symbol;

typedef struct library {
    object obj[MAX_OBJECTS];
    int nobj;
    symbol *sym;
    int nsym;
} library;

/* Every source file's object (the sources decide: a stale object of a
 * removed file is not read), with its global names from nm. */
static void read_library(library *L)
{
    memset(L, 0, sizeof *L);
    L->sym = calloc(MAX_NAMES, sizeof *L->sym);
    cr_assert_not_null(L->sym);
    paths p;
    size_t n = find(&p, "src/*/*.c");
    cr_assert(n > 50 && n < MAX_OBJECTS);
    for (size_t i = 0; i < n; i++) {
        object *o = &L->obj[L->nobj];
        snprintf(o->src, sizeof o->src, "%s", p.g.gl_pathv[i]);
        module_of_path(o->src, o->module, sizeof o->module);
        char cmd[512];
        snprintf(cmd, sizeof cmd, "nm -P -g %s/obj/%.*s.o", refimg_build_dir(), (int)strlen(o->src) - 2, o->src);
        FILE *f = popen(cmd, "r");
        cr_assert_not_null(f, "%s", cmd);
        char line[512];
        while (fgets(line, sizeof line, f)) {
            char name[256], type[8];
            if (sscanf(line, "%255s %7s", name, type) != 2 || strlen(name) >= sizeof L->sym[0].name)
                continue;
            cr_assert_lt(L->nsym, MAX_NAMES);
            symbol *s = &L->sym[L->nsym++];
            memcpy(s->name, name, strlen(name) + 1); /* fits: checked above */
            s->object = L->nobj;
            s->defined = strchr("TDRBCVW", type[0]) != NULL;
        }
        cr_assert_eq(pclose(f), 0, "%s (is the library built?)", cmd);
        L->nobj++;
    }
    globfree(&p.g);
}

static int definer(const library *L, const char *name)
{
    for (int i = 0; i < L->nsym; i++)
        if (L->sym[i].defined && !strcmp(L->sym[i].name, name))
            return L->sym[i].object;
    return -1;
}

/* calls[a * nobj + b]: object a needs a name object b defines. */
static unsigned char *call_matrix(const library *L)
{
    unsigned char *m = calloc((size_t)L->nobj * (size_t)L->nobj, 1);
    cr_assert_not_null(m);
    for (int i = 0; i < L->nsym; i++) {
        if (L->sym[i].defined)
            continue;
        int b = definer(L, L->sym[i].name);
        if (b >= 0 && b != L->sym[i].object)
            m[L->sym[i].object * L->nobj + b] = 1;
    }
    return m;
}

Test(layers, every_call_follows_the_layers, .timeout = 120)
{
    library L;
    read_library(&L);
    unsigned char *m = call_matrix(&L);
    int bad = 0;
    for (int a = 0; a < L.nobj; a++)
        for (int b = 0; b < L.nobj; b++) {
            if (!m[a * L.nobj + b])
                continue;
            const object *A = &L.obj[a], *B = &L.obj[b];
            int ok = may_use(A->module, B->module) &&
                     (strcmp(B->module, "io") || strcmp(A->module, "scene") || is_scene_file(A->src));
            if (!ok) {
                cr_log_error("%s calls %s: %s may use %s", A->src, B->src, A->module,
                             *layers[layer_of(A->module)].may_use ? layers[layer_of(A->module)].may_use
                                                                  : "no other module");
                bad++;
            }
        }
    free(m);
    free(L.sym);
    cr_assert_eq(bad, 0, "%d calls against the layers (above)", bad);
}

/* Tarjan's strongly connected components over the files of one module:
 * any component of two or more files is a circle of calls. */
typedef struct scc {
    const library *L;
    const unsigned char *m;
    int *index, *low, *stack, *on, depth, top, counter;
    int *comp, ncomp;
} scc;

static void strong(scc *s, int v)
{
    s->index[v] = s->low[v] = s->counter++;
    s->stack[s->top++] = v;
    s->on[v] = 1;
    for (int w = 0; w < s->L->nobj; w++) {
        if (!s->m[v * s->L->nobj + w])
            continue;
        if (s->index[w] < 0) {
            strong(s, w);
            s->low[v] = s->low[w] < s->low[v] ? s->low[w] : s->low[v];
        } else if (s->on[w] && s->index[w] < s->low[v]) {
            s->low[v] = s->index[w];
        }
    }
    if (s->low[v] == s->index[v]) {
        int w;
        do {
            w = s->stack[--s->top];
            s->on[w] = 0;
            s->comp[w] = s->ncomp;
        } while (w != v);
        s->ncomp++;
    }
}

static int known_circle(const char *a, const char *b, int *used)
{
    for (size_t k = 0; k < sizeof known_circles / sizeof known_circles[0]; k++)
        if ((!strcmp(a, known_circles[k].a) && !strcmp(b, known_circles[k].b)) ||
            (!strcmp(a, known_circles[k].b) && !strcmp(b, known_circles[k].a))) {
            used[k] = 1;
            return 1;
        }
    return 0;
}

Test(layers, no_two_files_call_each_other, .timeout = 120)
{
    library L;
    read_library(&L);
    unsigned char *m = call_matrix(&L);
    int n = L.nobj;
    scc s = {&L, m, malloc(sizeof(int) * (size_t)n), malloc(sizeof(int) * (size_t)n),
             malloc(sizeof(int) * (size_t)n), calloc((size_t)n, sizeof(int)), 0, 0, 0,
             malloc(sizeof(int) * (size_t)n), 0};
    cr_assert(s.index && s.low && s.stack && s.on && s.comp);
    for (int v = 0; v < n; v++)
        s.index[v] = -1;
    for (int v = 0; v < n; v++)
        if (s.index[v] < 0)
            strong(&s, v);
    int used[sizeof known_circles / sizeof known_circles[0]] = {0};
    int bad = 0;
    for (int c = 0; c < s.ncomp; c++) {
        int size = 0, first = -1;
        for (int v = 0; v < n; v++)
            if (s.comp[v] == c) {
                size++;
                first = first < 0 ? v : first;
            }
        if (size < 2)
            continue;
        /* a circle of two known files is allowed; every edge of it is shown otherwise */
        int second = -1;
        for (int v = first + 1; v < n && second < 0; v++)
            if (s.comp[v] == c)
                second = v;
        if (size == 2 && known_circle(L.obj[first].src, L.obj[second].src, used))
            continue;
        cr_log_error("a circle of %d files:", size);
        for (int a = 0; a < n; a++)
            for (int b = 0; b < n; b++)
                if (s.comp[a] == c && s.comp[b] == c && m[a * n + b])
                    cr_log_error("  %s -> %s", L.obj[a].src, L.obj[b].src);
        bad++;
    }
    for (size_t k = 0; k < sizeof known_circles / sizeof known_circles[0]; k++)
        cr_assert(used[k], "%s and %s no longer call each other: delete their exception in tests/test_layers.c",
                  known_circles[k].a, known_circles[k].b);
    free(s.index);
    free(s.low);
    free(s.stack);
    free(s.on);
    free(s.comp);
    free(m);
    free(L.sym);
    cr_assert_eq(bad, 0, "%d circles of calls between files (above)", bad);
}

/* The library touches no file at run time: only src/io (which exists to
 * read and write files) and the scene module's file readers and writers
 * call the file-system functions. */
Test(layers, the_runtime_touches_no_file, .timeout = 120)
{
    library L;
    read_library(&L);
    int bad = 0, readers = 0;
    for (int i = 0; i < L.nsym; i++) {
        const symbol *s = &L.sym[i];
        const object *o = &L.obj[s->object];
        if (s->defined)
            continue;
        const int may_touch_files = !strcmp(o->module, "io") || is_scene_file(o->src);
        for (size_t k = 0; k < sizeof file_functions / sizeof file_functions[0]; k++)
            if (!strcmp(s->name, file_functions[k])) {
                readers += may_touch_files;
                if (!may_touch_files) {
                    cr_log_error("%s calls %s: only src/io and the scene module's file readers touch files", o->src,
                                 s->name);
                    bad++;
                }
            }
    }
    free(L.sym);
    cr_assert_gt(readers, 3, "the check sees the PNG reader and the scene loader open files");
    cr_assert_eq(bad, 0, "%d calls against the rule (above)", bad);
}
