/* SPDX-License-Identifier: MIT */
/* Animated output of `iskra render`: GIF read back with giflib (frames,
 * delays, loop, palette), YUV4MPEG2 parsed and checked against BT.601,
 * raw RGBA frames through a pipe (the README's ffmpeg line, with the
 * reader swapped when ffmpeg is absent), all against the PNG sequence of
 * the same run. */
#include <criterion/criterion.h>
#include <gif_lib.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>

#include "iskra/anim.h"
#include "iskra/png.h"
#include "refimg.h"
#include "tool_cli.h"

#define OUT "out/test_render_anim"

typedef struct gif_frames {
    int n, width, height;
    isk_canvas frame[64];
    int delay[64];
    int loops;       /* the NETSCAPE2.0 loop count, -1 when absent */
    int colors[64];  /* palette size per frame */
} gif_frames;

static void gif_load(const char *path, gif_frames *g)
{
    memset(g, 0, sizeof *g);
    g->loops = -1;
    int err = 0;
    GifFileType *gif = DGifOpenFileName(path, &err);
    cr_assert_not_null(gif, "%s: %s", path, GifErrorString(err));
    cr_assert_eq(DGifSlurp(gif), GIF_OK, "%s: %s", path, GifErrorString(gif->Error));
    g->width = gif->SWidth;
    g->height = gif->SHeight;
    g->n = gif->ImageCount;
    cr_assert_leq(g->n, 64);
    for (int i = 0; i < g->n; i++) {
        SavedImage *im = &gif->SavedImages[i];
        ColorMapObject *map = im->ImageDesc.ColorMap ? im->ImageDesc.ColorMap : gif->SColorMap;
        cr_assert_not_null(map, "frame %d has no palette", i);
        g->colors[i] = map->ColorCount;
        cr_assert_eq(im->ImageDesc.Width, g->width);
        cr_assert_eq(im->ImageDesc.Height, g->height);
        cr_assert_eq(isk_canvas_init(&g->frame[i], g->width, g->height), ISK_OK);
        for (int p = 0; p < g->width * g->height; p++) {
            int idx = im->RasterBits[p];
            cr_assert_lt(idx, map->ColorCount);
            uint8_t *o = isk_canvas_at(&g->frame[i], p % g->width, p / g->width);
            o[0] = map->Colors[idx].Red;
            o[1] = map->Colors[idx].Green;
            o[2] = map->Colors[idx].Blue;
            o[3] = 255;
        }
        GraphicsControlBlock gcb;
        cr_assert_eq(DGifSavedExtensionToGCB(gif, i, &gcb), GIF_OK, "frame %d has no delay", i);
        g->delay[i] = gcb.DelayTime;
        for (int e = 0; e + 1 < im->ExtensionBlockCount; e++) {
            ExtensionBlock *b = &im->ExtensionBlocks[e];
            if (b->Function == APPLICATION_EXT_FUNC_CODE && b->ByteCount == 11 &&
                !memcmp(b->Bytes, "NETSCAPE2.0", 11) && b[1].ByteCount == 3 && b[1].Bytes[0] == 1)
                g->loops = b[1].Bytes[1] | b[1].Bytes[2] << 8;
        }
    }
    DGifCloseFile(gif, &err);
}

static void gif_free(gif_frames *g)
{
    for (int i = 0; i < g->n; i++)
        isk_canvas_free(&g->frame[i]);
}

static void load(isk_canvas *c, const char *path)
{
    isk_error err;
    cr_assert_eq(isk_png_read(c, path, &err), ISK_OK, "%s", err.message);
}

/* Sequence frame f of dir (DIR/frame_%06ld.png). */
static void seq_frame(isk_canvas *c, const char *dir, long f)
{
    char path[256];
    snprintf(path, sizeof path, "%s/frame_%06ld.png", dir, f);
    load(c, path);
}

static char *file_bytes(const char *path, size_t *n)
{
    FILE *f = fopen(path, "rb");
    cr_assert_not_null(f, "%s", path);
    fseek(f, 0, SEEK_END);
    long len = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *b = malloc((size_t)len + 1);
    cr_assert_eq(fread(b, 1, (size_t)len, f), (size_t)len);
    fclose(f);
    *n = (size_t)len;
    return b;
}

