/* SPDX-License-Identifier: MIT */
/* The tutorial's fountain in C (docs/tutorial.md): the effect of
 * docs/tutorial/step4.ini built from C structs, drawn at frame 120 into
 * fountain.png (the same bytes as the scene file's image), then changed
 * while it runs and drawn again 60 frames later into fountain_tilted.png.
 *
 *     cc fountain.c -o fountain $(pkg-config --cflags --libs iskra) && ./fountain
 */
#include <iskra.h>
#include <stdio.h>

/* Scene files give angles in degrees; C fields hold radians. */
static const double DEG = 3.14159265358979323846 / 180.0;

/* Writes the canvas to a PNG; 0 on success. */
static int save(const isk_canvas *c, const char *path)
{
    isk_error err;
    if (isk_png_write(c, path, &err) != ISK_OK) {
        fprintf(stderr, "%s\n", err.message);
        return 1;
    }
    printf("wrote %s\n", path);
    return 0;
}

int main(void)
{
    /* [scene] and [view] */
    isk_effect_def d;
    isk_effect_def_init(&d); /* every field at its default, as an empty scene file */
    d.width = 320;
    d.height = 240;
    d.background = isk_rgba(0x10, 0x10, 0x18, 0xff);
    d.xmin = -6;
    d.xmax = 6;
    d.ymin = 0;
    d.ymax = 9;

    /* [force gravity] */
    int gravity = isk_effect_def_add_force(&d, "gravity", ISK_FORCE_GRAVITY);
    /* [bounds]: a floor only, keeping half of the speed at a bounce */
    isk_status s = isk_bounds_reflect(&d.bounds, d.xmin, d.xmax, d.ymin, d.ymax, ISK_SIDE_BOTTOM, 0, 0.5);
    /* [emitter sparks] */
    isk_emitter_def *e = isk_effect_def_add_emitter(&d, "sparks");
    if (gravity < 0 || !e || s != ISK_OK) {
        isk_effect_def_free(&d);
        return 1;
    }
    d.forces[gravity].g = 9.81;
    e->born.source = ISK_SOURCE_STREAM;
    e->born.position = (isk_vec2){0, 1};
    e->born.rate = 200;
    e->launch.kind = ISK_VELGEN_CONE;
    e->launch.angle = 90 * DEG;
    e->launch.spread = 40 * DEG;
    e->launch.speed_min = 6;
    e->launch.speed_max = 9;
    e->life.seconds = 2.5;
    isk_emitter_use_force(e, gravity);
    e->look.draw = ISK_DRAW_SPRITE;
    e->look.sprite = ISK_SPRITE_SMOOTH;
    e->look.size = 0.3;
    e->look.blend = ISK_BLEND_ADD;
    e->look.color_over_life.n = 3;
    e->look.color_over_life.stops[0] = (isk_color_stop){0.0, isk_rgba(0xff, 0xf6, 0xc0, 0xff)};
    e->look.color_over_life.stops[1] = (isk_color_stop){0.4, isk_rgba(0xff, 0xa5, 0x00, 0xff)}; /* orange */
    e->look.color_over_life.stops[2] = (isk_color_stop){1.0, isk_rgba(0x80, 0x10, 0x00, 0x00)};

    /* Check and compile the definition: a bad value is refused here, with
     * the message a scene file would get. */
    isk_effect *fx;
    isk_error err;
    s = isk_effect_create(&fx, &d, &err);
    isk_effect_def_free(&d); /* the effect keeps its own copy */
    if (s != ISK_OK) {
        fprintf(stderr, "%s\n", err.message);
        return 1;
    }

    isk_canvas canvas = {0}; /* zeroed: freeing it is safe even if init fails */
    int failed = isk_canvas_init(&canvas, 320, 240) != ISK_OK;
    /* 120 frames of 1/60 s, then draw: the image of frame 120 */
    failed = failed || isk_effect_run(fx, &canvas, 120) != ISK_OK || save(&canvas, "fountain.png");

    /* Change it while it runs, by the names a scene file uses */
    if (!failed && isk_effect_set(fx, "emitter sparks", "angle", "60", &err) != ISK_OK) {
        fprintf(stderr, "%s\n", err.message);
        failed = 1;
    }
    failed = failed || isk_effect_run(fx, &canvas, 60) != ISK_OK || save(&canvas, "fountain_tilted.png");

    isk_canvas_free(&canvas);
    isk_effect_destroy(fx);
    return failed;
}
