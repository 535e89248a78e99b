/* SPDX-License-Identifier: MIT */
/* Knob study "campfire": what the sine table's lookup changes on a real
 * picture.  The campfire scene (scenes/fire_campfire.ini: four emitters
 * that sway through the oscillation stage) is rendered at its frame 180
 * with every emitter's osc_table set to floor (the scene's, the fire
 * thesis's), round and lerp, and compared pixel by pixel with libm's sin:
 * how many pixels differ, by how much at most (0..255 per channel), and
 * the largest horizontal offset of a particle (world units and pixels).
 * campfire_sine.csv. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "iskra/effect.h"
#include "iskra/scene.h"
#include "iskra/sinlut.h"
#include "study.h"

#define SCENE "fire_campfire"

typedef struct picture {
    isk_canvas c;
    double *x;    /* every particle's x, emitters in order */
    size_t n;
} picture;

static int render(isk_sinlut_mode mode, picture *out)
{
    isk_effect_def def;
    isk_error err;
    isk_effect *fx = NULL;
    if (isk_scene_load(&def, SCENE, &err) != ISK_OK) {
        fprintf(stderr, "iskra bench: campfire: %s\n", err.message);
        return 1;
    }
    for (int i = 0; i < def.nemitters; i++)
        def.emitters[i].motion.osc_table = mode;
    const long frames = def.show.frames;
    isk_status st = isk_effect_create(&fx, &def, &err);
    int w = def.width, h = def.height;
    isk_effect_def_free(&def);
    if (st != ISK_OK) {
        fprintf(stderr, "iskra bench: campfire: %s\n", err.message);
        return 1;
    }
    if (isk_canvas_init(&out->c, w, h) != ISK_OK || isk_effect_run(fx, &out->c, frames) != ISK_OK) {
        fprintf(stderr, "iskra bench: campfire: cannot render\n");
        isk_effect_destroy(fx);
        return 1;
    }
    out->n = isk_effect_particle_count(fx);
    out->x = malloc((out->n ? out->n : 1) * sizeof *out->x);
    if (!out->x) {
        isk_effect_destroy(fx);
        return 1;
    }
    size_t k = 0;
    for (int g = 0; g < isk_effect_emitter_count(fx); g++) {
        const isk_particles *p = isk_effect_particles(fx, g);
        for (size_t i = 0; i < p->count; i++)
            out->x[k++] = p->x[i];
    }
    isk_effect_destroy(fx);
    return 0;
}

int study_knobs_campfire(const study_opts *o)
{
    (void)o->quick; /* one render per lookup: cheap either way */
    picture ref, pic[3];
    memset(&ref, 0, sizeof ref);
    memset(pic, 0, sizeof pic);
    const isk_sinlut_mode modes[3] = {ISK_SINLUT_FLOOR, ISK_SINLUT_ROUND, ISK_SINLUT_LERP};
    int rc = render(ISK_SINLUT_LIBM, &ref);
    for (int m = 0; m < 3 && !rc; m++)
        rc = render(modes[m], &pic[m]);
    if (rc)
        goto done;
    const double px_per_unit = ref.c.width / 6.0; /* the scene's view: x -3..3 */
    printf("the sine table on the campfire (%s, frame 180, %dx%d): against libm sin\n", SCENE, ref.c.width,
           ref.c.height);
    printf("  %6s %16s %18s %24s\n", "lookup", "pixels differing", "max channel diff", "max particle x offset");
    study_buf csv = {0};
    study_printf(&csv, "lookup,pixels_differing,max_channel_difference,max_x_offset_units,max_x_offset_px\n");
    for (int m = 0; m < 3; m++) {
        long diff = 0;
        int worst = 0;
        for (int y = 0; y < ref.c.height; y++)
            for (int x = 0; x < ref.c.width; x++) {
                const uint8_t *a = ref.c.pixels + (size_t)y * ref.c.stride + 4 * (size_t)x;
                const uint8_t *b = pic[m].c.pixels + (size_t)y * pic[m].c.stride + 4 * (size_t)x;
                int d = 0;
                for (int k = 0; k < 4; k++)
                    d = abs(a[k] - b[k]) > d ? abs(a[k] - b[k]) : d;
                diff += d > 0;
                worst = d > worst ? d : worst;
            }
        double dx = 0;
        for (size_t i = 0; i < ref.n && i < pic[m].n; i++)
            dx = fmax(dx, fabs(ref.x[i] - pic[m].x[i]));
        if (ref.n != pic[m].n)
            dx = INFINITY; /* a different population: not comparable particle by particle */
        printf("  %6s %16ld %14d/255 %14.2e (%5.3f px)\n", isk_sinlut_mode_names[modes[m]], diff, worst, dx,
               dx * px_per_unit);
        study_printf(&csv, "%s,%ld,%d,%.6e,%.6e\n", isk_sinlut_mode_names[modes[m]], diff, worst, dx,
                     dx * px_per_unit);
    }
    printf("\n");
    if (study_write_text(o, "campfire_sine.csv", &csv))
        rc = 1;
    study_buf_free(&csv);
done:
    isk_canvas_free(&ref.c);
    free(ref.x);
    for (int m = 0; m < 3; m++) {
        isk_canvas_free(&pic[m].c);
        free(pic[m].x);
    }
    return rc;
}