/* Two renders of one animation are the same bytes. */
static void same_bytes(const char *a, const char *b)
{
    size_t na, nb;
    char *x = file_bytes(a, &na), *y = file_bytes(b, &nb);
    cr_assert(na == nb && !memcmp(x, y, na), "%s and %s differ", a, b);
    free(x);
    free(y);
}

Test(render_anim, gif_frames_equal_the_sequence_when_they_have_few_colours, .timeout = 120)
{
    const char *d = OUT "/few";
    cli_fresh(d);
    cr_assert_eq(cli_run(d, "render fig16_regular --frames 40 --every 10 --fps 10 --out " OUT "/few/a.gif --out-dir " OUT
                            "/few/seq"),
                 0, "%s", cli_slurp(OUT "/few/stderr.txt"));
    gif_frames g;
    gif_load(OUT "/few/a.gif", &g);
    cr_assert_eq(g.n, 5, "frames 0, 10, 20, 30, 40");
    cr_assert_eq(g.loops, 0, "loops forever");
    for (int i = 0; i < g.n; i++) {
        isk_canvas png;
        seq_frame(&png, OUT "/few/seq", 10 * i);
        cr_assert(isk_canvas_equal(&png, &g.frame[i]), "GIF frame %d differs from sequence frame %d", i, 10 * i);
        cr_assert_eq(g.delay[i], 10, "10 fps: 10 cs per frame, frame %d has %d", i, g.delay[i]);
        isk_canvas_free(&png);
    }
    gif_free(&g);
    /* the same frames give the same bytes */
    cr_assert_eq(cli_run(d, "render fig16_regular --frames 40 --every 10 --fps 10 --out " OUT "/few/b.gif"), 0);
    same_bytes(OUT "/few/a.gif", OUT "/few/b.gif");
}

Test(render_anim, gif_of_a_many_colour_scene_stays_close_and_deterministic, .timeout = 120)
{
    const char *d = OUT "/many";
    cli_fresh(d);
    cr_assert_eq(cli_run(d, "render fire_campfire --frames 60 --every 20 --out " OUT "/many/fire.gif --out-dir " OUT
                            "/many/seq"),
                 0, "%s", cli_slurp(OUT "/many/stderr.txt"));
    gif_frames g;
    gif_load(OUT "/many/fire.gif", &g);
    cr_assert_eq(g.n, 4);
    cr_assert_eq(g.width, 480);
    for (int i = 0; i < g.n; i++) {
        isk_canvas png;
        seq_frame(&png, OUT "/many/seq", 20 * i);
        isk_canvas_diff diff;
        cr_assert(isk_canvas_compare(&png, &g.frame[i], &diff, NULL));
        /* alpha is 255 on both sides, so mean_abs over RGB is 4/3 of this */
        cr_assert_lt(diff.mean_abs, 1.0, "frame %d: mean difference %.3f per channel", i, diff.mean_abs);
        cr_assert_lt(diff.max_channel, 64, "frame %d: a colour %d off", i, diff.max_channel);
        cr_assert_leq(g.colors[i], 256);
        isk_canvas_free(&png);
    }
    /* the fire has far more than 256 colours by frame 60: median cut ran */
    cr_assert_eq(g.colors[3], 256);
    /* one frame as PNG, to look at beside the sequence's */
    cr_assert_eq(isk_png_write(&g.frame[3], OUT "/many/gif_frame_60.png", NULL), ISK_OK);
    gif_free(&g);
    cr_assert_eq(cli_run(d, "render fire_campfire --frames 60 --every 20 --out " OUT "/many/again.gif"), 0);
    same_bytes(OUT "/many/fire.gif", OUT "/many/again.gif");
}

