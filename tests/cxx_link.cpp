/* SPDX-License-Identifier: MIT */
// Every public header, compiled and linked as C++ (g++ -std=c++11 -Wall
// -Wextra -Wpedantic -Werror): the extern "C" guards, no C-only syntax in a
// header, and the symbols link.  tests/run_all.sh runs the result.
#include <iskra.h>
#include <iskra/sdl.h>
#include <iskra/ui_sdl.h>

#include <cstdio>
#include <cstring>

int main()
{
    if (std::strcmp(isk_version(), ISKRA_VERSION_STRING) != 0)
        return 1;
    isk_canvas c;
    if (isk_canvas_init(&c, 16, 16) != ISK_OK)
        return 2;
    isk_canvas_fill(&c, ISK_BLACK);
    isk_draw_dot(&c, 3.5, 4.25, ISK_YELLOW, ISK_BLEND_ADD);
    isk_effect_def d;
    isk_effect_def_init(&d);
    d.width = 16;
    d.height = 16;
    isk_emitter_def *e = isk_effect_def_add_emitter(&d, "p");
    e->born.source = ISK_SOURCE_PARTICLE;
    isk_effect *fx = nullptr;
    isk_error err;
    if (isk_effect_create(&fx, &d, &err) != ISK_OK) {
        std::fprintf(stderr, "%s\n", err.message);
        return 3;
    }
    if (isk_effect_set(fx, "emitter p", "color", "red", &err) != ISK_OK || isk_effect_step(fx) != ISK_OK ||
        isk_effect_render(fx, &c) != ISK_OK)
        return 4;
    const isk_key *k = isk_key_find(ISK_SECTION_SCENE, "dt");
    isk_effect_destroy(fx);
    isk_effect_def_free(&d);
    isk_canvas_free(&c);
    std::printf("cxx_link: iskra %s, %d keys, dt <= %g\n", isk_version(), isk_key_count(), k ? k->max : 0.0);
    return 0;
}
