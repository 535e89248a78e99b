/* SPDX-License-Identifier: MIT */
/* Temporaries removed on signals (see cleanup.h). */
#include "cleanup.h"

#include <pthread.h>
#include <signal.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "iskra/png.h"

#define MAX_TEMPS 8

/* Read by the handler: every field is written with the signals blocked. */
static const char *volatile temps[MAX_TEMPS];
static const char *volatile cmd_name = "iskra";
static volatile long files_committed; /* regular files renamed into place */

/* What the numbered outputs have done so far (cleanup_note). */
static struct {
    const char *volatile where;
    volatile long first, last, every, count;
} noted[CLEANUP_NSERIES];

static const struct {
    const char *noun, *nouns, *done, *dones, *unit, *units;
} series_words[CLEANUP_NSERIES] = {
    [CLEANUP_FRAMES] = {"frame", "frames", "was written", "were written", "file", "files"},
    [CLEANUP_STATES] = {"state", "states", "was written", "were written", "file", "files"},
    [CLEANUP_STREAM] = {"frame", "frames", "was streamed", "were streamed", "frame", "frames"},
};

static const struct {
    int sig;
    const char *name;
} handled[] = {{SIGINT, "SIGINT"}, {SIGTERM, "SIGTERM"}, {SIGHUP, "SIGHUP"}, {SIGPIPE, "SIGPIPE"}};
enum { NHANDLED = sizeof handled / sizeof handled[0] };

/* ---- inside the handler: write(2) only ----------------------------------------- */

static void put(const char *s)
{
    size_t n = strlen(s);
    while (n > 0) {
        ssize_t w = write(STDERR_FILENO, s, n);
        if (w <= 0)
            return;
        s += w;
        n -= (size_t)w;
    }
}

static void put_long(long v)
{
    char buf[24];
    int i = (int)sizeof buf - 1;
    unsigned long u = v < 0 ? 0ul - (unsigned long)v : (unsigned long)v;
    buf[i] = 0;
    do {
        buf[--i] = (char)('0' + u % 10);
        u /= 10;
    } while (u && i > 1);
    if (v < 0)
        buf[--i] = '-';
    put(buf + i);
}

/* "; WHERE: frames 0 to 8 (every 2) were written (5 files)", or
 * "; WHERE: frame 0 was written (1 file)" */
static void put_series(int k)
{
    const int one = noted[k].count == 1;
    put("; ");
    put(noted[k].where);
    put(": ");
    put(one ? series_words[k].noun : series_words[k].nouns);
    put(" ");
    put_long(noted[k].first);
    if (!one) {
        put(" to ");
        put_long(noted[k].last);
        if (noted[k].every > 1) {
            put(" (every ");
            put_long(noted[k].every);
            put(")");
        }
    }
    put(" ");
    put(one ? series_words[k].done : series_words[k].dones);
    put(" (");
    put_long(noted[k].count);
    put(" ");
    put(one ? series_words[k].unit : series_words[k].units);
    put(")");
}

static void on_signal(int sig)
{
    for (int i = 0; i < MAX_TEMPS; i++)
        if (temps[i])
            unlink(temps[i]);
    const char *name = "a signal";
    for (int i = 0; i < NHANDLED; i++)
        if (handled[i].sig == sig)
            name = handled[i].name;
    put("iskra ");
    put(cmd_name);
    put(": interrupted by ");
    put(name);
    long in_series = 0;
    int said = 0;
    for (int k = 0; k < CLEANUP_NSERIES; k++)
        if (noted[k].where && noted[k].count > 0) {
            put_series(k);
            said = 1;
            if (k != CLEANUP_STREAM)
                in_series += noted[k].count;
        }
    const long others = files_committed - in_series;
    if (others > 0) {
        put("; ");
        put_long(others);
        put(said ? (others == 1 ? " more file was written" : " more files were written")
                 : (others == 1 ? " file was written" : " files were written"));
        said = 1;
    }
    if (noted[CLEANUP_FRAMES].where && noted[CLEANUP_FRAMES].count > 0)
        put("; rerun with --resume to continue\n");
    else if (said)
        put("\n");
    else if (noted[CLEANUP_FRAMES].where)
        put("; no frame was written\n");
    else
        put("; nothing was written\n");
    _exit(128 + sig);
}

