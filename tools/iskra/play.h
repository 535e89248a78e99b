/* SPDX-License-Identifier: MIT */
/* The simulator behind `iskra play` (internal to the tool): one player
 * holds the running effect, the window's canvas and the widget layer; the
 * play_*.c files each do one part of a frame.
 *
 *   cmd_play.c      options and the SDL window (web/iskra_web.c: the web page)
 *   play_frame.c    one shown frame, gluing the parts
 *   play_layout.c   where the parts sit, for the screen the window must fit
 *   play_actions.c  the buttons and their shortcuts (one table: play, pause,
 *                   stop, reset, reload, step, save, screenshots, panel)
 *   play_panel.c    the thesis's console, control for control: a view of the
 *                   key table, every edit through isk_effect_set (the
 *                   explosion scenes' panel)
 *   play_inspector.c the inspector (every other scene's panel): every
 *                   section of the running scene with its live keys
 *   play_key_widget.c one key as the widget its row calls for (slider,
 *                   colour, choice, toggle, text field)
 *   play_fields.c   what a field shows and how a typed value is applied (the
 *                   table's messages, the thesis's replacement values)
 *   play_names.c    the widgets' names: --list-widgets, suggestions for a
 *                   name a script got wrong, bringing a widget into view
 *   play_charts.c   energy and particle count over time, the integrator
 *                   table with measured cost and energy drift
 *   play_energy.c   kinetic and potential energy of the state
 *   play_probes.c   the scene's probes over time, beside the particle count
 *   play_hud.c      the thesis's FPS text and the HUD over the canvas
 *   play_files.c    reload (by hand and when the file changes), save,
 *                   screenshots
 *   play_script.c   --script: events played at given frames (tests, demos)
 *   play_shadow.c   --shadow, G: a reference copy stepped finer beside the
 *                   scene, its error on the canvas (play_shadow.h)
 *
 * A frame: input into the widget layer; the panel (its actions change the
 * effect at once); shortcuts; the simulation steps of the frame; the
 * canvas and the HUD into the window.  Everything but the clock is
 * deterministic, and --fixed-clock replaces the clock (one step per frame),
 * so a scripted session gives the same pixels every time. */
#ifndef ISKRA_TOOL_PLAY_H
#define ISKRA_TOOL_PLAY_H

#include <stddef.h>
#include <stdio.h>

#include "iskra/effect.h"
#include "iskra/keys.h"
#include "iskra/sdl.h"
#include "iskra/timestep.h"
#include "iskra/ui.h"
#include "iskra/timeline.h"
#include "scene_args.h"

#define PLAY_HISTORY 600       /* samples kept for the charts */
#define PLAY_SCRIPT_MAX 4000000 /* tokens of a script or lesson (a long lesson has a few hundred thousand) */
#define PLAY_MAX_STEPS_PER_FRAME 5

/* What a click on the canvas does besides the scene's explosions. */
enum { PLAY_CLICK_ADD_POTENTIAL = ISK_EXPLOSION_COUNT, PLAY_CLICK_NONE, PLAY_CLICK_MODES };

/* Which panel shows beside the canvas. */
typedef enum play_panel_kind {
    PLAY_PANEL_CONSOLE = 0,    /* the thesis's console: scenes with a layer or potentials */
    PLAY_PANEL_INSPECTOR       /* every section's live keys: the other scenes */
} play_panel_kind;

/* How the console is arranged. */
typedef enum play_arrangement {
    PLAY_WIDE = 0,             /* the thesis page's: console and side beside the canvas, the rest below */
    PLAY_COMPACT               /* three columns beside the canvas (screens of 1280x720 and 1366x768) */
} play_arrangement;