Test(render_anim, gif_delays_follow_real_time_in_whole_centiseconds)
{
    const char *d = OUT "/delays";
    cli_fresh(d);
    static const struct {
        const char *args;
        int n, delay[8];
    } cases[] = {
        /* 100/30 = 3.33 cs: frame ends at 3, 7, 10, 13, 17, 20 */
        {"--frames 5 --fps 30", 6, {3, 4, 3, 3, 4, 3}},
        /* above 50 fps every frame still lasts 2 cs (browsers slow 1 to 10) */
        {"--frames 3 --fps 60", 4, {2, 2, 2, 2}},
        {"--frames 2 --fps 0.5", 3, {200, 200, 200}},
        /* the default is real time: dt 0.001 s, every 10 -> 100 fps -> 2 cs */
        {"--frames 20 --every 10", 3, {2, 2, 2}},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        char args[256];
        snprintf(args, sizeof args, "render fig16_regular %s --out " OUT "/delays/d.gif", cases[k].args);
        cr_assert_eq(cli_run(d, args), 0, "%s", args);
        gif_frames g;
        gif_load(OUT "/delays/d.gif", &g);
        cr_assert_eq(g.n, cases[k].n, "%s", args);
        for (int i = 0; i < g.n; i++)
            cr_assert_eq(g.delay[i], cases[k].delay[i], "%s: frame %d lasts %d cs", args, i, g.delay[i]);
        gif_free(&g);
    }
}

/* BT.601 limited range, in doubles (independent of the writer's integers). */
static double bt601(int plane, const uint8_t *p)
{
    double r = p[0], g = p[1], b = p[2];
    if (plane == 0)
        return 16.0 + (65.481 * r + 128.553 * g + 24.966 * b) / 255.0;
    if (plane == 1)
        return 128.0 + (-37.797 * r - 74.203 * g + 112.0 * b) / 255.0;
    return 128.0 + (112.0 * r - 93.786 * g - 18.214 * b) / 255.0;
}

Test(render_anim, y4m_is_yuv4mpeg2_444_with_bt601_values, .timeout = 120)
{
    const char *d = OUT "/y4m";
    cli_fresh(d);
    cr_assert_eq(cli_run(d, "render fire_campfire --frames 4 --every 2 --out " OUT "/y4m/f.y4m --out-dir " OUT
                            "/y4m/seq"),
                 0, "%s", cli_slurp(OUT "/y4m/stderr.txt"));
    size_t n;
    char *v = file_bytes(OUT "/y4m/f.y4m", &n);
    const char *header = "YUV4MPEG2 W480 H400 F30:1 Ip A1:1 C444\n"; /* dt 1/60, every 2 */
    cr_assert_eq(strncmp(v, header, strlen(header)), 0, "%.60s", v);
    size_t plane = 480 * 400, pos = strlen(header);
    cr_assert_eq(n, pos + 3 * (6 + 3 * plane), "three frames of FRAME + 3 planes");
    double worst = 0;
    for (int f = 0; f < 3; f++) {
        cr_assert_eq(strncmp(v + pos, "FRAME\n", 6), 0);
        pos += 6;
        isk_canvas png;
        seq_frame(&png, OUT "/y4m/seq", 2 * f);
        for (int k = 0; k < 3; k++)
            for (int y = 0; y < 400; y++)
                for (int x = 0; x < 480; x++) {
                    double want = bt601(k, isk_canvas_at(&png, x, y));
                    double got = (unsigned char)v[pos + (size_t)k * plane + (size_t)y * 480 + (size_t)x];
                    worst = fabs(got - want) > worst ? fabs(got - want) : worst;
                }
        pos += 3 * plane;
        isk_canvas_free(&png);
    }
    cr_assert_lt(worst, 1.0, "a Y4M sample is %.2f off BT.601", worst);
    free(v);
    /* --fps as a fraction in thousandths */
    cr_assert_eq(cli_run(d, "render fig09_stationary_particle --fps 29.97 --out " OUT "/y4m/g.y4m"), 0);
    v = file_bytes(OUT "/y4m/g.y4m", &n);
    cr_assert_eq(strncmp(v, "YUV4MPEG2 W600 H600 F2997:100 ", 30), 0, "%.40s", v);
    free(v);
}

/* Reads exactly n bytes or fails. */
static void read_exact(FILE *p, uint8_t *buf, size_t n, int frame)
{
    size_t got = fread(buf, 1, n, p);
    cr_assert_eq(got, n, "frame %d: %zu of %zu bytes", frame, got, n);
}