/* ---- outside ------------------------------------------------------------------- */

static void block(sigset_t *old)
{
    sigset_t all;
    sigemptyset(&all);
    for (int i = 0; i < NHANDLED; i++)
        sigaddset(&all, handled[i].sig);
    pthread_sigmask(SIG_BLOCK, &all, old); /* sigprocmask is unspecified with threads */
}

static void unblock(const sigset_t *old)
{
    pthread_sigmask(SIG_SETMASK, old, NULL);
}

void cleanup_install(const char *cmd)
{
    cmd_name = cmd;
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    sigfillset(&sa.sa_mask);
    for (int i = 0; i < NHANDLED; i++) {
        /* A signal ignored when we started (nohup, a background job) stays
         * ignored: whoever started us asked for that. */
        struct sigaction old;
        if (sigaction(handled[i].sig, NULL, &old) == 0 && old.sa_handler == SIG_IGN)
            continue;
        sigaction(handled[i].sig, &sa, NULL);
    }
    /* Past the file size limit (ulimit -f) a write fails with EFBIG
     * instead of killing us: the failure is then reported and cleaned up
     * like a full disk. */
    signal(SIGXFSZ, SIG_IGN);
}

static void forget(const char *temp)
{
    for (int i = 0; temp && i < MAX_TEMPS; i++)
        if (temps[i] == temp)
            temps[i] = NULL;
}

int cleanup_outfile_open(isk_outfile *o, const char *path)
{
    sigset_t old;
    isk_error err;
    block(&old);
    isk_status s = isk_outfile_open(o, path, &err);
    int slot = -1;
    for (int i = 0; s == ISK_OK && o->temp && i < MAX_TEMPS && slot < 0; i++)
        if (!temps[i])
            slot = i;
    if (slot >= 0)
        temps[slot] = o->temp;
    else if (s == ISK_OK && o->temp) {
        isk_outfile_abort(o); /* more temporaries than the registry holds: a bug, refuse */
        s = isk_error_set(&err, ISK_ERR_FULL, "%s: too many files open at once", path);
    }
    unblock(&old);
    if (s != ISK_OK) {
        fprintf(stderr, "iskra %s: %s\n", cmd_name, err.message);
        return 1;
    }
    return 0;
}

int cleanup_outfile_commit(isk_outfile *o)
{
    sigset_t old;
    isk_error err;
    block(&old);
    forget(o->temp);
    const int renamed_file = o->temp != NULL;
    isk_status s = isk_outfile_commit(o, &err);
    if (s == ISK_OK && renamed_file)
        files_committed++;
    unblock(&old);
    if (s != ISK_OK) {
        fprintf(stderr, "iskra %s: %s\n", cmd_name, err.message);
        return 1;
    }
    return 0;
}

void cleanup_outfile_abort(isk_outfile *o)
{
    sigset_t old;
    block(&old);
    forget(o->temp);
    isk_outfile_abort(o);
    unblock(&old);
}

int cleanup_png_write(const isk_canvas *c, const char *path)
{
    isk_outfile o;
    if (cleanup_outfile_open(&o, path))
        return 1;
    isk_error err;
    if (isk_png_write_stream(c, o.f, path, &err) != ISK_OK) {
        cleanup_outfile_abort(&o);
        fprintf(stderr, "iskra %s: %s\n", cmd_name, err.message);
        return 1;
    }
    return cleanup_outfile_commit(&o);
}

void cleanup_note(cleanup_series k, const char *where, long first, long last, long every, long count)
{
    sigset_t old;
    block(&old);
    noted[k].where = where;
    noted[k].first = first;
    noted[k].last = last;
    noted[k].every = every;
    noted[k].count = count;
    unblock(&old);
}

void cleanup_hold(sigset_t *saved)
{
    block(saved);
}

void cleanup_release(const sigset_t *saved)
{
    unblock(saved);
}
