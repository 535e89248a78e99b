/* SPDX-License-Identifier: MIT */
/* tests/fuzz/scene_mutator.h — a structure-aware mutator for scene files,
 * driven by the key table (iskra/keys.h), for tests/fuzz/fuzz_scene.c.
 *
 * Byte-level mutation rarely turns "rate = 20" into "rate = 1e7" or moves a
 * key into the section where it means something else.  Each call picks one
 * of these, from libFuzzer's seed (deterministic):
 *   - a key's value becomes an extreme of its documented range: its min or
 *     max, just past them, +-1e308, 1e-300, 0, -1, a word it accepts, one
 *     of its names, an empty list;
 *   - a "key = value" line moves to another section (swapping keys between
 *     sections, so kinds and applicability get exercised);
 *   - a section is copied under another name, or a new section of a random
 *     type is added with a random key of it;
 *   - otherwise libFuzzer's own byte mutation.
 * The text stays under max_size; when it would not, libFuzzer's mutation is
 * used instead. */
#ifndef ISKRA_FUZZ_SCENE_MUTATOR_H
#define ISKRA_FUZZ_SCENE_MUTATOR_H

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/keys.h"

size_t LLVMFuzzerMutate(uint8_t *data, size_t size, size_t max_size);

typedef struct mut_rng {
    uint64_t s;
} mut_rng;

static uint32_t mut_next(mut_rng *r)
{
    r->s = r->s * 6364136223846793005ull + 1442695040888963407ull;
    return (uint32_t)(r->s >> 33);
}

static size_t mut_below(mut_rng *r, size_t n) { return n ? mut_next(r) % n : 0; }

/* Line starts of text[0..n): at most max of them. */
static size_t mut_lines(const char *text, size_t n, size_t *starts, size_t max)
{
    size_t k = 0;
    for (size_t i = 0; i < n && k < max; i++)
        if (i == 0 || text[i - 1] == '\n')
            starts[k++] = i;
    return k;
}

static size_t mut_line_end(const char *text, size_t n, size_t start)
{
    while (start < n && text[start] != '\n')
        start++;
    return start;
}

/* An extreme value for row k, as text. */
static void mut_extreme(mut_rng *r, const isk_key *k, char *out, size_t n)
{
    const char *fixed[] = {"1e308", "-1e308", "1e-300", "-1e-300", "0", "-1", "1/0", "268435457", "nan", ""};
    switch (mut_below(r, 6)) {
    case 0:
        if (k->lo_bound) {
            snprintf(out, n, "%.17g", k->min);
            return;
        }
        break;
    case 1:
        if (k->hi_bound) {
            snprintf(out, n, "%.17g", k->max);
            return;
        }
        break;
    case 2:
        if (k->hi_bound) {
            snprintf(out, n, "%.17g", k->max * 1.5 + 1);
            return;
        }
        break;
    case 3:
        if (k->words) {
            snprintf(out, n, "%s", k->words[0].word);
            return;
        }
        if (k->nnames) {
            snprintf(out, n, "%s", k->names[mut_below(r, (size_t)k->nnames)]);
            return;
        }
        break;
    case 4: { /* a list of the right shape with extreme items */
        const char *item = fixed[mut_below(r, 8)];
        snprintf(out, n, "%s, %s, %s, %s", item, fixed[mut_below(r, 8)], item, fixed[mut_below(r, 8)]);
        return;
    }
    default:
        break;
    }
    snprintf(out, n, "%s", fixed[mut_below(r, sizeof fixed / sizeof fixed[0])]);
}

/* The row of "key" in any section (the first), or NULL. */
static const isk_key *mut_row(const char *key, size_t len)
{
    char name[64];
    if (len >= sizeof name)
        return NULL;
    memcpy(name, key, len);
    name[len] = 0;
    for (int s = 0; s < ISK_SECTION_COUNT; s++) {
        const isk_key *k = isk_key_find((isk_section_kind)s, name);
        if (k)
            return k;
    }
    return NULL;
}

static size_t mut_finish(uint8_t *data, size_t max_size, const char *out, size_t len, size_t size)
{
    if (len >= max_size)
        return LLVMFuzzerMutate(data, size, max_size);
    memcpy(data, out, len);
    return len;
}

static size_t scene_mutate(uint8_t *data, size_t size, size_t max_size, unsigned int seed)
{
    mut_rng r = {seed * 2654435761u + 1};
    const char *text = (const char *)data;
    size_t starts[512];
    size_t nl = mut_lines(text, size, starts, 512);
    char *out = malloc(max_size + 256);
    if (!out)
        return LLVMFuzzerMutate(data, size, max_size);
    size_t len = 0, result;
    unsigned op = (unsigned)mut_below(&r, 4);
    if (op == 0 && nl) { /* a value to an extreme of its range */
        size_t li = starts[mut_below(&r, nl)], le = mut_line_end(text, size, li);
        const char *eq = memchr(text + li, '=', le - li);
        size_t klen = eq ? (size_t)(eq - (text + li)) : 0;
        while (klen && text[li + klen - 1] == ' ')
            klen--;
        const isk_key *k = eq ? mut_row(text + li, klen) : NULL;
        if (!k) {
            free(out);
            return LLVMFuzzerMutate(data, size, max_size);
        }
        char v[128];
        mut_extreme(&r, k, v, sizeof v);
        len = (size_t)snprintf(out, max_size + 256, "%.*s = %s%.*s", (int)klen, text + li, v, (int)(size - le),
                               text + le);
        /* keep what came before the line */
        char *whole = malloc(li + len + 1);
        if (!whole) {
            free(out);
            return LLVMFuzzerMutate(data, size, max_size);
        }
        memcpy(whole, text, li);
        memcpy(whole + li, out, len);
        result = mut_finish(data, max_size, whole, li + len, size);
        free(whole);
        free(out);
        return result;
    }
    if (op == 1 && nl > 1) { /* a line moves elsewhere */
        size_t a = mut_below(&r, nl), b = mut_below(&r, nl);
        size_t as = starts[a], ae = mut_line_end(text, size, as);
        for (size_t i = 0; i < nl; i++) {
            if (i == a)
                continue;
            size_t s = starts[i], e = mut_line_end(text, size, s);
            if (i == b) {
                memcpy(out + len, text + as, ae - as);
                len += ae - as;
                out[len++] = '\n';
            }
            memcpy(out + len, text + s, e - s);
            len += e - s;
            out[len++] = '\n';
            if (len > max_size)
                break;
        }
        result = mut_finish(data, max_size, out, len, size);
        free(out);
        return result;
    }
    if (op == 2) { /* a new section with one of its keys */
        int s = (int)mut_below(&r, ISK_SECTION_COUNT);
        const isk_key *k = NULL;
        for (int tries = 0; tries < 8 && (!k || (int)k->section != s); tries++)
            k = isk_key_at((int)mut_below(&r, (size_t)isk_key_count()));
        if (!k)
            k = isk_key_at(0);
        char v[128];
        mut_extreme(&r, k, v, sizeof v);
        len = (size_t)snprintf(out, max_size + 256, "%.*s\n[%s%s]\n%s = %s\n", (int)size, text,
                               isk_section_name(k->section), isk_section_named(k->section) ? " m" : "", k->name, v);
        result = mut_finish(data, max_size, out, len, size);
        free(out);
        return result;
    }
    free(out);
    return LLVMFuzzerMutate(data, size, max_size);
}

#endif