Test(render_anim, raw_frames_through_a_pipe_are_the_canvas_bytes, .timeout = 120)
{
    const char *d = OUT "/raw";
    cli_fresh(d);
    cr_assert_eq(cli_run(d, "render fire_campfire --frames 10 --every 5 --out-dir " OUT "/raw/seq"), 0);
    char cmd[512];
    snprintf(cmd, sizeof cmd, "%s/bin/iskra render fire_campfire --frames 10 --every 5 --raw --out -",
             refimg_build_dir());
    FILE *p = popen(cmd, "r");
    cr_assert_not_null(p);
    static uint8_t buf[480 * 400 * 4];
    for (int f = 0; f < 3; f++) {
        read_exact(p, buf, sizeof buf, f);
        isk_canvas png, raw;
        seq_frame(&png, OUT "/raw/seq", 5 * f);
        cr_assert_eq(isk_canvas_wrap(&raw, buf, 480, 400, 480 * 4), ISK_OK);
        cr_assert(isk_canvas_equal(&png, &raw), "raw frame %d differs from sequence frame %d", f, 5 * f);
        isk_canvas_free(&png);
    }
    cr_assert_eq(fgetc(p), EOF, "more bytes than three frames");
    int rc = pclose(p);
    cr_assert(WIFEXITED(rc) && WEXITSTATUS(rc) == 0);
    /* raw frames into a file are the same bytes */
    cr_assert_eq(cli_run(d, "render fire_campfire --frames 10 --every 5 --raw --out " OUT "/raw/f.rgba"), 0);
    size_t n;
    char *b = file_bytes(OUT "/raw/f.rgba", &n);
    cr_assert_eq(n, 3 * sizeof buf);
    cr_assert_eq(memcmp(b + 2 * sizeof buf, buf, sizeof buf), 0);
    free(b);
}

/* The README's line, word for word, with 60 frames instead of 600; its
 * ffmpeg when there is one, else a reader counting the bytes. */
Test(render_anim, the_readme_ffmpeg_line_works, .timeout = 300)
{
    const char *d = OUT "/readme";
    cli_fresh(d);
    size_t n;
    char *readme = file_bytes("README.md", &n);
    const char *line = "iskra render fire_campfire --frames 600 --raw --out - | ffmpeg -f rawvideo -pixel_format rgba "
                       "-video_size 480x400 -framerate 60 -i - fire.mp4";
    cr_assert_not_null(strstr(readme, line), "README.md lacks the line: %s", line);
    free(readme);
    char cmd[1024];
    int have_ffmpeg = system("command -v ffmpeg >/dev/null 2>&1") == 0;
    if (have_ffmpeg)
        snprintf(cmd, sizeof cmd,
                 "cd " OUT "/readme && PATH=\"$PWD/../../../%s/bin:$PATH\" iskra render fire_campfire --frames 60 "
                 "--raw --out - | ffmpeg -loglevel error -f rawvideo -pixel_format rgba -video_size 480x400 "
                 "-framerate 60 -i - fire.mp4",
                 refimg_build_dir());
    else
        snprintf(cmd, sizeof cmd,
                 "cd " OUT "/readme && PATH=\"$PWD/../../../%s/bin:$PATH\" iskra render fire_campfire --frames 60 "
                 "--raw --out - | wc -c > bytes.txt",
                 refimg_build_dir());
    cr_assert_eq(system(cmd), 0, "%s", cmd);
    if (have_ffmpeg) {
        cr_assert(cli_exists(OUT "/readme/fire.mp4"));
    } else {
        char *count = cli_slurp(OUT "/readme/bytes.txt");
        cr_assert_eq(atol(count), 61L * 480 * 400 * 4, "bytes: %s", count);
        free(count);
    }
}

Test(render_anim, usage_errors_write_nothing)
{
    const char *d = OUT "/usage";
    cli_fresh(d);
    const char *bad[] = {
        "render fig16_regular --out -",
        "render fig16_regular --raw",
        "render fig16_regular --raw --out-dir " OUT "/usage/x",
        "render fig16_regular --fps 10 --out " OUT "/usage/x.png",
        "render fig16_regular --fps 10 --raw --out " OUT "/usage/x.rgba",
        "render fig16_regular --fps 0 --out " OUT "/usage/x.gif",
        "render fig16_regular --fps nan --out " OUT "/usage/x.gif",
        "render fig16_regular --fps 1001 --out " OUT "/usage/x.gif",
        "render fig16_regular --every 2 --out " OUT "/usage/x.png",
        "render fig16_regular --resume --out " OUT "/usage/x.gif",
        "render fig16_regular --frames 5 --dt 1000 --every 2 --out " OUT "/usage/x.gif", /* 1/(dt K) below 0.001 */
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        cr_assert_eq(cli_run(d, bad[i]), 2, "%s", bad[i]);
        char *err = cli_slurp(OUT "/usage/stderr.txt");
        cr_assert_neq(err[0], 0, "no message for %s", bad[i]);
        free(err);
        cr_assert_not(cli_exists(OUT "/usage/x.gif") || cli_exists(OUT "/usage/x.png") || cli_exists(OUT "/usage/x"),
                      "%s wrote something", bad[i]);
    }
}