typedef struct play_layout {
    isk_ui_rect window;        /* the whole window (0, 0, w, h) */
    isk_ui_rect canvas;        /* the scene's canvas, at the top-left, shown 1:1 */
    /* the console, wide */
    isk_ui_rect console;       /* buttons, speed, fields, walls: beside the canvas */
    isk_ui_rect side;          /* charts, integrators, keys: beside the console */
    isk_ui_rect bottom;        /* click modes, potentials, layer: below */
    /* the console, compact */
    isk_ui_rect column[3];     /* console and click modes; potentials and layer; charts, integrators, files */
    /* the inspector */
    isk_ui_rect inspector;     /* beside the canvas */
    isk_ui_rect under;         /* below the canvas: messages and the charts (may be empty) */
} play_layout;

typedef struct play_integrator_stats {
    double ns;                 /* measured cost, ns per particle-step (smoothed) */
    double drift;              /* relative change of total energy since it took over */
    int have_ns, have_drift;
} play_integrator_stats;

typedef struct play_history {
    int n;
    double t[PLAY_HISTORY], kinetic[PLAY_HISTORY], potential[PLAY_HISTORY], total[PLAY_HISTORY],
        count[PLAY_HISTORY];
} play_history;

struct player;

/* Where a lesson's shot:NAME goes instead of a file (iskra play --replay,
 * iskra replay --check): the window (whole_window 1) or the canvas. */
typedef void (*play_shot_fn)(struct player *p, void *user, const char *name, int whole_window);

typedef struct play_script {
    char **tokens;
    int *lines;                /* each token's line in `file` (lessons) */
    int n, cap, next;
    long wait_until;           /* frames_shown before which nothing more is played */
    int revealing;             /* 1: the next token's widget was asked into view (play_inspector_reveal) */
    char *text;                /* the owned copy the tokens point into */
    const char *file;          /* the lesson file, or NULL: --script */
    play_shot_fn shot;         /* NULL: shot:PATH writes a PNG to PATH and says so */
    void *shot_user;
} play_script;

/* The charts' points, thinned for drawing (play_charts.c). */
typedef struct play_chart_points {
    double t[120], v[4][120];
    size_t n;
} play_chart_points;

/* The probes' readings over time (play_probes.c): a series per number
 * charted (a gate's two rates, a region's count). */
#define PLAY_PROBE_SERIES 8
typedef struct play_probe_history {
    int n, nseries;
    double t[PLAY_HISTORY];
    double v[PLAY_PROBE_SERIES][PLAY_HISTORY];
    char name[PLAY_PROBE_SERIES][48];
    double chart_t[120], chart_v[PLAY_PROBE_SERIES][120]; /* thinned for drawing */
} play_probe_history;

/* Sizes of the window's parts (play_layout.c, play_panel.c), in units of the widget scale. */
enum { CONSOLE_W = 190, SIDE_W = 230, BOTTOM_H = 150, CONSOLE_MIN_H = 300, MARGIN = 6, GAP = 4, LABEL_W = 86 };
/* The compact console and the inspector (units at the 6x13 font): panel widths, the least height. */
enum { COMPACT_MIN_W = 600, COMPACT_MAX_W = 720, COMPACT_H = 600, INSPECTOR_MIN_W = 360, INSPECTOR_MAX_W = 520,
       INSPECTOR_MIN_H = 480, INSPECTOR_MAX_H = 720 };
/* What a window must leave of a screen: a title bar's height, and a little at the sides. */
enum { SCREEN_TITLE_H = 48, SCREEN_SIDE_W = 16 };

/* One section of the running scene, as the inspector addresses it. */
typedef struct play_item {
    isk_section_kind section;
    int index;                 /* the item of that section (0 for the unnamed ones) */
    int kind;                  /* its kind (isk_key_item_kind), -1 for sections without */
    char name[ISK_NAME_MAX + 16];  /* "emitter flame", "scene": isk_effect_set's section */
    char token[ISK_NAME_MAX + 16]; /* "emitter-flame", "scene": its widgets' names start so */
} play_item;

