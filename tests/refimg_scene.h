/* SPDX-License-Identifier: MIT */
/* tests/refimg_scene.h — a reference-image test's canvas, made and checked
 * (header-only; include it after <criterion/criterion.h>).
 *
 *     isk_canvas c = refimg_canvas(64, 48, ISK_BLACK);
 *     // draw on c
 *     refimg_expect("my_scene", &c);   // compares with refimg/my_scene.png, frees c
 */
#ifndef ISKRA_TESTS_REFIMG_SCENE_H
#define ISKRA_TESTS_REFIMG_SCENE_H

#include "iskra/canvas.h"
#include "refimg.h"

static inline isk_canvas refimg_canvas(int w, int h, isk_color bg)
{
    isk_canvas c;
    cr_assert_eq(isk_canvas_init(&c, w, h), ISK_OK);
    isk_canvas_fill(&c, bg);
    return c;
}

static inline void refimg_expect(const char *name, isk_canvas *c)
{
    cr_assert(refimg_check(name, c), "refimg %s differs", name);
    isk_canvas_free(c);
}

#endif