/* The library's writers refuse what they must. */
Test(render_anim, anim_api_checks_its_arguments)
{
    isk_anim *a = (isk_anim *)&a;
    isk_anim_opts o = {ISK_ANIM_GIF, 4, 4, 10};
    isk_error err;
    cr_assert_eq(isk_anim_begin(NULL, stdout, &o, &err), ISK_ERR_NULL);
    cr_assert_eq(isk_anim_begin(&a, NULL, &o, &err), ISK_ERR_NULL);
    cr_assert_null(a);
    cr_assert_eq(isk_anim_begin(&a, stdout, NULL, &err), ISK_ERR_NULL);
    isk_anim_opts bad = o;
    bad.width = 0;
    cr_assert_eq(isk_anim_begin(&a, stdout, &bad, &err), ISK_ERR_SIZE);
    bad = o;
    bad.height = ISK_CANVAS_MAX_DIM + 1;
    cr_assert_eq(isk_anim_begin(&a, stdout, &bad, &err), ISK_ERR_SIZE);
    bad = o;
    bad.fps = NAN;
    cr_assert_eq(isk_anim_begin(&a, stdout, &bad, &err), ISK_ERR_NAN);
    bad.fps = 0;
    cr_assert_eq(isk_anim_begin(&a, stdout, &bad, &err), ISK_ERR_RANGE);
    bad.format = ISK_ANIM_RAW; /* raw needs no rate */
    FILE *sink = fopen("/dev/null", "wb");
    cr_assert_eq(isk_anim_begin(&a, sink, &bad, &err), ISK_OK, "%s", err.message);
    isk_canvas c;
    cr_assert_eq(isk_canvas_init(&c, 5, 4), ISK_OK);
    cr_assert_eq(isk_anim_frame(a, &c, &err), ISK_ERR_SIZE, "a 5x4 frame in a 4x4 animation");
    cr_assert_eq(isk_anim_frame(a, NULL, &err), ISK_ERR_NULL);
    cr_assert_eq(isk_anim_frame(NULL, &c, &err), ISK_ERR_NULL);
    cr_assert_eq(isk_anim_count(a), 0);
    cr_assert_eq(isk_anim_end(a, &err), ISK_OK);
    bad.format = (isk_anim_format)9;
    cr_assert_eq(isk_anim_begin(&a, sink, &bad, &err), ISK_ERR_RANGE);
    cr_assert_eq(isk_anim_end(NULL, &err), ISK_ERR_NULL);
    isk_anim_abort(NULL);
    cr_assert_eq(isk_anim_count(NULL), 0);
    isk_anim_format f;
    cr_assert(isk_anim_format_of_path("x/A.GIF", &f) && f == ISK_ANIM_GIF);
    cr_assert(isk_anim_format_of_path("v.y4m", &f) && f == ISK_ANIM_Y4M);
    cr_assert_not(isk_anim_format_of_path("x.png", &f));
    cr_assert_not(isk_anim_format_of_path(".gif", &f));
    cr_assert_not(isk_anim_format_of_path(NULL, &f));
    cr_assert_str_eq(isk_anim_format_name(ISK_ANIM_RAW), "raw");
    cr_assert_null(isk_anim_format_name((isk_anim_format)-1));
    /* a GIF writer aborted half-way writes no trailer and leaks nothing */
    o.width = 5;
    o.height = 4;
    cr_assert_eq(isk_anim_begin(&a, sink, &o, &err), ISK_OK);
    cr_assert_eq(isk_anim_frame(a, &c, &err), ISK_OK);
    cr_assert_eq(isk_anim_count(a), 1);
    isk_anim_abort(a);
    fclose(sink);
    isk_canvas_free(&c);
}