/* The inspector's state (play_inspector.c). */
typedef struct play_inspector {
    int section;               /* the selected section: an isk_section_kind */
    int item;                  /* and its item (index into the definition's forces, emitters, ...) */
    int sections_scroll;       /* the first row shown of the list of sections */
    int keys_scroll;           /* the first key shown of the selected section */
    char filter[48];           /* only keys whose name holds this (empty: all) */
    char reveal[ISK_UI_ID_MAX];/* a widget to bring into view in the next frame (scripts), or "" */
} play_inspector_state;

/* What the player asks of the program that shows it: an SDL window
 * (cmd_play.c) or a web page (web/iskra_web.c).  Either hook may be NULL. */
typedef struct play_host {
    void *user;
    /* The window's canvas becomes w x h (the panel came or went, a reloaded
     * scene has another size); on failure err says why and nothing changed. */
    isk_status (*resize)(void *user, int w, int h, isk_error *err);
    /* An event as if the user made it, arriving with the next frame (--script). */
    isk_status (*push_event)(void *user, const isk_event *ev);
    /* A file the user asked for (save, screenshots), handed over whole: the
     * web page offers it as a download.  NULL: written to disk. */
    void (*deliver)(void *user, const char *file_name, const void *bytes, size_t n);
} play_host;

/* Rewind keeps at most this much of a run (the campfire's first minute
 * fits: docs/simulator.md, "Going back in time"). */
#define PLAY_TIMELINE_BYTES ((size_t)64 << 20)

typedef struct player {
    /* the scene */
    scene_args args;
    isk_effect *fx;
    char name[64];             /* for screenshots and saves */
    const char *shots;         /* screenshot directory (NULL: the current one) */
    const char *path;          /* the scene file, or NULL for a built-in scene */
    long long stamp;           /* the file's modification time and size when read */
    long long stamp_size;
    double base_dt;            /* the scene's dt when loaded (the thesis's precision quirk scales it) */
    /* display */
    play_host host;
    isk_canvas sim;            /* what the effect draws (trails live here) */
    isk_canvas *shown;         /* the window's canvas */
    isk_ui ui;
    play_layout lay;
    play_panel_kind panel_kind;
    play_arrangement arrangement;
    int screen_w, screen_h;    /* the screen the window must fit (--screen, or the display's) */
    int borderless;            /* 1: screen_w x screen_h is all room (a web page's); 0: a window's title
                                * bar and sides take SCREEN_TITLE_H and SCREEN_SIDE_W of it */
    int panel, hud;            /* 1: shown */
    int panel_toggle;          /* hide/show the panel at the end of this frame */
    int shot_pending;          /* 1: canvas, 2: window screenshot at the end of this frame */
    /* time */
    isk_timestep ts;
    int fixed_clock;
    const char *follow;        /* --follow: the emitter the mouse moves (NULL: none) */
    int paused, physics_off, failed, quit;
    long frames_shown;
    double elapsed;            /* real seconds since start */
    double update_ms;          /* simulation time per shown frame (smoothed) */
    double pace;               /* simulated / intended time over the last frames (1: real time kept) */
    double behind_until;       /* real time until which the HUD says real time is not kept */
    double pace_real, pace_dropped; /* this second's real time and the part of it dropped */
    /* the console's own state */
    double slider;             /* 1..1000, the thesis's speed slider */
    int click_mode;            /* an isk_explosion, or PLAY_CLICK_ADD_POTENTIAL / _NONE */
    int selected, pot_scroll;  /* the selected potential (index into isk_effect_potentials), -1 none */
    int dragging;              /* 1 while a potential follows the pointer */
    int count_refused;         /* thesis: an explosion count that is not 1..limit makes clicks do nothing */
    char precision_text[64];   /* thesis: the precision as typed ("2.5"), "" when it is the substeps */
    char status[600];          /* the last message of an action, under the console */
    char reload_error[600];    /* "FILE:LINE: message" while the file does not load; "" when it does */
    int drag_level;            /* play_stability.c: 1 + where the drag sits against the edges; 0: not seen */
    int spring_level;          /* play_stability.c: the same for the stiffest potential core */
    play_inspector_state insp;
    /* charts */
    play_history hist;
    isk_canvas chart_cache;    /* the charts, drawn again every few frames */
    int chart_drawn_n;         /* samples when they were drawn (-1: draw them) */
    play_chart_points chart_points;
    play_probe_history probe_hist; /* nseries 0: the scene has no probe to chart */
    play_integrator_stats stats[ISK_INTEGRATOR_COUNT];
    double energy_ref;         /* total energy when the current integrator's drift started */
    double energy_scale;       /* the size of the energies then (kinetic + |potential|) */
    int energy_ref_valid;
    size_t count_ref;          /* particles then (a click restarts the drift) */
    int ref_integrator;        /* the integrator then */
    /* rewind (iskra/timeline.h): the frames since the last reset, in at
     * most PLAY_TIMELINE_BYTES (NULL until the first restart) */
    isk_timeline *timeline;
    int timeline_shown;        /* the bar along the canvas's foot is drawn */
    int timeline_held;         /* the bar took the button's press: the drag is its */
    isk_ui_rect timeline_bar;  /* where it is, in the window */
    /* the shadow run (play_shadow.h): a reference copy stepped beside, NULL while off */
    struct play_shadow *shadow;
    int shadow_wanted;         /* --shadow or G: on (it starts with the scene, a reset, a seek) */
    int shadow_factor;         /* --shadow-factor: its substeps per the scene's (0: PLAY_SHADOW_FACTOR) */
    /* files */
    const char *save_to;       /* --save PATH, or NULL: iskra-SCENE.ini */
    play_script script;
} player;

