/* SPDX-License-Identifier: MIT */
/* The widget layer (iskra/ui.h) in an SDL demo: a panel of controls beside a
 * drawing they change.
 *
 * For demo writers: every control is one call per frame with a name, a
 * rectangle and the value it shows; the program keeps its values, the layer
 * only hover, press and focus.  Events from the window go in through
 * iskra/ui_sdl.h; Escape cancels an edit, and quits when nothing is edited.
 *
 *   count    slider, 3..48 dots on the ring
 *   radius   number field (Return applies, Escape cancels; out of range is
 *            refused with a message under the field)
 *   colour   radio group; shape: list; spin: toggle; reset: button
 *
 * With --png the demo plays a fixed script (clicks, a drag, typing) through
 * the same input functions and writes the final frame, the image the tests
 * compare with refimg/ui_demo.png.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "example.h"
#include "iskra/ui.h"
#include "iskra/ui_sdl.h"

#define W 640
#define H 400

typedef struct demo {
    isk_ui ui;
    double count;
    double radius;
    int colour, shape, shape_scroll, spin;
    long turn;
    char radius_text[32];
} demo;

static const char *const colour_names[] = {"yellow", "cyan", "magenta"};
static const isk_color colours[] = {{255, 255, 0, 255}, {0, 230, 255, 255}, {255, 80, 220, 255}};
static const char *const shapes[] = {"dots", "rings", "petals", "spiral", "grid"};

static void reset(demo *d)
{
    d->count = 12;
    d->radius = 120;
    d->colour = 0;
    d->shape = 0;
    d->spin = 0;
    d->turn = 0;
}

/* The drawing the controls change. */
static void draw_picture(demo *d, isk_canvas *c, isk_ui_rect area)
{
    isk_fill_rect(c, area.x, area.y, area.w, area.h, ISK_BLACK, ISK_BLEND_REPLACE);
    const double cx = area.x + area.w / 2.0, cy = area.y + area.h / 2.0;
    const int n = (int)d->count;
    const isk_color col = colours[d->colour];
    for (int i = 0; i < n; i++) {
        double a = 2 * 3.14159265358979323846 * i / n + d->turn * 0.02;
        double r = d->shape == 3 ? d->radius * (0.3 + 0.7 * i / n) : d->radius;
        double x = cx + r * cos(a), y = cy + r * sin(a);
        switch (d->shape) {
        case 1:
            isk_fill_circle_aa(c, x, y, 9, col, ISK_BLEND_OVER);
            isk_fill_circle_aa(c, x, y, 6, ISK_BLACK, ISK_BLEND_OVER);
            break;
        case 2: isk_stroke_line(c, cx, cy, x, y, col, ISK_BLEND_OVER); break;
        case 4: isk_fill_rect(c, (int)x - 4, (int)y - 4, 8, 8, col, ISK_BLEND_OVER); break;
        default: isk_fill_circle_aa(c, x, y, 6, col, ISK_BLEND_OVER); break;
        }
    }
}

static void frame_ui(demo *d, isk_canvas *c)
{
    isk_ui *ui = &d->ui;
    isk_ui_begin(ui, c);
    isk_ui_clear(ui);
    const int gap = isk_ui_px(ui, 6), row = isk_ui_row_height(ui);
    isk_ui_rect all = {0, 0, c->width, c->height};
    all = isk_ui_inset(all, gap);
    isk_ui_rect panel = isk_ui_cut_right(&all, isk_ui_px(ui, 230));
    isk_ui_cut_right(&all, gap);
    draw_picture(d, c, all);

    isk_ui_panel(ui, panel);
    isk_ui_rect p = isk_ui_inset(panel, isk_ui_px(ui, 8)), line, label;
    const int label_w = isk_ui_px(ui, 60);

    line = isk_ui_cut_top(&p, row);
    label = isk_ui_cut_left(&line, label_w);
    char text[64];
    snprintf(text, sizeof text, "count %d", (int)d->count);
    isk_ui_label(ui, label, text, ISK_UI_LEFT);
    isk_ui_slider(ui, "count", line, &d->count, 3, 48, 1);
    isk_ui_cut_top(&p, gap);

    line = isk_ui_cut_top(&p, row);
    isk_ui_label(ui, isk_ui_cut_left(&line, label_w), "radius", ISK_UI_LEFT);
    snprintf(d->radius_text, sizeof d->radius_text, "%g", d->radius);
    char typed[64];
    if (isk_ui_field(ui, "radius", line, d->radius_text, ISK_UI_FIELD_NUMBER, typed, sizeof typed) ==
        ISK_UI_FIELD_APPLY) {
        char *end;
        double v = strtod(typed, &end);
        if (end == typed || *end || !(v >= 10 && v <= 180))
            isk_ui_field_error(ui, "radius", "expected a number between 10 and 180");
        else
            d->radius = v;
    }
    isk_ui_cut_top(&p, gap);

    line = isk_ui_cut_top(&p, row);
    isk_ui_radio(ui, "colour", line, colour_names, 3, 0, &d->colour);
    isk_ui_cut_top(&p, gap);

    line = isk_ui_cut_top(&p, row);
    isk_ui_toggle(ui, "spin", isk_ui_cut_left(&line, line.w / 2), "spin", &d->spin);
    if (isk_ui_button(ui, "reset", line, "Reset"))
        reset(d);
    isk_ui_cut_top(&p, gap);

    isk_ui_rect list = isk_ui_cut_top(&p, 3 * row + isk_ui_px(ui, 2));
    isk_ui_list(ui, "shape", list, shapes, 5, &d->shape, &d->shape_scroll);
    isk_ui_cut_top(&p, gap);

    snprintf(text, sizeof text, "%d %s %s\nradius %g%s", (int)d->count, colour_names[d->colour], shapes[d->shape],
             d->radius, d->spin ? ", spinning" : "");
    isk_ui_box(ui, p);
    isk_ui_text(ui, isk_ui_inset(p, isk_ui_px(ui, 4)), text, ui->style.text, ISK_UI_LEFT);
    isk_ui_end(ui);
    if (d->spin)
        d->turn++;
}

