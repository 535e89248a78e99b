/* SPDX-License-Identifier: MIT */
/* iskra/ui_sdl.h — feeds the SDL window's events (iskra/sdl.h) to the
 * widget layer (iskra/ui.h).  Header-only, so neither library depends on
 * the other.  Only the left button drives widgets (a double click's second
 * press selects a field's text); keypad + and - count as + and -; a key
 * held with Ctrl arrives or'ed with ISK_UI_MOD_CTRL (Ctrl+A selects all).
 *
 * Example: a window with one button, until Escape (pressed by the program):
 *
 *     typedef struct app { isk_ui ui; int clicks; } app;
 *     static int frame(void *user, isk_canvas *c, double dt, const isk_event *ev, int n)
 *     {
 *         app *a = user;
 *         (void)dt;
 *         for (int i = 0; i < n; i++) isk_ui_feed_event(&a->ui, &ev[i]);
 *         isk_ui_begin(&a->ui, c);
 *         isk_ui_clear(&a->ui);
 *         isk_ui_rect r = {20, 20, 160, isk_ui_row_height(&a->ui)};
 *         if (isk_ui_button(&a->ui, "hello", r, "Hello")) a->clicks++;
 *         isk_ui_end(&a->ui);
 *         return isk_ui_key(&a->ui, ISK_UI_KEY_ESCAPE);   // quit on Escape outside a field
 *     }
 *     // in main():
 *     app a = {.clicks = 0};
 *     isk_ui_init(&a.ui, 1);
 *     isk_window *w;
 *     isk_error err;
 *     if (isk_window_open(&w, "widgets", 200, 80, &err) != ISK_OK) {
 *         fprintf(stderr, "%s\n", err.message);
 *         return 1;
 *     }
 *     isk_window_set_escape_quits(w, 0);               // so Escape can cancel an edit
 *     isk_event esc = {.type = ISK_EVENT_KEY_DOWN, .key = ISK_KEY_ESCAPE};
 *     isk_status s = isk_window_push_event(w, &esc);   // as if the user pressed it
 *     isk_canvas canvas = {0};
 *     if (s == ISK_OK) s = isk_canvas_init(&canvas, 200, 80);
 *     if (s == ISK_OK) s = isk_window_run(w, &canvas, frame, &a, 0, &err);
 *     if (s != ISK_OK) fprintf(stderr, "%s\n", err.message);
 *     isk_canvas_free(&canvas);
 *     isk_window_close(w);
 *     return s != ISK_OK;
 */
#ifndef ISKRA_UI_SDL_H
#define ISKRA_UI_SDL_H

#include "iskra/sdl.h"
#include "iskra/ui.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The widget layer's key for an iskra/sdl.h key code (0: none). */
static inline int isk_ui_key_from_window(int key)
{
    if (key >= ISK_KEY_F1 && key <= ISK_KEY_F12)
        return ISK_UI_KEY_F1 + (key - ISK_KEY_F1);
    switch (key) {
    case ISK_KEY_BACKSPACE: return ISK_UI_KEY_BACKSPACE;
    case ISK_KEY_DELETE: return ISK_UI_KEY_DELETE;
    case ISK_KEY_RETURN: return ISK_UI_KEY_RETURN;
    case ISK_KEY_ESCAPE: return ISK_UI_KEY_ESCAPE;
    case ISK_KEY_TAB: return ISK_UI_KEY_TAB;
    case ISK_KEY_LEFT: return ISK_UI_KEY_LEFT;
    case ISK_KEY_RIGHT: return ISK_UI_KEY_RIGHT;
    case ISK_KEY_UP: return ISK_UI_KEY_UP;
    case ISK_KEY_DOWN: return ISK_UI_KEY_DOWN;
    case ISK_KEY_HOME: return ISK_UI_KEY_HOME;
    case ISK_KEY_END: return ISK_UI_KEY_END;
    case ISK_KEY_KP_PLUS: return '+';
    case ISK_KEY_KP_MINUS: return '-';
    default: return key >= 32 && key <= 126 ? key : 0;
    }
}

static inline void isk_ui_feed_event(isk_ui *ui, const isk_event *ev)
{
    switch (ev->type) {
    case ISK_EVENT_MOUSE_MOVE: isk_ui_input_mouse(ui, ev->x, ev->y); break;
    case ISK_EVENT_MOUSE_DOWN:
    case ISK_EVENT_MOUSE_UP:
        if (ev->button == 1)
            isk_ui_input_button_clicks(ui, ev->x, ev->y, ev->type == ISK_EVENT_MOUSE_DOWN, ev->clicks);
        break;
    case ISK_EVENT_WHEEL: isk_ui_input_wheel(ui, ev->wheel); break;
    case ISK_EVENT_TEXT: isk_ui_input_text(ui, ev->text); break;
    case ISK_EVENT_KEY_DOWN: {
        int key = isk_ui_key_from_window(ev->key);
        if (key && (ev->mods & ISK_MOD_CTRL))
            key |= ISK_UI_MOD_CTRL;
        isk_ui_input_key(ui, key);
        break;
    }
    default: break;
    }
}

#ifdef __cplusplus
}
#endif

#endif