/* play_rewind.c: the timeline kept up to date (after a restart, every
 * shown frame, every step), B's step back, the bar's input (1: it took
 * the pointer's press or drag) and its drawing over the canvas's foot. */
void play_rewind_restart(player *p);
void play_rewind_watch(player *p);
void play_rewind_stepped(player *p);
void play_rewind_to(player *p, long frame);
void play_rewind_back(player *p);
int play_rewind_input(player *p, const isk_ui_area_state *a);
void play_rewind_draw(player *p);

/* play_actions.c */
typedef enum play_action {
    PLAY_PLAY = 0, PLAY_PAUSE, PLAY_STOP, PLAY_RESET, PLAY_RELOAD, PLAY_STEP,
    PLAY_SLOWER, PLAY_FASTER, PLAY_MORE_PRECISION, PLAY_LESS_PRECISION,
    PLAY_SAVE, PLAY_SHOT, PLAY_SHOT_WINDOW, PLAY_PANEL, PLAY_HUD, PLAY_QUIT, PLAY_TOGGLE_PAUSE,
    PLAY_BACK, PLAY_TIMELINE, PLAY_SHADOW, PLAY_ACTION_COUNT
} play_action;
typedef struct play_action_info {
    const char *id;            /* widget name, for scripts */
    const char *label;         /* on the button */
    const char *keys;          /* its shortcut(s) as listed in the panel */
    int key, key2;             /* ISK_UI_KEY_* or ASCII (0: none) */
    const char *meaning;
} play_action_info;
const play_action_info *play_action_at(play_action a);
void play_do(player *p, play_action a);
/* The keys and what they do, for --help (from the same table). */
void play_keys_help(FILE *f);
/* Runs the actions of this frame's shortcut keys (keys a field took are not shortcuts). */
void play_shortcuts(player *p);
/* One shown frame (play_frame.c): the events into the widgets, the panel,
 * the steps that dt_seconds of real time call for (one with a fixed
 * clock), the canvas and the HUD into p->shown.  Non-zero: stop. */