/* Clicks the named widget of the last frame (at its centre). */
static void click(demo *d, const char *name)
{
    isk_ui_rect r;
    if (isk_ui_find(&d->ui, name, &r)) {
        isk_ui_input_button(&d->ui, r.x + r.w / 2, r.y + r.h / 2, 1);
        isk_ui_input_button(&d->ui, r.x + r.w / 2, r.y + r.h / 2, 0);
    }
}

static void run_frames(demo *d, isk_canvas *c, int n)
{
    for (int i = 0; i < n || isk_ui_pending(&d->ui); i++)
        frame_ui(d, c);
}

/* The --png picture: a fixed session through the same input functions. */
static void scripted(demo *d, isk_canvas *c)
{
    run_frames(d, c, 1);
    isk_ui_rect s;
    isk_ui_find(&d->ui, "count", &s);
    isk_ui_input_mouse(&d->ui, s.x + s.w / 4, s.y + s.h / 2);
    isk_ui_input_button(&d->ui, s.x + s.w / 4, s.y + s.h / 2, 1);
    isk_ui_input_mouse(&d->ui, s.x + s.w * 3 / 4, s.y + s.h / 2);
    isk_ui_input_button(&d->ui, s.x + s.w * 3 / 4, s.y + s.h / 2, 0);
    click(d, "colour/cyan");
    click(d, "shape/1");
    click(d, "spin");
    run_frames(d, c, 1);
    click(d, "radius");
    run_frames(d, c, 1);
    for (int i = 0; i < 3; i++)
        isk_ui_input_key(&d->ui, ISK_UI_KEY_BACKSPACE);
    isk_ui_input_text(&d->ui, "400");
    isk_ui_input_key(&d->ui, ISK_UI_KEY_RETURN); /* refused: stays in the field with a message */
    run_frames(d, c, 10);
}

static int window_frame(void *user, isk_canvas *c, double dt, const isk_event *ev, int n)
{
    (void)dt;
    demo *d = user;
    for (int i = 0; i < n; i++)
        isk_ui_feed_event(&d->ui, &ev[i]);
    frame_ui(d, c);
    return isk_ui_key(&d->ui, ISK_UI_KEY_ESCAPE);
}

int main(int argc, char **argv)
{
    example_opts o = {0};
    example_parse(argc, argv, &o, 0, "ui_demo", "the widget layer (iskra/ui.h) driving a drawing");
    static demo d;
    isk_ui_init(&d.ui, 1);
    reset(&d);
    isk_canvas c;
    if (isk_canvas_init(&c, W, H) != ISK_OK) {
        fprintf(stderr, "ui_demo: out of memory\n");
        return 1;
    }
    int rc = 0;
    if (o.png) {
        scripted(&d, &c);
        rc = example_write_png(&c, &o);
        isk_ui_init(&d.ui, 1);
        reset(&d);
    }
    if (!rc && o.window) {
        isk_window *w;
        isk_error err;
        if (isk_window_open(&w, "iskra ui demo", W, H, &err) != ISK_OK) {
            fprintf(stderr, "ui_demo: cannot open a window: %s\n", err.message);
            rc = 1;
        } else {
            isk_window_set_escape_quits(w, 0);
            if (isk_window_run(w, &c, window_frame, &d, 0, &err) != ISK_OK) {
                fprintf(stderr, "ui_demo: %s\n", err.message);
                rc = 1;
            }
            isk_window_close(w);
        }
    }
    isk_canvas_free(&c);
    return rc;
}