int play_frame(player *p, double dt_seconds, const isk_event *ev, int nev);
/* Hides or shows the panel: the window's canvas changes size. */
void play_toggle_panel(player *p);
/* Runs `steps` simulation frames (with their timing, charts and drift). */
void play_simulate(player *p, int steps);
/* After anything that rebuilt the state (reset, reload): charts restart. */
void play_restarted(player *p);
/* The console's state for a freshly created effect (start, reload): the
 * slider, the click mode, the time step; a start_paused scene runs its
 * first frame and holds. */
void play_begin_scene(player *p);
/* Says so when this frame's edits moved the scene's drag across iskra's
 * cap or its integrator's drag edge, or a potential's core across its
 * spring edge (play_stability.c). */
void play_stability_watch(player *p);
void play_say(player *p, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/* play_layout.c */
/* The panel a scene gets: the console for scenes with a layer emitter or a
 * potential (the explosion thesis's simulator scenes), the inspector for
 * the others. */
play_panel_kind play_panel_for(const isk_effect_def *d);
/* Chooses the widget scale, the font and the console's arrangement for the
 * screen (p->screen_w x p->screen_h) and the scene: `asked` > 0 is
 * --ui-scale.  Text is at least 10 px tall unless the scale was asked for
 * or the screen is smaller than 1280x720. */
void play_choose_layout(player *p, int asked);
/* Where everything sits for a canvas of cw x ch with the panel shown or
 * not (from p's scale, panel kind, arrangement and screen). */
void play_layout_plan(const player *p, int cw, int ch, int panel, play_layout *out);
/* The same into p->lay, for the scene's canvas and p->panel. */
void play_layout_compute(player *p);

/* play_panel.c */
void play_panel(player *p);
/* The six buttons (play ... step) and the speed slider, cut off the top of *a. */
void play_transport(player *p, isk_ui_rect *a);
/* Save, screenshots, panel; the last message, whole; the keys without a
 * button when they fit, in a. */
void play_extras(player *p, isk_ui_rect a);
/* Save, screenshots, panel as two rows of two buttons in r. */
void play_file_buttons(player *p, isk_ui_rect r);
/* Chooses a click mode (an isk_explosion, PLAY_CLICK_ADD_POTENTIAL or _NONE). */
void play_set_click_mode(player *p, int mode);
/* The canvas as a widget: clicks explode / add potentials, potentials are
 * picked and dragged. */
void play_canvas(player *p);

/* play_inspector.c */
void play_inspector(player *p);
/* The inspector's state for a freshly loaded scene (the first emitter selected). */
void play_inspector_begin(player *p);
/* Calls `name` for every widget name the inspector can show (every
 * section and every live key, drawn or scrolled out of view). */
void play_inspector_names(const player *p, void (*name)(void *user, const char *name), void *user);
/* Brings widget `name` into view at the end of the next frame (selects its
 * section, clears the filter, scrolls to it), so it shows from the frame
 * after; 1 when the inspector has it. */
int play_inspector_reveal(player *p, const char *name);

/* play_key_widget.c */
/* Key k of `it` as the widget its row calls for, in r (one row; a colour
 * ramp also uses `second`, the row under it); named `id` (a slider's
 * field: `id`, its track: `id`/slider).  Edits go through isk_effect_set;
 * a refused value keeps the field open with the table's message. */
void play_key_widget(player *p, const char *id, isk_ui_rect r, isk_ui_rect second, const play_item *it,
                     const isk_key *k);
/* The rows key k takes in the inspector (2 for a colour ramp, else 1). */
int play_key_widget_rows(const isk_key *k);

/* play_names.c */
/* Every widget name of the window now: the last frame's, then the
 * inspector's not drawn; each once, into `name`. */
void play_widget_names(const player *p, void (*name)(void *user, const char *name), void *user);
/* " (did you mean 'a', 'b'?)" for a name no widget has, or "". */
void play_suggest_widget(const player *p, const char *wrong, char *out, size_t n);

/* play_fields.c */
/* The section of the first force of `kind` ("force gravity"), or NULL. */
const char *play_force_section(const isk_effect *fx, isk_force_kind kind, char *buf, size_t n);
/* The section of the first layer emitter ("emitter particles"), or NULL. */
const char *play_layer_section(const isk_effect *fx, char *buf, size_t n);
/* The field `id` showing key `key` of `section` (NULL: disabled, shows "-"),
 * applying what is typed through isk_effect_set; returns 1 when applied. */
int play_key_field(player *p, const char *id, isk_ui_rect r, const char *section, const char *key);
/* One number of a list-valued key ("position" x or y, "rect" xmin..ymax);
 * `current` (may be NULL: the key's value) is the list shown. */
int play_key_part_field(player *p, const char *id, isk_ui_rect r, const char *section, const char *key, int part,
                        const char *current);
/* The thesis's precision field (substeps; its fractional quirk in thesis fidelity). */
int play_precision_field(player *p, const char *id, isk_ui_rect r);
/* isk_effect_set, the message into the status line when refused; 0 / -1. */
int play_set(player *p, const char *section, const char *key, const char *value);
/* The slider's value (1..1000) for the scene's speed_divisor and back. */
double play_slider_of_divisor(double f);
double play_divisor_of_slider(double s);

/* play_energy.c */
typedef struct play_energy {
    double kinetic, potential; /* potential: isk_forces_potential_energy of every emitter's forces */
} play_energy;
play_energy play_energy_of(const isk_effect *fx);

/* play_charts.c */
void play_charts_sample(player *p, double step_seconds, long steps);
void play_charts_reset(player *p);
/* The energy chart over the particle count's (side by side: beside it). */
void play_charts_draw(player *p, isk_ui_rect r, int side_by_side);
/* A chart in the charts' look into r of c, or a box saying `empty`. */
struct isk_chart;
void play_chart_look(struct isk_chart *ch, const player *p);
void play_chart_into(player *p, isk_canvas *c, isk_ui_rect r, const struct isk_chart *ch, const char *empty);
/* The integrator table (a radio group with cost and drift beside). */
void play_integrators(player *p, isk_ui_rect r);

/* play_probes.c: the probes' chart (only for a scene with probes: the
 * particle count's chart then shares its place with it). */
void play_probes_reset(player *p);
void play_probes_sample(player *p);
void play_probes_chart(player *p, isk_canvas *c, isk_ui_rect r);

/* play_hud.c */
void play_hud_draw(player *p);

/* Counts a frame's real time and what the accumulator dropped of it. */
void play_pace(player *p, double real_seconds, double dropped_seconds);
/* The effective speed 1/f and whether real time is kept, as text. */
void play_speed_text(const player *p, char *buf, size_t n);

/* play_files.c */
/* Reloads the scene (0), or keeps the running one and says why (-1). */
int play_reload(player *p);
/* Checks the file every half second; reloads when it changed. */
void play_watch(player *p);
void play_remember_file(player *p);
void play_save(player *p);
void play_screenshot(player *p, int whole_window, const char *path);

/* play_script.c */
/* Parses --script; 0, or 2 after a message on stderr. */
int play_script_parse(play_script *s, const char *text);
/* Parses a lesson's events (lesson.h): text is the file's lines from
 * first_line on; '#' at a token's start comments out the rest of its line;
 * shot names are NAME, not paths.  0, or 2 after "FILE:LINE: message". */
int play_script_parse_lesson(play_script *s, const char *text, const char *file, int first_line);
/* Plays the tokens due at this frame (events into the window's queue). */
int play_script_run(player *p);
/* Before the first frame: the events of frame:0 (a lesson's input that
 * reached the first frame). */
int play_script_start(player *p);
/* 1 when every token has been played. */
int play_script_done(const player *p);
/* The script's name of a window key (ISK_KEY_* or ASCII) into out: "esc",
 * "f9", "a"; 0 when a script cannot name it. */
int play_script_key_name(int key, char *out, size_t n);
void play_script_free(play_script *s);
/* The script's help lines. */
void play_script_help(FILE *f);

#endif
